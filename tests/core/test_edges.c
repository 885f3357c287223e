/* SPDX-License-Identifier: MIT */
/*
 * test_edges: the edge table's shortcuts (src/raster.c, src/activate.c)
 * against the oracles.
 *  - Twins: an edge made for a row whose twin (the same two vertices, the
 *    other side) was made for the same row joins the twin's record instead of
 *    being made and folded. Covered at every size of the twin table (widths
 *    under 49 have none; 49, 97 and 193 columns and up have 32, 64 and 128
 *    slots), with batches larger than the table (probes run out: the rest is
 *    left to the numeric fold) and with seams (the same corners as copied
 *    vertices: other indices, equal coordinates, folded numerically).
 *  - Column lists (merge_columns): batches with many edges off either side of
 *    the screen, merged into lists that hold old edges off the screen too
 *    (a column's list there is in no order of x).
 *  - Runs and small tails: edges stepped many columns a row (near-horizontal
 *    edges reaching far off either side, clipped at the guard band: the step
 *    packed with the end row in one word, src/zs_internal.h zs_edge.run),
 *    slivers that cover a single row (never stepped), and rows whose new
 *    tails hold 1 .. 10 edges and rows with many (the column lists, the
 *    last edge of the list stepped after the loops), with twins, seams and
 *    edges off the screen among them.
 *  - Tall edges: from far above the screen to far below it (64 x 800, guard
 *    band 4 half-heights), dy past 2^15 in 1/16 px: zs_edge keeps dy and
 *    both remainders (in 1/16, exact: zs_edge) in 16 bits, unsigned.
 * Every frame: zt_guarded_frame and the ray caster in span mode, and the same
 * image byte for byte in zline mode and in span mode without the edge
 * scratch (ZS_CFG_NO_ZLINE: insertion sort and numeric fold only).
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEED 0xED6E5ED600000013ull
#define EH 40
#define SCENES 10

static zs_color rnd_color(zt_rng *g)
{
    return (zs_color)(zt_u32(g) & 0xFFFFFFu);
}

/* A vertex, and with seam set a second one at the same place (same
 * coordinates, another index). */
static int vtx(zt_scene *sc, double x, double y, double d, zs_color c, int *seam)
{
    int v = zt_scene_vertex_px(sc, x, y, d, c);
    if (seam)
        *seam = zt_scene_vertex_px(sc, x, y, d, c);
    return v;
}

/* Fans and strips whose tops lie on row yr (so their shared edges are made
 * for one row), some with seams, spread from 60 px left of the screen to 60
 * px right of it; big triangles off either side reaching over many rows, so
 * the rows' batches meet old edges off the screen. */
static void scene(zt_rng *g, zt_scene *sc, int w, int yr, int groups)
{
    for (int k = 0; k < groups; k++) {
        int kind = (int)zt_below(g, 3);
        double ax = zt_uniform(g, -60, w + 60), d = zt_uniform(g, 1.2, 3.5);
        int seams = zt_below(g, 3) == 0;
        if (kind == 0) { /* fan from an apex on row yr */
            int m = 3 + (int)zt_below(g, 10), rim[13], rim2[13];
            double R = zt_uniform(g, 6, 60), Ry = zt_uniform(g, 3, 25);
            double ay = yr + zt_uniform(g, -0.3, 0.3);
            int apex = vtx(sc, ax, ay, d, rnd_color(g), NULL);
            for (int i = 0; i < m; i++) {
                double th = 3.141592653589793 * (0.05 + 0.9 * (i + zt_uniform(g, 0.1, 0.9)) / m);
                rim[i] = vtx(sc, ax + R * cos(th), ay + 1 + Ry * sin(th),
                             d * (1 + zt_uniform(g, -0.2, 0.2)), rnd_color(g),
                             seams ? &rim2[i] : NULL);
            }
            for (int i = 0; i + 1 < m; i++) /* with seams, every other one uses the copies */
                zt_scene_tri_front(sc, apex, seams && i % 2 ? rim2[i] : rim[i],
                                   seams && i % 2 ? rim2[i + 1] : rim[i + 1], rnd_color(g));
        } else if (kind == 1) { /* strip of quads, tops on row yr */
            int n = 2 + (int)zt_below(g, 18), A[21], B[21], A2[21], B2[21];
            double dx = zt_uniform(g, 2, 12), drop = zt_uniform(g, 2, 20);
            for (int i = 0; i <= n; i++) {
                double x = ax + i * dx;
                A[i] = vtx(sc, x, yr + zt_uniform(g, -0.3, 0.3), d, rnd_color(g),
                           seams ? &A2[i] : NULL);
                B[i] = vtx(sc, x + zt_uniform(g, -3, 3), yr + drop + zt_uniform(g, -1, 1),
                           d * 1.05, rnd_color(g), seams ? &B2[i] : NULL);
            }
            for (int i = 0; i < n; i++) {
                int s = seams && i % 2;
                zt_scene_tri_front(sc, A[i], A[i + 1], B[i], rnd_color(g));
                zt_scene_tri_front(sc, s ? A2[i + 1] : A[i + 1], s ? B2[i + 1] : B[i + 1],
                                   s ? B2[i] : B[i], rnd_color(g));
            }
        } else { /* big, off one side, tops on other rows */
            double side = zt_below(g, 2) ? -zt_uniform(g, 5, 80) : w + zt_uniform(g, 5, 80);
            int v0 = vtx(sc, side, zt_uniform(g, -10, EH + 10), d, rnd_color(g), NULL);
            int v1 = vtx(sc, side + zt_uniform(g, -40, 40), zt_uniform(g, -10, EH + 10),
                         d * 1.1, rnd_color(g), NULL);
            int v2 = vtx(sc, zt_uniform(g, -20, w + 20), zt_uniform(g, -10, EH + 10), d * 0.9,
                         rnd_color(g), NULL);
            zt_scene_tri_front(sc, v0, v1, v2, rnd_color(g));
        }
    }
}

/* Few new edges a row: small fans and pairs (twins, some with seams) on
 * rows of their own, slivers a fraction of a row high (one row centre or
 * two), and long flat triangles whose edges cross the screen and beyond in a
 * few rows. */
static void scene_runs(zt_rng *g, zt_scene *sc, int w, int yr, int groups)
{
    (void)yr;
    for (int k = 0; k < groups; k++) {
        int kind = (int)zt_below(g, 4);
        double ax = zt_uniform(g, -40, w + 40), d = zt_uniform(g, 1.2, 3.5);
        double ay = (int)zt_range(g, 1, EH - 6) + zt_uniform(g, -0.45, 0.45);
        int seams = zt_below(g, 3) == 0;
        if (kind == 0) { /* a fan of 1..4 from an apex: tails of 2..5 edges */
            int m = 2 + (int)zt_below(g, 4), rim[6], rim2[6];
            double R = zt_uniform(g, 3, 30), Ry = zt_uniform(g, 1, 12);
            int apex = vtx(sc, ax, ay, d, rnd_color(g), NULL);
            for (int i = 0; i < m; i++) {
                double th = 3.141592653589793 * (0.05 + 0.9 * (i + zt_uniform(g, 0.1, 0.9)) / m);
                rim[i] = vtx(sc, ax + R * cos(th), ay + 1 + Ry * sin(th), d, rnd_color(g),
                             seams ? &rim2[i] : NULL);
            }
            for (int i = 0; i + 1 < m; i++)
                zt_scene_tri_front(sc, apex, seams && i % 2 ? rim2[i] : rim[i],
                                   seams && i % 2 ? rim2[i + 1] : rim[i + 1], rnd_color(g));
        } else if (kind == 1) { /* slivers: under a row high, or just over */
            double hgt = zt_below(g, 2) ? zt_uniform(g, 0.05, 0.95) : zt_uniform(g, 1.0, 2.2);
            double len = zt_uniform(g, 2, 3.0 * w);
            int a = vtx(sc, ax - len / 2, ay, d, rnd_color(g), NULL);
            int b = vtx(sc, ax + len / 2, ay + zt_uniform(g, -0.2, 0.2), d, rnd_color(g), NULL);
            int c = vtx(sc, ax + zt_uniform(g, -len / 2, len / 2), ay + hgt, d * 1.02,
                        rnd_color(g), NULL);
            zt_scene_tri_front(sc, a, b, c, rnd_color(g));
        } else if (kind == 2) { /* long and flat: many columns a row, off both sides */
            double x0 = -zt_uniform(g, 0.5, 6) * w, x1 = w + zt_uniform(g, 0.5, 6) * w;
            double dy = zt_uniform(g, 1.2, 6);
            int a = vtx(sc, x0, ay, d, rnd_color(g), NULL);
            int b = vtx(sc, x1, ay + zt_uniform(g, -0.5, 0.5) * dy, d * 1.05, rnd_color(g), NULL);
            int c = vtx(sc, zt_uniform(g, x0, x1), ay + dy, d * 0.95, rnd_color(g), NULL);
            zt_scene_tri_front(sc, a, b, c, rnd_color(g));
            if (zt_below(g, 2)) { /* its neighbour across the long edge */
                int e = vtx(sc, zt_uniform(g, x0, x1), ay - dy, d, rnd_color(g), NULL);
                zt_scene_tri_front(sc, b, a, e, rnd_color(g));
            }
        } else { /* a quad (two twins) of a row or a few */
            double qw = zt_uniform(g, 1, 25), qh = zt_uniform(g, 0.6, 4);
            int A2 = -1, B2 = -1;
            int A = vtx(sc, ax, ay, d, rnd_color(g), seams ? &A2 : NULL);
            int B = vtx(sc, ax + qw, ay + qh, d * 1.03, rnd_color(g), seams ? &B2 : NULL);
            int C = vtx(sc, ax + qw + zt_uniform(g, -2, 2), ay + zt_uniform(g, -0.4, 0.4), d,
                        rnd_color(g), NULL);
            int D = vtx(sc, ax + zt_uniform(g, -2, 2), ay + qh + zt_uniform(g, -0.4, 0.4), d,
                        rnd_color(g), NULL);
            zt_scene_tri_front(sc, A, C, B, rnd_color(g));
            zt_scene_tri_front(sc, seams ? A2 : A, seams ? B2 : B, D, rnd_color(g));
        }
    }
}

/* Edges from far above the screen to far below it, within the guard band
 * (up to 4 half-heights either side at these sizes): dy past 2^15 in 1/16
 * px, the width of zs_edge.dy. Tall strips of quads (their shared diagonals
 * tall too), fans from an apex far above, and slanted slivers a few pixels
 * wide. */
static void scene_tall(zt_rng *g, zt_scene *sc, int w, int yr, int groups)
{
    const double h = sc->h;
    (void)yr;
    for (int k = 0; k < groups; k++) {
        int kind = (int)zt_below(g, 3);
        double top = h * zt_uniform(g, -1.45, -0.3), bot = h * zt_uniform(g, 1.3, 2.45);
        double x0 = zt_uniform(g, -0.4, 1.4) * w, d = zt_uniform(g, 1.2, 3.5);
        if (kind == 0) { /* a strip of quads */
            int n = 1 + (int)zt_below(g, 5), A[6], B[6];
            double dx = zt_uniform(g, 1, 8), lean = zt_uniform(g, -1.2, 1.2) * w;
            for (int i = 0; i <= n; i++) {
                A[i] = vtx(sc, x0 + i * dx, top + zt_uniform(g, -2, 2), d, rnd_color(g), NULL);
                B[i] = vtx(sc, x0 + lean + i * dx, bot + zt_uniform(g, -2, 2), d * 1.1,
                           rnd_color(g), NULL);
            }
            for (int i = 0; i < n; i++) {
                zt_scene_tri_front(sc, A[i], A[i + 1], B[i], rnd_color(g));
                zt_scene_tri_front(sc, A[i + 1], B[i + 1], B[i], rnd_color(g));
            }
        } else if (kind == 1) { /* a fan from far above to a rim far below */
            int m = 2 + (int)zt_below(g, 5), rim[7];
            int apex = vtx(sc, x0, top, d, rnd_color(g), NULL);
            for (int i = 0; i < m; i++)
                rim[i] = vtx(sc, x0 + zt_uniform(g, -0.6, 0.6) * w + 3.0 * i, bot - 5.0 * i,
                             d * 1.05, rnd_color(g), NULL);
            for (int i = 0; i + 1 < m; i++)
                zt_scene_tri_front(sc, apex, rim[i], rim[i + 1], rnd_color(g));
        } else { /* a slanted sliver, its middle vertex on the screen */
            double x1 = zt_uniform(g, -0.4, 1.4) * w;
            int a = vtx(sc, x0, top, d, rnd_color(g), NULL);
            int b = vtx(sc, x1, bot, d * 0.9, rnd_color(g), NULL);
            int c = vtx(sc, (x0 + x1) / 2 + zt_uniform(g, -4, 4), zt_uniform(g, 0, h), d,
                        rnd_color(g), NULL);
            zt_scene_tri_front(sc, a, b, c, rnd_color(g));
        }
    }
}

typedef void (*scene_fn)(zt_rng *g, zt_scene *sc, int w, int yr, int groups);

static void run_size_with(int w, int h, uint64_t seed, scene_fn make, int min_groups,
                          int groups, int randoms)
{
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, seed);
    zt_ctx c, cn;
    zt_ctx_init_flags(&c, w, h, 1500, 6000, 1500, 0);
    zt_ctx_init_flags(&cn, w, h, 1500, 6000, 1500, ZS_CFG_NO_ZLINE);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, w, h, 256);
    zt_gframe *f = zt_gframe_new(w, h), *fz = zt_gframe_new(w, h), *fn = zt_gframe_new(w, h);
    const int bands[] = {1, 5, h};
    for (int k = 0; k < SCENES; k++) {
        zt_scene_reset(&sc);
        int yr = (int)zt_range(&g, 0, h - 4);
        make(&g, &sc, w, yr, min_groups + (int)zt_below(&g, (uint32_t)groups));
        if (randoms)
            zt_scene_random(&g, &sc, randoms, ZT_SC_PLAIN | ZT_SC_SHARED | ZT_SC_BIG, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 1);
        char what[120];
        snprintf(what, sizeof what, "edges: %dx%d scene %d (row %d, %zu triangles, seed %llx)",
                 w, h, k, yr, sc.nt, (unsigned long long)seed);
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, bands[k % 3]);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(f->st.tris_dropped == 0 && f->st.records_skipped == 0 &&
                     f->st.verts_dropped == 0,
                 "%s: pools too small for the test", what);
        bad += zt_vs_raycast(f, what);
        zt_guarded_frame(&c, &cam, ZS_MODE_ZLINE, &m, 1, NULL, fz, bands[(k + 1) % 3]);
        zt_guarded_frame(&cn, &cam, ZS_MODE_SPAN, &m, 1, NULL, fn, bands[(k + 2) % 3]);
        long d = zt_first_diff(f->img, fz->img, (size_t)w * (size_t)h * 2);
        ZT_CHECK(d < 0, "%s: span and zline differ at pixel (%ld,%ld)", what, d / 2 % w,
                 d / 2 / w);
        d = zt_first_diff(f->img, fn->img, (size_t)w * (size_t)h * 2);
        ZT_CHECK(d < 0, "%s: span with and without the edge scratch differ at pixel (%ld,%ld)",
                 what, d / 2 % w, d / 2 / w);
    }
    zt_gframe_free(f);
    zt_gframe_free(fz);
    zt_gframe_free(fn);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    zt_ctx_free(&cn);
    ZT_CHECK(bad == 0, "%dx%d: %lu pixels disagree with the ray caster", w, h, bad);
}

static void run_width_with(int w, uint64_t seed, scene_fn make, int min_groups, int groups,
                           int randoms)
{
    run_size_with(w, EH, seed, make, min_groups, groups, randoms);
}

static void run_width(int w, uint64_t seed)
{
    run_width_with(w, seed, scene, 6, 30, 10);
}

/* No twin table (width 40), 32 slots (60), 64 (100), 128 (200, 300): twins,
 * seams, full tables and off-screen lists at each. */
static void test_twins_and_columns(void **state)
{
    (void)state;
    static const int widths[] = {40, 48, 49, 60, 96, 97, 100, 192, 193, 200, 300};
    for (size_t i = 0; i < sizeof widths / sizeof widths[0]; i++)
        run_width(widths[i], SEED + i);
}

/* Runs and small tails at every size of the twin table: few groups a scene
 * (tails of a few edges) and more (long tails), with and
 * without random content around them. */
static void test_runs_and_small_tails(void **state)
{
    (void)state;
    static const int widths[] = {40, 60, 100, 200, 300};
    for (size_t i = 0; i < sizeof widths / sizeof widths[0]; i++) {
        run_width_with(widths[i], SEED + 0x100 + i, scene_runs, 1, 4, 0);
        run_width_with(widths[i], SEED + 0x200 + i, scene_runs, 8, 40, 6);
    }
}

/* Edges taller than 2^15 in 1/16 px (64 x 800: a guard of 4 half-heights
 * either side, dy up to 3.9 screen heights), alone and among random
 * content. */
static void test_tall_edges(void **state)
{
    (void)state;
    run_size_with(64, 800, SEED + 0x300, scene_tall, 2, 10, 0);
    run_size_with(64, 800, SEED + 0x301, scene_tall, 6, 20, 6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_twins_and_columns),
        cmocka_unit_test(test_runs_and_small_tails),
        cmocka_unit_test(test_tall_edges),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
