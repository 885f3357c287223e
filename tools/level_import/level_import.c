/* SPDX-License-Identifier: MIT */
/* A level from a mesh file whose groups name cells and portals (assimp, via
 * the application layer's importer):
 *
 *   cell_NAME      any faces of the cell (floor, walls, ceiling): the cell's
 *                  plan polygon is the convex hull of their points seen from
 *                  above, its floor and ceiling their lowest and highest y;
 *   portal_A_B     the opening between cells A and B: its plan endpoints are
 *                  the two points of the group farthest apart, and must lie
 *                  on both cells' outlines.
 *
 * Every other side of a cell becomes a wall. World coordinates are rounded
 * to 1/unit; the result is checked like a level file (lv_check). */
#include "level_import.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "zs_import.h"

#define IM_MAX_GROUPS 1024

typedef struct im_group {
    char name[64];
    int (*pt)[3]; /* plan x, plan y, height (level units) */
    int n, cap;
} im_group;

typedef struct im_state {
    im_group cells[IM_MAX_GROUPS], portals[IM_MAX_GROUPS];
    int ncells, nportals, unit;
    char *err;
    size_t errlen;
} im_state;

static int fail(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, n, fmt, ap);
    va_end(ap);
    return -1;
}

static im_group *group(im_group *gs, int *n, const char *name)
{
    int i;
    for (i = 0; i < *n; i++)
        if (!strcmp(gs[i].name, name))
            return &gs[i];
    if (*n == IM_MAX_GROUPS)
        return NULL;
    memset(&gs[*n], 0, sizeof gs[*n]);
    snprintf(gs[*n].name, sizeof gs[*n].name, "%s", name);
    return &gs[(*n)++];
}

static int on_part(void *user, const zs_import_part *part)
{
    im_state *s = user;
    const char *name = part->mesh->mName.data;
    im_group *g;
    unsigned v;
    if (!strncmp(name, "cell_", 5) && name[5] && !strchr(name + 5, '_'))
        g = group(s->cells, &s->ncells, name + 5);
    else if (!strncmp(name, "portal_", 7))
        g = group(s->portals, &s->nportals, name + 7);
    else
        return fail(s->err, s->errlen,
                    "group \"%s\" is neither cell_NAME nor portal_A_B (NAME without '_')", name);
    if (!g)
        return fail(s->err, s->errlen, "more than %d cell or portal groups", IM_MAX_GROUPS);
    for (v = 0; v < part->mesh->mNumVertices; v++) {
        double p[3];
        long q[3];
        int k;
        zs_import_position(part, v, p);
        q[0] = lround(p[0] * s->unit);
        q[1] = lround(-p[2] * s->unit);
        q[2] = lround(p[1] * s->unit);
        for (k = 0; k < 3; k++)
            if (!(fabs(p[k] * s->unit) <= ZS_LEVEL_MAX_COORD))
                return fail(s->err, s->errlen,
                            "group \"%s\": a point is farther than %d level units from the origin",
                            name, ZS_LEVEL_MAX_COORD);
        if (g->n == g->cap) {
            g->cap = g->cap ? 2 * g->cap : 64;
            g->pt = realloc(g->pt, sizeof *g->pt * (size_t)g->cap);
        }
        for (k = 0; k < 3; k++)
            g->pt[g->n][k] = (int)q[k];
        g->n++;
    }
    return 0;
}

static long cross(const int *o, const int *a, const int *b)
{
    return (long)(a[0] - o[0]) * (b[1] - o[1]) - (long)(a[1] - o[1]) * (b[0] - o[0]);
}

static int cmp_xy(const void *pa, const void *pb)
{
    const int *a = pa, *b = pb;
    return a[0] != b[0] ? (a[0] > b[0]) - (a[0] < b[0]) : (a[1] > b[1]) - (a[1] < b[1]);
}

/* Convex hull (counter-clockwise, no collinear points) of n plan points;
 * returns its size, the points in out. */
static int hull(int (*pt)[3], int n, int (*out)[2])
{
    int (*p)[2] = malloc(sizeof *p * (size_t)(n + 1)), i, k = 0, m = 0, t;
    for (i = 0; i < n; i++) {
        p[i][0] = pt[i][0];
        p[i][1] = pt[i][1];
    }
    qsort(p, (size_t)n, sizeof *p, cmp_xy);
    for (i = 0; i < n; i++)
        if (m == 0 || p[m - 1][0] != p[i][0] || p[m - 1][1] != p[i][1]) {
            p[m][0] = p[i][0];
            p[m][1] = p[i][1];
            m++;
        }
    if (m < 3) {
        memcpy(out, p, sizeof *p * (size_t)m);
        free(p);
        return m;
    }
    for (i = 0; i < m; i++) { /* lower */
        while (k >= 2 && cross(out[k - 2], out[k - 1], p[i]) <= 0)
            k--;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        k++;
    }
    for (i = m - 2, t = k + 1; i >= 0; i--) { /* upper */
        while (k >= t && cross(out[k - 2], out[k - 1], p[i]) <= 0)
            k--;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        k++;
    }
    free(p);
    return k - 1;
}

static int vertex_of(lv_level *lv, int x, int y)
{
    int i;
    for (i = 0; i < lv->nverts; i++)
        if (lv->xy[i][0] == x && lv->xy[i][1] == y)
            return i;
    lv->xy = realloc(lv->xy, sizeof *lv->xy * (size_t)(lv->nverts + 1));
    lv->xy[lv->nverts][0] = x;
    lv->xy[lv->nverts][1] = y;
    return lv->nverts++;
}

/* Is q strictly inside segment a-b? */
static int inside_edge(const int *a, const int *b, const int *q)
{
    if (cross(a, b, q) != 0)
        return 0;
    return (long)(q[0] - a[0]) * (b[0] - a[0]) + (long)(q[1] - a[1]) * (b[1] - a[1]) > 0 &&
           (long)(q[0] - b[0]) * (a[0] - b[0]) + (long)(q[1] - b[1]) * (a[1] - b[1]) > 0;
}

static int build(im_state *s, lv_level *lv, char *err, size_t n)
{
    int i, j, k;
    int (*ends)[2][2] = calloc((size_t)s->nportals + 1, sizeof *ends);
    int *pa = calloc((size_t)s->nportals + 1, sizeof(int)), *pb = calloc((size_t)s->nportals + 1, sizeof(int));
    int rc = 0;
    memset(lv, 0, sizeof *lv);
    lv->unit = s->unit;
    if (s->ncells == 0)
        rc = fail(err, n, "no cell_NAME group");
    /* portals: their cells and their two plan endpoints */
    for (j = 0; j < s->nportals && rc == 0; j++) {
        im_group *g = &s->portals[j];
        char a[64], *b;
        long best = -1;
        snprintf(a, sizeof a, "%s", g->name);
        b = strchr(a, '_');
        if (!b || !b[1] || strchr(b + 1, '_')) {
            rc = fail(err, n, "group \"portal_%s\" is not portal_A_B", g->name);
            break;
        }
        *b++ = 0;
        pa[j] = pb[j] = -1;
        for (i = 0; i < s->ncells; i++) {
            if (!strcmp(s->cells[i].name, a))
                pa[j] = i;
            if (!strcmp(s->cells[i].name, b))
                pb[j] = i;
        }
        if (pa[j] < 0 || pb[j] < 0) {
            rc = fail(err, n, "portal_%s: a portal between unknown cells (no cell_%s)", g->name,
                      pa[j] < 0 ? a : b);
            break;
        }
        for (i = 0; i < g->n; i++)
            for (k = i + 1; k < g->n; k++) {
                long dx = g->pt[i][0] - g->pt[k][0], dy = g->pt[i][1] - g->pt[k][1];
                if (dx * dx + dy * dy > best) {
                    best = dx * dx + dy * dy;
                    ends[j][0][0] = g->pt[i][0];
                    ends[j][0][1] = g->pt[i][1];
                    ends[j][1][0] = g->pt[k][0];
                    ends[j][1][1] = g->pt[k][1];
                }
            }
        if (best <= 0)
            rc = fail(err, n, "portal_%s has no width seen from above", g->name);
    }
    if (rc == 0) {
        lv->ncells = s->ncells;
        lv->cells = calloc((size_t)s->ncells, sizeof *lv->cells);
    }
    for (i = 0; i < s->ncells && rc == 0; i++) {
        im_group *g = &s->cells[i];
        int (*h)[2] = malloc(sizeof *h * (size_t)(2 * g->n + 2 + 2 * s->nportals));
        int m = hull(g->pt, g->n, h), lo = g->pt[0][2], hi = g->pt[0][2], e;
        lv_cell *c = &lv->cells[i];
        for (k = 1; k < g->n; k++) {
            lo = g->pt[k][2] < lo ? g->pt[k][2] : lo;
            hi = g->pt[k][2] > hi ? g->pt[k][2] : hi;
        }
        if (m < 3) {
            free(h);
            rc = fail(err, n, "cell_%s has no area seen from above", g->name);
            break;
        }
        /* the ends of this cell's portals that fall inside a side join the outline */
        for (j = 0; j < s->nportals && rc == 0; j++) {
            if (pa[j] != i && pb[j] != i)
                continue;
            for (e = 0; e < 2; e++) {
                int found = 0;
                for (k = 0; k < m && !found; k++)
                    if (h[k][0] == ends[j][e][0] && h[k][1] == ends[j][e][1])
                        found = 1;
                for (k = 0; k < m && !found; k++)
                    if (inside_edge(h[k], h[(k + 1) % m], ends[j][e])) {
                        memmove(h + k + 2, h + k + 1, sizeof *h * (size_t)(m - k - 1));
                        h[k + 1][0] = ends[j][e][0];
                        h[k + 1][1] = ends[j][e][1];
                        m++;
                        found = 1;
                    }
                if (!found)
                    rc = fail(err, n, "portal_%s: its end (%d, %d) is not on the outline of "
                              "cell_%s", s->portals[j].name, ends[j][e][0], ends[j][e][1], g->name);
            }
        }
        c->floor = lo;
        c->ceiling = hi;
        c->nv = m;
        c->v = malloc(sizeof(int) * (size_t)m);
        for (k = 0; k < m; k++)
            c->v[k] = vertex_of(lv, h[k][0], h[k][1]);
        free(h);
    }
    if (rc == 0) {
        lv->portals = calloc((size_t)s->nportals + 1, sizeof *lv->portals);
        for (j = 0; j < s->nportals; j++) {
            lv_portal *p = &lv->portals[lv->nportals++];
            p->a = pa[j];
            p->b = pb[j];
            p->va = vertex_of(lv, ends[j][0][0], ends[j][0][1]);
            p->vb = vertex_of(lv, ends[j][1][0], ends[j][1][1]);
            p->line = 0;
        }
        /* every other side is a wall, once */
        for (i = 0; i < lv->ncells; i++) {
            const lv_cell *c = &lv->cells[i];
            for (k = 0; k < c->nv; k++) {
                int u = c->v[k], w = c->v[(k + 1) % c->nv], dup = 0;
                for (j = 0; j < lv->nportals && !dup; j++)
                    dup = (lv->portals[j].va == u && lv->portals[j].vb == w) ||
                          (lv->portals[j].va == w && lv->portals[j].vb == u);
                for (j = 0; j < lv->nwalls && !dup; j++)
                    dup = (lv->walls[j].va == u && lv->walls[j].vb == w) ||
                          (lv->walls[j].va == w && lv->walls[j].vb == u);
                if (dup)
                    continue;
                lv->walls = realloc(lv->walls, sizeof *lv->walls * (size_t)(lv->nwalls + 1));
                lv->walls[lv->nwalls].va = u;
                lv->walls[lv->nwalls].vb = w;
                lv->walls[lv->nwalls].line = 0;
                lv->nwalls++;
            }
        }
        {
            char msg[400];
            if (lv_check(lv, msg, sizeof msg) != 0)
                rc = fail(err, n, "%s", msg);
        }
    }
    free(ends);
    free(pa);
    free(pb);
    if (rc != 0)
        lv_free(lv);
    return rc;
}

int lv_import_mesh(const char *path, int unit, lv_level *lv, char *err, size_t n)
{
    const struct aiScene *scene;
    im_state *s;
    int rc, i;
    char msg[480];
    if (unit < 1 || unit > 256 || (unit & (unit - 1)))
        return fail(err, n, "unit must be a power of two from 1 to 256");
    scene = aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                   aiProcess_ValidateDataStructure);
    if (!scene)
        return fail(err, n, "%s: %s", path, aiGetErrorString());
    s = calloc(1, sizeof *s);
    s->unit = unit;
    s->err = msg;
    s->errlen = sizeof msg;
    rc = zs_import_walk(scene, on_part, s);
    if (rc != 0 && rc != -1)
        snprintf(msg, sizeof msg, "the file's node hierarchy is malformed or too deep");
    if (rc == 0)
        rc = build(s, lv, msg, sizeof msg);
    if (rc != 0)
        fail(err, n, "%s: %s", path, msg);
    for (i = 0; i < s->ncells; i++)
        free(s->cells[i].pt);
    for (i = 0; i < s->nportals; i++)
        free(s->portals[i].pt);
    free(s);
    aiReleaseImport(scene);
    return rc ? -1 : 0;
}
