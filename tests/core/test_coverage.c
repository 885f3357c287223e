/* SPDX-License-Identifier: MIT */
/*
 * test_coverage: single random triangles, each rendered alone in ID16, in both
 * visibility modes. The set of pixels carrying the triangle's tag must equal,
 * exactly, the set given by the half-space reference rasterizer (integer edge
 * functions on the hook's snapped 28.4 vertices, top-left rule), taken over
 * all the records the hook reported for that triangle (clipping may split it).
 *
 * The reference rasterizer itself is first cross-checked against a second,
 * independently written oracle: a scanline formula with exact integer ceil
 * divisions (rows ytop <= cy < ybot, columns ceil(xl-0.5) .. ceil(xr-0.5)-1).
 *
 * A third check catches triangles that the renderer loses: the test projects
 * and snaps each (unclipped, on-screen-ish) triangle itself in double precision
 * and, when that covers a good number of pixels, the renderer must report
 * records for it; the hook's snapped vertices must also lie within a small
 * tolerance of the test's own projection (transform accuracy).
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64
#define NTRIS 10000
#define SEED 0xC0FE12AB34CD0001ull

static zt_rng g_rng;
static unsigned long g_pixels_in, g_renders, g_clipped, g_on_centre, g_on_edge, g_empty,
    g_multi;
static double g_max_dev;

/* ---- second oracle: scanline with exact ceil divisions ---- */

static int64_t ceil_div(int64_t a, int64_t b) /* b > 0 */
{
    return a >= 0 ? (a + b - 1) / b : -((-a) / b);
}

/* x of edge a->b at y = cy as a rational num/den (den > 0), for ya != yb */
static void edge_x(int64_t xa, int64_t ya, int64_t xb, int64_t yb, int64_t cy, int64_t *num,
                   int64_t *den)
{
    if (yb < ya) {
        int64_t t;
        t = xa; xa = xb; xb = t;
        t = ya; ya = yb; yb = t;
    }
    *den = yb - ya;
    *num = xa * (yb - ya) + (cy - ya) * (xb - xa);
}

static void scan_mask(const int32_t xy[6], int x0, int y0, int w, int h, uint8_t *mask)
{
    memset(mask, 0, (size_t)w * (size_t)h);
    if (zt_area2(xy) == 0) return;
    int64_t ymin = xy[1], ymax = xy[1];
    for (int k = 1; k < 3; k++) {
        if (xy[2 * k + 1] < ymin) ymin = xy[2 * k + 1];
        if (xy[2 * k + 1] > ymax) ymax = xy[2 * k + 1];
    }
    for (int j = 0; j < h; j++) {
        int64_t cy = (int64_t)(y0 + j) * 16 + 8;
        if (!(ymin <= cy && cy < ymax)) continue;
        int64_t n[2], d[2];
        int m = 0;
        for (int k = 0; k < 3 && m < 2; k++) {
            int64_t xa = xy[2 * k], ya = xy[2 * k + 1];
            int64_t xb = xy[(2 * k + 2) % 6], yb = xy[(2 * k + 3) % 6];
            if (ya == yb) continue;
            int64_t lo = ya < yb ? ya : yb, hi = ya < yb ? yb : ya;
            if (!(lo <= cy && cy < hi)) continue;
            edge_x(xa, ya, xb, yb, cy, &n[m], &d[m]);
            m++;
        }
        if (m != 2) continue;
        /* order: left has the smaller x (compare n0/d0 vs n1/d1) */
        if (n[0] * d[1] > n[1] * d[0]) {
            int64_t t;
            t = n[0]; n[0] = n[1]; n[1] = t;
            t = d[0]; d[0] = d[1]; d[1] = t;
        }
        /* first column i with 16 i + 8 >= xl: i = ceil((xl - 8) / 16) */
        int64_t c0 = ceil_div(n[0] - 8 * d[0], 16 * d[0]);
        int64_t c1 = ceil_div(n[1] - 8 * d[1], 16 * d[1]); /* exclusive */
        for (int64_t i = c0; i < c1; i++)
            if (i >= x0 && i < x0 + w) mask[(size_t)j * (size_t)w + (size_t)(i - x0)] = 1;
    }
}

static void random_snapped_tri(zt_rng *g, int32_t xy[6])
{
    int mode = (int)zt_below(g, 4);
    double s = exp(zt_uniform(g, log(0.05), log(40.0))) * 16;
    double cx = zt_uniform(g, -40, 40) * 16, cy = zt_uniform(g, -40, 40) * 16;
    for (int k = 0; k < 3; k++) {
        double x = cx + s * zt_uniform(g, -1, 1), y = cy + s * zt_uniform(g, -1, 1);
        xy[2 * k] = (int32_t)floor(x);
        xy[2 * k + 1] = (int32_t)floor(y);
        if (mode == 1) { /* on pixel centres or edges */
            xy[2 * k] = (xy[2 * k] & ~15) + (zt_below(g, 2) ? 8 : 0);
            xy[2 * k + 1] = (xy[2 * k + 1] & ~15) + (zt_below(g, 2) ? 8 : 0);
        }
    }
    if (mode == 2) { /* axis-aligned edges */
        xy[3] = xy[1];
        xy[4] = xy[2];
    }
}

static void test_oracle_selfcheck(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x1111);
    enum { WW = 90, HH = 90, X0 = -45, Y0 = -45 };
    static uint8_t mask[WW * HH];
    unsigned long px = 0;
    for (int t = 0; t < 20000; t++) {
        int32_t xy[6];
        random_snapped_tri(&g, xy);
        scan_mask(xy, X0, Y0, WW, HH, mask);
        for (int j = 0; j < HH; j++)
            for (int i = 0; i < WW; i++) {
                int a = zt_covers(xy, X0 + i, Y0 + j), b = mask[j * WW + i];
                px += (unsigned long)a;
                if (a != b)
                    ZT_FAIL("oracles disagree (seed %llx, tri %d) at pixel (%d,%d): half-space %d, "
                            "scanline %d; xy = %d %d %d %d %d %d",
                            (unsigned long long)SEED, t, X0 + i, Y0 + j, a, b, xy[0], xy[1], xy[2],
                            xy[3], xy[4], xy[5]);
            }
        /* orientation independence */
        int32_t rev[6] = {xy[0], xy[1], xy[4], xy[5], xy[2], xy[3]};
        for (int k = 0; k < 50; k++) {
            int i = (int)zt_range(&g, X0, X0 + WW - 1), j = (int)zt_range(&g, Y0, Y0 + HH - 1);
            ZT_CHECK(zt_covers(xy, i, j) == zt_covers(rev, i, j), "orientation dependence");
        }
    }
    /* tiny known cases: a 2x2-pixel square split in two along a diagonal */
    int32_t a[6] = {0, 0, 32, 0, 32, 32}, b[6] = {0, 0, 32, 32, 0, 32};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
            ZT_CHECK(zt_covers(a, i, j) + zt_covers(b, i, j) == 1, "square split (%d,%d)", i, j);
    ZT_CHECK(zt_covers(a, 1, 0) && !zt_covers(a, 0, 1), "diagonal split owner");
    /* centre exactly on a left vertical edge: inside; on a right one: outside */
    int32_t l[6] = {8, 0, 8, 64, 40, 32};
    ZT_CHECK(zt_covers(l, 0, 1) == 1, "left edge centre");
    int32_t rr[6] = {40, 0, 40, 64, 0, 32};
    ZT_CHECK(zt_covers(rr, 2, 1) == 0, "right edge centre");
    /* horizontal top edge through centres: inside; bottom: outside */
    int32_t top[6] = {0, 8, 64, 8, 32, 60};
    ZT_CHECK(zt_covers(top, 1, 0) == 1, "top edge");
    int32_t bot[6] = {0, 40, 64, 40, 32, 0};
    ZT_CHECK(zt_covers(bot, 1, 2) == 0, "bottom edge");
    printf("test_coverage: oracle self-check 20000 triangles agree (%lu covered pixels)\n", px);
}

/* ---- the renderer against the reference ---- */

typedef struct tri_case {
    double px[3], py[3], d[3]; /* intended pixel positions and depths */
    int exact;                 /* positions given directly in 28.4 at d = 1 */
    int32_t q[3][2];           /* exact mode: 28.4 targets */
} tri_case;

static void make_case(zt_rng *g, tri_case *tc)
{
    memset(tc, 0, sizeof *tc);
    int kind = (int)zt_below(g, 10);
    double s = exp(zt_uniform(g, log(0.1), log(3.0 * W)));
    double cx = zt_uniform(g, -0.4 * W, 1.4 * W), cy = zt_uniform(g, -0.4 * H, 1.4 * H);
    if (kind < 3) { /* exact 28.4 positions on the d = 1 plane; many on centres/edges */
        tc->exact = 1;
        for (int k = 0; k < 3; k++) {
            double x = cx + s * zt_uniform(g, -1, 1), y = cy + s * zt_uniform(g, -1, 1);
            int32_t qx = (int32_t)floor(x * 16), qy = (int32_t)floor(y * 16);
            int r = (int)zt_below(g, 4);
            if (r == 0) { qx = (qx & ~15) + 8; qy = (qy & ~15) + 8; }
            if (r == 1) { qx &= ~15; qy &= ~15; }
            if (r == 2) { qx = (qx & ~15) + 8; qy &= ~15; }
            tc->q[k][0] = qx;
            tc->q[k][1] = qy;
            tc->px[k] = qx / 16.0;
            tc->py[k] = qy / 16.0;
            tc->d[k] = 1.0;
        }
        if (kind == 2) { /* a horizontal or vertical edge */
            if (zt_below(g, 2)) { tc->q[1][1] = tc->q[0][1]; tc->py[1] = tc->py[0]; }
            else { tc->q[1][0] = tc->q[0][0]; tc->px[1] = tc->px[0]; }
        }
    } else {
        double dd = exp(zt_uniform(g, log(0.6), log(12.0)));
        for (int k = 0; k < 3; k++) {
            tc->px[k] = cx + s * zt_uniform(g, -1, 1);
            tc->py[k] = cy + s * zt_uniform(g, -1, 1);
            tc->d[k] = kind < 6 ? dd : dd * exp(zt_uniform(g, -0.5, 0.5));
        }
    }
}

/* builds the single-triangle mesh; returns 0 if it is not front-facing / usable */
static void build(zt_scene *sc, const tri_case *tc)
{
    zt_scene_reset(sc);
    int v[3];
    for (int k = 0; k < 3; k++) {
        if (tc->exact) {
            /* unit_div 512, W = H = 64: pixel x = 32 + p / 16, so p = q - 512 */
            v[k] = zt_scene_vertex_world(sc, (tc->q[k][0] - 512) / 512.0,
                                         (512 - tc->q[k][1]) / 512.0, -1.0, 0);
        } else {
            v[k] = zt_scene_vertex_px(sc, tc->px[k], tc->py[k], tc->d[k], 0);
        }
    }
    zt_scene_tri_front(sc, v[0], v[1], v[2], ZS_RGB(255, 255, 255));
}

static void run_cases(zs_visibility mode, const char *mname)
{
    zt_ctx c;
    zt_ctx_init(&c, W, H, 64, 64, 64);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 4, ZS_FX(64));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 512);
    zt_recs recs = {0};
    static uint8_t img[W * H * 2];
    static uint8_t ref[W * H];
    zt_rng_seed(&g_rng, SEED);
    for (int t = 0; t < NTRIS; t++) {
        tri_case tc;
        make_case(&g_rng, &tc);
        build(&sc, &tc);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        memset(img, 0xEE, sizeof img);
        zs_status st = zt_frame(&c, &cam, mode, NULL, &m, 1, &recs, img, (t % 3 == 0) ? H : 1 + t % 5);
        g_renders++;
        ZT_CHECK(st == ZS_OK, "frame failed: %s (seed %llx tri %d)", zs_strerror(st),
                 (unsigned long long)SEED, t);
        const zs_stats *stats = zs_frame_stats(&c.r);
        if (stats->tris_clipped) g_clipped++;
        if (recs.n > 1) g_multi++;
        memset(ref, 0, sizeof ref);
        for (size_t i = 0; i < recs.n; i++) {
            const zt_rec *rc = &recs.v[i];
            ZT_CHECK(rc->tag == 1, "the only triangle of the frame has tag %u (seed %llx tri %d)",
                     rc->tag, (unsigned long long)SEED, t);
            for (int k = 0; k < 3; k++) {
                if ((rc->xy[2 * k] & 15) == 8 && (rc->xy[2 * k + 1] & 15) == 8) g_on_centre++;
                if ((rc->xy[2 * k] & 15) == 0 || (rc->xy[2 * k + 1] & 15) == 0) g_on_edge++;
            }
            int bx0, by0, bx1, by1;
            if (!zt_bbox(rc->xy, W, H, &bx0, &by0, &bx1, &by1)) continue;
            for (int y = by0; y <= by1; y++)
                for (int x = bx0; x <= bx1; x++)
                    if (zt_covers(rc->xy, x, y)) ref[y * W + x] = 1;
        }
        unsigned long cnt = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint16_t id = zt_id_at(img, W, x, y);
                int want = ref[y * W + x];
                cnt += (unsigned long)want;
                if (id != (want ? 1 : 0)) {
                    print_error("coverage mismatch (%s mode, seed %llx, tri %d) at pixel (%d,%d): "
                                "ID16 %u, reference %d\n",
                                mname, (unsigned long long)SEED, t, x, y, id, want);
                    for (size_t i = 0; i < recs.n; i++)
                        print_error("  record %zu tag %u xy28.4 = %d %d  %d %d  %d %d\n", i,
                                    recs.v[i].tag, recs.v[i].xy[0], recs.v[i].xy[1],
                                    recs.v[i].xy[2], recs.v[i].xy[3], recs.v[i].xy[4],
                                    recs.v[i].xy[5]);
                    fail();
                }
            }
        g_pixels_in += cnt;
        if (cnt == 0) g_empty++;

        /* lost triangles / transform accuracy, only for unclipped triangles that lie
         * well inside the near/far range and near the screen */
        int tame = 1;
        for (int k = 0; k < 3; k++)
            if (tc.px[k] < -2 * W || tc.px[k] > 3 * W || tc.py[k] < -2 * H || tc.py[k] > 3 * H)
                tame = 0;
        if (tame && stats->tris_clipped == 0) {
            /* our own projection of the quantised world vertices */
            int32_t mine[6];
            const zs_mesh *mm = &m;
            for (int k = 0; k < 3; k++) {
                int vi = mm->indices[k];
                double x = sc.pos[3 * vi] / 512.0, y = sc.pos[3 * vi + 1] / 512.0,
                       z = sc.pos[3 * vi + 2] / 512.0, px, py;
                zt_world_to_px(W, H, x, y, z, &px, &py);
                mine[2 * k] = (int32_t)floor(px * 16 + 0.5);
                mine[2 * k + 1] = (int32_t)floor(py * 16 + 0.5);
            }
            unsigned long mycnt = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) mycnt += (unsigned long)zt_covers(mine, x, y);
            if (mycnt >= 8)
                ZT_CHECK(recs.n > 0, "triangle lost: own projection covers %lu pixels, renderer "
                         "reported no record (seed %llx tri %d, xy %d %d %d %d %d %d)",
                         mycnt, (unsigned long long)SEED, t, mine[0], mine[1], mine[2], mine[3],
                         mine[4], mine[5]);
            if (recs.n == 1) {
                for (int k = 0; k < 3; k++) {
                    double best = 1e30;
                    for (int j = 0; j < 3; j++) {
                        double dx = recs.v[0].xy[2 * j] - mine[2 * k],
                               dy = recs.v[0].xy[2 * j + 1] - mine[2 * k + 1];
                        double dv = fabs(dx) > fabs(dy) ? fabs(dx) : fabs(dy);
                        if (dv < best) best = dv;
                    }
                    if (best > g_max_dev) g_max_dev = best;
                    ZT_CHECK(best <= 3, "snapped vertex %d is %.0f/16 px away from the test's own "
                             "projection (seed %llx tri %d)", k, best, (unsigned long long)SEED, t);
                }
            }
        }
    }
    zt_recs_free(&recs);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_span(void **state)
{
    (void)state;
    run_cases(ZS_MODE_SPAN, "span");
}

static void test_zline(void **state)
{
    (void)state;
    run_cases(ZS_MODE_ZLINE, "zline");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oracle_selfcheck),
        cmocka_unit_test(test_span),
        cmocka_unit_test(test_zline),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    printf("test_coverage: seed %llx, %d triangles x 2 modes = %lu renders on %dx%d, %lu covered "
           "pixels, %lu empty, %lu clipped, %lu split into >1 record, %lu snapped vertices on pixel "
           "centres, %lu on a pixel edge line, max vertex deviation from own projection %.0f/16 px; "
           "%d failed\n",
           (unsigned long long)SEED, NTRIS, g_renders, W, H, g_pixels_in, g_empty, g_clipped,
           g_multi, g_on_centre, g_on_edge, g_max_dev, rc);
    fflush(stdout);
    return rc;
}
