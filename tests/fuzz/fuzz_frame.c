/* SPDX-License-Identifier: MIT */
/*
 * fuzz_frame: whole zspan frames from arbitrary bytes (libFuzzer).
 *
 * The input is decoded (see decode_scene; missing bytes read as zero) into a
 * renderer config (small screens and small pools so that every overflow path
 * is reached), a camera from raw Q16.16 values (look_at, set_view, any
 * perspective), shading parameters (format, shading, lights, fog,
 * background), up to four meshes (int16 positions at any scale, indices in
 * and out of range, optional colours and normals, model matrices) and a
 * render plan (band size, first row, zs_render_rows or zs_render_frame,
 * stride padding). Invalid arguments are part of the input space: every call
 * must return a status the header documents for that argument, and a
 * rejected call must change nothing.
 *
 * One input renders the scene four to seven times: span mode and zline mode
 * in the decoded format, span mode in ZS_FMT_ID16 (unless that is the
 * format), Warnock mode, and the draws alone into a renderer with large
 * pools; with ZS_CFG_ABUFFER (a quarter of the inputs) also span mode on a
 * renderer without it and an anti-aliased frame (edges or transparency).
 * Invariants:
 *   - status codes: each call's result is in the set the header allows for
 *     the arguments (computed here from the header's rules, not from src/);
 *   - memory: guard bytes around each band buffer and the stride padding
 *     between its rows stay untouched (plus ASan on the exact-size arena);
 *   - span mode writes every pixel of every row exactly once, with spans
 *     inside [0, width) (the span fills are counted, see span_counted.c);
 *   - span mode == zline mode byte for byte, in every format (ties go to
 *     the earlier record in both modes and the colour planes are evaluated
 *     identically; see the notes in README.md (Robustness));
 *   - statistics: submitted == culled + rejected + empty + dropped + stored,
 *     records == setup-hook calls, pools never above their capacities,
 *     tris_drawn + records_skipped == records after a complete frame, the
 *     geometry statistics equal in both modes;
 *   - the work bound of README.md (Robustness), per band;
 *   - coverage (ID16): a pixel shows tag t only where a record of tag t
 *     covers its centre (half-space reference rasterizer, top-left rule), and
 *     with no edge-pool drop every covered pixel shows some tag;
 *   - colours: background pixels (and, unlit and flat, triangle pixels) have
 *     the packed value the header defines for the format;
 *   - capacity policy: with a full triangle pool and no vertex drop, the
 *     records are exactly the first max_triangles records that large pools
 *     store (the last triangles submitted are the ones dropped);
 *   - Warnock mode == span mode byte for byte, with the same records (when
 *     neither left records out of a full active pool);
 *   - A-buffer: with anti-aliasing off, the same frame as a renderer
 *     without ZS_CFG_ABUFFER; on, guards and padding intact, the statuses
 *     the header gives (zs_frame_antialias needs the flag and span mode,
 *     zs_draw_opacity a transparent frame), and rows no stored record comes
 *     within a pixel of equal the aliased frame's (when its pools dropped
 *     nothing: it also keeps triangles that cover sub-samples but no centre).
 */
#include <string.h>

#include "fuzz_util.h"
#include "zspan/zspan.h"
#include "zt.h"

#define MAXW 64
#define MAXH 64
#define MAXMESH 4
#define MAXV 48
#define MAXT 48
#define GUARD 32
#define CANARY 0xA5
#define BIT(s) (1u << (unsigned)(s))

/* The config's feature flags (ZS_CFG_*), where the header has them. */
#ifdef ZS_CFG_NO_ZLINE
#define CFG_FLAGS(c) ((c).flags)
#define ARENA_BYTES(c)                                                                  \
    ZS_ARENA_BYTES_CFG((c).width, (c).height, (c).max_triangles, (c).max_vertices,      \
                       (c).max_active_edges, (c).flags)
#define NO_ZLINE(c) (((c).flags & ZS_CFG_NO_ZLINE) != 0)
#define FLAT_ONLY(c) (((c).flags & ZS_CFG_FLAT_ONLY) != 0)
#else
#define ARENA_BYTES(c)                                                                  \
    ZS_ARENA_BYTES((c).width, (c).height, (c).max_triangles, (c).max_vertices,          \
                   (c).max_active_edges)
#define NO_ZLINE(c) 0
#define FLAT_ONLY(c) 0
#endif

/* ------------------------------------------------------------------ */
/* Decoded input                                                        */
/* ------------------------------------------------------------------ */

typedef struct fmesh {
    zs_mesh m;
    int16_t pos[3 * MAXV];
    uint16_t idx[3 * MAXT];
    zs_color fcol[MAXT], vcol[MAXV];
    int16_t fnorm[3 * MAXT], vnorm[3 * MAXV];
    zs_mat34 model;
    int has_model;
    unsigned allowed; /* statuses zs_draw may return */
} fmesh;

typedef struct scene {
    zs_config cfg;
    unsigned arena_off;
    zs_camera cam;
    unsigned cam_allowed_la, cam_allowed_persp;
    int cam_la_must_fail;
    int cam_kind;
    int32_t bad_mode;
    int call_shading;
    zs_shade_params sp;
    unsigned shade_allowed;
    int nmesh;
    fmesh mesh[MAXMESH];
    int band, start_row, use_frame_api, stop_after, pad;
    uint8_t misuse;
    uint8_t aa; /* A-buffer frame: mode (bit 0: transparent), opacities */
} scene;

static const int32_t k_special[] = {
    0,          1,          -1,         ZS_FX_ONE,      -ZS_FX_ONE,      INT32_MAX,
    INT32_MIN,  INT32_MIN + 1, ZS_FX(180), ZS_FX(180) - 1, ZS_FX(90),     ZS_FX(32767),
    -ZS_FX(32767), 0x7FFF0000, 65535,   ZS_FX(1) / 10,  ZS_FX(100),      ZS_FX(1) / 1024,
    ZS_FX(179), 229,        200,        260,            ZS_FX(60),       ZS_FX(1) / 2,
};
#define NSPECIAL (sizeof k_special / sizeof k_special[0])

/* A Q16.16 value: raw, special, small integer quarters, or a scaled int16. */
static int32_t fx_pick(fz_reader *d)
{
    uint8_t k = fz_u8(d);
    switch (k & 7u) {
    case 0: return (int32_t)fz_u32(d);
    case 1: return k_special[fz_u8(d) % NSPECIAL];
    case 6: return (int32_t)(int16_t)fz_u16(d) * 16;
    case 7: {
        int64_t m = (int16_t)fz_u16(d);
        int64_t v = m * ((int64_t)1 << (fz_u8(d) % 17u));
        return (int32_t)(v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : v);
    }
    default: return (int32_t)(int8_t)fz_u8(d) * (ZS_FX_ONE / 4); /* -32 .. 31.75 */
    }
}

static zs_vec3 vec_pick(fz_reader *d)
{
    zs_fixed x = fx_pick(d);
    zs_fixed y = fx_pick(d);
    zs_fixed z = fx_pick(d);
    return zs_vec3_make(x, y, z);
}

/* A model or view matrix: identity, a composition of simple transforms, or raw. */
static zs_mat34 mat_pick(fz_reader *d, int *has)
{
    uint8_t k = fz_u8(d);
    zs_mat34 m = zs_mat34_identity();
    *has = 1;
    switch (k % 4u) {
    case 0: *has = (k & 4u) ? 1 : 0; break;
    case 1:
    case 2: {
        zs_fixed tx = (int8_t)fz_u8(d) * (ZS_FX_ONE / 8);
        zs_fixed ty = (int8_t)fz_u8(d) * (ZS_FX_ONE / 8);
        zs_fixed tz = (int8_t)fz_u8(d) * (ZS_FX_ONE / 8);
        zs_fixed ax = (zs_fixed)fz_u8(d) * (ZS_FX(360) / 256);
        zs_fixed ay = (zs_fixed)fz_u8(d) * (ZS_FX(360) / 256);
        zs_fixed az = (zs_fixed)fz_u8(d) * (ZS_FX(360) / 256);
        uint8_t sk = fz_u8(d);
        zs_fixed s = sk == 0 ? ZS_FX_ONE : (zs_fixed)sk * (ZS_FX_ONE / 32);
        zs_mat34 t = zs_mat34_translate(tx, ty, tz), rx = zs_mat34_rotate_x(ax),
                 ry = zs_mat34_rotate_y(ay), rz = zs_mat34_rotate_z(az), sc;
        if (k & 0x80u) {
            zs_vec3 v = vec_pick(d);
            sc = zs_mat34_scale(v.x, v.y, v.z);
        } else
            sc = zs_mat34_scale(s, s, s);
        m = zs_mat34_mul(&rx, &sc);
        m = zs_mat34_mul(&ry, &m);
        m = zs_mat34_mul(&rz, &m);
        m = zs_mat34_mul(&t, &m);
        break;
    }
    default:
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                m.m[i][j] = fx_pick(d);
        break;
    }
    return m;
}

static int64_t dot64(const int64_t a[3], const int64_t b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Camera and its allowed statuses (header: look_at fails only with
 * ZS_ERR_CAMERA for eye == target or up along the view; perspective with
 * ZS_ERR_FOV outside (0, 180) or narrower than ~0.0035 degrees, then
 * ZS_ERR_DEPTH_RANGE unless 0 < near < far). */
static void decode_camera(fz_reader *d, scene *s)
{
    zs_camera *c = &s->cam;
    uint8_t k = fz_u8(d);
    memset(c, 0, sizeof *c);
    s->cam_kind = k % 4u;
    s->cam_la_must_fail = 0;
    s->cam_allowed_la = BIT(ZS_OK);
    if (s->cam_kind <= 1) {
        zs_vec3 eye, target, up;
        if (s->cam_kind == 0) { /* small, mostly sensible */
            int32_t v[6];
            for (int i = 0; i < 6; i++)
                v[i] = (int8_t)fz_u8(d) * (ZS_FX_ONE / 16);
            eye = zs_vec3_make(v[0], v[1], v[2]);
            target = zs_vec3_make(v[3], v[4], v[5] - ZS_FX_ONE);
            uint8_t u = fz_u8(d);
            up = zs_vec3_make(0, ZS_FX_ONE, 0);
            if (u >= 192) {
                for (int i = 0; i < 3; i++)
                    v[i] = (int8_t)fz_u8(d) * 256;
                up = zs_vec3_make(v[0], v[1], v[2]);
            }
        } else {
            eye = vec_pick(d);
            target = vec_pick(d);
            up = vec_pick(d);
        }
        int64_t dv[3] = {(int64_t)target.x - eye.x, (int64_t)target.y - eye.y,
                         (int64_t)target.z - eye.z};
        int64_t uv[3] = {up.x, up.y, up.z};
        int64_t cr[3] = {dv[1] / 4 * (uv[2] / 4) - dv[2] / 4 * (uv[1] / 4),
                         dv[2] / 4 * (uv[0] / 4) - dv[0] / 4 * (uv[2] / 4),
                         dv[0] / 4 * (uv[1] / 4) - dv[1] / 4 * (uv[0] / 4)};
        (void)dot64;
        /* exact degeneracies must fail; the cross product is exact here when
         * every component is a multiple of 4 (else only "may fail") */
        int exact = !(dv[0] % 4 || dv[1] % 4 || dv[2] % 4 || uv[0] % 4 || uv[1] % 4 || uv[2] % 4);
        if ((dv[0] == 0 && dv[1] == 0 && dv[2] == 0) || (uv[0] == 0 && uv[1] == 0 && uv[2] == 0) ||
            (exact && cr[0] == 0 && cr[1] == 0 && cr[2] == 0))
            s->cam_la_must_fail = 1;
        s->cam_allowed_la = s->cam_la_must_fail ? BIT(ZS_ERR_CAMERA)
                                                : BIT(ZS_OK) | BIT(ZS_ERR_CAMERA);
        zs_status st = zs_camera_look_at(c, eye, target, up);
        FZ_CHECK(BIT(st) & s->cam_allowed_la, "look_at returned %d (%s), allowed mask %#x",
                 (int)st, zs_strerror(st), s->cam_allowed_la);
        if (st == ZS_OK) {
            /* the view's 3x3 is a rotation: unit rows, Q16.16, 1% */
            for (int i = 0; i < 3; i++) {
                int64_t l2 = 0;
                for (int j = 0; j < 3; j++)
                    l2 += (int64_t)c->view.m[i][j] * c->view.m[i][j];
                FZ_CHECK(l2 > ((int64_t)1 << 32) / 100 * 98 && l2 < ((int64_t)1 << 32) / 100 * 102,
                         "look_at row %d not unit: |r|^2 = %lld", i, (long long)l2);
            }
            FZ_CHECK(c->has_view == 1, "look_at OK without has_view");
        } else {
            FZ_CHECK(c->has_view == 0, "failed look_at set has_view");
        }
    } else {
        int has;
        zs_mat34 v = mat_pick(d, &has);
        FZ_CHECK(zs_camera_set_view(c, &v) == ZS_OK, "set_view failed");
    }
    /* perspective */
    int32_t fov, nz, fz;
    uint8_t pk = fz_u8(d);
    if (pk < 200) { /* sensible */
        fov = ZS_FX(1) + (int32_t)(pk % 179u) * ZS_FX(1);
        nz = (int32_t)(1 + fz_u8(d)) * (ZS_FX_ONE / 64);
        fz = nz + (int32_t)(1 + fz_u16(d)) * (ZS_FX_ONE / 64);
    } else {
        fov = fx_pick(d);
        nz = fx_pick(d);
        fz = fx_pick(d);
        if (pk == 255)
            fz = nz; /* near == far */
    }
    unsigned allowed;
    if (fov <= 0 || fov >= ZS_FX(180))
        allowed = BIT(ZS_ERR_FOV);
    else {
        unsigned dr = (nz <= 0 || fz <= nz) ? BIT(ZS_ERR_DEPTH_RANGE) : BIT(ZS_OK);
        if (fov < 200)
            allowed = BIT(ZS_ERR_FOV);
        else if (fov <= 260)
            allowed = BIT(ZS_ERR_FOV) | dr;
        else
            allowed = dr;
    }
    s->cam_allowed_persp = allowed;
    zs_status st = zs_camera_perspective(c, fov, nz, fz);
    FZ_CHECK(BIT(st) & allowed, "perspective(fov %d, near %d, far %d) returned %d (%s)", fov, nz,
             fz, (int)st, zs_strerror(st));
    FZ_CHECK((st == ZS_OK) == (c->has_projection == 1), "has_projection %u after status %d",
             c->has_projection, (int)st);
}

static unsigned shade_allowed(const zs_shade_params *p, const zs_config *cfg)
{
    unsigned m = 0;
    (void)cfg;
    if (FLAT_ONLY(*cfg) && (p->shading != ZS_SHADE_FLAT || p->fog.enabled))
        m |= BIT(ZS_ERR_MODE);
    if (p->shading != ZS_SHADE_FLAT && p->shading != ZS_SHADE_GOURAUD)
        m |= BIT(ZS_ERR_MODE);
    if ((unsigned)p->format >= (unsigned)ZS_FMT_COUNT)
        m |= BIT(ZS_ERR_FORMAT);
    int bad = p->light_count > ZS_MAX_LIGHTS || p->ambient < 0 || p->background > 0xFFFFFFu ||
              (p->fog.enabled && p->fog.end <= p->fog.start) || p->fog.color > 0xFFFFFFu;
    for (int i = 0; i < p->light_count && i < ZS_MAX_LIGHTS; i++)
        if (p->lights[i].intensity < 0 ||
            (p->lights[i].direction.x == 0 && p->lights[i].direction.y == 0 &&
             p->lights[i].direction.z == 0))
            bad = 1;
    if (bad)
        m |= BIT(ZS_ERR_ARGUMENT);
    return m ? m : BIT(ZS_OK);
}

static void decode_shading(fz_reader *d, scene *s)
{
    uint8_t k = fz_u8(d);
    zs_shade_params *p = &s->sp;
    *p = zs_shade_default();
    s->call_shading = k & 1u;
    if (!s->call_shading) {
        s->shade_allowed = BIT(ZS_OK);
        return;
    }
    uint8_t f = fz_u8(d);
    p->format = (zs_format)(f < 240 ? f % ZS_FMT_COUNT : (int)(int8_t)f);
    uint8_t sh = fz_u8(d);
    p->shading = (zs_shading)(sh < 250 ? sh % 2u : sh);
    uint32_t bg = fz_u32(d);
    p->background = (k & 2u) ? bg : (bg & 0xFFFFFFu);
    if (k & 4u) { /* lit */
        uint8_t a = fz_u8(d);
        p->ambient = a < 250 ? (int32_t)a * (ZS_FX_ONE / 128) : fx_pick(d);
        uint8_t lc = fz_u8(d);
        p->light_count = (uint8_t)(lc < 250 ? lc % (ZS_MAX_LIGHTS + 1u) : lc);
        for (int i = 0; i < ZS_MAX_LIGHTS; i++) {
            uint8_t lk = fz_u8(d);
            if (lk < 200) {
                int32_t v[3];
                for (int k2 = 0; k2 < 3; k2++)
                    v[k2] = (int8_t)fz_u8(d) * 4096;
                p->lights[i].direction = zs_vec3_make(v[0], v[1], v[2]);
                p->lights[i].intensity = (int32_t)fz_u8(d) * (ZS_FX_ONE / 128);
            } else {
                p->lights[i].direction = vec_pick(d);
                p->lights[i].intensity = fx_pick(d);
            }
        }
    }
    if (k & 8u) { /* fog */
        p->fog.enabled = (uint8_t)(1 + fz_u8(d) % 2u); /* any non-zero enables */
        uint32_t fc = fz_u32(d);
        p->fog.color = (k & 16u) ? fc : (fc & 0xFFFFFFu);
        if (k & 32u) {
            p->fog.start = fx_pick(d);
            p->fog.end = fx_pick(d);
        } else {
            p->fog.start = (int32_t)fz_u8(d) * (ZS_FX_ONE / 16);
            p->fog.end = p->fog.start + (int32_t)(1 + fz_u8(d)) * (ZS_FX_ONE / 16);
        }
    }
    s->shade_allowed = shade_allowed(p, &s->cfg);
}

static int16_t pos_pick(fz_reader *d, unsigned kind)
{
    switch (kind) {
    case 0: return (int16_t)(int8_t)fz_u8(d);
    case 1: return (int16_t)fz_u16(d);
    case 2: return (int16_t)((int8_t)fz_u8(d) * 256);
    default: {
        uint8_t v = fz_u8(d);
        static const int16_t ex[] = {-32768, 32767, 0, -32767, 1, -1};
        return v < 192 ? (int16_t)(int8_t)v : ex[v % 6u];
    }
    }
}

static void decode_mesh(fz_reader *d, fmesh *f)
{
    zs_mesh *m = &f->m;
    uint8_t flags = fz_u8(d);
    uint8_t vc = (uint8_t)(fz_u8(d) % (MAXV + 1u)), tc = (uint8_t)(fz_u8(d) % (MAXT + 1u));
    unsigned pk = (flags >> 4) & 3u;
    memset(m, 0, sizeof *m);
    for (unsigned i = 0; i < 3u * vc; i++)
        f->pos[i] = pos_pick(d, pk);
    uint8_t ik = fz_u8(d);
    int oob = 0;
    for (unsigned i = 0; i < 3u * tc; i++) {
        uint16_t v;
        if (ik >= 240)
            v = fz_u16(d);
        else if (ik >= 224)
            v = (uint16_t)(fz_u8(d) % (vc + 2u));
        else
            v = vc ? (uint16_t)(fz_u8(d) % vc) : fz_u8(d);
        f->idx[i] = v;
        if (v >= vc)
            oob = 1;
    }
    uint8_t sk = fz_u8(d);
    if (sk < 200)
        m->scale = (int32_t)(1 + sk) * (ZS_FX_ONE / 256); /* 1/256 .. 200/256 */
    else if (sk < 216)
        m->scale = -(int32_t)(1 + sk - 200) * (ZS_FX_ONE / 64); /* mirrored */
    else
        m->scale = fx_pick(d);
    m->color = fz_u32(d);
    if (flags & 1u) {
        for (unsigned i = 0; i < tc; i++)
            f->fcol[i] = fz_u32(d);
        m->face_colors = f->fcol;
    }
    if (flags & 2u) {
        for (unsigned i = 0; i < vc; i++)
            f->vcol[i] = fz_u32(d);
        m->vertex_colors = f->vcol;
    }
    if (flags & 4u) {
        for (unsigned i = 0; i < 3u * tc; i++)
            f->fnorm[i] = (int16_t)fz_u16(d);
        m->face_normals = f->fnorm;
    }
    if (flags & 8u) {
        for (unsigned i = 0; i < 3u * vc; i++)
            f->vnorm[i] = (int16_t)fz_u16(d);
        m->vertex_normals = f->vnorm;
    }
    m->positions = f->pos;
    m->indices = f->idx;
    m->vertex_count = vc;
    m->triangle_count = tc;
    if (flags & 0x80u) { /* NULL arrays */
        uint8_t nk = fz_u8(d);
        if (nk & 1u)
            m->positions = NULL;
        if (nk & 2u)
            m->indices = NULL;
    }
    f->model = mat_pick(d, &f->has_model);
    if (!m->positions || !m->indices || m->scale == 0 || m->vertex_count == 0)
        f->allowed = BIT(ZS_ERR_MESH) | (oob ? BIT(ZS_ERR_INDEX) : 0u);
    else
        f->allowed = oob ? BIT(ZS_ERR_INDEX) : BIT(ZS_OK);
}

/* Returns 0 when the input takes the config-error path (already checked). */
static int decode_scene(fz_reader *d, scene *s)
{
    uint8_t k = fz_u8(d);
    if (k == 0xFF) { /* raw config: the error paths of zs_arena_bytes / zs_init */
        uint16_t v[5];
        for (int i = 0; i < 5; i++)
            v[i] = fz_u16(d);
        zs_config c = zs_config_default(v[0], v[1], v[2], v[3], v[4]);
        unsigned allowed = 0;
#ifdef ZS_CFG_NO_ZLINE
        c.flags = fz_u16(d);
        if (!ZS_CFG_FLAGS_OK(c.flags))
            allowed |= BIT(ZS_ERR_ARGUMENT);
#endif
        if (c.width == 0 || c.height == 0 || c.width > ZS_MAX_DIM || c.height > ZS_MAX_DIM)
            allowed |= BIT(ZS_ERR_SIZE);
        if (c.max_triangles == 0 || c.max_vertices == 0 || c.max_active_edges < 2 ||
            c.max_active_edges > ZS_MAX_ACTIVE_EDGES)
            allowed |= BIT(ZS_ERR_CAPACITY);
        size_t need = zs_arena_bytes(&c);
        if (allowed) {
            FZ_CHECK(need == 0, "zs_arena_bytes of an invalid config = %zu", need);
        } else {
            FZ_CHECK(need == ARENA_BYTES(c), "zs_arena_bytes %zu != ZS_ARENA_BYTES", need);
            allowed = BIT(ZS_ERR_ARENA_SMALL);
        }
        /* too small an arena (or an invalid config): nothing is touched */
        static uint8_t small[4096];
        size_t give = need ? (size_t)(fz_u32(d) % need) : fz_u16(d);
        if (give > sizeof small)
            give = sizeof small;
        zs_renderer r;
        memset(&r, 0x5A, sizeof r);
        memset(small, CANARY, sizeof small);
        zs_status st = zs_init(&r, small, give, &c);
        FZ_CHECK(BIT(st) & allowed, "zs_init(%u,%u,%u,%u,%u, arena %zu) returned %d (%s)",
                 c.width, c.height, c.max_triangles, c.max_vertices, c.max_active_edges, give,
                 (int)st, zs_strerror(st));
        for (size_t i = 0; i < sizeof small; i++)
            FZ_CHECK(small[i] == CANARY, "failed zs_init wrote arena byte %zu", i);
        return 0;
    }
    {
        uint16_t w = (uint16_t)(1 + fz_u8(d) % MAXW);
        uint16_t h = (uint16_t)(1 + fz_u8(d) % MAXH);
        uint16_t nt = (uint16_t)(1 + fz_u8(d) % 128u);
        uint16_t nv = (uint16_t)(1 + fz_u8(d) % 160u);
        uint16_t ne = (uint16_t)(2 + fz_u8(d) % 48u);
        s->cfg = zs_config_default(w, h, nt, nv, ne);
    }
    s->arena_off = k % 8u;
#ifdef ZS_CFG_NO_ZLINE
    {
        uint8_t f = fz_u8(d);
        /* NO_ZLINE and FLAT_ONLY from the low bits, the A-buffer in a quarter
         * of the inputs, rarely an unknown bit */
        s->cfg.flags = (uint16_t)(f < 240 ? (f % 4u) | ((f / 4u) % 4u == 3u ? ZS_CFG_ABUFFER : 0u)
                                          : (unsigned)f << 8);
    }
#endif
    decode_camera(d, s);
    uint8_t mk = fz_u8(d);
    s->bad_mode = mk >= 250 ? (int32_t)fz_u32(d) : -1;
    decode_shading(d, s);
    s->nmesh = 1 + fz_u8(d) % MAXMESH;
    for (int i = 0; i < s->nmesh; i++)
        decode_mesh(d, &s->mesh[i]);
    uint8_t b = fz_u8(d);
    s->band = 1 + b % s->cfg.height;
    uint8_t sr = fz_u8(d);
    s->start_row = (sr & 3u) == 3u ? (sr >> 2) % s->cfg.height : 0;
    uint8_t pl = fz_u8(d);
    s->use_frame_api = pl & 1u;
    s->stop_after = (pl & 2u) ? 1 + (pl >> 2) % 8u : 0;
    s->pad = fz_u8(d) % 8u;
    s->misuse = fz_u8(d);
    s->aa = fz_u8(d);
    return 1;
}

/* ------------------------------------------------------------------ */
/* Span fill counting (called from span_counted.c)                      */
/* ------------------------------------------------------------------ */

static struct {
    int on;
    const uint8_t *base;
    size_t stride;
    unsigned bpp;
    int w, rows;
    uint8_t cnt[MAXH][MAXW];
    unsigned long calls, empty;
} g_fill;

static unsigned long g_empty_spans; /* zero-width fills seen (reported, allowed) */

void fuzz_span_fill(const uint8_t *row, int x0, int x1)
{
    if (!g_fill.on)
        return;
    FZ_CHECK(row >= g_fill.base, "span fill before the band buffer");
    size_t off = (size_t)(row - g_fill.base);
    FZ_CHECK(off % g_fill.stride == 0, "span fill at a row pointer not on a row start (%zu)", off);
    size_t y = off / g_fill.stride;
    FZ_CHECK(y < (size_t)g_fill.rows, "span fill in row %zu of a %d-row band", y, g_fill.rows);
    FZ_CHECK(x0 >= 0 && x1 <= g_fill.w && x0 <= x1, "span fill [%d, %d) in a row of %d", x0, x1,
             g_fill.w);
    g_fill.calls++;
    if (x0 == x1)
        g_fill.empty++;
    for (int x = x0; x < x1; x++)
        g_fill.cnt[y][x]++;
}

/* ------------------------------------------------------------------ */
/* Rendering one frame                                                  */
/* ------------------------------------------------------------------ */

typedef struct frame_out {
    zs_stats st;
    zt_recs recs;
    uint8_t img[MAXW * MAXH * 3];
    uint8_t rendered[MAXH];
    int complete, nrendered;
    zs_format fmt;
    unsigned bpp;
    int draw_ok[MAXMESH];
    uint16_t first_tag[MAXMESH];
} frame_out;

typedef struct band_ctx {
    zs_renderer *r;
    const scene *s;
    frame_out *o;
    zs_visibility mode;
    uint8_t *buf;      /* with guards */
    size_t total, stride;
    zs_stats prev;
    int bands;
} band_ctx;

static uint64_t min64(uint64_t a, uint64_t b) { return a < b ? a : b; }

/* The work bound (README.md (Robustness)), for the rows rendered between two
 * snapshots. stats.max_active_edges counts edge sides, two per active
 * triangle (header), and is a running maximum: A = max_active_edges / 2
 * bounds the active triangles of every row so far; the edge records of a row
 * are at most 2A (an edge two triangles share is stored once). A is also at
 * most the active pool (config max_active_edges / 2) and the triangles drawn. */
static uint64_t active_bound(const zs_stats *b, const zs_config *cfg)
{
    uint64_t A = b->max_active_edges / 2u;
    FZ_CHECK(A <= cfg->max_active_edges / 2u && A <= b->tris_drawn,
             "max_active_edges %u: more active triangles than the pool (%u) or drawn (%u)",
             b->max_active_edges, cfg->max_active_edges / 2u, b->tris_drawn);
    return A;
}

static void check_work(const zs_stats *a, const zs_stats *b, uint64_t rows, uint64_t w,
                       zs_visibility mode, const zs_config *cfg)
{
    uint64_t A = active_bound(b, cfg), E = 2 * A;
    uint64_t X = b->crossings - a->crossings, S = b->spans - a->spans;
    uint64_t D = b->depth_evals - a->depth_evals, P = b->pixels_shaded - a->pixels_shaded;
    FZ_CHECK(b->rows - a->rows == rows, "rows %u -> %u for %llu rows", a->rows, b->rows,
             (unsigned long long)rows);
    if (mode == ZS_MODE_WARNOCK) {
        /* windows, not a walk: only the rows and the pixels written */
        FZ_CHECK(P == rows * w, "warnock pixels_shaded %llu != rows * W = %llu",
                 (unsigned long long)P, (unsigned long long)(rows * w));
    } else if (mode == ZS_MODE_SPAN) {
        uint64_t xrow = min64(A * (A > 0 ? A - 1 : 0) / 2, w - 1);
        FZ_CHECK(X <= rows * xrow, "crossings %llu > rows %llu * min(A(A-1)/2, W-1) = %llu (A %llu)",
                 (unsigned long long)X, (unsigned long long)rows, (unsigned long long)(rows * xrow),
                 (unsigned long long)A);
        FZ_CHECK(S >= rows && S <= rows * min64(E + 1, w) + X,
                 "spans %llu not in [rows, rows * min(E+1, W) + X] = [%llu, %llu] (E %llu X %llu)",
                 (unsigned long long)S, (unsigned long long)rows,
                 (unsigned long long)(rows * min64(E + 1, w) + X), (unsigned long long)E,
                 (unsigned long long)X);
        FZ_CHECK(D <= rows * (2 * A + 2 * A * A) + A * X,
                 "depth_evals %llu > rows * (2A + 2A^2) + A * X = %llu (A %llu X %llu)",
                 (unsigned long long)D, (unsigned long long)(rows * (2 * A + 2 * A * A) + A * X),
                 (unsigned long long)A, (unsigned long long)X);
        FZ_CHECK(P == rows * w, "span pixels_shaded %llu != rows * W = %llu", (unsigned long long)P,
                 (unsigned long long)(rows * w));
    } else {
        FZ_CHECK(X == 0, "zline mode counted %llu crossings", (unsigned long long)X);
        /* runs of one owner: split at edges and where a pair swaps (once
         * per row at most), plus the background either side */
        uint64_t runs = min64(3 + E + A * (A > 0 ? A - 1 : 0) / 2, w);
        FZ_CHECK(S >= rows && S <= rows * runs, "zline spans %llu not in [%llu, %llu]",
                 (unsigned long long)S, (unsigned long long)rows, (unsigned long long)(rows * runs));
        FZ_CHECK(D <= rows * A * w, "zline depth_evals %llu > rows * A * W = %llu",
                 (unsigned long long)D, (unsigned long long)(rows * A * w));
        FZ_CHECK(P == rows * w, "zline pixels_shaded %llu != rows * W = %llu", (unsigned long long)P,
                 (unsigned long long)(rows * w));
    }
}

static void band_begin(band_ctx *c, int rows)
{
    memset(c->buf, CANARY, c->total);
    g_fill.on = c->mode == ZS_MODE_SPAN;
    g_fill.base = c->buf + GUARD;
    g_fill.stride = c->stride;
    g_fill.bpp = c->o->bpp;
    g_fill.w = c->s->cfg.width;
    g_fill.rows = rows;
    g_fill.calls = 0;
    g_fill.empty = 0;
    memset(g_fill.cnt, 0, sizeof g_fill.cnt);
}

/* After a band: guards, padding, exactly-once fills, the work bound, copy out. */
static void band_end(band_ctx *c, int y0, int rows)
{
    const scene *s = c->s;
    frame_out *o = c->o;
    int w = s->cfg.width;
    size_t rowbytes = (size_t)w * o->bpp;
    const zs_stats *now = zs_frame_stats(c->r);
    for (size_t i = 0; i < GUARD; i++) {
        FZ_CHECK(c->buf[i] == CANARY, "guard byte %zu before the band written", i);
        FZ_CHECK(c->buf[c->total - 1 - i] == CANARY, "guard byte %zu after the band written", i);
    }
    for (int y = 0; y < rows; y++) {
        const uint8_t *row = c->buf + GUARD + (size_t)y * c->stride;
        for (size_t k = rowbytes; k < c->stride; k++)
            FZ_CHECK(row[k] == CANARY, "row %d padding byte %zu written (stride %zu)", y0 + y, k,
                     c->stride);
        memcpy(o->img + (size_t)(y0 + y) * rowbytes, row, rowbytes);
        o->rendered[y0 + y] = 1;
    }
    /* rows of the buffer past this band stay untouched */
    for (size_t i = GUARD + (size_t)rows * c->stride; i < c->total - GUARD; i++)
        FZ_CHECK(c->buf[i] == CANARY, "byte %zu past the band's %d rows written", i, rows);
    if (c->mode == ZS_MODE_SPAN) {
        FZ_CHECK(g_fill.calls > 0,
                 "no span fill counted in a span band: span.c no longer fills through "
                 "zs_fill_flat/zs_fill_gouraud; update tests/fuzz/span_counted.c");
        for (int y = 0; y < rows; y++)
            for (int x = 0; x < w; x++)
                FZ_CHECK(g_fill.cnt[y][x] == 1, "span mode wrote pixel (%d,%d) %u times", x, y0 + y,
                         g_fill.cnt[y][x]);
        FZ_CHECK(g_fill.calls == now->spans - c->prev.spans,
                 "stats.spans counted %u spans, %lu fills seen", now->spans - c->prev.spans,
                 g_fill.calls);
        g_empty_spans += g_fill.empty;
    }
    check_work(&c->prev, now, (uint64_t)rows, (uint64_t)w, c->mode, &s->cfg);
    c->prev = *now;
    o->nrendered += rows;
    c->bands++;
    g_fill.on = 0;
}

static int band_cb(void *user, int y0, int rows, const void *buf, size_t stride)
{
    band_ctx *c = (band_ctx *)user;
    FZ_CHECK(buf == c->buf + GUARD && stride == c->stride, "band callback got another buffer");
    FZ_CHECK(y0 >= 0 && rows >= 1 && rows <= c->s->band && y0 + rows <= c->s->cfg.height,
             "band callback rows %d+%d (band %d, height %d)", y0, rows, c->s->band,
             c->s->cfg.height);
    band_end(c, y0, rows);
    if (c->s->stop_after && c->bands >= c->s->stop_after)
        return 1;
    band_begin(c, c->s->band); /* the next band is rendered after we return */
    return 0;
}

static void check_stats_identity(const zs_stats *s, const zs_config *cfg)
{
    FZ_CHECK(s->tris_submitted ==
                 s->tris_culled + s->tris_rejected + s->tris_empty + s->tris_dropped + s->tris_stored,
             "submitted %u != culled %u + rejected %u + empty %u + dropped %u + stored %u",
             s->tris_submitted, s->tris_culled, s->tris_rejected, s->tris_empty, s->tris_dropped,
             s->tris_stored);
    FZ_CHECK(s->records >= s->tris_stored && s->records <= cfg->max_triangles,
             "records %u (stored %u, pool %u)", s->records, s->tris_stored, cfg->max_triangles);
    FZ_CHECK(s->tris_stored == 0 || s->records > 0, "stored without records");
    FZ_CHECK(s->verts_stored <= cfg->max_vertices, "verts_stored %u > pool %u", s->verts_stored,
             cfg->max_vertices);
    FZ_CHECK(s->tris_clipped <= s->tris_submitted, "clipped %u > submitted %u", s->tris_clipped,
             s->tris_submitted);
    /* capacity policy: a dropped triangle or piece means a full pool, and
     * every dropped triangle lost at least one record */
    FZ_CHECK(s->records_dropped >= s->tris_dropped, "records_dropped %u < tris_dropped %u",
             s->records_dropped, s->tris_dropped);
    FZ_CHECK(s->records_dropped == 0 || s->records == cfg->max_triangles || s->verts_dropped > 0,
             "dropped %u records with room in both pools (records %u/%u, verts %u/%u)",
             s->records_dropped, s->records, cfg->max_triangles, s->verts_stored, cfg->max_vertices);
    FZ_CHECK(s->verts_dropped == 0 || s->verts_stored == cfg->max_vertices,
             "vertices dropped (%u) with room in the pool (%u/%u)", s->verts_dropped,
             s->verts_stored, cfg->max_vertices);
}

/* aa: the A-buffer mode asked for after the shading (-1: none asked) */
static void run_frame(zs_renderer *r, const scene *s, zs_visibility mode, int id16, int aa,
                      frame_out *o)
{
    zs_status st;
    zt_recs_clear(&o->recs);
    zs_set_setup_hook(r, zt_recs_hook, &o->recs);
    memset(o->rendered, 0, sizeof o->rendered);
    o->nrendered = 0;
    o->complete = 0;
    st = zs_frame_begin(r, &s->cam, mode);
    FZ_CHECK(st == ZS_OK, "frame_begin returned %d (%s) on a camera that passed before", (int)st,
             zs_strerror(st));
    const zs_stats *now = zs_frame_stats(r);
    {
        static const zs_stats zero;
        FZ_CHECK(memcmp(now, &zero, sizeof zero) == 0, "frame_begin did not clear the statistics");
    }
    /* shading */
    o->fmt = ZS_FMT_RGB565_BE;
    if (s->call_shading || id16) {
        zs_shade_params p = s->call_shading ? s->sp : zs_shade_default();
        unsigned allowed = s->call_shading ? s->shade_allowed : BIT(ZS_OK);
        if (id16) {
            if (!(allowed & BIT(ZS_OK)))
                p = zs_shade_default();
            p.format = ZS_FMT_ID16;
            allowed = shade_allowed(&p, &s->cfg);
        }
        st = zs_frame_shading(r, &p);
        FZ_CHECK(BIT(st) & allowed, "frame_shading returned %d (%s), allowed %#x", (int)st,
                 zs_strerror(st), allowed);
        if (st == ZS_OK)
            o->fmt = p.format;
    }
    o->bpp = zs_format_bytes(o->fmt);
    FZ_CHECK(o->bpp >= 1 && o->bpp <= 3, "format %d has %u bytes", (int)o->fmt, o->bpp);
    if (aa >= 0) {
        /* the header: needs ZS_CFG_ABUFFER and span mode unless off */
        int can = aa == ZS_AA_OFF || ((s->cfg.flags & ZS_CFG_ABUFFER) && mode == ZS_MODE_SPAN);
        st = zs_frame_antialias(r, (zs_aa_mode)aa);
        FZ_CHECK(st == (can ? ZS_OK : ZS_ERR_MODE), "frame_antialias(%d) in mode %d, flags %#x "
                 "returned %d (%s)", aa, (int)mode, s->cfg.flags, (int)st, zs_strerror(st));
        if (!can)
            aa = ZS_AA_OFF;
    }
    /* draws */
    uint32_t tags = 0;
    for (int i = 0; i < s->nmesh; i++) {
        const fmesh *f = &s->mesh[i];
        zs_stats before = *now;
        size_t nrec = o->recs.n;
        if (aa == ZS_AA_TRANSPARENT) {
            uint8_t op = (uint8_t)(s->aa & 2u ? 255u - (unsigned)(i * 85) : (unsigned)(i * 85));
            st = zs_draw_opacity(r, op);
            FZ_CHECK(st == ZS_OK, "draw_opacity(%u) returned %d (%s)", op, (int)st,
                     zs_strerror(st));
        } else if (aa >= 0 && i == 0) {
            st = zs_draw_opacity(r, 128);
            FZ_CHECK(st == ZS_ERR_MODE, "draw_opacity outside a transparent frame returned %d",
                     (int)st);
        }
        st = zs_draw(r, &f->m, f->has_model ? &f->model : NULL);
        FZ_CHECK(BIT(st) & f->allowed, "draw %d returned %d (%s), allowed %#x", i, (int)st,
                 zs_strerror(st), f->allowed);
        o->draw_ok[i] = st == ZS_OK;
        o->first_tag[i] = (uint16_t)(tags + 1);
        if (st != ZS_OK) {
            FZ_CHECK(memcmp(&before, now, sizeof before) == 0 && o->recs.n == nrec,
                     "a rejected draw changed the statistics or stored records");
        } else {
            tags += f->m.triangle_count;
            FZ_CHECK(now->tris_submitted == before.tris_submitted + f->m.triangle_count,
                     "submitted %u -> %u for %u triangles", before.tris_submitted,
                     now->tris_submitted, f->m.triangle_count);
        }
        check_stats_identity(now, &s->cfg);
        FZ_CHECK(now->records == o->recs.n, "records %u != %zu hook calls", now->records,
                 o->recs.n);
    }
    for (size_t i = 0; i < o->recs.n; i++) {
        const zt_rec *t = &o->recs.v[i];
        FZ_CHECK(t->tag >= 1 && t->tag <= tags, "record %zu has tag %u of %u", i, t->tag, tags);
        FZ_CHECK(i == 0 || t->tag >= o->recs.v[i - 1].tag, "record tags out of submission order");
        for (int k = 0; k < 3; k++)
            FZ_CHECK(t->z[k] <= ZS_DEPTH_ONE, "record %zu depth %u above 1.0", i, t->z[k]);
        for (int k = 0; k < 6; k++) {
            int32_t lim = 16 * 3 * (k % 2 ? s->cfg.height : s->cfg.width); /* guard band */
            FZ_CHECK(t->xy[k] > -lim && t->xy[k] < lim, "record %zu coordinate %d = %d outside "
                     "the guard band", i, k, t->xy[k]);
        }
        FZ_CHECK(zt_area2(t->xy) != 0, "record %zu has zero area", i);
    }
    /* render */
    band_ctx c;
    memset(&c, 0, sizeof c);
    c.r = r;
    c.s = s;
    c.o = o;
    c.mode = mode;
    c.stride = (size_t)s->cfg.width * o->bpp + (size_t)s->pad;
    c.total = GUARD + c.stride * (size_t)s->band + GUARD;
    c.buf = malloc(c.total);
    c.prev = *now;
    if (s->use_frame_api) {
        band_begin(&c, s->band);
        st = zs_render_frame(r, c.buf + GUARD, c.stride, s->band, band_cb, &c);
        FZ_CHECK(st == ZS_OK, "render_frame returned %d (%s)", (int)st, zs_strerror(st));
    } else {
        for (int y = s->start_row; y < s->cfg.height; y += s->band) {
            int n = s->band < s->cfg.height - y ? s->band : s->cfg.height - y;
            band_begin(&c, n);
            st = zs_render_rows(r, y, n, c.buf + GUARD, c.stride);
            FZ_CHECK(st == ZS_OK, "render_rows(%d, %d) returned %d (%s)", y, n, (int)st,
                     zs_strerror(st));
            band_end(&c, y, n);
        }
    }
    o->complete = o->rendered[s->cfg.height - 1];
    g_fill.on = 0;
    free(c.buf);
    o->st = *now;
    const zs_stats *f = &o->st;
    FZ_CHECK(f->rows == (uint32_t)o->nrendered, "stats.rows %u, %d rendered", f->rows,
             o->nrendered);
    if (mode == ZS_MODE_WARNOCK) {
        /* Warnock counts a record drawn or skipped in the first band it
         * reaches (warnock.c gather): never both */
        FZ_CHECK(f->tris_drawn + f->records_skipped <= f->records,
                 "warnock drawn %u + skipped %u > records %u", f->tris_drawn, f->records_skipped,
                 f->records);
        return;
    }
    FZ_CHECK(f->tris_drawn + f->records_skipped <= f->records,
             "drawn %u + skipped %u > records %u", f->tris_drawn, f->records_skipped, f->records);
    /* (an anti-aliased frame also stores records that reach sub-samples but
     * no pixel centre: the walk never activates those) */
    if (o->complete && aa <= ZS_AA_OFF)
        FZ_CHECK(f->tris_drawn + f->records_skipped == f->records,
                 "complete frame: drawn %u + skipped %u != records %u", f->tris_drawn,
                 f->records_skipped, f->records);
    FZ_CHECK(f->max_active_edges <= s->cfg.max_active_edges &&
                 f->max_active_edges <= 2 * f->tris_drawn,
             "max_active_edges %u (pool %u, drawn %u)", f->max_active_edges,
             s->cfg.max_active_edges, f->tris_drawn);
    /* a triangle is skipped only when all max_active_edges / 2 active slots
     * are taken; those triangles' edges are then all on that row */
    FZ_CHECK(f->records_skipped == 0 || f->max_active_edges >= s->cfg.max_active_edges / 2u,
             "edge pool drops (%u) with the pool never full (max %u of %u)", f->records_skipped,
             f->max_active_edges, s->cfg.max_active_edges);
}

/* ------------------------------------------------------------------ */
/* Independent pixel packing (from the header's format descriptions)   */
/* ------------------------------------------------------------------ */

static void pack(zs_format fmt, uint32_t rgb, uint8_t out[3])
{
    uint32_t r = (rgb >> 16) & 255u, g = (rgb >> 8) & 255u, b = rgb & 255u;
    uint16_t v = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    switch (fmt) {
    case ZS_FMT_RGB565_BE: out[0] = (uint8_t)(v >> 8); out[1] = (uint8_t)v; break;
    case ZS_FMT_RGB565: memcpy(out, &v, 2); break;
    case ZS_FMT_RGB666: out[0] = (uint8_t)(r & 0xFC); out[1] = (uint8_t)(g & 0xFC); out[2] = (uint8_t)(b & 0xFC); break;
    case ZS_FMT_GRAY8: out[0] = (uint8_t)((77 * r + 150 * g + 29 * b) >> 8); break;
    case ZS_FMT_RGB888: out[0] = (uint8_t)r; out[1] = (uint8_t)g; out[2] = (uint8_t)b; break;
    default: memset(out, 0, 3); break;
    }
}

/* Colour source of triangle t of a mesh in flat unlit shading (header order). */
static uint32_t flat_color(const zs_mesh *m, unsigned t)
{
    if (m->face_colors)
        return m->face_colors[t] & 0xFFFFFFu;
    if (m->vertex_colors) {
        uint32_t out = 0;
        for (int s = 0; s < 24; s += 8) {
            uint32_t sum = 0;
            for (int k = 0; k < 3; k++)
                sum += (m->vertex_colors[m->indices[3 * t + (unsigned)k]] >> s) & 255u;
            out |= ((sum + 1u) / 3u) << s;
        }
        return out;
    }
    return m->color & 0xFFFFFFu;
}

/* The records of b are the first records of a (field by field: zt_rec has padding). */
static int recs_prefix(const zt_recs *a, const zt_recs *b)
{
    if (b->n > a->n)
        return 0;
    for (size_t i = 0; i < b->n; i++) {
        const zt_rec *x = &a->v[i], *y = &b->v[i];
        if (x->tag != y->tag || memcmp(x->xy, y->xy, sizeof x->xy) != 0 ||
            memcmp(x->z, y->z, sizeof x->z) != 0)
            return 0;
    }
    return 1;
}

/* Frame b equals frame a (span mode) byte for byte, with the same rows,
 * geometry statistics and setup records; walk: the active-edge figures
 * too (the modes that walk the same active list). */
static void same_frames(const char *what, const frame_out *a, const frame_out *b, int walk,
                        int w, int h)
{
    const zs_stats *p = &a->st, *q = &b->st;
    FZ_CHECK(a->fmt == b->fmt && a->nrendered == b->nrendered,
             "span and %s frames differ in format or rows", what);
#define SAME(f) FZ_CHECK(p->f == q->f, "span " #f " %u != %s %u", p->f, what, q->f)
    SAME(tris_submitted); SAME(tris_culled); SAME(tris_rejected); SAME(tris_clipped);
    SAME(tris_empty); SAME(tris_dropped); SAME(tris_stored); SAME(records); SAME(records_dropped);
    SAME(verts_stored); SAME(verts_dropped); SAME(saturated); SAME(rows);
    if (walk) {
        SAME(tris_drawn); SAME(records_skipped); SAME(max_active_edges);
    }
#undef SAME
    FZ_CHECK(recs_prefix(&b->recs, &a->recs) && a->recs.n == b->recs.n,
             "setup records differ between span and %s", what);
    size_t rowbytes = (size_t)w * a->bpp;
    for (int y = 0; y < h; y++) {
        FZ_CHECK(a->rendered[y] == b->rendered[y], "row %d rendered in span or %s only", y, what);
        if (!a->rendered[y])
            continue;
        const uint8_t *u = a->img + (size_t)y * rowbytes, *v = b->img + (size_t)y * rowbytes;
        if (memcmp(u, v, rowbytes) != 0) {
            size_t i = 0;
            while (u[i] == v[i])
                i++;
            FZ_CHECK(0, "span != %s at row %d pixel %zu (format %d): %02x vs %02x", what, y,
                     i / a->bpp, (int)a->fmt, u[i], v[i]);
        }
    }
}

/* floor(v / 16) */
static int floor16(int32_t v) { return (int)(v >= 0 ? v / 16 : -((15 - v) / 16)); }


static uint16_t id_at(const frame_out *o, int w, int x, int y)
{
    uint16_t v;
    memcpy(&v, o->img + ((size_t)y * (size_t)w + (size_t)x) * 2, 2);
    return v;
}

/* ------------------------------------------------------------------ */
/* The entry point                                                      */
/* ------------------------------------------------------------------ */

/* FUZZ_VERBOSE=1 ./fuzz_frame input: prints the decoded scene (for repros). */
/* ------------------------------------------------------------------ */
/* The 1-bit formats                                                    */
/* ------------------------------------------------------------------ */

static uint8_t g_grey[MAXW * MAXH], g_bits[MAXW * MAXH], g_mono[2][MAXW * MAXH];
static int g_err[(MAXW + 2) * (MAXH + 1)];

/* This harness's own dithering of a GRAY8 frame (the header's rules). */
static void dither_ref(const uint8_t *g, int w, int h, int diffuse, uint8_t *bits)
{
    static const uint8_t bayer[8][8] = {
        {0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
        {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
        {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
        {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21}};
    memset(g_err, 0, sizeof g_err);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (!diffuse) {
                bits[y * w + x] = 128 * g[y * w + x] > 255 * (2 * bayer[y & 7][x & 7] + 1);
                continue;
            }
            int *e0 = &g_err[y * (w + 2) + x + 1], *e1 = e0 + (w + 2);
            int v = g[y * w + x] + *e0, on = v >= 128, e = v - (on ? 255 : 0);
            int d1 = e / 16, d3 = 3 * e / 16, d5 = 5 * e / 16;
            bits[y * w + x] = (uint8_t)on;
            e0[1] += e - d1 - d3 - d5;
            e1[-1] += d3;
            e1[0] += d5;
            e1[1] += d1;
        }
}

static int bit_of(const uint8_t *img, zs_format fmt, int w, int x, int y)
{
    if (fmt == ZS_FMT_MONO_PAGE)
        return (img[(y / 8) * w + x] >> (y % 8)) & 1;
    return (img[y * ((w + 7) / 8) + x / 8] >> (7 - x % 8)) & 1;
}

/* One whole frame in `fmt` with the scene's look and ZS_MONO_* flags mono,
 * bands of `band` rows; returns 0 when the shading was refused. */
static int mono_frame(zs_renderer *r, const scene *s, zs_visibility mode, zs_format fmt,
                      unsigned mono, int band, uint8_t *img)
{
    int w = s->cfg.width, h = s->cfg.height;
    zs_shade_params p = s->call_shading ? s->sp : zs_shade_default();
    p.format = fmt;
    p.mono = (uint8_t)mono;
    FZ_CHECK(zs_frame_begin(r, &s->cam, mode) == ZS_OK, "mono frame_begin");
    if (zs_frame_shading(r, &p) != ZS_OK)
        return 0;
    for (int i = 0; i < s->nmesh; i++)
        zs_draw(r, &s->mesh[i].m, s->mesh[i].has_model ? &s->mesh[i].model : NULL);
    size_t stride = zs_format_stride(fmt, (unsigned)w);
    for (int y = 0; y < h; y += band) {
        int n = band < h - y ? band : h - y;
        uint8_t *dst = fmt == ZS_FMT_GRAY8      ? img + (size_t)y * stride
                       : fmt == ZS_FMT_MONO_PAGE ? img + (size_t)(y / 8) * stride
                                                 : img + (size_t)y * stride;
        zs_status st = zs_render_rows(r, y, n, dst, stride);
        FZ_CHECK(st == ZS_OK, "mono render_rows returned %d", (int)st);
    }
    return 1;
}

/* Is pixel (x, y)'s centre within half a pixel (Chebyshev) of an edge of
 * a record of the ID16 frame? Lines are drawn on the pixel nearest where an
 * edge crosses a row's or a column's centre line. In 1/16 px: the edge's
 * points within 8 + 1 of the centre in x and in y form one interval. */
static int near_record_edge(const frame_out *id, int x, int y)
{
    int64_t cx = 16 * x + 8, cy = 16 * y + 8, m = 9;
    for (size_t i = 0; i < id->recs.n; i++)
        for (int k = 0; k < 3; k++) {
            const int32_t *a = &id->recs.v[i].xy[2 * k], *b = &id->recs.v[i].xy[2 * ((k + 1) % 3)];
            /* a + t (b - a), t in [0, 1] (scaled by 2^20), inside the box */
            int64_t lo = 0, hi = 1 << 20, d[2] = {b[0] - a[0], b[1] - a[1]};
            int64_t c[2] = {cx - a[0], cy - a[1]};
            for (int j = 0; j < 2 && lo <= hi; j++) {
                if (d[j] == 0) {
                    if (c[j] < -m || c[j] > m) lo = hi + 1;
                    continue;
                }
                int64_t t0 = (c[j] - m) * (1 << 20) / d[j], t1 = (c[j] + m) * (1 << 20) / d[j];
                if (t0 > t1) { int64_t t = t0; t0 = t1; t1 = t; }
                if (t0 - 1 > lo) lo = t0 - 1;
                if (t1 + 1 < hi) hi = t1 + 1;
            }
            if (lo <= hi) return 1;
        }
    return 0;
}

/* Filled 1-bit frames equal this harness's dithering of the GRAY8 frame in
 * both modes; line drawings are the same in both modes and layouts, and a
 * drawn pixel shows another triangle than a neighbour in the ID16 frame (a
 * boundary between draws) or lies by an edge of one of its records (when
 * no triangle fell between pixel centres: the edges of those are drawn
 * too, and the frame's records do not show them). */
static void check_mono(const scene *s, const frame_out *id)
{
    static uint8_t arena[ZS_ARENA_BYTES_CFG(MAXW, MAXH, 600, 600, 64, ZS_CFG_MONO | ZS_CFG_LINES)];
    zs_config c = s->cfg;
    zs_renderer r;
    int w = c.width, h = c.height, band = 1 + (s->misuse + (unsigned)w) % 11u;
    c.flags = (uint16_t)((c.flags | ZS_CFG_MONO | ZS_CFG_LINES) & ~ZS_CFG_ABUFFER);
    if (zs_arena_bytes(&c) > sizeof arena || zs_init(&r, arena, sizeof arena, &c) != ZS_OK)
        return;
    if (!mono_frame(&r, s, ZS_MODE_SPAN, ZS_FMT_GRAY8, 0, h, g_grey))
        return;
    for (int k = 0; k < 2; k++) {
        zs_format fmt = k ? ZS_FMT_MONO_MSB : ZS_FMT_MONO_PAGE;
        int ok = mono_frame(&r, s, k ? ZS_MODE_SPAN : (NO_ZLINE(c) ? ZS_MODE_SPAN : ZS_MODE_ZLINE),
                            fmt, k ? ZS_MONO_DIFFUSE : 0u, band, g_mono[0]);
        FZ_CHECK(ok, "mono shading refused where GRAY8 was taken");
        dither_ref(g_grey, w, h, k, g_bits);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                FZ_CHECK(bit_of(g_mono[0], fmt, w, x, y) == g_bits[y * w + x],
                         "1-bit frame (%s) differs from the dithered grey at (%d,%d)",
                         k ? "msb, diffusion" : "page, bayer", x, y);
    }
    /* line drawings */
    if (!mono_frame(&r, s, ZS_MODE_SPAN, ZS_FMT_MONO_PAGE, ZS_MONO_LINES, band, g_mono[0]))
        return;
    FZ_CHECK(mono_frame(&r, s, NO_ZLINE(c) ? ZS_MODE_SPAN : ZS_MODE_ZLINE, ZS_FMT_MONO_MSB,
                        ZS_MONO_LINES, 8, g_mono[1]), "lines refused the second time");
    /* no record kept but the stored ones (a clipped triangle counted stored
     * or dropped may have left a centre-less piece kept) */
    int all_hold_centres = r.priv.n_tris == zs_frame_stats(&r)->records;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int a = bit_of(g_mono[0], ZS_FMT_MONO_PAGE, w, x, y);
            FZ_CHECK(a == bit_of(g_mono[1], ZS_FMT_MONO_MSB, w, x, y),
                     "line drawings differ (span page / zline msb) at (%d,%d)", x, y);
            if (!a || !id->rendered[y] || (y > 0 && !id->rendered[y - 1]) ||
                (y + 1 < h && !id->rendered[y + 1]))
                continue;
            uint16_t t = id_at(id, w, x, y);
            FZ_CHECK(!all_hold_centres || (x > 0 && id_at(id, w, x - 1, y) != t) ||
                         (y > 0 && id_at(id, w, x, y - 1) != t) ||
                         (x + 1 < w && id_at(id, w, x + 1, y) != t) ||
                         (y + 1 < h && id_at(id, w, x, y + 1) != t) || near_record_edge(id, x, y),
                     "line pixel (%d,%d) inside one triangle (tag %u), by none of its edges", x,
                     y, t);
        }
}

static int g_verbose;

static void dump_scene(const scene *s)
{
    const zs_camera *c = &s->cam;
    fprintf(stderr, "config %ux%u tris %u verts %u edges %u flags %#x; arena offset %u; aa %#x\n",
            s->cfg.width, s->cfg.height, s->cfg.max_triangles, s->cfg.max_vertices,
            s->cfg.max_active_edges, s->cfg.flags, s->arena_off, s->aa);
    fprintf(stderr, "camera kind %d view", s->cam_kind);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            fprintf(stderr, " %d", c->view.m[i][j]);
    fprintf(stderr, "; fov %d near %d far %d (has %u %u)\n", c->fov_deg, c->near_z, c->far_z,
            c->has_view, c->has_projection);
    fprintf(stderr, "shading call %d: shading %d format %d bg %#x ambient %d lights %u fog %u "
            "[%d, %d] allowed %#x\n", s->call_shading, (int)s->sp.shading, (int)s->sp.format,
            s->sp.background, s->sp.ambient, s->sp.light_count, s->sp.fog.enabled,
            s->sp.fog.start, s->sp.fog.end, s->shade_allowed);
    for (int i = 0; i < s->nmesh; i++) {
        const zs_mesh *m = &s->mesh[i].m;
        fprintf(stderr, "mesh %d: %u verts %u tris scale %d colour %#x fc %d vc %d fn %d vn %d "
                "allowed %#x\n  positions", i, m->vertex_count, m->triangle_count, m->scale,
                m->color, !!m->face_colors, !!m->vertex_colors, !!m->face_normals,
                !!m->vertex_normals, s->mesh[i].allowed);
        for (unsigned k = 0; m->positions && k < 3u * m->vertex_count; k++)
            fprintf(stderr, " %d", m->positions[k]);
        fprintf(stderr, "\n  indices");
        for (unsigned k = 0; m->indices && k < 3u * m->triangle_count; k++)
            fprintf(stderr, " %u", m->indices[k]);
        fprintf(stderr, "\n  model %s", s->mesh[i].has_model ? "" : "NULL");
        for (int a = 0; s->mesh[i].has_model && a < 3; a++)
            for (int b = 0; b < 4; b++)
                fprintf(stderr, " %d", s->mesh[i].model.m[a][b]);
        fprintf(stderr, "\n");
    }
    fprintf(stderr, "band %d start %d frame_api %d stop_after %d pad %d misuse %u\n", s->band,
            s->start_row, s->use_frame_api, s->stop_after, s->pad, s->misuse);
}

static void dump_recs(const char *what, const zt_recs *rs)
{
    for (size_t i = 0; i < rs->n; i++)
        fprintf(stderr, "%s record %zu tag %u xy %d %d %d %d %d %d z %u %u %u\n", what, i,
                rs->v[i].tag, rs->v[i].xy[0], rs->v[i].xy[1], rs->v[i].xy[2], rs->v[i].xy[3],
                rs->v[i].xy[4], rs->v[i].xy[5], rs->v[i].z[0], rs->v[i].z[1], rs->v[i].z[2]);
}

static scene g_s;
static frame_out g_span, g_zline, g_id, g_warn, g_plain, g_aa;
static zt_recs g_big_recs;
static uint8_t g_cov_ok[MAXH][MAXW], g_cov_any[MAXH][MAXW];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    g_verbose = getenv("FUZZ_VERBOSE") != NULL;
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_reader d;
    scene *s = &g_s;
    zs_status st;
    fz_init(&d, data, size);
    memset(s, 0, sizeof *s);
    if (!decode_scene(&d, s))
        return 0;
    if (g_verbose)
        dump_scene(s);
    const zs_config *cfg = &s->cfg;
    int W = cfg->width, H = cfg->height;

    size_t need = zs_arena_bytes(cfg);
#ifdef ZS_CFG_NO_ZLINE
    if (!ZS_CFG_FLAGS_OK(cfg->flags)) {
        static uint8_t some[64];
        zs_renderer r0;
        FZ_CHECK(need == 0, "zs_arena_bytes with unknown flags %#x = %zu", cfg->flags, need);
        st = zs_init(&r0, some, sizeof some, cfg);
        FZ_CHECK(st == ZS_ERR_ARGUMENT, "zs_init with unknown flags %#x returned %d", cfg->flags,
                 (int)st);
        return 0;
    }
#endif
    FZ_CHECK(need == ARENA_BYTES(*cfg), "zs_arena_bytes %zu", need);
    /* exact-size heap block at the chosen misalignment: ASan sees any overrun */
    uint8_t *block = malloc(need + s->arena_off);
    uint8_t *arena = block + s->arena_off;
    zs_renderer r;
    FZ_CHECK(zs_init(&r, arena, need - 1, cfg) == ZS_ERR_ARENA_SMALL, "arena of need-1 accepted");
    st = zs_init(&r, arena, need, cfg);
    FZ_CHECK(st == ZS_OK, "zs_init returned %d (%s)", (int)st, zs_strerror(st));

    /* a camera that failed (or was never completed) is refused; so is a mode
     * the core does not have (span, zline, priority and Warnock it has) */
    int cam_ok = s->cam.has_view == 1 && s->cam.has_projection == 1;
    if (s->bad_mode >= 0 && s->bad_mode != ZS_MODE_SPAN && s->bad_mode != ZS_MODE_ZLINE &&
        s->bad_mode != ZS_MODE_PRIORITY && s->bad_mode != ZS_MODE_WARNOCK) {
        st = zs_frame_begin(&r, &s->cam, (zs_visibility)s->bad_mode);
        FZ_CHECK(st == ZS_ERR_MODE || (!cam_ok && st == ZS_ERR_CAMERA),
                 "frame_begin(mode %d) returned %d (%s)", (int)s->bad_mode, (int)st,
                 zs_strerror(st));
    }
    st = zs_frame_begin(&r, &s->cam, ZS_MODE_SPAN);
    if (!cam_ok) {
        FZ_CHECK(st == ZS_ERR_CAMERA, "frame_begin with an incomplete camera returned %d (%s)",
                 (int)st, zs_strerror(st));
        FZ_CHECK(zs_draw(&r, &s->mesh[0].m, NULL) == ZS_ERR_STATE, "draw without a frame");
        free(block);
        return 0;
    }
    if (st == ZS_ERR_FOV) {
        /* allowed only where cot(fov/2) * height / width does not fit */
        FZ_CHECK(s->cam.fov_deg < ZS_FX(1), "frame_begin refused fov %d with ZS_ERR_FOV",
                 s->cam.fov_deg);
        free(block);
        return 0;
    }
    FZ_CHECK(st == ZS_OK, "frame_begin returned %d (%s)", (int)st, zs_strerror(st));

    /* span and zline in the decoded format */
    run_frame(&r, s, ZS_MODE_SPAN, 0, -1, &g_span);
    if (g_verbose)
        dump_recs("span", &g_span.recs);
    if (NO_ZLINE(*cfg)) {
        /* the z-buffer line was left out: zline frames are refused and the
         * span frame stands alone (still checked below against the reference) */
        st = zs_frame_begin(&r, &s->cam, ZS_MODE_ZLINE);
        FZ_CHECK(st == ZS_ERR_MODE, "ZS_MODE_ZLINE without a z-buffer line returned %d", (int)st);
        zt_recs keep = g_zline.recs; /* each frame owns its record array */
        g_zline = g_span;
        g_zline.recs = keep;
        zt_recs_clear(&g_zline.recs);
        for (size_t i = 0; i < g_span.recs.n; i++)
            zt_recs_hook(&g_zline.recs, g_span.recs.v[i].tag, g_span.recs.v[i].xy,
                         g_span.recs.v[i].z);
    } else {
        run_frame(&r, s, ZS_MODE_ZLINE, 0, -1, &g_zline);
    }
    same_frames("zline", &g_span, &g_zline, 1, W, H);

    /* ID16 frame: coverage against the reference rasterizer */
    const frame_out *id = &g_span;
    unsigned last_bpp = g_zline.bpp;
    if (g_span.fmt != ZS_FMT_ID16) {
        last_bpp = 2;
        run_frame(&r, s, ZS_MODE_SPAN, 1, -1, &g_id);
        id = &g_id;
        FZ_CHECK(g_id.fmt == ZS_FMT_ID16, "ID16 frame in format %d", (int)g_id.fmt);
        FZ_CHECK(g_id.st.records == g_span.st.records && g_id.nrendered == g_span.nrendered,
                 "ID16 frame stored %u records (%d rows), colour frame %u (%d rows)",
                 g_id.st.records, g_id.nrendered, g_span.st.records, g_span.nrendered);
    }
    memset(g_cov_ok, 0, sizeof g_cov_ok);
    memset(g_cov_any, 0, sizeof g_cov_any);
    for (size_t i = 0; i < id->recs.n; i++) {
        const zt_rec *t = &id->recs.v[i];
        int x0, y0, x1, y1;
        if (!zt_bbox(t->xy, W, H, &x0, &y0, &x1, &y1))
            continue;
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++)
                if (id->rendered[y] && zt_covers(t->xy, x, y)) {
                    g_cov_any[y][x] = 1;
                    if (id_at(id, W, x, y) == t->tag)
                        g_cov_ok[y][x] = 1;
                }
    }
    for (int y = 0; y < H; y++) {
        if (!id->rendered[y])
            continue;
        for (int x = 0; x < W; x++) {
            uint16_t t = id_at(id, W, x, y);
            FZ_CHECK(!t || g_cov_ok[y][x], "pixel (%d,%d) shows tag %u, which no record of that "
                     "tag covers", x, y, t);
            FZ_CHECK(t || !g_cov_any[y][x] || id->st.records_skipped > 0,
                     "pixel (%d,%d) covered by a record but shows no triangle", x, y);
        }
    }

    /* colours of the decoded format, from the ID16 picture */
    if (g_span.fmt != ZS_FMT_ID16) {
        const zs_shade_params *p = &s->sp;
        int custom = s->call_shading && (s->shade_allowed & BIT(ZS_OK));
        uint32_t bg = custom ? p->background : 0;
        int flat_unlit = !custom || (p->shading == ZS_SHADE_FLAT && p->light_count == 0 &&
                                     p->ambient == ZS_FX_ONE && !p->fog.enabled);
        uint8_t want[3];
        unsigned bpp = g_span.bpp;
        for (int y = 0; y < H; y++) {
            if (!id->rendered[y])
                continue;
            for (int x = 0; x < W; x++) {
                uint16_t t = id_at(id, W, x, y);
                const uint8_t *px = g_span.img + ((size_t)y * (size_t)W + (size_t)x) * bpp;
                if (!t) {
                    pack(g_span.fmt, bg, want);
                } else if (flat_unlit) {
                    int mi = s->nmesh - 1;
                    while (mi > 0 && (!g_span.draw_ok[mi] || g_span.first_tag[mi] > t))
                        mi--;
                    FZ_CHECK(g_span.draw_ok[mi], "tag %u from a rejected draw", t);
                    pack(g_span.fmt, flat_color(&s->mesh[mi].m, (unsigned)(t - g_span.first_tag[mi])),
                         want);
                } else {
                    continue;
                }
                FZ_CHECK(memcmp(px, want, bpp) == 0,
                         "pixel (%d,%d) tag %u format %d: %02x%02x%02x, want %02x%02x%02x", x, y,
                         t, (int)g_span.fmt, px[0], bpp > 1 ? px[1] : 0, bpp > 2 ? px[2] : 0,
                         want[0], bpp > 1 ? want[1] : 0, bpp > 2 ? want[2] : 0);
            }
        }
    }

    /* capacity policy: large pools store a superset whose first records are ours */
    if (g_span.st.records_dropped > 0 && g_span.st.verts_dropped == 0) {
        static uint8_t big_arena[ZS_ARENA_BYTES(MAXW, MAXH, 4096, 4096, 2)];
        zs_renderer big;
        zs_config bc = zs_config_default((uint16_t)W, (uint16_t)H, 4096, 4096, 2);
        FZ_CHECK(zs_init(&big, big_arena, sizeof big_arena, &bc) == ZS_OK, "big init");
        zt_recs_clear(&g_big_recs);
        zs_set_setup_hook(&big, zt_recs_hook, &g_big_recs);
        FZ_CHECK(zs_frame_begin(&big, &s->cam, ZS_MODE_SPAN) == ZS_OK, "big frame_begin");
        /* (shading does not change what is stored) */
        for (int i = 0; i < s->nmesh; i++)
            zs_draw(&big, &s->mesh[i].m, s->mesh[i].has_model ? &s->mesh[i].model : NULL);
        const zs_stats *bs = zs_frame_stats(&big);
        FZ_CHECK(bs->verts_dropped == 0 && bs->records_dropped == 0, "large pools dropped");
        FZ_CHECK(g_big_recs.n > g_span.recs.n, "large pools stored %zu records, small %zu",
                 g_big_recs.n, g_span.recs.n);
        FZ_CHECK(recs_prefix(&g_big_recs, &g_span.recs),
                 "records of a full pool are not the first records of large pools");
    }

    /* calls out of order on the finished (or stopped) frame */
    {
        uint8_t tmp[MAXW * 3 + 8];
        switch (s->misuse % 6u) {
        case 1:
            if (g_span.complete) {
                st = zs_draw(&r, &s->mesh[0].m, NULL);
                FZ_CHECK(st == ZS_ERR_STATE || (st == ZS_ERR_MESH && !(s->mesh[0].allowed & BIT(ZS_OK))) ||
                             st == ZS_ERR_INDEX,
                         "draw after rendering returned %d", (int)st);
            }
            break;
        case 2: {
            zs_shade_params p = zs_shade_default();
            st = zs_frame_shading(&r, &p);
            FZ_CHECK(st == ZS_ERR_STATE, "shading after rendering returned %d", (int)st);
            break;
        }
        case 3:
            st = zs_render_rows(&r, 0, 1, tmp, sizeof tmp);
            FZ_CHECK(st == ZS_ERR_ROW || st == ZS_ERR_STATE, "render_rows(0) again returned %d",
                     (int)st);
            break;
        case 4:
            st = zs_render_rows(&r, H - 1, 1, tmp, (size_t)W * last_bpp - 1);
            FZ_CHECK(st == ZS_ERR_BUFFER || st == ZS_ERR_ROW || st == ZS_ERR_STATE,
                     "short stride returned %d", (int)st);
            break;
        case 5:
            st = zs_render_rows(&r, 0, 0, tmp, sizeof tmp);
            FZ_CHECK(st == ZS_ERR_ROW || st == ZS_ERR_STATE, "rows = 0 returned %d", (int)st);
            break;
        default: break;
        }
    }
    /* Warnock mode: the span frame byte for byte, in every format and band
     * plan; anti-aliasing is refused there (ZS_ERR_MODE) */
    run_frame(&r, s, ZS_MODE_WARNOCK, 0, s->aa & 4u ? ZS_AA_EDGES : -1, &g_warn);
    /* (with a full active pool each mode leaves out its own records) */
    if (g_span.st.records_skipped == 0 && g_warn.st.records_skipped == 0)
        same_frames("warnock", &g_span, &g_warn, 0, W, H);

    /* The A-buffer. Off, a renderer with it renders as one without; on, the
     * frame keeps to its buffers (band guards, stride padding, ASan on the
     * exact arena), every status is the header's, and rows that no stored
     * record comes within a pixel of are the aliased rows. */
    if (cfg->flags & ZS_CFG_ABUFFER) {
        zs_config pc = *cfg;
        pc.flags = (uint16_t)(pc.flags & ~ZS_CFG_ABUFFER);
        size_t pneed = zs_arena_bytes(&pc);
        FZ_CHECK(pneed > 0 && pneed < need, "arena without the A-buffer %zu, with %zu", pneed,
                 need);
        uint8_t *pblock = malloc(pneed);
        zs_renderer pr;
        FZ_CHECK(zs_init(&pr, pblock, pneed, &pc) == ZS_OK, "init without the A-buffer");
        run_frame(&pr, s, ZS_MODE_SPAN, 0, -1, &g_plain);
        same_frames("no-abuffer", &g_plain, &g_span, 1, W, H);
        free(pblock);

        zs_aa_mode am = s->aa & 1u ? ZS_AA_TRANSPARENT : ZS_AA_EDGES;
        run_frame(&r, s, ZS_MODE_SPAN, 0, (int)am, &g_aa);
        const zs_stats *a = &g_aa.st;
        FZ_CHECK(g_aa.nrendered == g_span.nrendered && g_aa.fmt == g_span.fmt,
                 "A-buffer frame: %d rows, format %d", g_aa.nrendered, (int)g_aa.fmt);
        FZ_CHECK(a->aa_max_fragments <= ZS_ABUFFER_FRAGMENTS &&
                     /* resolved and left aliased (pool full) are disjoint */
                     a->aa_pixels + a->aa_overflow <= (uint32_t)g_aa.nrendered * (uint32_t)W,
                 "A-buffer stats: pixels %u fragments %u max %u overflow %u", a->aa_pixels,
                 a->aa_fragments, a->aa_max_fragments, a->aa_overflow);
        static uint8_t near_rec[MAXH];
        memset(near_rec, 0, sizeof near_rec);
        for (size_t i = 0; i < g_aa.recs.n; i++) {
            const int32_t *xy = g_aa.recs.v[i].xy;
            int32_t lo = xy[1], hi = xy[1];
            for (int k = 3; k < 6; k += 2) {
                lo = xy[k] < lo ? xy[k] : lo;
                hi = xy[k] > hi ? xy[k] : hi;
            }
            for (int y = floor16(lo) - 1; y <= floor16(hi) + 1; y++)
                if (y >= 0 && y < H)
                    near_rec[y] = 1;
        }
        /* (only where the A-buffer frame lost nothing to a full pool: it also
         * stores triangles that cover sub-samples but no centre, so with a
         * small pool it can drop one that the aliased frame kept) */
        size_t rb = (size_t)W * g_aa.bpp;
        int aa_complete = a->records_dropped == 0 && a->verts_dropped == 0 && a->records_skipped == 0;
        for (int y = 0; y < H; y++)
            if (aa_complete && g_aa.rendered[y] && !near_rec[y])
                FZ_CHECK(memcmp(g_aa.img + (size_t)y * rb, g_span.img + (size_t)y * rb, rb) == 0,
                         "A-buffer row %d differs from the aliased row, no record near it", y);
    } else if (s->aa & 8u) {
        /* refused without the flag (ZS_ERR_MODE): the frame stays aliased */
        run_frame(&r, s, ZS_MODE_SPAN, 0, ZS_AA_EDGES, &g_aa);
        same_frames("refused-aa", &g_span, &g_aa, 1, W, H);
    }

    /* the 1-bit formats join the same scene */
    if (g_span.complete && id->nrendered == H && s->cfg.max_triangles <= 600 &&
        s->cfg.max_vertices <= 600 && s->cfg.max_active_edges <= 64)
        check_mono(s, id);
    free(block);
    return 0;
}
