/* SPDX-License-Identifier: MIT */
/* The Cortex-M4 index check of zs_draw (geometry.c: two indices a word by
 * usub16 + sel, which the host never builds) against the rule it stands for:
 * ZS_ERR_INDEX exactly when an index is at or above vertex_count. Meshes of
 * 1..300 vertices and 0..40 triangles, the index array at both halfword
 * alignments, valid or with one index made bad at every position (just past
 * the count, 65535, a little past, or with the top bit set). Exit 0 when
 * every answer is right. */
#include "port.h"
#include "zspan/zspan.h"
#include <string.h>

static uint8_t arena[64 * 1024];
static int16_t pos[3 * 300];
static uint16_t idx_buf[3 * 40 + 2];
static uint32_t seed = 12345u;

static uint32_t next(void)
{
    seed = seed * 1103515245u + 12345u;
    return seed >> 8;
}

int main(void)
{
    zs_renderer r;
    zs_camera cam;
    zs_config cfg = zs_config_default(32, 32, 200, 400, 64);
    unsigned long checks = 0, wrong = 0;
    unsigned vc, tris, k;
    int off, bad_at;
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK) {
        sh_printf("check_indices_m4: zs_init failed\n");
        return 1;
    }
    memset(&cam, 0, sizeof cam);
    zs_camera_look_at(&cam, zs_vec3_make(0, 0, ZS_FX(5)), zs_vec3_make(0, 0, 0),
                      zs_vec3_make(0, ZS_FX(1), 0));
    zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(100));
    for (k = 0; k < 300; k++) {
        pos[3 * k] = (int16_t)(k * 7 % 200 - 100);
        pos[3 * k + 1] = (int16_t)(k * 13 % 200 - 100);
        pos[3 * k + 2] = (int16_t)(k % 5);
    }
    for (vc = 1; vc <= 300; vc += vc < 40 ? 1 : 37)
        for (off = 0; off < 2; off++)
            for (tris = 0; tris <= 40; tris += tris < 10 ? 1 : 9)
                for (bad_at = -1; bad_at < (int)(3 * tris); bad_at++) {
                    uint16_t *idx = idx_buf + off;
                    int want_err = 0;
                    zs_mesh m;
                    zs_status st;
                    for (k = 0; k < 3 * tris; k++)
                        idx[k] = (uint16_t)(next() % vc);
                    if (bad_at >= 0) {
                        uint32_t v = next(), kind = v & 3u;
                        idx[bad_at] = (uint16_t)(kind == 0   ? vc
                                                 : kind == 1 ? 65535u
                                                 : kind == 2 ? vc + ((v >> 4) & 255u)
                                                             : 0x8000u + vc);
                        want_err = idx[bad_at] >= vc;
                    }
                    memset(&m, 0, sizeof m);
                    m.positions = pos;
                    m.indices = idx;
                    m.scale = ZS_FX(1) / 64;
                    m.vertex_count = (uint16_t)vc;
                    m.triangle_count = (uint16_t)tris;
                    m.color = 0xFFFFFFu;
                    if (zs_frame_begin(&r, &cam, ZS_MODE_SPAN) != ZS_OK) {
                        sh_printf("check_indices_m4: zs_frame_begin failed\n");
                        return 1;
                    }
                    st = zs_draw(&r, &m, 0);
                    checks++;
                    if ((st == ZS_ERR_INDEX) != want_err && wrong++ < 5)
                        sh_printf("vertices %u, offset %d, triangles %u, bad index at %d: "
                                  "status %d\n",
                                  vc, off, tris, bad_at, (int)st);
                }
    sh_printf("check_indices_m4: %lu meshes, %lu wrong\n", checks, wrong);
    return wrong != 0;
}
