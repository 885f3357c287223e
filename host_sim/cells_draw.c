/* SPDX-License-Identifier: MIT */
/* zspan-sim render --cells kd|grid: the scene's chunks (a mesh each, placed by
 * the one model matrix) as the objects of host-built scene cells
 * (app/zs_cells_build.c), drawn with zs_draw_cells so that whole cells
 * outside the view are never transformed (zspan/cull.h). */
#include "sim.h"

#include <stdlib.h>

#include "zs_cells_build.h"
#include "zs_model.h"
#include "zspan/cull.h"

/* The world box of a chunk: its mesh box's 8 corners through the model. */
static void world_box(const zs_mesh *m, const zs_mat34 *model, const zs_bounds *b, double lo[3],
                      double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = 1e300;
        hi[k] = -1e300;
    }
    for (int c = 0; c < 8; c++) {
        double p[3], w[3];
        for (int k = 0; k < 3; k++)
            p[k] = ((c >> k) & 1 ? b->hi[k] : b->lo[k]) * (m->scale / 65536.0);
        for (int k = 0; k < 3; k++) {
            w[k] = p[k];
            if (model)
                w[k] = model->m[k][3] / 65536.0 + (model->m[k][0] * p[0] + model->m[k][1] * p[1] +
                                                   model->m[k][2] * p[2]) / 65536.0;
            lo[k] = w[k] < lo[k] ? w[k] : lo[k];
            hi[k] = w[k] > hi[k] ? w[k] : hi[k];
        }
    }
}

zs_status sim_draw_cells(zs_renderer *r, const zs_model *scene, const zs_mat34 *model, int kind,
                         size_t *cell_count)
{
    size_t n = scene->count;
    double *lo = malloc((n ? n : 1) * 3 * sizeof *lo), *hi = malloc((n ? n : 1) * 3 * sizeof *hi);
    zs_scene_object *obj = malloc((n ? n : 1) * sizeof *obj);
    zs_cellsb_result res;
    zs_status st = ZS_ERR_ARGUMENT;
    *cell_count = 0;
    if (!lo || !hi || !obj || n == 0 || n > 65535)
        goto done;
    for (size_t i = 0; i < n; i++) {
        zs_scene_object *o = &obj[i];
        o->mesh = &scene->chunks[i].mesh;
        o->model = model;
        zs_mesh_bounds(o->mesh, &o->bounds);
        world_box(o->mesh, model, &o->bounds, &lo[3 * i], &hi[3 * i]);
    }
    if (zs_cellsb_build(lo, hi, n, kind, kind == ZS_CELLS_KD ? ZS_CELLS_DEFAULT_PARAM : 6,
                        &res) != NULL)
        goto done;
    {
        zs_scene_object *ordered = malloc(n * sizeof *ordered);
        if (ordered) {
            for (size_t i = 0; i < n; i++)
                ordered[i] = obj[res.order[i]];
            zs_cells sc = {res.cells, ordered, (uint16_t)res.cell_count, (uint16_t)n};
            st = zs_draw_cells(r, &sc);
            *cell_count = res.cell_count;
            free(ordered);
        }
    }
    zs_cellsb_free(&res);
done:
    free(lo);
    free(hi);
    free(obj);
    return st;
}
