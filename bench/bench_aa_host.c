/* SPDX-License-Identifier: MIT */
/*
 * Host side of the A-buffer checksum check (make check-abuffer-m4): frame 0
 * of every standard scene in span mode with ZS_AA_EDGES, one line per scene
 * "SCENE XXXXXXXX" (FNV-1a 32 of the RGB565 big-endian rows), to compare with
 * the sum_edges of the Cortex-M4 image (bench/bench_aa_fw.c, "quick").
 */
#include "bench_scenes.h"

#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    static uint8_t fb[BENCH_H * BENCH_W * 2];
    static zs_renderer r;
    zs_camera cam;
    int si, y;
    if (bench_camera(&cam) != ZS_OK)
        return 1;
    for (si = 0; si < BENCH_SCENE_COUNT; si++) {
        const bench_scene *s = &bench_scenes[si];
        zs_config cfg = bench_config(s);
        zs_mat34 mv = bench_model_view(s, 0);
        size_t n;
        void *arena;
        zs_status st;
        cfg.flags |= ZS_CFG_ABUFFER;
        n = zs_arena_bytes(&cfg);
        arena = malloc(n);
        if (!arena || zs_init(&r, arena, n, &cfg) != ZS_OK)
            return 1;
        st = zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
        if (st == ZS_OK)
            st = zs_frame_antialias(&r, ZS_AA_EDGES);
        if (st == ZS_OK)
            st = zs_draw(&r, s->mesh, &mv);
        for (y = 0; st == ZS_OK && y < BENCH_H; y++)
            st = zs_render_rows(&r, y, 1, fb + (size_t)y * BENCH_W * 2, BENCH_W * 2);
        if (st != ZS_OK) {
            fprintf(stderr, "bench_aa_host: %s: %s\n", s->name, zs_strerror(st));
            return 1;
        }
        printf("%s %08lx\n", s->name, (unsigned long)bench_fnv1a(BENCH_FNV_BASIS, fb, sizeof fb));
        free(arena);
    }
    return 0;
}
