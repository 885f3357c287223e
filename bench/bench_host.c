/* SPDX-License-Identifier: MIT */
/*
 * Host driver of the benchmark.
 *
 *   bench_host run [--scene NAME] [--mode span|zline|both] [--frames N] [--ppm DIR]
 *       renders the scenes and prints one line per frame:
 *       R host SCENE MODE FRAME sum=XXXXXXXX tris=.. verts=.. edges=.. dropped=..
 *       and per scene: A host SCENE arena=BYTES caps=T,V,E
 *   bench_host arena T V E   prints zs_arena_bytes for 240x240 and those capacities
 *   bench_host caps   (built with bench/caps_generous/) prints the bench_caps.h
 *       with the largest pool use of every scene over all frames and modes.
 *
 * Under callgrind, collect only zs_frame_begin, zs_draw and zs_render_rows
 * (--toggle-collect) to count the render alone.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_scenes.h"
#include "bench_caps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *mode_name(zs_visibility m)
{
    return m == ZS_MODE_SPAN ? "span" : "zline";
}

static void ppm_write(const char *dir, const char *scene, const char *mode, int frame,
                      const uint8_t *img)
{
    char path[512];
    FILE *f;
    int i;
    snprintf(path, sizeof path, "%s/%s-%s-%d.ppm", dir, scene, mode, frame);
    f = fopen(path, "wb");
    if (!f) {
        perror(path);
        return;
    }
    fprintf(f, "P6\n%d %d\n255\n", BENCH_W, BENCH_H);
    for (i = 0; i < BENCH_W * BENCH_H; i++) {
        unsigned v = ((unsigned)img[2 * i] << 8) | img[2 * i + 1];
        unsigned char rgb[3];
        rgb[0] = (unsigned char)(((v >> 11) & 31) * 255 / 31);
        rgb[1] = (unsigned char)(((v >> 5) & 63) * 255 / 63);
        rgb[2] = (unsigned char)((v & 31) * 255 / 31);
        fwrite(rgb, 1, 3, f);
    }
    fclose(f);
}

typedef struct scene_use {
    uint32_t tris, verts, edges;                    /* largest pool use */
    uint32_t tris_dropped, verts_dropped, records_skipped;
    int frames_dropping;
} scene_use;

/* Renders frames 0..frames-1 of scene s in the modes of the mask (1 span,
 * 2 zline) with pool capacities cfg; prints the R lines if print. Returns 0,
 * or -1 on an API error. */
static int render_scene(const bench_scene *s, const zs_config *cfg, const zs_camera *cam,
                        int modes, int frames, int print, const char *ppm, scene_use *use)
{
    static uint8_t img[BENCH_W * BENCH_H * 2];
    size_t need = zs_arena_bytes(cfg);
    void *arena = malloc(need);
    zs_renderer r;
    zs_status st;
    int mi;
    memset(use, 0, sizeof *use);
    if (!arena || (st = zs_init(&r, arena, need, cfg)) != ZS_OK) {
        fprintf(stderr, "bench_host: %s: init failed\n", s->name);
        free(arena);
        return -1;
    }
    for (mi = 0; mi < 2; mi++) {
        zs_visibility mode = mi ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
        int f;
        if (!(modes & (1 << mi)))
            continue;
        for (f = 0; f < frames; f++) {
            const zs_stats *stt;
            uint32_t sum;
            int y;
            st = bench_submit(&r, cam, s, f, mode);
            for (y = 0; st == ZS_OK && y < BENCH_H; y++)
                st = zs_render_rows(&r, y, 1, img + (size_t)y * BENCH_W * 2, BENCH_W * 2);
            if (st != ZS_OK) {
                fprintf(stderr, "bench_host: %s %s frame %d: %s\n", s->name, mode_name(mode), f,
                        zs_strerror(st));
                free(arena);
                return -1;
            }
            sum = bench_fnv1a(BENCH_FNV_BASIS, img, sizeof img);
            stt = zs_frame_stats(&r);
            if (stt->tris_stored > use->tris)
                use->tris = stt->tris_stored;
            if (stt->verts_stored > use->verts)
                use->verts = stt->verts_stored;
            if (stt->max_active_edges > use->edges)
                use->edges = stt->max_active_edges;
            use->tris_dropped += stt->tris_dropped;
            use->verts_dropped += stt->verts_dropped;
            use->records_skipped += stt->records_skipped;
            if (stt->records_dropped || stt->verts_dropped || stt->records_skipped)
                use->frames_dropping++;
            if (print)
                printf("R host %s %s %d sum=%08lx tris=%lu verts=%lu edges=%lu "
                       "culled=%lu clipped=%lu dropped=%lu spans=%lu evals=%lu crossings=%lu "
                       "drawn=%lu\n",
                       s->name, mode_name(mode), f, (unsigned long)sum,
                       (unsigned long)stt->tris_stored, (unsigned long)stt->verts_stored,
                       (unsigned long)stt->max_active_edges, (unsigned long)stt->tris_culled,
                       (unsigned long)stt->tris_clipped,
                       (unsigned long)(stt->tris_dropped + stt->verts_dropped +
                                       stt->records_skipped),
                       (unsigned long)stt->spans, (unsigned long)stt->depth_evals,
                       (unsigned long)stt->crossings, (unsigned long)stt->tris_drawn);
            if (ppm)
                ppm_write(ppm, s->name, mode_name(mode), f, img);
        }
    }
    free(arena);
    return 0;
}

static uint16_t grow(uint32_t v)
{
    uint32_t n = v + (v / 16u > 1u ? v / 16u : 1u);
    return (uint16_t)(n > 65535u ? 65535u : n);
}

int main(int argc, char **argv)
{
    const char *only = NULL, *ppm = NULL;
    int frames = BENCH_FRAMES, modes = 3, caps = 0, mono = 0, i, si, failures = 0;
    zs_camera cam;
    uint16_t tight[BENCH_SCENE_COUNT][3];
    if (argc == 5 && !strcmp(argv[1], "arena")) {
        /* bench_host arena TRIS VERTS EDGES: zs_arena_bytes at 240x240 */
        /* a display board's build: flat shading, span mode only */
        zs_config c = zs_config_default(BENCH_W, BENCH_H, (uint16_t)atoi(argv[2]),
                                        (uint16_t)atoi(argv[3]), (uint16_t)atoi(argv[4]));
        c.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE;
        printf("%zu\n", zs_arena_bytes(&c));
        return 0;
    }
    if (argc < 2 || (strcmp(argv[1], "run") && strcmp(argv[1], "caps"))) {
        fprintf(stderr, "usage: bench_host run|caps [--scene NAME] [--mode span|zline|both] "
                        "[--frames N] [--ppm DIR] [--mono]\n"
                        "       bench_host arena TRIANGLES VERTICES EDGES\n");
        return 2;
    }
    caps = !strcmp(argv[1], "caps");
    for (i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--scene") && i + 1 < argc)
            only = argv[++i];
        else if (!strcmp(argv[i], "--mode") && i + 1 < argc) {
            const char *m = argv[++i];
            modes = !strcmp(m, "span") ? 1 : !strcmp(m, "zline") ? 2 : 3;
        } else if (!strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--ppm") && i + 1 < argc)
            ppm = argv[++i];
        else if (!strcmp(argv[i], "--mono"))
            mono = 1;
        else {
            fprintf(stderr, "bench_host: unknown argument '%s'\n", argv[i]);
            return 2;
        }
    }
#ifndef BENCH_CAPS_GENEROUS
    if (caps) {
        fprintf(stderr, "bench_host: 'caps' needs the build with bench/caps_generous\n");
        return 2;
    }
#endif
    if (frames < 1 || frames > BENCH_FRAMES)
        frames = BENCH_FRAMES;
    if (bench_camera(&cam) != ZS_OK) {
        fprintf(stderr, "bench_host: camera setup failed\n");
        return 1;
    }
    for (si = 0; si < BENCH_SCENE_COUNT; si++) {
        const bench_scene *s = &bench_scenes[si];
        zs_config cfg = bench_config(s);
        scene_use use;
        if (only && strcmp(only, s->name))
            continue;
        if (!caps) {
            printf("A host %s arena=%zu caps=%u,%u,%u\n", s->name, zs_arena_bytes(&cfg),
                   s->max_triangles, s->max_vertices, s->max_active_edges);
            if (render_scene(s, &cfg, &cam, modes, frames, 1, ppm, &use) != 0)
                return 1;
            failures += use.frames_dropping;
            if (mono) { /* the firmware test's textured frames (bench_tex_frame) */
                static zs_renderer tr;
                static uint8_t tarena[64 * 1024];
                zs_config tc = bench_tex_config();
                int k;
                if (zs_arena_bytes(&tc) > sizeof tarena ||
                    zs_init(&tr, tarena, sizeof tarena, &tc) != ZS_OK) {
                    fprintf(stderr, "bench_host: textured init failed\n");
                    return 1;
                }
                for (k = 0; k < BENCH_TEX_VARIANTS; k++) {
                    uint32_t sum = 0, covered = 0;
                    zs_status st = bench_tex_frame(&tr, &cam, k, &sum, &covered);
                    if (st != ZS_OK) {
                        fprintf(stderr, "bench_host: textured %s: %s\n", bench_tex_names[k],
                                zs_strerror(st));
                        return 1;
                    }
                    printf("R host textured %s 0 sum=%08lx covered=%lu dropped=%lu\n",
                           bench_tex_names[k], (unsigned long)sum, (unsigned long)covered,
                           (unsigned long)(tr.stats.tris_dropped + tr.stats.verts_dropped +
                                           tr.stats.records_skipped));
                }
            }
            if (mono) { /* the firmware test's Warnock and A-buffer frames */
                static zs_renderer er;
                static uint8_t earena[64 * 1024];
                zs_config ec = bench_extra_config();
                int k;
                if (zs_arena_bytes(&ec) > sizeof earena ||
                    zs_init(&er, earena, sizeof earena, &ec) != ZS_OK) {
                    fprintf(stderr, "bench_host: A-buffer init failed\n");
                    return 1;
                }
                for (k = 0; k < BENCH_EXTRA_VARIANTS; k++) {
                    uint32_t sum = 0;
                    zs_status st = bench_extra_frame(&er, &cam, k, &sum);
                    if (st != ZS_OK) {
                        fprintf(stderr, "bench_host: textured %s: %s\n", bench_extra_names[k],
                                zs_strerror(st));
                        return 1;
                    }
                    printf("R host textured %s 0 sum=%08lx dropped=%lu\n", bench_extra_names[k],
                           (unsigned long)sum,
                           (unsigned long)(er.stats.tris_dropped + er.stats.verts_dropped +
                                           er.stats.records_skipped + er.stats.aa_overflow +
                                           er.stats.aa_skipped));
                }
            }
            if (mono) { /* the firmware test's 1-bit frames (bench_mono_frame) */
                static zs_renderer mr;
                static uint8_t marena[64 * 1024];
                zs_config mc = cfg;
                int k;
                mc.flags |= ZS_CFG_MONO | ZS_CFG_LINES;
                if (zs_arena_bytes(&mc) > sizeof marena ||
                    zs_init(&mr, marena, sizeof marena, &mc) != ZS_OK) {
                    fprintf(stderr, "bench_host: mono init failed\n");
                    return 1;
                }
                for (k = 0; k < BENCH_MONO_VARIANTS; k++) {
                    uint32_t sum = 0;
                    zs_status st = bench_mono_frame(&mr, &cam, s, k, &sum);
                    if (st != ZS_OK) {
                        fprintf(stderr, "bench_host: %s %s: %s\n", s->name, bench_mono_names[k],
                                zs_strerror(st));
                        return 1;
                    }
                    printf("R host %s %s 0 sum=%08lx dropped=%lu\n", s->name, bench_mono_names[k],
                           (unsigned long)sum,
                           (unsigned long)(mr.stats.tris_dropped + mr.stats.verts_dropped +
                                           mr.stats.records_skipped));
                }
            }
            continue;
        }
        /* caps: the pool use with generous pools, then grow each pool that
         * still drops at that size (the statistics need not bound every
         * internal pool exactly) until no frame drops anything. */
        if (render_scene(s, &cfg, &cam, 3, BENCH_FRAMES, 0, NULL, &use) != 0)
            return 1;
        if (use.frames_dropping) {
            fprintf(stderr, "bench_host: %s drops triangles even with the generous pools\n",
                    s->name);
            return 1;
        }
        tight[si][0] = (uint16_t)(use.tris ? use.tris : 1);
        tight[si][1] = (uint16_t)(use.verts ? use.verts : 1);
        tight[si][2] = (uint16_t)(use.edges < 2 ? 2 : use.edges);
        for (i = 0; i < 1000; i++) {
            cfg = zs_config_default(BENCH_W, BENCH_H, tight[si][0], tight[si][1], tight[si][2]);
            if (render_scene(s, &cfg, &cam, 3, BENCH_FRAMES, 0, NULL, &use) != 0)
                return 1;
            if (!use.frames_dropping)
                break;
            if (use.tris_dropped)
                tight[si][0] = grow(tight[si][0]);
            if (use.verts_dropped)
                tight[si][1] = grow(tight[si][1]);
            if (use.records_skipped)
                tight[si][2] = grow(tight[si][2]);
        }
    }
    if (caps) {
        static const char *const macro[BENCH_SCENE_COUNT] = {"SPHERE285", "CUBES", "WUSON", "CLUSTER"};
        printf("/* Generated by bench_caps: pool capacities of each benchmark scene, the\n"
               " * smallest (from the largest use over all frames and both modes, grown\n"
               " * where a pool still overflowed) with which no frame drops anything.\n"
               " * Do not edit. */\n"
               "#ifndef ZSPAN_BENCH_CAPS_H\n#define ZSPAN_BENCH_CAPS_H\n");
        for (si = 0; si < BENCH_SCENE_COUNT; si++)
            printf("#define BENCH_CAPS_%s %u, %u, %u\n", macro[si], tight[si][0], tight[si][1],
                   tight[si][2]);
        printf("#endif\n");
    }
    if (failures) {
        fprintf(stderr, "bench_host: %d frames dropped triangles (pool too small)\n", failures);
        return 1;
    }
    return 0;
}
