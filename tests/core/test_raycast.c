/* SPDX-License-Identifier: MIT */
/*
 * test_raycast: random scenes (20-60 triangles: penetrating, abutting,
 * duplicated, crossing the near plane, large tilted planes) rendered in ID16
 * in both modes and compared at every pixel with a double-precision ray
 * caster over the hook's snapped records: coverage by the reference edge
 * functions (top-left rule), depth by barycentric interpolation of the three
 * window depths in screen space, nearest wins, exact geometric duplicates go
 * to the one submitted first.
 *
 * The same frames check zs_pick against the ID16 image at every pixel, and
 * Warnock mode joins the two others against the ray caster.
 *
 * Near ties are excluded: a pixel where the nearest and the runner-up of
 * another tag differ in window depth by less than TOL (2^-20) may go either
 * way. Their number is printed and must stay below MAX_EXCLUDED_FRACTION of
 * the covered pixels; everything else must agree exactly. Duplicates with
 * the same vertices in another order are exact ties too: the first wins.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 80
#define NSCENES 300
#define TOL (1.0 / 1048576.0) /* 2^-20 in window depth */
#define MAX_EXCLUDED_FRACTION 0.005
#define SEED 0x4A7CA57000000003ull

static unsigned long g_bad[3], g_near_disagree[3], g_px[3], g_excluded[3], g_dup_ties[3], g_tris, g_records, g_clipped;
static unsigned long g_picks, g_pick_hits;
static const char *const k_mode_name[3] = {"span", "zline", "warnock"};

static void run(zs_visibility mode)
{
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 600, 1800, 600);
    zs_camera cam;
    const double near_d = 0.5;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    zt_recs recs = {0};
    zt_cast cast;
    zt_cast_alloc(&cast, W, H);
    static uint8_t img[W * H * 2];
    int m = mode == ZS_MODE_WARNOCK ? 2 : (int)mode;
    for (int n = 0; n < NSCENES; n++) {
        zt_scene_reset(&sc);
        int ntri = (int)zt_range(&g, 20, 60);
        unsigned flags = ZT_SC_ALL;
        if (n % 4 == 1) flags = ZT_SC_PLAIN;            /* penetration-heavy */
        if (n % 4 == 2) flags = ZT_SC_FLAT | ZT_SC_SHARED | ZT_SC_DUP;
        if (n % 4 == 3) flags = ZT_SC_LAYERS | ZT_SC_PLAIN; /* depth-range decisions */
        zt_scene_random(&g, &sc, ntri, flags, near_d);
        zs_mesh mesh = zt_scene_mesh(&sc, 1, 0);
        memset(img, 0xAB, sizeof img);
        zs_status st = zt_frame(&c, &cam, mode, NULL, &mesh, 1, &recs, img, 1 + n % 11);
        ZT_CHECK(st == ZS_OK, "scene %d: %s", n, zs_strerror(st));
        const zs_stats *stats = zs_frame_stats(&c.r);
        ZT_CHECK(stats->records == recs.n, "scene %d: stats.records %u, hook calls %zu", n,
                 stats->records, recs.n);
        ZT_CHECK(stats->tris_dropped == 0 && stats->records_skipped == 0 &&
                     stats->verts_dropped == 0,
                 "scene %d: pools too small for the test (dropped %u/%u/%u)", n,
                 stats->tris_dropped, stats->records_skipped, stats->verts_dropped);
        ZT_CHECK(stats->tris_submitted == stats->tris_culled + stats->tris_rejected +
                                              stats->tris_empty + stats->tris_dropped +
                                              stats->tris_stored,
                 "scene %d: stats accounting does not add up", n);
        if (m == 0) {
            g_tris += sc.nt;
            g_records += recs.n;
            g_clipped += stats->tris_clipped;
        }
        /* picking names the ID16 pixel everywhere, after a frame of any mode */
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                zs_pick_hit hit;
                ZT_ST(zs_pick(&c.r, x, y, &hit), ZS_OK);
                uint16_t id = zt_id_at(img, W, x, y);
                ZT_CHECK(hit.tag == id && (hit.record == ZS_PICK_NONE) == (id == 0),
                         "%s scene %d: pick (%d,%d) tag %u record %u, ID16 %u", k_mode_name[m], n,
                         x, y, hit.tag, hit.record, id);
                if (id) {
                    /* its depth: the record's plane there (the ray caster's, in double) */
                    double z = zt_depth_at(&recs.v[hit.record], x, y);
                    ZT_CHECK(fabs((double)hit.depth / 1073741824.0 - z) < 1e-5,
                             "%s scene %d: pick (%d,%d) depth %.9f, plane %.9f", k_mode_name[m], n,
                             x, y, (double)hit.depth / 1073741824.0, z);
                    g_pick_hits++;
                }
                g_picks++;
            }
        zt_raycast(&recs, &cast);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int p = y * W + x;
                uint16_t id = zt_id_at(img, W, x, y);
                uint16_t want = cast.owner[p];
                if (want) g_px[m]++;
                if (cast.exact[p] && cast.z2[p] - cast.z1[p] >= TOL) g_dup_ties[m]++;
                int near_tie = want && cast.z2[p] - cast.z1[p] < TOL;
                if (near_tie) g_excluded[m]++;
                if (id == want) continue;
                if (near_tie) {
                    g_near_disagree[m]++;
                    continue;
                }
                /* report the first few in detail, fail after the whole run */
                if (g_bad[m]++ >= 3) continue;
                print_error("raycast mismatch (%s, seed %llx, scene %d) at pixel (%d,%d): ID16 %u, "
                            "ray caster %u (z %.9f, runner-up %.9f)\n",
                            k_mode_name[m], (unsigned long long)SEED, n, x, y, id, want,
                            cast.z1[p], cast.z2[p]);
                for (size_t i = 0; i < recs.n; i++)
                    if ((recs.v[i].tag == id || recs.v[i].tag == want) &&
                        zt_covers(recs.v[i].xy, x, y))
                        print_error("  record tag %u xy %d %d %d %d %d %d z %u %u %u -> z %.9f\n",
                                    recs.v[i].tag, recs.v[i].xy[0], recs.v[i].xy[1],
                                    recs.v[i].xy[2], recs.v[i].xy[3], recs.v[i].xy[4],
                                    recs.v[i].xy[5], recs.v[i].z[0], recs.v[i].z[1],
                                    recs.v[i].z[2], zt_depth_at(&recs.v[i], x, y));
            }
    }
    ZT_CHECK(g_bad[m] == 0, "%s: %lu pixels disagree with the ray caster (beyond near ties)",
             k_mode_name[m], g_bad[m]);
    ZT_CHECK((double)g_excluded[m] <= MAX_EXCLUDED_FRACTION * (double)g_px[m],
             "%s: %lu near-tie pixels excluded of %lu covered (limit %.2f%%)",
             k_mode_name[m], g_excluded[m], g_px[m], 100 * MAX_EXCLUDED_FRACTION);
    zt_cast_free(&cast);
    zt_recs_free(&recs);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_span(void **state)
{
    (void)state;
    run(ZS_MODE_SPAN);
}

static void test_zline(void **state)
{
    (void)state;
    run(ZS_MODE_ZLINE);
}

static void test_warnock(void **state)
{
    (void)state;
    run(ZS_MODE_WARNOCK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_span),
        cmocka_unit_test(test_zline),
        cmocka_unit_test(test_warnock),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_raycast: seed %llx, %d scenes %dx%d, %lu triangles (%lu records, %lu clipped), "
           "near-tie tolerance 2^-20: span %lu of %lu covered pixels excluded (%.4f%%, %lu of them "
           "disagreeing), zline %lu of %lu (%.4f%%, %lu disagreeing); exact-duplicate ties (any vertex order) decided by order: span %lu, zline %lu; "
           "disagreeing pixels: span %lu, zline %lu; warnock %lu of %lu excluded, %lu disagreeing; "
           "%lu picks equal to the ID16 pixel (%lu on a triangle, depth within 1e-5 of the plane); "
           "%d failed\n",
           (unsigned long long)SEED, NSCENES, W, H, g_tris, g_records, g_clipped, g_excluded[0],
           g_px[0], g_px[0] ? 100.0 * g_excluded[0] / g_px[0] : 0.0, g_near_disagree[0],
           g_excluded[1], g_px[1], g_px[1] ? 100.0 * g_excluded[1] / g_px[1] : 0.0,
           g_near_disagree[1], g_dup_ties[0], g_dup_ties[1], g_bad[0], g_bad[1], g_excluded[2],
           g_px[2], g_bad[2], g_picks, g_pick_hits, rc);
    fflush(stdout);
    return rc;
}
