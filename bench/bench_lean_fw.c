/* SPDX-License-Identifier: MIT */
/*
 * The lean firmware (make check-lean, mk/lean.mk): what a small Cortex-M0
 * application of the lean configuration links. The bench scenes, flat and
 * unlit, in span mode, RGB565 big-endian rows through one line buffer:
 * zs_init, zs_frame_begin, zs_draw and zs_render_rows and nothing else of
 * the core (no zs_frame_shading, no zs_strerror), so the map file shows the
 * core's footprint for that use. Linked twice: with the core built
 * -DZS_LEAN and with the full core, to compare. Output through semihosting,
 * in the bench's format (bench_fw.c):
 *
 *   I BOARD free_ram=N
 *   R BOARD SCENE span FRAME instr=N sum=XXXXXXXX dropped=N
 *   S BOARD SCENE skip need=N free=N          (the arena does not fit)
 *   E BOARD SCENE code=N                      (a call failed)
 *
 * instr counts every call (zs_frame_begin + zs_draw, then each row) timed on
 * its own, less the timer reads' own cost, as bench_fw.c's timing=rows.
 */
#include "bench_scenes.h"
#include "port.h"
#include "bench_fw_timing.h"

static uint8_t line[BENCH_W * 2];

int main(void)
{
    static zs_renderer r;
    zs_camera cam;
    size_t free_bytes;
    uint8_t *free_ram = port_free_ram(&free_bytes);
    uint32_t ipt, overhead_milli;
    int si, errors = 0;
    const char *board = port_this_board.name;

    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    overhead_milli = bench_section_overhead_milli(ipt);
    sh_printf("I %s free_ram=%u\n", board, (unsigned)free_bytes);
    if (bench_camera(&cam) != ZS_OK) {
        sh_printf("E %s camera\n", board);
        return 1;
    }
    for (si = 0; si < BENCH_SCENE_COUNT; si++) {
        const bench_scene *s = &bench_scenes[si];
        zs_config cfg = bench_config(s); /* flat only, as the bench */
        size_t need = zs_arena_bytes(&cfg);
        zs_status st;
        int f;
        if (need > free_bytes) {
            sh_printf("S %s %s skip need=%u free=%u\n", board, s->name, (unsigned)need,
                      (unsigned)free_bytes);
            continue;
        }
        st = zs_init(&r, free_ram, need, &cfg);
        for (f = 0; st == ZS_OK && f < BENCH_FRAMES; f++) {
            uint64_t ticks, instr_milli, a = port_ticks(), b;
            uint32_t sum = BENCH_FNV_BASIS, sections = 1;
            st = bench_submit(&r, &cam, s, f, ZS_MODE_SPAN);
            b = port_ticks();
            ticks = b - a;
            if (st == ZS_OK)
                st = bench_timed_rows(&r, line, sizeof line, &ticks, &sections, &sum);
            if (st != ZS_OK)
                break;
            instr_milli = ticks * ipt;
            if (instr_milli > (uint64_t)sections * overhead_milli)
                instr_milli -= (uint64_t)sections * overhead_milli;
            sh_printf("R %s %s span %d instr=%lu sum=%08lx dropped=%lu\n", board, s->name, f,
                      (unsigned long)((instr_milli + 500u) / 1000u), (unsigned long)sum,
                      (unsigned long)(r.stats.tris_dropped + r.stats.verts_dropped +
                                      r.stats.records_skipped));
        }
        if (st != ZS_OK) {
            sh_printf("E %s %s code=%d\n", board, s->name, (int)st);
            errors++;
        }
    }
    return errors ? 1 : 0;
}
