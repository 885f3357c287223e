/* SPDX-License-Identifier: MIT */
/*
 * test_tiling: meshes that tile a region exactly must cover every pixel of the
 * region exactly once (no cracks, no double hits), in both visibility modes.
 *
 *  - grids of quads (random diagonal), vertices jittered inside their cells,
 *    some snapped exactly onto pixel centres or pixel edges, boundary vertices
 *    kept on the rectangle's sides; the rectangle is random (sometimes the
 *    whole screen, sometimes partly off-screen); all vertices at one depth
 *    (the depth-1 plane with exact 28.4 placement, or another depth placed
 *    through the projection);
 *  - fans around an interior vertex of a convex polygon.
 *
 * Oracles: the half-space reference rasterizer on the hook's snapped records
 * counts the records covering each pixel centre; that count must be 1 inside
 * the region and 0 outside (region = rectangle / convex polygon from the
 * snapped vertices, top-left rule), and the ID16 image must equal the tag of
 * the unique covering record (0 outside). stats.pixels_shaded is checked
 * (span mode: width * rows; zline mode, no overlap: see check_shaded).
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 80
#define NGRID 300
#define NFAN 300
#define SEED 0x711E5EED00000007ull

static unsigned long g_meshes, g_tris, g_region_px, g_centre_v, g_edge_v, g_retries, g_renders;

static int32_t snap_kind(zt_rng *g, int32_t q, int kind)
{
    if (kind == 1) return (q & ~15) + 8; /* pixel centre */
    if (kind == 2) return q & ~15;       /* pixel edge */
    return q;
    (void)g;
}

typedef struct grid {
    int nx, ny;
    int32_t *q; /* (nx+1)*(ny+1)*2 */
    int *diag;  /* nx*ny */
} grid;

/* orientation of the 3 given 28.4 points in screen coords (y down) */
static int64_t orient(const int32_t *a, const int32_t *b, const int32_t *c)
{
    return ((int64_t)b[0] - a[0]) * ((int64_t)c[1] - a[1]) -
           ((int64_t)c[0] - a[0]) * ((int64_t)b[1] - a[1]);
}

/* orientation with a margin against a vertex moving by ~2/16 px */
static int orient_ok(const int32_t *a, const int32_t *b, const int32_t *c)
{
    int64_t o = orient(a, b, c);
    int64_t l = 0;
    const int32_t *p[3] = {a, b, c};
    for (int k = 0; k < 3; k++) {
        int64_t dx = llabs((int64_t)p[(k + 1) % 3][0] - p[k][0]);
        int64_t dy = llabs((int64_t)p[(k + 1) % 3][1] - p[k][1]);
        if (dx > l) l = dx;
        if (dy > l) l = dy;
    }
    return o > 8 * l;
}

static int grid_ok(const grid *gr)
{
    /* every triangle non-degenerate with the same orientation (y-down area > 0
     * with the ordering used below) */
    for (int j = 0; j < gr->ny; j++)
        for (int i = 0; i < gr->nx; i++) {
            const int32_t *p00 = &gr->q[2 * (j * (gr->nx + 1) + i)];
            const int32_t *p10 = &gr->q[2 * (j * (gr->nx + 1) + i + 1)];
            const int32_t *p01 = &gr->q[2 * ((j + 1) * (gr->nx + 1) + i)];
            const int32_t *p11 = &gr->q[2 * ((j + 1) * (gr->nx + 1) + i + 1)];
            if (gr->diag[j * gr->nx + i]) {
                if (!orient_ok(p00, p10, p11) || !orient_ok(p00, p11, p01)) return 0;
            } else {
                if (!orient_ok(p00, p10, p01) || !orient_ok(p10, p11, p01)) return 0;
            }
        }
    return 1;
}

static void make_grid(zt_rng *g, grid *gr, int32_t X0, int32_t Y0, int32_t X1, int32_t Y1)
{
    for (;;) {
        gr->nx = (int)zt_range(g, 1, 10);
        gr->ny = (int)zt_range(g, 1, 10);
        gr->q = realloc(gr->q, sizeof(int32_t) * 2 * (size_t)((gr->nx + 1) * (gr->ny + 1)));
        gr->diag = realloc(gr->diag, sizeof(int) * (size_t)(gr->nx * gr->ny));
        double cw = (double)(X1 - X0) / gr->nx, ch = (double)(Y1 - Y0) / gr->ny;
        double jit = zt_uniform(g, 0.0, 0.2);
        for (int j = 0; j <= gr->ny; j++)
            for (int i = 0; i <= gr->nx; i++) {
                double x = X0 + i * cw, y = Y0 + j * ch;
                int bx = (i == 0 || i == gr->nx), by = (j == 0 || j == gr->ny);
                if (!bx) x += zt_uniform(g, -jit, jit) * cw;
                if (!by) y += zt_uniform(g, -jit, jit) * ch;
                int32_t qx = i == 0 ? X0 : i == gr->nx ? X1 : (int32_t)floor(x);
                int32_t qy = j == 0 ? Y0 : j == gr->ny ? Y1 : (int32_t)floor(y);
                int kind = (int)zt_below(g, 4); /* 0 free, 1 centre, 2 edge, 3 free */
                if (!bx) qx = snap_kind(g, qx, kind);
                if (!by) qy = snap_kind(g, qy, kind == 3 ? 0 : kind);
                gr->q[2 * (j * (gr->nx + 1) + i)] = qx;
                gr->q[2 * (j * (gr->nx + 1) + i) + 1] = qy;
            }
        for (int k = 0; k < gr->nx * gr->ny; k++) gr->diag[k] = (int)zt_below(g, 2);
        if (grid_ok(gr)) return;
        g_retries++;
    }
}

/* pixels_shaded: both modes write every pixel of every row once; in zline
 * mode with no overlapping surfaces each covered pixel is depth-tested once. */
static void check_shaded(const zs_stats *st, zs_visibility mode, unsigned long region,
                         const char *what)
{
    unsigned long all = (unsigned long)W * H;
    ZT_CHECK(st->pixels_shaded == all, "%s: %s pixels_shaded %u != %lu", what,
             mode == ZS_MODE_SPAN ? "span" : "zline", st->pixels_shaded, all);
    if (mode == ZS_MODE_ZLINE)
        ZT_CHECK(st->depth_evals == region, "%s: zline depth_evals %u, expected one per covered "
                 "pixel (%lu)", what, st->depth_evals, region);
    ZT_CHECK(st->rows == H, "%s: rows %u != %d", what, st->rows, H);
}

/* Renders the scene (in one or two draws), checks count == inside and the
 * ID16 owner. inside[] gives the region membership of each pixel. */
static void check_scene(zt_ctx *c, const zs_camera *cam, zt_scene *sc, const uint8_t *inside,
                        int split, const char *what, int idx)
{
    zt_recs recs = {0};
    static uint16_t cnt[W * H];
    static uint8_t img[W * H * 2];
    zs_mesh m[2];
    int nm = 1;
    m[0] = zt_scene_mesh(sc, 1, 0);
    if (split && sc->nt > 1) {
        /* the same vertices through two draws */
        m[1] = m[0];
        uint16_t half = (uint16_t)(sc->nt / 2);
        m[0].triangle_count = half;
        m[1].indices = sc->idx + 3 * half;
        m[1].triangle_count = (uint16_t)(sc->nt - half);
        nm = 2;
    }
    unsigned long region = 0;
    for (int p = 0; p < W * H; p++) region += inside[p];
    for (int mode = 0; mode < 2; mode++) {
        memset(img, 0xCD, sizeof img);
        zs_status st = zt_frame(c, cam, (zs_visibility)mode, NULL, m, nm, &recs, img,
                                mode ? 1 + idx % 9 : H);
        g_renders++;
        ZT_CHECK(st == ZS_OK, "%s %d: frame failed %s", what, idx, zs_strerror(st));
        const zs_stats *stats = zs_frame_stats(&c->r);
        ZT_CHECK(stats->tris_culled == 0,
                 "%s %d (seed %llx): %u triangles culled in a front-facing tiling", what, idx,
                 (unsigned long long)SEED, stats->tris_culled);
        zt_coverage_count(&recs, W, H, cnt);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int p = y * W + x;
                if (cnt[p] != inside[p])
                    ZT_FAIL("%s %d (seed %llx, %s): pixel (%d,%d) covered by %u records of the "
                            "hook, expected %u",
                            what, idx, (unsigned long long)SEED, mode ? "zline" : "span", x, y,
                            cnt[p], inside[p]);
            }
        /* owner per pixel */
        for (size_t i = 0; i < recs.n; i++) {
            int bx0, by0, bx1, by1;
            const zt_rec *t = &recs.v[i];
            if (!zt_bbox(t->xy, W, H, &bx0, &by0, &bx1, &by1)) continue;
            for (int y = by0; y <= by1; y++)
                for (int x = bx0; x <= bx1; x++)
                    if (zt_covers(t->xy, x, y)) {
                        uint16_t id = zt_id_at(img, W, x, y);
                        if (id != t->tag)
                            ZT_FAIL("%s %d (seed %llx, %s): pixel (%d,%d) ID16 %u, owner tag %u "
                                    "(record xy %d %d %d %d %d %d)",
                                    what, idx, (unsigned long long)SEED,
                                    mode ? "zline" : "span", x, y, id, t->tag, t->xy[0],
                                    t->xy[1], t->xy[2], t->xy[3], t->xy[4], t->xy[5]);
                    }
        }
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (!inside[y * W + x] && zt_id_at(img, W, x, y) != 0)
                    ZT_FAIL("%s %d (%s): pixel (%d,%d) outside the region has ID %u", what, idx,
                            mode ? "zline" : "span", x, y, zt_id_at(img, W, x, y));
        check_shaded(stats, (zs_visibility)mode, region, what);
        if (mode == 0) {
            for (size_t i = 0; i < recs.n; i++)
                for (int k = 0; k < 3; k++) {
                    if ((recs.v[i].xy[2 * k] & 15) == 8 && (recs.v[i].xy[2 * k + 1] & 15) == 8)
                        g_centre_v++;
                    if ((recs.v[i].xy[2 * k] & 15) == 0 || (recs.v[i].xy[2 * k + 1] & 15) == 0)
                        g_edge_v++;
                }
        }
    }
    g_region_px += region;
    g_tris += sc->nt;
    g_meshes++;
    zt_recs_free(&recs);
}

static void test_grids(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 400, 400, 200);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 8, ZS_FX(50));
    zt_scene sc;
    grid gr = {0, 0, NULL, NULL};
    static uint8_t inside[W * H];
    for (int n = 0; n < NGRID; n++) {
        /* the rectangle (28.4) */
        int32_t X0, Y0, X1, Y1;
        int r = (int)zt_below(&g, 4);
        if (r == 0) { /* exactly the screen */
            X0 = 0; Y0 = 0; X1 = 16 * W; Y1 = 16 * H;
        } else {
            X0 = (int32_t)zt_range(&g, -16 * 30, 16 * (W - 10));
            Y0 = (int32_t)zt_range(&g, -16 * 30, 16 * (H - 10));
            X1 = X0 + (int32_t)zt_range(&g, 16 * 8, 16 * (W + 20));
            Y1 = Y0 + (int32_t)zt_range(&g, 16 * 8, 16 * (H + 20));
            if (r == 1) { X0 = (X0 & ~15) + 8; Y1 = (Y1 & ~15) + 8; } /* sides through centres */
            if (r == 2) { X1 &= ~15; Y0 &= ~15; }                     /* on pixel edges */
        }
        make_grid(&g, &gr, X0, Y0, X1, Y1);
        int exact = (n % 3) != 2;
        double depth = exact ? 1.0 : zt_uniform(&g, 0.6, 6.0);
        zt_scene_init(&sc, W, H, exact ? 8 * H : 256);
        for (int j = 0; j <= gr.ny; j++)
            for (int i = 0; i <= gr.nx; i++) {
                int32_t qx = gr.q[2 * (j * (gr.nx + 1) + i)], qy = gr.q[2 * (j * (gr.nx + 1) + i) + 1];
                if (exact)
                    zt_scene_vertex_q(&sc, qx, qy, 0);
                else
                    zt_scene_vertex_px(&sc, qx / 16.0, qy / 16.0, depth, 0);
            }
        for (int j = 0; j < gr.ny; j++)
            for (int i = 0; i < gr.nx; i++) {
                int a = j * (gr.nx + 1) + i, b = a + 1, d = a + gr.nx + 1, e = d + 1;
                /* clockwise on the y-down screen is clockwise seen by the camera:
                 * emit the reverse order (counter-clockwise = front) */
                if (gr.diag[j * gr.nx + i]) {
                    zt_scene_tri(&sc, a, e, b, 0);
                    zt_scene_tri(&sc, a, d, e, 0);
                } else {
                    zt_scene_tri(&sc, a, d, b, 0);
                    zt_scene_tri(&sc, b, d, e, 0);
                }
            }
        /* the region from the snapped corners: run a probe frame to read them */
        zt_recs probe = {0};
        static uint8_t img[W * H * 2];
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        ZT_ST(zt_frame(&c, &cam, ZS_MODE_SPAN, NULL, &m, 1, &probe, img, H), ZS_OK);
        int32_t mnx = INT32_MAX, mny = INT32_MAX, mxx = INT32_MIN, mxy = INT32_MIN;
        for (size_t i = 0; i < probe.n; i++)
            for (int k = 0; k < 3; k++) {
                int32_t x = probe.v[i].xy[2 * k], y = probe.v[i].xy[2 * k + 1];
                if (x < mnx) mnx = x;
                if (x > mxx) mxx = x;
                if (y < mny) mny = y;
                if (y > mxy) mxy = y;
            }
        if (exact) {
            /* exact placement: every snapped vertex is one of the placed ones,
             * and the region is the intended rectangle */
            if (zs_frame_stats(&c.r)->tris_clipped == 0) {
                for (size_t i = 0; i < probe.n; i++)
                    for (int k = 0; k < 3; k++) {
                        int32_t x = probe.v[i].xy[2 * k], y = probe.v[i].xy[2 * k + 1];
                        int found = 0;
                        for (int v = 0; v < (gr.nx + 1) * (gr.ny + 1) && !found; v++)
                            found = gr.q[2 * v] == x && gr.q[2 * v + 1] == y;
                        ZT_CHECK(found, "grid %d: snapped vertex (%d,%d) is not a placed 28.4 "
                                 "position (exact placement through the projection)", n, x, y);
                    }
            }
            mnx = X0;
            mxx = X1;
            mny = Y0;
            mxy = Y1;
        }
        zt_recs_free(&probe);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int64_t cx = 16 * x + 8, cy = 16 * y + 8;
                inside[y * W + x] = (uint8_t)(mnx <= cx && cx < mxx && mny <= cy && cy < mxy);
            }
        check_scene(&c, &cam, &sc, inside, n % 2, "grid", n);
        zt_scene_free(&sc);
    }
    free(gr.q);
    free(gr.diag);
    zt_ctx_free(&c);
}

/* convex polygon membership with the top-left rule, polygon given clockwise
 * on screen (y down), 28.4 */
static int poly_inside(const int32_t *q, int n, int px, int py)
{
    int64_t cx = 16 * (int64_t)px + 8, cy = 16 * (int64_t)py + 8;
    for (int k = 0; k < n; k++) {
        int64_t ax = q[2 * k], ay = q[2 * k + 1];
        int64_t bx = q[2 * ((k + 1) % n)], by = q[2 * ((k + 1) % n) + 1];
        int64_t dx = bx - ax, dy = by - ay;
        int64_t e = dx * (cy - ay) - dy * (cx - ax); /* > 0 inside for clockwise-on-screen */
        if (e < 0) return 0;
        if (e == 0 && !(-dy > 0 || (dy == 0 && dx > 0))) return 0;
    }
    return 1;
}

static void test_fans(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xFA11);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 64, 64, 64);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 8, ZS_FX(50));
    zt_scene sc;
    static uint8_t inside[W * H];
    int32_t q[2 * 17];
    for (int n = 0; n < NFAN; n++) {
        int nv;
        int32_t ctr[2];
        for (;;) {
            nv = (int)zt_range(&g, 3, 16);
            double cx = zt_uniform(&g, -10, W + 10), cy = zt_uniform(&g, -10, H + 10);
            double rx = zt_uniform(&g, 6, 70), ry = rx * zt_uniform(&g, 0.5, 1.5);
            double ph = zt_uniform(&g, 0, 6.283185307179586);
            for (int k = 0; k < nv; k++) {
                /* clockwise on screen: increasing angle with y down */
                double a = ph + 6.283185307179586 * (k + zt_uniform(&g, -0.3, 0.3)) / nv;
                int32_t qx = (int32_t)floor((cx + rx * cos(a)) * 16);
                int32_t qy = (int32_t)floor((cy + ry * sin(a)) * 16);
                int kind = (int)zt_below(&g, 3);
                q[2 * k] = snap_kind(&g, qx, kind);
                q[2 * k + 1] = snap_kind(&g, qy, kind);
            }
            /* the interior vertex: a random convex combination, maybe on a centre */
            double wsum = 0, fx = 0, fy = 0;
            for (int k = 0; k < nv; k++) {
                double wgt = zt_uniform(&g, 0.2, 1.0);
                wsum += wgt;
                fx += wgt * q[2 * k];
                fy += wgt * q[2 * k + 1];
            }
            int kind = (int)zt_below(&g, 3);
            ctr[0] = snap_kind(&g, (int32_t)floor(fx / wsum), kind);
            ctr[1] = snap_kind(&g, (int32_t)floor(fy / wsum), kind);
            /* strictly convex boundary and every fan triangle properly oriented */
            int ok = 1;
            for (int k = 0; k < nv && ok; k++) {
                const int32_t *a = &q[2 * k], *b = &q[2 * ((k + 1) % nv)],
                              *d = &q[2 * ((k + 2) % nv)];
                if (orient(a, b, d) <= 0) ok = 0;
                if (!orient_ok(ctr, a, b)) ok = 0;
            }
            if (ok) break;
            g_retries++;
        }
        zt_scene_init(&sc, W, H, 8 * H);
        int vc = zt_scene_vertex_q(&sc, ctr[0], ctr[1], 0);
        for (int k = 0; k < nv; k++) zt_scene_vertex_q(&sc, q[2 * k], q[2 * k + 1], 0);
        /* (centre, k, k+1) is clockwise on the y-down screen: emit it reversed */
        for (int k = 0; k < nv; k++) zt_scene_tri(&sc, vc, vc + 1 + (k + 1) % nv, vc + 1 + k, 0);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) inside[y * W + x] = (uint8_t)poly_inside(q, nv, x, y);
        check_scene(&c, &cam, &sc, inside, n % 2, "fan", n);
        zt_scene_free(&sc);
    }
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grids),
        cmocka_unit_test(test_fans),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    printf("test_tiling: seed %llx, %lu meshes (%d grids, %d fans), %lu triangles, %lu renders, "
           "%lu region pixels each covered exactly once, %lu snapped vertices on pixel centres, "
           "%lu on pixel edge lines, %lu regenerated layouts; %d failed\n",
           (unsigned long long)SEED, g_meshes, NGRID, NFAN, g_tris, g_renders, g_region_px,
           g_centre_v, g_edge_v, g_retries, rc);
    fflush(stdout);
    return rc;
}
