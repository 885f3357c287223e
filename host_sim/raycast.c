/* SPDX-License-Identifier: MIT */
/* A ray caster over the core's snapped records: one ray per pixel centre,
 * in double precision, independent of the core's fixed-point planes; with a
 * uniform grid of screen cells so that a ray meets only the records whose
 * bounding box reaches its cell. */
#include "raycast.h"

#include <stdlib.h>
#include <string.h>

void sim_rc_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    sim_rc_set *s = user;
    sim_rc_rec *t;
    int k;
    if (s->dump) {
        fprintf(s->dump, "%u", (unsigned)tag);
        for (k = 0; k < 3; k++)
            fprintf(s->dump, " %.4f %.4f %.17g", (double)xy[2 * k] / 16.0,
                    (double)xy[2 * k + 1] / 16.0, (double)z[k] / 1073741824.0);
        fputc('\n', s->dump);
    }
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 256;
        sim_rc_rec *v = realloc(s->v, cap * sizeof *v);
        if (!v) {
            s->failed = 1;
            return;
        }
        s->v = v;
        s->cap = cap;
    }
    t = &s->v[s->n++];
    memcpy(t->xy, xy, sizeof t->xy);
    memcpy(t->z, z, sizeof t->z);
    t->tag = tag;
}

void sim_rc_free(sim_rc_set *s)
{
    free(s->v);
    s->v = NULL;
    s->n = s->cap = 0;
}

void sim_rc_image_free(sim_rc_image *im)
{
    free(im->tag);
    free(im->rec);
    free(im->z1);
    memset(im, 0, sizeof *im);
}

static int64_t area2(const int32_t xy[6])
{
    return ((int64_t)xy[2] - xy[0]) * ((int64_t)xy[5] - xy[1]) -
           ((int64_t)xy[4] - xy[0]) * ((int64_t)xy[3] - xy[1]);
}

/* The centre (16 px + 8, 16 py + 8) inside, a boundary point belonging to
 * left edges and to top (horizontal, interior below) edges. */
static int covers(const int32_t xy[6], int px, int py)
{
    int64_t a = area2(xy), s = a > 0 ? 1 : -1;
    int64_t cx = 16 * (int64_t)px + 8, cy = 16 * (int64_t)py + 8;
    int k;
    if (a == 0)
        return 0;
    for (k = 0; k < 3; k++) {
        int64_t ax = xy[2 * k], ay = xy[2 * k + 1];
        int64_t dx = xy[(2 * k + 2) % 6] - ax, dy = xy[(2 * k + 3) % 6] - ay;
        int64_t e = (dx * (cy - ay) - dy * (cx - ax)) * s;
        if (e < 0)
            return 0;
        if (e == 0) {
            int64_t nx = -dy * s, ny = dx * s; /* inward normal */
            if (!(nx > 0 || (nx == 0 && ny > 0)))
                return 0;
        }
    }
    return 1;
}

static double depth_at(const sim_rc_rec *t, int px, int py)
{
    double x0 = t->xy[0], y0 = t->xy[1], x1 = t->xy[2], y1 = t->xy[3], x2 = t->xy[4],
           y2 = t->xy[5];
    double cx = 16.0 * px + 8, cy = 16.0 * py + 8, a = (double)area2(t->xy);
    double l1 = ((cx - x0) * (y2 - y0) - (x2 - x0) * (cy - y0)) / a;
    double l2 = ((x1 - x0) * (cy - y0) - (cx - x0) * (y1 - y0)) / a;
    double z0 = t->z[0] / 1073741824.0, z1 = t->z[1] / 1073741824.0, z2 = t->z[2] / 1073741824.0;
    return z0 + l1 * (z1 - z0) + l2 * (z2 - z0);
}

static int same_vertices(const sim_rc_rec *a, const sim_rc_rec *b)
{
    int used[3] = {0, 0, 0}, i, j;
    for (i = 0; i < 3; i++) {
        int found = 0;
        for (j = 0; j < 3 && !found; j++)
            if (!used[j] && a->xy[2 * i] == b->xy[2 * j] && a->xy[2 * i + 1] == b->xy[2 * j + 1] &&
                a->z[i] == b->z[j])
                used[j] = found = 1;
        if (!found)
            return 0;
    }
    return 1;
}

/* Pixels whose centres the record's bounding box holds, clipped; 0 if none. */
static int pixel_box(const sim_rc_rec *t, int w, int h, int b[4])
{
    int64_t lo[2], hi[2];
    int k, a;
    for (a = 0; a < 2; a++) {
        lo[a] = hi[a] = t->xy[a];
        for (k = 1; k < 3; k++) {
            int64_t v = t->xy[2 * k + a];
            lo[a] = v < lo[a] ? v : lo[a];
            hi[a] = v > hi[a] ? v : hi[a];
        }
        /* centres 16 i + 8 in [lo, hi]: i from ceil((lo - 8) / 16) to floor((hi - 8) / 16) */
        lo[a] = lo[a] - 8 >= 0 ? (lo[a] - 8 + 15) / 16 : -((8 - lo[a]) / 16);
        hi[a] = hi[a] - 8 >= 0 ? (hi[a] - 8) / 16 : -((8 - hi[a] + 15) / 16);
    }
    b[0] = (int)(lo[0] < 0 ? 0 : lo[0]);
    b[1] = (int)(lo[1] < 0 ? 0 : lo[1]);
    b[2] = (int)(hi[0] >= w ? w - 1 : hi[0]);
    b[3] = (int)(hi[1] >= h ? h - 1 : hi[1]);
    return b[0] <= b[2] && b[1] <= b[3];
}

/* The nearest record at one centre among list[0 .. n) (ascending; NULL:
 * all records). */
static void cast_one(const sim_rc_set *s, const uint32_t *list, size_t n, int x, int y,
                     sim_rc_image *im)
{
    size_t p = (size_t)y * (size_t)im->w + (size_t)x, i;
    int32_t best = -1;
    double z1 = 2.0;
    for (i = 0; i < n; i++) {
        uint32_t k = list ? list[i] : (uint32_t)i;
        const sim_rc_rec *t = &s->v[k];
        double z;
        im->tests++;
        if (!covers(t->xy, x, y))
            continue;
        z = depth_at(t, x, y);
        /* strict: the first of equal depths keeps it; so does the first of
         * exact copies, whatever the last bits of the two evaluations say */
        if (z < z1 && !(best >= 0 && same_vertices(t, &s->v[best]))) {
            z1 = z;
            best = (int32_t)k;
        }
    }
    im->rec[p] = best;
    im->tag[p] = best >= 0 ? s->v[best].tag : 0;
    im->z1[p] = z1;
}

int sim_rc_depth_of(const sim_rc_set *s, uint16_t tag, int x, int y, double *z)
{
    size_t i;
    int found = 0;
    for (i = 0; i < s->n; i++)
        if (s->v[i].tag == tag && covers(s->v[i].xy, x, y)) {
            double d = depth_at(&s->v[i], x, y);
            if (!found || d < *z)
                *z = d;
            found = 1;
        }
    return found;
}

int sim_raycast(const sim_rc_set *s, int w, int h, int cell, sim_rc_image *im)
{
    size_t np = (size_t)w * (size_t)h, i;
    uint32_t *start = NULL, *list = NULL;
    int gw = 1, gh = 1, x, y, rc = -1;
    memset(im, 0, sizeof *im);
    im->w = w;
    im->h = h;
    im->tag = malloc(np * sizeof *im->tag);
    im->rec = malloc(np * sizeof *im->rec);
    im->z1 = malloc(np * sizeof *im->z1);
    if (!im->tag || !im->rec || !im->z1)
        goto out;
    if (cell <= 0) { /* every ray meets every record */
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                cast_one(s, NULL, s->n, x, y, im);
        rc = 0;
        goto out;
    }
    /* the grid: each cell lists the records whose box reaches it, in
     * submission order (counted, then filled) */
    gw = (w + cell - 1) / cell;
    gh = (h + cell - 1) / cell;
    start = calloc((size_t)gw * (size_t)gh + 1, sizeof *start);
    if (!start)
        goto out;
    for (i = 0; i < s->n; i++) {
        int b[4], cx, cy;
        if (!pixel_box(&s->v[i], w, h, b))
            continue;
        for (cy = b[1] / cell; cy <= b[3] / cell; cy++)
            for (cx = b[0] / cell; cx <= b[2] / cell; cx++)
                start[(size_t)cy * (size_t)gw + (size_t)cx + 1]++;
    }
    for (i = 1; i <= (size_t)gw * (size_t)gh; i++)
        start[i] += start[i - 1];
    list = malloc(((size_t)start[(size_t)gw * (size_t)gh] + 1) * sizeof *list);
    if (!list)
        goto out;
    {
        uint32_t *fill = malloc(((size_t)gw * (size_t)gh + 1) * sizeof *fill);
        if (!fill)
            goto out;
        memcpy(fill, start, ((size_t)gw * (size_t)gh + 1) * sizeof *fill);
        for (i = 0; i < s->n; i++) {
            int b[4], cx, cy;
            if (!pixel_box(&s->v[i], w, h, b))
                continue;
            for (cy = b[1] / cell; cy <= b[3] / cell; cy++)
                for (cx = b[0] / cell; cx <= b[2] / cell; cx++)
                    list[fill[(size_t)cy * (size_t)gw + (size_t)cx]++] = (uint32_t)i;
        }
        free(fill);
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t c = (size_t)(y / cell) * (size_t)gw + (size_t)(x / cell);
            cast_one(s, list + start[c], start[c + 1] - start[c], x, y, im);
        }
    rc = 0;
out:
    free(start);
    free(list);
    if (rc != 0)
        sim_rc_image_free(im);
    return rc;
}
