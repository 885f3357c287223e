/* SPDX-License-Identifier: MIT */
/* Level files: parse, check, write (tools/level/level.h; README.md, Portal levels). */
#include "level.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define LV_MAX_VERTS 32000
#define LV_MAX_TOKENS 260

static int fail(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, n, fmt, ap);
    va_end(ap);
    return -1;
}

static void *grow(void *p, int count, size_t size)
{
    /* capacity doubles at powers of two */
    if (count == 0 || (count & (count - 1)) == 0) {
        size_t cap = count == 0 ? 4 : (size_t)count * 2;
        void *q = realloc(p, cap * size);
        if (!q) {
            fprintf(stderr, "zspan-level: out of memory\n");
            exit(1);
        }
        return q;
    }
    return p;
}

static int parse_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

void lv_free(lv_level *lv)
{
    int i;
    for (i = 0; i < lv->ncells; i++) {
        free(lv->cells[i].v);
        free(lv->cells[i].edge_kind);
    }
    free(lv->cells);
    free(lv->xy);
    free(lv->walls);
    free(lv->portals);
    memset(lv, 0, sizeof *lv);
}

static long cross3(const int *a, const int *b, const int *c)
{
    return (long)(b[0] - a[0]) * (c[1] - a[1]) - (long)(b[1] - a[1]) * (c[0] - a[0]);
}

/* Do two convex counter-clockwise polygons share interior points? A
 * separating axis among their edges means no. */
static int polygons_overlap(const lv_level *lv, const lv_cell *p, const lv_cell *q)
{
    int pass, i, k;
    for (pass = 0; pass < 2; pass++) {
        const lv_cell *a = pass ? q : p, *b = pass ? p : q;
        for (i = 0; i < a->nv; i++) {
            const int *u = lv->xy[a->v[i]], *w = lv->xy[a->v[(i + 1) % a->nv]];
            int all_out = 1;
            if (u[0] == w[0] && u[1] == w[1])
                continue;
            for (k = 0; k < b->nv && all_out; k++)
                all_out = cross3(u, w, lv->xy[b->v[k]]) <= 0;
            if (all_out)
                return 0;
        }
    }
    return 1;
}

int lv_check(lv_level *lv, char *err, size_t n)
{
    int i, j, k;
    if (lv->ncells == 0)
        return fail(err, n, "the level has no cells");
    if (lv->ncells > ZS_LEVEL_MAX_CELLS)
        return fail(err, n, "%d cells: at most %d", lv->ncells, ZS_LEVEL_MAX_CELLS);
    for (i = 0; i < lv->ncells; i++) {
        lv_cell *c = &lv->cells[i];
        long area = 0;
        free(c->edge_kind);
        c->edge_kind = malloc(sizeof(int) * (size_t)c->nv);
        if (!c->edge_kind)
            return fail(err, n, "out of memory");
        for (k = 0; k < c->nv; k++) {
            const int *a = lv->xy[c->v[k]], *b = lv->xy[c->v[(k + 1) % c->nv]],
                      *d = lv->xy[c->v[(k + 2) % c->nv]];
            c->edge_kind[k] = -2; /* not yet covered */
            if (a[0] == b[0] && a[1] == b[1])
                return fail(err, n, "cell %d: vertices %d and %d are at the same point", i,
                            c->v[k], c->v[(k + 1) % c->nv]);
            if (cross3(a, b, d) < 0)
                return fail(err, n,
                            "cell %d is not convex and counter-clockwise (seen from above) at "
                            "vertex %d",
                            i, c->v[(k + 1) % c->nv]);
            area += cross3(lv->xy[c->v[0]], a, b);
        }
        if (area <= 0)
            return fail(err, n, "cell %d has no area (its vertices are collinear)", i);
    }
    /* every edge of a cell is a wall or a portal of that cell, and only one */
    for (j = 0; j < lv->nportals; j++) {
        lv_portal *p = &lv->portals[j];
        int side;
        for (side = 0; side < 2; side++) {
            lv_cell *c = &lv->cells[side ? p->b : p->a];
            int found = 0;
            for (k = 0; k < c->nv; k++) {
                int u = c->v[k], w = c->v[(k + 1) % c->nv];
                if ((u == p->va && w == p->vb) || (u == p->vb && w == p->va)) {
                    if (c->edge_kind[k] != -2)
                        return fail(err, n, "line %d: cell %d's edge %d-%d has two portals",
                                    p->line, side ? p->b : p->a, u, w);
                    c->edge_kind[k] = j;
                    found = 1;
                }
            }
            if (!found)
                return fail(err, n,
                            "line %d: portal %d-%d is not an edge of cell %d (a portal must lie "
                            "on an edge both its cells have)",
                            p->line, p->va, p->vb, side ? p->b : p->a);
        }
        {
            const lv_cell *a = &lv->cells[p->a], *b = &lv->cells[p->b];
            int lo = a->floor > b->floor ? a->floor : b->floor;
            int hi = a->ceiling < b->ceiling ? a->ceiling : b->ceiling;
            if (lo >= hi)
                return fail(err, n,
                            "line %d: the portal between cells %d and %d has no opening (their "
                            "floor-to-ceiling heights do not overlap)",
                            p->line, p->a, p->b);
        }
    }
    for (j = 0; j < lv->nwalls; j++) {
        const lv_wall *w = &lv->walls[j];
        int found = 0;
        for (i = 0; i < lv->ncells; i++) {
            lv_cell *c = &lv->cells[i];
            for (k = 0; k < c->nv; k++) {
                int u = c->v[k], x = c->v[(k + 1) % c->nv];
                if ((u == w->va && x == w->vb) || (u == w->vb && x == w->va)) {
                    if (c->edge_kind[k] >= 0)
                        return fail(err, n,
                                    "line %d: edge %d-%d of cell %d is both a wall and a portal",
                                    w->line, u, x, i);
                    if (c->edge_kind[k] == -1)
                        return fail(err, n, "line %d: wall %d-%d is given twice", w->line, u, x);
                    c->edge_kind[k] = -1;
                    found = 1;
                }
            }
        }
        if (!found)
            return fail(err, n, "line %d: wall %d-%d is not an edge of any cell", w->line, w->va,
                        w->vb);
    }
    for (i = 0; i < lv->ncells; i++) {
        const lv_cell *c = &lv->cells[i];
        for (k = 0; k < c->nv; k++)
            if (c->edge_kind[k] == -2)
                return fail(err, n,
                            "cell %d is not closed: its edge from vertex %d to vertex %d is "
                            "neither a wall nor a portal",
                            i, c->v[k], c->v[(k + 1) % c->nv]);
    }
    /* cells must not overlap in plan (the PVS is computed on the plan) */
    for (i = 0; i < lv->ncells; i++) {
        int bi[4], bj[4];
        const lv_cell *a = &lv->cells[i];
        bi[0] = bi[2] = lv->xy[a->v[0]][0];
        bi[1] = bi[3] = lv->xy[a->v[0]][1];
        for (k = 1; k < a->nv; k++) {
            const int *p = lv->xy[a->v[k]];
            bi[0] = p[0] < bi[0] ? p[0] : bi[0];
            bi[1] = p[1] < bi[1] ? p[1] : bi[1];
            bi[2] = p[0] > bi[2] ? p[0] : bi[2];
            bi[3] = p[1] > bi[3] ? p[1] : bi[3];
        }
        for (j = i + 1; j < lv->ncells; j++) {
            const lv_cell *b = &lv->cells[j];
            bj[0] = bj[2] = lv->xy[b->v[0]][0];
            bj[1] = bj[3] = lv->xy[b->v[0]][1];
            for (k = 1; k < b->nv; k++) {
                const int *p = lv->xy[b->v[k]];
                bj[0] = p[0] < bj[0] ? p[0] : bj[0];
                bj[1] = p[1] < bj[1] ? p[1] : bj[1];
                bj[2] = p[0] > bj[2] ? p[0] : bj[2];
                bj[3] = p[1] > bj[3] ? p[1] : bj[3];
            }
            if (bi[2] <= bj[0] || bj[2] <= bi[0] || bi[3] <= bj[1] || bj[3] <= bi[1])
                continue;
            if (polygons_overlap(lv, a, b))
                return fail(err, n, "cells %d and %d overlap", i, j);
        }
    }
    return 0;
}

/* Splits a line into tokens (in place); '#' starts a comment. */
static int tokenize(char *line, char **tok, int max)
{
    int n = 0;
    char *p = line, *h = strchr(line, '#');
    if (h)
        *h = 0;
    while (*p) {
        while (*p == ' ' || *p == '\t' || *p == '\r')
            *p++ = 0;
        if (!*p)
            break;
        if (n == max)
            return -1;
        tok[n++] = p;
        while (*p && *p != ' ' && *p != '\t' && *p != '\r')
            p++;
    }
    return n;
}

int lv_parse(const char *text, const char *name, lv_level *lv, char *err, size_t n)
{
    char *copy = strdup(text), *line, *next;
    int lineno = 0, header = 0, rc = 0;
    char msg[400];
    memset(lv, 0, sizeof *lv);
    lv->unit = 1;
    if (!copy)
        return fail(err, n, "%s: out of memory", name);
    for (line = copy; line && rc == 0; line = next) {
        char *tok[LV_MAX_TOKENS];
        int nt, i;
        long v[LV_MAX_TOKENS];
        next = strchr(line, '\n');
        if (next)
            *next++ = 0;
        lineno++;
        nt = tokenize(line, tok, LV_MAX_TOKENS);
        if (nt < 0) {
            rc = fail(err, n, "%s:%d: more than %d fields on a line", name, lineno,
                      LV_MAX_TOKENS);
            break;
        }
        if (nt == 0)
            continue;
        if (!header) {
            if (nt != 2 || strcmp(tok[0], "zspan-level") || strcmp(tok[1], "1")) {
                rc = fail(err, n, "%s:%d: not a level file (the first line must be "
                          "\"zspan-level 1\")", name, lineno);
                break;
            }
            header = 1;
            continue;
        }
        for (i = 1; i < nt; i++)
            if (parse_int(tok[i], -ZS_LEVEL_MAX_COORD, ZS_LEVEL_MAX_COORD, &v[i]) != 0) {
                rc = fail(err, n, "%s:%d: \"%s\" is not an integer in [-%d, %d]", name, lineno,
                          tok[i], ZS_LEVEL_MAX_COORD, ZS_LEVEL_MAX_COORD);
                break;
            }
        if (rc)
            break;
        if (!strcmp(tok[0], "unit")) {
            if (nt != 2 || v[1] < 1 || v[1] > 256 || (v[1] & (v[1] - 1))) {
                rc = fail(err, n, "%s:%d: unit needs one power of two from 1 to 256", name,
                          lineno);
                break;
            }
            lv->unit = (int)v[1];
        } else if (!strcmp(tok[0], "vertex")) {
            if (nt != 3) {
                rc = fail(err, n, "%s:%d: vertex needs X Y", name, lineno);
                break;
            }
            if (lv->nverts >= LV_MAX_VERTS) {
                rc = fail(err, n, "%s:%d: more than %d vertices", name, lineno, LV_MAX_VERTS);
                break;
            }
            lv->xy = grow(lv->xy, lv->nverts, sizeof *lv->xy);
            lv->xy[lv->nverts][0] = (int)v[1];
            lv->xy[lv->nverts][1] = (int)v[2];
            lv->nverts++;
        } else if (!strcmp(tok[0], "cell")) {
            lv_cell *c;
            if (nt < 6) {
                rc = fail(err, n, "%s:%d: cell needs FLOOR CEILING and at least 3 vertices",
                          name, lineno);
                break;
            }
            if (v[1] >= v[2]) {
                rc = fail(err, n, "%s:%d: cell %d: floor %ld is not below ceiling %ld", name,
                          lineno, lv->ncells, v[1], v[2]);
                break;
            }
            for (i = 3; i < nt; i++)
                if (v[i] < 0 || v[i] >= lv->nverts) {
                    rc = fail(err, n, "%s:%d: cell %d: vertex %ld out of range (%d vertices "
                              "defined so far)", name, lineno, lv->ncells, v[i], lv->nverts);
                    break;
                }
            if (rc)
                break;
            lv->cells = grow(lv->cells, lv->ncells, sizeof *lv->cells);
            c = &lv->cells[lv->ncells++];
            memset(c, 0, sizeof *c);
            c->floor = (int)v[1];
            c->ceiling = (int)v[2];
            c->nv = nt - 3;
            c->v = malloc(sizeof(int) * (size_t)c->nv);
            for (i = 3; i < nt; i++)
                c->v[i - 3] = (int)v[i];
        } else if (!strcmp(tok[0], "wall")) {
            if (nt != 3) {
                rc = fail(err, n, "%s:%d: wall needs V0 V1", name, lineno);
                break;
            }
            if (v[1] < 0 || v[1] >= lv->nverts || v[2] < 0 || v[2] >= lv->nverts) {
                rc = fail(err, n, "%s:%d: wall: vertex out of range (%d vertices defined so far)",
                          name, lineno, lv->nverts);
                break;
            }
            lv->walls = grow(lv->walls, lv->nwalls, sizeof *lv->walls);
            lv->walls[lv->nwalls].va = (int)v[1];
            lv->walls[lv->nwalls].vb = (int)v[2];
            lv->walls[lv->nwalls].line = lineno;
            lv->nwalls++;
        } else if (!strcmp(tok[0], "portal")) {
            if (nt != 5) {
                rc = fail(err, n, "%s:%d: portal needs CELL_A CELL_B V0 V1", name, lineno);
                break;
            }
            if (v[1] < 0 || v[1] >= lv->ncells || v[2] < 0 || v[2] >= lv->ncells) {
                rc = fail(err, n, "%s:%d: portal between unknown cells %ld and %ld (%d cells "
                          "defined so far)", name, lineno, v[1], v[2], lv->ncells);
                break;
            }
            if (v[1] == v[2]) {
                rc = fail(err, n, "%s:%d: portal from cell %ld to itself", name, lineno, v[1]);
                break;
            }
            if (v[3] < 0 || v[3] >= lv->nverts || v[4] < 0 || v[4] >= lv->nverts) {
                rc = fail(err, n, "%s:%d: portal: vertex out of range (%d vertices defined so "
                          "far)", name, lineno, lv->nverts);
                break;
            }
            lv->portals = grow(lv->portals, lv->nportals, sizeof *lv->portals);
            lv->portals[lv->nportals].a = (int)v[1];
            lv->portals[lv->nportals].b = (int)v[2];
            lv->portals[lv->nportals].va = (int)v[3];
            lv->portals[lv->nportals].vb = (int)v[4];
            lv->portals[lv->nportals].line = lineno;
            lv->nportals++;
        } else {
            rc = fail(err, n, "%s:%d: unknown keyword \"%s\" (unit, vertex, cell, wall, portal)",
                      name, lineno, tok[0]);
        }
    }
    free(copy);
    if (rc == 0 && !header)
        rc = fail(err, n, "%s: empty file (the first line must be \"zspan-level 1\")", name);
    if (rc == 0 && lv_check(lv, msg, sizeof msg) != 0) {
        int at = 0, len = 0;
        /* "line N: ..." becomes "NAME:N: ..." like the parser's own messages */
        if (sscanf(msg, "line %d: %n", &at, &len) == 1 && len > 0)
            rc = fail(err, n, "%s:%d: %s", name, at, msg + len);
        else
            rc = fail(err, n, "%s: %s", name, msg);
    }
    if (rc != 0)
        lv_free(lv);
    return rc;
}

int lv_load(const char *path, lv_level *lv, char *err, size_t n)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long len;
    int rc;
    if (!f)
        return fail(err, n, "%s: %s", path, strerror(errno));
    if (fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return fail(err, n, "%s: cannot read", path);
    }
    buf = malloc((size_t)len + 1);
    if (!buf || fread(buf, 1, (size_t)len, f) != (size_t)len) {
        free(buf);
        fclose(f);
        return fail(err, n, "%s: cannot read", path);
    }
    fclose(f);
    buf[len] = 0;
    if (strlen(buf) != (size_t)len) {
        free(buf);
        return fail(err, n, "%s: not a text file (a NUL byte)", path);
    }
    rc = lv_parse(buf, path, lv, err, n);
    free(buf);
    return rc;
}

int lv_write(FILE *f, const lv_level *lv)
{
    int i, k;
    fprintf(f, "zspan-level 1\nunit %d\n", lv->unit);
    for (i = 0; i < lv->nverts; i++)
        fprintf(f, "vertex %d %d\n", lv->xy[i][0], lv->xy[i][1]);
    for (i = 0; i < lv->ncells; i++) {
        fprintf(f, "cell %d %d", lv->cells[i].floor, lv->cells[i].ceiling);
        for (k = 0; k < lv->cells[i].nv; k++)
            fprintf(f, " %d", lv->cells[i].v[k]);
        fputc('\n', f);
    }
    for (i = 0; i < lv->nwalls; i++)
        fprintf(f, "wall %d %d\n", lv->walls[i].va, lv->walls[i].vb);
    for (i = 0; i < lv->nportals; i++)
        fprintf(f, "portal %d %d %d %d\n", lv->portals[i].a, lv->portals[i].b, lv->portals[i].va,
                lv->portals[i].vb);
    return ferror(f) ? -1 : 0;
}
