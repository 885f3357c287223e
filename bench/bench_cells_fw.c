/* SPDX-License-Identifier: MIT */
/*
 * Scene cells on the MCU (issue 14, zspan/cull.h): the city and forest of
 * bench/bench_cells.c (cells built on the host, emitted as const arrays by
 * bench_cells --emit) drawn from the same 24 views each, for QEMU
 * mps2-an386 as Cortex-M4 and Cortex-M0 code. Per structure and view, the
 * instructions of zs_frame_begin + the draws (transform, cull, clip, set-up;
 * no rows rendered: the rows cost the same whichever structure culled):
 *
 *   R BOARD SCENE STRUCTURE VIEW instr=N submitted=N untransformed=N
 *     stored=N cells_culled=N
 *
 * STRUCTURE: plain (every object with zs_draw, no culling), none (a box per
 * object, zs_draw_bounded through one leaf), kd4, kd8 (k-d tree, leaf size),
 * grid6, grid8 (uniform grid, columns per side).
 */
#include "cells_data.h"
#include "port.h"

#include <string.h>

#define CB_W 240
#define CB_H 240

int main(void)
{
    static zs_renderer r;
    size_t free_bytes, need;
    uint8_t *ram = port_free_ram(&free_bytes);
    const char *board = port_this_board.name;
    zs_config cfg = zs_config_default(CB_W, CB_H, 9000, 9600, 64);
    uint32_t ipt;
    int si, vi, errors = 0;
    cfg.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE;
    need = zs_arena_bytes(&cfg);
    if (need == 0 || need > free_bytes || zs_init(&r, ram, need, &cfg) != ZS_OK) {
        sh_printf("E %s arena %u of %u\n", board, (unsigned)need, (unsigned)free_bytes);
        return 1;
    }
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    sh_printf("I %s %s ipt_milli=%u\n", board, port_this_board.cpu, (unsigned)ipt);
    for (si = 0; si < cb_structure_count; si++) {
        const cb_structure *s = &cb_structures[si];
        int plain = strcmp(s->name, "plain") == 0, v = 0;
        for (vi = 0; vi < cb_view_count; vi++) {
            const cb_view *cv = &cb_views[vi];
            zs_camera cam;
            zs_status e;
            uint64_t a, b;
            const zs_stats *st;
            if (strcmp(cv->scene, s->scene) != 0)
                continue;
            e = zs_camera_look_at(&cam, zs_vec3_make(cv->eye[0], cv->eye[1], cv->eye[2]),
                                  zs_vec3_make(cv->target[0], cv->target[1], cv->target[2]),
                                  zs_vec3_make(0, ZS_FX(1), 0));
            if (e == ZS_OK)
                e = zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 4, ZS_FX(150));
            a = port_ticks();
            if (e == ZS_OK)
                e = zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
            if (e == ZS_OK && plain) {
                uint16_t k;
                for (k = 0; e == ZS_OK && k < s->cells.object_count; k++)
                    e = zs_draw(&r, s->cells.objects[k].mesh, s->cells.objects[k].model);
            } else if (e == ZS_OK) {
                e = zs_draw_cells(&r, &s->cells);
            }
            b = port_ticks();
            st = zs_frame_stats(&r);
            if (e != ZS_OK || st->tris_dropped || st->verts_dropped) {
                sh_printf("E %s %s %s %d %s\n", board, s->scene, s->name, v, zs_strerror(e));
                errors++;
            } else {
                sh_printf("R %s %s %s %d instr=%lu submitted=%lu untransformed=%lu stored=%lu "
                          "cells_culled=%lu\n",
                          board, s->scene, s->name, v,
                          (unsigned long)(((b - a) * ipt + 500u) / 1000u),
                          (unsigned long)st->tris_submitted,
                          (unsigned long)st->tris_untransformed, (unsigned long)st->records,
                          (unsigned long)st->cells_culled);
            }
            v++;
        }
    }
    sh_printf("M %s static_ram=%u stack_used=%u\n", board, (unsigned)port_static_ram(),
              (unsigned)port_stack_high_water());
    return errors ? 1 : 0;
}
