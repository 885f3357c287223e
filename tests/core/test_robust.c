/*
 * test_robust: hostile input. Near-plane crossings (clipped records against
 * the ray caster), triangles wholly behind the eye / beyond far / off-screen
 * (rejected, nothing drawn), int16 extremes with large scales and tiny
 * scales, degenerate triangles (culled and counted), and every pool overflowed
 * (triangles, vertices, active edges): no fault, documented status codes,
 * drops counted, guard bytes around and between the rows of the output
 * untouched, and in every frame the documented accounting
 *   tris_submitted == culled + rejected + empty + dropped + stored
 * plus stats.records == setup-hook calls.
 *
 * Every frame here also checks a weak invariant that needs no depth: a pixel
 * that shows tag t is covered (reference rasterizer) by a record of tag t.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64
#define GUARD 64
#define PAD 7
#define TOL (1.0 / 1048576.0)
#define SEED 0x50B057AA00000009ull

static unsigned long g_frames, g_clipped, g_rejected, g_culled, g_dropped, g_vdropped,
    g_edropped, g_excluded, g_saturated, g_px;

typedef struct rframe {
    zs_status draw_st;
    zs_status render_st;
    zs_stats st;
    zt_recs recs;
    uint8_t img[W * H * 2]; /* tight copy of the ID16 output */
} rframe;

/* Renders meshes in ID16 with guard bytes and row padding; checks guards,
 * accounting, records == hook calls, and the weak coverage invariant. */
static void robust_frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                         const zs_mesh *meshes, int nm, const zs_mat34 *model, rframe *f,
                         int band)
{
    size_t stride = W * 2 + PAD;
    size_t total = GUARD + stride * H + GUARD;
    uint8_t *buf = malloc(total);
    memset(buf, 0xE7, total);
    zt_recs_clear(&f->recs);
    zs_set_setup_hook(&c->r, zt_recs_hook, &f->recs);
    ZT_ST(zs_frame_begin(&c->r, cam, mode), ZS_OK);
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_ID16;
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    f->draw_st = ZS_OK;
    for (int i = 0; i < nm; i++) {
        zs_status s = zs_draw(&c->r, &meshes[i], model);
        if (s != ZS_OK && f->draw_st == ZS_OK) f->draw_st = s;
    }
    f->render_st = ZS_OK;
    for (int y = 0; y < H && f->render_st == ZS_OK; y += band) {
        int n = band < H - y ? band : H - y;
        f->render_st = zs_render_rows(&c->r, y, n, buf + GUARD + (size_t)y * stride, stride);
    }
    ZT_ST(f->render_st, ZS_OK);
    f->st = *zs_frame_stats(&c->r);
    g_frames++;
    /* guards and row padding */
    for (size_t i = 0; i < GUARD; i++) {
        ZT_CHECK(buf[i] == 0xE7, "guard byte %zu before the buffer overwritten", i);
        ZT_CHECK(buf[total - 1 - i] == 0xE7, "guard byte %zu after the buffer overwritten", i);
    }
    for (int y = 0; y < H; y++) {
        for (size_t k = W * 2; k < stride; k++)
            ZT_CHECK(buf[GUARD + (size_t)y * stride + k] == 0xE7,
                     "row %d padding byte %zu overwritten", y, k);
        memcpy(f->img + (size_t)y * W * 2, buf + GUARD + (size_t)y * stride, W * 2);
    }
    free(buf);
    /* accounting */
    const zs_stats *s = &f->st;
    ZT_CHECK(s->tris_submitted ==
                 s->tris_culled + s->tris_rejected + s->tris_empty + s->tris_dropped + s->tris_stored,
             "accounting: submitted %u != culled %u + rejected %u + empty %u + dropped %u + "
             "stored %u",
             s->tris_submitted, s->tris_culled, s->tris_rejected, s->tris_empty, s->tris_dropped,
             s->tris_stored);
    ZT_CHECK(s->records == f->recs.n, "stats.records %u != %zu hook calls", s->records, f->recs.n);
    ZT_CHECK(s->records >= s->tris_stored, "records %u < tris_stored %u", s->records,
             s->tris_stored);
    ZT_CHECK(s->records <= c->cfg.max_triangles, "records %u above max_triangles %u", s->records,
             c->cfg.max_triangles);
    ZT_CHECK(s->verts_stored <= c->cfg.max_vertices, "verts_stored %u above max_vertices %u",
             s->verts_stored, c->cfg.max_vertices);
    ZT_CHECK(s->tris_drawn <= s->records, "tris_drawn %u > records %u", s->tris_drawn, s->records);
    ZT_CHECK(s->rows == H, "rows %u", s->rows);
    ZT_CHECK(s->max_active_edges <= c->cfg.max_active_edges, "max_active_edges %u above %u",
             s->max_active_edges, c->cfg.max_active_edges);
    if (mode == ZS_MODE_SPAN)
        ZT_CHECK(s->pixels_shaded == (uint32_t)W * H, "span pixels_shaded %u", s->pixels_shaded);
    /* a shown tag is covered by one of its records */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint16_t id = zt_id_at(f->img, W, x, y);
            if (!id) continue;
            int ok = 0;
            for (size_t i = 0; i < f->recs.n && !ok; i++)
                ok = f->recs.v[i].tag == id && zt_covers(f->recs.v[i].xy, x, y);
            ZT_CHECK(ok, "pixel (%d,%d) shows tag %u, which no record of that tag covers", x, y, id);
        }
    g_clipped += s->tris_clipped;
    g_rejected += s->tris_rejected;
    g_culled += s->tris_culled;
    g_dropped += s->tris_dropped;
    g_vdropped += s->verts_dropped;
    g_edropped += s->edges_dropped;
    g_saturated += s->saturated;
}

/* ID16 output against the ray caster over the frame's records; returns the
 * number of disagreeing pixels (beyond near ties), printing the first ones */
static unsigned long vs_raycast(const rframe *f, const char *what)
{
    zt_cast cast;
    zt_cast_alloc(&cast, W, H);
    zt_raycast(&f->recs, &cast);
    unsigned long bad = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int p = y * W + x;
            uint16_t id = zt_id_at(f->img, W, x, y), want = cast.owner[p];
            if (want) g_px++;
            int tie = want && cast.z2[p] - cast.z1[p] < TOL;
            if (tie) g_excluded++;
            if (id == want || tie) continue;
            if (bad++ < 3) {
                print_error("%s: pixel (%d,%d) ID16 %u, ray caster %u (z %.9f, runner-up %.9f)\n",
                            what, x, y, id, want, cast.z1[p], cast.z2[p]);
                for (size_t i = 0; i < f->recs.n; i++)
                    if ((f->recs.v[i].tag == id || f->recs.v[i].tag == want) &&
                        zt_covers(f->recs.v[i].xy, x, y))
                        print_error("  record tag %u xy %d %d %d %d %d %d z %u %u %u -> %.9f\n",
                                    f->recs.v[i].tag, f->recs.v[i].xy[0], f->recs.v[i].xy[1],
                                    f->recs.v[i].xy[2], f->recs.v[i].xy[3], f->recs.v[i].xy[4],
                                    f->recs.v[i].xy[5], f->recs.v[i].z[0], f->recs.v[i].z[1],
                                    f->recs.v[i].z[2], zt_depth_at(&f->recs.v[i], x, y));
            }
        }
    zt_cast_free(&cast);
    return bad;
}

static rframe *new_frame(void) { return calloc(1, sizeof(rframe)); }
static void free_frame(rframe *f)
{
    zt_recs_free(&f->recs);
    free(f);
}

static int all_background(const rframe *f)
{
    for (int i = 0; i < W * H; i++)
        if (zt_id_at(f->img, W, i % W, i / W)) return 0;
    return 1;
}

/* ---------------------------------------------------------------- */

static void test_near_plane(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 400, 1200, 400);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    rframe *f = new_frame();
    unsigned long bad = 0, clipped = 0;
    for (int n = 0; n < 120; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 5, 30), ZT_SC_NEAR | ZT_SC_PLAIN, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 1 + n % 7);
            ZT_ST(f->draw_st, ZS_OK);
            char what[96];
            snprintf(what, sizeof what, "near-plane scene %d (%s, seed %llx)", n,
                     mode ? "zline" : "span", (unsigned long long)SEED);
            bad += vs_raycast(f, what);
            if (mode == 0) clipped += f->st.tris_clipped;
            /* clipped pieces never reach in front of the near plane: depth >= 0 */
        }
    }
    ZT_CHECK(clipped > 0, "no triangle was clipped: the test does not exercise the near plane");
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster in near-plane scenes", bad);
    free_frame(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* The minimal scene found by test_raycast (seed 4a7ca57000000003 scene 132):
 * a near-plane-clipped sliver whose window depth changes by more than 1.0 per
 * pixel, in front of another triangle. */
static void test_steep_sliver(void **state)
{
    (void)state;
    static const int16_t pos[] = {105, 48, -193, -68, 223, -177, -288, 21, -177,
                                  51,  49, 43,   -262, 264, -599, -304, 382, -752};
    static const uint16_t idx[] = {0, 1, 2, 3, 4, 5};
    zt_ctx c;
    zt_ctx_init(&c, 96, 80, 16, 32, 16);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 128;
    m.vertex_count = 6;
    m.triangle_count = 2;
    zt_recs recs = {0};
    static uint8_t img[96 * 80 * 2];
    zt_cast cast;
    zt_cast_alloc(&cast, 96, 80);
    unsigned long bad = 0;
    for (int mode = 0; mode < 2; mode++) {
        ZT_ST(zt_frame(&c, &cam, (zs_visibility)mode, NULL, &m, 1, &recs, img, 80), ZS_OK);
        zt_raycast(&recs, &cast);
        for (int y = 0; y < 80; y++)
            for (int x = 0; x < 96; x++) {
                int p = y * 96 + x;
                uint16_t id = zt_id_at(img, 96, x, y);
                if (id == cast.owner[p] || cast.z2[p] - cast.z1[p] < TOL) continue;
                if (bad++ < 2)
                    print_error("steep sliver (%s): pixel (%d,%d) ID16 %u, ray caster %u (z %.6f "
                                "vs %.6f)\n",
                                mode ? "zline" : "span", x, y, id, cast.owner[p], cast.z1[p],
                                cast.z2[p]);
            }
    }
    zt_cast_free(&cast);
    zt_recs_free(&recs);
    zt_ctx_free(&c);
    ZT_CHECK(bad == 0, "a steep (depth slope > 1 per pixel) clipped sliver is drawn at the wrong "
             "depth: %lu pixels", bad);
}

static void test_rejected(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 64, 64, 32);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(20));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 256);
    /* behind the eye (z > 0), including one that would project onto the
     * screen through the eye; beyond far; far to the left / right / above /
     * below the view volume */
    double tris[][9] = {
        {-1, -1, 2, 1, -1, 2, 0, 1, 2},         {-1, -1, 0.2, 1, -1, 0.3, 0, 1, 0.1},
        {-5, -5, 8, 5, -5, 8, 0, 5, 8},          {-1, -1, -25, 1, -1, -25, 0, 1, -30},
        {-60, -1, -5, -50, -1, -5, -55, 1, -5},  {50, -1, -5, 60, -1, -5, 55, 1, -5},
        {-1, 50, -5, 1, 50, -5, 0, 60, -5},      {-1, -60, -5, 1, -60, -5, 0, -50, -5},
    };
    int nt = (int)(sizeof tris / sizeof tris[0]);
    for (int i = 0; i < nt; i++) {
        int v[3];
        for (int k = 0; k < 3; k++)
            v[k] = zt_scene_vertex_world(&sc, tris[i][3 * k], tris[i][3 * k + 1], tris[i][3 * k + 2],
                                         0);
        /* both windings: neither may draw anything */
        zt_scene_tri(&sc, v[0], v[1], v[2], 0);
        zt_scene_tri(&sc, v[0], v[2], v[1], 0);
    }
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    rframe *f = new_frame();
    for (int mode = 0; mode < 2; mode++) {
        robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 5);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(all_background(f), "a triangle outside the view volume was drawn");
        ZT_CHECK(f->recs.n == 0, "%zu records stored for triangles outside the view volume",
                 f->recs.n);
        ZT_CHECK(f->st.tris_submitted == (uint32_t)(2 * nt), "submitted %u", f->st.tris_submitted);
        ZT_CHECK(f->st.tris_stored == 0 && f->st.tris_empty == 0,
                 "stored %u empty %u for triangles outside the view volume", f->st.tris_stored,
                 f->st.tris_empty);
        /* one winding of each is front-facing: at least those are rejected
         * (the back-facing ones may be culled or rejected first) */
        ZT_CHECK(f->st.tris_rejected >= (uint32_t)nt,
                 "only %u of %d outside front-facing triangles counted as rejected",
                 f->st.tris_rejected, nt);
    }
    free_frame(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_extremes(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xE);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 200, 600, 200);
    rframe *f = new_frame();
    int16_t pos[3 * 60];
    uint16_t idx[3 * 20];
    unsigned long bad = 0;
    for (int n = 0; n < 200; n++) {
        /* int16 extremes and random values, big or tiny scales, model
         * matrices that scale and translate a lot */
        for (int i = 0; i < 60; i++) {
            int r = (int)zt_below(&g, 4);
            int32_t v = r == 0 ? (zt_below(&g, 2) ? 32767 : -32768)
                        : r == 1 ? (int32_t)zt_range(&g, -32768, 32767)
                                 : (int32_t)zt_range(&g, -300, 300);
            pos[i] = (int16_t)v;
        }
        for (int t = 0; t < 20; t++) {
            idx[3 * t] = (uint16_t)(3 * t);
            idx[3 * t + 1] = (uint16_t)(3 * t + 1);
            idx[3 * t + 2] = (uint16_t)(3 * t + 2);
        }
        zs_mesh m;
        memset(&m, 0, sizeof m);
        m.positions = pos;
        m.indices = idx;
        m.vertex_count = 60;
        m.triangle_count = 20;
        int sk = n % 4;
        /* scales keep model coordinates within +-32767 units */
        m.scale = sk == 0 ? 65535 : sk == 1 ? ZS_FX(1) / 16 : sk == 2 ? 1 : ZS_FX(1) / 1024;
        zs_mat34 model = zs_mat34_identity();
        if (n % 3 == 1) model = zs_mat34_translate(0, 0, -(zs_fixed)zt_range(&g, 0, ZS_FX(30000)));
        if (n % 3 == 2) {
            zs_mat34 s = zs_mat34_scale(ZS_FX(1) / 64, ZS_FX(1) / 64, ZS_FX(1) / 64);
            zs_mat34 t = zs_mat34_translate(0, 0, -ZS_FX(2));
            model = zs_mat34_mul(&t, &s);
        }
        zs_camera cam;
        zs_fixed nearz = n % 5 == 0 ? 1 : n % 5 == 1 ? ZS_FX(1) / 100 : ZS_FX(1) / 2;
        zs_fixed farz = n % 2 ? ZS_FX(32767) : ZS_FX(100);
        zt_camera_std(&cam, nearz, farz);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, &model, f, 1 + n % 9);
            ZT_ST(f->draw_st, ZS_OK);
            char what[96];
            snprintf(what, sizeof what, "extremes case %d (%s, seed %llx)", n,
                     mode ? "zline" : "span", (unsigned long long)SEED);
            bad += vs_raycast(f, what);
            for (size_t i = 0; i < f->recs.n; i++)
                for (int k = 0; k < 3; k++)
                    ZT_CHECK(f->recs.v[i].z[k] <= ZS_DEPTH_ONE, "%s: record depth %u above 1.0",
                             what, f->recs.v[i].z[k]);
        }
    }
    free_frame(f);
    zt_ctx_free(&c);
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster in extreme-coordinate frames", bad);
}

static void test_degenerate(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 64, 64, 32);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(20));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 8 * H);
    /* on the depth-1 plane, exact 28.4 positions well inside the screen */
    int a = zt_scene_vertex_q(&sc, 100, 100, 0);
    int b = zt_scene_vertex_q(&sc, 700, 400, 0);
    int d = zt_scene_vertex_q(&sc, 400, 250, 0); /* on the segment a-b: collinear */
    int e = zt_scene_vertex_q(&sc, 100, 100, 0); /* a copy of a */
    int p = zt_scene_vertex_q(&sc, 900, 900, 0);
    zt_scene_tri(&sc, a, a, b, 0);  /* repeated index */
    zt_scene_tri(&sc, a, b, b, 0);
    zt_scene_tri(&sc, a, b, d, 0);  /* collinear */
    zt_scene_tri(&sc, a, d, b, 0);
    zt_scene_tri(&sc, a, e, b, 0);  /* two equal positions */
    zt_scene_tri(&sc, p, p, p, 0);  /* a point */
    /* collinear in world space but not on the depth-1 plane: a segment seen
     * edge-on through the eye (points on one ray) */
    int r0 = zt_scene_vertex_world(&sc, 0.25, 0.25, -1, 0);
    int r1 = zt_scene_vertex_world(&sc, 0.5, 0.5, -2, 0);
    int r2 = zt_scene_vertex_world(&sc, 1.0, 1.0, -4, 0);
    zt_scene_tri(&sc, r0, r1, r2, 0);
    int nt = (int)sc.nt;
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    rframe *f = new_frame();
    for (int mode = 0; mode < 2; mode++) {
        robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 3);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(all_background(f), "a degenerate triangle was drawn");
        ZT_CHECK(f->recs.n == 0, "%zu records stored for zero-area triangles", f->recs.n);
        ZT_CHECK(f->st.tris_culled == (uint32_t)nt, "zero-area triangles: culled %u of %d "
                 "(rejected %u empty %u)", f->st.tris_culled, nt, f->st.tris_rejected,
                 f->st.tris_empty);
    }
    free_frame(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* many on-screen triangles that all span the middle rows */
static void overlapping_scene(zt_scene *sc, zt_rng *g, int ntri, int own_vertices)
{
    zt_scene_reset(sc);
    int shared[3] = {-1, -1, -1};
    for (int t = 0; t < ntri; t++) {
        int v[3];
        for (int k = 0; k < 3; k++) {
            if (!own_vertices && shared[k] >= 0 && t % 2) {
                v[k] = shared[k];
                continue;
            }
            double px = k == 0 ? zt_uniform(g, 2, 20) : k == 1 ? zt_uniform(g, 44, 62)
                                                            : zt_uniform(g, 10, 54);
            double py = k == 2 ? zt_uniform(g, 56, 62) : zt_uniform(g, 2, 8);
            v[k] = zt_scene_vertex_px(sc, px, py, zt_uniform(g, 2, 10), 0);
            shared[k] = v[k];
        }
        zt_scene_tri_front(sc, v[0], v[1], v[2], 0);
    }
}

static void test_pools(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9001);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 256);
    rframe *f = new_frame();
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));

    /* 1. triangle pool: 10 records, 50 triangles -> the last 40 dropped */
    {
        zt_ctx c;
        zt_ctx_init(&c, W, H, 10, 400, 400);
        overlapping_scene(&sc, &g, 50, 1);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 4);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.records == 10 && f->st.tris_stored == 10,
                     "triangle pool 10: records %u stored %u", f->st.records, f->st.tris_stored);
            ZT_CHECK(f->st.tris_dropped == 40, "triangle pool 10 with 50 triangles: dropped %u",
                     f->st.tris_dropped);
            for (size_t i = 0; i < f->recs.n; i++)
                ZT_CHECK(f->recs.v[i].tag == i + 1,
                         "the first triangles are kept (policy: the last are dropped): record "
                         "%zu has tag %u",
                         i, f->recs.v[i].tag);
            ZT_CHECK(vs_raycast(f, "triangle pool") == 0, "triangle pool overflow output wrong");
        }
        /* a second draw in the same frame is dropped whole, still ZS_OK */
        ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_CHECK(zs_frame_stats(&c.r)->tris_dropped == 90, "two draws: dropped %u",
                 zs_frame_stats(&c.r)->tris_dropped);
        zt_ctx_free(&c);
    }
    /* 2. vertex pool: 12 vertices, 30 triangles with their own vertices */
    {
        zt_ctx c;
        zt_ctx_init(&c, W, H, 200, 12, 400);
        overlapping_scene(&sc, &g, 30, 1);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 64);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.verts_dropped > 0, "vertex pool 12 with 90 vertices: none dropped");
            ZT_CHECK(f->st.verts_stored <= 12, "verts_stored %u", f->st.verts_stored);
            ZT_CHECK(f->st.tris_dropped > 0, "vertex pool overflow: no triangle counted dropped");
            ZT_CHECK(f->st.tris_stored >= 1, "vertex pool 12: not even the first triangles stored");
            ZT_CHECK(vs_raycast(f, "vertex pool") == 0, "vertex pool overflow output wrong");
        }
        zt_ctx_free(&c);
    }
    /* 3. active edge pool: 4 edges (2 triangles per row), 12 triangles over
     * the same rows */
    {
        zt_ctx c;
        zt_ctx_init(&c, W, H, 200, 400, 4);
        overlapping_scene(&sc, &g, 12, 0);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 1 + mode * 7);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.edges_dropped > 0, "edge pool 4 with 12 overlapping triangles: none "
                     "dropped");
            ZT_CHECK(f->st.max_active_edges <= 4, "max_active_edges %u", f->st.max_active_edges);
            ZT_CHECK(f->st.tris_drawn < f->st.records, "edge pool: drawn %u of %u records",
                     f->st.tris_drawn, f->st.records);
        }
        /* the minimum pool (2 edges) and 3-row bands */
        zt_ctx_free(&c);
        zt_ctx_init(&c, W, H, 200, 400, 2);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 3);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.edges_dropped > 0, "edge pool 2: none dropped");
        }
        zt_ctx_free(&c);
    }
    /* 4. everything at once, random scenes, tiny pools */
    for (int n = 0; n < 60; n++) {
        zt_ctx c;
        zt_ctx_init(&c, W, H, (int)zt_range(&g, 1, 20), (int)zt_range(&g, 3, 40),
                    (int)zt_range(&g, 2, 12));
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 40), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            robust_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 1 + n % 5);
            ZT_ST(f->draw_st, ZS_OK);
        }
        zt_ctx_free(&c);
    }
    free_frame(f);
    zt_scene_free(&sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_near_plane), cmocka_unit_test(test_steep_sliver),
        cmocka_unit_test(test_rejected),   cmocka_unit_test(test_extremes),
        cmocka_unit_test(test_degenerate), cmocka_unit_test(test_pools),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_robust: seed %llx, %lu guarded frames %dx%d; totals: %lu clipped, %lu rejected, "
           "%lu culled, %lu dropped triangles, %lu dropped vertices, %lu edge-pool drops, %lu "
           "saturations; ray-cast pixels %lu, near ties excluded %lu (tolerance 2^-20); %d failed\n",
           (unsigned long long)SEED, g_frames, W, H, g_clipped, g_rejected, g_culled, g_dropped,
           g_vdropped, g_edropped, g_saturated, g_px, g_excluded, rc);
    fflush(stdout);
    return rc;
}
