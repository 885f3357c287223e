/* SPDX-License-Identifier: MIT */
/* A scripted flight through a built level: from cell 0 to the cell farthest
 * from it in portal steps, through the midpoints of the portals on the way,
 * at a height every cell's opening allows, looking ahead along the path. */
#include "level.h"

#include <math.h>
#include <stdlib.h>

static int build_path(const zs_level *lv, double (*pts)[2], int max)
{
    int n = lv->cell_count, *prev = malloc(sizeof(int) * (size_t)n),
        *queue = malloc(sizeof(int) * (size_t)n), *via = malloc(sizeof(int) * (size_t)n),
        *chain = malloc(sizeof(int) * (size_t)n);
    int head = 0, tail = 0, last = 0, c, k, np = 0, nc = 0;
    for (c = 0; c < n; c++)
        prev[c] = -2;
    prev[0] = -1;
    queue[tail++] = 0;
    while (head < tail) {
        const zs_level_cell *cell;
        c = queue[head++];
        last = c;
        cell = &lv->cells[c];
        for (k = 0; k < cell->portal_count; k++) {
            int to = lv->portals[cell->first_portal + k].to;
            if (prev[to] == -2) {
                prev[to] = c;
                via[to] = cell->first_portal + k;
                queue[tail++] = to;
            }
        }
    }
    for (c = last; c >= 0; c = prev[c])
        chain[nc++] = c;
    for (k = nc - 1; k >= 0 && np + 2 <= max; k--) {
        const zs_level_cell *cell = &lv->cells[chain[k]];
        double sx = 0, sy = 0;
        int v;
        if (k < nc - 1) {
            const zs_level_portal *p = &lv->portals[via[chain[k]]];
            pts[np][0] = (p->ax + p->bx) / 2.0;
            pts[np][1] = (p->ay + p->by) / 2.0;
            np++;
        }
        for (v = 0; v < cell->vertex_count; v++) {
            sx += lv->vertices[2 * (cell->first_vertex + v)];
            sy += lv->vertices[2 * (cell->first_vertex + v) + 1];
        }
        pts[np][0] = sx / cell->vertex_count;
        pts[np][1] = sy / cell->vertex_count;
        np++;
    }
    free(prev);
    free(queue);
    free(via);
    free(chain);
    return np;
}

static void along(double (*pts)[2], int n, double s, double out[2])
{
    int i;
    for (i = 0; i + 1 < n; i++) {
        double dx = pts[i + 1][0] - pts[i][0], dy = pts[i + 1][1] - pts[i][1];
        double len = sqrt(dx * dx + dy * dy);
        if (s <= len || i + 2 == n) {
            double t = len > 0 ? s / len : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            out[0] = pts[i][0] + t * dx;
            out[1] = pts[i][1] + t * dy;
            return;
        }
        s -= len;
    }
    out[0] = pts[0][0];
    out[1] = pts[0][1];
}

int lv_flight(const zs_level *lv, int frames, double (*eye)[3], double (*target)[3])
{
    double (*pts)[2] = malloc(sizeof *pts * (2u * lv->cell_count + 2u));
    double total = 0, u = lv->unit / 65536.0, maxf = -1e9, minc = 1e9, h;
    int np, f, c;
    for (c = 0; c < lv->cell_count; c++) {
        maxf = lv->cells[c].floor > maxf ? lv->cells[c].floor : maxf;
        minc = lv->cells[c].ceiling < minc ? lv->cells[c].ceiling : minc;
    }
    if (maxf >= minc) {
        free(pts);
        return -1;
    }
    h = maxf + 0.55 * (minc - maxf);
    np = build_path(lv, pts, (int)(2u * lv->cell_count + 2u));
    for (c = 0; c + 1 < np; c++)
        total += hypot(pts[c + 1][0] - pts[c][0], pts[c + 1][1] - pts[c][1]);
    for (f = 0; f < frames; f++) {
        double s = frames > 1 ? total * f / (frames - 1) : 0, e[2], t[2];
        along(pts, np, s, e);
        along(pts, np, s + 6.0, t);
        if (hypot(t[0] - e[0], t[1] - e[1]) < 1e-6) {
            along(pts, np, s - 1.0, t);
            t[0] = 2 * e[0] - t[0];
            t[1] = 2 * e[1] - t[1];
        }
        if (hypot(t[0] - e[0], t[1] - e[1]) < 1e-6)
            t[0] = e[0] + 1.0;
        eye[f][0] = e[0] * u;
        eye[f][1] = h * u;
        eye[f][2] = -e[1] * u;
        target[f][0] = t[0] * u;
        target[f][1] = h * u * 0.9;
        target[f][2] = -t[1] * u;
    }
    free(pts);
    return 0;
}
