/* SPDX-License-Identifier: MIT */
/* The Stellaris OLED scenes (see oled_scene.h). */
#include "oled_scene.h"

#include "demo_scene.h"

zs_config oled_big_config(void)
{
    zs_config c = zs_config_default(OLED_BIG_W, OLED_BIG_H, OLED_BIG_TRIS, OLED_BIG_VERTS,
                                    OLED_BIG_EDGES);
    c.flags = OLED_BIG_FLAGS;
    return c;
}

zs_config oled_small_config(void)
{
    zs_config c = zs_config_default(OLED_SMALL_W, OLED_SMALL_H, OLED_SMALL_TRIS,
                                    OLED_SMALL_VERTS, OLED_SMALL_EDGES);
    c.flags = OLED_SMALL_FLAGS;
    return c;
}

zs_status oled_big_frame(zs_renderer *r, const struct demo_scene *s, uint32_t f)
{
    zs_camera cam;
    zs_shade_params p;
    zs_status st = demo_camera(&cam, 8u * f); /* 3 degrees a demo frame: 24 */
    if (st == ZS_OK)
        st = zs_frame_begin(r, &cam, ZS_MODE_SPAN);
    p = demo_shading(ZS_SHADE_GOURAUD, ZS_FMT_GRAY4);
    p.mono = ZS_GRAY4_DITHER;
    if (st == ZS_OK)
        st = zs_frame_shading(r, &p);
    return st == ZS_OK ? demo_scene_draw(r, s) : st;
}

/* A cube with corners at +-1 (scale 0.5), counter-clockwise faces. */
static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1,
};
static const uint16_t cube_idx[12 * 3] = {
    4, 5, 6, 4, 6, 7, 1, 0, 3, 1, 3, 2, 5, 1, 2, 5, 2, 6,
    0, 4, 7, 0, 7, 3, 7, 6, 2, 7, 2, 3, 0, 1, 5, 0, 5, 4,
};

zs_status oled_small_frame(zs_renderer *r, uint32_t f)
{
    zs_mesh cube = {0};
    zs_camera cam;
    zs_shade_params p = zs_shade_default();
    zs_mat34 spin = zs_mat34_rotate_y((zs_fixed)((f * 20u) % 360u) * ZS_FX_ONE);
    zs_mat34 tilt = zs_mat34_rotate_x(ZS_FX(30)), model = zs_mat34_mul(&tilt, &spin);
    zs_status st;
    cube.positions = cube_pos;
    cube.indices = cube_idx;
    cube.scale = ZS_FX(1) / 2;
    cube.vertex_count = 8;
    cube.triangle_count = 12;
    cube.color = ZS_RGB(255, 255, 255);
    /* a wide, short view: the cube fills the 16 rows */
    st = zs_camera_look_at(&cam, zs_vec3_make(0, 0, ZS_FX(2)), zs_vec3_make(0, 0, 0),
                           zs_vec3_make(0, ZS_FX(1), 0));
    if (st == ZS_OK)
        st = zs_camera_perspective(&cam, ZS_FX(40), ZS_FX(1) / 10, ZS_FX(10));
    if (st == ZS_OK)
        st = zs_frame_begin(r, &cam, ZS_MODE_SPAN);
    p.format = ZS_FMT_MONO_PAGE;
    p.ambient = ZS_FX_RATIO(15, 100);
    p.light_count = 1;
    p.lights[0].direction = zs_vec3_make(-ZS_FX(1), ZS_FX(1), ZS_FX(2));
    p.lights[0].intensity = ZS_FX_RATIO(85, 100);
    if (st == ZS_OK)
        st = zs_frame_shading(r, &p);
    return st == ZS_OK ? zs_draw(r, &cube, &model) : st;
}
