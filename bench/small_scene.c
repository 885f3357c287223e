/* SPDX-License-Identifier: MIT */
/*
 * A scene small enough for an 8 KB AVR (ATmega2560): three cubes, two of them
 * cutting into each other, and an octahedron with vertex colours and normals,
 * at 160x128. The same source runs on the host, on the AVR under simavr and on
 * RISC-V under QEMU; every frame's checksum must be the same everywhere.
 *
 * Output, one line per frame (FNV-1a 32 over every row's bytes, as the bench):
 *
 *   R BOARD small SHADE MODE FRAME sum=XXXXXXXX records=N
 *   K BOARD big_arena=N init=STATUS         (the largest configuration's arena size
 *                                            and what zs_init says of it)
 *   M BOARD arena=N static=N stack=N        (memory, from the port)
 *
 * Runs every shading (flat lit, Gouraud lit with fog) in both visibility modes
 * for SMALL_FRAMES frames (frame f turns the objects 9 degrees further). Around
 * each frame's zs_frame_begin .. last zs_render_rows the port's small_mark(1)
 * and small_mark(2) let a simulator count its cycles.
 *
 * Freestanding but for printf (the port gives stdout).
 */
#include <stdint.h>
#include <stdio.h>

#include "small_port.h"
#include "zspan/zspan.h"

#ifndef SMALL_FRAMES
#define SMALL_FRAMES 4
#endif
#define SMALL_W 160
#define SMALL_H 128
/* Pools: the largest use over 360 degrees of the animation on the host, with
 * a margin (22 records, 30 vertices, 32 edge sides over 40 frames of 9 degrees). */
#ifndef SMALL_TRIS
#define SMALL_TRIS 28
#define SMALL_VERTS 36
#define SMALL_EDGES 36
#endif

/* Corner i: x = bit 0, y = bit 1, z = bit 2 (set = +1). */
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
/* Octahedron: +x, -x, +y, -y, +z, -z; normals equal positions (Q1.14). */
static const int16_t octa_pos[6 * 3] = {
    1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1,
};
static const int16_t octa_nrm[6 * 3] = {
    16384, 0, 0, -16384, 0, 0, 0, 16384, 0, 0, -16384, 0, 0, 0, 16384, 0, 0, -16384,
};
static const uint16_t octa_idx[8 * 3] = {
    0, 2, 4, 4, 2, 1, 1, 2, 5, 5, 2, 0, 4, 3, 0, 1, 3, 4, 5, 3, 1, 0, 3, 5,
};
static const zs_color octa_colors[6] = {
    ZS_RGB(255, 60, 60), ZS_RGB(60, 255, 60), ZS_RGB(60, 60, 255),
    ZS_RGB(255, 255, 60), ZS_RGB(60, 255, 255), ZS_RGB(255, 60, 255),
};

static uint8_t arena[ZS_ARENA_BYTES(SMALL_W, SMALL_H, SMALL_TRIS, SMALL_VERTS, SMALL_EDGES)];
static uint8_t line[SMALL_W * 2];

static zs_mat34 place(int32_t deg, zs_fixed tx, zs_fixed ty, zs_fixed tz, int32_t tilt)
{
    zs_mat34 ry = zs_mat34_rotate_y(deg * ZS_FX_ONE);
    zs_mat34 rx = zs_mat34_rotate_x(tilt * ZS_FX_ONE);
    zs_mat34 t = zs_mat34_translate(tx, ty, tz);
    zs_mat34 m = zs_mat34_mul(&rx, &ry);
    return zs_mat34_mul(&t, &m);
}

static zs_status submit(zs_renderer *r, const zs_camera *cam, int gouraud, int zline, int frame)
{
    zs_mesh cube = {cube_pos, cube_idx, cube_colors, NULL, NULL, NULL, ZS_FX_RATIO(1, 2), 8, 12, 0,
                    NULL, NULL};
    zs_mesh octa = {octa_pos, octa_idx, NULL, octa_colors, NULL, octa_nrm, ZS_FX_RATIO(7, 10),
                    6, 8, 0, NULL, NULL};
    zs_shade_params p = zs_shade_default();
    int32_t a = 9 * (int32_t)frame;
    zs_mat34 m;
    zs_status st = zs_frame_begin(r, cam, zline ? ZS_MODE_ZLINE : ZS_MODE_SPAN);
    if (st != ZS_OK)
        return st;
    p.shading = gouraud ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    p.background = ZS_RGB(20, 24, 36);
    p.ambient = ZS_FX_RATIO(25, 100);
    p.light_count = 2;
    p.lights[0].direction = zs_vec3_make(-ZS_FX_RATIO(5, 10), ZS_FX(1), ZS_FX_RATIO(8, 10));
    p.lights[0].intensity = ZS_FX_RATIO(70, 100);
    p.lights[1].direction = zs_vec3_make(ZS_FX(1), -ZS_FX_RATIO(2, 10), ZS_FX_RATIO(3, 10));
    p.lights[1].intensity = ZS_FX_RATIO(30, 100);
    if (gouraud) {
        p.fog.enabled = 1;
        p.fog.color = p.background;
        p.fog.start = ZS_FX(3);
        p.fog.end = ZS_FX(7);
    }
    st = zs_frame_shading(r, &p);
    /* two cubes cutting into each other, one apart, the octahedron in front */
    m = place(30 + a, -ZS_FX_RATIO(4, 10), 0, -ZS_FX(4), 20);
    if (st == ZS_OK)
        st = zs_draw(r, &cube, &m);
    m = place(75 - 2 * a, ZS_FX_RATIO(1, 10), ZS_FX_RATIO(3, 10), -ZS_FX_RATIO(42, 10), -15);
    if (st == ZS_OK)
        st = zs_draw(r, &cube, &m);
    m = place(a, ZS_FX_RATIO(15, 10), -ZS_FX_RATIO(6, 10), -ZS_FX(5), 35);
    if (st == ZS_OK)
        st = zs_draw(r, &cube, &m);
    m = place(3 * a, -ZS_FX_RATIO(13, 10), -ZS_FX_RATIO(4, 10), -ZS_FX_RATIO(32, 10), 10);
    if (st == ZS_OK)
        st = zs_draw(r, &octa, &m);
    return st;
}

static uint32_t fnv1a(uint32_t h, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x01000193u;
    }
    return h;
}

int main(void)
{
    static zs_renderer r;
    zs_camera cam;
    zs_config cfg = zs_config_default(SMALL_W, SMALL_H, SMALL_TRIS, SMALL_VERTS, SMALL_EDGES);
    zs_mat34 view = zs_mat34_identity();
    int shade, mode, f, errors = 0;

    small_port_init();
    {
        /* the largest configuration: on a 16-bit size_t its arena cannot be
         * addressed, so zs_arena_bytes gives 0 and zs_init refuses it */
        zs_config big = zs_config_default(ZS_MAX_DIM, ZS_MAX_DIM, ZS_MAX_TRIANGLES,
                                          ZS_MAX_VERTICES, ZS_MAX_ACTIVE_EDGES);
        printf("K %s big_arena=%lu init=%d\n", SMALL_BOARD, (unsigned long)zs_arena_bytes(&big),
               (int)zs_init(&r, arena, sizeof arena, &big));
    }
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK || zs_camera_set_view(&cam, &view) ||
        zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(20))) {
        printf("E %s init\n", SMALL_BOARD);
        small_port_exit(1);
        return 1;
    }
    for (shade = 0; shade < 2; shade++)
        for (mode = 0; mode < 2; mode++)
            for (f = 0; f < SMALL_FRAMES; f++) {
                uint32_t sum = 0x811C9DC5u;
                zs_status st;
                int y;
                small_mark(1);
                st = submit(&r, &cam, shade, mode, f);
                for (y = 0; st == ZS_OK && y < SMALL_H; y++) {
                    st = zs_render_rows(&r, y, 1, line, sizeof line);
                    small_mark(3); /* the checksum is not the renderer's work */
                    sum = fnv1a(sum, line, sizeof line);
                    small_mark(4);
                }
                small_mark(2);
                if (st != ZS_OK) {
                    printf("E %s %d %d %d status %d\n", SMALL_BOARD, shade, mode, f, (int)st);
                    errors++;
                    continue;
                }
                printf("R %s small %s %s %d sum=%08lx records=%lu verts=%lu edges=%lu dropped=%lu\n",
                       SMALL_BOARD, shade ? "gouraud" : "flat", mode ? "zline" : "span", f,
                       (unsigned long)sum, (unsigned long)r.stats.records,
                       (unsigned long)r.stats.verts_stored, (unsigned long)r.stats.max_active_edges,
                       (unsigned long)(r.stats.tris_dropped + r.stats.verts_dropped +
                                       r.stats.records_skipped));
            }
    printf("M %s arena=%lu static=%lu stack=%lu\n", SMALL_BOARD, (unsigned long)sizeof arena,
           (unsigned long)small_static_ram(), (unsigned long)small_stack_used());
    small_port_exit(errors ? 1 : 0);
    return errors ? 1 : 0;
}
