/* SPDX-License-Identifier: MIT */
/*
 * test_hlines: the vector hidden-line drawing of app/zs_hlines.c (zspan-sim
 * render --svg-lines) against dense sampling with a ray caster.
 *
 * Random scenes of closed and open meshes (boxes, faceted spheres, prisms,
 * folded sheets), each its own group, placed so that they occlude each other
 * without cutting into each other, some crossing the near plane; and scenes
 * of closed meshes that cut into one another, where the lines the meshes
 * meet along are drawn too. The test finds the feature edges itself (by
 * brute force over the triangles), and the meeting lines (each front face
 * of one group cut by the plane of each of another's, the piece clipped to
 * that triangle), and samples each every 1/64 px on screen; each sample is
 * ray cast against every front face. Then:
 *  - a visible sample lies on an output segment, unless it is within 1/16 px
 *    of a visibility change along its edge;
 *  - a hidden sample lies on no output segment, except within 1/16 px of the
 *    segment's end;
 * so every segment end is within 1/16 px of the exact visible interval.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "zs_hlines.h"

#define W 200
#define H 150
#define PI 3.14159265358979323846
#define TOL (1.0 / 16)
#define STEP (1.0 / 64)
#define NEAR 0.5
#define CELL 4
#define NCUT 6 /* scenes of meshes cutting into one another */
#define FEAT_CAP (4 * 12000)

static uint64_t rs;
static double urand(void)
{
    rs = rs * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rs >> 11) / 9007199254740992.0;
}
static double uni(double a, double b) { return a + (b - a) * urand(); }

typedef struct scene {
    double pos[3 * 8000];
    uint32_t idx[3 * 12000];
    int group[12000];
    size_t nv, nt;
} scene;

static uint32_t vtx(scene *s, double x, double y, double z)
{
    s->pos[3 * s->nv] = x;
    s->pos[3 * s->nv + 1] = y;
    s->pos[3 * s->nv + 2] = z;
    return (uint32_t)s->nv++;
}

static void tri(scene *s, uint32_t a, uint32_t b, uint32_t c, int g)
{
    s->idx[3 * s->nt] = a;
    s->idx[3 * s->nt + 1] = b;
    s->idx[3 * s->nt + 2] = c;
    s->group[s->nt] = g;
    s->nt++;
}

/* One mesh in model space, then rotated and moved to (cx, cy, cz). */
static void add_mesh(scene *s, int kind, int g, double cx, double cy, double cz)
{
    size_t v0 = s->nv;
    if (kind == 0) { /* box */
        double a = uni(0.3, 1), b = uni(0.3, 1), c = uni(0.3, 1);
        for (int i = 0; i < 8; i++) vtx(s, (i & 1) ? a : -a, (i & 2) ? b : -b, (i & 4) ? c : -c);
        static const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int k = 0; k < 6; k++) {
            tri(s, (uint32_t)v0 + f[k][0], (uint32_t)v0 + f[k][1], (uint32_t)v0 + f[k][2], g);
            tri(s, (uint32_t)v0 + f[k][0], (uint32_t)v0 + f[k][2], (uint32_t)v0 + f[k][3], g);
        }
    } else if (kind == 1) { /* sphere 12 x 8 */
        int sl = 12, st = 8;
        uint32_t top = vtx(s, 0, 1, 0);
        for (int i = 1; i < st; i++)
            for (int j = 0; j < sl; j++) {
                double th = PI * i / st, ph = 2 * PI * j / sl;
                vtx(s, sin(th) * cos(ph), cos(th), -sin(th) * sin(ph));
            }
        uint32_t bot = vtx(s, 0, -1, 0);
#define RING(i, j) (top + 1 + (uint32_t)(((i) - 1) * sl + ((j) % sl)))
        for (int j = 0; j < sl; j++) {
            tri(s, top, RING(1, j), RING(1, j + 1), g);
            tri(s, bot, RING(st - 1, j + 1), RING(st - 1, j), g);
            for (int i = 1; i + 1 < st; i++) {
                tri(s, RING(i, j), RING(i + 1, j), RING(i + 1, j + 1), g);
                tri(s, RING(i, j), RING(i + 1, j + 1), RING(i, j + 1), g);
            }
        }
#undef RING
    } else if (kind == 2) { /* prism */
        for (int k = 0; k < 2; k++)
            for (int i = 0; i < 3; i++)
                vtx(s, 0.8 * cos(2 * PI * i / 3), 0.8 * sin(2 * PI * i / 3), k ? 1 : -1);
        uint32_t b = (uint32_t)v0;
        tri(s, b, b + 2, b + 1, g);
        tri(s, b + 3, b + 4, b + 5, g);
        for (uint32_t i = 0; i < 3; i++) {
            uint32_t j = (i + 1) % 3;
            tri(s, b + i, b + j, b + 3 + j, g);
            tri(s, b + i, b + 3 + j, b + 3 + i, g);
        }
    } else { /* folded sheet */
        int n = 4;
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++) {
                double x = 2.0 * i / n - 1, y = 2.0 * j / n - 1;
                vtx(s, x, y, i <= n / 2 ? 0 : -0.9 * x);
            }
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                uint32_t a = (uint32_t)v0 + (uint32_t)(j * (n + 1) + i);
                tri(s, a, a + 1, a + (uint32_t)n + 2, g);
                tri(s, a, a + (uint32_t)n + 2, a + (uint32_t)n + 1, g);
            }
    }
    double ax = uni(0, 2 * PI), ay = uni(0, 2 * PI);
    for (size_t i = v0; i < s->nv; i++) {
        double *p = s->pos + 3 * i, x = p[0], y = p[1], z = p[2];
        double y1 = y * cos(ax) - z * sin(ax), z1 = y * sin(ax) + z * cos(ax);
        double x2 = x * cos(ay) + z1 * sin(ay), z2 = -x * sin(ay) + z1 * cos(ay);
        p[0] = x2 + cx;
        p[1] = y1 + cy;
        p[2] = z2 + cz;
    }
}

static void random_scene(scene *s, int k)
{
    double c[6][3];
    int n = 3 + k % 3;
    s->nv = s->nt = 0;
    for (int d = 0; d < n; d++) {
        for (int tries = 0; tries < 300; tries++) {
            c[d][2] = -uni(k % 4 == 0 ? 1.0 : 3.5, 9);
            c[d][0] = uni(-0.6, 0.6) * -c[d][2];
            c[d][1] = uni(-0.45, 0.45) * -c[d][2];
            int ok = 1;
            for (int e = 0; e < d; e++) {
                double dx = c[d][0] - c[e][0], dy = c[d][1] - c[e][1], dz = c[d][2] - c[e][2];
                if (sqrt(dx * dx + dy * dy + dz * dz) < 2 * 1.8) ok = 0;
            }
            if (ok) break;
        }
        add_mesh(s, (int)(urand() * 4), d, c[d][0], c[d][1], c[d][2]);
    }
}

/* Two to four closed meshes, each overlapping the one before by about a
 * third of its size. */
static void cutting_scene(scene *s)
{
    double c[3] = {uni(-1, 1), uni(-1, 1), -uni(5, 7)};
    int n = 2 + (int)(urand() * 3);
    s->nv = s->nt = 0;
    for (int d = 0; d < n; d++) {
        if (d > 0) {
            double a = uni(0, 2 * PI), b = uni(-0.6, 0.6), r = uni(1.0, 1.4);
            c[0] += r * cos(a) * cos(b);
            c[1] += r * sin(a) * cos(b);
            c[2] += r * sin(b);
        }
        add_mesh(s, (int)(urand() * 3), d, c[0], c[1], c[2]);
    }
}

/* ---- the oracle ---- */

static void sub(const double *a, const double *b, double *o)
{
    for (int k = 0; k < 3; k++) o[k] = a[k] - b[k];
}
static void crs(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static double dt(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void nrm(const scene *s, size_t t, double *n)
{
    const double *a = s->pos + 3 * s->idx[3 * t], *b = s->pos + 3 * s->idx[3 * t + 1],
                 *c = s->pos + 3 * s->idx[3 * t + 2];
    double u[3], v[3];
    sub(b, a, u);
    sub(c, a, v);
    crs(u, v, n);
    double l = sqrt(dt(n, n));
    for (int k = 0; k < 3; k++) n[k] /= l;
}

static int front(const scene *s, size_t t)
{
    double n[3];
    nrm(s, t, n);
    return -dt(n, s->pos + 3 * s->idx[3 * t]) > 0;
}

/* Ray from the eye through P: does triangle t hit it nearer than P? */
static int hides(const scene *s, size_t t, const double *P)
{
    const double *p0 = s->pos + 3 * s->idx[3 * t], *p1 = s->pos + 3 * s->idx[3 * t + 1],
                 *p2 = s->pos + 3 * s->idx[3 * t + 2];
    double e1[3], e2[3], h[3], q[3], o[3];
    sub(p1, p0, e1);
    sub(p2, p0, e2);
    crs(P, e2, h);
    double a = dt(e1, h);
    if (fabs(a) < 1e-18) return 0;
    double f = 1 / a;
    for (int k = 0; k < 3; k++) o[k] = -p0[k];
    double u = f * dt(o, h);
    if (u < 0 || u > 1) return 0;
    crs(o, e1, q);
    double v = f * dt(P, q);
    if (v < 0 || u + v > 1) return 0;
    double tt = f * dt(e2, q);
    /* between the eye and P, and beyond the near plane (nearer is clipped away) */
    return tt > 1e-9 && tt < 1 - 1e-9 && tt * -P[2] >= NEAR;
}

/* Where front faces t and u meet: t's edges cut by u's plane give a
 * segment in that plane, clipped to u by u's edges' inward normals. */
static int meeting(const scene *s, size_t t, size_t u, double *A, double *B)
{
    const double *q[3], *p[3];
    double nu[3], d[3], P[2][3];
    int np = 0;
    for (int k = 0; k < 3; k++) {
        p[k] = s->pos + 3 * s->idx[3 * t + k];
        q[k] = s->pos + 3 * s->idx[3 * u + k];
    }
    nrm(s, u, nu);
    for (int k = 0; k < 3; k++) {
        double w[3];
        sub(p[k], q[0], w);
        d[k] = dt(w, nu);
    }
    for (int k = 0; k < 3 && np < 2; k++) {
        int j = (k + 1) % 3;
        if ((d[k] > 0) == (d[j] > 0)) continue;
        double f = d[k] / (d[k] - d[j]);
        for (int c = 0; c < 3; c++) P[np][c] = p[k][c] + f * (p[j][c] - p[k][c]);
        np++;
    }
    if (np < 2) return 0;
    double lo = 0, hi = 1, D[3];
    sub(P[1], P[0], D);
    for (int k = 0; k < 3; k++) {
        double e[3], in[3], w[3];
        sub(q[(k + 1) % 3], q[k], e);
        crs(nu, e, in); /* points into u */
        sub(P[0], q[k], w);
        double a = dt(in, w), b = dt(in, D); /* inside where a + b t >= 0 */
        if (b == 0) {
            if (a < 0) return 0;
        } else if (b > 0) {
            if (-a / b > lo) lo = -a / b;
        } else if (-a / b < hi) {
            hi = -a / b;
        }
    }
    if (hi - lo < 1e-9) return 0;
    for (int c = 0; c < 3; c++) {
        A[c] = P[0][c] + lo * D[c];
        B[c] = P[0][c] + hi * D[c];
    }
    return 1;
}

typedef struct feat {
    double A[3], B[3];
    size_t i;
    long other;
    uint32_t a, b;
} feat;

/* distance from (x, y) to the segment and the parameter of the foot */
static double seg_dist(const zs_hl_seg *g, double x, double y, double *endd)
{
    double dx = g->x1 - g->x0, dy = g->y1 - g->y0, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - g->x0) * dx + (y - g->y0) * dy) / l2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    double fx = g->x0 + t * dx - x, fy = g->y0 + t * dy - y;
    double d0 = hypot(x - g->x0, y - g->y0), d1 = hypot(x - g->x1, y - g->y1);
    *endd = d0 < d1 ? d0 : d1;
    return hypot(fx, fy);
}

static void test_vs_raycast(void **state)
{
    (void)state;
    scene *s = malloc(sizeof *s);
    zs_hl_view v = {W, H, 60.0, NEAR, 30.0};
    /* segments by grid cell, to find the ones near a sample */
    enum { GW = W / CELL + 2, GH = H / CELL + 2 };
    size_t *cell_n = malloc(GW * GH * sizeof *cell_n), *cell_cap = malloc(GW * GH * sizeof *cell_cap);
    size_t **cell = malloc(GW * GH * sizeof *cell);
    for (int c = 0; c < GW * GH; c++) { cell_n[c] = cell_cap[c] = 0; cell[c] = NULL; }
    long samples = 0, vis_total = 0, checked_ends = 0;
    double worst_end = 0;
    rs = 0x5EED0016;
    feat *fl = malloc(FEAT_CAP * sizeof *fl);
    long meeting_total = 0;
    for (int k = 0; k < 16 + NCUT; k++) {
        if (k < 16)
            random_scene(s, k);
        else
            cutting_scene(s);
        zs_hl_result r;
        assert_int_equal(zs_hl_compute(&v, s->pos, s->nv, s->idx, s->group, s->nt, &r), 0);
        assert_true(r.n > 10);
        for (int c = 0; c < GW * GH; c++) cell_n[c] = 0;
        for (size_t g = 0; g < r.n; g++) {
            const zs_hl_seg *q = &r.seg[g];
            int x0 = (int)floor((fmin(q->x0, q->x1) - 0.5) / CELL), x1 = (int)floor((fmax(q->x0, q->x1) + 0.5) / CELL);
            int y0 = (int)floor((fmin(q->y0, q->y1) - 0.5) / CELL), y1 = (int)floor((fmax(q->y0, q->y1) + 0.5) / CELL);
            for (int cy = y0 < 0 ? 0 : y0; cy <= y1 && cy < GH; cy++)
                for (int cx = x0 < 0 ? 0 : x0; cx <= x1 && cx < GW; cx++) {
                    int c = cy * GW + cx;
                    if (cell_n[c] == cell_cap[c]) {
                        cell_cap[c] = cell_cap[c] ? 2 * cell_cap[c] : 8;
                        cell[c] = realloc(cell[c], cell_cap[c] * sizeof **cell);
                    }
                    cell[c][cell_n[c]++] = g;
                }
        }
        /* brute-force feature edges, then the meeting lines */
        size_t nfl = 0;
        for (size_t i = 0; i < s->nt; i++)
            for (int e = 0; e < 3; e++) {
                uint32_t a = s->idx[3 * i + e], b = s->idx[3 * i + (e + 1) % 3];
                long other = -1;
                for (size_t j = 0; j < s->nt && other < 0; j++)
                    for (int f = 0; f < 3; f++)
                        if (s->idx[3 * j + f] == b && s->idx[3 * j + (f + 1) % 3] == a)
                            other = (long)j;
                if (other >= 0 && (size_t)other < i) continue;
                int fi = front(s, i), fo = other >= 0 ? front(s, (size_t)other) : 0, feat;
                if (other < 0) feat = fi;
                else if (fi != fo) feat = 1;
                else if (fi) {
                    double n1[3], n2[3];
                    nrm(s, i, n1);
                    nrm(s, (size_t)other, n2);
                    feat = dt(n1, n2) < cos(30 * PI / 180);
                } else feat = 0;
                if (!feat || nfl == FEAT_CAP) continue;
                memcpy(fl[nfl].A, s->pos + 3 * a, sizeof fl[nfl].A);
                memcpy(fl[nfl].B, s->pos + 3 * b, sizeof fl[nfl].B);
                fl[nfl].i = i;
                fl[nfl].other = other;
                fl[nfl].a = a;
                fl[nfl].b = b;
                nfl++;
            }
        size_t nedges = nfl;
        for (size_t i = 0; i < s->nt; i++)
            for (size_t j = 0; j < s->nt; j++) {
                if (nfl == FEAT_CAP || s->group[i] == s->group[j] || !front(s, i) || !front(s, j) ||
                    !meeting(s, i, j, fl[nfl].A, fl[nfl].B))
                    continue;
                fl[nfl].i = i;
                fl[nfl].other = (long)j;
                fl[nfl].a = (uint32_t)i;
                fl[nfl].b = (uint32_t)j;
                nfl++;
            }
        meeting_total += nfl - nedges;
        for (size_t fk = 0; fk < nfl; fk++) {
            {
                size_t i = fl[fk].i;
                long other = fl[fk].other;
                uint32_t a = fl[fk].a, b = fl[fk].b;
                double A[3], B[3], ax, ay, bx, by;
                memcpy(A, fl[fk].A, sizeof A);
                memcpy(B, fl[fk].B, sizeof B);
                if (A[2] > -v.near_z && B[2] > -v.near_z) continue;
                if (A[2] > -v.near_z || B[2] > -v.near_z) { /* cut at the near plane */
                    double *in = A[2] > -v.near_z ? A : B, *o = in == A ? B : A;
                    double t = (-v.near_z - o[2]) / (in[2] - o[2]);
                    for (int c = 0; c < 3; c++) in[c] = o[c] + t * (in[c] - o[c]);
                }
                zs_hl_project(&v, A, &ax, &ay);
                zs_hl_project(&v, B, &bx, &by);
                double len = hypot(bx - ax, by - ay);
                int n = (int)ceil(len / STEP) + 1;
                /* visibility of every sample first, then the checks */
                uint8_t *vis = malloc((size_t)n + 1);
                double *sx = malloc(((size_t)n + 1) * sizeof *sx), *sy = malloc(((size_t)n + 1) * sizeof *sy);
                uint8_t *in_scr = malloc((size_t)n + 1);
                for (int q = 0; q <= n; q++) {
                    double u = (double)q / n;
                    sx[q] = ax + u * (bx - ax);
                    sy[q] = ay + u * (by - ay);
                    in_scr[q] = sx[q] >= 0 && sy[q] >= 0 && sx[q] <= W && sy[q] <= H;
                    double wa = -A[2], wb = -B[2], t = u * wa / (u * wa + (1 - u) * wb), P[3];
                    for (int c = 0; c < 3; c++) P[c] = A[c] + t * (B[c] - A[c]);
                    vis[q] = 1;
                    for (size_t tt = 0; tt < s->nt && vis[q]; tt++) {
                        if (tt == i || (long)tt == other || !front(s, tt)) continue;
                        /* only the part of a face in front of the near plane hides */
                        if (hides(s, tt, P)) {
                            /* the hit point's depth must be beyond the near plane */
                            vis[q] = 0;
                        }
                    }
                }
                for (int q = 0; q <= n; q++) {
                    if (!in_scr[q]) continue;
                    /* distance along the edge to the nearest visibility change */
                    double change = 1e9;
                    for (int d = 1; d * STEP <= 2 * TOL && change > 1e8; d++) {
                        if ((q - d >= 0 && vis[q - d] != vis[q]) || (q + d <= n && vis[q + d] != vis[q]))
                            change = d * STEP * len / (len > 0 ? len : 1);
                    }
                    double best = 1e9, best_end = 1e9;
                    int cx = (int)floor(sx[q] / CELL), cy = (int)floor(sy[q] / CELL);
                    if (cx >= 0 && cy >= 0 && cx < GW && cy < GH) {
                        int c = cy * GW + cx;
                        for (size_t m = 0; m < cell_n[c]; m++) {
                            double ed, dd = seg_dist(&r.seg[cell[c][m]], sx[q], sy[q], &ed);
                            if (dd < best) { best = dd; best_end = ed; }
                        }
                    }
                    samples++;
                    if (vis[q]) {
                        vis_total++;
                        if (best > 1e-6 && change > TOL && sx[q] > TOL && sy[q] > TOL &&
                            sx[q] < W - TOL && sy[q] < H - TOL)
                            fail_msg("scene %d: visible sample (%.4f,%.4f) of edge %u-%u on no "
                                     "segment (%.2g px away)", k, sx[q], sy[q], a, b, best);
                    } else if (best < 1e-6) {
                        checked_ends++;
                        if (best_end > worst_end) worst_end = best_end;
                        if (best_end > TOL)
                            fail_msg("scene %d: hidden sample (%.4f,%.4f) of edge %u-%u on a "
                                     "segment, %.4f px from its end", k, sx[q], sy[q], a, b,
                                     best_end);
                    }
                }
                free(vis); free(sx); free(sy); free(in_scr);
            }
        }
        zs_hl_free(&r);
    }
    print_message("hlines: 16 scenes and %d of meshes cutting into one another (%ld meeting "
                  "segments), %ld edge samples (%ld visible) every 1/64 px; hidden samples on a "
                  "segment: %ld, at most %.4f px from its end\n",
                  NCUT, meeting_total, samples, vis_total, checked_ends, worst_end);
    free(fl);
    for (int c = 0; c < GW * GH; c++) free(cell[c]);
    free(cell); free(cell_n); free(cell_cap);
    free(s);
}

static void test_svg(void **state)
{
    (void)state;
    zs_hl_view v = {64, 48, 60.0, NEAR, 30.0};
    zs_hl_result r = {0};
    zs_hl_seg g = {1.5, 2.25, 30, 40};
    r.seg = &g;
    r.n = 1;
    assert_int_equal(zs_hl_write_svg("out/test_hlines.svg", &v, &r), 0);
    FILE *f = fopen("out/test_hlines.svg", "r");
    char buf[2048];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    assert_non_null(strstr(buf, "shape-rendering=\"crispEdges\""));
    assert_non_null(strstr(buf, "<line x1=\"1.5000\" y1=\"2.2500\" x2=\"30.0000\" y2=\"40.0000\"/>"));
    assert_int_equal(zs_hl_write_svg("/nonexistent/dir/x.svg", &v, &r), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vs_raycast),
        cmocka_unit_test(test_svg),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
