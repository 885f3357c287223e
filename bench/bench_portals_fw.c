/* SPDX-License-Identifier: MIT */
/*
 * Portal-level benchmark image (Cortex-M4 on QEMU mps2-an386): a generated
 * building floor (zspan-level gen building 8x6 7, converted to const arrays
 * with its scripted flight, mk/portals.mk) drawn along the flight with every
 * cell, with the eye cell's PVS, and with the PVS narrowed by the portal
 * walk (zs_level_draw). 240x240, RGB565 big-endian, flat unlit face colours,
 * vertical fov 60 degrees, near 0.05, far 100. One line per frame and cull:
 *
 *   I BOARD CPU ipt_milli=N
 *   L BOARD CULL FRAME instr=N sum=XXXXXXXX submitted=N culled=N drawn=N
 *     pvs=N visited=N portals=N dropped=N
 *   C BOARD FRAME equal|DIFFER          (the three frames' checksums)
 *   M BOARD static_ram=N stack_used=N
 *
 * Instructions are SysTick ticks times the calibrated instructions per tick
 * (qemu -icount shift=0) around zs_frame_begin + zs_level_draw + the 240
 * zs_render_rows calls into a framebuffer; checksums (FNV-1a 32 of the
 * frame's bytes) are taken afterwards. "quick" on the command line runs the
 * first two frames only (make test). Exit status 1 on an error or a frame
 * that differs between culls.
 */
#include "bench_level.h"
#include "port.h"

#include <string.h>

#define W 240
#define H 240

static const char *const k_cull_name[3] = {"none", "pvs", "portals"};

static uint32_t fnv1a(const uint8_t *p, size_t n)
{
    uint32_t h = 0x811C9DC5u;
    size_t i;
    for (i = 0; i < n; i++)
        h = (h ^ p[i]) * 0x01000193u;
    return h;
}

int main(void)
{
    static zs_renderer r;
    static char cmd[64];
    size_t free_bytes, need, at;
    uint8_t *ram = port_free_ram(&free_bytes), *fb;
    zs_config cfg = zs_config_default(W, H, 4000,
                                      bench_level_VERTICES + 1024 > 65535
                                          ? 65535
                                          : (uint16_t)(bench_level_VERTICES + 1024),
                                      1024);
    uint32_t ipt;
    int frames = bench_level_PATH_FRAMES, f, errors = 0;
    const char *board = port_this_board.name;
    cfg.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE;
    if (sh_get_cmdline(cmd, sizeof cmd) == 0 && strstr(cmd, "quick"))
        frames = 2;
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    sh_printf("I %s %s ipt_milli=%u\n", board, port_this_board.cpu, (unsigned)ipt);
    need = zs_arena_bytes(&cfg);
    at = (need + 7u) & ~(size_t)7u;
    if (at + (size_t)W * H * 2 > free_bytes) {
        sh_printf("E %s arena %u + framebuffer do not fit %u\n", board, (unsigned)need,
                  (unsigned)free_bytes);
        return 1;
    }
    fb = ram + at;
    if (zs_init(&r, ram, need, &cfg) != ZS_OK || zs_level_check(&bench_level) != ZS_OK) {
        sh_printf("E %s init\n", board);
        return 1;
    }
    for (f = 0; f < frames; f++) {
        const zs_fixed *p = bench_level_path[f];
        zs_vec3 eye = zs_vec3_make(p[0], p[1], p[2]);
        zs_camera cam;
        uint32_t sums[3] = {0, 0, 0};
        int c;
        if (zs_camera_look_at(&cam, eye, zs_vec3_make(p[3], p[4], p[5]),
                              zs_vec3_make(0, ZS_FX_ONE, 0)) != ZS_OK ||
            zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_ONE / 20, ZS_FX(100)) != ZS_OK) {
            sh_printf("E %s camera %d\n", board, f);
            return 1;
        }
        for (c = 0; c < 3; c++) {
            zs_level_stats ls;
            const zs_stats *st;
            zs_status s;
            uint64_t a, b;
            int y;
            a = port_ticks();
            s = zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
            if (s == ZS_OK)
                s = zs_level_draw(&r, &bench_level, eye, (zs_level_cull)c, &ls);
            for (y = 0; s == ZS_OK && y < H; y++)
                s = zs_render_rows(&r, y, 1, fb + (size_t)y * W * 2, W * 2);
            b = port_ticks();
            if (s != ZS_OK) {
                sh_printf("E %s %s %d %s\n", board, k_cull_name[c], f, zs_strerror(s));
                errors++;
                continue;
            }
            st = zs_frame_stats(&r);
            sums[c] = fnv1a(fb, (size_t)W * H * 2);
            sh_printf("L %s %s %d instr=%lu sum=%08lx submitted=%lu culled=%lu drawn=%lu pvs=%lu "
                      "visited=%lu portals=%lu dropped=%lu\n",
                      board, k_cull_name[c], f,
                      (unsigned long)(((b - a) * ipt + 500u) / 1000u), (unsigned long)sums[c],
                      (unsigned long)ls.tris_submitted, (unsigned long)ls.tris_culled,
                      (unsigned long)ls.cells_drawn, (unsigned long)ls.pvs_cells,
                      (unsigned long)ls.cells_visited, (unsigned long)ls.portals_tested,
                      (unsigned long)(st->tris_dropped + st->verts_dropped + st->records_skipped));
            if (st->tris_dropped + st->verts_dropped + st->records_skipped)
                errors++;
        }
        if (sums[0] != sums[1] || sums[0] != sums[2])
            errors++;
        sh_printf("C %s %d %s\n", board, f,
                  sums[0] == sums[1] && sums[0] == sums[2] ? "equal" : "DIFFER");
    }
    sh_printf("M %s static_ram=%u stack_used=%u\n", board, (unsigned)port_static_ram(),
              (unsigned)port_stack_high_water());
    return errors ? 1 : 0;
}
