/* SPDX-License-Identifier: MIT */
/* The Cortex-M4 projection loop of zs_draw (geometry.c: the load-multiple
 * assembly of project_all) and back-face loop (setup.c's plain_simd), which
 * the host never builds, against the C they stand for: built for the host
 * and for mps2-an386, both print one hash per random draw of the vertex
 * pool (x, y, depth, or the unprojected mark and outcodes), the triangle
 * records and the set-up's counts, and make check-project-m4 compares the
 * two lists. The draws: 1..300 vertices anywhere in int16,
 * mesh scales from 2^-16 to 2^-9, random rotations and translations,
 * cameras with random eye, target, field of view, near and far, so that
 * many meshes are small on the screen (then the assembly runs) and some
 * are not or cross near, far or the guard band (the checked loop); 0..64
 * random triangles (front and back faces, some past the capacity). The
 * last line counts the draws whose every vertex was projected. */
#include "zspan/zspan.h"
#include "../../src/zs_internal.h"
#include <string.h>
#include "check_rng.h"
#ifdef __arm__
#include "port.h"
#define OUT sh_printf
#else
#include <stdio.h>
#define OUT printf
#endif

#define DRAWS 600
#define MAXV 300

static uint8_t arena[ZS_ARENA_BYTES(240, 240, 48, MAXV + 64, 64)];
static int16_t pos[3 * MAXV];
#define MAXT 64
static uint16_t idx[3 * MAXT];
static zs_color fcol[MAXT];
int main(void)
{
    zs_renderer r;
    zs_camera cam;
    zs_config cfg = zs_config_default(240, 240, 48, MAXV + 64, 64);
    unsigned d, k, all_in = 0;
    check_seed(0x2C0FFEEu);
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK) {
        OUT("check_project_m4: zs_init failed\n");
        return 1;
    }
    for (d = 0; d < DRAWS; d++) {
        zs_mesh m;
        zs_mat34 model, rot;
        uint32_t h = 0x811C9DC5u, vc, spread, tris;
        zs_fixed v6[6], fov, near_z, far_z, ang;
        int inside = 1;
        vc = (uint32_t)range(1, MAXV);
        spread = 32767u >> range(0, 12);
        /* (one call a statement: the order of arguments is unspecified) */
        for (k = 0; k < 6; k++)
            v6[k] = range(k < 2 ? -ZS_FX(20) : k == 2 ? -ZS_FX(60) : -ZS_FX(2),
                          k < 2 ? ZS_FX(20) : k == 2 ? ZS_FX(60) : ZS_FX(2));
        fov = range(ZS_FX(20), ZS_FX(100));
        near_z = range(ZS_FX(1) / 64, ZS_FX(2));
        far_z = range(ZS_FX(8), ZS_FX(4000));
        memset(&cam, 0, sizeof cam);
        zs_camera_look_at(&cam, zs_vec3_make(v6[0], v6[1], v6[2]),
                          zs_vec3_make(v6[3], v6[4], v6[5]), zs_vec3_make(0, ZS_FX(1), 0));
        zs_camera_perspective(&cam, fov, near_z, far_z);
        for (k = 0; k < 3 * vc; k++)
            pos[k] = (int16_t)range(-(int32_t)spread - 1, (int32_t)spread);
        if (d % 7 == 0) /* the int16 extremes */
            for (k = 0; k < 6 && k < 3 * vc; k++)
                pos[k] = (int16_t)((k & 1) ? 32767 : -32768);
        tris = (uint32_t)range(0, MAXT);
        for (k = 0; k < 3 * tris; k++)
            idx[k] = (uint16_t)(next() % vc);
        for (k = 0; k < tris; k++)
            fcol[k] = next();
        ang = range(0, ZS_FX(360));
        rot = zs_mat34_rotate_y(ang);
        ang = range(0, ZS_FX(360));
        model = zs_mat34_rotate_x(ang);
        model = zs_mat34_mul(&rot, &model);
        for (k = 0; k < 3; k++)
            v6[k] = range(-ZS_FX(3), ZS_FX(3));
        rot = zs_mat34_translate(v6[0], v6[1], v6[2]);
        model = zs_mat34_mul(&rot, &model);
        memset(&m, 0, sizeof m);
        m.positions = pos;
        m.indices = idx;
        m.scale = ZS_FX(1) >> range(9, 16);
        if (next() & 1)
            m.scale = -m.scale;
        m.vertex_count = (uint16_t)vc;
        m.triangle_count = (uint16_t)tris;
        m.color = 0xFFFFFFu;
        if (d & 1) /* face colours: each record's by its triangle's number */
            m.face_colors = fcol;
        if (zs_frame_begin(&r, &cam, ZS_MODE_SPAN) != ZS_OK || zs_draw(&r, &m, &model) != ZS_OK) {
            OUT("check_project_m4: draw %u failed\n", d);
            return 1;
        }
        for (k = 0; k < vc; k++) {
            const zs_vert *v = &r.priv.verts[k];
            h = fnv_word(h, (uint32_t)(uint16_t)v->x | ((uint32_t)(uint16_t)v->y << 16));
            h = fnv_word(h, v->z);
            if (v->z & ZS_VERT_UNPROJECTED)
                inside = 0;
        }
        /* and the set-up's records and counts (the assembly cull loop) */
        for (k = 0; k < r.priv.n_tris; k++) {
            const zs_tri *t = &r.priv.tris[k];
            h = fnv_word(h, (uint32_t)t->v[0] | ((uint32_t)t->v[1] << 16));
            h = fnv_word(h, (uint32_t)t->v[2] | ((uint32_t)t->next << 16));
            h = fnv_word(h, t->color);
        }
        h = fnv_word(h, r.stats.tris_culled);
        h = fnv_word(h, r.stats.tris_stored);
        h = fnv_word(h, r.stats.tris_empty);
        h = fnv_word(h, r.stats.tris_rejected);
        h = fnv_word(h, r.stats.tris_dropped);
        all_in += (unsigned)inside;
        OUT("P %u %08lx\n", d, (unsigned long)h);
    }
    OUT("N %u draws, %u with every vertex projected\n", DRAWS, all_in);
    return 0;
}
