/* SPDX-License-Identifier: MIT */
/* Helpers shared by the port tests (see ports_common.h). */
#include "ports_common.h"

#include <stdio.h>
#include <stdlib.h>

#include "demo_scene.h"

uint32_t *ports_demo_666(unsigned w, unsigned h, uint32_t frame)
{
    static demo_scene scene;
    static int scene_ready;
    zs_renderer r;
    zs_config cfg;
    size_t arena_size, stride = (size_t)w * 2u;
    void *arena;
    uint8_t *rows;
    uint32_t *out;
    unsigned max_tris = DEMO_TRIANGLES * 2u + 64u, i;
    int ok;

    if (!scene_ready) {
        demo_scene_init(&scene);
        scene_ready = 1;
    }
    cfg = zs_config_default((uint16_t)w, (uint16_t)h, (uint16_t)max_tris,
                            (uint16_t)(max_tris * 3u > ZS_MAX_VERTICES ? ZS_MAX_VERTICES
                                                                       : max_tris * 3u),
                            ZS_MAX_ACTIVE_EDGES);
    arena_size = zs_arena_bytes(&cfg);
    arena = malloc(arena_size);
    rows = malloc(stride * h);
    out = malloc((size_t)w * h * sizeof *out);
    ok = arena != NULL && rows != NULL && out != NULL &&
         zs_init(&r, arena, arena_size, &cfg) == ZS_OK &&
         demo_frame(&r, &scene, frame, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_RGB565_BE) ==
             ZS_OK &&
         zs_render_rows(&r, 0, (int)h, rows, stride) == ZS_OK;
    if (ok)
        for (i = 0; i < w * h; i++)
            out[i] = emu_666_from_565be(rows + (size_t)i * 2u);
    free(arena);
    free(rows);
    if (!ok) {
        free(out);
        return NULL;
    }
    return out;
}

unsigned ports_image_diff(const uint32_t *got, const uint32_t *want, unsigned w, unsigned h,
                          const char *what)
{
    unsigned x, y, bad = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            uint32_t a = got[(size_t)y * w + x], b = want[(size_t)y * w + x];
            if (a != b) {
                if (bad == 0)
                    printf("    %s: first difference at (%u, %u): want %05X got %05X\n", what, x,
                           y, (unsigned)b, (unsigned)a);
                bad++;
            }
        }
    return bad;
}

unsigned ports_view_diff(const emu_panel *e, const uint32_t *want, unsigned w, unsigned h)
{
    unsigned vw, vh, bad;
    uint32_t *view;
    emu_view_size(e, 0, &vw, &vh);
    if (vw != w || vh != h) {
        printf("    view is %ux%u, want %ux%u\n", vw, vh, w, h);
        return w * h;
    }
    view = malloc((size_t)w * h * sizeof *view);
    if (view == NULL)
        return w * h;
    emu_view_666(e, 0, view);
    bad = ports_image_diff(view, want, w, h, "panel view");
    free(view);
    return bad;
}
