/* SPDX-License-Identifier: MIT */
/* Shared helpers for the zspan core tests: see zt.h. */
#include "zt.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

char zt_ctx_msg[512];

static void *zt_xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q) {
        fprintf(stderr, "zt: out of memory\n");
        abort();
    }
    return q;
}

/* ---------------- PRNG ---------------- */

void zt_rng_seed(zt_rng *g, uint64_t seed) { g->s = seed; }

uint64_t zt_u64(zt_rng *g)
{
    uint64_t z = (g->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint32_t zt_u32(zt_rng *g) { return (uint32_t)(zt_u64(g) >> 32); }

uint32_t zt_below(zt_rng *g, uint32_t n)
{
    return (uint32_t)(((zt_u64(g) >> 32) * (uint64_t)n) >> 32);
}

int64_t zt_range(zt_rng *g, int64_t lo, int64_t hi)
{
    uint64_t span = (uint64_t)(hi - lo) + 1u;
    if (span == 0) return (int64_t)zt_u64(g);
    return lo + (int64_t)(zt_u64(g) % span);
}

double zt_unit(zt_rng *g) { return (double)(zt_u64(g) >> 11) * (1.0 / 9007199254740992.0); }

double zt_uniform(zt_rng *g, double lo, double hi) { return lo + (hi - lo) * zt_unit(g); }

/* ---------------- hook collector ---------------- */

void zt_recs_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    zt_recs *rs = (zt_recs *)user;
    if (rs->n == rs->cap) {
        rs->cap = rs->cap ? rs->cap * 2 : 256;
        rs->v = (zt_rec *)zt_xrealloc(rs->v, rs->cap * sizeof *rs->v);
    }
    zt_rec *t = &rs->v[rs->n];
    t->tag = tag;
    t->order = (uint32_t)rs->n;
    memcpy(t->xy, xy, sizeof t->xy);
    memcpy(t->z, z, sizeof t->z);
    rs->n++;
}

void zt_recs_clear(zt_recs *rs) { rs->n = 0; }

void zt_recs_free(zt_recs *rs)
{
    free(rs->v);
    rs->v = NULL;
    rs->n = rs->cap = 0;
}

/* ---------------- reference rasterizer ---------------- */

int64_t zt_area2(const int32_t xy[6])
{
    int64_t x0 = xy[0], y0 = xy[1], x1 = xy[2], y1 = xy[3], x2 = xy[4], y2 = xy[5];
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
}

int zt_covers(const int32_t xy[6], int px, int py)
{
    int64_t area = zt_area2(xy);
    if (area == 0) return 0;
    int64_t s = area > 0 ? 1 : -1;
    int64_t cx = (int64_t)px * 16 + 8, cy = (int64_t)py * 16 + 8;
    for (int k = 0; k < 3; k++) {
        int64_t ax = xy[2 * k], ay = xy[2 * k + 1];
        int64_t bx = xy[(2 * k + 2) % 6], by = xy[(2 * k + 3) % 6];
        int64_t dx = bx - ax, dy = by - ay;
        /* E = cross(b - a, P - a); for a positive area the interior has E > 0. */
        int64_t e = (dx * (cy - ay) - dy * (cx - ax)) * s;
        if (e < 0) return 0;
        if (e == 0) {
            /* Inward normal n = s * (-dy, dx). Left edge: n.x > 0 (interior to
             * the right). Top edge: horizontal with the interior below it
             * (n.y > 0, y down). Only those own their boundary. */
            int64_t nx = -dy * s, ny = dx * s;
            if (!(nx > 0 || (nx == 0 && ny > 0))) return 0;
        }
    }
    return 1;
}

static int64_t zt_min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}
static int64_t zt_max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

int zt_bbox(const int32_t xy[6], int w, int h, int *x0, int *y0, int *x1, int *y1)
{
    int64_t mnx = zt_min3(xy[0], xy[2], xy[4]), mxx = zt_max3(xy[0], xy[2], xy[4]);
    int64_t mny = zt_min3(xy[1], xy[3], xy[5]), mxy = zt_max3(xy[1], xy[3], xy[5]);
    /* pixel i has centre 16i+8; candidates: 16i+8 in [mn, mx] */
    int64_t ax = mnx - 8, bx = mxx - 8, ay = mny - 8, by = mxy - 8;
    /* ceil(ax/16) .. floor(bx/16) */
    int64_t ix0 = ax >= 0 ? (ax + 15) / 16 : -((-ax) / 16);
    int64_t ix1 = bx >= 0 ? bx / 16 : -((-bx + 15) / 16);
    int64_t iy0 = ay >= 0 ? (ay + 15) / 16 : -((-ay) / 16);
    int64_t iy1 = by >= 0 ? by / 16 : -((-by + 15) / 16);
    if (ix0 < 0) ix0 = 0;
    if (iy0 < 0) iy0 = 0;
    if (ix1 > w - 1) ix1 = w - 1;
    if (iy1 > h - 1) iy1 = h - 1;
    if (ix0 > ix1 || iy0 > iy1) return 0;
    *x0 = (int)ix0;
    *y0 = (int)iy0;
    *x1 = (int)ix1;
    *y1 = (int)iy1;
    return 1;
}

double zt_depth_at(const zt_rec *t, int px, int py)
{
    int64_t x0 = t->xy[0], y0 = t->xy[1], x1 = t->xy[2], y1 = t->xy[3], x2 = t->xy[4],
            y2 = t->xy[5];
    int64_t cx = (int64_t)px * 16 + 8, cy = (int64_t)py * 16 + 8;
    int64_t a = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    /* barycentric weights of vertices 1 and 2 (exact integer numerators) */
    int64_t n1 = (cx - x0) * (y2 - y0) - (x2 - x0) * (cy - y0);
    int64_t n2 = (x1 - x0) * (cy - y0) - (cx - x0) * (y1 - y0);
    double l1 = (double)n1 / (double)a, l2 = (double)n2 / (double)a;
    double z0 = t->z[0] / 1073741824.0, z1 = t->z[1] / 1073741824.0,
           z2 = t->z[2] / 1073741824.0;
    return z0 + l1 * (z1 - z0) + l2 * (z2 - z0);
}

void zt_coverage_count(const zt_recs *rs, int w, int h, uint16_t *cnt)
{
    memset(cnt, 0, (size_t)w * (size_t)h * sizeof *cnt);
    for (size_t i = 0; i < rs->n; i++) {
        int bx0, by0, bx1, by1;
        if (!zt_bbox(rs->v[i].xy, w, h, &bx0, &by0, &bx1, &by1)) continue;
        for (int y = by0; y <= by1; y++)
            for (int x = bx0; x <= bx1; x++)
                if (zt_covers(rs->v[i].xy, x, y)) cnt[(size_t)y * (size_t)w + (size_t)x]++;
    }
}

/* ---------------- ray caster ---------------- */

void zt_cast_alloc(zt_cast *c, int w, int h)
{
    size_t n = (size_t)w * (size_t)h;
    c->w = w;
    c->h = h;
    c->owner = (uint16_t *)zt_xrealloc(NULL, n * sizeof *c->owner);
    c->z1 = (double *)zt_xrealloc(NULL, n * sizeof *c->z1);
    c->z2 = (double *)zt_xrealloc(NULL, n * sizeof *c->z2);
    c->exact = (uint8_t *)zt_xrealloc(NULL, n);
    c->best = (int32_t *)zt_xrealloc(NULL, n * sizeof *c->best);
}

void zt_cast_free(zt_cast *c)
{
    free(c->owner);
    free(c->z1);
    free(c->z2);
    free(c->exact);
    free(c->best);
    memset(c, 0, sizeof *c);
}

int zt_same_vertex_set(const zt_rec *a, const zt_rec *b)
{
    int used[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        int found = 0;
        for (int j = 0; j < 3 && !found; j++)
            if (!used[j] && a->xy[2 * i] == b->xy[2 * j] && a->xy[2 * i + 1] == b->xy[2 * j + 1] &&
                a->z[i] == b->z[j]) {
                used[j] = 1;
                found = 1;
            }
        if (!found) return 0;
    }
    return 1;
}

void zt_raycast(const zt_recs *rs, zt_cast *c)
{
    int w = c->w, h = c->h;
    size_t n = (size_t)w * (size_t)h;
    int32_t *best = c->best;
    for (size_t p = 0; p < n; p++) {
        best[p] = -1;
        c->owner[p] = 0;
        c->z1[p] = 2.0;
        c->z2[p] = 2.0;
        c->exact[p] = 0;
    }
    /* pass 1: nearest; strict < keeps the first-hooked record on exact ties */
    for (size_t i = 0; i < rs->n; i++) {
        int bx0, by0, bx1, by1;
        const zt_rec *t = &rs->v[i];
        if (!zt_bbox(t->xy, w, h, &bx0, &by0, &bx1, &by1)) continue;
        for (int y = by0; y <= by1; y++)
            for (int x = bx0; x <= bx1; x++) {
                if (!zt_covers(t->xy, x, y)) continue;
                size_t p = (size_t)y * (size_t)w + (size_t)x;
                double z = zt_depth_at(t, x, y);
                /* a copy of the current nearest (any vertex order) is an
                 * exact tie: the one hooked first keeps it, whatever the
                 * last bits of the two double evaluations say */
                if (z < c->z1[p] &&
                    !(best[p] >= 0 && zt_same_vertex_set(t, &rs->v[best[p]]))) {
                    c->z1[p] = z;
                    best[p] = (int32_t)i;
                }
            }
    }
    /* pass 2: runner-up with another tag, exact duplicates of the winner
     * excluded (the renderer must resolve those by submission order) */
    for (size_t i = 0; i < rs->n; i++) {
        int bx0, by0, bx1, by1;
        const zt_rec *t = &rs->v[i];
        if (!zt_bbox(t->xy, w, h, &bx0, &by0, &bx1, &by1)) continue;
        for (int y = by0; y <= by1; y++)
            for (int x = bx0; x <= bx1; x++) {
                size_t p = (size_t)y * (size_t)w + (size_t)x;
                if (best[p] < 0 || best[p] == (int32_t)i) continue;
                if (!zt_covers(t->xy, x, y)) continue;
                const zt_rec *b = &rs->v[best[p]];
                if (t->tag == b->tag) continue;
                if (zt_same_vertex_set(t, b)) {
                    c->exact[p] = 1;
                    continue;
                }
                double z = zt_depth_at(t, x, y);
                if (z < c->z2[p]) c->z2[p] = z;
            }
    }
    for (size_t p = 0; p < n; p++)
        if (best[p] >= 0) c->owner[p] = rs->v[best[p]].tag;
}

/* ---------------- scene builder ---------------- */

void zt_scene_init(zt_scene *s, int w, int h, int unit_div)
{
    memset(s, 0, sizeof *s);
    s->w = w;
    s->h = h;
    s->unit_div = unit_div;
}

void zt_scene_reset(zt_scene *s)
{
    s->nv = s->nt = 0;
    s->clamped = 0;
}

void zt_scene_free(zt_scene *s)
{
    free(s->pos);
    free(s->idx);
    free(s->fcol);
    free(s->vcol);
    memset(s, 0, sizeof *s);
}

static int16_t zt_q16(zt_scene *s, double v)
{
    double q = floor(v * s->unit_div + 0.5);
    if (q > 32767.0) {
        s->clamped++;
        q = 32767.0;
    }
    if (q < -32768.0) {
        s->clamped++;
        q = -32768.0;
    }
    return (int16_t)q;
}

int zt_scene_vertex_world(zt_scene *s, double x, double y, double z, zs_color c)
{
    if (s->nv == s->capv) {
        s->capv = s->capv ? s->capv * 2 : 64;
        s->pos = (int16_t *)zt_xrealloc(s->pos, s->capv * 3 * sizeof *s->pos);
        s->vcol = (zs_color *)zt_xrealloc(s->vcol, s->capv * sizeof *s->vcol);
    }
    s->pos[3 * s->nv] = zt_q16(s, x);
    s->pos[3 * s->nv + 1] = zt_q16(s, y);
    s->pos[3 * s->nv + 2] = zt_q16(s, z);
    s->vcol[s->nv] = c;
    return (int)s->nv++;
}

int zt_scene_vertex_px(zt_scene *s, double px, double py, double d, zs_color c)
{
    double hh = s->h / 2.0, hw = s->w / 2.0;
    double x = (px - hw) * d / hh;
    double y = (hh - py) * d / hh;
    return zt_scene_vertex_world(s, x, y, -d, c);
}

int zt_scene_vertex_q(zt_scene *s, int32_t qx, int32_t qy, zs_color c)
{
    if (s->unit_div != 8 * s->h) {
        fprintf(stderr, "zt_scene_vertex_q: unit_div must be 8*h\n");
        abort();
    }
    double u = s->unit_div;
    return zt_scene_vertex_world(s, (qx - 8.0 * s->w) / u, (8.0 * s->h - qy) / u, -1.0, c);
}

void zt_world_to_px(int w, int h, double x, double y, double z, double *px, double *py)
{
    double d = -z;
    *px = w / 2.0 + (h / 2.0) * x / d;
    *py = h / 2.0 - (h / 2.0) * y / d;
}

void zt_scene_tri(zt_scene *s, int a, int b, int c, zs_color fc)
{
    if (s->nt == s->capt) {
        s->capt = s->capt ? s->capt * 2 : 64;
        s->idx = (uint16_t *)zt_xrealloc(s->idx, s->capt * 3 * sizeof *s->idx);
        s->fcol = (zs_color *)zt_xrealloc(s->fcol, s->capt * sizeof *s->fcol);
    }
    s->idx[3 * s->nt] = (uint16_t)a;
    s->idx[3 * s->nt + 1] = (uint16_t)b;
    s->idx[3 * s->nt + 2] = (uint16_t)c;
    s->fcol[s->nt] = fc;
    s->nt++;
}

void zt_scene_tri_front(zt_scene *s, int a, int b, int c, zs_color fc)
{
    /* In a right-handed frame a counter-clockwise triangle seen from the eye
     * (origin) has its normal (b-a)x(c-a) pointing toward the eye. */
    double p[3][3];
    int id[3] = {a, b, c};
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++) p[k][j] = s->pos[3 * id[k] + j];
    double u[3], v[3], n[3];
    for (int j = 0; j < 3; j++) {
        u[j] = p[1][j] - p[0][j];
        v[j] = p[2][j] - p[0][j];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double dot = -(n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]);
    if (dot >= 0)
        zt_scene_tri(s, a, b, c, fc);
    else
        zt_scene_tri(s, a, c, b, fc);
}

zs_mesh zt_scene_mesh(const zt_scene *s, int use_fcol, int use_vcol)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = s->pos;
    m.indices = s->idx;
    m.face_colors = use_fcol ? s->fcol : NULL;
    m.vertex_colors = use_vcol ? s->vcol : NULL;
    m.scale = ZS_FX(1) / s->unit_div;
    m.vertex_count = (uint16_t)s->nv;
    m.triangle_count = (uint16_t)s->nt;
    m.color = ZS_RGB(200, 180, 160);
    return m;
}

zs_mesh zt_scene_grey_quad(zt_scene *s, int w, int h, int v)
{
    zs_color col = ZS_RGB(v, v, v);
    int a, b, c, d;
    zt_scene_init(s, w, h, 128);
    a = zt_scene_vertex_px(s, -2, -2, 2.0, col);
    b = zt_scene_vertex_px(s, w + 2, -2, 2.0, col);
    c = zt_scene_vertex_px(s, w + 2, h + 2, 2.0, col);
    d = zt_scene_vertex_px(s, -2, h + 2, 2.0, col);
    zt_scene_tri_front(s, a, b, c, col);
    zt_scene_tri_front(s, a, c, d, col);
    return zt_scene_mesh(s, 1, 0);
}

void zt_random_light(zt_rng *g, zs_shade_params *sp, zs_fixed min_intensity)
{
    zs_fixed dx, dy;
    sp->ambient = (zs_fixed)zt_range(g, 0, ZS_FX(1) / 2);
    sp->light_count = 1;
    dx = (zs_fixed)zt_range(g, -ZS_FX(2), ZS_FX(2));
    dy = (zs_fixed)zt_range(g, -ZS_FX(2), ZS_FX(2));
    sp->lights[0].direction = zs_vec3_make(dx, dy, ZS_FX(1));
    sp->lights[0].intensity = (zs_fixed)zt_range(g, min_intensity, ZS_FX(3) / 2);
}

void zt_camera_std(zs_camera *cam, zs_fixed near_z, zs_fixed far_z)
{
    zs_status st = zs_camera_look_at(cam, zs_vec3_make(0, 0, 0), zs_vec3_make(0, 0, -ZS_FX(1)),
                                     zs_vec3_make(0, ZS_FX(1), 0));
    if (st != ZS_OK) {
        fprintf(stderr, "zt_camera_std: look_at failed: %d\n", (int)st);
        abort();
    }
    st = zs_camera_perspective(cam, ZS_FX(90), near_z, far_z);
    if (st != ZS_OK) {
        fprintf(stderr, "zt_camera_std: perspective failed: %d\n", (int)st);
        abort();
    }
}

/* ---------------- harness ---------------- */

void zt_ctx_init(zt_ctx *c, int w, int h, int max_tris, int max_verts, int max_edges)
{
    zt_ctx_init_flags(c, w, h, max_tris, max_verts, max_edges, 0);
}

void zt_ctx_init_flags(zt_ctx *c, int w, int h, int max_tris, int max_verts, int max_edges,
                       uint16_t flags)
{
    memset(c, 0, sizeof *c);
    c->cfg = zs_config_default((uint16_t)w, (uint16_t)h, (uint16_t)max_tris,
                               (uint16_t)max_verts, (uint16_t)max_edges);
    c->cfg.flags = flags;
    c->arena_size = zs_arena_bytes(&c->cfg);
    if (c->arena_size == 0) {
        fprintf(stderr, "zt_ctx_init: zs_arena_bytes == 0 for %dx%d flags %#x\n", w, h,
                (unsigned)flags);
        abort();
    }
    c->arena = (uint8_t *)zt_xrealloc(NULL, c->arena_size);
    zs_status st = zs_init(&c->r, c->arena, c->arena_size, &c->cfg);
    if (st != ZS_OK) {
        fprintf(stderr, "zt_ctx_init: zs_init failed: %s\n", zs_strerror(st));
        abort();
    }
}

zs_status zt_begin(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                   const zs_shade_params *sp, const zs_mesh *m)
{
    zs_status st = zs_frame_begin(&c->r, cam, mode);
    if (st == ZS_OK)
        st = zs_frame_shading(&c->r, sp);
    if (st == ZS_OK && m)
        st = zs_draw(&c->r, m, NULL);
    return st;
}

void zt_ctx_free(zt_ctx *c)
{
    free(c->arena);
    c->arena = NULL;
}

zs_status zt_render_rows_all(zs_renderer *r, uint8_t *img, int w, int h, zs_format fmt,
                             int band)
{
    size_t stride = (size_t)w * zs_format_bytes(fmt);
    if (band < 1) band = 1;
    for (int y = 0; y < h; y += band) {
        int n = band < h - y ? band : h - y;
        zs_status st = zs_render_rows(r, y, n, img + (size_t)y * stride, stride);
        if (st != ZS_OK) return st;
    }
    return ZS_OK;
}

typedef struct zt_band_user {
    uint8_t *img;
    size_t stride;
    int next_y, band, h, bad;
} zt_band_user;

static int zt_band_cb(void *user, int y0, int rows, const void *buf, size_t stride)
{
    zt_band_user *u = (zt_band_user *)user;
    if (y0 != u->next_y || rows < 1 || rows > u->band || y0 + rows > u->h ||
        stride != u->stride) {
        u->bad = 1;
        return 1;
    }
    for (int k = 0; k < rows; k++)
        memcpy(u->img + (size_t)(y0 + k) * u->stride, (const uint8_t *)buf + (size_t)k * stride,
               u->stride);
    u->next_y = y0 + rows;
    return 0;
}

zs_status zt_render_frame_all(zs_renderer *r, uint8_t *img, int w, int h, zs_format fmt,
                              int band)
{
    size_t stride = (size_t)w * zs_format_bytes(fmt);
    uint8_t *buf = (uint8_t *)zt_xrealloc(NULL, stride * (size_t)band);
    memset(buf, 0xA5, stride * (size_t)band);
    zt_band_user u = {img, stride, 0, band, h, 0};
    zs_status st = zs_render_frame(r, buf, stride, band, zt_band_cb, &u);
    free(buf);
    if (st == ZS_OK && (u.bad || u.next_y != h)) return ZS_STATUS_COUNT; /* harness error */
    return st;
}

zs_status zt_frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                   const zs_shade_params *sp, const zs_mesh *meshes, int nmesh,
                   zt_recs *recs, uint8_t *img, int band)
{
    zs_status first = ZS_OK, st;
    if (recs) {
        zt_recs_clear(recs);
        zs_set_setup_hook(&c->r, zt_recs_hook, recs);
    } else {
        zs_set_setup_hook(&c->r, NULL, NULL);
    }
    st = zs_frame_begin(&c->r, cam, mode);
    if (st != ZS_OK) return st;
    zs_shade_params p;
    if (sp) {
        p = *sp;
    } else {
        p = zs_shade_default();
        p.format = ZS_FMT_ID16;
    }
    st = zs_frame_shading(&c->r, &p);
    if (st != ZS_OK) return st;
    for (int i = 0; i < nmesh; i++) {
        st = zs_draw(&c->r, &meshes[i], NULL);
        if (st != ZS_OK && first == ZS_OK) first = st;
    }
    st = zt_render_rows_all(&c->r, img, c->cfg.width, c->cfg.height, p.format, band);
    if (st != ZS_OK && first == ZS_OK) first = st;
    return first;
}

uint16_t zt_id_at(const uint8_t *img, int w, int x, int y)
{
    uint16_t v;
    memcpy(&v, img + ((size_t)y * (size_t)w + (size_t)x) * 2u, 2);
    return v;
}

long zt_first_diff(const uint8_t *a, const uint8_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i]) return (long)i;
    return -1;
}

/* ---------------- random scenes ---------------- */

static zs_color zt_rand_color(zt_rng *g) { return (zs_color)(zt_u32(g) & 0xFFFFFFu); }

void zt_scene_random(zt_rng *g, zt_scene *s, int ntri, unsigned flags, double near_d)
{
    unsigned kinds[7];
    int nk = 0;
    for (int b = 0; b < 7; b++)
        if (flags & (1u << b)) kinds[nk++] = 1u << b;
    if (nk == 0) return;
    int start_nt = (int)s->nt;
    double W = s->w, H = s->h;
    while ((int)s->nt - start_nt < ntri) {
        unsigned k = kinds[zt_below(g, (uint32_t)nk)];
        double sz = exp(zt_uniform(g, log(1.0), log(1.2 * W)));
        double cx = zt_uniform(g, -0.3 * W, 1.3 * W), cy = zt_uniform(g, -0.3 * H, 1.3 * H);
        double base = exp(zt_uniform(g, log(near_d * 2.5), log(near_d * 60)));
        zs_color fc = zt_rand_color(g);
        if (k == ZT_SC_PLAIN || k == ZT_SC_FLAT) {
            int v[3];
            for (int i = 0; i < 3; i++) {
                double d = k == ZT_SC_FLAT ? base : base * exp(zt_uniform(g, -0.5, 0.5));
                v[i] = zt_scene_vertex_px(s, cx + sz * zt_uniform(g, -1, 1),
                                          cy + sz * zt_uniform(g, -1, 1), d, zt_rand_color(g));
            }
            zt_scene_tri_front(s, v[0], v[1], v[2], fc);
        } else if (k == ZT_SC_SHARED) {
            /* a quad (possibly folded along its diagonal) as two triangles */
            int v[4];
            double fold = zt_below(g, 2) ? 0.0 : zt_uniform(g, -0.4, 0.4);
            for (int i = 0; i < 4; i++) {
                double a = 6.283185307179586 * (i + zt_uniform(g, -0.2, 0.2)) / 4;
                double d = base * (1.0 + ((i == 1) ? fold : 0.0) + zt_uniform(g, -0.05, 0.05) *
                                                                         (fold != 0.0));
                v[i] = zt_scene_vertex_px(s, cx + sz * cos(a), cy + sz * sin(a), d,
                                          zt_rand_color(g));
            }
            zt_scene_tri_front(s, v[0], v[1], v[2], fc);
            zt_scene_tri_front(s, v[0], v[2], v[3], zt_rand_color(g));
        } else if (k == ZT_SC_DUP) {
            if (s->nt == 0) continue;
            size_t t = zt_below(g, (uint32_t)s->nt);
            int a = s->idx[3 * t], b = s->idx[3 * t + 1], c = s->idx[3 * t + 2];
            int how = (int)zt_below(g, 3);
            if (how == 0) {
                zt_scene_tri(s, a, b, c, fc);
            } else if (how == 1) {
                zt_scene_tri(s, b, c, a, fc);
            } else {
                int id[3] = {a, b, c}, nv[3];
                for (int i = 0; i < 3; i++) {
                    int n = (int)s->nv;
                    zt_scene_vertex_world(s, 0, 0, 0, zt_rand_color(g));
                    s->pos[3 * n] = s->pos[3 * id[i]];
                    s->pos[3 * n + 1] = s->pos[3 * id[i] + 1];
                    s->pos[3 * n + 2] = s->pos[3 * id[i] + 2];
                    nv[i] = n;
                }
                zt_scene_tri(s, nv[0], nv[1], nv[2], fc);
            }
        } else if (k == ZT_SC_NEAR) {
            /* one or two vertices near/behind the eye, the others in front */
            int nb = 1 + (int)zt_below(g, 2), v[3];
            for (int i = 0; i < 3; i++) {
                if (i < nb) {
                    double d = zt_uniform(g, -3.0 * near_d, 0.95 * near_d);
                    v[i] = zt_scene_vertex_world(s, zt_uniform(g, -2, 2) * near_d,
                                                 zt_uniform(g, -2, 2) * near_d, -d,
                                                 zt_rand_color(g));
                } else {
                    v[i] = zt_scene_vertex_px(s, cx + sz * zt_uniform(g, -1, 1),
                                              cy + sz * zt_uniform(g, -1, 1),
                                              near_d * zt_uniform(g, 1.5, 20), zt_rand_color(g));
                }
            }
            zt_scene_tri_front(s, v[0], v[1], v[2], fc);
        } else if (k == ZT_SC_LAYERS) {
            /* 2..4 triangles over one region, each vertex at its layer's
             * depth plus 0..2 position units, layers 1..3 units apart: at
             * depth d one unit moves window depth by about near / (d^2 *
             * unit_div), from well over to well under the span walk's
             * 2^-15 range resolution */
            int nl = 2 + (int)zt_below(g, 3);
            double d = base * 2, unit = 1.0 / s->unit_div;
            for (int l = 0; l < nl; l++) {
                int v[3];
                for (int i = 0; i < 3; i++) {
                    double a = 6.283185307179586 * (i + zt_uniform(g, -0.15, 0.15)) / 3;
                    v[i] = zt_scene_vertex_px(s, cx + sz * cos(a), cy + sz * sin(a),
                                              d + unit * (double)zt_below(g, 3), zt_rand_color(g));
                }
                zt_scene_tri_front(s, v[0], v[1], v[2], zt_rand_color(g));
                d += unit * (double)(1 + zt_below(g, 3));
            }
        } else { /* ZT_SC_BIG: a tilted plane beyond the screen, two triangles */
            double d0 = base * 2, tx = zt_uniform(g, -0.5, 0.5), ty = zt_uniform(g, -0.5, 0.5);
            double px[4] = {-0.5 * W, 1.5 * W, 1.5 * W, -0.5 * W};
            double py[4] = {-0.5 * H, -0.5 * H, 1.5 * H, 1.5 * H};
            int v[4];
            for (int i = 0; i < 4; i++) {
                double d = d0 * (1.0 + tx * (px[i] / W - 0.5) + ty * (py[i] / H - 0.5));
                v[i] = zt_scene_vertex_px(s, px[i] + zt_uniform(g, -5, 5),
                                          py[i] + zt_uniform(g, -5, 5), d, zt_rand_color(g));
            }
            zt_scene_tri_front(s, v[0], v[1], v[2], fc);
            zt_scene_tri_front(s, v[0], v[2], v[3], zt_rand_color(g));
        }
    }
}
