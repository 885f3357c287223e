/* SPDX-License-Identifier: MIT */
/*
 * A-buffer benchmark image (Cortex-M4, QEMU mps2-an386, core at -O2): the
 * standard scenes (bench_scenes.h) in span mode with ZS_CFG_ABUFFER, each
 * frame rendered with anti-aliasing off and with ZS_AA_EDGES, rows into a
 * framebuffer, the whole frame (zs_frame_begin .. the last zs_render_rows)
 * one timed section. One line per measurement (semihosting):
 *
 *   I BOARD ipt_milli=N
 *   A BOARD SCENE arena=N arena_aa=N            (without / with ZS_CFG_ABUFFER)
 *   R BOARD SCENE FRAME off=N edges=N sum_off=X sum_edges=X aa_pixels=N
 *     fragments=N max_fragments=N overflow=N skipped=N
 *
 * Command line "quick": frame 0 only.
 */
#include "bench_scenes.h"
#include "port.h"

#include <string.h>

#define ROW_BYTES (BENCH_W * 2)

static int has_word(const char *s, const char *w)
{
    size_t n = strlen(w);
    const char *p = strstr(s, w);
    return p && (p == s || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0);
}

/* One frame, timed; returns the instructions (x1000 from ticks * ipt). */
static zs_status timed_frame(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int f,
                             zs_aa_mode aa, uint8_t *fb, uint32_t ipt, uint32_t *instr,
                             uint32_t *sum)
{
    zs_mat34 mv = bench_model_view(s, f);
    uint64_t a = port_ticks(), b;
    zs_status st = zs_frame_begin(r, cam, ZS_MODE_SPAN);
    int y;
    if (st == ZS_OK && aa != ZS_AA_OFF)
        st = zs_frame_antialias(r, aa);
    if (st == ZS_OK)
        st = zs_draw(r, s->mesh, &mv);
    for (y = 0; st == ZS_OK && y < BENCH_H; y++)
        st = zs_render_rows(r, y, 1, fb + (size_t)y * ROW_BYTES, ROW_BYTES);
    b = port_ticks();
    *instr = (uint32_t)(((b - a) * ipt + 500u) / 1000u);
    *sum = bench_fnv1a(BENCH_FNV_BASIS, fb, (size_t)BENCH_H * ROW_BYTES);
    return st;
}

int main(void)
{
    static zs_renderer r;
    static char cmd[128];
    zs_camera cam;
    size_t free_bytes;
    uint8_t *free_ram = port_free_ram(&free_bytes);
    uint32_t ipt;
    int quick = 0, si, errors = 0;
    const char *board = port_this_board.name;
    if (sh_get_cmdline(cmd, sizeof cmd) == 0)
        quick = has_word(cmd, "quick");
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    sh_printf("I %s ipt_milli=%u\n", board, (unsigned)ipt);
    if (bench_camera(&cam) != ZS_OK)
        return 1;
    for (si = 0; si < BENCH_SCENE_COUNT; si++) {
        const bench_scene *s = &bench_scenes[si];
        zs_config cfg = bench_config(s);
        size_t plain = zs_arena_bytes(&cfg), need, at;
        uint8_t *fb;
        int f;
        cfg.flags |= ZS_CFG_ABUFFER;
        need = zs_arena_bytes(&cfg);
        at = (need + 7u) & ~(size_t)7u;
        if (at + (size_t)BENCH_H * ROW_BYTES > free_bytes ||
            zs_init(&r, free_ram, need, &cfg) != ZS_OK) {
            sh_printf("E %s %s does not fit: need=%u free=%u\n", board, s->name,
                      (unsigned)need, (unsigned)free_bytes);
            errors++;
            continue;
        }
        fb = free_ram + at;
        sh_printf("A %s %s arena=%u arena_aa=%u\n", board, s->name, (unsigned)plain,
                  (unsigned)need);
        for (f = 0; f < (quick ? 1 : BENCH_FRAMES); f++) {
            uint32_t off, on, sum_off, sum_on;
            const zs_stats *st = zs_frame_stats(&r);
            if (timed_frame(&r, &cam, s, f, ZS_AA_OFF, fb, ipt, &off, &sum_off) != ZS_OK ||
                timed_frame(&r, &cam, s, f, ZS_AA_EDGES, fb, ipt, &on, &sum_on) != ZS_OK) {
                sh_printf("E %s %s %d render\n", board, s->name, f);
                errors++;
                break;
            }
            sh_printf("R %s %s %d off=%lu edges=%lu sum_off=%08lx sum_edges=%08lx "
                      "aa_pixels=%lu fragments=%lu max_fragments=%lu overflow=%lu "
                      "skipped=%lu\n",
                      board, s->name, f, (unsigned long)off, (unsigned long)on,
                      (unsigned long)sum_off, (unsigned long)sum_on,
                      (unsigned long)st->aa_pixels, (unsigned long)st->aa_fragments,
                      (unsigned long)st->aa_max_fragments, (unsigned long)st->aa_overflow,
                      (unsigned long)st->aa_skipped);
        }
    }
    return errors ? 1 : 0;
}
