/* SPDX-License-Identifier: MIT */
/* Culling by boxes before the transform (zspan/cull.h): a draw's box, or a
 * scene cell's, against the six planes of the view frustum in clip space. */
#include "zs_internal.h"
#include "zspan/cull.h"

#define COORD_LIMIT ((int64_t)1 << 46) /* |world coordinate|, Q16 (2^30 units) */

void zs_mesh_bounds(const zs_mesh *mesh, zs_bounds *out)
{
    uint32_t i;
    int k;
    memset(out, 0, sizeof *out);
    if (!mesh || !mesh->positions || mesh->vertex_count == 0)
        return;
    for (k = 0; k < 3; k++)
        out->lo[k] = out->hi[k] = mesh->positions[k];
    for (i = 1; i < mesh->vertex_count; i++)
        for (k = 0; k < 3; k++) {
            int16_t v = mesh->positions[3u * i + (uint32_t)k];
            out->lo[k] = v < out->lo[k] ? v : out->lo[k];
            out->hi[k] = v > out->hi[k] ? v : out->hi[k];
        }
}

static int64_t clamp_coord(zs_renderer *r, int64_t v)
{
    if (v > COORD_LIMIT || v < -COORD_LIMIT) {
        r->stats.saturated++;
        return v > 0 ? COORD_LIMIT : -COORD_LIMIT;
    }
    return v;
}

/* m * p (Q16.16 in and out, p within COORD_LIMIT). */
static void apply(zs_renderer *r, const zs_mat34 *m, const int64_t p[3], int64_t out[3])
{
    int k, j;
    for (k = 0; k < 3; k++) {
        int64_t s = m->m[k][3];
        for (j = 0; j < 3; j++)
            s += zs_mul_q16_wide(p[j], m->m[k][j]);
        out[k] = clamp_coord(r, s);
    }
}

/* Are the 8 corners of the world box (corner k from lo / hi by its bits)
 * all beyond one frustum plane? corner_world gives corner k in world space. */
typedef void (*corner_fn)(zs_renderer *r, const void *box, int k, int64_t world[3]);

static int box_outside(zs_renderer *r, const void *box, corner_fn corner)
{
    /* bit p of `beyond` stays set while every corner so far is past plane p */
    unsigned beyond = 0x3Fu;
    int k;
    for (k = 0; k < 8 && beyond; k++) {
        int64_t world[3], eye[3], xc, yc, w, margin;
        unsigned out = 0;
        corner(r, box, k, world);
        apply(r, &r->cam.view, world, eye);
        xc = zs_mul_q16_wide(eye[0], r->priv.proj_sx);
        yc = zs_mul_q16_wide(eye[1], r->priv.proj_sy);
        w = -eye[2];
        /* wider than any rounding of the vertex transform */
        margin = (w < 0 ? -w : w) / 256 + 64;
        if (w < r->cam.near_z - margin)
            out |= 0x01u;
        if (w > r->cam.far_z + margin)
            out |= 0x02u;
        if (xc < -w - margin)
            out |= 0x04u;
        if (xc > w + margin)
            out |= 0x08u;
        if (yc < -w - margin)
            out |= 0x10u;
        if (yc > w + margin)
            out |= 0x20u;
        beyond &= out;
    }
    return beyond != 0;
}

typedef struct mesh_box {
    const zs_mesh *mesh;
    const zs_mat34 *model;
    const zs_bounds *b;
} mesh_box;

static void mesh_corner(zs_renderer *r, const void *box, int k, int64_t world[3])
{
    const mesh_box *mb = (const mesh_box *)box;
    int64_t p[3];
    int j;
    for (j = 0; j < 3; j++) {
        int16_t v = (k >> j) & 1 ? mb->b->hi[j] : mb->b->lo[j];
        p[j] = (int64_t)v * mb->mesh->scale; /* < 2^46 */
    }
    apply(r, mb->model, p, world);
}

static void cell_corner(zs_renderer *r, const void *box, int k, int64_t world[3])
{
    const zs_cell *c = (const zs_cell *)box;
    int j;
    (void)r;
    for (j = 0; j < 3; j++)
        world[j] = (k >> j) & 1 ? c->hi[j] : c->lo[j];
}

/* The frame counts of a draw left out whole. */
static void count_untransformed(zs_renderer *r, const zs_mesh *m)
{
    r->stats.tris_submitted += m->triangle_count;
    r->stats.tris_rejected += m->triangle_count;
    r->stats.tris_untransformed += m->triangle_count;
    r->stats.verts_untransformed += m->vertex_count;
    r->priv.tag_counter += m->triangle_count; /* its tags, as zs_draw would use them */
}

static zs_status check_mesh(const zs_mesh *m)
{
    uint32_t i;
    if (!m->positions || !m->indices || m->scale == 0 || m->vertex_count == 0)
        return ZS_ERR_MESH;
    for (i = 0; i < 3u * m->triangle_count; i++)
        if (m->indices[i] >= m->vertex_count)
            return ZS_ERR_INDEX;
    return ZS_OK;
}

zs_status zs_draw_bounded(zs_renderer *r, const zs_mesh *m, const zs_mat34 *model,
                          const zs_bounds *b)
{
    mesh_box mb;
    zs_status st;
    int k;
    if (!r || !m)
        return ZS_ERR_NULL;
    if (!b)
        return zs_draw(r, m, model);
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    st = check_mesh(m);
    if (st != ZS_OK)
        return st;
    for (k = 0; k < 3; k++)
        if (b->lo[k] > b->hi[k])
            return ZS_ERR_ARGUMENT;
    mb.mesh = m;
    mb.model = model ? model : &zs_identity34;
    mb.b = b;
    if (box_outside(r, &mb, mesh_corner)) {
        count_untransformed(r, m);
        return ZS_OK;
    }
    return zs_draw(r, m, model);
}

zs_status zs_cells_check(const zs_cells *s)
{
    /* depth-first from the root; each level remembers its next child and
     * the object its range must end at */
    uint16_t next_child[ZS_CELLS_MAX_DEPTH], end_child[ZS_CELLS_MAX_DEPTH];
    uint32_t end_obj[ZS_CELLS_MAX_DEPTH];
    uint32_t expect_child = 1, next_obj = 0, i;
    int depth = 0, k;
    if (!s || !s->cells || (!s->objects && s->object_count))
        return ZS_ERR_NULL;
    if (s->cell_count == 0)
        return ZS_ERR_BSP;
    for (i = 0; i < s->object_count; i++)
        if (!s->objects[i].mesh)
            return ZS_ERR_NULL;
    /* breadth-first layout: children right after the previous cells' */
    for (i = 0; i < s->cell_count; i++) {
        const zs_cell *c = &s->cells[i];
        for (k = 0; k < 3; k++)
            if (c->lo[k] > c->hi[k])
                return ZS_ERR_BSP;
        if ((uint32_t)c->first_object + c->object_count > s->object_count)
            return ZS_ERR_BSP;
        if (c->child_count == 0)
            continue;
        if (c->first_child != expect_child || c->first_child <= i)
            return ZS_ERR_BSP;
        expect_child += c->child_count;
        if (expect_child > s->cell_count)
            return ZS_ERR_BSP;
    }
    if (expect_child != s->cell_count || s->cells[0].object_count != s->object_count)
        return ZS_ERR_BSP; /* every cell reached, every object in the root's range */
    /* ranges: a leaf's objects follow the previous leaf's, an inner cell's
     * range is its children's together */
    i = 0;
    for (;;) {
        const zs_cell *c = &s->cells[i];
        if (c->first_object != next_obj)
            return ZS_ERR_BSP;
        if (c->child_count == 0) {
            next_obj += c->object_count;
        } else {
            if (depth >= ZS_CELLS_MAX_DEPTH - 1)
                return ZS_ERR_BSP;
            next_child[depth] = c->first_child;
            end_child[depth] = (uint16_t)(c->first_child + c->child_count);
            end_obj[depth] = (uint32_t)c->first_object + c->object_count;
            depth++;
        }
        /* the next cell: the next child of the innermost level left */
        while (depth > 0 && next_child[depth - 1] == end_child[depth - 1]) {
            depth--;
            if (next_obj != end_obj[depth])
                return ZS_ERR_BSP;
        }
        if (depth == 0)
            break;
        i = next_child[depth - 1]++;
    }
    return ZS_OK;
}

/* The objects [first, first + n) of a culled cell: counted, not drawn. */
static void skip_objects(zs_renderer *r, const zs_cells *s, uint32_t first, uint32_t n)
{
    uint32_t i;
    for (i = first; i < first + n; i++)
        count_untransformed(r, s->objects[i].mesh);
}

zs_status zs_draw_cells(zs_renderer *r, const zs_cells *s)
{
    uint16_t next_child[ZS_CELLS_MAX_DEPTH], end_child[ZS_CELLS_MAX_DEPTH];
    int depth = 0;
    uint32_t i = 0;
    zs_status st;
    if (!r)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    st = zs_cells_check(s);
    if (st != ZS_OK)
        return st;
    for (;;) {
        const zs_cell *c = &s->cells[i];
        if (box_outside(r, c, cell_corner)) {
            r->stats.cells_culled++;
            skip_objects(r, s, c->first_object, c->object_count);
        } else if (c->child_count == 0) {
            uint32_t k;
            for (k = c->first_object; k < (uint32_t)c->first_object + c->object_count; k++) {
                const zs_scene_object *o = &s->objects[k];
                st = zs_draw_bounded(r, o->mesh, o->model, &o->bounds);
                if (st != ZS_OK)
                    return st;
            }
        } else { /* checked: depth stays below ZS_CELLS_MAX_DEPTH */
            next_child[depth] = c->first_child;
            end_child[depth] = (uint16_t)(c->first_child + c->child_count);
            depth++;
        }
        while (depth > 0 && next_child[depth - 1] == end_child[depth - 1])
            depth--;
        if (depth == 0)
            break;
        i = next_child[depth - 1]++;
    }
    return ZS_OK;
}
