/* SPDX-License-Identifier: MIT */
/*
 * test_warnock: Warnock mode's own cases (the random and model scenes of
 * test_modes, test_models, test_raycast, test_shortcuts, test_extremes,
 * test_mono and test_lines hold it to the other modes byte for byte):
 *  - the window counts of simple frames, worked out here: an empty frame
 *    and a screen-filling triangle take one window per band, a triangle
 *    with its edges inside the screen splits down to the pixels along them;
 *  - an exact depth tie where the surrounding triangle must not be taken
 *    as in front: a small triangle submitted first lies on the same plane
 *    inside a big one, and keeps every pixel it covers (half-space oracle);
 *  - a band whose records do not fit the active pool is rendered in parts,
 *    still equal to span mode, and ZS_CFG_NO_ZLINE does not stop the mode;
 *  - the widest screen (1024) with a dense mesh: the bounded stack suffices.
 */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define SEED 0x3A2B0C1500000015ull

static unsigned long g_frames, g_windows, g_decisions;

static void render(zt_ctx *c, zs_visibility mode, const zs_mesh *m, uint8_t *img, int band,
                   zt_recs *recs)
{
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    ZT_ST(zt_frame(c, &cam, mode, NULL, m, m ? 1 : 0, recs, img, band), ZS_OK);
    g_frames++;
    if (mode == ZS_MODE_WARNOCK) {
        g_windows += zs_frame_stats(&c->r)->windows;
        g_decisions += zs_frame_stats(&c->r)->pixel_decisions;
    }
}

/* Bands of `band` rows over h rows. */
static uint32_t bands_of(int h, int band)
{
    return (uint32_t)((h + band - 1) / band);
}

static void test_window_counts(void **state)
{
    (void)state;
    enum { W = 64, H = 48 };
    zt_ctx c;
    zt_ctx_init(&c, W, H, 16, 16, 16);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 8 * H);
    static uint8_t img[W * H * 2];
    static const int bands[] = {1, 5, 16, H};
    for (int b = 0; b < 4; b++) {
        /* nothing drawn: one background window per band */
        render(&c, ZS_MODE_WARNOCK, NULL, img, bands[b], NULL);
        const zs_stats *st = zs_frame_stats(&c.r);
        ZT_CHECK(st->windows == bands_of(H, bands[b]) && st->pixel_decisions == 0,
                 "empty frame, bands of %d: %u windows, %u decisions", bands[b], st->windows,
                 st->pixel_decisions);
        for (int i = 0; i < W * H; i++) ZT_CHECK(zt_id_at(img, W, i % W, i / W) == 0, "drawn");
        /* one triangle larger than the screen (within the guard band, so
         * one record): surrounds every band */
        zt_scene_reset(&sc);
        int v0 = zt_scene_vertex_q(&sc, -16 * W / 10, -16 * H / 10, 0);
        int v1 = zt_scene_vertex_q(&sc, 16 * 22 * W / 10, -16 * H / 10, 0);
        int v2 = zt_scene_vertex_q(&sc, -16 * W / 10, 16 * 22 * H / 10, 0);
        zt_scene_tri_front(&sc, v0, v1, v2, 0x123456);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        render(&c, ZS_MODE_WARNOCK, &m, img, bands[b], NULL);
        st = zs_frame_stats(&c.r);
        ZT_CHECK(st->windows == bands_of(H, bands[b]) && st->pixel_decisions == 0,
                 "covering triangle, bands of %d: %u windows", bands[b], st->windows);
        for (int i = 0; i < W * H; i++) ZT_CHECK(zt_id_at(img, W, i % W, i / W) == 1, "not covered");
        /* one triangle inside the screen: the only record of each window it
         * reaches, drawn as spans: still one window per band */
        zt_scene_reset(&sc);
        v0 = zt_scene_vertex_q(&sc, 16 * 5 + 3, 16 * 4 + 1, 0);
        v1 = zt_scene_vertex_q(&sc, 16 * 60 + 7, 16 * 9 + 11, 0);
        v2 = zt_scene_vertex_q(&sc, 16 * 21 + 5, 16 * 44 + 2, 0);
        zt_scene_tri_front(&sc, v0, v1, v2, 0x654321);
        m = zt_scene_mesh(&sc, 1, 0);
        zt_recs recs = {0};
        render(&c, ZS_MODE_WARNOCK, &m, img, bands[b], &recs);
        st = zs_frame_stats(&c.r);
        ZT_CHECK(st->windows == bands_of(H, bands[b]), "one triangle, bands of %d: %u windows",
                 bands[b], st->windows);
        ZT_CHECK(recs.n == 1, "%zu records", recs.n);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                ZT_CHECK(zt_id_at(img, W, x, y) == (zt_covers(recs.v[0].xy, x, y) ? 1 : 0),
                         "one triangle, pixel (%d,%d) against the half-space oracle", x, y);
        zt_recs_free(&recs);
    }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_equal_depth_inside(void **state)
{
    (void)state;
    enum { W = 64, H = 48 };
    zt_ctx c;
    zt_ctx_init(&c, W, H, 16, 16, 16);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 8 * H);
    zt_rng g;
    zt_rng_seed(&g, SEED);
    static uint8_t img[W * H * 2], ref[W * H * 2];
    unsigned long small_px = 0;
    for (int k = 0; k < 40; k++) {
        zt_scene_reset(&sc);
        /* the small one first, then a big one around it, all on one plane */
        int a0 = zt_scene_vertex_q(&sc, (int32_t)zt_range(&g, 16 * 8, 16 * 30),
                                   (int32_t)zt_range(&g, 16 * 6, 16 * 20), 0);
        int a1 = zt_scene_vertex_q(&sc, (int32_t)zt_range(&g, 16 * 34, 16 * 56),
                                   (int32_t)zt_range(&g, 16 * 6, 16 * 40), 0);
        int a2 = zt_scene_vertex_q(&sc, (int32_t)zt_range(&g, 16 * 8, 16 * 56),
                                   (int32_t)zt_range(&g, 16 * 24, 16 * 42), 0);
        zt_scene_tri_front(&sc, a0, a1, a2, 0x0000FF);
        int b0 = zt_scene_vertex_q(&sc, -16 * W / 10, -16 * H / 10, 0);
        int b1 = zt_scene_vertex_q(&sc, 16 * 22 * W / 10, -16 * H / 10, 0);
        int b2 = zt_scene_vertex_q(&sc, -16 * W / 10, 16 * 22 * H / 10, 0);
        zt_scene_tri_front(&sc, b0, b1, b2, 0x00FF00);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        zt_recs recs = {0};
        render(&c, ZS_MODE_ZLINE, &m, ref, H, &recs);
        ZT_CHECK(recs.n == 2, "%zu records", recs.n);
        int flat = 1;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 3; j++) flat &= recs.v[i].z[j] == recs.v[0].z[0];
        ZT_CHECK(flat, "scene %d: the vertices are not on one depth (%u %u %u / %u %u %u)", k,
                 recs.v[0].z[0], recs.v[0].z[1], recs.v[0].z[2], recs.v[1].z[0], recs.v[1].z[1],
                 recs.v[1].z[2]);
        for (int band = 1; band <= H; band = band * 3 + 1) {
            render(&c, ZS_MODE_WARNOCK, &m, img, band, NULL);
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    uint16_t want = zt_covers(recs.v[0].xy, x, y) ? 1 : 2;
                    uint16_t id = zt_id_at(img, W, x, y);
                    ZT_CHECK(id == want, "scene %d band %d: pixel (%d,%d) shows %u, the tie "
                             "goes to the first submitted (%u)", k, band, x, y, id, want);
                    small_px += want == 1;
                }
            ZT_CHECK(zt_first_diff(ref, img, sizeof img) < 0, "scene %d: Warnock != zline", k);
        }
        zt_recs_free(&recs);
    }
    ZT_CHECK(small_px > 1000, "only %lu pixels of the small triangles", small_px);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_small_pool(void **state)
{
    (void)state;
    enum { W = 80, H = 60 };
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 1);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    static uint8_t img[W * H * 2], ref[W * H * 2];
    unsigned long split = 0;
    for (int k = 0; k < 60; k++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 20, 40), ZT_SC_PLAIN | ZT_SC_SHARED, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        /* a pool just large enough for the busiest row */
        zt_ctx big;
        zt_ctx_init(&big, W, H, 200, 600, 200);
        render(&big, ZS_MODE_SPAN, &m, ref, H, NULL);
        uint32_t need = zs_frame_stats(&big.r)->max_active_edges;
        uint32_t records = zs_frame_stats(&big.r)->records;
        zt_ctx_free(&big);
        if (need < 2) continue;
        zt_ctx c;
        zt_ctx_init(&c, W, H, 200, 600, (int)need);
        render(&c, ZS_MODE_SPAN, &m, img, 7, NULL);
        ZT_CHECK(zs_frame_stats(&c.r)->records_skipped == 0, "span skipped with its own need");
        ZT_CHECK(zt_first_diff(ref, img, sizeof img) < 0, "span with the tight pool differs");
        render(&c, ZS_MODE_WARNOCK, &m, img, H, NULL);
        const zs_stats *st = zs_frame_stats(&c.r);
        ZT_CHECK(st->records_skipped == 0 && st->max_active_edges <= need,
                 "scene %d: Warnock skipped %u records, used %u edge sides of %u", k,
                 st->records_skipped, st->max_active_edges, need);
        ZT_CHECK(zt_first_diff(ref, img, sizeof img) < 0, "scene %d: Warnock with a pool of %u "
                 "sides differs from span", k, need);
        split += records > need / 2; /* the whole frame could not be one band */
        zt_ctx_free(&c);
    }
    ZT_CHECK(split > 30, "only %lu scenes needed split bands", split);
    /* without the z-buffer line */
    zt_ctx c;
    memset(&c, 0, sizeof c);
    c.cfg = zs_config_default(W, H, 200, 600, 200);
    c.cfg.flags = ZS_CFG_NO_ZLINE;
    c.arena_size = zs_arena_bytes(&c.cfg);
    c.arena = malloc(c.arena_size);
    ZT_ST(zs_init(&c.r, c.arena, c.arena_size, &c.cfg), ZS_OK);
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    render(&c, ZS_MODE_SPAN, &m, ref, H, NULL);
    render(&c, ZS_MODE_WARNOCK, &m, img, 9, NULL);
    ZT_CHECK(zt_first_diff(ref, img, sizeof img) < 0, "NO_ZLINE: Warnock differs from span");
    free(c.arena);
    zt_scene_free(&sc);
}

static void test_widest(void **state)
{
    (void)state;
    enum { W = 1024, H = 24 };
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 2);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 3000, 9000, 3000);
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    zt_scene_random(&g, &sc, 1500, ZT_SC_PLAIN | ZT_SC_SHARED | ZT_SC_DUP, 0.5);
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    uint8_t *ref = malloc(W * H * 2), *img = malloc(W * H * 2);
    render(&c, ZS_MODE_SPAN, &m, ref, H, NULL);
    render(&c, ZS_MODE_WARNOCK, &m, img, H, NULL);
    ZT_CHECK(zs_frame_stats(&c.r)->pixel_decisions > 0, "no pixel decided by the centre rule");
    ZT_CHECK(zt_first_diff(ref, img, (size_t)W * H * 2) < 0, "1024 wide: Warnock != span");
    free(ref);
    free(img);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_window_counts),
        cmocka_unit_test(test_equal_depth_inside),
        cmocka_unit_test(test_small_pool),
        cmocka_unit_test(test_widest),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_warnock: %lu frames, %lu Warnock windows visited, %lu pixel decisions; %d "
           "failed\n",
           g_frames, g_windows, g_decisions, rc);
    fflush(stdout);
    return rc;
}
