/* SPDX-License-Identifier: MIT */
/*
 * test_area_sim: issue 15's host side, through the zspan-sim command line.
 *
 * Ray casting (`render --mode raycast`): on assimp's models and on scenes of
 * spheres written here, the grid and the grid-less caster give the same
 * image, and it differs from span mode's ID image (read back here) only
 * where the program reports near ties, never elsewhere.
 *
 * Visible regions (`render --svg`), checked against the PNGs by this file's
 * own geometry (the SVG's paths parsed back):
 *  - at every pixel centre whose owner is the same at the centre and at 16
 *    points 1/16 px around it, the owning region's tag is the ID image's
 *    pixel (background where no region holds it); the others are counted;
 *  - on a 4 x 4 grid of samples per pixel away from every edge, each sample
 *    inside a triangle of the frame (--dump-tris) lies in exactly one
 *    region and a sample outside all in none: the regions are disjoint and
 *    cover the covered area, and their areas (shoelace) add up to it;
 *  - a triangle behind a smaller one keeps a region with a hole (area: its
 *    own less the small one's, exactly), one whose corner is hidden a
 *    concave region (smaller than the hull of its pieces);
 *  - librsvg's rsvg-convert renders the SVG to the raster PNG: without
 *    antialiasing (shape-rendering crispEdges) equal at every pixel whose
 *    owner is settled as above; with it, equal (within 1 per channel) at
 *    every pixel whose square lies inside one region.
 */
#include "sim_run.h"

#include <setjmp.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <sys/stat.h>

#define PI 3.14159265358979323846

#ifndef TOP
#define TOP "."
#endif
#define OUT TOP "/build/tests/area"

static int g_failed, g_checks;

#define CHECK(cond, ...)                                                                        \
    do {                                                                                        \
        g_checks++;                                                                             \
        if (!(cond)) {                                                                          \
            g_failed++;                                                                         \
            fprintf(stderr, "%s:%d: check failed: %s\n  ", __FILE__, __LINE__, #cond);           \
            fprintf(stderr, __VA_ARGS__);                                                       \
            fputc('\n', stderr);                                                                \
        }                                                                                       \
    } while (0)

/* ---- scenes ---- */

static void write_spheres(const char *path, int n, unsigned seed)
{
    FILE *f = fopen(path, "w");
    int k, i, j, v = 0;
    const int S = 20, R = 11;
    srand(seed);
    for (k = 0; f && k < n; k++) {
        double c[3], rad = 0.25 + 0.35 * rand() / (double)RAND_MAX;
        for (i = 0; i < 3; i++) c[i] = 4.0 * rand() / (double)RAND_MAX - 2.0;
        int base = v;
        for (i = 0; i <= R; i++)
            for (j = 0; j < S; j++) {
                double th = PI * i / R, ph = 2 * PI * j / S;
                fprintf(f, "v %.5f %.5f %.5f\n", c[0] + rad * sin(th) * cos(ph), c[1] + rad * cos(th),
                        c[2] - rad * sin(th) * sin(ph));
                v++;
            }
        for (i = 0; i < R; i++)
            for (j = 0; j < S; j++) {
                int a = base + i * S + j + 1, b = base + i * S + (j + 1) % S + 1, cc = a + S,
                    d = b + S;
                if (i > 0) fprintf(f, "f %d %d %d\n", a, b, cc);
                if (i < R - 1) fprintf(f, "f %d %d %d\n", b, d, cc);
            }
    }
    if (f) fclose(f);
}

static void write_obj(const char *path, const double (*v)[3], int nv, const int (*t)[3], int nt)
{
    FILE *f = fopen(path, "w");
    int i;
    for (i = 0; f && i < nv; i++) fprintf(f, "v %.6f %.6f %.6f\n", v[i][0], v[i][1], v[i][2]);
    for (i = 0; f && i < nt; i++) fprintf(f, "f %d %d %d\n", t[i][0] + 1, t[i][1] + 1, t[i][2] + 1);
    if (f) fclose(f);
}

/* ---- the SVG's regions ---- */

typedef struct poly {
    int n;
    double x[64], y[64];
} poly;

typedef struct region {
    unsigned tag;
    uint32_t rgb;
    poly *p;
    int n;
    double area;
} region;

typedef struct regions {
    region *r;
    int n;
    double area;
} regions;

static double poly_area(const poly *p)
{
    double s = 0;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        s += p->x[i] * p->y[j] - p->x[j] * p->y[i];
    }
    return 0.5 * s;
}

static int read_svg(const char *path, regions *rs)
{
    FILE *f = fopen(path, "r");
    char *line = NULL;
    size_t cap = 0;
    memset(rs, 0, sizeof *rs);
    if (!f) return -1;
    while (getline(&line, &cap, f) > 0) {
        unsigned tag, rgb;
        char *d;
        if (sscanf(line, "<path data-tag=\"%u\" fill=\"#%x\"", &tag, &rgb) != 2) continue;
        d = strstr(line, " d=\"");
        if (!d) continue;
        d += 4;
        rs->r = realloc(rs->r, (size_t)(rs->n + 1) * sizeof *rs->r);
        region *r = &rs->r[rs->n++];
        memset(r, 0, sizeof *r);
        r->tag = tag;
        r->rgb = rgb;
        while (*d && *d != '"') {
            char op;
            double x, y;
            int used;
            while (*d == ' ') d++;
            op = *d++;
            if (op == 'Z') continue;
            if (sscanf(d, "%lf %lf%n", &x, &y, &used) != 2) break;
            d += used;
            if (op == 'M') {
                r->p = realloc(r->p, (size_t)(r->n + 1) * sizeof *r->p);
                r->p[r->n++].n = 0;
            }
            poly *p = &r->p[r->n - 1];
            if (p->n < 64) {
                p->x[p->n] = x;
                p->y[p->n] = y;
                p->n++;
            }
        }
        for (int k = 0; k < r->n; k++) r->area += poly_area(&r->p[k]);
        rs->area += r->area;
    }
    free(line);
    fclose(f);
    return 0;
}

static void free_regions(regions *rs)
{
    for (int i = 0; i < rs->n; i++) free(rs->r[i].p);
    free(rs->r);
    memset(rs, 0, sizeof *rs);
}

/* Distance-signed inside test of a convex polygon of either orientation:
 * the least signed distance to its edges (> 0 inside). */
static double inside_margin(const poly *p, double x, double y)
{
    double s = poly_area(p) > 0 ? 1 : -1, m = 1e30;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        double dx = p->x[j] - p->x[i], dy = p->y[j] - p->y[i], len = hypot(dx, dy);
        if (len == 0) continue;
        double c = s * (dx * (y - p->y[i]) - dy * (x - p->x[i])) / len;
        m = c < m ? c : m;
    }
    return m;
}

/* Pieces binned into cells of 8 x 8 pixels. */
typedef struct pgrid {
    int gw, gh;
    int *start, *item; /* item: region index * 65536 + piece index */
} pgrid;

static void pgrid_build(pgrid *g, const regions *rs, int w, int h)
{
    g->gw = (w + 7) / 8;
    g->gh = (h + 7) / 8;
    int nc = g->gw * g->gh, total = 0;
    g->start = calloc((size_t)nc + 1, sizeof *g->start);
    for (int pass = 0; pass < 2; pass++) {
        int *fill = pass ? calloc((size_t)nc, sizeof *fill) : NULL;
        for (int i = 0; i < rs->n; i++)
            for (int k = 0; k < rs->r[i].n; k++) {
                const poly *p = &rs->r[i].p[k];
                double lx = 1e30, hx = -1e30, ly = 1e30, hy = -1e30;
                for (int v = 0; v < p->n; v++) {
                    lx = fmin(lx, p->x[v]); hx = fmax(hx, p->x[v]);
                    ly = fmin(ly, p->y[v]); hy = fmax(hy, p->y[v]);
                }
                int cx0 = (int)floor(lx / 8), cx1 = (int)floor(hx / 8), cy0 = (int)floor(ly / 8),
                    cy1 = (int)floor(hy / 8);
                for (int cy = cy0 < 0 ? 0 : cy0; cy <= cy1 && cy < g->gh; cy++)
                    for (int cx = cx0 < 0 ? 0 : cx0; cx <= cx1 && cx < g->gw; cx++) {
                        int c = cy * g->gw + cx;
                        if (!pass) g->start[c + 1]++;
                        else g->item[g->start[c] + fill[c]++] = i * 65536 + k;
                    }
            }
        if (!pass) {
            for (int c = 0; c < nc; c++) g->start[c + 1] += g->start[c];
            total = g->start[nc];
            g->item = malloc((size_t)(total + 1) * sizeof *g->item);
        }
        free(fill);
    }
}

/* Regions holding the point with a margin above eps (count), the last one's
 * tag in *tag; *near set when some piece edge is within eps. */
static int owners(const regions *rs, const pgrid *g, double x, double y, double eps,
                  unsigned *tag, int *near)
{
    int cx = (int)floor(x / 8), cy = (int)floor(y / 8), n = 0, last = -1;
    *tag = 0;
    if (cx < 0 || cy < 0 || cx >= g->gw || cy >= g->gh) return 0;
    int c = cy * g->gw + cx;
    for (int k = g->start[c]; k < g->start[c + 1]; k++) {
        int ri = g->item[k] / 65536, pi = g->item[k] % 65536;
        double m = inside_margin(&rs->r[ri].p[pi], x, y);
        if (fabs(m) <= eps) *near = 1;
        if (m > eps && ri != last) {
            n++;
            last = ri;
            *tag = rs->r[ri].tag;
        }
    }
    return n;
}

static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(px - ax - t * dx, py - ay - t * dy);
}

/* Some piece edge within rad of the point (the cells around it searched). */
static int boundary_near(const regions *rs, const pgrid *g, double x, double y, double rad)
{
    for (int k = 0; k < 4; k++) {
        int cx = (int)floor((x + (k & 1 ? rad : -rad)) / 8), cy = (int)floor((y + (k & 2 ? rad : -rad)) / 8);
        if (cx < 0 || cy < 0 || cx >= g->gw || cy >= g->gh) continue;
        int c = cy * g->gw + cx;
        for (int i = g->start[c]; i < g->start[c + 1]; i++) {
            const poly *p = &rs->r[g->item[i] / 65536].p[g->item[i] % 65536];
            for (int v = 0; v < p->n; v++) {
                int w = (v + 1) % p->n;
                if (seg_dist(x, y, p->x[v], p->y[v], p->x[w], p->y[w]) <= rad) return 1;
            }
        }
    }
    return 0;
}

/* The owner at a centre if it is the same at radius rad around, else -1. */
static long settled_owner(const regions *rs, const pgrid *g, double x, double y, double rad)
{
    unsigned t0, t;
    int near = 0;
    if (owners(rs, g, x, y, 1e-9, &t0, &near) > 1) return -2;
    if (rad <= 0.1 && boundary_near(rs, g, x, y, rad)) return -1; /* exact, for 1/16 px */
    for (int k = 0; k < 16; k++) {
        double a = 2 * PI * k / 16;
        int nn = 0;
        if (owners(rs, g, x + rad * cos(a), y + rad * sin(a), 1e-9, &t, &nn) > 1 || t != t0)
            return -1;
    }
    return t0;
}

/* ---- frame triangles (--dump-tris) ---- */

typedef struct tris {
    double (*v)[6];
    double (*z)[3];
    unsigned *tag;
    int n;
} tris;

static void read_tris(const char *path, tris *ts)
{
    FILE *f = fopen(path, "r");
    unsigned tag;
    double a[9];
    memset(ts, 0, sizeof *ts);
    while (f && fscanf(f, "%u %lf %lf %lf %lf %lf %lf %lf %lf %lf", &tag, &a[0], &a[1], &a[2], &a[3],
                       &a[4], &a[5], &a[6], &a[7], &a[8]) == 10) {
        ts->v = realloc(ts->v, (size_t)(ts->n + 1) * sizeof *ts->v);
        ts->z = realloc(ts->z, (size_t)(ts->n + 1) * sizeof *ts->z);
        ts->tag = realloc(ts->tag, (size_t)(ts->n + 1) * sizeof *ts->tag);
        ts->tag[ts->n] = tag;
        ts->z[ts->n][0] = a[2];
        ts->z[ts->n][1] = a[5];
        ts->z[ts->n][2] = a[8];
        double *t = ts->v[ts->n++];
        t[0] = a[0]; t[1] = a[1]; t[2] = a[3]; t[3] = a[4]; t[4] = a[6]; t[5] = a[7];
    }
    if (f) fclose(f);
}

/* Least depth at (x, y) of the frame's triangles of one tag holding it. */
static int tag_depth(const tris *ts, unsigned tag, double x, double y, double *z)
{
    int found = 0;
    for (int t = 0; t < ts->n; t++) {
        const double *v = ts->v[t];
        if (ts->tag[t] != tag) continue;
        double d = (v[2] - v[0]) * (v[5] - v[1]) - (v[4] - v[0]) * (v[3] - v[1]);
        if (d == 0) continue;
        double l1 = ((x - v[0]) * (v[5] - v[1]) - (v[4] - v[0]) * (y - v[1])) / d;
        double l2 = ((v[2] - v[0]) * (y - v[1]) - (x - v[0]) * (v[3] - v[1])) / d;
        if (l1 < -1e-9 || l2 < -1e-9 || l1 + l2 > 1 + 1e-9) continue;
        double zz = ts->z[t][0] + l1 * (ts->z[t][1] - ts->z[t][0]) + l2 * (ts->z[t][2] - ts->z[t][0]);
        if (!found || zz < *z) *z = zz;
        found = 1;
    }
    return found;
}

/* ---- the checks of one --svg scene ---- */

static void check_svg_scene(const char *name, const char *file_args)
{
    char svg[512], png[512], ids[512], dump[512];
    run_result rr;
    image im_rgb, im_ids, im_crisp, im_aa;
    regions rs;
    tris ts;
    pgrid g;
    snprintf(svg, sizeof svg, OUT "/%s.svg", name);
    snprintf(png, sizeof png, OUT "/%s.png", name);
    snprintf(ids, sizeof ids, OUT "/%s_ids.png", name);
    snprintf(dump, sizeof dump, OUT "/%s.tris", name);
    run(&rr, SIM " render %s --svg %s --out %s --dump-tris %s", file_args, svg, png, dump);
    CHECK(rr.exited && rr.status == 0, "%s: render --svg: %s", name, rr.out);
    run(&rr, SIM " render %s --shade ids --out %s", file_args, ids);
    CHECK(rr.exited && rr.status == 0, "%s: render --shade ids: %s", name, rr.out);
    if (read_png(png, &im_rgb) || read_png(ids, &im_ids) || read_svg(svg, &rs)) {
        CHECK(0, "%s: outputs missing", name);
        return;
    }
    read_tris(dump, &ts);
    int w = im_ids.w, h = im_ids.h;
    pgrid_build(&g, &rs, w, h);
    /* the frame's triangles as one-piece regions, binned the same way */
    regions trs;
    pgrid tg;
    trs.n = ts.n;
    trs.area = 0;
    trs.r = calloc((size_t)ts.n + 1, sizeof *trs.r);
    for (int t = 0; t < ts.n; t++) {
        trs.r[t].tag = (unsigned)t + 1;
        trs.r[t].n = 1;
        trs.r[t].p = calloc(1, sizeof(poly));
        trs.r[t].p->n = 3;
        for (int k = 0; k < 3; k++) {
            trs.r[t].p->x[k] = ts.v[t][2 * k];
            trs.r[t].p->y[k] = ts.v[t][2 * k + 1];
        }
    }
    pgrid_build(&tg, &trs, w, h);
    /* 1. pixel centres */
    long settled = 0, unsettled = 0, bad = 0, ties = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            long o = settled_owner(&rs, &g, x + 0.5, y + 0.5, 1.0 / 16);
            if (o < 0) { unsettled++; continue; }
            settled++;
            uint32_t want = pixel(&im_ids, y * w + x);
            if ((uint32_t)o == want) continue;
            /* two planes within 2^-20 of each other there: a near tie */
            double za, zb;
            if (o && want && tag_depth(&ts, (unsigned)o, x + 0.5, y + 0.5, &za) &&
                tag_depth(&ts, want, x + 0.5, y + 0.5, &zb) && fabs(za - zb) < 1.0 / 1048576) {
                ties++;
                continue;
            }
            if (bad++ < 3)
                fprintf(stderr, "%s: pixel (%d,%d): region tag %ld, ID image %u\n", name, x, y, o,
                        want);
        }
    CHECK(bad == 0, "%s: %ld settled pixel centres differ from the ID image", name, bad);
    /* 2. samples: disjoint, covering */
    long samples = 0, in_union = 0, wrong = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int s = 0; s < 16; s++) {
                /* off the 1/16 px lattice the vertices are snapped to */
                double px = x + (s % 4 + 0.5) / 4 + 0.01234, py = y + (s / 4 + 0.5) / 4 + 0.00731;
                int near = 0, edge = 0;
                unsigned tag;
                int inside = owners(&trs, &tg, px, py, 1e-6, &tag, &edge) > 0;
                int n = owners(&rs, &g, px, py, 1e-6, &tag, &near);
                if (edge || near) continue;
                samples++;
                in_union += inside;
                if (n != inside && wrong++ < 3)
                    fprintf(stderr, "%s: sample (%.3f,%.3f) in %d regions, in the triangles: %d\n",
                            name, px, py, n, inside);
            }
    CHECK(wrong == 0, "%s: %ld samples are in the wrong number of regions", name, wrong);
    double union_area = in_union / 16.0;
    CHECK(fabs(rs.area - union_area) <= 0.01 * union_area + 1.0,
          "%s: regions' area %.4f, triangles' covered area %.4f (samples)", name, rs.area,
          union_area);
    /* 3. rsvg-convert, crisp and antialiased */
    char crisp_svg[512], crisp_png[512], aa_png[512];
    snprintf(crisp_svg, sizeof crisp_svg, OUT "/%s_crisp.svg", name);
    snprintf(crisp_png, sizeof crisp_png, OUT "/%s_crisp.png", name);
    snprintf(aa_png, sizeof aa_png, OUT "/%s_rsvg.png", name);
    run(&rr, "sed 's/<svg /<svg shape-rendering=\"crispEdges\" /' %s > %s && rsvg-convert %s -o %s "
             "&& rsvg-convert %s -o %s",
        svg, crisp_svg, crisp_svg, crisp_png, svg, aa_png);
    CHECK(rr.exited && rr.status == 0, "%s: rsvg-convert: %s", name, rr.out);
    long crisp_bad = 0, crisp_n = 0, aa_bad = 0, aa_n = 0;
    if (read_png(crisp_png, &im_crisp) == 0 && read_png(aa_png, &im_aa) == 0 &&
        im_crisp.w == w && im_aa.w == w && im_crisp.bytes == 3 && im_aa.bytes == 3) {
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                /* without antialiasing a pixel is lit by the region holding
                 * its centre, away from slivers: settled 3/4 px around */
                long o = settled_owner(&rs, &g, x + 0.5, y + 0.5, 0.75);
                if (o >= 0) {
                    crisp_n++;
                    if (pixel(&im_crisp, i) != pixel(&im_rgb, i) && crisp_bad++ < 3)
                        fprintf(stderr, "%s: crisp rsvg pixel (%d,%d) %06x, PNG %06x\n", name, x,
                                y, pixel(&im_crisp, i), pixel(&im_rgb, i));
                }
                /* the whole square in one region: 5 x 5 samples, no edge near */
                unsigned t0 = 0, t;
                int one = 1;
                for (int s = 0; s < 25 && one; s++) {
                    int near = 0;
                    int n = owners(&rs, &g, x + 0.02 + 0.24 * (s % 5), y + 0.02 + 0.24 * (s / 5),
                                   0.3, &t, &near);
                    if (near || n > 1 || (s && t != t0)) one = 0;
                    if (!s) t0 = t;
                }
                if (!one) continue;
                aa_n++;
                uint32_t a = pixel(&im_aa, i), b = pixel(&im_rgb, i);
                for (int k = 0; k < 24; k += 8)
                    if (abs((int)((a >> k) & 255) - (int)((b >> k) & 255)) > 1) {
                        if (aa_bad++ < 3)
                            fprintf(stderr, "%s: rsvg pixel (%d,%d) %06x, PNG %06x\n", name, x,
                                    y, a, b);
                        break;
                    }
            }
        free_image(&im_crisp);
        free_image(&im_aa);
    } else {
        CHECK(0, "%s: rsvg-convert's PNGs unreadable", name);
    }
    CHECK(crisp_bad == 0, "%s: %ld of %ld settled pixels differ in the crisp rsvg image", name,
          crisp_bad, crisp_n);
    CHECK(aa_bad == 0, "%s: %ld of %ld interior pixels differ in the antialiased rsvg image",
          name, aa_bad, aa_n);
    printf("test_area_sim: svg %s: %d regions, area %.3f px^2 (samples %.3f), %ld settled pixel "
           "centres equal to the ID image (%ld of them near ties, planes within 2^-20), %ld within "
           "1/16 px of a boundary; %ld samples in one region each; rsvg-convert: %ld crisp "
           "pixels, %ld antialiased interior pixels equal\n",
           name, rs.n, rs.area, union_area, settled - ties, ties, unsettled, samples,
           crisp_n - crisp_bad, aa_n - aa_bad);
    free(g.start);
    free(g.item);
    free(tg.start);
    free(tg.item);
    free_regions(&trs);
    free(ts.v);
    free(ts.z);
    free(ts.tag);
    free_regions(&rs);
    free_image(&im_rgb);
    free_image(&im_ids);
}

static const region *region_of(const regions *rs, unsigned tag)
{
    for (int i = 0; i < rs->n; i++)
        if (rs->r[i].tag == tag) return &rs->r[i];
    return NULL;
}

/* A hole and a concave region, by their areas. */
static void check_shapes(void)
{
    static const double v[][3] = {
        {-1.2, -1.0, 0}, {1.2, -1.0, 0}, {0, 1.2, 0},             /* big, behind */
        {-0.2, -0.3, 0.5}, {0.25, -0.3, 0.5}, {0.05, 0.2, 0.5},    /* small, in front: a hole */
        {0.3, -1.3, 0.3}, {1.4, -1.3, 0.3}, {0.9, 0.0, 0.3},       /* over a corner: concave */
    };
    static const int t[][3] = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    char obj[512], svg[512];
    run_result rr;
    regions rs;
    snprintf(obj, sizeof obj, OUT "/shapes.obj");
    snprintf(svg, sizeof svg, OUT "/shapes_only.svg");
    write_obj(obj, v, 9, t, 3);
    run(&rr, SIM " render %s --svg %s --out " OUT "/shapes_only.png", obj, svg);
    CHECK(rr.exited && rr.status == 0, "shapes: %s", rr.out);
    if (read_svg(svg, &rs) != 0) {
        CHECK(0, "shapes: no svg");
        return;
    }
    const region *big = region_of(&rs, 1), *small = region_of(&rs, 2), *corner = region_of(&rs, 3);
    CHECK(big && small && corner, "shapes: %d regions", rs.n);
    if (big && small && corner) {
        /* whole areas from the SVG's own unhidden triangles */
        double a_small = small->area, a_corner = corner->area;
        /* the small one lies wholly inside the big one: a hole */
        int in_hole = 0, around = 0;
        double cx = 0, cy = 0;
        for (int k = 0; k < small->p[0].n; k++) { cx += small->p[0].x[k]; cy += small->p[0].y[k]; }
        cx /= small->p[0].n;
        cy /= small->p[0].n;
        for (int k = 0; k < big->n; k++) {
            in_hole |= inside_margin(&big->p[k], cx, cy) > 0;
            for (int a = 0; a < 8; a++)
                around += inside_margin(&big->p[k], cx + 30 * cos(a * PI / 4),
                                        cy + 30 * sin(a * PI / 4)) > 0;
        }
        CHECK(!in_hole && around == 8, "shapes: the small triangle's centre in the big region %d, "
              "points around it %d of 8", in_hole, around);
        /* the big triangle's own area, from the dump of its record */
        char dump[512];
        tris ts;
        snprintf(dump, sizeof dump, OUT "/shapes.tris");
        run(&rr, SIM " render %s --dump-tris %s --out " OUT "/shapes_d.png", obj, dump);
        read_tris(dump, &ts);
        CHECK(ts.n == 3, "shapes: %d records", ts.n);
        if (ts.n == 3) {
            poly p[3];
            for (int i = 0; i < 3; i++) {
                p[i].n = 3;
                for (int k = 0; k < 3; k++) { p[i].x[k] = ts.v[i][2 * k]; p[i].y[k] = ts.v[i][2 * k + 1]; }
            }
            double whole = fabs(poly_area(&p[0])), hole = fabs(poly_area(&p[1]));
            CHECK(fabs(a_small - hole) < 1e-6, "shapes: small region %.6f, its triangle %.6f",
                  a_small, hole);
            CHECK(fabs(a_corner - fabs(poly_area(&p[2]))) < 1e-6, "shapes: corner region %.6f",
                  a_corner);
            /* big = whole - hole - overlap with the corner triangle: concave */
            double visible = big->area;
            CHECK(visible < whole - hole - 1.0 && visible > 0.5 * whole,
                  "shapes: big region %.4f of %.4f (hole %.4f)", visible, whole, hole);
            printf("test_area_sim: shapes: big triangle %.3f px^2, visible %.3f (a hole of %.3f "
                   "and a hidden corner of %.3f) in %d convex pieces\n",
                   whole, visible, hole, whole - hole - visible, big->n);
        }
        free(ts.v);
        free(ts.z);
        free(ts.tag);
    }
    free_regions(&rs);
}

/* ---- ray casting ---- */

static void check_raycast(const char *name, const char *file_args)
{
    char a[512], b[512], ids[512];
    run_result rr;
    image ia, ib, ii;
    unsigned long recs, tests, differ, covered_px, near, other;
    snprintf(a, sizeof a, OUT "/%s_rc.png", name);
    snprintf(b, sizeof b, OUT "/%s_rc0.png", name);
    snprintf(ids, sizeof ids, OUT "/%s_span.png", name);
    run(&rr, SIM " render %s --mode raycast --shade ids --out %s", file_args, a);
    CHECK(rr.exited && rr.status == 0, "%s: raycast: %s", name, rr.out);
    const char *line = strstr(rr.out, "raycast: ");
    CHECK(line && sscanf(line, "raycast: %lu records, grid 8x8 px, %lu ray-record tests; %lu of "
                               "%lu covered pixels differ from span mode, %lu of them near ties "
                               "(depths within 2^-20), %lu other",
                         &recs, &tests, &differ, &covered_px, &near, &other) == 6,
          "%s: no raycast line: %s", name, rr.out);
    run(&rr, SIM " render %s --mode raycast --grid 0 --shade ids --out %s", file_args, b);
    CHECK(rr.exited && rr.status == 0, "%s: raycast --grid 0: %s", name, rr.out);
    run(&rr, SIM " render %s --shade ids --out %s", file_args, ids);
    if (read_png(a, &ia) || read_png(b, &ib) || read_png(ids, &ii)) {
        CHECK(0, "%s: images missing", name);
        return;
    }
    CHECK(same_image(&ia, &ib), "%s: the grid changes the ray-cast image", name);
    long d = 0;
    for (int i = 0; i < ia.w * ia.h; i++) d += pixel(&ia, i) != pixel(&ii, i);
    CHECK(d == (long)differ && other == 0,
          "%s: %ld pixels differ from span mode (reported %lu, %lu not near ties)", name, d,
          differ, other);
    printf("test_area_sim: raycast %s: %lu records, %lu covered pixels, %lu differ from span "
           "mode (%lu near ties, %lu other); grid and no grid equal\n",
           name, recs, covered_px, differ, near, other);
    free_image(&ia);
    free_image(&ib);
    free_image(&ii);
}

static void test_all(void **state)
{
    char path[512], args[768];
    (void)state;
    mkdir(TOP "/build", 0777);
    mkdir(TOP "/build/tests", 0777);
    mkdir(OUT, 0777);
    snprintf(path, sizeof path, OUT "/spheres.obj");
    write_spheres(path, 10, 15);
    snprintf(args, sizeof args, "%s --fit --eye 0,0,2.2 --size 160x120", path);
    check_raycast("spheres", args);
    check_svg_scene("spheres", args);
    static const char *models[] = {"Collada/duck.dae", "OBJ/spider.obj", "OBJ/WusonOBJ.obj"};
    int loaded = 0;
    for (int i = 0; i < 3; i++) {
        FILE *f;
        snprintf(path, sizeof path, ASSIMP_MODELS "/%s", models[i]);
        if (!(f = fopen(path, "r"))) continue;
        fclose(f);
        loaded++;
        snprintf(args, sizeof args, "%s --fit --eye 0.4,0.3,1.6", path);
        const char *name = i == 0 ? "duck" : i == 1 ? "spider" : "wuson";
        check_raycast(name, args);
        if (i != 1) check_svg_scene(name, args);
    }
    CHECK(loaded > 0, "no assimp test model found");
    /* penetrating pair and the shapes scene through all the checks */
    static const double pv[][3] = {{-1, -0.8, -0.6}, {1, -0.8, 0.6}, {0, 1, 0},
                                   {-1, -0.5, 0.5},  {1, -0.3, -0.5}, {-0.2, 0.9, 0.1}};
    static const int pt[][3] = {{0, 1, 2}, {3, 4, 5}};
    snprintf(path, sizeof path, OUT "/pierce.obj");
    write_obj(path, pv, 6, pt, 2);
    snprintf(args, sizeof args, "%s --two-sided", path);
    check_svg_scene("pierce", args);
    check_shapes();
    snprintf(args, sizeof args, OUT "/shapes.obj");
    check_svg_scene("shapes", args);
    (void)covered; /* sim_run.h's, unused here */
    printf("test_area_sim: %d checks, %d failed\n", g_checks, g_failed);
    assert_int_equal(g_failed, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_all),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
