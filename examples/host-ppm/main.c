/* SPDX-License-Identifier: MIT */
/*
 * Example: one frame of two cubes cutting into each other, rendered on the
 * host into a PPM file, band by band; nothing but zspan and the C library.
 *
 *     cc -std=c99 -Ipath/to/zspan/include main.c path/to/libzspan.a -o host-ppm
 *     ./host-ppm frame.ppm        (prints the frame's FNV-1a checksum)
 *
 * Also the program the packaging test builds outside the tree (zspan.mk,
 * CMake, pkg-config): every build must print the same checksum.
 */
#include <stdint.h>
#include <stdio.h>

#include "zspan/zspan.h"

#define W 160
#define H 120
#define BAND 8

/* Corner i: x = bit 0, y = bit 1, z = bit 2 (set = +1); faces counter-clockwise
 * seen from outside: +x, -x, +y, -y, +z, -z. */
static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1, -1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1,
};
static const uint16_t cube_idx[12 * 3] = {
    1, 3, 7, 1, 7, 5, 0, 6, 2, 0, 4, 6, 2, 6, 7, 2, 7, 3,
    0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 3, 1, 0, 2, 3,
};
static const zs_color cube_colors[12] = {
    ZS_RGB(230, 80, 60),  ZS_RGB(230, 80, 60),  ZS_RGB(60, 180, 90),  ZS_RGB(60, 180, 90),
    ZS_RGB(70, 120, 230), ZS_RGB(70, 120, 230), ZS_RGB(240, 200, 60), ZS_RGB(240, 200, 60),
    ZS_RGB(200, 90, 210), ZS_RGB(200, 90, 210), ZS_RGB(90, 210, 220), ZS_RGB(90, 210, 220),
};

/* Room for every triangle, vertex and edge of the scene (zs_frame_stats gives
 * the real use: 12 records, 16 vertices, 10 edge sides here). */
static uint8_t arena[ZS_ARENA_BYTES(W, H, 24, 16, 16)];
static uint8_t band[BAND * W * 3];

typedef struct output {
    FILE *file;
    uint32_t sum;
} output;

/* zs_render_frame hands over each finished band of rows. */
static int write_band(void *user, int y0, int rows, const void *buf, size_t stride)
{
    output *o = user;
    const uint8_t *p = buf;
    int y;
    size_t i;
    (void)y0;
    for (y = 0; y < rows; y++, p += stride) {
        for (i = 0; i < W * 3; i++) {
            o->sum ^= p[i];
            o->sum *= 0x01000193u; /* FNV-1a 32 */
        }
        if (fwrite(p, 1, W * 3, o->file) != W * 3)
            return 1;
    }
    return 0;
}

static zs_mat34 place(int ry_deg, int rx_deg, zs_fixed x, zs_fixed y, zs_fixed z)
{
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(ry_deg)), rx = zs_mat34_rotate_x(ZS_FX(rx_deg));
    zs_mat34 t = zs_mat34_translate(x, y, z);
    zs_mat34 m = zs_mat34_mul(&rx, &ry);
    return zs_mat34_mul(&t, &m);
}

int main(int argc, char **argv)
{
    static zs_renderer r;
    const char *path = argc > 1 ? argv[1] : "frame.ppm";
    zs_config cfg = zs_config_default(W, H, 24, 16, 16);
    zs_mesh cube = {cube_pos, cube_idx, cube_colors, NULL, NULL, NULL, ZS_FX_RATIO(7, 10), 8, 12,
                    0, NULL, NULL};
    zs_vec3 eye = zs_vec3_make(0, ZS_FX(1), ZS_FX(4));
    zs_vec3 target = zs_vec3_make(0, 0, 0), up = zs_vec3_make(0, ZS_FX(1), 0);
    zs_shade_params look = zs_shade_default();
    zs_camera cam;
    zs_mat34 a = place(30, 20, -ZS_FX_RATIO(45, 100), 0, 0);
    zs_mat34 b = place(-25, -10, ZS_FX_RATIO(45, 100), ZS_FX_RATIO(2, 10), ZS_FX_RATIO(2, 10));
    output out = {NULL, 0x811C9DC5u};
    zs_status st;

    look.format = ZS_FMT_RGB888;
    look.background = ZS_RGB(20, 24, 36);
    look.ambient = ZS_FX_RATIO(3, 10);
    look.light_count = 1;
    look.lights[0].direction = zs_vec3_make(-ZS_FX_RATIO(5, 10), ZS_FX(1), ZS_FX_RATIO(8, 10));
    look.lights[0].intensity = ZS_FX_RATIO(7, 10);

    st = zs_init(&r, arena, sizeof arena, &cfg);
    if (st == ZS_OK)
        st = zs_camera_look_at(&cam, eye, target, up);
    if (st == ZS_OK)
        st = zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(20));
    if (st == ZS_OK)
        st = zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
    if (st == ZS_OK)
        st = zs_frame_shading(&r, &look);
    if (st == ZS_OK)
        st = zs_draw(&r, &cube, &a);
    if (st == ZS_OK)
        st = zs_draw(&r, &cube, &b);
    if (st != ZS_OK) {
        fprintf(stderr, "host-ppm: %s\n", zs_strerror(st));
        return 1;
    }
    out.file = fopen(path, "wb");
    if (!out.file) {
        perror(path);
        return 1;
    }
    fprintf(out.file, "P6\n%d %d\n255\n", W, H);
    st = zs_render_frame(&r, band, W * 3, BAND, write_band, &out);
    if (fclose(out.file) != 0 || st != ZS_OK || zs_frame_stats(&r)->rows != H) {
        fprintf(stderr, "host-ppm: could not write %s\n", path);
        return 1;
    }
    printf("%s: %dx%d, %lu triangles drawn, checksum %08lx\n", path, W, H,
           (unsigned long)zs_frame_stats(&r)->tris_drawn, (unsigned long)out.sum);
    return 0;
}
