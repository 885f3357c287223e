/* SPDX-License-Identifier: MIT */
/* A checked level as the core's arrays (zspan/portal.h): cell meshes (floor,
 * ceiling, walls and the steps above and below openings between cells of
 * different heights), plan polygons, directed portals, the PVS; and the C
 * source that defines them. */
#include "level.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

typedef struct mesh_acc {
    int16_t *pos;
    int nv, cap_v;
    uint16_t *idx;
    zs_color *col;
    int nt, cap_t;
    int overflow;
} mesh_acc;

static int acc_vertex(mesh_acc *m, int x, int h, int y)
{
    int i;
    for (i = 0; i < m->nv; i++)
        if (m->pos[3 * i] == x && m->pos[3 * i + 1] == h && m->pos[3 * i + 2] == -y)
            return i;
    if (m->nv == 65535) {
        m->overflow = 1;
        return 0;
    }
    if (m->nv == m->cap_v) {
        m->cap_v = m->cap_v ? 2 * m->cap_v : 64;
        m->pos = realloc(m->pos, sizeof(int16_t) * 3 * (size_t)m->cap_v);
    }
    m->pos[3 * m->nv] = (int16_t)x;
    m->pos[3 * m->nv + 1] = (int16_t)h;
    m->pos[3 * m->nv + 2] = (int16_t)-y;
    return m->nv++;
}

static void acc_tri(mesh_acc *m, int a, int b, int c, zs_color col)
{
    if (m->nt == 65535) {
        m->overflow = 1;
        return;
    }
    if (m->nt == m->cap_t) {
        m->cap_t = m->cap_t ? 2 * m->cap_t : 64;
        m->idx = realloc(m->idx, sizeof(uint16_t) * 3 * (size_t)m->cap_t);
        m->col = realloc(m->col, sizeof(zs_color) * (size_t)m->cap_t);
    }
    m->idx[3 * m->nt] = (uint16_t)a;
    m->idx[3 * m->nt + 1] = (uint16_t)b;
    m->idx[3 * m->nt + 2] = (uint16_t)c;
    m->col[m->nt] = col;
    m->nt++;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static int neighbour(const lv_level *lv, int c, int m)
{
    const lv_portal *p = &lv->portals[lv->cells[c].edge_kind[m]];
    return p->a == c ? p->b : p->a;
}

/* Heights at which the wall faces meeting at polygon vertex m of cell c
 * change: floor, ceiling and the floor and ceiling of the cell beyond each
 * opening on the two edges at m, inside (floor, ceiling). Both faces at the
 * vertex use the same list, so they share their vertical edges exactly
 * (no T-junctions, no cracks). */
static int breaks_at(const lv_level *lv, int c, int m, int *out)
{
    const lv_cell *cell = &lv->cells[c];
    int n = 0, e, k, j;
    out[n++] = cell->floor;
    out[n++] = cell->ceiling;
    for (e = 0; e < 2; e++) {
        int edge = e ? m : (m + cell->nv - 1) % cell->nv;
        if (cell->edge_kind[edge] >= 0) {
            const lv_cell *nb = &lv->cells[neighbour(lv, c, edge)];
            int hs[2] = {nb->floor, nb->ceiling};
            for (k = 0; k < 2; k++)
                if (hs[k] > cell->floor && hs[k] < cell->ceiling)
                    out[n++] = hs[k];
        }
    }
    qsort(out, (size_t)n, sizeof(int), cmp_int);
    for (k = j = 0; k < n; k++)
        if (j == 0 || out[j - 1] != out[k])
            out[j++] = out[k];
    return j;
}

static long cross2(const int *a, const int *b, const int *c)
{
    return (long)(b[0] - a[0]) * (c[1] - a[1]) - (long)(b[1] - a[1]) * (c[0] - a[0]);
}

static zs_color shade(zs_color c, int num, int den)
{
    uint32_t r = ((c >> 16) & 255u) * (uint32_t)num / (uint32_t)den;
    uint32_t g = ((c >> 8) & 255u) * (uint32_t)num / (uint32_t)den;
    uint32_t b = (c & 255u) * (uint32_t)num / (uint32_t)den;
    return ZS_RGB(r, g, b);
}

/* A vertical face over edge a -> b (cell on its left) between heights lo and
 * hi: a ladder of triangles between the break lists at a and at b. */
static void wall_face(mesh_acc *m, const int *a, const int *b, const int *ha, int na,
                      const int *hb, int nb, int lo, int hi, zs_color col)
{
    int i = 0, j = 0, la[16], lb[16], n1 = 0, n2 = 0, k;
    for (k = 0; k < na; k++)
        if (ha[k] >= lo && ha[k] <= hi)
            la[n1++] = ha[k];
    for (k = 0; k < nb; k++)
        if (hb[k] >= lo && hb[k] <= hi)
            lb[n2++] = hb[k];
    while (i < n1 - 1 || j < n2 - 1) {
        int va = acc_vertex(m, a[0], la[i], a[1]), vb = acc_vertex(m, b[0], lb[j], b[1]);
        if (j >= n2 - 1 || (i < n1 - 1 && la[i + 1] <= lb[j + 1])) {
            acc_tri(m, vb, va, acc_vertex(m, a[0], la[i + 1], a[1]), col);
            i++;
        } else {
            acc_tri(m, vb, va, acc_vertex(m, b[0], lb[j + 1], b[1]), col);
            j++;
        }
    }
}

static const zs_color k_palette[8] = {
    ZS_RGB(200, 120, 90), ZS_RGB(110, 170, 200), ZS_RGB(150, 200, 110), ZS_RGB(210, 190, 100),
    ZS_RGB(180, 130, 200), ZS_RGB(120, 200, 180), ZS_RGB(220, 150, 150), ZS_RGB(160, 160, 220)};

static void cell_mesh(const lv_level *lv, int c, mesh_acc *m)
{
    const lv_cell *cell = &lv->cells[c];
    zs_color base = k_palette[(unsigned)c * 5u % 8u];
    zs_color floor_col = (c & 1) ? ZS_RGB(90, 90, 100) : ZS_RGB(120, 110, 95);
    int k;
    int (*br)[16] = malloc(sizeof *br * (size_t)cell->nv);
    int *nbr = malloc(sizeof(int) * (size_t)cell->nv);
    for (k = 0; k < cell->nv; k++)
        nbr[k] = breaks_at(lv, c, k, br[k]);
    /* floor and ceiling: ears cut at strictly convex corners, so that every
     * side of the polygon, collinear points and all, is a triangle edge
     * shared exactly with the walls (a fan would span a side with collinear
     * points in one edge: a T-junction, a crack) */
    {
        int *ring = malloc(sizeof(int) * (size_t)cell->nv), n = cell->nv;
        memcpy(ring, cell->v, sizeof(int) * (size_t)n);
        while (n >= 3) {
            int pick = -1;
            for (k = 0; k < n && pick < 0; k++) {
                const int *p = lv->xy[ring[(k + n - 1) % n]], *q = lv->xy[ring[k]],
                          *r = lv->xy[ring[(k + 1) % n]];
                long rest = 0;
                int j;
                if (cross2(p, q, r) <= 0)
                    continue;
                /* what is left must keep an area (or be nothing) */
                for (j = 0; j < n; j++)
                    if (j != k && (j + 1) % n != k)
                        rest += cross2(lv->xy[ring[(k + 1) % n]], lv->xy[ring[j]],
                                       lv->xy[ring[(j + 1) % n == k ? (k + 1) % n : (j + 1) % n]]);
                if (n == 3 || rest > 0)
                    pick = k;
            }
            if (pick < 0)
                break;
            {
                int u = ring[(pick + n - 1) % n], v = ring[pick], w = ring[(pick + 1) % n];
                const int *p = lv->xy[u], *q = lv->xy[v], *r = lv->xy[w];
                acc_tri(m, acc_vertex(m, p[0], cell->floor, p[1]),
                        acc_vertex(m, q[0], cell->floor, q[1]), acc_vertex(m, r[0], cell->floor, r[1]),
                        floor_col);
                acc_tri(m, acc_vertex(m, p[0], cell->ceiling, p[1]),
                        acc_vertex(m, r[0], cell->ceiling, r[1]),
                        acc_vertex(m, q[0], cell->ceiling, q[1]), ZS_RGB(215, 215, 205));
            }
            memmove(ring + pick, ring + pick + 1, sizeof(int) * (size_t)(n - pick - 1));
            n--;
        }
        free(ring);
    }
    for (k = 0; k < cell->nv; k++) {
        int k1 = (k + 1) % cell->nv;
        const int *a = lv->xy[cell->v[k]], *b = lv->xy[cell->v[k1]];
        /* walls a little darker the more they face plan +y, for unlit views */
        int dx = b[0] - a[0], dy = b[1] - a[1];
        int num = dx > 0 ? 10 : dx < 0 ? 7 : dy > 0 ? 9 : 8;
        zs_color col = shade(base, num, 10);
        if (cell->edge_kind[k] < 0) {
            wall_face(m, a, b, br[k], nbr[k], br[k1], nbr[k1], cell->floor, cell->ceiling, col);
        } else {
            const lv_cell *nb = &lv->cells[neighbour(lv, c, k)];
            int lo = nb->floor > cell->floor ? nb->floor : cell->floor;
            int hi = nb->ceiling < cell->ceiling ? nb->ceiling : cell->ceiling;
            if (lo > cell->floor)
                wall_face(m, a, b, br[k], nbr[k], br[k1], nbr[k1], cell->floor, lo, col);
            if (hi < cell->ceiling)
                wall_face(m, a, b, br[k], nbr[k], br[k1], nbr[k1], hi, cell->ceiling, col);
        }
    }
    free(br);
    free(nbr);
}

static int fail(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, n, fmt, ap);
    va_end(ap);
    return -1;
}

int lv_build(const lv_level *lv, uint8_t *pvs, lv_built *b, char *err, size_t n)
{
    int c, nv = 0, np = 0, k;
    size_t nc = (size_t)(unsigned)lv->ncells;
    memset(b, 0, sizeof *b);
    b->pvs = pvs;
    for (c = 0; c < lv->ncells; c++) {
        nv += lv->cells[c].nv;
        for (k = 0; k < lv->cells[c].nv; k++)
            np += lv->cells[c].edge_kind[k] >= 0;
    }
    if (lv->ncells < 1 || nv > 65535 || np > 65535)
        return fail(err, n, "too many polygon points (%d) or portals (%d) for 16-bit indices",
                    nv, np);
    b->vertices = malloc(sizeof(int16_t) * 2 * (size_t)(unsigned)nv + 4);
    b->cells = calloc(nc, sizeof *b->cells);
    b->portals = calloc((size_t)(unsigned)np + 1, sizeof *b->portals);
    b->meshes = calloc(nc, sizeof *b->meshes);
    b->positions = calloc(nc, sizeof *b->positions);
    b->indices = calloc(nc, sizeof *b->indices);
    b->colors = calloc(nc, sizeof *b->colors);
    nv = np = 0;
    for (c = 0; c < lv->ncells; c++) {
        const lv_cell *cell = &lv->cells[c];
        zs_level_cell *zc = &b->cells[c];
        mesh_acc m;
        zc->first_vertex = (uint16_t)nv;
        zc->vertex_count = (uint16_t)cell->nv;
        zc->first_portal = (uint16_t)np;
        zc->floor = (int16_t)cell->floor;
        zc->ceiling = (int16_t)cell->ceiling;
        for (k = 0; k < cell->nv; k++) {
            const int *a = lv->xy[cell->v[k]], *bb = lv->xy[cell->v[(k + 1) % cell->nv]];
            b->vertices[2 * nv] = (int16_t)a[0];
            b->vertices[2 * nv + 1] = (int16_t)a[1];
            nv++;
            if (cell->edge_kind[k] >= 0) {
                zs_level_portal *p = &b->portals[np++];
                const lv_cell *nb = &lv->cells[neighbour(lv, c, k)];
                p->ax = (int16_t)a[0];
                p->ay = (int16_t)a[1];
                p->bx = (int16_t)bb[0];
                p->by = (int16_t)bb[1];
                p->bottom = (int16_t)(nb->floor > cell->floor ? nb->floor : cell->floor);
                p->top = (int16_t)(nb->ceiling < cell->ceiling ? nb->ceiling : cell->ceiling);
                p->to = (uint16_t)neighbour(lv, c, k);
            }
        }
        zc->portal_count = (uint16_t)(np - zc->first_portal);
        memset(&m, 0, sizeof m);
        cell_mesh(lv, c, &m);
        if (m.overflow)
            return fail(err, n, "cell %d: its mesh has more than 65535 vertices or triangles", c);
        b->positions[c] = m.pos;
        b->indices[c] = m.idx;
        b->colors[c] = m.col;
        b->meshes[c].positions = m.pos;
        b->meshes[c].indices = m.idx;
        b->meshes[c].face_colors = m.col;
        b->meshes[c].scale = ZS_FX_ONE / lv->unit;
        b->meshes[c].vertex_count = (uint16_t)m.nv;
        b->meshes[c].triangle_count = (uint16_t)m.nt;
        b->total_tris += m.nt;
    }
    b->level.cell_count = (uint16_t)lv->ncells;
    b->level.portal_count = (uint16_t)np;
    b->level.vertex_count = (uint16_t)nv;
    b->level.unit = ZS_FX_ONE / lv->unit;
    b->level.vertices = b->vertices;
    b->level.cells = b->cells;
    b->level.portals = b->portals;
    b->level.pvs = b->pvs;
    b->level.meshes = b->meshes;
    return 0;
}

void lv_built_free(lv_built *b)
{
    int c;
    for (c = 0; c < b->level.cell_count && b->positions; c++) {
        free(b->positions[c]);
        free(b->indices[c]);
        free(b->colors[c]);
    }
    free(b->positions);
    free(b->indices);
    free(b->colors);
    free(b->vertices);
    free(b->cells);
    free(b->portals);
    free(b->pvs);
    free(b->meshes);
    memset(b, 0, sizeof *b);
}

/* Separator before item i of a list printed `per` to a line. */
static const char *sep(int i, int per)
{
    return i == 0 ? "\n    " : i % per ? ", " : ",\n    ";
}

int lv_emit_c(FILE *f, const lv_built *b, const char *name)
{
    const zs_level *lv = &b->level;
    int c, i, rb = (lv->cell_count + 7) / 8;
    fprintf(f, "/* Generated by zspan-level: %u cells, %u portals, %d triangles. */\n",
            lv->cell_count, lv->portal_count, b->total_tris);
    fprintf(f, "#include \"zspan/portal.h\"\n\n");
    for (c = 0; c < lv->cell_count; c++) {
        const zs_mesh *m = &lv->meshes[c];
        fprintf(f, "static const int16_t %s_pos%d[] = {", name, c);
        for (i = 0; i < 3 * m->vertex_count; i++)
            fprintf(f, "%s%d", sep(i, 12), m->positions[i]);
        fprintf(f, "};\nstatic const uint16_t %s_idx%d[] = {", name, c);
        for (i = 0; i < 3 * m->triangle_count; i++)
            fprintf(f, "%s%u", sep(i, 12), m->indices[i]);
        fprintf(f, "};\nstatic const zs_color %s_col%d[] = {", name, c);
        for (i = 0; i < m->triangle_count; i++)
            fprintf(f, "%s0x%06lXu", sep(i, 8), (unsigned long)m->face_colors[i]);
        fprintf(f, "};\n");
    }
    fprintf(f, "static const zs_mesh %s_meshes[%u] = {\n", name, lv->cell_count);
    for (c = 0; c < lv->cell_count; c++)
        fprintf(f,
                "    {.positions = %s_pos%d, .indices = %s_idx%d, .face_colors = %s_col%d, "
                ".scale = %ld, .vertex_count = %u, .triangle_count = %u},\n",
                name, c, name, c, name, c, (long)lv->meshes[c].scale, lv->meshes[c].vertex_count,
                lv->meshes[c].triangle_count);
    fprintf(f, "};\nstatic const int16_t %s_vertices[] = {", name);
    for (i = 0; i < 2 * lv->vertex_count; i++)
        fprintf(f, "%s%d", sep(i, 12), lv->vertices[i]);
    fprintf(f, "};\nstatic const zs_level_cell %s_cells[] = {\n", name);
    for (c = 0; c < lv->cell_count; c++) {
        const zs_level_cell *z = &lv->cells[c];
        fprintf(f, "    {%u, %u, %u, %u, %d, %d},\n", z->first_vertex, z->vertex_count,
                z->first_portal, z->portal_count, z->floor, z->ceiling);
    }
    fprintf(f, "};\nstatic const zs_level_portal %s_portals[] = {\n", name);
    for (i = 0; i < lv->portal_count; i++) {
        const zs_level_portal *p = &lv->portals[i];
        fprintf(f, "    {%d, %d, %d, %d, %d, %d, %u},\n", p->ax, p->ay, p->bx, p->by, p->bottom,
                p->top, p->to);
    }
    if (!lv->portal_count)
        fprintf(f, "    {0, 0, 0, 0, 0, 0, 0},\n");
    fprintf(f, "};\nstatic const uint8_t %s_pvs[] = {", name);
    for (i = 0; i < lv->cell_count * rb; i++)
        fprintf(f, "%s0x%02X", sep(i, 12), lv->pvs[i]);
    fprintf(f, "};\nconst zs_level %s = {\n    .cell_count = %u, .portal_count = %u, "
               ".vertex_count = %u, .unit = %ld,\n    .vertices = %s_vertices, .cells = %s_cells, "
               ".portals = %s_portals,\n    .pvs = %s_pvs, .meshes = %s_meshes};\n",
            name, lv->cell_count, lv->portal_count, lv->vertex_count, (long)lv->unit, name, name,
            name, name, name);
    return ferror(f) ? -1 : 0;
}
