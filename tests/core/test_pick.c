/* SPDX-License-Identifier: MIT */
/*
 * test_pick: zs_pick's contract. (Its answers are checked against the ID16
 * image at every pixel in test_raycast's random scenes, after frames of all
 * three modes, and in test_models' real meshes.)
 *  - refusals: NULL arguments, a pixel off the screen, a frame whose
 *    rendering has not begun;
 *  - answers once rendering has begun (a frame stopped early too), equal to
 *    the finished frame's ID16 pixels, in any format (tag only in ID16);
 *  - the depth is the record's plane at the centre (double oracle);
 *  - a frame that skipped records (active pool too small) says so.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 48
#define SEED 0x9C1C000000000015ull

static unsigned long g_picks, g_hits;

static int stop_early(void *user, int y0, int rows, const void *buf, size_t stride)
{
    (void)user;
    (void)rows;
    (void)buf;
    (void)stride;
    return y0 >= 8; /* stops after the band at row 8 */
}

static void test_pick(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 300, 900, 300);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    static uint8_t id[W * H * 2], img[W * H * 3];
    zs_pick_hit hit;
    for (int k = 0; k < 40; k++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 50), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        zt_recs recs = {0};
        ZT_ST(zt_frame(&c, &cam, ZS_MODE_SPAN, NULL, &m, 1, &recs, id, 1 + k % 5), ZS_OK);
        /* refusals */
        ZT_ST(zs_pick(NULL, 0, 0, &hit), ZS_ERR_NULL);
        ZT_ST(zs_pick(&c.r, 0, 0, NULL), ZS_ERR_NULL);
        ZT_ST(zs_pick(&c.r, -1, 0, &hit), ZS_ERR_ARGUMENT);
        ZT_ST(zs_pick(&c.r, W, 0, &hit), ZS_ERR_ARGUMENT);
        ZT_ST(zs_pick(&c.r, 0, H, &hit), ZS_ERR_ARGUMENT);
        ZT_ST(zs_pick(&c.r, 0, -1, &hit), ZS_ERR_ARGUMENT);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                ZT_ST(zs_pick(&c.r, x, y, &hit), ZS_OK);
                uint16_t want = zt_id_at(id, W, x, y);
                ZT_CHECK(hit.tag == want, "scene %d (%d,%d): tag %u, ID16 %u", k, x, y, hit.tag,
                         want);
                if (!want) {
                    ZT_CHECK(hit.record == ZS_PICK_NONE && hit.depth == 0 && hit.depth_q40 == 0,
                             "background: record %u depth %u", hit.record, hit.depth);
                    continue;
                }
                ZT_CHECK(hit.record < recs.n && recs.v[hit.record].tag == want,
                         "record %u of %zu", hit.record, recs.n);
                ZT_CHECK(zt_covers(recs.v[hit.record].xy, x, y), "record does not cover");
                double z = zt_depth_at(&recs.v[hit.record], x, y);
                ZT_CHECK(fabs(hit.depth / 1073741824.0 - z) < 1e-5 &&
                             hit.depth == (uint32_t)(hit.depth_q40 >> 10),
                         "depth %u (q40 %lld), plane %.9f", hit.depth, (long long)hit.depth_q40, z);
                g_hits++;
            }
        g_picks += W * H;
        /* before rendering: refused; in another format, stopped early: the
         * same records, tag 0 */
        zs_shade_params sp = zs_shade_default();
        sp.format = ZS_FMT_RGB888;
        ZT_ST(zs_frame_begin(&c.r, &cam, k % 2 ? ZS_MODE_WARNOCK : ZS_MODE_ZLINE), ZS_OK);
        ZT_ST(zs_frame_shading(&c.r, &sp), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_ST(zs_pick(&c.r, 1, 1, &hit), ZS_ERR_STATE);
        ZT_ST(zs_render_frame(&c.r, img, W * 3, 8, stop_early, NULL), ZS_OK);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                ZT_ST(zs_pick(&c.r, x, y, &hit), ZS_OK);
                uint16_t want = zt_id_at(id, W, x, y);
                ZT_CHECK(hit.tag == 0 && (hit.record == ZS_PICK_NONE) == (want == 0) &&
                             (want == 0 || recs.v[hit.record].tag == want),
                         "RGB888 frame (%d,%d): record %u tag %u, ID16 %u", x, y, hit.record,
                         hit.tag, want);
            }
        g_picks += W * H;
        zt_recs_free(&recs);
    }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_pick_skipped(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 300, 900, 4); /* two active triangles */
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    for (int l = 0; l < 3; l++) { /* three overlapping triangles on the same rows */
        int a = zt_scene_vertex_px(&sc, 5 + l, 5, 2.0 + l, 0);
        int b = zt_scene_vertex_px(&sc, 60, 10, 2.0 + l, 0);
        int d = zt_scene_vertex_px(&sc, 20, 40, 2.0 + l, 0);
        zt_scene_tri_front(&sc, a, b, d, 0x111111u * (unsigned)(l + 1));
    }
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    static uint8_t id[W * H * 2];
    zs_pick_hit hit;
    ZT_ST(zt_frame(&c, &cam, ZS_MODE_SPAN, NULL, &m, 1, NULL, id, H), ZS_OK);
    ZT_CHECK(zs_frame_stats(&c.r)->records_skipped > 0, "nothing skipped");
    ZT_ST(zs_pick(&c.r, 20, 20, &hit), ZS_ERR_CAPACITY);
    ZT_CHECK(hit.tag == 1, "the nearest record (tag 1) is still named: %u", hit.tag);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pick),
        cmocka_unit_test(test_pick_skipped),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_pick: %lu picks checked (%lu on a triangle, depth within 1e-5 of the plane); "
           "%d failed\n",
           g_picks, g_hits, rc);
    fflush(stdout);
    return rc;
}
