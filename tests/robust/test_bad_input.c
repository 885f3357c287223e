/*
 * test_bad_input: the bad-input policy (README.md (Robustness)) beyond what
 * tests/core/test_api.c and test_robust.c check.
 *
 *  - every public call in every renderer state: the documented status, and a
 *    refused call changes nothing (the frame renders exactly as without it);
 *  - every shading field alone out of its range: ZS_ERR_ARGUMENT, and the
 *    extremes that are in range are accepted;
 *  - Q16.16 limits (INT32_MIN / INT32_MAX) in look_at, set_view, model
 *    matrices and mesh scales: documented statuses, guarded output, the
 *    statistics add up and span == zline;
 *  - needle and sliver triangles (1/16 px wide, long, every direction):
 *    coverage equal to the reference rasterizer, span == zline;
 *  - mesh edge cases: last valid index, vertex_count 0, triangle_count 0,
 *    NULL arrays with no triangles, mirrored and extreme scales;
 *  - triangle tags wrap after 65535 and skip 0 (ID16);
 *  - zs_render_frame stopped by its callback, then resumed by zs_render_rows;
 *  - strides and row ranges at their limits for every pixel format;
 *  - regression: the folded model-to-clip transform with large coefficients
 *    (fuzz_frame found a signed 64-bit overflow in its fast path; the inputs
 *    are tests/fuzz/corpus/frame/regress-transform-overflow-*).
 */
#include "zt_test.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define W 48
#define H 32
#define GUARD 48
#define CANARY 0xC3

static unsigned long g_checks;
#define ST(expr, want)                                                          \
    do {                                                                        \
        g_checks++;                                                             \
        ZT_ST(expr, want);                                                      \
    } while (0)

static zs_vec3 V(int32_t x, int32_t y, int32_t z) { return zs_vec3_make(x, y, z); }

/* A small scene: two overlapping, penetrating triangles in front of the
 * standard camera (eye at the origin looking down -Z, fov 90). */
static const int16_t k_pos[] = {-200, -150, -400, 220, -120, -300, 0, 200, -500,
                                -180, 100,  -250, 200, 160,  -520, 30, -200, -350};
static const uint16_t k_idx[] = {0, 1, 2, 3, 5, 4};
static const zs_color k_fcol[] = {ZS_RGB(200, 40, 40), ZS_RGB(40, 200, 90)};

static zs_mesh scene_mesh(void)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = k_pos;
    m.indices = k_idx;
    m.face_colors = k_fcol;
    m.scale = ZS_FX(1) / 128;
    m.vertex_count = 6;
    m.triangle_count = 2;
    m.color = ZS_RGB(255, 255, 255);
    return m;
}

static void std_cam(zs_camera *cam) { zt_camera_std(cam, ZS_FX(1) / 8, ZS_FX(100)); }

static int sink(void *user, int y0, int rows, const void *buf, size_t stride)
{
    (void)user; (void)y0; (void)rows; (void)buf; (void)stride;
    return 0;
}

/* Renders the rest of the frame in bands through a guarded buffer with row
 * padding; checks the guards and padding; copies rows into img (tight). */
static zs_status render_guarded(zs_renderer *r, int w, int h, unsigned bpp, int band,
                                uint8_t *img)
{
    size_t rowb = (size_t)w * bpp, stride = rowb + 5, total = GUARD + stride * (size_t)band + GUARD;
    uint8_t *buf = malloc(total);
    zs_status st = ZS_OK;
    int y0 = 0;
    while (y0 < h) {
        int n = band < h - y0 ? band : h - y0;
        memset(buf, CANARY, total);
        st = zs_render_rows(r, y0, n, buf + GUARD, stride);
        if (st != ZS_OK)
            break;
        for (size_t i = 0; i < GUARD; i++) {
            ZT_CHECK(buf[i] == CANARY, "guard byte %zu before the band written", i);
            ZT_CHECK(buf[total - 1 - i] == CANARY, "guard byte %zu after the band written", i);
        }
        for (int y = 0; y < n; y++) {
            const uint8_t *row = buf + GUARD + (size_t)y * stride;
            for (size_t k = rowb; k < stride; k++)
                ZT_CHECK(row[k] == CANARY, "row %d padding byte %zu written", y0 + y, k);
            memcpy(img + (size_t)(y0 + y) * rowb, row, rowb);
        }
        y0 += n;
    }
    free(buf);
    return st;
}

static void check_accounting(const zs_stats *s)
{
    g_checks++;
    ZT_CHECK(s->tris_submitted ==
                 s->tris_culled + s->tris_rejected + s->tris_empty + s->tris_dropped + s->tris_stored,
             "submitted %u != culled %u + rejected %u + empty %u + dropped %u + stored %u",
             s->tris_submitted, s->tris_culled, s->tris_rejected, s->tris_empty, s->tris_dropped,
             s->tris_stored);
}

/* ------------------------------------------------------------------ */

/* A reference frame of the scene (span, RGB565 BE). */
static void reference_frame(zt_ctx *c, uint8_t *img)
{
    zs_camera cam;
    zs_mesh m = scene_mesh();
    std_cam(&cam);
    ST(zs_frame_begin(&c->r, &cam, ZS_MODE_SPAN), ZS_OK);
    ST(zs_draw(&c->r, &m, NULL), ZS_OK);
    ST(render_guarded(&c->r, W, H, 2, 5, img), ZS_OK);
}

static void test_state_matrix(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 32, 32, 16);
    zs_renderer *r = &c.r, fresh;
    zs_camera cam, bad;
    zs_mesh m = scene_mesh();
    zs_shade_params sp = zs_shade_default();
    static uint8_t ref[W * H * 2], img[W * H * 2], line[W * 3];
    std_cam(&cam);
    memset(&bad, 0, sizeof bad);
    reference_frame(&c, ref);

    /* a zeroed renderer (never initialised): every frame call is out of order */
    memset(&fresh, 0, sizeof fresh);
    ST(zs_frame_begin(&fresh, &cam, ZS_MODE_SPAN), ZS_ERR_STATE);
    ST(zs_frame_shading(&fresh, &sp), ZS_ERR_STATE);
    ST(zs_draw(&fresh, &m, NULL), ZS_ERR_STATE);
    ST(zs_render_rows(&fresh, 0, 1, line, sizeof line), ZS_ERR_STATE);
    ST(zs_render_frame(&fresh, line, sizeof line, 1, sink, NULL), ZS_ERR_STATE);
    ZT_CHECK(zs_frame_stats(NULL) == NULL, "zs_frame_stats(NULL) not NULL");
    zs_set_setup_hook(NULL, NULL, NULL); /* must not crash */

    /* READY (initialised, no frame yet) */
    zt_ctx c2;
    zt_ctx_init(&c2, W, H, 32, 32, 16);
    ST(zs_frame_shading(&c2.r, &sp), ZS_ERR_STATE);
    ST(zs_draw(&c2.r, &m, NULL), ZS_ERR_STATE);
    ST(zs_render_rows(&c2.r, 0, 1, line, sizeof line), ZS_ERR_STATE);
    ST(zs_render_frame(&c2.r, line, sizeof line, 1, sink, NULL), ZS_ERR_STATE);
    zt_ctx_free(&c2);

    /* OPEN: refused calls in the middle of a frame leave it as it was */
    ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
    ST(zs_frame_begin(r, &bad, ZS_MODE_SPAN), ZS_ERR_CAMERA); /* the open frame goes on */
    ST(zs_frame_begin(r, &cam, (zs_visibility)7), ZS_ERR_MODE);
    {
        zs_shade_params b = sp;
        b.format = (zs_format)99;
        ST(zs_frame_shading(r, &b), ZS_ERR_FORMAT);
        b = sp;
        b.ambient = -1;
        ST(zs_frame_shading(r, &b), ZS_ERR_ARGUMENT);
    }
    {
        zs_mesh b = m;
        static const uint16_t oob[] = {0, 1, 2, 3, 5, 6};
        b.indices = oob;
        ST(zs_draw(r, &b, NULL), ZS_ERR_INDEX);
        b = m;
        b.scale = 0;
        ST(zs_draw(r, &b, NULL), ZS_ERR_MESH);
    }
    ST(zs_render_rows(r, 0, 1, line, 2 * W - 1), ZS_ERR_BUFFER);
    ST(zs_render_rows(r, H, 1, line, sizeof line), ZS_ERR_ROW);
    ST(zs_draw(r, &m, NULL), ZS_OK);
    ST(zs_frame_shading(r, &sp), ZS_ERR_STATE); /* after a draw */
    ST(render_guarded(r, W, H, 2, 5, img), ZS_OK);
    ZT_CHECK(memcmp(img, ref, sizeof img) == 0,
             "a frame with refused calls in it differs from the same frame without them");
    {
        zs_stats s = *zs_frame_stats(r);
        ZT_CHECK(s.tris_submitted == 2, "refused draws counted: submitted %u", s.tris_submitted);
    }

    /* RENDERING: draw and shading refused, a bad frame_begin leaves the frame */
    ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
    ST(zs_draw(r, &m, NULL), ZS_OK);
    ST(render_guarded(r, W, 10, 2, 5, img), ZS_OK); /* rows 0..9 */
    ST(zs_draw(r, &m, NULL), ZS_ERR_STATE);
    ST(zs_frame_shading(r, &sp), ZS_ERR_STATE);
    ST(zs_frame_begin(r, &bad, ZS_MODE_ZLINE), ZS_ERR_CAMERA);
    ST(zs_render_rows(r, 9, 1, line, sizeof line), ZS_ERR_ROW);
    {
        static uint8_t rest[W * H * 2];
        size_t rowb = 2 * W;
        for (int y = 10; y < H; y++)
            ST(zs_render_rows(r, y, 1, rest + (size_t)y * rowb, rowb), ZS_OK);
        ZT_CHECK(memcmp(rest + 10 * rowb, ref + 10 * rowb, (H - 10) * rowb) == 0,
                 "rows after refused calls while rendering differ");
    }
    /* DONE: everything but a new frame is refused */
    {
        zs_status s0 = zs_render_rows(r, H - 1, 1, line, sizeof line);
        ZT_CHECK(s0 == ZS_ERR_ROW || s0 == ZS_ERR_STATE, "render after the last row: %d", (int)s0);
        s0 = zs_render_frame(r, line, sizeof line, 1, sink, NULL);
        ZT_CHECK(s0 == ZS_OK || s0 == ZS_ERR_STATE,
                 "render_frame on a finished frame returned %d", (int)s0);
        g_checks += 2;
    }
    ST(zs_draw(r, &m, NULL), ZS_ERR_STATE);
    ST(zs_frame_shading(r, &sp), ZS_ERR_STATE);
    reference_frame(&c, img); /* and a new frame works */
    ZT_CHECK(memcmp(img, ref, sizeof img) == 0, "a new frame after DONE differs");
    zt_ctx_free(&c);
}

static void test_shading_arguments(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 32, 32, 16);
    zs_renderer *r = &c.r;
    zs_camera cam;
    std_cam(&cam);
    ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
    zs_shade_params ok = zs_shade_default(), p;
    ok.light_count = 2;
    ok.lights[0].direction = V(ZS_FX(1), 0, 0);
    ok.lights[0].intensity = ZS_FX(1);
    ok.lights[1].direction = V(0, 0, ZS_FX(1));
    ok.lights[1].intensity = ZS_FX(1) / 2;
    ok.fog.enabled = 1;
    ok.fog.start = ZS_FX(1);
    ok.fog.end = ZS_FX(10);
    ok.fog.color = 0x808080;
    ST(zs_frame_shading(r, &ok), ZS_OK);

    /* each field alone out of range */
    p = ok; p.lights[0].direction = V(0, 0, 0);            ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.lights[1].direction = V(0, 0, 0);            ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.lights[0].intensity = -1;                    ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.lights[1].intensity = INT32_MIN;             ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.ambient = -1;                                ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.ambient = INT32_MIN;                         ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.background = 0x1000000u;                     ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.background = 0xFFFFFFFFu;                    ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.fog.color = 0x1000000u;                      ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.fog.end = p.fog.start;                       ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.fog.end = p.fog.start - 1;                   ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.fog.start = INT32_MAX; p.fog.end = INT32_MIN; ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.light_count = 3;                             ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.light_count = 255;                           ST(zs_frame_shading(r, &p), ZS_ERR_ARGUMENT);
    p = ok; p.shading = (zs_shading)-1;                    ST(zs_frame_shading(r, &p), ZS_ERR_MODE);
    p = ok; p.format = ZS_FMT_COUNT;                       ST(zs_frame_shading(r, &p), ZS_ERR_FORMAT);

    /* in range, however extreme */
    p = ok; p.fog.enabled = 0; p.fog.end = p.fog.start;   ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.fog.enabled = 0; p.fog.color = 0xFFFFFFFFu;
    {
        /* fog off: its colour is not used; either reading is documented enough */
        zs_status s0 = zs_frame_shading(r, &p);
        ZT_CHECK(s0 == ZS_OK || s0 == ZS_ERR_ARGUMENT, "unused fog colour: %d", (int)s0);
        g_checks++;
    }
    p = ok; p.ambient = INT32_MAX;                         ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.ambient = 0;                                 ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.lights[0].intensity = INT32_MAX;             ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.lights[0].direction = V(INT32_MIN, INT32_MIN, INT32_MIN); ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.lights[0].direction = V(1, 0, 0);            ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.lights[1].direction = V(0, 0, 0); p.light_count = 1; /* unused light */
    ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.fog.start = INT32_MIN; p.fog.end = INT32_MAX; ST(zs_frame_shading(r, &p), ZS_OK);
    p = ok; p.background = 0xFFFFFFu;                      ST(zs_frame_shading(r, &p), ZS_OK);

    /* and an extreme but valid look renders */
    p = ok;
    p.shading = ZS_SHADE_GOURAUD;
    p.ambient = INT32_MAX;
    p.lights[0].intensity = INT32_MAX;
    p.fog.start = INT32_MIN;
    p.fog.end = INT32_MAX;
    p.format = ZS_FMT_RGB888;
    ST(zs_frame_shading(r, &p), ZS_OK);
    zs_mesh m = scene_mesh();
    ST(zs_draw(r, &m, NULL), ZS_OK);
    static uint8_t img[W * H * 3];
    ST(render_guarded(r, W, H, 3, 7, img), ZS_OK);
    check_accounting(zs_frame_stats(r));
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
        for (int mode = 0; mode < 2; mode++) {
            ST(zs_frame_begin(&c->r, cam, (zs_visibility)mode), ZS_OK);
            ST(zs_frame_shading(&c->r, &sp), ZS_OK);
            zs_status st = zs_draw(&c->r, m, model);
            g_checks++;
            ZT_CHECK(st == ZS_OK || st == ZS_ERR_MESH, "%s: draw returned %d (%s)", what, (int)st,
                     zs_strerror(st));
            ST(render_guarded(&c->r, W, H, bpp, 1 + mode * 6, mode ? b : a), ZS_OK);
            check_accounting(zs_frame_stats(&c->r));
            if (mode == 0)
                sa = *zs_frame_stats(&c->r);
            else
                ZT_CHECK(sa.records == zs_frame_stats(&c->r)->records &&
                             sa.saturated == zs_frame_stats(&c->r)->saturated,
                         "%s: the two modes stored differently", what);
        }
        ZT_CHECK(memcmp(a, b, (size_t)W * H * bpp) == 0, "%s: span != zline (format %d)", what,
                 (int)sp.format);
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
    zs_mesh m = scene_mesh();
    zs_camera cam;
    char what[128];

    /* look_at at the limits: OK or ZS_ERR_CAMERA, never anything else; a
     * camera that was accepted renders */
    for (int i = 0; i < nex; i++)
        for (int j = 0; j < nex; j += 3) {
            zs_vec3 eye = V(ex[i], ex[j], ex[(i + j) % nex]);
            zs_vec3 target = V(ex[j], ex[(i * 7) % nex], ex[i]);
            zs_status st = zs_camera_look_at(&cam, eye, target, V(0, ZS_FX(1), 0));
            g_checks++;
            ZT_CHECK(st == ZS_OK || st == ZS_ERR_CAMERA, "look_at at the limits: %d", (int)st);
            if (st != ZS_OK)
                continue;
            ST(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 16, INT32_MAX), ZS_OK);
            snprintf(what, sizeof what, "look_at eye %d %d %d target %d %d %d", eye.x, eye.y,
                     eye.z, target.x, target.y, target.z);
            both_modes(&c, &cam, &m, NULL, what);
        }
    /* up at the limits (parallel to the view or not) */
    for (int i = 0; i < nex; i++) {
        zs_status st = zs_camera_look_at(&cam, V(0, 0, 0), V(0, 0, -ZS_FX(1)), V(ex[i], ex[nex - 1 - i], ex[i]));
        g_checks++;
        ZT_CHECK(st == ZS_OK || st == ZS_ERR_CAMERA, "look_at with up at the limits: %d", (int)st);
    }
    ST(zs_camera_look_at(&cam, V(0, 0, 0), V(0, 0, INT32_MIN), V(0, 0, INT32_MAX)), ZS_ERR_CAMERA);
    ST(zs_camera_look_at(&cam, V(INT32_MIN, INT32_MIN, INT32_MIN), V(INT32_MIN, INT32_MIN, INT32_MIN),
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
        ST(zs_camera_set_view(&cam, &view), ZS_OK);
        zs_fixed nz = n % 4 ? 1 : ZS_FX(1) / 8;
        ST(zs_camera_perspective(&cam, n % 2 ? ZS_FX(179) : ZS_FX(1), nz,
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
    ZT_ST(zt_frame(c, &cam, (zs_visibility)mode, NULL, &m, 1, &recs, img, 3), ZS_OK);
    unsigned long bad = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int want = 0;
            for (size_t i = 0; i < recs.n; i++)
                want |= zt_covers(recs.v[i].xy, x, y);
            int got = zt_id_at(img, W, x, y) != 0;
            if (want != got && bad++ < 2)
                print_error("needle %d %d %d %d %d %d (%s): pixel (%d,%d) drawn %d, reference %d\n",
                            q[0], q[1], q[2], q[3], q[4], q[5], mode ? "zline" : "span", x, y, got,
                            want);
        }
    check_accounting(zs_frame_stats(&c->r));
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
        for (int mode = 0; mode < 2; mode++, n++)
            bad += needle(&c, &sc, q, mode);
    }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    ZT_CHECK(bad == 0, "%lu pixels of %d needle/sliver frames differ from the reference", bad, n);
}

static void test_mesh_edges(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 32, 32, 16);
    zs_renderer *r = &c.r;
    zs_camera cam;
    std_cam(&cam);
    zs_mesh m = scene_mesh(), b;
    static const uint16_t last[] = {5, 4, 3};
    static const uint16_t past[] = {5, 4, 6};
    static const uint16_t big[] = {0, 1, 65535};
    ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
    b = m; b.indices = last; b.triangle_count = 1;         ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.indices = past; b.triangle_count = 1;         ST(zs_draw(r, &b, NULL), ZS_ERR_INDEX);
    b = m; b.indices = big; b.triangle_count = 1;          ST(zs_draw(r, &b, NULL), ZS_ERR_INDEX);
    b = m; b.vertex_count = 5;                             ST(zs_draw(r, &b, NULL), ZS_ERR_INDEX);
    b = m; b.vertex_count = 0;
    {
        zs_status s0 = zs_draw(r, &b, NULL);
        ZT_CHECK(s0 == ZS_ERR_MESH || s0 == ZS_ERR_INDEX, "vertex_count 0: %d", (int)s0);
        g_checks++;
    }
    b = m; b.triangle_count = 0;                           ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.triangle_count = 0; b.face_colors = NULL;     ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.positions = NULL; b.triangle_count = 0;       ST(zs_draw(r, &b, NULL), ZS_ERR_MESH);
    b = m; b.indices = NULL; b.triangle_count = 0;         ST(zs_draw(r, &b, NULL), ZS_ERR_MESH);
    b = m; b.scale = -ZS_FX(1) / 128;                      ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.scale = INT32_MIN;                            ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.scale = INT32_MAX;                            ST(zs_draw(r, &b, NULL), ZS_OK);
    b = m; b.scale = 1;                                    ST(zs_draw(r, &b, NULL), ZS_OK);
    {
        const zs_stats *s = zs_frame_stats(r);
        /* 1 + 0 + 0 + 2 + 2 + 2 + 2 triangles from the accepted draws */
        ZT_CHECK(s->tris_submitted == 9, "submitted %u, expected 9", s->tris_submitted);
        check_accounting(s);
    }
    static uint8_t img[W * H * 2];
    ST(render_guarded(r, W, H, 2, H, img), ZS_OK);
    zt_ctx_free(&c);
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
    g_checks += 4;
    zt_recs_free(&recs);
    free(idx);
    zt_ctx_free(&c);
}

typedef struct stopper {
    int calls, stop_at;
    int y_next;
} stopper;

static int stop_cb(void *user, int y0, int rows, const void *buf, size_t stride)
{
    stopper *s = (stopper *)user;
    (void)buf;
    (void)stride;
    ZT_CHECK(y0 == s->y_next && rows >= 1, "band %d+%d, expected to start at %d", y0, rows,
             s->y_next);
    s->y_next = y0 + rows;
    return ++s->calls >= s->stop_at;
}

static void test_render_frame_resume(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 32, 32, 16);
    zs_renderer *r = &c.r;
    zs_camera cam;
    std_cam(&cam);
    zs_mesh m = scene_mesh();
    static uint8_t ref[W * H * 2], band[W * 2 * 4];
    reference_frame(&c, ref);
    for (int stop = 1; stop <= 3; stop++) {
        ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
        ST(zs_draw(r, &m, NULL), ZS_OK);
        stopper s = {0, stop, 0};
        ST(zs_render_frame(r, band, 2 * W, 4, stop_cb, &s), ZS_OK);
        ZT_CHECK(s.calls == stop && s.y_next == 4 * stop, "stopped after %d bands at row %d",
                 s.calls, s.y_next);
        /* the rest through zs_render_rows, one row at a time */
        for (int y = s.y_next; y < H; y++) {
            ST(zs_render_rows(r, y, 1, band, 2 * W), ZS_OK);
            ZT_CHECK(memcmp(band, ref + (size_t)y * 2 * W, 2 * W) == 0,
                     "row %d after a stopped render_frame differs", y);
        }
        ZT_CHECK(zs_frame_stats(r)->rows == H, "rows %u", zs_frame_stats(r)->rows);
    }
    /* band_rows far above the height: one band */
    ST(zs_frame_begin(r, &cam, ZS_MODE_ZLINE), ZS_OK);
    stopper s = {0, 1000, 0};
    static uint8_t whole[W * H * 2];
    ST(zs_render_frame(r, whole, 2 * W, INT_MAX, stop_cb, &s), ZS_OK);
    ZT_CHECK(s.calls == 1 && s.y_next == H, "band_rows INT_MAX: %d bands to row %d", s.calls,
             s.y_next);
    zt_ctx_free(&c);
}

static void test_strides_and_rows(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 32, 32, 16);
    zs_renderer *r = &c.r;
    zs_camera cam;
    std_cam(&cam);
    static uint8_t buf[W * 3 * 4 + 64];
    for (int f = 0; f < ZS_FMT_COUNT; f++) {
        zs_shade_params sp = zs_shade_default();
        sp.format = (zs_format)f;
        size_t need = (size_t)W * zs_format_bytes(sp.format);
        ST(zs_frame_begin(r, &cam, ZS_MODE_SPAN), ZS_OK);
        ST(zs_frame_shading(r, &sp), ZS_OK);
        ST(zs_render_rows(r, 0, 1, buf, need - 1), ZS_ERR_BUFFER);
        ST(zs_render_rows(r, 0, 1, buf, 0), ZS_ERR_BUFFER);
        ST(zs_render_rows(r, 0, 1, buf, need), ZS_OK);
        ST(zs_render_rows(r, 1, 2, buf, need + 1), ZS_OK);
        ST(zs_render_rows(r, 3, 0, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, 3, -5, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, INT_MIN, 1, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, 3, INT_MAX, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, INT_MAX, INT_MAX, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, H - 1, 2, buf, need), ZS_ERR_ROW);
        ST(zs_render_rows(r, H - 1, 1, buf, need), ZS_OK); /* rows 3..H-2 skipped */
        ZT_CHECK(zs_frame_stats(r)->rows == 4, "format %d: rows %u", f, zs_frame_stats(r)->rows);
        ST(zs_frame_begin(r, &cam, ZS_MODE_ZLINE), ZS_OK);
        ST(zs_frame_shading(r, &sp), ZS_OK);
        ST(zs_render_frame(r, buf, need - 1, 1, sink, NULL), ZS_ERR_BUFFER);
        {
            zs_status s0 = zs_render_frame(r, buf, need, 0, sink, NULL);
            ZT_CHECK(s0 == ZS_ERR_ROW || s0 == ZS_ERR_ARGUMENT, "band_rows 0: %d", (int)s0);
            s0 = zs_render_frame(r, buf, need, INT_MIN, sink, NULL);
            ZT_CHECK(s0 == ZS_ERR_ROW || s0 == ZS_ERR_ARGUMENT, "band_rows INT_MIN: %d", (int)s0);
            g_checks += 2;
        }
        ST(zs_render_frame(r, buf, need, 4, NULL, NULL), ZS_ERR_NULL);
        ST(zs_render_frame(r, buf, need, 4, sink, NULL), ZS_OK);
    }
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
    ST(zs_camera_set_view(&cam, &id), ZS_OK);
    ST(zs_camera_perspective(&cam, 2293760, 1024, 66909184), ZS_OK);
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
    ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ST(zs_draw(&c.r, &m, &model), ZS_OK);

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
        cmocka_unit_test(test_state_matrix),     cmocka_unit_test(test_shading_arguments),
        cmocka_unit_test(test_q16_limits),       cmocka_unit_test(test_needles),
        cmocka_unit_test(test_mesh_edges),       cmocka_unit_test(test_tag_wrap),
        cmocka_unit_test(test_render_frame_resume), cmocka_unit_test(test_strides_and_rows),
        cmocka_unit_test(test_transform_overflow),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    printf("test_bad_input: %lu status/invariant checks, %d failed\n", g_checks, rc);
    fflush(stdout);
    return rc;
}
