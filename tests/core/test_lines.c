/* SPDX-License-Identifier: MIT */
/* LIBS: -lassimp */
/*
 * test_lines: hidden-line drawing (ZS_MONO_LINES) against an oracle that
 * knows nothing of the core's method.
 *
 * The oracle works in double precision from the meshes and model matrices
 * the test draws: every mesh edge is classified by its faces (front or back
 * from the world-space geometry and the eye): a boundary edge of a front
 * face, a silhouette (one face front, one back), a crease (both front, the
 * normals more than the crease angle apart). The scenes are closed meshes (cubes, spheres, a prism) and an open one (a
 * folded sheet), each its own draw call, placed so they occlude each other
 * without interpenetrating, so the visible edges are exactly the drawing's
 * lines.
 *
 * Each feature edge is sampled every 1/10 px on screen and each sample is
 * ray cast against every front face (visible when nothing but the edge's
 * own faces is nearer); where
 * visibility changes between two samples the change is found by bisection
 * to 1/1000 px, so the visible pieces of the edges are known as segments.
 *
 * Checked on every scene, in both visibility modes and both 1-bit layouts:
 *  - every drawn pixel is within 1 px (Chebyshev distance from its centre)
 *    of a visible piece of a feature edge; the largest distance is printed.
 *    Hidden edges are never drawn: a pixel near only hidden pieces fails;
 *  - at least 98% of the visible samples (so of the visible length) have a
 *    drawn pixel within 1 px: on every scene, random ones (some hold a
 *    sheet seen edge-on or a sharp corner's tip, thinner than a pixel) and
 *    model views alike;
 *  - span == zline, page == MSB layouts, and any band height give the same
 *    drawing.
 * The same on models of Debian's assimp-testmodels (each turned three ways,
 * with a box beside it), where the files are installed, and on scenes whose
 * objects cut into one another (each its own draw): there the lines where
 * two draws' surfaces meet are features too, and the oracle finds them by
 * intersecting every pair of front faces of two draws (the segment both
 * triangles share), sampled and ray cast like the edges.
 * ZT_LINES_SURVEY=1 prints every scene's figures and only counts failures;
 * ZT_LINES_DUMP=1 writes out/lines_N.ppm; ZT_LINES_PROBE=scene,x,y prints
 * the triangles around a pixel.
 */
#include "zt_test.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120
#define NSCENES 60
/* scenes whose objects cut into one another */
#define NCUTTING 12
#define CREASE 30
/* the bound: within 1 px of a visible edge */
#define TOL 1.0
/* ZT_LINES_SURVEY=1: the figures of every scene, the checks only counted */
static int g_survey, g_survey_fails;
#define LCHECK(cond, ...)                                                        \
    do {                                                                         \
        if (g_survey) {                                                          \
            if (!(cond)) {                                                       \
                g_survey_fails++;                                                \
                print_message(__VA_ARGS__);                                      \
                print_message("\n");                                             \
            }                                                                    \
        } else {                                                                 \
            ZT_CHECK(cond, __VA_ARGS__);                                         \
        }                                                                        \
    } while (0)
#define SEED 0x11AE500000000016ull
#define PI 3.14159265358979323846

typedef struct mesh_b {
    int16_t *pos;   /* 3 per vertex (mesh_alloc) */
    uint16_t *idx;  /* 3 per triangle */
    int nv, nt;
    zs_fixed scale;
} mesh_b;

static void mesh_alloc(mesh_b *m, size_t nv, size_t nt)
{
    m->pos = calloc(3 * nv, sizeof *m->pos);
    m->idx = calloc(3 * nt, sizeof *m->idx);
    m->nv = m->nt = 0;
}

static void mesh_release(mesh_b *m)
{
    free(m->pos);
    free(m->idx);
    m->pos = NULL;
    m->idx = NULL;
}

static int add_v(mesh_b *m, double x, double y, double z)
{
    m->pos[3 * m->nv] = (int16_t)lround(x * 8192);
    m->pos[3 * m->nv + 1] = (int16_t)lround(y * 8192);
    m->pos[3 * m->nv + 2] = (int16_t)lround(z * 8192);
    return m->nv++;
}

static void add_t(mesh_b *m, int a, int b, int c)
{
    m->idx[3 * m->nt] = (uint16_t)a;
    m->idx[3 * m->nt + 1] = (uint16_t)b;
    m->idx[3 * m->nt + 2] = (uint16_t)c;
    m->nt++;
}

/* unit cube [-1,1]^3 scaled by s (s <= 3.9), outward counter-clockwise faces */
static void make_box(mesh_b *m, double sx, double sy, double sz)
{
    m->nv = m->nt = 0;
    m->scale = ZS_FX(1) / 8192;
    for (int i = 0; i < 8; i++)
        add_v(m, (i & 1) ? sx : -sx, (i & 2) ? sy : -sy, (i & 4) ? sz : -sz);
    static const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int k = 0; k < 6; k++) {
        add_t(m, f[k][0], f[k][1], f[k][2]);
        add_t(m, f[k][0], f[k][2], f[k][3]);
    }
}

static void make_sphere(mesh_b *m, double r, int slices, int stacks)
{
    m->nv = m->nt = 0;
    m->scale = ZS_FX(1) / 8192;
    int top = add_v(m, 0, r, 0);
    for (int i = 1; i < stacks; i++) {
        double th = PI * i / stacks;
        for (int j = 0; j < slices; j++) {
            double ph = 2 * PI * j / slices;
            add_v(m, r * sin(th) * cos(ph), r * cos(th), -r * sin(th) * sin(ph));
        }
    }
    int bot = add_v(m, 0, -r, 0);
#define RING(i, j) (1 + ((i) - 1) * slices + ((j) % slices))
    for (int j = 0; j < slices; j++) {
        add_t(m, top, RING(1, j), RING(1, j + 1));
        add_t(m, bot, RING(stacks - 1, j + 1), RING(stacks - 1, j));
        for (int i = 1; i + 1 < stacks; i++) {
            add_t(m, RING(i, j), RING(i + 1, j), RING(i + 1, j + 1));
            add_t(m, RING(i, j), RING(i + 1, j + 1), RING(i, j + 1));
        }
    }
#undef RING
}

/* a triangular prism (creases of 60 and 90 degrees) */
static void make_prism(mesh_b *m, double r, double len)
{
    m->nv = m->nt = 0;
    m->scale = ZS_FX(1) / 8192;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 3; i++) {
            double a = 2 * PI * i / 3;
            add_v(m, r * cos(a), r * sin(a), k ? len : -len);
        }
    add_t(m, 0, 2, 1);
    add_t(m, 3, 4, 5);
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        add_t(m, i, j, 3 + j);
        add_t(m, i, 3 + j, 3 + i);
    }
}

/* an open sheet folded once (boundary edges, one crease), both sides drawn
 * as one-sided front faces toward +z */
static void make_sheet(mesh_b *m, double s)
{
    m->nv = m->nt = 0;
    m->scale = ZS_FX(1) / 8192;
    int n = 6;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = s * (2.0 * i / n - 1), y = s * (2.0 * j / n - 1);
            double z = i <= n / 2 ? 0 : -(x) * 0.9; /* the fold at x = 0 */
            add_v(m, x, y, z);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i;
            add_t(m, a, a + 1, a + n + 2);
            add_t(m, a, a + n + 2, a + n + 1);
        }
}

/* ---- the double-precision oracle ---- */

typedef struct wtri {
    double p[3][3];   /* world */
    double n[3];      /* unit normal */
    int front;
    int draw, index;  /* which draw, which triangle of it */
} wtri;

typedef struct scene {
    mesh_b meshes[6];
    zs_mat34 model[6];
    int nmesh;
    wtri *t;
    int nt;
} scene;

static void world_of(const mesh_b *m, const zs_mat34 *M, int v, double out[3])
{
    double p[3];
    for (int k = 0; k < 3; k++) p[k] = m->pos[3 * v + k] * (m->scale / 65536.0);
    for (int r = 0; r < 3; r++)
        out[r] = (M->m[r][0] * p[0] + M->m[r][1] * p[1] + M->m[r][2] * p[2] + M->m[r][3]) /
                 65536.0;
}

static void sub3(const double a[3], const double b[3], double o[3])
{
    for (int k = 0; k < 3; k++) o[k] = a[k] - b[k];
}
static void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void build_world(scene *s)
{
    s->nt = 0;
    for (int d = 0; d < s->nmesh; d++) s->nt += s->meshes[d].nt;
    s->t = calloc((size_t)s->nt, sizeof *s->t);
    int k = 0;
    for (int d = 0; d < s->nmesh; d++) {
        const mesh_b *m = &s->meshes[d];
        for (int i = 0; i < m->nt; i++, k++) {
            wtri *t = &s->t[k];
            for (int j = 0; j < 3; j++) world_of(m, &s->model[d], m->idx[3 * i + j], t->p[j]);
            double e1[3], e2[3], eye[3];
            sub3(t->p[1], t->p[0], e1);
            sub3(t->p[2], t->p[0], e2);
            cross(e1, e2, t->n);
            double l = sqrt(dot(t->n, t->n));
            for (int j = 0; j < 3; j++) t->n[j] /= l;
            for (int j = 0; j < 3; j++) eye[j] = -t->p[0][j]; /* the eye is the origin */
            t->front = dot(t->n, eye) > 0;
            t->draw = d;
            t->index = i;
        }
    }
}

/* Ray from the eye (origin) through P: distance factor of the hit of t
 * (P * f is the hit), or -1. */
static double ray_hit(const wtri *t, const double P[3])
{
    double e1[3], e2[3], h[3], q[3], s[3];
    sub3(t->p[1], t->p[0], e1);
    sub3(t->p[2], t->p[0], e2);
    cross(P, e2, h);
    double a = dot(e1, h);
    if (fabs(a) < 1e-18) return -1;
    double f = 1 / a;
    for (int k = 0; k < 3; k++) s[k] = -t->p[0][k];
    double u = f * dot(s, h);
    if (u < 0 || u > 1) return -1;
    cross(s, e1, q);
    double v = f * dot(P, q);
    if (v < 0 || u + v > 1) return -1;
    return f * dot(e2, q);
}

typedef struct sample {
    double x, y;
    int visible;
} sample;

/* A visible piece of a feature edge, on screen (px). */
typedef struct seg {
    double x0, y0, x1, y1;
} seg;

typedef struct samples {
    sample *v;
    size_t n, cap;
    seg *s;
    size_t ns, caps;
} samples;

static void push(samples *s, double x, double y, int vis)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 4096;
        s->v = realloc(s->v, s->cap * sizeof *s->v);
    }
    s->v[s->n].x = x;
    s->v[s->n].y = y;
    s->v[s->n].visible = vis;
    s->n++;
}

static void push_seg(samples *s, double x0, double y0, double x1, double y1)
{
    if (s->ns == s->caps) {
        s->caps = s->caps ? 2 * s->caps : 1024;
        s->s = realloc(s->s, s->caps * sizeof *s->s);
    }
    s->s[s->ns].x0 = x0;
    s->s[s->ns].y0 = y0;
    s->s[s->ns].x1 = x1;
    s->s[s->ns].y1 = y1;
    s->ns++;
}

/* One feature edge A-B (world) of faces q1 and q2 (q2 -1 for a boundary). */
typedef struct fedge {
    double A[3], B[3], ax, ay, bx, by;
    int q1, q2;
} fedge;

/* The screen point at parameter u of the edge (uniform on screen). */
static void edge_at(const fedge *e, double u, double *sx, double *sy)
{
    *sx = e->ax + u * (e->bx - e->ax);
    *sy = e->ay + u * (e->by - e->ay);
}

/* Is the edge point at screen parameter u visible: does the ray to it meet
 * no front face (but its own) nearer? */
static int edge_visible(const scene *s, const fedge *e, double u)
{
    /* the perspective-correct world parameter of u */
    double wa = -e->A[2], wb = -e->B[2];
    double t = u * wa / (u * wa + (1 - u) * wb);
    double P[3];
    for (int c = 0; c < 3; c++) P[c] = e->A[c] + t * (e->B[c] - e->A[c]);
    for (int q = 0; q < s->nt; q++) {
        if (q == e->q1 || q == e->q2 || !s->t[q].front) continue;
        double f = ray_hit(&s->t[q], P);
        if (f > 0 && f < 1 - 1e-9) return 0;
    }
    return 1;
}

/* Samples every 1/10 px of the edge's on-screen part, and its visible
 * pieces, their ends found by bisection to 1/1000 px where visibility
 * changes between two samples. */
static void sample_edge(const scene *s, const fedge *e, samples *out)
{
    int n = (int)ceil(hypot(e->bx - e->ax, e->by - e->ay) * 10) + 1;
    double len = hypot(e->bx - e->ax, e->by - e->ay);
    int bis = 1;
    while (len / n / (1 << bis) > 0.001 && bis < 20) bis++;
    double run_u = 0;
    int run = 0, prev_vis = 0;
    double prev_u = 0;
    for (int k = 0; k <= n; k++) {
        double u = (double)k / n, sx, sy;
        edge_at(e, u, &sx, &sy);
        int inside = !(sx < 0 || sy < 0 || sx >= W || sy >= H);
        int vis = inside && edge_visible(s, e, u);
        if (inside) push(out, sx, sy, vis);
        if (k > 0 && vis != prev_vis) {
            /* the change lies between prev_u and u */
            double lo = prev_u, hi = u;
            for (int b = 0; b < bis; b++) {
                double m = (lo + hi) / 2, mx, my;
                edge_at(e, m, &mx, &my);
                int mv = !(mx < 0 || my < 0 || mx >= W || my >= H) && edge_visible(s, e, m);
                if (mv == prev_vis)
                    lo = m;
                else
                    hi = m;
            }
            if (vis) {
                run = 1;
                run_u = hi;
            } else if (run) {
                double x0, y0, x1, y1;
                edge_at(e, run_u, &x0, &y0);
                edge_at(e, lo, &x1, &y1);
                push_seg(out, x0, y0, x1, y1);
                run = 0;
            }
        } else if (k == 0 && vis) {
            run = 1;
            run_u = 0;
        }
        prev_vis = vis;
        prev_u = u;
    }
    if (run) {
        double x0, y0, x1, y1;
        edge_at(e, run_u, &x0, &y0);
        edge_at(e, 1, &x1, &y1);
        push_seg(out, x0, y0, x1, y1);
    }
}

/* Samples every feature edge of the scene. */
static void feature_samples(const scene *s, samples *out)
{
    double cosc = cos(CREASE * PI / 180);
    int base = 0;
    for (int d = 0; d < s->nmesh; d++) {
        const mesh_b *m = &s->meshes[d];
        for (int i = 0; i < m->nt; i++)
            for (int e = 0; e < 3; e++) {
                int a = m->idx[3 * i + e], b = m->idx[3 * i + (e + 1) % 3];
                /* the other face on this edge runs it b -> a */
                int other = -1;
                for (int j = 0; j < m->nt && other < 0; j++)
                    for (int f = 0; f < 3; f++)
                        if (m->idx[3 * j + f] == b && m->idx[3 * j + (f + 1) % 3] == a) other = j;
                if (other >= 0 && other < i) continue; /* each shared edge once */
                const wtri *t1 = &s->t[base + i], *t2 = other >= 0 ? &s->t[base + other] : NULL;
                int feature;
                if (!t2)
                    feature = t1->front;
                else if (t1->front != t2->front)
                    feature = 1;
                else
                    feature = t1->front && dot(t1->n, t2->n) < cosc;
                if (!feature) continue;
                fedge fe;
                world_of(m, &s->model[d], a, fe.A);
                world_of(m, &s->model[d], b, fe.B);
                zt_world_to_px(W, H, fe.A[0], fe.A[1], fe.A[2], &fe.ax, &fe.ay);
                zt_world_to_px(W, H, fe.B[0], fe.B[1], fe.B[2], &fe.bx, &fe.by);
                fe.q1 = base + i;
                fe.q2 = other >= 0 ? base + other : -1;
                sample_edge(s, &fe, out);
            }
        base += m->nt;
    }
}

/* The segment where front faces t and u (of two draws) meet, if they do:
 * each triangle cut by the other's plane gives an interval of the planes'
 * common line; the segment is the two intervals' overlap. */
static int tri_meet(const wtri *t, const wtri *u, double A[3], double B[3])
{
    const wtri *tr[2] = {t, u};
    double dir[3], lo[2], hi[2], pt[2][2][3];
    cross(t->n, u->n, dir);
    if (dot(dir, dir) < 1e-12) return 0; /* parallel planes */
    for (int w = 0; w < 2; w++) {
        const wtri *a = tr[w], *b = tr[1 - w];
        double d[3], q[2][3];
        int nq = 0;
        for (int i = 0; i < 3; i++) {
            double v[3];
            sub3(a->p[i], b->p[0], v);
            d[i] = dot(v, b->n);
        }
        for (int i = 0; i < 3 && nq < 2; i++) {
            int j = (i + 1) % 3;
            if ((d[i] < 0) == (d[j] < 0) || d[i] == d[j]) continue;
            double f = d[i] / (d[i] - d[j]);
            for (int c = 0; c < 3; c++) q[nq][c] = a->p[i][c] + f * (a->p[j][c] - a->p[i][c]);
            nq++;
        }
        if (nq < 2) return 0;
        double s0 = dot(q[0], dir), s1 = dot(q[1], dir);
        int sw = s0 > s1;
        lo[w] = sw ? s1 : s0;
        hi[w] = sw ? s0 : s1;
        memcpy(pt[w][0], q[sw], sizeof pt[w][0]);
        memcpy(pt[w][1], q[!sw], sizeof pt[w][1]);
    }
    int wl = lo[0] > lo[1] ? 0 : 1, wh = hi[0] < hi[1] ? 0 : 1;
    if (lo[wl] >= hi[wh]) return 0;
    memcpy(A, pt[wl][0], 3 * sizeof *A);
    memcpy(B, pt[wh][1], 3 * sizeof *B);
    return 1;
}

/* Samples the lines where front faces of two draws meet. */
static void meeting_samples(const scene *s, samples *out)
{
    for (int q = 0; q < s->nt; q++)
        for (int v = q + 1; v < s->nt; v++) {
            const wtri *t = &s->t[q], *u = &s->t[v];
            if (!t->front || !u->front || t->draw == u->draw) continue;
            fedge fe;
            if (!tri_meet(t, u, fe.A, fe.B)) continue;
            zt_world_to_px(W, H, fe.A[0], fe.A[1], fe.A[2], &fe.ax, &fe.ay);
            zt_world_to_px(W, H, fe.B[0], fe.B[1], fe.B[2], &fe.bx, &fe.by);
            fe.q1 = q;
            fe.q2 = v;
            sample_edge(s, &fe, out);
        }
}

/* Chebyshev (L-infinity) distance from (px, py) to a segment: the largest
 * of two linear functions' absolute values is convex along the segment, so
 * its least value is at an end or where one of the lines x = px, y = py,
 * x - px = +-(y - py) crosses it. */
static double seg_dist(const seg *g, double px, double py)
{
    double dx = g->x1 - g->x0, dy = g->y1 - g->y0, ex = g->x0 - px, ey = g->y0 - py;
    double cand[6] = {0, 1, -1, -1, -1, -1}, best = 1e300;
    if (dx != 0) cand[2] = -ex / dx;
    if (dy != 0) cand[3] = -ey / dy;
    if (dx - dy != 0) cand[4] = -(ex - ey) / (dx - dy);
    if (dx + dy != 0) cand[5] = -(ex + ey) / (dx + dy);
    for (int k = 0; k < 6; k++) {
        double u = cand[k];
        if (u < 0 || u > 1) continue;
        double a = fabs(ex + u * dx), b = fabs(ey + u * dy);
        double d = a > b ? a : b;
        if (d < best) best = d;
    }
    return best;
}

/* ---- scenes ---- */

static void random_scene(zt_rng *g, scene *s)
{
    double cx[6], cy[6], cz[6], rad[6];
    s->nmesh = 3 + (int)zt_below(g, 3);
    for (int d = 0; d < s->nmesh; d++) {
        int kind = (int)zt_below(g, 4);
        mesh_b *m = &s->meshes[d];
        mesh_alloc(m, 600, 1200);
        double r;
        if (kind == 0) {
            make_box(m, zt_uniform(g, 0.3, 1), zt_uniform(g, 0.3, 1), zt_uniform(g, 0.3, 1));
            r = sqrt(3.0);
        } else if (kind == 1) {
            make_sphere(m, 1, 24, 16);
            r = 1;
        } else if (kind == 2) {
            make_prism(m, 0.8, 1);
            r = 1.3;
        } else {
            make_sheet(m, 1);
            r = 1.6;
        }
        /* a place whose bounding sphere meets no other's */
        for (int tries = 0;; tries++) {
            cz[d] = -zt_uniform(g, 4, 10);
            cx[d] = zt_uniform(g, -0.6, 0.6) * -cz[d];
            cy[d] = zt_uniform(g, -0.45, 0.45) * -cz[d];
            rad[d] = r;
            int ok = 1;
            for (int e = 0; e < d; e++)
                if (hypot(hypot(cx[d] - cx[e], cy[d] - cy[e]), cz[d] - cz[e]) < rad[d] + rad[e] + 0.05)
                    ok = 0;
            if (ok || tries > 200) break;
        }
        zs_mat34 rx = zs_mat34_rotate_x((zs_fixed)zt_range(g, 0, ZS_FX(360)));
        zs_mat34 ry = zs_mat34_rotate_y((zs_fixed)zt_range(g, 0, ZS_FX(360)));
        zs_mat34 tr = zs_mat34_translate((zs_fixed)lround(cx[d] * 65536),
                                         (zs_fixed)lround(cy[d] * 65536),
                                         (zs_fixed)lround(cz[d] * 65536));
        zs_mat34 rr = zs_mat34_mul(&ry, &rx);
        s->model[d] = zs_mat34_mul(&tr, &rr);
    }
}

/* Objects that cut into one another: a box, a sphere or a prism, and two
 * or three more placed so that their bounding spheres overlap by a third
 * to a half of the smaller radius. */
static void cutting_scene(zt_rng *g, scene *s)
{
    double cx = 0, cy = 0, cz = -5;
    s->nmesh = 2 + (int)zt_below(g, 2);
    for (int d = 0; d < s->nmesh; d++) {
        int kind = (int)zt_below(g, 3);
        mesh_b *m = &s->meshes[d];
        mesh_alloc(m, 600, 1200);
        double r;
        if (kind == 0) {
            make_box(m, zt_uniform(g, 0.5, 1), zt_uniform(g, 0.5, 1), zt_uniform(g, 0.5, 1));
            r = 1;
        } else if (kind == 1) {
            make_sphere(m, 1, 24, 16);
            r = 1;
        } else {
            make_prism(m, 0.8, 1);
            r = 0.9;
        }
        double x = cx, y = cy, z = cz;
        if (d > 0) { /* beside the previous one, overlapping */
            double a = zt_uniform(g, 0, 2 * PI), b = zt_uniform(g, -0.6, 0.6);
            double dist = 2 * r * zt_uniform(g, 0.55, 0.7);
            x += dist * cos(a) * cos(b);
            y += dist * sin(a) * cos(b);
            z += dist * sin(b);
        }
        cx = x;
        cy = y;
        cz = z;
        zs_mat34 rx = zs_mat34_rotate_x((zs_fixed)zt_range(g, 0, ZS_FX(360)));
        zs_mat34 ry = zs_mat34_rotate_y((zs_fixed)zt_range(g, 0, ZS_FX(360)));
        zs_mat34 tr = zs_mat34_translate((zs_fixed)lround(x * 65536), (zs_fixed)lround(y * 65536),
                                         (zs_fixed)lround(z * 65536));
        zs_mat34 rr = zs_mat34_mul(&ry, &rx);
        s->model[d] = zs_mat34_mul(&tr, &rr);
    }
}

/* (Not the spider: its legs cut into its body, and the lines where surfaces
 * intersect are drawn but are no feature edges of the oracle.) */
static const char *k_models[] = {
    "/usr/share/assimp/models/STL/sphereWithHole.stl",
    "/usr/share/assimp/models/PLY/Wuson.ply",
    "/usr/share/assimp/models/OBJ/box.obj",
};
#define NMODELS ((int)(sizeof k_models / sizeof k_models[0]))
#define MODEL_VIEWS 3

static const int16_t *g_weld_pos;
static int weld_cmp(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    int c = memcmp(&g_weld_pos[3 * i], &g_weld_pos[3 * j], 3 * sizeof(int16_t));
    return c ? c : (i > j) - (i < j);
}

/* Vertices at the same (quantised) position made one (files such as STL
 * repeat them per face), so the oracle's edges join the faces that meet. */
static void weld(mesh_b *m)
{
    int *ord = malloc((size_t)m->nv * sizeof *ord), *map = malloc((size_t)m->nv * sizeof *map);
    for (int i = 0; i < m->nv; i++) ord[i] = i;
    g_weld_pos = m->pos;
    qsort(ord, (size_t)m->nv, sizeof *ord, weld_cmp);
    for (int k = 0; k < m->nv; k++) {
        int i = ord[k];
        map[i] = (k > 0 && memcmp(&m->pos[3 * ord[k - 1]], &m->pos[3 * i], 6) == 0) ? map[ord[k - 1]] : i;
    }
    for (int t = 0; t < 3 * m->nt; t++) m->idx[t] = (uint16_t)map[m->idx[t]];
    free(ord);
    free(map);
}

/* A model file as one mesh, fitted into the unit sphere; 0 if absent. */
static int load_model(const char *path, mesh_b *m)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fclose(f);
    const struct aiScene *sc = aiImportFile(path, aiProcess_Triangulate |
                                                      aiProcess_JoinIdenticalVertices |
                                                      aiProcess_PreTransformVertices);
    if (!sc) return 0;
    size_t nv = 0, nt = 0;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, rad = 0;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        nv += sc->mMeshes[i]->mNumVertices;
        nt += sc->mMeshes[i]->mNumFaces;
        for (unsigned v = 0; v < sc->mMeshes[i]->mNumVertices; v++) {
            const struct aiVector3D *p = &sc->mMeshes[i]->mVertices[v];
            double q[3] = {p->x, p->y, p->z};
            for (int k = 0; k < 3; k++) {
                if (q[k] < lo[k]) lo[k] = q[k];
                if (q[k] > hi[k]) hi[k] = q[k];
            }
        }
    }
    if (nv == 0 || nv > 60000 || nt > 60000) {
        aiReleaseImport(sc);
        return 0;
    }
    double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    for (unsigned i = 0; i < sc->mNumMeshes; i++)
        for (unsigned v = 0; v < sc->mMeshes[i]->mNumVertices; v++) {
            const struct aiVector3D *p = &sc->mMeshes[i]->mVertices[v];
            double d = sqrt((p->x - c[0]) * (p->x - c[0]) + (p->y - c[1]) * (p->y - c[1]) +
                            (p->z - c[2]) * (p->z - c[2]));
            if (d > rad) rad = d;
        }
    mesh_alloc(m, nv, nt);
    m->scale = ZS_FX(1) / 8192;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *am = sc->mMeshes[i];
        int base = m->nv;
        for (unsigned v = 0; v < am->mNumVertices; v++)
            add_v(m, (am->mVertices[v].x - c[0]) / rad * 1.5, (am->mVertices[v].y - c[1]) / rad * 1.5,
                  (am->mVertices[v].z - c[2]) / rad * 1.5);
        for (unsigned k = 0; k < am->mNumFaces; k++)
            if (am->mFaces[k].mNumIndices == 3)
                add_t(m, base + (int)am->mFaces[k].mIndices[0], base + (int)am->mFaces[k].mIndices[1],
                      base + (int)am->mFaces[k].mIndices[2]);
    }
    aiReleaseImport(sc);
    weld(m);
    return 1;
}

/* The model (already in meshes[0]) turned, in front of the camera, and a
 * box beside it. */
static void model_scene(zt_rng *g, scene *s)
{
    s->nmesh = 2;
    zs_mat34 rx = zs_mat34_rotate_x((zs_fixed)zt_range(g, 0, ZS_FX(360)));
    zs_mat34 ry = zs_mat34_rotate_y((zs_fixed)zt_range(g, 0, ZS_FX(360)));
    zs_mat34 tr = zs_mat34_translate(0, 0, -ZS_FX(4));
    zs_mat34 rr = zs_mat34_mul(&ry, &rx);
    s->model[0] = zs_mat34_mul(&tr, &rr);
    mesh_alloc(&s->meshes[1], 600, 1200);
    make_box(&s->meshes[1], 0.4, 0.4, 0.4);
    s->model[1] = zs_mat34_translate(ZS_FX(3), ZS_FX(1), -ZS_FX(5));
}

typedef struct ctx {
    zs_renderer r;
    uint8_t *arena;
} ctx;

static zs_status draw_lines(ctx *c, const scene *s, zs_visibility mode, zs_format fmt,
                            uint8_t *img, int band)
{
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 4, ZS_FX(40));
    zs_status st = zs_frame_begin(&c->r, &cam, mode);
    if (st != ZS_OK) return st;
    zs_shade_params sp = zs_shade_default();
    sp.format = fmt;
    sp.mono = ZS_MONO_LINES;
    sp.crease_deg = CREASE;
    if ((st = zs_frame_shading(&c->r, &sp)) != ZS_OK) return st;
    for (int d = 0; d < s->nmesh; d++) {
        zs_mesh m;
        memset(&m, 0, sizeof m);
        m.positions = s->meshes[d].pos;
        m.indices = s->meshes[d].idx;
        m.scale = s->meshes[d].scale;
        m.vertex_count = (uint16_t)s->meshes[d].nv;
        m.triangle_count = (uint16_t)s->meshes[d].nt;
        m.color = 0xFFFFFF;
        if ((st = zs_draw(&c->r, &m, &s->model[d])) != ZS_OK) return st;
    }
    size_t stride = fmt == ZS_FMT_MONO_PAGE ? W : (W + 7) / 8;
    for (int y = 0; y < H; y += band) {
        int n = band < H - y ? band : H - y;
        uint8_t *p = img + (fmt == ZS_FMT_MONO_PAGE ? (size_t)(y / 8) : (size_t)y) * stride;
        if ((st = zs_render_rows(&c->r, y, n, p, stride)) != ZS_OK) return st;
    }
    return ZS_OK;
}


/* debugging aid: ZT_LINES_PROBE=scene,x,y prints the triangle tags around a
 * pixel and the oracle's view of them */
static void probe(ctx *c, const scene *s, int k)
{
    const char *e = getenv("ZT_LINES_PROBE");
    int pk, px, py;
    if (!e || sscanf(e, "%d,%d,%d", &pk, &px, &py) != 3 || pk != k) return;
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 4, ZS_FX(40));
    zs_frame_begin(&c->r, &cam, ZS_MODE_SPAN);
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_ID16;
    zs_frame_shading(&c->r, &sp);
    for (int d = 0; d < s->nmesh; d++) {
        zs_mesh m;
        memset(&m, 0, sizeof m);
        m.positions = s->meshes[d].pos;
        m.indices = s->meshes[d].idx;
        m.scale = s->meshes[d].scale;
        m.vertex_count = (uint16_t)s->meshes[d].nv;
        m.triangle_count = (uint16_t)s->meshes[d].nt;
        m.color = 0xFFFFFF;
        zs_draw(&c->r, &m, &s->model[d]);
    }
    uint16_t *ids = malloc(W * H * 2);
    zs_render_rows(&c->r, 0, H, ids, W * 2);
    for (int y = py - 2; y <= py + 2; y++) {
        for (int x = px - 3; x <= px + 3; x++)
            fprintf(stderr, " %5d", (x >= 0 && x < W && y >= 0 && y < H) ? ids[y * W + x] : -1);
        fprintf(stderr, "\n");
    }
    int seen[64], ns = 0;
    for (int y = py - 2; y <= py + 2; y++)
        for (int x = px - 3; x <= px + 3; x++) {
            if (x < 0 || x >= W || y < 0 || y >= H) continue;
            int id = ids[y * W + x], dup = 0;
            for (int i = 0; i < ns; i++) dup |= seen[i] == id;
            if (!dup && id && ns < 64) seen[ns++] = id;
        }
    for (int i = 0; i < ns; i++) {
        const wtri *t = &s->t[seen[i] - 1];
        double sx[3], sy[3];
        for (int j = 0; j < 3; j++) zt_world_to_px(W, H, t->p[j][0], t->p[j][1], t->p[j][2], &sx[j], &sy[j]);
        fprintf(stderr, "tag %d: draw %d tri %d front %d n (%.3f %.3f %.3f) screen (%.2f,%.2f) (%.2f,%.2f) (%.2f,%.2f)\n",
                seen[i], t->draw, t->index, t->front, t->n[0], t->n[1], t->n[2], sx[0], sy[0], sx[1], sy[1], sx[2], sy[2]);
        for (int j = 0; j < i; j++) {
            const wtri *u = &s->t[seen[j] - 1];
            fprintf(stderr, "   angle to %d: %.1f deg\n", seen[j], acos(fmin(1, dot(t->n, u->n))) * 180 / PI);
        }
    }
    free(ids);
}

static int px_on(const uint8_t *img, zs_format fmt, int x, int y)
{
    if (fmt == ZS_FMT_MONO_PAGE) return (img[(y / 8) * W + x] >> (y % 8)) & 1;
    return (img[y * ((W + 7) / 8) + x / 8] >> (7 - x % 8)) & 1;
}

static void test_lines_vs_oracle(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    g_survey = getenv("ZT_LINES_SURVEY") != NULL;
    ctx c;
    zs_config cfg = zs_config_default(W, H, 30000, 30000, 4096);
    cfg.flags = ZS_CFG_LINES;
    size_t an = zs_arena_bytes(&cfg);
    c.arena = malloc(an);
    ZT_ST(zs_init(&c.r, c.arena, an, &cfg), ZS_OK);
    uint8_t *img = malloc(W * H), *ref = malloc(W * H);
    uint8_t *on = malloc(W * H);
    double *dist = malloc(W * H * sizeof *dist), worst_dist = 0;
    double worst_recall = 1, worst_model_recall = 1;
    int random_short = 0;
    long total_drawn = 0, total_vis = 0, total_hidden_only = 0, total_found = 0;
    long model_drawn = 0, cut_drawn = 0;
    double worst_cut_recall = 1, worst_cut_dist = 0;
    int models_loaded = 0;
    zt_rng gc;
    zt_rng_seed(&gc, SEED + 1);
    for (int k = 0; k < NSCENES + NMODELS * MODEL_VIEWS + NCUTTING; k++) {
        scene s;
        int cutting = k >= NSCENES + NMODELS * MODEL_VIEWS;
        if (k < NSCENES) {
            random_scene(&g, &s);
        } else if (cutting) {
            cutting_scene(&gc, &s);
        } else {
            if (!load_model(k_models[(k - NSCENES) / MODEL_VIEWS], &s.meshes[0])) {
                if ((k - NSCENES) % MODEL_VIEWS == 0)
                    print_message("lines: %s not found, skipped\n",
                                  k_models[(k - NSCENES) / MODEL_VIEWS]);
                continue;
            }
            models_loaded++;
            model_scene(&g, &s);
        }
        build_world(&s);
        probe(&c, &s, k);
        samples sm = {0};
        feature_samples(&s, &sm);
        if (cutting)
            meeting_samples(&s, &sm);
        ZT_ST(draw_lines(&c, &s, ZS_MODE_SPAN, ZS_FMT_MONO_MSB, ref, 8), ZS_OK);
        ZT_CHECK(zs_frame_stats(&c.r)->tris_dropped == 0, "pools large enough");
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) on[y * W + x] = (uint8_t)px_on(ref, ZS_FMT_MONO_MSB, x, y);
        /* the same drawing in the other mode, layout and band heights */
        for (int v = 0; v < 6; v++) {
            zs_format fmt = (v & 1) ? ZS_FMT_MONO_MSB : ZS_FMT_MONO_PAGE;
            int band = v == 0 ? 8 : v == 1 ? 1 : v == 2 ? 16 : v == 3 ? 7 : v == 4 ? 24 : 5;
            zs_visibility mode = v >= 4 ? ZS_MODE_WARNOCK : v >= 2 ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
            memset(img, 0, W * H);
            ZT_ST(draw_lines(&c, &s, mode, fmt, img, band), ZS_OK);
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++)
                    ZT_CHECK(px_on(img, fmt, x, y) == on[y * W + x],
                             "scene %d variant %d: pixel (%d,%d) differs", k, v, x, y);
        }
        /* precision: the distance of every pixel centre to the visible
         * pieces of the feature edges (within 3 px; farther counts as 9) */
        for (int i = 0; i < W * H; i++) dist[i] = 9;
        for (size_t i = 0; i < sm.ns; i++) {
            const seg *gs = &sm.s[i];
            int x0 = (int)floor(fmin(gs->x0, gs->x1)) - 3, x1 = (int)floor(fmax(gs->x0, gs->x1)) + 3;
            int y0 = (int)floor(fmin(gs->y0, gs->y1)) - 3, y1 = (int)floor(fmax(gs->y0, gs->y1)) + 3;
            for (int y = y0; y <= y1; y++)
                for (int x = x0; x <= x1; x++) {
                    if (x < 0 || y < 0 || x >= W || y >= H) continue;
                    double dd = seg_dist(gs, x + 0.5, y + 0.5);
                    if (dd < dist[y * W + x]) dist[y * W + x] = dd;
                }
        }
        long vis = 0, found = 0;
        for (size_t i = 0; i < sm.n; i++) {
            const sample *p = &sm.v[i];
            if (!p->visible) continue;
            int x0 = (int)floor(p->x - 0.5 - TOL), x1 = (int)ceil(p->x - 0.5 + TOL);
            int y0 = (int)floor(p->y - 0.5 - TOL), y1 = (int)ceil(p->y - 0.5 + TOL);
            int hit = 0;
            for (int y = y0; y <= y1; y++)
                for (int x = x0; x <= x1; x++) {
                    if (x < 0 || y < 0 || x >= W || y >= H) continue;
                    if (fabs(x + 0.5 - p->x) > TOL || fabs(y + 0.5 - p->y) > TOL) continue;
                    if (on[y * W + x]) hit = 1;
                }
            vis++;
            found += hit;
        }
        long drawn = 0, stray = 0;
        double dist_scene = 0;
        for (int i = 0; i < W * H; i++) {
            drawn += on[i];
            if (on[i] && dist[i] > dist_scene) dist_scene = dist[i];
            if (on[i] && dist[i] > TOL) {
                stray++;
                if (stray <= 3)
                    print_error("scene %d: drawn pixel (%d,%d) is %.3f px from the nearest "
                                "visible edge (limit %.2f)\n",
                                k, i % W, i / W, dist[i], TOL);
            }
        }
        if (getenv("ZT_LINES_DUMP")) { /* debugging aid: the drawing and the oracle */
            char name[64];
            snprintf(name, sizeof name, "out/lines_%d.ppm", k);
            FILE *f = fopen(name, "wb");
            if (f) {
                uint8_t *rgb = calloc(W * H * 3, 1);
                for (size_t i = 0; i < sm.n; i++) {
                    int x = (int)sm.v[i].x, y = (int)sm.v[i].y;
                    rgb[(y * W + x) * 3 + (sm.v[i].visible ? 1 : 2)] = 160;
                }
                for (int i = 0; i < W * H; i++)
                    if (on[i]) rgb[i * 3] = 255;
                fprintf(f, "P6 %d %d 255\n", W, H);
                fwrite(rgb, 1, W * H * 3, f);
                fclose(f);
                free(rgb);
            }
        }
        double recall = vis ? (double)found / vis : 1;
        if (getenv("ZT_LINES_VERBOSE"))
        {
            int wi = 0;
            for (int i = 0; i < W * H; i++) if (on[i] && dist[i] == dist_scene) wi = i;
            print_message("scene %d: max dist %.3f at (%d,%d) recall %.4f drawn %ld\n", k, dist_scene, wi % W, wi / W, recall, drawn);
        }
        if (recall < worst_recall) worst_recall = recall;
        total_drawn += drawn;
        total_vis += vis;
        total_hidden_only += stray;
        LCHECK(drawn > 50 && vis > 100, "scene %d: a real drawing (%ld px, %ld samples)", k,
                 drawn, vis);
        if (k >= NSCENES && !cutting)
            print_message("lines: model %s view %d: %ld drawn pixels, %ld not near a visible "
                          "edge, %.2f%% of the visible length drawn\n",
                          k_models[(k - NSCENES) / MODEL_VIEWS], (k - NSCENES) % MODEL_VIEWS,
                          drawn, stray, vis ? 100.0 * (double)found / (double)vis : 0.0);
        LCHECK(stray == 0, "scene %d: %ld of %ld drawn pixels are farther than %.2f px from a "
               "visible edge", k, stray, drawn, TOL);
        if (dist_scene > worst_dist) worst_dist = dist_scene;
        if (cutting) {
            if (recall < worst_cut_recall) worst_cut_recall = recall;
            if (dist_scene > worst_cut_dist) worst_cut_dist = dist_scene;
            cut_drawn += drawn;
            LCHECK(recall >= 0.98, "cutting scene %d: %.2f%% of the visible length drawn", k,
                   100 * recall);
        } else if (k >= NSCENES) {
            model_drawn += drawn;
            if (recall < worst_model_recall) worst_model_recall = recall;
            LCHECK(recall >= 0.98, "model view %d: %.2f%% of the visible length drawn", k,
                   100 * recall);
        } else {
            if (recall < 0.98) random_short++;
            LCHECK(recall >= 0.98, "scene %d: %.2f%% of the visible edge length drawn", k,
                   100 * recall);
        }
        total_found += found;
        free(sm.v);
        free(sm.s);

        free(s.t);
        for (int d = 0; d < s.nmesh; d++) mesh_release(&s.meshes[d]);
    }
    double all = total_vis ? (double)total_found / total_vis : 0;
    print_message("lines: %d random scenes, the model views and the cutting scenes: %ld drawn pixels, %ld visible "
                  "edge samples; %.2f%% of the visible length drawn (worst scene %.2f%%, worst "
                  "model view %.2f%%, %d random scenes under 98%%); every drawn pixel at most "
                  "%.3f px from a visible edge (models: %ld drawn pixels)\n",
                  NSCENES, total_drawn, total_vis, 100 * all, 100 * worst_recall,
                  100 * worst_model_recall, random_short, worst_dist, model_drawn);
    LCHECK(all >= 0.98, "%.2f%% of the visible edge length drawn", 100 * all);
    print_message("lines: %d model views (%d models of %d found)\n", models_loaded,
                  models_loaded / MODEL_VIEWS, NMODELS);
    print_message("lines: %d scenes of objects cutting into one another: %ld drawn pixels, "
                  "worst scene %.2f%% of the visible length (edges and meeting lines) drawn, "
                  "every drawn pixel at most %.3f px from them\n",
                  NCUTTING, cut_drawn, 100 * worst_cut_recall, worst_cut_dist);
    free(img); free(ref); free(on); free(dist);
    free(c.arena);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lines_vs_oracle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
