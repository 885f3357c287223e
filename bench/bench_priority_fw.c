/* SPDX-License-Identifier: MIT */
/*
 * List-priority benchmark (issue 14): the four bench scenes (bench_scenes.h)
 * in span mode with their meshes, and in ZS_MODE_PRIORITY with the same
 * meshes compiled by zspan-meshc --bsp (mk/priority.mk) and drawn with
 * zs_draw_bsp. Firmware image for QEMU mps2-an386 (Cortex-M4 code, and the
 * same program in Cortex-M0 code), and a host build whose checksums must
 * match. 240x240 RGB565 big-endian into a framebuffer, frames 0..9. One
 * line per measurement:
 *
 *   I BOARD CPU ipt_milli=N
 *   R BOARD SCENE MODE FRAME instr=N sum=XXXXXXXX records=N nodes=N pruned=N
 *   A BOARD SCENE MODE arena=N tris=N verts=N edges=N   (the arena for the
 *     largest pool use of the frames; the run itself uses generous pools)
 *   M BOARD static_ram=N stack_used=N
 *
 * Instructions: SysTick ticks times the calibrated instructions per tick
 * (qemu -icount shift=0) around zs_frame_begin + the draw + the 240
 * zs_render_rows calls. "quick" on the command line: frame 0 only.
 *
 * MODE priority-paint: the BSP frame painted back to front into the
 * framebuffer by zs_paint_frame instead of rendered in rows; its checksums
 * must be the priority-bsp ones (painter == band image, on every CPU).
 */
#include "bench_scenes.h"
#include "bsp_cluster.h"
#include "bsp_cubes.h"
#include "bsp_sphere285.h"
#include "bsp_wuson.h"
#include "port.h"
#include "zspan/priority.h"

#include <string.h>

static const zs_bsp *const k_trees[BENCH_SCENE_COUNT] = {&bsp_sphere285_bsp, &bsp_cubes_bsp,
                                                         &bsp_wuson_bsp, &bsp_cluster_bsp};

static uint32_t fnv1a(const uint8_t *p, size_t n)
{
    uint32_t h = BENCH_FNV_BASIS;
    size_t i;
    for (i = 0; i < n; i++)
        h = (h ^ p[i]) * 0x01000193u;
    return h;
}

int main(void)
{
    static zs_renderer r;
    static char cmd[64];
    size_t free_bytes;
    uint8_t *ram = port_free_ram(&free_bytes);
    const char *board = port_this_board.name;
    zs_camera cam;
    uint32_t ipt;
    int frames = BENCH_FRAMES, si, errors = 0;
    if (sh_get_cmdline(cmd, sizeof cmd) == 0 && strstr(cmd, "quick"))
        frames = 1;
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    sh_printf("I %s %s ipt_milli=%u\n", board, port_this_board.cpu, (unsigned)ipt);
    if (bench_camera(&cam) != ZS_OK)
        return 1;
    for (si = 0; si < BENCH_SCENE_COUNT; si++) {
        const bench_scene *s = &bench_scenes[si];
        const zs_bsp *tree = k_trees[si];
        int pri;
        for (pri = 0; pri < 3; pri++) { /* span, priority-bsp, priority-paint */
            const zs_mesh *mesh = pri ? tree->mesh : s->mesh;
            zs_config cfg = zs_config_default(BENCH_W, BENCH_H, mesh->triangle_count,
                                              mesh->vertex_count, 4096);
            size_t need, at;
            uint8_t *fb;
            uint32_t peak_tris = 0, peak_verts = 0, peak_edges = 0;
            const char *mname = pri == 2 ? "priority-paint" : pri ? "priority-bsp" : "span";
            int f;
            /* priority frames keep no depth planes */
            cfg.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE | (pri ? ZS_CFG_PRIORITY_ONLY : 0u);
            need = zs_arena_bytes(&cfg);
            at = (need + 7u) & ~(size_t)7u;
            if (need == 0 || at + (size_t)BENCH_W * BENCH_H * 2 > free_bytes) {
                sh_printf("E %s %s %s arena %u does not fit %u\n", board, s->name, mname,
                          (unsigned)need, (unsigned)free_bytes);
                errors++;
                continue;
            }
            fb = ram + at;
            if (zs_init(&r, ram, need, &cfg) != ZS_OK) {
                sh_printf("E %s init\n", board);
                return 1;
            }
            for (f = 0; f < frames; f++) {
                zs_mat34 mv = bench_model_view(s, f);
                const zs_stats *st;
                zs_status e;
                uint64_t a, b;
                int y;
                a = port_ticks();
                e = zs_frame_begin(&r, &cam, pri ? ZS_MODE_PRIORITY : ZS_MODE_SPAN);
                if (e == ZS_OK)
                    e = pri ? zs_draw_bsp(&r, tree, &mv) : zs_draw(&r, mesh, &mv);
                if (e == ZS_OK && pri == 2)
                    e = zs_paint_frame(&r, fb, BENCH_W * 2);
                for (y = 0; e == ZS_OK && pri != 2 && y < BENCH_H; y++)
                    e = zs_render_rows(&r, y, 1, fb + (size_t)y * BENCH_W * 2, BENCH_W * 2);
                b = port_ticks();
                if (e != ZS_OK) {
                    sh_printf("E %s %s %s %d %s\n", board, s->name, mname, f, zs_strerror(e));
                    errors++;
                    continue;
                }
                st = zs_frame_stats(&r);
                sh_printf("R %s %s %s %d instr=%lu sum=%08lx records=%lu nodes=%lu pruned=%lu\n",
                          board, s->name, mname, f,
                          (unsigned long)(((b - a) * ipt + 500u) / 1000u),
                          (unsigned long)fnv1a(fb, (size_t)BENCH_W * BENCH_H * 2),
                          (unsigned long)st->records, (unsigned long)st->bsp_nodes,
                          (unsigned long)st->bsp_pruned);
                if (st->tris_dropped + st->verts_dropped + st->records_skipped)
                    errors++;
                peak_tris = st->records > peak_tris ? st->records : peak_tris;
                peak_verts = st->verts_stored > peak_verts ? st->verts_stored : peak_verts;
                peak_edges = st->max_active_edges > peak_edges ? st->max_active_edges : peak_edges;
            }
            {
                zs_config pk = zs_config_default(BENCH_W, BENCH_H,
                                                 (uint16_t)(peak_tris ? peak_tris : 1),
                                                 (uint16_t)(peak_verts ? peak_verts : 1),
                                                 (uint16_t)(peak_edges > 2 ? peak_edges : 2));
                pk.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE | (pri ? ZS_CFG_PRIORITY_ONLY : 0u);
                sh_printf("A %s %s %s arena=%lu tris=%lu verts=%lu edges=%lu\n", board, s->name,
                          mname, (unsigned long)zs_arena_bytes(&pk), (unsigned long)peak_tris,
                          (unsigned long)peak_verts, (unsigned long)peak_edges);
            }
        }
    }
    sh_printf("M %s static_ram=%u stack_used=%u\n", board, (unsigned)port_static_ram(),
              (unsigned)port_stack_high_water());
    return errors ? 1 : 0;
}
