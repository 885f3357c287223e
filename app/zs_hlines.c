/* SPDX-License-Identifier: MIT */
/* Vector hidden lines (see zs_hlines.h). */
#include "zs_hlines.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void zs_hl_project(const zs_hl_view *v, const double p[3], double *x, double *y)
{
    double cot = 1.0 / tan(v->fov_deg * PI / 360.0), k = 0.5 * v->height * cot;
    *x = 0.5 * v->width + k * (p[0] / -p[2]);
    *y = 0.5 * v->height - k * (p[1] / -p[2]);
}

typedef struct sface {        /* a front face, projected */
    double x[3], y[3], q[3];  /* screen, and 1/w */
    double sign;              /* orientation of the projection */
    long tri;                 /* the triangle it comes from */
} sface;

typedef struct edge_rec {
    uint32_t a, b;            /* a < b */
    int group;
    uint32_t tri;
} edge_rec;

static int edge_cmp(const void *pa, const void *pb)
{
    const edge_rec *a = pa, *b = pb;
    if (a->group != b->group) return a->group < b->group ? -1 : 1;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    if (a->b != b->b) return a->b < b->b ? -1 : 1;
    return a->tri < b->tri ? -1 : (a->tri > b->tri);
}

static void normal_of(const double *pos, const uint32_t *t, double n[3])
{
    const double *a = pos + 3 * t[0], *b = pos + 3 * t[1], *c = pos + 3 * t[2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double l;
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0)
        for (int k = 0; k < 3; k++) n[k] /= l;
}

/* Front: the normal points toward the eye (the origin). */
static int is_front(const double *pos, const uint32_t *t)
{
    double n[3];
    const double *a = pos + 3 * t[0];
    normal_of(pos, t, n);
    return -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) > 0;
}

/* Intervals [lo, hi] of s in [0, 1]. */
typedef struct ival {
    double lo, hi;
} ival;

static int ival_cmp(const void *pa, const void *pb)
{
    const ival *a = pa, *b = pb;
    return a->lo < b->lo ? -1 : (a->lo > b->lo);
}

static int push_seg(zs_hl_result *r, double x0, double y0, double x1, double y1)
{
    if (r->n == r->cap) {
        size_t c = r->cap ? 2 * r->cap : 256;
        zs_hl_seg *s = realloc(r->seg, c * sizeof *s);
        if (!s) return -1;
        r->seg = s;
        r->cap = c;
    }
    r->seg[r->n].x0 = x0;
    r->seg[r->n].y0 = y0;
    r->seg[r->n].x1 = x1;
    r->seg[r->n].y1 = y1;
    r->n++;
    return 0;
}

/* s-range where a + b s >= 0, intersected into [*lo, *hi]. */
static void half(double a, double b, double *lo, double *hi)
{
    if (b == 0) {
        if (a < 0) *hi = -1;
        return;
    }
    if (b > 0) {
        double s = -a / b;
        if (s > *lo) *lo = s;
    } else {
        double s = -a / b;
        if (s < *hi) *hi = s;
    }
}

/* Visible pieces of the eye-space segment A..B (already in front of the
 * near plane), occluded by faces; skip1/skip2: its own triangles. */
static int clip_edge(const zs_hl_view *v, const double A[3], const double B[3], const sface *f,
                     size_t nf, long skip1, long skip2, ival **hid, size_t *hcap,
                     zs_hl_result *out)
{
    double ax, ay, bx, by, qa = 1.0 / -A[2], qb = 1.0 / -B[2];
    size_t nh = 0, i;
    zs_hl_project(v, A, &ax, &ay);
    zs_hl_project(v, B, &bx, &by);
    double dx = bx - ax, dy = by - ay;
    for (i = 0; i < nf; i++) {
        const sface *t = &f[i];
        double lo = 0, hi = 1;
        if (t->tri == skip1 || t->tri == skip2) continue;
        /* inside the face's projection */
        for (int k = 0; k < 3 && lo <= hi; k++) {
            int j = (k + 1) % 3;
            double ex = t->x[j] - t->x[k], ey = t->y[j] - t->y[k];
            double c0 = t->sign * (ex * (ay - t->y[k]) - ey * (ax - t->x[k]));
            double c1 = t->sign * (ex * dy - ey * dx);
            half(c0, c1, &lo, &hi);
        }
        if (lo >= hi) continue;
        /* nearer than the edge: q_face(s) - q_edge(s) > 0 (1/w larger) */
        {
            double det = (t->x[1] - t->x[0]) * (t->y[2] - t->y[0]) -
                         (t->x[2] - t->x[0]) * (t->y[1] - t->y[0]);
            if (det == 0) continue;
            /* the face's 1/w as a plane over the screen */
            double gx = ((t->q[1] - t->q[0]) * (t->y[2] - t->y[0]) -
                         (t->q[2] - t->q[0]) * (t->y[1] - t->y[0])) / det;
            double gy = ((t->q[2] - t->q[0]) * (t->x[1] - t->x[0]) -
                         (t->q[1] - t->q[0]) * (t->x[2] - t->x[0])) / det;
            double f0 = t->q[0] + gx * (ax - t->x[0]) + gy * (ay - t->y[0]);
            double f1 = gx * dx + gy * dy;
            /* relative margin: faces through an endpoint of the edge meet it there */
            double eps = 1e-9 * (qa > qb ? qa : qb);
            half(f0 - qa - eps, f1 - (qb - qa), &lo, &hi);
        }
        if (hi - lo <= 1e-12) continue;
        if (nh == *hcap) {
            size_t c = *hcap ? 2 * *hcap : 64;
            ival *p = realloc(*hid, c * sizeof *p);
            if (!p) return -1;
            *hid = p;
            *hcap = c;
        }
        (*hid)[nh].lo = lo;
        (*hid)[nh].hi = hi;
        nh++;
    }
    if (nh > 1)
        qsort(*hid, nh, sizeof **hid, ival_cmp);
    {
        double s = 0; /* start of the current visible piece */
        for (i = 0; i <= nh; i++) {
            double e = i < nh ? (*hid)[i].lo : 1.0;
            if (e > s) {
                /* clip the visible piece to the screen rectangle */
                double lo = s, hi = e;
                half(ax, dx, &lo, &hi);
                half(v->width - ax, -dx, &lo, &hi);
                half(ay, dy, &lo, &hi);
                half(v->height - ay, -dy, &lo, &hi);
                if (hi > lo &&
                    push_seg(out, ax + lo * dx, ay + lo * dy, ax + hi * dx, ay + hi * dy) != 0)
                    return -1;
            }
            if (i < nh && (*hid)[i].hi > s) s = (*hid)[i].hi;
        }
    }
    return 0;
}

/* Near-plane clip of a polygon (eye space), at most 4 vertices out. */
static int clip_near(const double in[3][3], double zn, double out[4][3])
{
    int n = 0;
    for (int k = 0; k < 3; k++) {
        const double *a = in[k], *b = in[(k + 1) % 3];
        int ia = a[2] <= -zn, ib = b[2] <= -zn;
        if (ia) {
            memcpy(out[n++], a, sizeof(double) * 3);
        }
        if (ia != ib) {
            double t = (-zn - a[2]) / (b[2] - a[2]);
            for (int c = 0; c < 3; c++) out[n][c] = a[c] + t * (b[c] - a[c]);
            out[n][2] = -zn;
            n++;
        }
    }
    return n;
}

/* The segment where triangles t and u (eye space) meet, if they do: each
 * cut by the other's plane gives an interval of the planes' common line;
 * the segment is the overlap of the two. */
static int tri_meet(const double *pos, const uint32_t *t, const uint32_t *u, double A[3],
                    double B[3])
{
    const uint32_t *tr[2] = {t, u};
    double n[2][3], dir[3], lo[2], hi[2], pt[2][2][3];
    normal_of(pos, t, n[0]);
    normal_of(pos, u, n[1]);
    dir[0] = n[0][1] * n[1][2] - n[0][2] * n[1][1];
    dir[1] = n[0][2] * n[1][0] - n[0][0] * n[1][2];
    dir[2] = n[0][0] * n[1][1] - n[0][1] * n[1][0];
    if (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2] < 1e-18)
        return 0; /* parallel */
    for (int w = 0; w < 2; w++) {
        const double *b0 = pos + 3 * tr[1 - w][0], *nb = n[1 - w];
        double d[3], q[2][3];
        int nq = 0;
        for (int i = 0; i < 3; i++) {
            const double *p = pos + 3 * tr[w][i];
            d[i] = (p[0] - b0[0]) * nb[0] + (p[1] - b0[1]) * nb[1] + (p[2] - b0[2]) * nb[2];
        }
        for (int i = 0; i < 3 && nq < 2; i++) {
            int j = (i + 1) % 3;
            const double *p = pos + 3 * tr[w][i], *o = pos + 3 * tr[w][j];
            if ((d[i] < 0) == (d[j] < 0) || d[i] == d[j]) continue;
            double f = d[i] / (d[i] - d[j]);
            for (int c = 0; c < 3; c++) q[nq][c] = p[c] + f * (o[c] - p[c]);
            nq++;
        }
        if (nq < 2) return 0;
        double s0 = q[0][0] * dir[0] + q[0][1] * dir[1] + q[0][2] * dir[2];
        double s1 = q[1][0] * dir[0] + q[1][1] * dir[1] + q[1][2] * dir[2];
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

/* Cuts the eye-space segment A..B to the near plane; 0 if nothing is left. */
static int near_cut(const zs_hl_view *v, double A[3], double B[3])
{
    if (A[2] > -v->near_z && B[2] > -v->near_z) return 0;
    if (A[2] > -v->near_z || B[2] > -v->near_z) {
        double *in = A[2] > -v->near_z ? A : B, *o = in == A ? B : A;
        double t = (-v->near_z - o[2]) / (in[2] - o[2]);
        for (int c = 0; c < 3; c++) in[c] = o[c] + t * (in[c] - o[c]);
        in[2] = -v->near_z;
    }
    return 1;
}

int zs_hl_compute(const zs_hl_view *v, const double *pos, size_t nverts, const uint32_t *idx,
                  const int *group, size_t ntris, zs_hl_result *out)
{
    sface *faces = malloc((2 * ntris + 1) * sizeof *faces);
    edge_rec *er = malloc((3 * ntris + 1) * sizeof *er);
    uint8_t *front = malloc(ntris + 1);
    ival *hid = NULL;
    struct {
        double lo[3], hi[3];
    } *box = NULL;
    size_t hcap = 0, nf = 0, ne = 0, i, j;
    double cosc = cos((v->crease_deg > 0 ? v->crease_deg : 30.0) * PI / 180.0);
    int rc = -1;
    (void)nverts;
    memset(out, 0, sizeof *out);
    if (!faces || !er || !front) goto done;
    /* front faces, clipped to the near plane and projected */
    for (i = 0; i < ntris; i++) {
        double tri[3][3], poly[4][3];
        int n;
        front[i] = (uint8_t)is_front(pos, idx + 3 * i);
        if (!front[i]) continue;
        for (int k = 0; k < 3; k++) memcpy(tri[k], pos + 3 * idx[3 * i + k], sizeof tri[k]);
        n = clip_near(tri, v->near_z, poly);
        for (int k = 1; k + 1 < n; k++) {
            sface *f = &faces[nf];
            const double *p[3] = {poly[0], poly[k], poly[k + 1]};
            for (int c = 0; c < 3; c++) {
                zs_hl_project(v, p[c], &f->x[c], &f->y[c]);
                f->q[c] = 1.0 / -p[c][2];
            }
            f->sign = ((f->x[1] - f->x[0]) * (f->y[2] - f->y[0]) -
                       (f->x[2] - f->x[0]) * (f->y[1] - f->y[0])) > 0 ? 1.0 : -1.0;
            f->tri = (long)i;
            nf++;
        }
    }
    /* edges with their triangles */
    for (i = 0; i < ntris; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = idx[3 * i + k], b = idx[3 * i + (k + 1) % 3];
            er[ne].a = a < b ? a : b;
            er[ne].b = a < b ? b : a;
            er[ne].group = group[i];
            er[ne].tri = (uint32_t)i;
            ne++;
        }
    qsort(er, ne, sizeof *er, edge_cmp);
    for (i = 0; i < ne; i = j) {
        uint32_t t1, t2;
        int feature, two;
        for (j = i + 1; j < ne && er[j].a == er[i].a && er[j].b == er[i].b &&
                        er[j].group == er[i].group;
             j++)
            ;
        two = j - i == 2;
        t1 = er[i].tri;
        t2 = two ? er[i + 1].tri : t1;
        if (!two)
            feature = front[t1]; /* boundary (or non-manifold: each face alone) */
        else if (front[t1] != front[t2])
            feature = 1;
        else if (front[t1]) {
            double n1[3], n2[3];
            normal_of(pos, idx + 3 * t1, n1);
            normal_of(pos, idx + 3 * t2, n2);
            feature = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] < cosc;
        } else
            feature = 0;
        if (!two && j - i > 1) feature = 1; /* non-manifold: draw it */
        if (!feature) continue;
        {
            double A[3], B[3];
            memcpy(A, pos + 3 * er[i].a, sizeof A);
            memcpy(B, pos + 3 * er[i].b, sizeof B);
            if (!near_cut(v, A, B)) /* in front of the near plane only */
                continue;
            out->feature_edges++;
            /* the faces of its own triangles do not hide it */
            if (clip_edge(v, A, B, faces, nf, (long)t1, two ? (long)t2 : -1, &hid, &hcap, out) !=
                0)
                goto done;
        }
    }
    /* where front faces of two groups cut into each other: the segment
     * both share, clipped like an edge (boxes first: most pairs are apart) */
    box = malloc((ntris + 1) * sizeof *box);
    if (!box) goto done;
    for (i = 0; i < ntris; i++)
        for (int c = 0; c < 3; c++) {
            box[i].lo[c] = box[i].hi[c] = pos[3 * idx[3 * i] + c];
            for (int k = 1; k < 3; k++) {
                double p = pos[3 * idx[3 * i + k] + c];
                if (p < box[i].lo[c]) box[i].lo[c] = p;
                if (p > box[i].hi[c]) box[i].hi[c] = p;
            }
        }
    for (i = 0; i < ntris; i++) {
        if (!front[i]) continue;
        for (j = i + 1; j < ntris; j++) {
            double A[3], B[3];
            int c;
            if (!front[j] || group[j] == group[i]) continue;
            for (c = 0; c < 3; c++)
                if (box[i].lo[c] > box[j].hi[c] || box[j].lo[c] > box[i].hi[c]) break;
            if (c < 3 || !tri_meet(pos, idx + 3 * i, idx + 3 * j, A, B) || !near_cut(v, A, B))
                continue;
            out->meeting_lines++;
            if (clip_edge(v, A, B, faces, nf, (long)i, (long)j, &hid, &hcap, out) != 0)
                goto done;
        }
    }
    rc = 0;
done:
    free(box);
    free(faces);
    free(er);
    free(front);
    free(hid);
    if (rc != 0) zs_hl_free(out);
    return rc;
}

void zs_hl_free(zs_hl_result *r)
{
    free(r->seg);
    memset(r, 0, sizeof *r);
}

int zs_hl_write_svg(const char *path, const zs_hl_view *v, const zs_hl_result *r)
{
    FILE *f = fopen(path, "w");
    size_t i;
    if (!f) return -1;
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "viewBox=\"0 0 %d %d\" shape-rendering=\"crispEdges\">\n"
            "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n"
            "<g stroke=\"black\" stroke-width=\"1\" stroke-linecap=\"round\" fill=\"none\">\n",
            v->width, v->height, v->width, v->height, v->width, v->height);
    for (i = 0; i < r->n; i++)
        fprintf(f, "<line x1=\"%.4f\" y1=\"%.4f\" x2=\"%.4f\" y2=\"%.4f\"/>\n", r->seg[i].x0,
                r->seg[i].y0, r->seg[i].x1, r->seg[i].y1);
    fprintf(f, "</g>\n</svg>\n");
    return fclose(f) == 0 ? 0 : -1;
}
