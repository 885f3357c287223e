/* SPDX-License-Identifier: MIT */
/* The demo or mesh scene of the animated programs (see zs_scene.h). */
#include "zs_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int zs_scene_load(zs_scene *s, const char *const *meshes, int nmeshes, zs_shading shade,
                  const char *prog)
{
    return zs_scene_load_meshes(s, meshes, nmeshes, shade, 0, 0, 0, prog);
}

int zs_scene_load_meshes(zs_scene *s, const char *const *meshes, int nmeshes, zs_shading shade,
                         int flip, int two_sided, int up_axis, const char *prog)
{
    memset(s, 0, sizeof *s);
    if (nmeshes == 0) {
        s->demo = malloc(sizeof *s->demo);
        if (s->demo == NULL) {
            fprintf(stderr, "%s: out of memory\n", prog);
            return -1;
        }
        demo_scene_init(s->demo);
        s->max_tris = DEMO_TRIANGLES * 2u + 64u;
        return 0;
    }
#ifdef ZS_APP_NO_MESH
    (void)meshes;
    (void)shade;
    (void)flip;
    (void)two_sided;
    (void)up_axis;
    fprintf(stderr, "%s: built without mesh loading (assimp)\n", prog);
    return -1;
#else
    {
        zs_model_opts mo = zs_model_opts_default();
        unsigned long limit = ZS_MAX_TRIANGLES / (two_sided ? 6u : 3u);
        int f;
        mo.prog = prog;
        mo.want_normals = shade == ZS_SHADE_GOURAUD;
        mo.flip_winding = flip;
        mo.up = up_axis;
        for (f = 0; f < nmeshes; f++)
            if (zs_model_load_opts(&s->model, meshes[f], &mo) != 0)
                return -1;
        /* Clipping may split triangles: the pool holds three per triangle. */
        if (s->model.total_tris > limit) {
            fprintf(stderr,
                    "%s: %lu triangles: an animated view takes at most %lu%s; decimate with "
                    "zspan-meshc --max-triangles %lu --format zsm -o out/model FILE and give "
                    "--mesh out/model.zsm\n",
                    prog, (unsigned long)s->model.total_tris, limit,
                    two_sided ? " with --two-sided" : "", limit);
            return -1;
        }
        if (zs_model_fit_and_colour(&s->model) != 0 ||
            (two_sided && zs_model_add_back_faces(&s->model) != 0)) {
            fprintf(stderr, "%s: cannot prepare the meshes\n", prog);
            return -1;
        }
        s->max_tris = s->model.total_tris * 3u + 64u;
        return 0;
    }
#endif
}

zs_status zs_scene_frame(zs_renderer *r, const zs_scene *s, long start, long k, double spin,
                         zs_visibility mode, zs_shading shade, zs_format fmt)
{
    if (s->demo != NULL) {
        long step = spin >= 3.0 ? lround(spin / 3.0) : (spin > 0.0 ? 1 : 0);
        return demo_frame_mono(r, s->demo, (uint32_t)(start + k * step), mode, shade, fmt,
                               s->mono);
    }
#ifdef ZS_APP_NO_MESH
    (void)start;
    (void)k;
    (void)mode;
    (void)shade;
    (void)fmt;
    return ZS_ERR_STATE;
#else
    return zs_model_frame(r, &s->model, mode, shade, fmod(spin * (double)(k + start), 360.0),
                          fmt, s->mono);
#endif
}

void zs_scene_free(zs_scene *s)
{
    free(s->demo);
#ifndef ZS_APP_NO_MESH
    zs_model_free(&s->model);
#endif
    memset(s, 0, sizeof *s);
}
