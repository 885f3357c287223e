/* SPDX-License-Identifier: MIT */
/*
 * Firmware benchmark image (Cortex-M4 on QEMU mps2-an386, Cortex-M0 on QEMU
 * microbit). Output through semihosting, one line per measurement:
 *
 *   I BOARD CPU ipt_milli=N nominal=N overhead=N free_ram=N
 *   R BOARD SCENE MODE FRAME instr=N sum=XXXXXXXX dropped=N
 *   S BOARD SCENE skip need=N free=N          (the arena does not fit)
 *   M BOARD static_ram=N stack_used=N stack_size=N
 *
 * Command line (qemu -semihosting-config arg=...): "quick" renders frame 0 of
 * the first scene in both modes and in the three 1-bit outputs of
 * bench_mono_frame (the firmware test of make test); "rows"
 * forces the per-row timing below even when a framebuffer fits. Every run
 * also renders the textured scene (bench_tex_frame) and its Warnock and
 * A-buffer frames (bench_extra_frame), once each. For profiles: a scene's
 * name renders only that scene, "span" or "zline" only that mode, "notex"
 * skips the textured scene and the extra frames.
 *
 * Instructions are counted from SysTick ticks * the calibrated instructions
 * per tick (qemu -icount shift=0 runs one instruction per ns) around
 * zs_frame_begin + zs_draw + the 240 zs_render_rows calls only:
 *  - timing=frame: when a 240x240 framebuffer fits next to the arena (mps2-an386),
 *    the rows go to it and the whole frame is one timed section; the checksum
 *    is computed afterwards;
 *  - timing=rows: otherwise (microbit) each call is timed on its own with a
 *    one-row buffer whose checksum is updated between calls; the cost of the
 *    timer reads is measured (same code shape) and subtracted. The same code
 *    measured both ways agrees within 0.25%; timing=frame also counts the
 *    benchmark's own row loop (about 10 instructions a row).
 */
#include "bench_scenes.h"
#include "port.h"
#include "bench_fw_timing.h"

#include <string.h>

static uint8_t line[BENCH_W * 2];

static const char *mode_name(zs_visibility m)
{
    return m == ZS_MODE_SPAN ? "span" : "zline";
}

static int has_word(const char *s, const char *w)
{
    size_t n = strlen(w);
    while (*s) {
        while (*s == ' ')
            s++;
        if (!strncmp(s, w, n) && (s[n] == ' ' || s[n] == 0))
            return 1;
        while (*s && *s != ' ')
            s++;
    }
    return 0;
}

int main(void)
{
    static zs_renderer r;
    static char cmd[128];
    zs_camera cam;
    size_t free_bytes;
    uint8_t *free_ram = port_free_ram(&free_bytes);
    uint32_t ipt, overhead_milli;
    int quick = 0, per_row = 0, si, errors = 0, only_scene = 0, notex = 0;
    int mode_lo = 0, mode_hi = 2;
    const char *board = port_this_board.name;

    if (sh_get_cmdline(cmd, sizeof cmd) == 0)
    {
        quick = has_word(cmd, "quick");
        per_row = has_word(cmd, "rows");
        notex = has_word(cmd, "notex");
        for (si = 0; si < BENCH_SCENE_COUNT; si++)
            if (has_word(cmd, bench_scenes[si].name))
                only_scene = si + 1;
        if (has_word(cmd, "span"))
            mode_hi = 1;
        if (has_word(cmd, "zline"))
            mode_lo = 1;
    }
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    overhead_milli = bench_section_overhead_milli(ipt);
    sh_printf("I %s %s ipt_milli=%u nominal=%u overhead_milli=%u free_ram=%u\n", board,
              port_this_board.cpu, (unsigned)ipt, (unsigned)port_this_board.nominal_ipt_milli,
              (unsigned)overhead_milli, (unsigned)free_bytes);
    if (bench_camera(&cam) != ZS_OK) {
        sh_printf("E %s camera\n", board);
        return 1;
    }
    for (si = 0; si < (quick ? 1 : BENCH_SCENE_COUNT); si++) {
        const bench_scene *s = &bench_scenes[si];
        zs_config cfg = bench_config(s);
        size_t need = zs_arena_bytes(&cfg);
        int mi;
        zs_status st;
        uint8_t *fb;
        if (only_scene && si != only_scene - 1)
            continue;
        if (need > free_bytes) {
            sh_printf("S %s %s skip need=%u free=%u\n", board, s->name, (unsigned)need,
                      (unsigned)free_bytes);
            continue;
        }
        st = zs_init(&r, free_ram, need, &cfg);
        if (st != ZS_OK) {
            sh_printf("E %s %s init %s\n", board, s->name, zs_strerror(st));
            errors++;
            continue;
        }
        /* A framebuffer after the arena if the RAM allows (not on the microbit). */
        fb = NULL;
        {
            size_t at = (need + 7u) & ~(size_t)7u;
            if (!per_row && at + (size_t)BENCH_H * sizeof line <= free_bytes)
                fb = free_ram + at;
        }
        sh_printf("A %s %s arena=%u timing=%s\n", board, s->name, (unsigned)need,
                  fb ? "frame" : "rows");
        for (mi = mode_lo; mi < mode_hi; mi++) {
            zs_visibility mode = mi ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
            int f;
            for (f = 0; f < (quick ? 1 : BENCH_FRAMES); f++) {
                uint64_t ticks = 0, a, b;
                uint32_t sum = BENCH_FNV_BASIS, sections = 1;
                const zs_stats *stt;
                uint64_t instr_milli;
                int y;
                if (fb) {
                    /* whole frame in one timed section, rows into a framebuffer */
                    a = port_ticks();
                    st = bench_submit(&r, &cam, s, f, mode);
                    for (y = 0; st == ZS_OK && y < BENCH_H; y++)
                        st = zs_render_rows(&r, y, 1, fb + (size_t)y * sizeof line, sizeof line);
                    b = port_ticks();
                    ticks = b - a;
                    if (st == ZS_OK)
                        sum = bench_fnv1a(sum, fb, (size_t)BENCH_H * sizeof line);
                } else {
                    /* one row buffer: time each call, checksum outside */
                    a = port_ticks();
                    st = bench_submit(&r, &cam, s, f, mode);
                    b = port_ticks();
                    ticks += b - a;
                    if (st == ZS_OK)
                        st = bench_timed_rows(&r, line, sizeof line, &ticks, &sections, &sum);
                }
                if (st != ZS_OK) {
                    sh_printf("E %s %s %s %d %s\n", board, s->name, mode_name(mode), f,
                              zs_strerror(st));
                    errors++;
                    break;
                }
                stt = zs_frame_stats(&r);
                instr_milli = ticks * ipt;
                if (instr_milli > (uint64_t)sections * overhead_milli)
                    instr_milli -= (uint64_t)sections * overhead_milli;
                sh_printf("R %s %s %s %d instr=%lu sum=%08lx dropped=%lu\n", board, s->name,
                          mode_name(mode), f, (unsigned long)((instr_milli + 500u) / 1000u),
                          (unsigned long)sum,
                          (unsigned long)(stt->records_dropped + stt->verts_dropped +
                                          stt->records_skipped));
            }
        }
    }
    if (quick) { /* the 1-bit outputs of frame 0 (host == M4 == M0) */
        const bench_scene *s = &bench_scenes[0];
        zs_config cfg = bench_config(s);
        size_t need;
        int k;
        cfg.flags |= ZS_CFG_MONO | ZS_CFG_LINES;
        need = zs_arena_bytes(&cfg);
        if (need > free_bytes || zs_init(&r, free_ram, need, &cfg) != ZS_OK) {
            sh_printf("E %s %s mono init\n", board, s->name);
            errors++;
        } else {
            for (k = 0; k < BENCH_MONO_VARIANTS; k++) {
                uint32_t sum = 0;
                uint64_t a = port_ticks(), b;
                zs_status st = bench_mono_frame(&r, &cam, s, k, &sum);
                b = port_ticks();
                if (st != ZS_OK) {
                    sh_printf("E %s %s %s 0 %s\n", board, s->name, bench_mono_names[k],
                              zs_strerror(st));
                    errors++;
                    continue;
                }
                sh_printf("R %s %s %s 0 instr=%lu sum=%08lx dropped=%lu\n", board, s->name,
                          bench_mono_names[k], (unsigned long)((b - a) * ipt / 1000u),
                          (unsigned long)sum,
                          (unsigned long)(r.stats.records_dropped + r.stats.verts_dropped +
                                          r.stats.records_skipped));
            }
        }
    }
    if (!notex) { /* the textured scene (bench_tex_frame): host == M4 == M0, and its cost */
        zs_config cfg = bench_tex_config();
        size_t need = zs_arena_bytes(&cfg);
        int k;
        if (need > free_bytes || zs_init(&r, free_ram, need, &cfg) != ZS_OK) {
            sh_printf("E %s textured init\n", board);
            errors++;
        } else {
            for (k = 0; k < BENCH_TEX_VARIANTS; k++) {
                uint32_t sum = 0;
                uint64_t a = port_ticks(), b;
                zs_status st = bench_tex_frame(&r, &cam, k, &sum, 0);
                b = port_ticks();
                if (st != ZS_OK) {
                    sh_printf("E %s textured %s 0 %s\n", board, bench_tex_names[k],
                              zs_strerror(st));
                    errors++;
                    continue;
                }
                sh_printf("R %s textured %s 0 instr=%lu sum=%08lx dropped=%lu\n", board,
                          bench_tex_names[k], (unsigned long)((b - a) * ipt / 1000u),
                          (unsigned long)sum,
                          (unsigned long)(r.stats.records_dropped + r.stats.verts_dropped +
                                          r.stats.records_skipped));
            }
        }
    }
    if (!notex) { /* Warnock and A-buffer frames of that scene (bench_extra_frame): host == M4 == M0 */
        zs_config cfg = bench_extra_config();
        size_t need = zs_arena_bytes(&cfg);
        int k;
        if (need > free_bytes || zs_init(&r, free_ram, need, &cfg) != ZS_OK) {
            sh_printf("E %s textured a-buffer init need=%u free=%u\n", board, (unsigned)need,
                      (unsigned)free_bytes);
            errors++;
        } else {
            for (k = 0; k < BENCH_EXTRA_VARIANTS; k++) {
                uint32_t sum = 0;
                uint64_t a = port_ticks(), b;
                zs_status st = bench_extra_frame(&r, &cam, k, &sum);
                b = port_ticks();
                if (st != ZS_OK) {
                    sh_printf("E %s textured %s 0 %s\n", board, bench_extra_names[k],
                              zs_strerror(st));
                    errors++;
                    continue;
                }
                sh_printf("R %s textured %s 0 instr=%lu sum=%08lx dropped=%lu\n", board,
                          bench_extra_names[k], (unsigned long)((b - a) * ipt / 1000u),
                          (unsigned long)sum,
                          (unsigned long)(r.stats.records_dropped + r.stats.verts_dropped +
                                          r.stats.records_skipped + r.stats.aa_overflow +
                                          r.stats.aa_skipped));
            }
        }
    }
    sh_printf("M %s static_ram=%u stack_used=%u stack_size=%u\n", board,
              (unsigned)port_static_ram(), (unsigned)port_stack_high_water(),
              (unsigned)port_stack_size());
    return errors ? 1 : 0;
}
