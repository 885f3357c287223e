/* SPDX-License-Identifier: MIT */
/* The benchmark scenes; see bench_scenes.h. */
#include "bench_scenes.h"

#include "bench_caps.h"
#include "cluster.h"
#include "cubes.h"
#include "sphere285.h"
#include "wuson.h"

const bench_scene bench_scenes[BENCH_SCENE_COUNT] = {
    {"sphere285", &bench_sphere285, ZS_FX(-3), 0, BENCH_CAPS_SPHERE285},
    {"cubes", &bench_cubes, ZS_FX(-8), ZS_FX(20), BENCH_CAPS_CUBES},
    {"wuson", &bench_wuson, ZS_FX(-3), 0, BENCH_CAPS_WUSON},
    {"cluster", &bench_cluster, ZS_FX(-3), ZS_FX(20), BENCH_CAPS_CLUSTER},
};

zs_mat34 bench_model_view(const bench_scene *s, int frame)
{
    zs_mat34 t = zs_mat34_translate(0, 0, s->tz);
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(30 + 2 * frame));
    zs_mat34 m;
    if (s->rx_deg) {
        zs_mat34 rx = zs_mat34_rotate_x(s->rx_deg);
        zs_mat34 rxy = zs_mat34_mul(&rx, &ry);
        m = zs_mat34_mul(&t, &rxy);
    } else {
        m = zs_mat34_mul(&t, &ry);
    }
    return m;
}

zs_config bench_config(const bench_scene *s)
{
    /* the scenes are flat and unlit: no per-vertex shading pools */
    zs_config c = zs_config_default(BENCH_W, BENCH_H, s->max_triangles, s->max_vertices,
                                    s->max_active_edges);
    c.flags = ZS_CFG_FLAT_ONLY;
    return c;
}

zs_status bench_camera(zs_camera *cam)
{
    static const zs_camera zero;
    zs_mat34 id = zs_mat34_identity();
    zs_status st;
    *cam = zero;
    st = zs_camera_set_view(cam, &id);
    if (st != ZS_OK)
        return st;
    return zs_camera_perspective(cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(100));
}

zs_status bench_submit(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int frame,
                       zs_visibility mode)
{
    zs_mat34 mv = bench_model_view(s, frame);
    zs_status st = zs_frame_begin(r, cam, mode);
    if (st != ZS_OK)
        return st;
    return zs_draw(r, s->mesh, &mv);
}

const char *const bench_mono_names[BENCH_MONO_VARIANTS] = {
    "mono-bayer", "mono-diffuse", "mono-lines", "gray4", "gray4-dither"};

zs_status bench_mono_frame(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int k,
                           uint32_t *sum)
{
    static uint8_t page[BENCH_W]; /* one page of 8 rows, or one row of bits */
    zs_mat34 mv = bench_model_view(s, 0);
    zs_shade_params sp = zs_shade_default();
    zs_status st = zs_frame_begin(r, cam, ZS_MODE_SPAN);
    int y;
    int rows = k == 1 || k == 2 ? 8 : 1; /* pages of 8 rows, or single rows */
    size_t n = k == 0 ? BENCH_W / 8 : k >= 3 ? BENCH_W / 2 : BENCH_W;
    if (st != ZS_OK)
        return st;
    sp.format = k == 0 ? ZS_FMT_MONO_MSB : k >= 3 ? ZS_FMT_GRAY4 : ZS_FMT_MONO_PAGE;
    sp.mono = (uint8_t)(k == 1   ? ZS_MONO_DIFFUSE
                        : k == 2 ? ZS_MONO_LINES
                        : k == 4 ? ZS_GRAY4_DITHER
                                 : 0u);
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK || (st = zs_draw(r, s->mesh, &mv)) != ZS_OK)
        return st;
    *sum = BENCH_FNV_BASIS;
    for (y = 0; st == ZS_OK && y < BENCH_H; y += rows) {
        st = zs_render_rows(r, y, rows, page, n);
        *sum = bench_fnv1a(*sum, page, n);
    }
    return st;
}

uint32_t bench_fnv1a(uint32_t h, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x01000193u;
    }
    return h;
}
