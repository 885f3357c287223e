/* SPDX-License-Identifier: MIT */
/* LIBS: -lassimp app/zs_bsp_build.c */
/*
 * test_priority: list-priority visibility (ZS_MODE_PRIORITY, zspan/priority.h).
 *
 *  - walk: random scenes (every kind of zt_scene_random) in priority mode
 *    against the half-space coverage oracle: at each pixel centre the owner
 *    is the first hooked record (hook order is storage order) whose edge
 *    functions cover it, in every band height.
 *  - bsp: non-penetrating scenes compiled by the host BSP compiler and drawn
 *    with zs_draw_bsp in priority mode against the same scenes drawn with
 *    zs_draw in span mode (RGB888, a unique colour per source triangle):
 *    random separated boxes, stacks of tilted plates whose planes cut each
 *    other (many splits), a room with pillars seen from many eye positions
 *    inside and outside, and assimp's test models (duck and Wuson included). The bound: a pixel may
 *    differ only within R pixels of an edge of a triangle that has a split
 *    vertex, R = 1 + (max_snap + 1) * (units to pixels at that triangle's
 *    nearest vertex): the rounding of the split vertex (max_snap, at most
 *    sqrt(3)/2 position units) plus the compiler's in-plane tolerance (one
 *    unit), plus one pixel for the coverage rule. No pixel that span mode
 *    covers may be left uncovered (cracks), anywhere.
 *  - bad trees: out-of-range children, cycles, shared nodes, bad ranges and
 *    planes, too deep: ZS_ERR_BSP, and nothing stored.
 *  - painter's output (zs_paint_frame, zs_priority_order, zs_record_get):
 *    the full-frame painter's image equals the priority-mode band image byte
 *    for byte on the walk's random scenes (every byte format, flat, Gouraud,
 *    fog), on textured random scenes (every texture mode), on every BSP view above and on every sorted NNS scene (so it has
 *    the ray caster's answer there too); the ordered list is checked pair by
 *    pair against exact depths: where two records cover a centre, the later
 *    one in the list is the nearer (the plain sort fails it); error codes.
 */
#include "zt_test.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../app/zs_bsp_build.h"
#include "zspan/priority.h"

#define W 96
#define H 72
#define SEED 0x9A1C0B5B00000001ull
/* window-depth difference below which span mode's choice between the two
 * nearest surfaces is a rounding matter (surfaces that touch) */
#define NEAR_TIE (1.0 / 4096.0)

/* ---------------- the walk against the coverage oracle ---------------- */

static void test_walk_oracle(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 600, 1800, 600);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    zt_recs recs = {0};
    static uint8_t img[W * H * 2];
    unsigned long px = 0, covered = 0, bad = 0;
    for (int n = 0; n < 200; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 60), ZT_SC_ALL, 0.5);
        zs_mesh mesh = zt_scene_mesh(&sc, 1, 0);
        memset(img, 0xAB, sizeof img);
        ZT_ST(zt_frame(&c, &cam, ZS_MODE_PRIORITY, NULL, &mesh, 1, &recs, img, 1 + n % 9),
              ZS_OK);
        const zs_stats *s = zs_frame_stats(&c.r);
        ZT_CHECK(s->depth_evals == 0 && s->crossings == 0, "scene %d: depth work in priority", n);
        ZT_CHECK(s->pixels_shaded == W * H, "scene %d: %u pixel writes", n, s->pixels_shaded);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint16_t want = 0;
                for (size_t i = 0; i < recs.n; i++)
                    if (zt_covers(recs.v[i].xy, x, y)) {
                        want = recs.v[i].tag;
                        break;
                    }
                px++;
                covered += want != 0;
                if (zt_id_at(img, W, x, y) != want && bad++ < 3)
                    print_error("walk: scene %d pixel (%d,%d): %u, oracle %u\n", n, x, y,
                                zt_id_at(img, W, x, y), want);
            }
    }
    printf("test_priority walk: 200 scenes, %lu pixels (%lu covered), %lu differ from the "
           "first-covering-record oracle\n",
           px, covered, bad);
    ZT_CHECK(bad == 0, "%lu pixels differ", bad);
    zt_recs_free(&recs);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* ---------------- painter's output against the band image ---------------- */

static void test_painter_walk(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 5);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 600, 1800, 600);
    zt_ctx small;
    zt_ctx_init(&small, W, H, 600, 1800, 2);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    static const zs_format fmts[] = {ZS_FMT_ID16,  ZS_FMT_RGB565_BE, ZS_FMT_RGB888,
                                     ZS_FMT_GRAY8, ZS_FMT_RGB666,    ZS_FMT_RGB565};
    /* room for a stride wider than the row: bytes past it must stay */
    static uint8_t band[W * H * 3], paint[(W * 3 + 5) * H];
    unsigned long frames = 0, differ = 0, guard = 0, writes = 0, gouraud = 0;
    for (int n = 0; n < 200; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 60), ZT_SC_ALL, 0.5);
        zs_format fmt = fmts[n % 6];
        int smooth = fmt != ZS_FMT_ID16 && n % 2;
        zs_mesh mesh = zt_scene_mesh(&sc, 1, smooth);
        zs_shade_params sp = zs_shade_default();
        sp.format = fmt;
        sp.background = 0x203040u;
        if (smooth) {
            sp.shading = ZS_SHADE_GOURAUD;
            if (n % 4 == 1) { /* fog too */
                sp.fog.enabled = 1;
                sp.fog.color = 0x8090A0u;
                sp.fog.start = ZS_FX(1);
                sp.fog.end = ZS_FX(8);
            }
        }
        size_t bpp = zs_format_bytes(fmt), row = W * bpp, stride = row + (size_t)(n % 6);
        memset(band, 0xAB, sizeof band);
        ZT_ST(zt_frame(&c, &cam, ZS_MODE_PRIORITY, &sp, &mesh, 1, NULL, band, 1 + n % 9), ZS_OK);
        ZT_CHECK(c.r.stats.records_skipped == 0, "scene %d: records skipped", n);
        /* the painter needs one active slot: paint with the smallest edge pool */
        zt_ctx *pc = n % 2 ? &small : &c;
        ZT_ST(zs_frame_begin(&pc->r, &cam, ZS_MODE_PRIORITY), ZS_OK);
        ZT_ST(zs_frame_shading(&pc->r, &sp), ZS_OK);
        ZT_ST(zs_draw(&pc->r, &mesh, NULL), ZS_OK);
        memset(paint, 0xCD, sizeof paint);
        ZT_ST(zs_paint_frame(&pc->r, paint, stride), ZS_OK);
        frames++;
        writes += pc->r.stats.pixels_shaded;
        gouraud += smooth;
        int bad = 0;
        for (int y = 0; y < H; y++) {
            if (memcmp(band + (size_t)y * row, paint + (size_t)y * stride, row) != 0 && !bad++)
                print_error("painter: scene %d format %d: row %d differs\n", n, (int)fmt, y);
            for (size_t k = row; k < stride; k++)
                guard += paint[(size_t)y * stride + k] != 0xCD;
        }
        differ += bad != 0;
        /* the frame is done: rows and a second paint are refused */
        ZT_ST(zs_paint_frame(&pc->r, paint, stride), ZS_ERR_STATE);
        ZT_ST(zs_render_rows(&pc->r, 0, 1, band, row), ZS_ERR_STATE);
    }
    printf("test_priority painter walk: %lu random scenes (6 byte formats, %lu Gouraud; half "
           "painted by a renderer with an edge pool of 2), %lu painted frames differ from the priority band image, %lu bytes written past the "
           "row; %.2f pixel writes per pixel (background included)\n",
           frames, gouraud, differ, guard, (double)writes / (double)(frames * W * H));
    ZT_CHECK(differ == 0 && guard == 0, "painter: %lu frames differ, %lu guard bytes", differ,
             guard);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    zt_ctx_free(&small);
}

/* Textured records through the painter: the texture planes are made per
 * record in the same active slot, so the image must still be the band's. */
static void test_painter_textured(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 6);
    zt_ctx c;
    memset(&c, 0, sizeof c);
    c.cfg = zs_config_default(W, H, 600, 1800, 600);
    c.cfg.flags = ZS_CFG_TEXTURE;
    c.arena_size = zs_arena_bytes(&c.cfg);
    c.arena = malloc(c.arena_size);
    ZT_ST(zs_init(&c.r, c.arena, c.arena_size, &c.cfg), ZS_OK);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    static uint16_t texels[64 * 64];
    for (int k = 0; k < 64 * 64; k++)
        texels[k] = (uint16_t)zt_u32(&g);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    static uint8_t band[W * H * 3], paint[W * H * 3];
    unsigned long differ = 0;
    const int nscenes = 96;
    for (int n = 0; n < nscenes; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 6, 40), ZT_SC_ALL, 0.5);
        int16_t *uv = malloc(2 * sc.nv * sizeof *uv + 1);
        int spread = 1 + (int)zt_below(&g, 12);
        for (size_t k = 0; k < 2 * sc.nv; k++)
            uv[k] = (int16_t)zt_range(&g, -spread * ZS_UV_ONE / 4, spread * ZS_UV_ONE / 4);
        zs_texture tex;
        memset(&tex, 0, sizeof tex);
        tex.texels = texels;
        tex.width = 64;
        tex.height = 64;
        tex.format = ZS_TEX_RGB565;
        tex.flags = (uint8_t)(n % 8); /* clamp, bilinear, subdivided: every mix */
        zs_mesh mesh = zt_scene_mesh(&sc, n % 2, (n / 2) % 2);
        mesh.uvs = uv;
        mesh.texture = &tex;
        zs_shade_params sp = zs_shade_default();
        sp.format = n % 3 == 0 ? ZS_FMT_RGB888 : n % 3 == 1 ? ZS_FMT_RGB565_BE : ZS_FMT_GRAY8;
        sp.shading = (n / 4) % 2 ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
        size_t bytes = (size_t)W * H * zs_format_bytes(sp.format);
        ZT_ST(zt_frame(&c, &cam, ZS_MODE_PRIORITY, &sp, &mesh, 1, NULL, band, 1 + n % 7), ZS_OK);
        ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
        ZT_ST(zs_frame_shading(&c.r, &sp), ZS_OK);
        ZT_ST(zs_draw(&c.r, &mesh, NULL), ZS_OK);
        ZT_ST(zs_paint_frame(&c.r, paint, W * zs_format_bytes(sp.format)), ZS_OK);
        long d = zt_first_diff(band, paint, bytes);
        if (d >= 0 && differ++ < 3)
            print_error("painter textured: scene %d (flags %u) differs at pixel %ld\n", n,
                        tex.flags, d / (long)zs_format_bytes(sp.format));
        free(uv);
    }
    printf("test_priority painter textured: %d random textured scenes (nearest, bilinear, "
           "subdivided, wrap and clamp), %lu painted frames differ from the band image\n",
           nscenes, differ);
    ZT_CHECK(differ == 0, "%lu textured frames differ", differ);
    zt_scene_free(&sc);
    free(c.arena);
}

static void test_painter_errors(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, 32, 24, 16, 48, 16);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zs_mesh pair = zt_mesh_pair();
    static uint8_t buf[32 * 24 * 3];
    uint16_t order[4];
    uint32_t n = 99;
    zs_record_tri rt;
    ZT_ST(zs_paint_frame(NULL, buf, 64), ZS_ERR_NULL);
    ZT_ST(zs_paint_frame(&c.r, NULL, 64), ZS_ERR_NULL);
    ZT_ST(zs_paint_frame(&c.r, buf, 64), ZS_ERR_STATE); /* no frame begun */
    ZT_ST(zs_priority_order(&c.r, order, 4, &n), ZS_ERR_STATE);
    ZT_ST(zs_record_get(&c.r, 0, &rt), ZS_ERR_STATE);
    ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_paint_frame(&c.r, buf, 64), ZS_ERR_MODE);
    ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
    zs_shade_params ids = zs_shade_default();
    ids.format = ZS_FMT_ID16;
    ZT_ST(zs_frame_shading(&c.r, &ids), ZS_OK);
    ZT_ST(zs_draw(&c.r, &pair, NULL), ZS_OK);
    ZT_CHECK(c.r.stats.records >= 2, "the pair stored %u records", c.r.stats.records);
    ZT_ST(zs_paint_frame(&c.r, buf, 63), ZS_ERR_BUFFER); /* ID16: 64 bytes a row */
    ZT_ST(zs_paint_frame(&c.r, buf, SIZE_MAX / 8), ZS_ERR_BUFFER);
    ZT_ST(zs_priority_order(&c.r, NULL, 0, NULL), ZS_ERR_NULL);
    ZT_ST(zs_priority_order(&c.r, NULL, 0, &n), ZS_ERR_CAPACITY);
    ZT_CHECK(n == c.r.stats.records, "count %u of %u records", n, c.r.stats.records);
    order[0] = 0x7777;
    ZT_ST(zs_priority_order(&c.r, order, n - 1, &n), ZS_ERR_CAPACITY);
    ZT_CHECK(order[0] == 0x7777, "a refused list wrote into the array");
    ZT_ST(zs_priority_order(&c.r, order, 4, &n), ZS_OK);
    for (uint32_t k = 0; k < n; k++)
        ZT_CHECK(order[k] == n - 1 - k, "order[%u] = %u", k, order[k]);
    ZT_ST(zs_record_get(&c.r, n, &rt), ZS_ERR_ARGUMENT);
    ZT_ST(zs_record_get(&c.r, 0, NULL), ZS_ERR_NULL);
    ZT_ST(zs_record_get(&c.r, 0, &rt), ZS_OK);
    ZT_CHECK(rt.rgb[0] == 1 && zt_area2((const int32_t[6]){rt.x[0], rt.y[0], rt.x[1], rt.y[1],
                                                            rt.x[2], rt.y[2]}) != 0,
             "record 0: tag %u", rt.rgb[0]);
    ZT_ST(zs_paint_frame(&c.r, buf, 64), ZS_OK);
    ZT_ST(zs_priority_order(&c.r, order, 4, &n), ZS_OK); /* still readable after */
    zt_ctx_free(&c);
    /* the 1-bit formats are dithered rows, not painted; the A-buffer resolves rows */
    zt_ctx d;
    memset(&d, 0, sizeof d);
    d.cfg = zs_config_default(32, 24, 16, 48, 16);
    d.cfg.flags = ZS_CFG_MONO;
    d.arena_size = zs_arena_bytes(&d.cfg);
    d.arena = malloc(d.arena_size);
    ZT_ST(zs_init(&d.r, d.arena, d.arena_size, &d.cfg), ZS_OK);
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_MONO_MSB;
    ZT_ST(zs_frame_begin(&d.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_frame_shading(&d.r, &sp), ZS_OK);
    ZT_ST(zs_paint_frame(&d.r, buf, 64), ZS_ERR_FORMAT);
    free(d.arena);
}

/* ---------------- BSP order against span mode ---------------- */

typedef struct mesh_buf {
    int16_t *pos;
    uint16_t *idx;
    uint32_t *fcol;
    size_t nv, nt, capv, capt;
} mesh_buf;

static uint32_t unique_color(size_t i)
{
    /* distinct for i < 2^24 - 1, never 0 (the background) */
    uint32_t c = (uint32_t)((i + 1) * 0x9E3779u) & 0xFFFFFFu; /* odd factor: a bijection */
    return c ? c : 1;
}

static int add_v(mesh_buf *m, double x, double y, double z)
{
    if (m->nv == m->capv) {
        m->capv = m->capv ? 2 * m->capv : 256;
        m->pos = realloc(m->pos, 3 * m->capv * sizeof *m->pos);
    }
    m->pos[3 * m->nv] = (int16_t)lrint(x);
    m->pos[3 * m->nv + 1] = (int16_t)lrint(y);
    m->pos[3 * m->nv + 2] = (int16_t)lrint(z);
    return (int)m->nv++;
}

static void add_t(mesh_buf *m, int a, int b, int c)
{
    if (m->nt == m->capt) {
        m->capt = m->capt ? 2 * m->capt : 256;
        m->idx = realloc(m->idx, 3 * m->capt * sizeof *m->idx);
        m->fcol = realloc(m->fcol, m->capt * sizeof *m->fcol);
    }
    m->idx[3 * m->nt] = (uint16_t)a;
    m->idx[3 * m->nt + 1] = (uint16_t)b;
    m->idx[3 * m->nt + 2] = (uint16_t)c;
    m->fcol[m->nt] = unique_color(m->nt);
    m->nt++;
}

/* A box of half sizes h about c, turned by angle a about y then b about x;
 * faces outward (counter-clockwise seen from outside). inward turns it
 * inside out (a room). */
static void add_box(mesh_buf *m, const double c[3], const double h[3], double a, double b,
                    int inward)
{
    int v[8];
    for (int k = 0; k < 8; k++) {
        double p[3] = {(k & 1) ? h[0] : -h[0], (k & 2) ? h[1] : -h[1], (k & 4) ? h[2] : -h[2]};
        double x = p[0] * cos(a) + p[2] * sin(a), z = -p[0] * sin(a) + p[2] * cos(a);
        double y = p[1] * cos(b) - z * sin(b), z2 = p[1] * sin(b) + z * cos(b);
        v[k] = add_v(m, c[0] + x, c[1] + y, c[2] + z2);
    }
    /* quads a b c d counter-clockwise from outside */
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        const int *s = q[f];
        if (!inward) {
            add_t(m, v[s[0]], v[s[1]], v[s[2]]);
            add_t(m, v[s[0]], v[s[2]], v[s[3]]);
        } else {
            add_t(m, v[s[0]], v[s[2]], v[s[1]]);
            add_t(m, v[s[0]], v[s[3]], v[s[2]]);
        }
    }
}

static zs_mesh mesh_of(const mesh_buf *m, int16_t *pos, uint16_t *idx, uint32_t *fcol, size_t nv,
                       size_t nt, zs_fixed scale)
{
    zs_mesh me;
    memset(&me, 0, sizeof me);
    (void)m;
    me.positions = pos;
    me.indices = idx;
    me.face_colors = fcol;
    me.scale = scale;
    me.vertex_count = (uint16_t)nv;
    me.triangle_count = (uint16_t)nt;
    me.color = 0xFFFFFF;
    return me;
}

typedef struct bsp_tally {
    unsigned long scenes, views, tris, out_tris, nodes, splits, slivers, pixels, covered,
        differ, in_bound, outside, cracks, mask, edge_on, near_tie, painted, paint_differ;
    double max_r;
} bsp_tally;

static void hook_keep(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    zt_recs_hook(user, tag, xy, z);
}

/* Pixels whose centre is within r of segment a-b (28.4 coordinates). */
static void mark_segment(uint8_t *mask, double ax, double ay, double bx, double by, double r)
{
    int x0 = (int)floor((ax < bx ? ax : bx) - r - 1), x1 = (int)ceil((ax > bx ? ax : bx) + r + 1);
    int y0 = (int)floor((ay < by ? ay : by) - r - 1), y1 = (int)ceil((ay > by ? ay : by) + r + 1);
    double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    for (int y = y0 < 0 ? 0 : y0; y <= y1 && y < H; y++)
        for (int x = x0 < 0 ? 0 : x0; x <= x1 && x < W; x++) {
            double cx = x + 0.5, cy = y + 0.5, t = 0;
            if (len2 > 0) {
                t = ((cx - ax) * dx + (cy - ay) * dy) / len2;
                t = t < 0 ? 0 : t > 1 ? 1 : t;
            }
            double ex = ax + t * dx - cx, ey = ay + t * dy - cy;
            if (ex * ex + ey * ey <= r * r)
                mask[y * W + x] = 1;
        }
}

/* Is the source triangle of colour rgb back-facing from the exact eye? */
static int edge_on(const zs_mesh *src, const uint8_t *rgb, const double eye[3])
{
    uint32_t col = (uint32_t)rgb[0] << 16 | (uint32_t)rgb[1] << 8 | rgb[2];
    for (size_t k = 0; k < src->triangle_count; k++) {
        if (src->face_colors[k] != col)
            continue;
        const int16_t *p0 = &src->positions[3 * src->indices[3 * k]];
        const int16_t *p1 = &src->positions[3 * src->indices[3 * k + 1]];
        const int16_t *p2 = &src->positions[3 * src->indices[3 * k + 2]];
        double u[3], v[3], n[3];
        for (int j = 0; j < 3; j++) {
            u[j] = p1[j] - p0[j];
            v[j] = p2[j] - p0[j];
        }
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        return n[0] * (eye[0] - p0[0]) + n[1] * (eye[1] - p0[1]) + n[2] * (eye[2] - p0[2]) <= 0;
    }
    return 0;
}

/* One view: span image of the source, priority image of the BSP, compared. */
static void compare_view(zt_ctx *c, const zs_camera *cam, const zs_mesh *src, const zs_bsp *bsp,
                         const zs_bspb_result *res, double units_per_world, bsp_tally *t,
                         const char *what, int view)
{
    static uint8_t span_img[W * H * 3], pri_img[W * H * 3], mask[W * H];
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_RGB888;
    zt_recs recs = {0};
    zt_recs span_recs = {0};
    zs_set_setup_hook(&c->r, hook_keep, &span_recs);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw(&c->r, src, NULL), ZS_OK);
    zs_set_setup_hook(&c->r, NULL, NULL);
    static zt_cast cast;
    if (!cast.owner)
        zt_cast_alloc(&cast, W, H);
    zt_raycast(&span_recs, &cast);
    zt_recs_free(&span_recs);
    ZT_ST(zt_render_rows_all(&c->r, span_img, W, H, ZS_FMT_RGB888, H), ZS_OK);
    ZT_CHECK(c->r.stats.tris_dropped == 0 && c->r.stats.records_skipped == 0,
             "%s: pools too small", what);
    zs_set_setup_hook(&c->r, hook_keep, &recs);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw_bsp(&c->r, bsp, NULL), ZS_OK);
    ZT_ST(zt_render_rows_all(&c->r, pri_img, W, H, ZS_FMT_RGB888, 1 + view % 7), ZS_OK);
    ZT_CHECK(c->r.stats.tris_dropped == 0 && c->r.stats.records_skipped == 0,
             "%s: pools too small (priority)", what);
    ZT_CHECK(c->r.stats.bsp_nodes == res->node_count, "%s: %u nodes visited of %zu", what,
             c->r.stats.bsp_nodes, res->node_count);
    zs_set_setup_hook(&c->r, NULL, NULL);
    /* the same tree painted back to front into a full frame */
    {
        static uint8_t paint_img[W * H * 3];
        memset(paint_img, 0x5A, sizeof paint_img);
        ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_PRIORITY), ZS_OK);
        ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
        ZT_ST(zs_draw_bsp(&c->r, bsp, NULL), ZS_OK);
        ZT_ST(zs_paint_frame(&c->r, paint_img, W * 3), ZS_OK);
        t->painted++;
        long d = zt_first_diff(pri_img, paint_img, sizeof paint_img);
        if (d >= 0 && t->paint_differ++ < 3)
            print_error("%s view %d: painter differs from the band image at pixel (%ld,%ld)\n",
                        what, view, d / 3 % W, d / 3 / W);
    }
    /* the bound around every record with a split vertex */
    memset(mask, 0, sizeof mask);
    double near = cam->near_z / 65536.0, far = cam->far_z / 65536.0, focal = H / 2.0;
    for (size_t i = 0; i < recs.n; i++) {
        const zt_rec *rc = &recs.v[i];
        size_t tri = (size_t)rc->tag - 1;
        const uint16_t *ix = &res->mesh.idx[3 * tri];
        if (!res->is_split[ix[0]] && !res->is_split[ix[1]] && !res->is_split[ix[2]])
            continue;
        double wmin = 1e300;
        for (int k = 0; k < 3; k++) {
            double z = rc->z[k] / 1073741824.0;
            double w = near / (1 - z * (far - near) / far);
            wmin = w < wmin ? w : wmin;
        }
        double r = 1 + (res->max_snap + 1.0) / units_per_world * focal / wmin;
        if (r > t->max_r)
            t->max_r = r;
        for (int k = 0; k < 3; k++)
            mark_segment(mask, rc->xy[2 * k] / 16.0, rc->xy[2 * k + 1] / 16.0,
                         rc->xy[(2 * k + 2) % 6] / 16.0, rc->xy[(2 * k + 3) % 6] / 16.0, r);
    }
    /* the eye in position units, exactly (double) */
    double eye[3];
    for (int j = 0; j < 3; j++) {
        eye[j] = 0;
        for (int k = 0; k < 3; k++)
            eye[j] -= cam->view.m[k][j] / 65536.0 * (cam->view.m[k][3] / 65536.0);
        eye[j] *= units_per_world;
    }
    for (int p = 0; p < W * H; p++) {
        const uint8_t *a = &span_img[3 * p], *b = &pri_img[3 * p];
        int a_bg = !a[0] && !a[1] && !a[2], b_bg = !b[0] && !b[1] && !b[2];
        t->pixels++;
        if (memcmp(a, b, 3) && cast.owner[p] && cast.z2[p] - cast.z1[p] < NEAR_TIE) {
            /* touching surfaces: span mode's depths there are a near tie */
            t->near_tie++;
            continue;
        }
        if (memcmp(a, b, 3) && !a_bg && edge_on(src, a, eye)) {
            /* span mode drew a triangle that faces away from the exact eye
             * (seen edge-on, turned by the 28.4 rounding): BSP pruning drops it */
            t->edge_on++;
            continue;
        }
        t->covered += !a_bg;
        t->mask += mask[p];
        if (!a_bg && b_bg && t->cracks++ < 3) {
            print_error("%s view %d: crack at (%d,%d)\n", what, view, p % W, p / W);
        }
        if (!memcmp(a, b, 3))
            continue;
        t->differ++;
        if (mask[p]) {
            t->in_bound++;
        } else if (t->outside++ < 3) {
            print_error("%s view %d: pixel (%d,%d) span %02x%02x%02x priority %02x%02x%02x "
                        "outside the bound\n",
                        what, view, p % W, p / W, a[0], a[1], a[2], b[0], b[1], b[2]);
        }
    }
    t->views++;
    zt_recs_free(&recs);
}

static void build_bsp(const mesh_buf *m, zs_bspb_result *res, const char *what)
{
    zs_bspb_mesh in;
    memset(&in, 0, sizeof in);
    in.pos = m->pos;
    in.idx = m->idx;
    in.fcol = m->fcol;
    in.nv = m->nv;
    in.nt = m->nt;
    const char *err = zs_bspb_build(&in, NULL, res);
    ZT_CHECK(err == NULL, "%s: BSP compiler: %s", what, err ? err : "");
}

static void look(zs_camera *cam, double ex, double ey, double ez, double tx, double ty,
                 double tz)
{
    ZT_ST(zs_camera_look_at(cam, zs_vec3_make((zs_fixed)lrint(ex * 65536), (zs_fixed)lrint(ey * 65536),
                                              (zs_fixed)lrint(ez * 65536)),
                            zs_vec3_make((zs_fixed)lrint(tx * 65536), (zs_fixed)lrint(ty * 65536),
                                         (zs_fixed)lrint(tz * 65536)),
                            zs_vec3_make(0, ZS_FX(1), 0)),
          ZS_OK);
    ZT_ST(zs_camera_perspective(cam, ZS_FX(90), ZS_FX(1) / 16, ZS_FX(200)), ZS_OK);
}

/* Runs one scene (positions in units of 1/div world units) from views. */
static void run_scene(zt_ctx *c, mesh_buf *m, int div, const double (*views)[6], int nviews,
                      bsp_tally *t, const char *what)
{
    zs_bspb_result res;
    build_bsp(m, &res, what);
    if (res.split_weight != 8)
        printf("test_priority bsp %s: built with split weight %d (with 8 the walk would need "
               "more than ZS_BSP_MAX_STACK), walk stack %d\n",
               what, res.split_weight, res.stack);
    zs_fixed scale = ZS_FX(1) / div;
    zs_mesh src = mesh_of(m, m->pos, m->idx, m->fcol, m->nv, m->nt, scale);
    zs_mesh out = mesh_of(m, res.mesh.pos, res.mesh.idx, res.mesh.fcol, res.mesh.nv, res.mesh.nt,
                          scale);
    zs_bsp bsp = {res.nodes, &out, (uint16_t)res.node_count};
    ZT_ST(zs_bsp_check(&bsp), ZS_OK);
    for (int v = 0; v < nviews; v++) {
        zs_camera cam;
        look(&cam, views[v][0], views[v][1], views[v][2], views[v][3], views[v][4], views[v][5]);
        compare_view(c, &cam, &src, &bsp, &res, div, t, what, v);
    }
    t->scenes++;
    t->tris += m->nt;
    t->out_tris += res.mesh.nt;
    t->nodes += res.node_count;
    t->splits += res.splits;
    t->slivers += res.slivers;
    zs_bspb_free(&res);
}

static void report(const char *what, const bsp_tally *t)
{
    printf("test_priority bsp %s: %lu scenes, %lu views, %lu triangles -> %lu after %lu splits "
           "(%lu slivers), %lu nodes; %lu pixels (%lu covered), %lu differ: %lu within the bound "
           "(largest R %.2f px, %lu pixels in it), %lu outside; %lu cracks; %lu pixels of "
           "triangles span mode drew although they face away from the exact eye (edge-on, "
           "turned by rounding: pruned by the BSP), %lu where span mode's two nearest "
           "depths are within 2^-12 (touching surfaces); painter's full frame: %lu of %lu "
           "views differ from the band image\n",
           what, t->scenes, t->views, t->tris, t->out_tris, t->splits, t->slivers, t->nodes,
           t->pixels, t->covered, t->differ, t->in_bound, t->max_r, t->mask, t->outside,
           t->cracks, t->edge_on, t->near_tie, t->paint_differ, t->painted);
}

static void test_bsp_random(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 1);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 4000, 6000, 1200);
    bsp_tally boxes = {0}, plates = {0};
    const int div = 256;
    for (int n = 0; n < 40; n++) {
        mesh_buf m = {0};
        if (n % 2 == 0) { /* separated boxes in the cells of a 4 x 3 x 4 grid */
            for (int k = 0; k < 48; k++) {
                if (zt_below(&g, 3) == 0)
                    continue;
                double ctr[3] = {((k % 4) - 1.5) * 2.0 * div, ((k / 4 % 3) - 1.0) * 2.0 * div,
                                 -(3.0 + (k / 12) * 2.0) * div};
                double h[3] = {zt_uniform(&g, 0.2, 0.9) * div, zt_uniform(&g, 0.2, 0.9) * div,
                               zt_uniform(&g, 0.2, 0.9) * div};
                add_box(&m, ctr, h, zt_uniform(&g, 0, 6.3), zt_uniform(&g, 0, 6.3), 0);
            }
        } else { /* tilted plates, each in a depth slab of its own: planes cut others */
            for (int k = 0; k < 30; k++) {
                double z0 = -(2.0 + 0.3 * k) * div, z1 = z0 - 0.25 * div;
                double px[3], py[3], pz[3];
                for (int j = 0; j < 3; j++) {
                    px[j] = zt_uniform(&g, -4, 4) * (-z0 / div) * div * 0.4;
                    py[j] = zt_uniform(&g, -3, 3) * (-z0 / div) * div * 0.4;
                    pz[j] = zt_uniform(&g, z1, z0);
                }
                /* counter-clockwise on screen: seen from the eye at the origin */
                double cr = (px[1] / -pz[1] - px[0] / -pz[0]) * (py[2] / -pz[2] - py[0] / -pz[0]) -
                            (px[2] / -pz[2] - px[0] / -pz[0]) * (py[1] / -pz[1] - py[0] / -pz[0]);
                int a = add_v(&m, px[0], py[0], pz[0]), b = add_v(&m, px[1], py[1], pz[1]),
                    cc = add_v(&m, px[2], py[2], pz[2]);
                if (cr > 0)
                    add_t(&m, a, b, cc);
                else
                    add_t(&m, a, cc, b);
            }
        }
        double views[4][6] = {{0, 0, 0, 0, 0, -1},
                              {zt_uniform(&g, -1, 1), zt_uniform(&g, -1, 1), 0.5, 0, 0, -6},
                              {3, 1, -4, 0, 0, -6},
                              {-2, -1.5, -12, 0, 0, -5}};
        run_scene(&c, &m, div, (const double(*)[6])views, n % 2 ? 1 : 4, n % 2 ? &plates : &boxes,
                  n % 2 ? "plates" : "boxes");
        free(m.pos);
        free(m.idx);
        free(m.fcol);
    }
    report("boxes", &boxes);
    report("plates", &plates);
    ZT_CHECK(boxes.outside == 0 && plates.outside == 0, "pixels outside the bound");
    ZT_CHECK(boxes.cracks == 0 && plates.cracks == 0, "cracks");
    ZT_CHECK(boxes.paint_differ == 0 && plates.paint_differ == 0 && boxes.painted == boxes.views,
             "painter's image differs from the band image");
    ZT_CHECK(plates.splits > 0, "the plates made no split: the test would not test splitting");
    zt_ctx_free(&c);
}

static void test_bsp_room(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 2);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 4000, 6000, 1200);
    bsp_tally t = {0};
    const int div = 512;
    mesh_buf m = {0};
    double room_c[3] = {0, 1.5 * div, 0}, room_h[3] = {8.0 * div, 1.5 * div, 6.0 * div};
    add_box(&m, room_c, room_h, 0, 0, 1);
    for (int k = 0; k < 10; k++) { /* pillars and crates */
        double ctr[3] = {(-6.0 + 3.0 * (k % 5)) * div, 0, (k < 5 ? -3.0 : 3.0) * div};
        double h[3] = {0.4 * div, (k % 2 ? 1.5 : 0.6) * div, 0.4 * div};
        ctr[1] = h[1];
        add_box(&m, ctr, h, zt_uniform(&g, 0, 1.5), 0, 0);
    }
    double views[40][6];
    for (int v = 0; v < 40; v++) {
        double ex, ey, ez, a = zt_uniform(&g, 0, 6.283);
        if (v < 32) { /* inside, among the pillars */
            ex = zt_uniform(&g, -7.5, 7.5);
            ey = zt_uniform(&g, 0.3, 2.7);
            ez = zt_uniform(&g, -5.5, 5.5);
        } else { /* outside the room, looking at it (its outer walls face away) */
            ex = 12 * cos(a);
            ey = zt_uniform(&g, 0, 5);
            ez = 10 * sin(a);
        }
        views[v][0] = ex;
        views[v][1] = ey;
        views[v][2] = ez;
        views[v][3] = v < 32 ? ex + cos(a) : 0;
        views[v][4] = v < 32 ? ey + zt_uniform(&g, -0.5, 0.5) : 1;
        views[v][5] = v < 32 ? ez + sin(a) : 0;
    }
    run_scene(&c, &m, div, (const double(*)[6])views, 40, &t, "room");
    report("room", &t);
    ZT_CHECK(t.outside == 0, "room: pixels outside the bound");
    ZT_CHECK(t.cracks == 0, "room: cracks");
    ZT_CHECK(t.paint_differ == 0, "room: painter differs from the band image");
    free(m.pos);
    free(m.idx);
    free(m.fcol);
    zt_ctx_free(&c);
}

static int load_model(const char *path, mesh_buf *m)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    fclose(f);
    const struct aiScene *s = aiImportFile(path, aiProcess_Triangulate |
                                                     aiProcess_JoinIdenticalVertices |
                                                     aiProcess_PreTransformVertices);
    if (!s)
        return -1;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, rad = 0;
    for (unsigned k = 0; k < s->mNumMeshes; k++)
        for (unsigned i = 0; i < s->mMeshes[k]->mNumVertices; i++) {
            const struct aiVector3D *v = &s->mMeshes[k]->mVertices[i];
            double p[3] = {v->x, v->y, v->z};
            for (int j = 0; j < 3; j++) {
                lo[j] = p[j] < lo[j] ? p[j] : lo[j];
                hi[j] = p[j] > hi[j] ? p[j] : hi[j];
            }
        }
    for (int j = 0; j < 3; j++)
        rad = (hi[j] - lo[j]) / 2 > rad ? (hi[j] - lo[j]) / 2 : rad;
    if (!(rad > 0))
        rad = 1;
    for (unsigned k = 0; k < s->mNumMeshes; k++) {
        const struct aiMesh *am = s->mMeshes[k];
        size_t base = m->nv;
        if (base + am->mNumVertices > 30000)
            break;
        for (unsigned i = 0; i < am->mNumVertices; i++) {
            const struct aiVector3D *v = &am->mVertices[i];
            add_v(m, (v->x - (lo[0] + hi[0]) / 2) / rad * 8192,
                  (v->y - (lo[1] + hi[1]) / 2) / rad * 8192,
                  (v->z - (lo[2] + hi[2]) / 2) / rad * 8192);
        }
        for (unsigned i = 0; i < am->mNumFaces && m->nt < 12000; i++)
            if (am->mFaces[i].mNumIndices == 3)
                add_t(m, (int)(base + am->mFaces[i].mIndices[0]),
                      (int)(base + am->mFaces[i].mIndices[1]),
                      (int)(base + am->mFaces[i].mIndices[2]));
    }
    aiReleaseImport(s);
    return m->nt > 0 ? 1 : -1;
}

static void test_bsp_models(void **state)
{
    (void)state;
    static const char *models[] = {
        "/usr/share/assimp/models/STL/sphereWithHole.stl",
        "/usr/share/assimp/models/OBJ/box.obj",
        "/usr/share/assimp/models/OBJ/spider.obj",
        "/usr/share/assimp/models/PLY/cube.ply",
        "/usr/share/assimp/models/Collada/duck.dae",
        "/usr/share/assimp/models/OBJ/WusonOBJ.obj",
    };
    zt_ctx c;
    zt_ctx_init(&c, W, H, 20000, 40000, 4096);
    int loaded = 0;
    for (size_t k = 0; k < sizeof models / sizeof models[0]; k++) {
        mesh_buf m = {0};
        int st = load_model(models[k], &m);
        if (st <= 0) {
            printf("test_priority: %s %s, skipped\n", models[k], st ? "not loaded" : "missing");
            continue;
        }
        loaded++;
        bsp_tally t = {0};
        double views[4][6] = {{0, 0, 3, 0, 0, 0}, {2, 1.5, 2, 0, 0, 0}, {-2.5, -1, -1, 0, 0, 0},
                              {0.3, 2.8, 0.2, 0, 0, 0}};
        run_scene(&c, &m, 8192, (const double(*)[6])views, 4, &t, models[k]);
        report(strrchr(models[k], '/') + 1, &t);
        ZT_CHECK(t.outside == 0, "%s: pixels outside the bound", models[k]);
        ZT_CHECK(t.cracks == 0, "%s: cracks", models[k]);
        ZT_CHECK(t.paint_differ == 0, "%s: painter differs from the band image", models[k]);
        free(m.pos);
        free(m.idx);
        free(m.fcol);
    }
    ZT_CHECK(loaded > 0, "no assimp test model loaded");
    zt_ctx_free(&c);
}

/* ---------------- depth sort (NNS) against the ray caster ---------------- */

static zs_color rand_color(zt_rng *g)
{
    return (zs_color)(zt_u32(g) & 0xFFFFFFu);
}

typedef struct hook_split {
    zt_recs *draw, *pieces;
    int sorting;
} hook_split;

static void hook_phase(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    hook_split *h = user;
    zt_recs_hook(h->sorting ? h->pieces : h->draw, tag, xy, z);
}

/* Three bars on the lines tangent to a circle, turned 120 degrees apart,
 * their depth growing along them: at each crossing the later bar is on top,
 * so the three overlap cyclically. */
static void add_bars(zt_rng *g, zt_scene *sc)
{
    double cx = zt_uniform(g, 30, W - 30), cy = zt_uniform(g, 25, H - 25);
    double o = zt_uniform(g, 3, 8), a0 = zt_uniform(g, 0, 6.283), len = zt_uniform(g, 22, 34);
    double w = zt_uniform(g, 2, 5), d0 = zt_uniform(g, 3, 6), grad = zt_uniform(g, 0.02, 0.06);
    if (zt_below(g, 2))
        grad = -grad;
    for (int k = 0; k < 3; k++) {
        double a = a0 + k * 2.0943951;
        double nx = cos(a), ny = sin(a), tx = -ny, ty = nx;
        int v[4];
        for (int j = 0; j < 4; j++) {
            double sp = (j & 1) ? len : -len, off = o + ((j & 2) ? w : 0);
            v[j] = zt_scene_vertex_px(sc, cx + off * nx + sp * tx, cy + off * ny + sp * ty,
                                      d0 + grad * sp, rand_color(g));
        }
        zs_color col = rand_color(g);
        zt_scene_tri_front(sc, v[0], v[1], v[3], col);
        zt_scene_tri_front(sc, v[0], v[3], v[2], col);
    }
}

/* Two triangles through each other: depths tilted opposite ways. */
static void add_penetrating(zt_rng *g, zt_scene *sc)
{
    double cx = zt_uniform(g, 20, W - 20), cy = zt_uniform(g, 15, H - 15), d = zt_uniform(g, 3, 8);
    for (int k = 0; k < 2; k++) {
        double tilt = (k ? -1 : 1) * zt_uniform(g, 0.05, 0.2);
        int v[3];
        for (int j = 0; j < 3; j++) {
            double px = cx + zt_uniform(g, -25, 25), py = cy + zt_uniform(g, -20, 20);
            v[j] = zt_scene_vertex_px(sc, px, py, d + tilt * (px - cx), rand_color(g));
        }
        zt_scene_tri_front(sc, v[0], v[1], v[2], rand_color(g));
    }
}

typedef struct nns_tally {
    unsigned long px, excluded, near_split, bad, scenes_wrong, pairs, swaps, splits, giveups;
    unsigned long paint_differ, paint_bad, order_pairs, order_bad, order_scenes_wrong;
} nns_tally;

/* The ordered list against exact depths: for every two records of the list
 * whose coverage shares a centre (away from cut edges and near ties), the
 * one later in the list (painted over the other) must be the nearer there.
 * Returns the violating pairs; counts the overlapping pairs in *pairs. */
static unsigned long check_order(const zs_renderer *r, const uint8_t *mask, const zt_cast *cast,
                                 unsigned long *pairs, int verbose)
{
    static uint16_t order[800];
    static zt_rec rec[800];
    uint32_t n = 0;
    unsigned long bad = 0;
    ZT_ST(zs_priority_order(r, order, 800, &n), ZS_OK);
    for (uint32_t i = 0; i < n; i++) {
        zs_record_tri rt;
        ZT_ST(zs_record_get(r, order[i], &rt), ZS_OK);
        rec[i].tag = (uint16_t)rt.rgb[0];
        for (int k = 0; k < 3; k++) {
            rec[i].xy[2 * k] = rt.x[k];
            rec[i].xy[2 * k + 1] = rt.y[k];
            rec[i].z[k] = rt.z[k];
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        int ax0, ay0, ax1, ay1;
        if (!zt_bbox(rec[i].xy, W, H, &ax0, &ay0, &ax1, &ay1))
            continue;
        for (uint32_t j = i + 1; j < n; j++) {
            int bx0, by0, bx1, by1, overlap = 0, wrong = 0;
            if (!zt_bbox(rec[j].xy, W, H, &bx0, &by0, &bx1, &by1))
                continue;
            for (int y = ay0 > by0 ? ay0 : by0; y <= (ay1 < by1 ? ay1 : by1); y++)
                for (int x = ax0 > bx0 ? ax0 : bx0; x <= (ax1 < bx1 ? ax1 : bx1); x++) {
                    int p = y * W + x;
                    if (mask[p] || (cast->owner[p] && cast->z2[p] - cast->z1[p] < 1.0 / 1048576) ||
                        !zt_covers(rec[i].xy, x, y) || !zt_covers(rec[j].xy, x, y))
                        continue;
                    overlap = 1;
                    /* j is painted after i: it must not be the farther */
                    if (zt_depth_at(&rec[j], x, y) > zt_depth_at(&rec[i], x, y) + 1.0 / 1048576) {
                        if (!wrong && verbose)
                            printf("order: records %u (list %u) over %u (list %u) at (%d,%d): "
                                   "%.9f behind %.9f, %u records, top %u\n",
                                   order[j], j, order[i], i, x, y, zt_depth_at(&rec[j], x, y),
                                   zt_depth_at(&rec[i], x, y), n, cast->owner[p]);
                        wrong = 1;
                    }
                }
            *pairs += (unsigned long)overlap;
            bad += (unsigned long)wrong;
        }
    }
    return bad;
}

static void run_sorted(zt_ctx *c, const zs_camera *cam, const zs_mesh *mesh, zs_sort_kind kind,
                       nns_tally *t, int scene)
{
    static uint8_t img[W * H * 2], mask[W * H];
    zt_recs draw = {0}, pieces = {0};
    hook_split h = {&draw, &pieces, 0};
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_ID16;
    zs_set_setup_hook(&c->r, hook_phase, &h);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw(&c->r, mesh, NULL), ZS_OK);
    h.sorting = 1;
    ZT_ST(zs_depth_sort(&c->r, kind, 0), ZS_OK);
    ZT_ST(zt_render_rows_all(&c->r, img, W, H, ZS_FMT_ID16, 1 + scene % 5), ZS_OK);
    zs_set_setup_hook(&c->r, NULL, NULL);
    const zs_stats *st = &c->r.stats;
    ZT_CHECK(st->tris_dropped == 0 && st->records_skipped == 0, "pools too small");
    t->pairs += st->sort_pairs;
    t->swaps += st->sort_swaps;
    t->splits += st->sort_splits;
    t->giveups += st->sort_giveups;
    /* the truth: the scene's records as drawn, ray cast */
    static zt_cast cast;
    if (!cast.owner)
        zt_cast_alloc(&cast, W, H);
    zt_raycast(&draw, &cast);
    /* pixels near the pieces' edges (their cut vertices are rounded) */
    memset(mask, 0, sizeof mask);
    for (size_t i = 0; i < pieces.n; i++)
        for (int k = 0; k < 3; k++)
            mark_segment(mask, pieces.v[i].xy[2 * k] / 16.0, pieces.v[i].xy[2 * k + 1] / 16.0,
                         pieces.v[i].xy[(2 * k + 2) % 6] / 16.0,
                         pieces.v[i].xy[(2 * k + 3) % 6] / 16.0, 1.0);
    unsigned long bad = 0;
    for (int p = 0; p < W * H; p++) {
        uint16_t id = zt_id_at(img, W, p % W, p / W), want = cast.owner[p];
        t->px++;
        if (want && cast.z2[p] - cast.z1[p] < 1.0 / 1048576) {
            t->excluded++;
            continue;
        }
        if (mask[p]) {
            t->near_split++;
            continue;
        }
        if (id != want)
            bad++;
    }
    t->bad += bad;
    t->scenes_wrong += bad > 0;
    /* the ordered list, pair by pair */
    unsigned long obad = check_order(&c->r, mask, &cast, &t->order_pairs,
                                    kind == ZS_SORT_NNS && getenv("ZT_ORDER_DEBUG"));
    t->order_bad += obad;
    t->order_scenes_wrong += obad > 0;
    /* the same frame painted into a full frame buffer */
    static uint8_t paint_img[W * H * 2];
    memset(paint_img, 0x5A, sizeof paint_img);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw(&c->r, mesh, NULL), ZS_OK);
    ZT_ST(zs_depth_sort(&c->r, kind, 0), ZS_OK);
    ZT_ST(zs_paint_frame(&c->r, paint_img, W * 2), ZS_OK);
    t->paint_differ += zt_first_diff(img, paint_img, sizeof img) >= 0;
    for (int p = 0; p < W * H; p++) {
        uint16_t want = cast.owner[p];
        if ((want && cast.z2[p] - cast.z1[p] < 1.0 / 1048576) || mask[p])
            continue;
        t->paint_bad += zt_id_at(paint_img, W, p % W, p / W) != want;
    }
    zt_recs_free(&draw);
    zt_recs_free(&pieces);
}

static void test_nns(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 3);
    zt_ctx c;
    memset(&c, 0, sizeof c);
    c.cfg = zs_config_default(W, H, 800, 2400, 800);
    c.cfg.flags = ZS_CFG_PRIORITY;
    c.arena_size = zs_arena_bytes(&c.cfg);
    ZT_CHECK(c.arena_size == zs_arena_bytes(&(zs_config){W, H, 800, 2400, 800, 0}) +
                                 2 * ((800 * 2 + 7) / 8 * 8),
             "ZS_CFG_PRIORITY costs %zu bytes", c.arena_size);
    c.arena = malloc(c.arena_size);
    ZT_ST(zs_init(&c.r, c.arena, c.arena_size, &c.cfg), ZS_OK);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    nns_tally nns = {0}, plain = {0};
    const int nscenes = 120;
    for (int n = 0; n < nscenes; n++) {
        zt_scene_reset(&sc);
        int kind = n % 3; /* bars, penetrations, both with random triangles */
        if (kind != 1)
            add_bars(&g, &sc);
        if (kind != 0)
            add_penetrating(&g, &sc);
        if (kind == 2)
            zt_scene_random(&g, &sc, 12, ZT_SC_FLAT | ZT_SC_PLAIN, 0.5);
        zs_mesh mesh = zt_scene_mesh(&sc, 1, 0);
        run_sorted(&c, &cam, &mesh, ZS_SORT_NNS, &nns, n);
        run_sorted(&c, &cam, &mesh, ZS_SORT_DEPTH, &plain, n);
    }
    printf("test_priority nns: %d scenes (cyclic bars, penetrating pairs, both with random "
           "triangles), %lu pixels; NNS: %lu pairs resolved, %lu moves, %lu splits, %lu give-ups, "
           "%lu pixels differ from the ray caster (%lu near ties and %lu near cut edges "
           "excluded); plain sort: %lu pixels wrong in %lu of %d scenes\n",
           nscenes, nns.px, nns.pairs, nns.swaps, nns.splits, nns.giveups, nns.bad,
           nns.excluded, nns.near_split, plain.bad, plain.scenes_wrong, nscenes);
    printf("test_priority painter: NNS scenes painted into a full frame: %lu of %d differ from "
           "the band image, %lu pixels from the ray caster; ordered list: %lu overlapping "
           "record pairs, %lu in the wrong order (plain sort: %lu of %lu pairs wrong, in %lu "
           "of %d scenes; its painted frames %lu differ from its band images)\n",
           nns.paint_differ, nscenes, nns.paint_bad, nns.order_pairs, nns.order_bad,
           plain.order_bad, plain.order_pairs, plain.order_scenes_wrong, nscenes,
           plain.paint_differ);
    ZT_CHECK(nns.bad == 0, "NNS order: %lu pixels differ from the ray caster", nns.bad);
    ZT_CHECK(nns.paint_differ == 0 && plain.paint_differ == 0 && nns.paint_bad == 0,
             "painter: %lu + %lu frames differ from the band image, %lu pixels from the ray "
             "caster", nns.paint_differ, plain.paint_differ, nns.paint_bad);
    ZT_CHECK(nns.order_bad == 0 && nns.order_pairs > 0, "ordered list: %lu pairs wrong",
             nns.order_bad);
    ZT_CHECK(plain.order_scenes_wrong * 2 > (unsigned long)nscenes,
             "the plain sort's list was wrong in only %lu scenes", plain.order_scenes_wrong);
    ZT_CHECK(nns.splits > 0, "no split: the scenes would not test cycles");
    ZT_CHECK(plain.scenes_wrong * 2 > (unsigned long)nscenes,
             "the plain sort was wrong in only %lu of %d scenes", plain.scenes_wrong, nscenes);
    /* without the flag, and with a bad kind */
    zt_ctx d;
    zt_ctx_init(&d, 16, 16, 8, 8, 8);
    ZT_ST(zs_frame_begin(&d.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_depth_sort(&d.r, ZS_SORT_NNS, 0), ZS_ERR_MODE);
    ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_depth_sort(&c.r, (zs_sort_kind)7, 0), ZS_ERR_ARGUMENT);
    zt_ctx_free(&d);
    zt_scene_free(&sc);
    free(c.arena);
}

/* ---------------- bad trees ---------------- */

static void test_bad_trees(void **state)
{
    (void)state;
    static const int16_t pos[] = {0, 0, -4, 4, 0, -4, 0, 4, -4, 0, 0, -8, 4, 0, -8, 0, 4, -8};
    static const uint16_t idx[] = {0, 1, 2, 3, 4, 5};
    zs_mesh mesh;
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos;
    mesh.indices = idx;
    mesh.scale = ZS_FX(1);
    mesh.vertex_count = 6;
    mesh.triangle_count = 2;
    mesh.color = 0xFFFFFF;
    /* good: root plane z = -4 (front +z), its triangle; back child z = -8 */
    zs_bsp_node good[2] = {{4, {0, 0, 1}, ZS_BSP_NONE, 1, 0, 1, 0},
                           {8, {0, 0, 1}, ZS_BSP_NONE, ZS_BSP_NONE, 1, 1, 0}};
    zs_bsp bsp = {good, &mesh, 2};
    ZT_ST(zs_bsp_check(&bsp), ZS_OK);
    zs_bsp_node bad[3];
    struct {
        const char *what;
        int node, field;
        long value;
    } cases[] = {
        {"back child out of range", 0, 1, 7},     {"back child is the node (cycle)", 0, 1, 0},
        {"front child not the next node", 0, 0, 1 + 1}, {"front child pointing back", 1, 0, 0},
        {"range past the mesh", 1, 2, 2},           {"n_front past the mesh", 1, 3, 5},
        {"normal out of range", 0, 4, 1L << 24},    {"d out of range", 0, 5, 0},
        {"node count of zero", -1, 0, 0},           {"node count above the tree", -2, 0, 0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        memcpy(bad, good, sizeof good);
        zs_bsp b = {bad, &mesh, 2};
        int nd = cases[k].node;
        if (nd >= 0) {
            zs_bsp_node *x = &bad[nd];
            switch (cases[k].field) {
            case 0: x->front = (uint16_t)cases[k].value; break;
            case 1: x->back = (uint16_t)cases[k].value; break;
            case 2: x->first = (uint16_t)cases[k].value; break;
            case 3: x->n_front = (uint16_t)cases[k].value; break;
            case 4: x->n[1] = (int32_t)cases[k].value; break;
            case 5: x->d = ZS_BSP_MAX_D; break;
            }
        } else if (nd == -1) {
            b.node_count = 0;
        } else {
            bad[2] = good[1];
            b.node_count = 3; /* node 2 is never reached */
        }
        zs_status st = zs_bsp_check(&b);
        ZT_CHECK(st == ZS_ERR_BSP, "%s: check gave %s", cases[k].what, zs_strerror(st));
    }
    /* a node shared by two parents: 0 -> front 1, back 2; 1 -> back 2 */
    zs_bsp_node shared[3] = {{4, {0, 0, 1}, 1, 2, 0, 1, 0},
                             {8, {0, 0, 1}, ZS_BSP_NONE, 2, 1, 1, 0},
                             {9, {0, 0, 1}, ZS_BSP_NONE, ZS_BSP_NONE, 0, 0, 0}};
    zs_bsp sb = {shared, &mesh, 3};
    ZT_ST(zs_bsp_check(&sb), ZS_ERR_BSP);
    /* a walk that could need more than ZS_BSP_MAX_STACK pending entries: a
     * chain of front children, each with its own triangle pending */
    static zs_bsp_node chain[ZS_BSP_MAX_STACK + 2];
    for (int k = 0; k < ZS_BSP_MAX_STACK + 2; k++) {
        zs_bsp_node nd = {k, {0, 0, 1}, (uint16_t)(k + 1), ZS_BSP_NONE, 0, 1, 0};
        chain[k] = nd;
    }
    chain[ZS_BSP_MAX_STACK + 1].front = ZS_BSP_NONE;
    zs_bsp deep = {chain, &mesh, ZS_BSP_MAX_STACK + 2};
    ZT_ST(zs_bsp_check(&deep), ZS_ERR_BSP);
    deep.node_count = ZS_BSP_MAX_STACK + 1;
    chain[ZS_BSP_MAX_STACK].front = ZS_BSP_NONE;
    ZT_ST(zs_bsp_check(&deep), ZS_OK); /* exactly the limit */
    /* the same length without pending ranges costs nothing */
    static zs_bsp_node chain2[1000];
    for (int k = 0; k < 1000; k++) {
        zs_bsp_node nd = {k, {0, 0, 1}, (uint16_t)(k + 1 < 1000 ? (unsigned)k + 1u : ZS_BSP_NONE),
                          ZS_BSP_NONE, 0, 0, 0};
        chain2[k] = nd;
    }
    zs_bsp longc = {chain2, &mesh, 1000};
    ZT_ST(zs_bsp_check(&longc), ZS_OK);
    ZT_ST(zs_bsp_check(NULL), ZS_ERR_NULL);
    /* a bad tree is never followed: nothing stored */
    zt_ctx c;
    zt_ctx_init(&c, 32, 32, 16, 16, 16);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_PRIORITY), ZS_OK);
    ZT_ST(zs_draw_bsp(&c.r, &sb, NULL), ZS_ERR_BSP);
    ZT_CHECK(c.r.stats.records == 0 && c.r.stats.tris_submitted == 0, "bad tree stored records");
    ZT_ST(zs_draw_bsp(&c.r, &bsp, NULL), ZS_OK);
    ZT_CHECK(c.r.stats.records == 2 && c.r.stats.bsp_nodes == 2, "good tree: %u records",
             c.r.stats.records);
    /* a model matrix that is not rotation and uniform scale */
    zs_mat34 sk = zs_mat34_scale(ZS_FX(1), ZS_FX(2), ZS_FX(1));
    ZT_ST(zs_draw_bsp(&c.r, &bsp, &sk), ZS_ERR_ARGUMENT);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_walk_oracle), cmocka_unit_test(test_bsp_random),
        cmocka_unit_test(test_bsp_room),    cmocka_unit_test(test_bsp_models),
        cmocka_unit_test(test_nns),         cmocka_unit_test(test_bad_trees),
        cmocka_unit_test(test_painter_walk), cmocka_unit_test(test_painter_errors),
        cmocka_unit_test(test_painter_textured),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stdout);
    return rc;
}
