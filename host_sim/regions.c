/* SPDX-License-Identifier: MIT */
/* Visible regions, object space, after Weiler and Atherton: every record's
 * triangle is clipped against each other record that lies in front of it
 * somewhere. The clip polygon is the other triangle cut to where its plane
 * is nearer (the depth difference of two planes is linear on the screen, so
 * that part is convex); each piece of the subject splits into the part
 * inside the clip polygon (hidden, dropped) and the parts outside, one per
 * edge of the clip polygon (kept). So a region is a union of disjoint
 * convex pieces, which holds concave results and holes alike. Double
 * precision: the records' vertices are exact in it (28.4), the cuts not. */
#include "regions.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Depth as a plane z = a x + b y + c over the screen (pixels). */
typedef struct plane {
    double a, b, c;
} plane;

static plane plane_of(const sim_rc_rec *t)
{
    double x0 = t->xy[0] / 16.0, y0 = t->xy[1] / 16.0, x1 = t->xy[2] / 16.0,
           y1 = t->xy[3] / 16.0, x2 = t->xy[4] / 16.0, y2 = t->xy[5] / 16.0;
    double z0 = t->z[0] / 1073741824.0, z1 = t->z[1] / 1073741824.0, z2 = t->z[2] / 1073741824.0;
    double d = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    plane p;
    p.a = ((z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0)) / d;
    p.b = ((x1 - x0) * (z2 - z0) - (x2 - x0) * (z1 - z0)) / d;
    p.c = z0 - p.a * x0 - p.b * y0;
    return p;
}

static double piece_area(const sim_vr_piece *p)
{
    double s = 0;
    int i;
    for (i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        s += p->x[i] * p->y[j] - p->x[j] * p->y[i];
    }
    return 0.5 * s;
}

/* Appends a point unless it repeats the last one (an edge of zero length
 * has no line to cut by). */
static unsigned long g_overflow;

static int add_point(sim_vr_piece *out, int n, double x, double y)
{
    if (n > 0 && fabs(x - out->x[n - 1]) + fabs(y - out->y[n - 1]) < 1e-9)
        return n;
    if (n >= SIM_VR_MAX_VERTS) {
        g_overflow++;
        return n;
    }
    out->x[n] = x;
    out->y[n] = y;
    return n + 1;
}

/* Keeps the part of p where f = fa x + fb y + fc < 0 (keep_negative) or
 * >= 0, into out; 0 if nothing is left. */
static int cut(const sim_vr_piece *p, double fa, double fb, double fc, int keep_negative,
               sim_vr_piece *out)
{
    double f[SIM_VR_MAX_VERTS];
    int i, n = 0;
    for (i = 0; i < p->n; i++) {
        f[i] = fa * p->x[i] + fb * p->y[i] + fc;
        if (!keep_negative)
            f[i] = -f[i];
    }
    for (i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        int in_i = f[i] < 0, in_j = f[j] < 0;
        if (in_i)
            n = add_point(out, n, p->x[i], p->y[i]);
        if (in_i != in_j) {
            double t = f[i] / (f[i] - f[j]);
            n = add_point(out, n, p->x[i] + t * (p->x[j] - p->x[i]),
                          p->y[i] + t * (p->y[j] - p->y[i]));
        }
    }
    /* and none equal to the first: no edge of zero length */
    while (n > 1 && fabs(out->x[n - 1] - out->x[0]) + fabs(out->y[n - 1] - out->y[0]) < 1e-9)
        n--;
    out->n = n;
    return n >= 3 && piece_area(out) > 1e-9;
}

/* Line through edge i of a positive-area piece, as f < 0 on its inside. */
static void edge_line(const sim_vr_piece *p, int i, double *fa, double *fb, double *fc)
{
    int j = (i + 1) % p->n;
    double dx = p->x[j] - p->x[i], dy = p->y[j] - p->y[i];
    /* inside (positive area, y down as given): cross(d, q - p_i) > 0 */
    *fa = dy;
    *fb = -dx;
    *fc = -(dy * p->x[i] - dx * p->y[i]);
}

static int push(sim_vr_region *r, const sim_vr_piece *p)
{
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 4;
        sim_vr_piece *v = realloc(r->p, cap * sizeof *v);
        if (!v)
            return -1;
        r->p = v;
        r->cap = cap;
    }
    r->p[r->n++] = *p;
    return 0;
}

/* The record's triangle with positive area, within the screen. */
static int screen_triangle(const sim_rc_rec *t, int w, int h, sim_vr_piece *out)
{
    sim_vr_piece a, b;
    int k;
    a.n = 3;
    for (k = 0; k < 3; k++) {
        a.x[k] = t->xy[2 * k] / 16.0;
        a.y[k] = t->xy[2 * k + 1] / 16.0;
    }
    if (piece_area(&a) < 0) { /* y down: the front faces come negative */
        double tx = a.x[1], ty = a.y[1];
        a.x[1] = a.x[2];
        a.y[1] = a.y[2];
        a.x[2] = tx;
        a.y[2] = ty;
    }
    /* -x < 0, x - w < 0, -y < 0, y - h < 0 */
    return cut(&a, -1, 0, 0, 1, &b) && cut(&b, 1, 0, -w, 1, &a) && cut(&a, 0, -1, 0, 1, &b) &&
           cut(&b, 0, 1, -h, 1, out);
}

/* Subtracts clip polygon c from every piece of r. */
static int subtract(sim_vr_region *r, const sim_vr_piece *c)
{
    sim_vr_region next = {0};
    size_t i;
    for (i = 0; i < r->n; i++) {
        sim_vr_piece rest = r->p[i], tmp;
        int k, inside = 1;
        for (k = 0; k < c->n && inside; k++) {
            double fa, fb, fc;
            edge_line(c, k, &fa, &fb, &fc);
            if (fabs(fa) + fabs(fb) < 1e-6)
                continue; /* a point, not an edge */
            if (cut(&rest, fa, fb, fc, 0, &tmp) && push(&next, &tmp) != 0) { /* outside: kept */
                free(next.p);
                return -1;
            }
            inside = cut(&rest, fa, fb, fc, 1, &tmp);
            rest = tmp;
        }
        /* what is left of rest lies inside c: hidden */
    }
    free(r->p);
    r->p = next.p;
    r->n = next.n;
    r->cap = next.cap;
    return 0;
}

static int boxes_meet(const sim_vr_piece *a, const sim_vr_piece *b)
{
    double al[2] = {a->x[0], a->y[0]}, ah[2] = {a->x[0], a->y[0]};
    double bl[2] = {b->x[0], b->y[0]}, bh[2] = {b->x[0], b->y[0]};
    int k;
    for (k = 1; k < a->n; k++) {
        al[0] = fmin(al[0], a->x[k]);
        ah[0] = fmax(ah[0], a->x[k]);
        al[1] = fmin(al[1], a->y[k]);
        ah[1] = fmax(ah[1], a->y[k]);
    }
    for (k = 1; k < b->n; k++) {
        bl[0] = fmin(bl[0], b->x[k]);
        bh[0] = fmax(bh[0], b->x[k]);
        bl[1] = fmin(bl[1], b->y[k]);
        bh[1] = fmax(bh[1], b->y[k]);
    }
    return al[0] < bh[0] && bl[0] < ah[0] && al[1] < bh[1] && bl[1] < ah[1];
}

int sim_vr_compute(const sim_rc_set *s, int w, int h, sim_vr_result *out)
{
    size_t i, j, n = s->n;
    sim_vr_piece *tri = malloc((n + 1) * sizeof *tri);
    char *on = malloc(n + 1);
    plane *pl = malloc((n + 1) * sizeof *pl);
    memset(out, 0, sizeof *out);
    g_overflow = 0;
    out->r = calloc(n + 1, sizeof *out->r);
    out->n = n;
    if (!tri || !on || !pl || !out->r)
        goto fail;
    for (i = 0; i < n; i++) {
        on[i] = (char)screen_triangle(&s->v[i], w, h, &tri[i]);
        pl[i] = plane_of(&s->v[i]);
    }
    for (i = 0; i < n; i++) {
        sim_vr_region *r = &out->r[i];
        int k;
        if (!on[i])
            continue; /* off the screen */
        if (push(r, &tri[i]) != 0)
            goto fail;
        for (j = 0; j < n && r->n > 0; j++) {
            sim_vr_piece c;
            double da, db, dc, spread;
            if (j == i || !on[j] || !boxes_meet(&tri[i], &tri[j]))
                continue;
            /* where j is nearer: z_j - z_i < 0 */
            da = pl[j].a - pl[i].a;
            db = pl[j].b - pl[i].b;
            dc = pl[j].c - pl[i].c;
            spread = fabs(da) * w + fabs(db) * h + fabs(dc);
            if (spread < 1e-12) { /* one plane: the first submitted is in front */
                if (j > i)
                    continue;
                c = tri[j];
            } else if (!cut(&tri[j], da, db, dc, 1, &c)) {
                continue; /* behind everywhere */
            }
            out->clips++;
            if (subtract(r, &c) != 0)
                goto fail;
        }
        for (k = 0; k < (int)r->n; k++)
            r->area += piece_area(&r->p[k]);
        out->area += r->area;
    }
    out->overflow = g_overflow;
    free(tri);
    free(on);
    free(pl);
    return g_overflow ? -2 : 0;
fail:
    free(tri);
    free(on);
    free(pl);
    sim_vr_free(out);
    return -1;
}

void sim_vr_free(sim_vr_result *res)
{
    size_t i;
    for (i = 0; res->r && i < res->n; i++)
        free(res->r[i].p);
    free(res->r);
    memset(res, 0, sizeof *res);
}

int sim_vr_write_svg(const char *path, const sim_vr_result *res, const sim_rc_set *s,
                     const uint32_t *rgb, uint32_t background, int w, int h)
{
    FILE *f = fopen(path, "w");
    size_t i, k;
    int bad;
    if (!f)
        return -1;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\">\n",
            w, h, w, h);
    fprintf(f, "<rect width=\"%d\" height=\"%d\" fill=\"#%06lx\"/>\n", w, h,
            (unsigned long)(background & 0xFFFFFFu));
    for (i = 0; i < res->n; i++) {
        const sim_vr_region *r = &res->r[i];
        if (r->n == 0)
            continue;
        fprintf(f, "<path data-tag=\"%u\" fill=\"#%06lx\" d=\"", (unsigned)s->v[i].tag,
                (unsigned long)(rgb[i] & 0xFFFFFFu));
        for (k = 0; k < r->n; k++) {
            int v;
            for (v = 0; v < r->p[k].n; v++)
                fprintf(f, "%s%.6f %.6f", v ? " L" : (k ? " M" : "M"), r->p[k].x[v], r->p[k].y[v]);
            fputs(" Z", f);
        }
        fputs("\"/>\n", f);
    }
    fputs("</svg>\n", f);
    bad = ferror(f);
    return (fclose(f) != 0 || bad) ? -1 : 0;
}
