/* SPDX-License-Identifier: MIT */
/*
 * test_extremes: rendering at the extremes of its input. Every frame is
 * rendered through guarded buffers (zt_render_guarded: guard bytes around
 * each band, padding after each row, all untouched) and its statistics must
 * add up as documented (zt_check_accounting); no input may fault (this suite
 * runs under ASan and UBSan).
 *
 *  - near-plane crossings: the clipped records against the ray caster;
 *  - a steep clipped sliver (depth slope > 1 per pixel) in front of another
 *    triangle;
 *  - triangles wholly behind the eye / beyond far / off-screen: rejected,
 *    nothing drawn;
 *  - int16 position extremes with large and tiny scales and model matrices;
 *  - degenerate triangles (repeated indices, collinear, a point): culled;
 *  - Q16.16 limits (INT32_MIN / INT32_MAX) in look_at, set_view, model
 *    matrices and mesh scales: documented statuses, span == zline;
 *  - needle and sliver triangles (1/16 px wide, long, every direction):
 *    coverage equal to the reference rasterizer;
 *  - triangle tags wrap after 65535 and skip 0 (ID16);
 *  - regression: the folded model-to-clip transform with large coefficients
 *    (fuzz_frame found a signed 64-bit overflow in its fast path; the inputs
 *    are tests/fuzz/corpus/frame/regress-transform-overflow-*).
 *
 * The ray-cast frames also check a weak invariant that needs no depth: a
 * pixel that shows tag t is covered (reference rasterizer) by a record of
 * tag t (zt_guarded_frame). Pool overflow is test_pools; bad arguments and
 * call order are test_api.
 */
#include "zt_test.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Frames compared with the ray caster. */
#define RW 64
#define RH 64
#define SEED 0x50B057AA00000009ull
/* Frames compared between the modes and with the reference rasterizer. */
#define W 48
#define H 32

static zs_vec3 V(int32_t x, int32_t y, int32_t z) { return zs_vec3_make(x, y, z); }

static void test_near_plane(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, RW, RH, 400, 1200, 400);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 128);
    zt_gframe *f = zt_gframe_new(RW, RH);
    unsigned long bad = 0, clipped = 0;
    for (int n = 0; n < 120; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 5, 30), ZT_SC_NEAR | ZT_SC_PLAIN, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < ZT_NMODES; mode++) {
            zt_guarded_frame(&c, &cam, ZT_MODE(mode), &m, 1, NULL, f, 1 + n % 7);
            ZT_ST(f->draw_st, ZS_OK);
            char what[96];
            snprintf(what, sizeof what, "near-plane scene %d (%s, seed %llx)", n,
                     ZT_MODE_NAME(mode), (unsigned long long)SEED);
            bad += zt_vs_raycast(f, what);
            if (mode == 0) clipped += f->st.tris_clipped;
            /* clipped pieces never reach in front of the near plane: depth >= 0 */
        }
    }
    ZT_CHECK(clipped > 0, "no triangle was clipped: the test does not exercise the near plane");
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster in near-plane scenes", bad);
    zt_gframe_free(f);
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
    for (int mode = 0; mode < ZT_NMODES; mode++) {
        ZT_ST(zt_frame(&c, &cam, ZT_MODE(mode), NULL, &m, 1, &recs, img, 80), ZS_OK);
        zt_raycast(&recs, &cast);
        for (int y = 0; y < 80; y++)
            for (int x = 0; x < 96; x++) {
                int p = y * 96 + x;
                uint16_t id = zt_id_at(img, 96, x, y);
                if (id == cast.owner[p] || cast.z2[p] - cast.z1[p] < ZT_TIE_TOL) continue;
                if (bad++ < 2)
                    print_error("steep sliver (%s): pixel (%d,%d) ID16 %u, ray caster %u (z %.6f "
                                "vs %.6f)\n",
                                ZT_MODE_NAME(mode), x, y, id, cast.owner[p], cast.z1[p],
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
    zt_ctx_init(&c, RW, RH, 64, 64, 32);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(20));
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 256);
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
    zt_gframe *f = zt_gframe_new(RW, RH);
    for (int mode = 0; mode < ZT_NMODES; mode++) {
        zt_guarded_frame(&c, &cam, ZT_MODE(mode), &m, 1, NULL, f, 5);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(zt_gframe_empty(f), "a triangle outside the view volume was drawn");
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
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_extremes(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xE);
    zt_ctx c;
    zt_ctx_init(&c, RW, RH, 200, 600, 200);
    zt_gframe *f = zt_gframe_new(RW, RH);
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
        for (int mode = 0; mode < ZT_NMODES; mode++) {
            zt_guarded_frame(&c, &cam, ZT_MODE(mode), &m, 1, &model, f, 1 + n % 9);
            ZT_ST(f->draw_st, ZS_OK);
            char what[96];
            snprintf(what, sizeof what, "extremes case %d (%s, seed %llx)", n,
                     ZT_MODE_NAME(mode), (unsigned long long)SEED);
            bad += zt_vs_raycast(f, what);
            for (size_t i = 0; i < f->recs.n; i++)
                for (int k = 0; k < 3; k++)
                    ZT_CHECK(f->recs.v[i].z[k] <= ZS_DEPTH_ONE, "%s: record depth %u above 1.0",
                             what, f->recs.v[i].z[k]);
        }
    }
    zt_gframe_free(f);
    zt_ctx_free(&c);
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster in extreme-coordinate frames", bad);
}

static void test_degenerate(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, RW, RH, 64, 64, 32);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(20));
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 8 * RH);
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
    zt_gframe *f = zt_gframe_new(RW, RH);
    for (int mode = 0; mode < ZT_NMODES; mode++) {
        zt_guarded_frame(&c, &cam, ZT_MODE(mode), &m, 1, NULL, f, 3);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(zt_gframe_empty(f), "a degenerate triangle was drawn");
        ZT_CHECK(f->recs.n == 0, "%zu records stored for zero-area triangles", f->recs.n);
        ZT_CHECK(f->st.tris_culled == (uint32_t)nt, "zero-area triangles: culled %u of %d "
                 "(rejected %u empty %u)", f->st.tris_culled, nt, f->st.tris_rejected,
                 f->st.tris_empty);
    }
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* One frame in both modes (ID16 and RGB565): guarded, accounted, span == zline. */
static void both_modes(zt_ctx *c, const zs_camera *cam, const zs_mesh *m, const zs_mat34 *model,
                       const char *what)
{
    static uint8_t a[W * H * 3], b[W * H * 3];
    for (int f = 0; f < 2; f++) {
        zs_shade_params sp = zs_shade_default();
        sp.format = f ? ZS_FMT_RGB888 : ZS_FMT_ID16;
        sp.shading = f ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
        unsigned bpp = zs_format_bytes(sp.format);
        zs_stats sa;
        for (int mode = 0; mode < ZT_NMODES; mode++) {
            ZT_STN(zs_frame_begin(&c->r, cam, ZT_MODE(mode)), ZS_OK);
            ZT_STN(zs_frame_shading(&c->r, &sp), ZS_OK);
            zs_status st = zs_draw(&c->r, m, model);
            zt_checks++;
            ZT_CHECK(st == ZS_OK || st == ZS_ERR_MESH, "%s: draw returned %d (%s)", what, (int)st,
                     zs_strerror(st));
            ZT_STN(zt_render_guarded(&c->r, W, H, bpp, 1 + mode * 6, mode ? b : a), ZS_OK);
            zt_check_accounting(zs_frame_stats(&c->r), &c->cfg);
            if (mode == 0)
                sa = *zs_frame_stats(&c->r);
            else {
                ZT_CHECK(sa.records == zs_frame_stats(&c->r)->records &&
                             sa.saturated == zs_frame_stats(&c->r)->saturated,
                         "%s: the two modes stored differently", what);
                ZT_CHECK(memcmp(a, b, (size_t)W * H * bpp) == 0, "%s: span != %s (format %d)",
                         what, ZT_MODE_NAME(mode), (int)sp.format);
            }
        }
    }
}

static void test_q16_limits(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 200, 200, 64);
    static const int32_t ex[] = {INT32_MIN, INT32_MIN + 1, -ZS_FX(32767), -ZS_FX(1), -1, 0, 1,
                                 ZS_FX(1), ZS_FX(32767), INT32_MAX - 1, INT32_MAX};
    const int nex = (int)(sizeof ex / sizeof ex[0]);
    zs_mesh m = zt_mesh_pair();
    zs_camera cam;
    char what[128];

    /* look_at at the limits: OK or ZS_ERR_CAMERA, never anything else; a
     * camera that was accepted renders */
    for (int i = 0; i < nex; i++)
        for (int j = 0; j < nex; j += 3) {
            zs_vec3 eye = V(ex[i], ex[j], ex[(i + j) % nex]);
            zs_vec3 target = V(ex[j], ex[(i * 7) % nex], ex[i]);
            zs_status st = zs_camera_look_at(&cam, eye, target, V(0, ZS_FX(1), 0));
            zt_checks++;
            ZT_CHECK(st == ZS_OK || st == ZS_ERR_CAMERA, "look_at at the limits: %d", (int)st);
            if (st != ZS_OK)
                continue;
            ZT_STN(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 16, INT32_MAX), ZS_OK);
            snprintf(what, sizeof what, "look_at eye %d %d %d target %d %d %d", eye.x, eye.y,
                     eye.z, target.x, target.y, target.z);
            both_modes(&c, &cam, &m, NULL, what);
        }
    /* up at the limits (parallel to the view or not) */
    for (int i = 0; i < nex; i++) {
        zs_status st = zs_camera_look_at(&cam, V(0, 0, 0), V(0, 0, -ZS_FX(1)), V(ex[i], ex[nex - 1 - i], ex[i]));
        zt_checks++;
        ZT_CHECK(st == ZS_OK || st == ZS_ERR_CAMERA, "look_at with up at the limits: %d", (int)st);
    }
    ZT_STN(zs_camera_look_at(&cam, V(0, 0, 0), V(0, 0, INT32_MIN), V(0, 0, INT32_MAX)), ZS_ERR_CAMERA);
    ZT_STN(zs_camera_look_at(&cam, V(INT32_MIN, INT32_MIN, INT32_MIN), V(INT32_MIN, INT32_MIN, INT32_MIN),
                         V(0, ZS_FX(1), 0)), ZS_ERR_CAMERA);

    /* set_view and model matrices full of limit values; scales at the limits */
    zt_rng g;
    zt_rng_seed(&g, 0xB0D1A5u);
    static const int32_t scales[] = {INT32_MIN, -ZS_FX(1), -1, 1, ZS_FX(1) / 128, ZS_FX(1),
                                     INT32_MAX};
    for (int n = 0; n < 60; n++) {
        zs_mat34 view = zs_mat34_identity(), model = zs_mat34_identity();
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 4; b++) {
                if (zt_below(&g, 3) == 0)
                    view.m[a][b] = ex[zt_below(&g, (uint32_t)nex)];
                if (zt_below(&g, 2) == 0)
                    model.m[a][b] = ex[zt_below(&g, (uint32_t)nex)];
            }
        if (n % 3 == 0)
            view = zs_mat34_identity();
        ZT_STN(zs_camera_set_view(&cam, &view), ZS_OK);
        zs_fixed nz = n % 4 ? 1 : ZS_FX(1) / 8;
        ZT_STN(zs_camera_perspective(&cam, n % 2 ? ZS_FX(179) : ZS_FX(1), nz,
                                 n % 5 ? INT32_MAX : nz + 2),
           ZS_OK);
        zs_mesh mm = m;
        mm.scale = scales[n % (int)(sizeof scales / sizeof scales[0])];
        snprintf(what, sizeof what, "limit matrices case %d", n);
        both_modes(&c, &cam, &mm, n % 4 == 3 ? NULL : &model, what);
    }
    zt_ctx_free(&c);
}

/* A single triangle in screen space (28.4) on the depth-1 plane; returns
 * its ID16 frame compared with the reference rasterizer. */
static unsigned long needle(zt_ctx *c, zt_scene *sc, const int32_t q[6], int mode)
{
    static uint8_t img[W * H * 2];
    zt_recs recs = {0};
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 8, ZS_FX(100));
    zt_scene_reset(sc);
    int a = zt_scene_vertex_q(sc, q[0], q[1], 0), b = zt_scene_vertex_q(sc, q[2], q[3], 0),
        d = zt_scene_vertex_q(sc, q[4], q[5], 0);
    zt_scene_tri(sc, a, b, d, 0);
    zt_scene_tri(sc, a, d, b, 0); /* one of the two windings is front-facing */
    zs_mesh m = zt_scene_mesh(sc, 0, 0);
    ZT_ST(zt_frame(c, &cam, ZT_MODE(mode), NULL, &m, 1, &recs, img, 3), ZS_OK);
    unsigned long bad = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int want = 0;
            for (size_t i = 0; i < recs.n; i++)
                want |= zt_covers(recs.v[i].xy, x, y);
            int got = zt_id_at(img, W, x, y) != 0;
            if (want != got && bad++ < 2)
                print_error("needle %d %d %d %d %d %d (%s): pixel (%d,%d) drawn %d, reference %d\n",
                            q[0], q[1], q[2], q[3], q[4], q[5], ZT_MODE_NAME(mode), x, y, got,
                            want);
        }
    zt_check_accounting(zs_frame_stats(&c->r), &c->cfg);
    zt_recs_free(&recs);
    return bad;
}

static void test_needles(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 16, 16, 8);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 8 * H);
    zt_rng g;
    zt_rng_seed(&g, 0x11EED1Eu);
    unsigned long bad = 0;
    int n = 0;
    /* 1/16 px wide needles, long, through pixel centres, every direction;
     * slivers with a vertex a single 1/16 px off the opposite edge */
    for (int k = 0; k < 400; k++) {
        int32_t q[6];
        int32_t x0 = (int32_t)zt_range(&g, -40, 16 * W + 40), y0 = (int32_t)zt_range(&g, -40, 16 * H + 40);
        int32_t x1 = (int32_t)zt_range(&g, -40, 16 * W + 40), y1 = (int32_t)zt_range(&g, -40, 16 * H + 40);
        if (k % 4 == 0) { /* on pixel centres */
            x0 = 16 * (x0 / 16) + 8; y0 = 16 * (y0 / 16) + 8;
            x1 = 16 * (x1 / 16) + 8; y1 = 16 * (y1 / 16) + 8;
        }
        if (k % 5 == 0) y1 = y0; /* horizontal */
        if (k % 7 == 0) x1 = x0; /* vertical */
        int32_t dx = (int32_t)zt_range(&g, -1, 1), dy = (int32_t)zt_range(&g, -1, 1);
        if (dx == 0 && dy == 0)
            dx = 1;
        q[0] = x0; q[1] = y0; q[2] = x1; q[3] = y1;
        if (k % 2) { /* needle: a second vertex 1/16 px beside the first */
            q[4] = x0 + dx; q[5] = y0 + dy;
        } else {     /* sliver: a vertex 1/16 px off the middle of the long edge */
            q[4] = (x0 + x1) / 2 + dx; q[5] = (y0 + y1) / 2 + dy;
        }
        for (int mode = 0; mode < ZT_NMODES; mode++, n++)
            bad += needle(&c, &sc, q, mode);
    }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    ZT_CHECK(bad == 0, "%lu pixels of %d needle/sliver frames differ from the reference", bad, n);
}

/* Tags count 1..65535 and then start again at 1: 0 is never a tag. */
static void test_tag_wrap(void **state)
{
    (void)state;
    enum { NT = 65535 + 3 };
    zt_ctx c;
    zt_ctx_init(&c, W, H, 16, 64, 16);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 8, ZS_FX(100));
    /* one visible triangle at the end of a long run of back faces */
    int16_t pos[9] = {-100, -100, -256, 100, -100, -256, 0, 100, -256};
    uint16_t *idx = malloc(3 * sizeof *idx * NT);
    for (int t = 0; t < NT; t++) {
        idx[3 * t] = 0;
        idx[3 * t + 1] = t == NT - 1 ? 1 : 2;
        idx[3 * t + 2] = t == NT - 1 ? 2 : 1;
    }
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 256;
    m.vertex_count = 3;
    m.triangle_count = 65535;
    static uint8_t img[W * H * 2];
    zt_recs recs = {0};
    /* 65535 back faces, then a mesh whose 3rd triangle is the front face:
     * its tag is 65535 + 3 -> wraps to 3 */
    zs_mesh tail = m;
    tail.indices = idx + 3 * (NT - 3);
    tail.triangle_count = 3;
    zs_mesh both[2] = {m, tail};
    ZT_ST(zt_frame(&c, &cam, ZS_MODE_SPAN, NULL, both, 2, &recs, img, 8), ZS_OK);
    ZT_CHECK(recs.n == 1, "%zu records", recs.n);
    if (recs.n == 1)
        ZT_CHECK(recs.v[0].tag == 3, "tag after wrapping: %u, expected 3 (65538 - 65535)",
                 recs.v[0].tag);
    uint16_t centre = zt_id_at(img, W, W / 2, H / 2);
    ZT_CHECK(centre == 3, "ID16 at the centre %u, expected tag 3", centre);
    ZT_CHECK(zs_frame_stats(&c.r)->tris_submitted == 65538, "submitted %u",
             zs_frame_stats(&c.r)->tris_submitted);
    zt_checks += 4;
    zt_recs_free(&recs);
    free(idx);
    zt_ctx_free(&c);
}

/* The vertex transform folds scale, model-view and projection into one set of
 * coefficients when they are small enough. Found by fuzz_frame: a coefficient
 * >= 2^46 did not force the general path when a later one was >= 2^31, and
 * the int16 x coefficient products overflowed 64 bits (UBSan). This frame is
 * that input; the sweep around it pushes scales and matrix entries across
 * the fast-path limits with int16 extremes (this suite runs under UBSan). */
static void test_transform_overflow(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 64, 96, 32);
    zs_camera cam;
    zs_mat34 id = zs_mat34_identity();
    ZT_STN(zs_camera_set_view(&cam, &id), ZS_OK);
    ZT_STN(zs_camera_perspective(&cam, 2293760, 1024, 66909184), ZS_OK);
    static const int16_t pos1[] = {-14592, 23808, -9984};
    static const uint16_t idx0[] = {0, 0, 0};
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos1;
    m.indices = idx0;
    m.scale = 11796480;
    m.vertex_count = 1;
    m.triangle_count = 0;
    zs_mat34 model = {{{-7906176, 6948, 8976, 901120},
                       {194046, 2622, -31081, 491520},
                       {14796254, 3678, 5204, -663552}}};
    ZT_STN(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_STN(zs_draw(&c.r, &m, &model), ZS_OK);

    static const int16_t pos[] = {-32768, 32767, -32768, 32767, -32768, 32767, 0, 32767, -1,
                                  -14592, 23808, -9984, 1, -1, 32767, -32768, 0, 0};
    static const uint16_t idx[] = {0, 1, 2, 3, 4, 5, 0, 2, 4, 1, 3, 5};
    static const int32_t scales[] = {(1 << 30) - 1, -(1 << 30) + 1, 1 << 30, -(1 << 30),
                                     11796480, -166783285, 1 << 20, -(1 << 16), 65535, 1};
    static const int32_t big[] = {INT32_MAX, INT32_MIN, 1 << 30, -(1 << 24), 14796254,
                                  -7906176, 1 << 16, 3};
    zt_rng g;
    zt_rng_seed(&g, 0xF01D0Bu);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 6;
    m.triangle_count = 4;
    char what[96];
    for (size_t si = 0; si < sizeof scales / sizeof scales[0]; si++)
        for (int n = 0; n < 12; n++) {
            zs_mat34 mm = zs_mat34_identity();
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 4; b++)
                    if (zt_below(&g, 2))
                        mm.m[a][b] = big[zt_below(&g, sizeof big / sizeof big[0])];
            m.scale = scales[si];
            snprintf(what, sizeof what, "transform sweep scale %d case %d", scales[si], n);
            both_modes(&c, &cam, &m, &mm, what);
        }
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_near_plane),   cmocka_unit_test(test_steep_sliver),
        cmocka_unit_test(test_rejected),     cmocka_unit_test(test_extremes),
        cmocka_unit_test(test_degenerate),   cmocka_unit_test(test_q16_limits),
        cmocka_unit_test(test_needles),      cmocka_unit_test(test_tag_wrap),
        cmocka_unit_test(test_transform_overflow),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_extremes: seed %llx, %lu guarded ray-cast frames %dx%d; totals: %lu clipped, "
           "%lu rejected, %lu culled triangles, %lu saturations; ray-cast pixels %lu, near ties "
           "excluded %lu (tolerance 2^-20); %lu status/invariant checks; %d failed\n",
           (unsigned long long)SEED, zt_tot.frames, RW, RH, zt_tot.clipped, zt_tot.rejected,
           zt_tot.culled, zt_tot.saturated, zt_tot.px, zt_tot.excluded, zt_checks, rc);
    fflush(stdout);
    return rc;
}
