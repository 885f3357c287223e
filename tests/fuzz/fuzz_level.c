/* SPDX-License-Identifier: MIT */
/*
 * fuzz_level: portal levels (zspan/portal.h) from arbitrary bytes (libFuzzer).
 *
 * The input picks a small generated level (kind, size, seed: tools/level),
 * builds its arrays, then overwrites up to 32 bytes anywhere in them (cells,
 * portals, plan vertices, PVS bitsets, the level's counts and unit), and
 * picks an eye (inside a cell or anywhere), a view direction, a field of view
 * and a screen size. zs_level_check and zs_level_draw (every cull) run on the
 * result, followed by the frame.
 *
 * Invariants: zs_level_check gives ZS_OK or ZS_ERR_LEVEL; zs_level_draw
 * gives what zs_level_check gave (ZS_OK drawing, ZS_ERR_LEVEL submitting
 * nothing); the statistics add up (drawn + culled triangles == the level's,
 * cells drawn <= cells, at most ZS_LEVEL_WALK_BUDGET portals tested, cells
 * drawn <= the PVS when not falling back); an unmodified level's frame with
 * portal culling equals the frame with every cell when the eye is well
 * inside a cell. ASan and UBSan catch the rest; -timeout catches a walk that
 * does not end.
 */
#include <stdint.h>
#include <string.h>

#include "fuzz_util.h"
#include "level.h"

#define FW 48
#define FH 36

static zs_fixed clamp_fx(int64_t v)
{
    return (zs_fixed)(v > INT32_MAX / 2 ? INT32_MAX / 2 : v < -(INT32_MAX / 2) ? -(INT32_MAX / 2) : v);
}

static void render(zs_renderer *r, uint8_t *img)
{
    int y;
    for (y = 0; y < FH; y++)
        FZ_CHECK(zs_render_rows(r, y, 1, img + y * FW * 2, FW * 2) == ZS_OK, "row %d", y);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t arena[ZS_ARENA_BYTES(FW, FH, 4000, 8000, 512)];
    static uint8_t img[FW * FH * 2], ref[FW * FH * 2];
    fz_reader d;
    lv_level lv;
    lv_built b;
    char err[256];
    zs_renderer r;
    zs_config cfg = zs_config_default(FW, FH, 4000, 8000, 512);
    zs_camera cam;
    zs_level l;
    zs_status chk, st;
    int kind, cols, rows, edits, k, c, pristine, eye_cell, centred;
    uint32_t seed;
    zs_vec3 eye, tgt;
    fz_init(&d, data, size);
    kind = fz_u8(&d) & 1;
    cols = 1 + fz_u8(&d) % 4;
    rows = 1 + fz_u8(&d) % 3;
    seed = fz_u32(&d);
    lv_generate(&lv, kind ? LV_BUILDING : LV_MAZE, cols, rows, seed);
    FZ_CHECK(lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err) == 0, "%s", err);
    l = b.level;
    /* edits: which array, an offset, a byte */
    edits = fz_u8(&d) % 33;
    pristine = edits == 0;
    for (k = 0; k < edits; k++) {
        uint8_t which = fz_u8(&d) % 6, v = fz_u8(&d);
        uint16_t at = fz_u16(&d);
        switch (which) {
        /* offsets within the arrays as built (the counts may have been edited) */
        case 0: ((uint8_t *)b.cells)[at % (b.level.cell_count * sizeof *b.cells)] = v; break;
        case 1:
            ((uint8_t *)b.portals)[at % (b.level.portal_count * sizeof *b.portals + 1u)] = v;
            break;
        case 2: ((uint8_t *)b.vertices)[at % (b.level.vertex_count * 4u)] = v; break;
        case 3:
            b.pvs[at % (b.level.cell_count * ((b.level.cell_count + 7u) / 8u))] = v;
            break;
        case 4: l.unit = (zs_fixed)(l.unit ^ ((uint32_t)v << (at % 32))); break;
        default: {
            uint16_t *count = at % 3 == 0 ? &l.cell_count : at % 3 == 1 ? &l.portal_count
                                                                         : &l.vertex_count;
            /* only ever smaller: the arrays behind the counts stay in bounds */
            if (v < *count)
                *count = v;
        } break;
        }
    }
    chk = zs_level_check(&l);
    FZ_CHECK(chk == ZS_OK || chk == ZS_ERR_LEVEL, "check gave %d", chk);
    /* the eye: a point well inside a cell (from its polygon's centre) or raw */
    c = fz_u8(&d) % b.level.cell_count;
    centred = fz_u8(&d) & 1;
    if (centred) {
        const zs_level_cell *cell = &b.cells[c];
        int64_t sx = 0, sy = 0;
        int v;
        for (v = 0; v < cell->vertex_count && cell->first_vertex + v < b.level.vertex_count; v++) {
            sx += b.vertices[2 * (cell->first_vertex + v)];
            sy += b.vertices[2 * (cell->first_vertex + v) + 1];
        }
        v = v ? v : 1;
        eye = zs_vec3_make(clamp_fx(sx * l.unit / v),
                           clamp_fx((int64_t)((cell->floor + cell->ceiling) / 2) * l.unit),
                           clamp_fx(-sy * l.unit / v));
    } else {
        eye = zs_vec3_make((zs_fixed)fz_u32(&d) >> 8, (zs_fixed)fz_u32(&d) >> 12,
                           (zs_fixed)fz_u32(&d) >> 8);
    }
    tgt = zs_vec3_make(eye.x + (int16_t)fz_u16(&d), eye.y + (int8_t)fz_u8(&d) * 64,
                       eye.z + (int16_t)fz_u16(&d)); /* |eye| <= 2^30: no overflow */
    if (zs_camera_look_at(&cam, eye, tgt, zs_vec3_make(0, ZS_FX_ONE, 0)) != ZS_OK ||
        zs_camera_perspective(&cam, ZS_FX(20 + fz_u8(&d) % 140), ZS_FX_ONE / 20, ZS_FX(200)) !=
            ZS_OK) {
        lv_built_free(&b);
        lv_free(&lv);
        return 0;
    }
    FZ_CHECK(zs_init(&r, arena, sizeof arena, &cfg) == ZS_OK, "init");
    eye_cell = chk == ZS_OK ? zs_level_find_cell(&l, eye) : -1;
    for (k = 0; k < 3; k++) {
        zs_level_stats ls;
        uint32_t total = 0;
        int i;
        FZ_CHECK(zs_frame_begin(&r, &cam, ZS_MODE_SPAN) == ZS_OK, "begin");
        st = zs_level_draw(&r, &l, eye, (zs_level_cull)k, &ls);
        FZ_CHECK(st == chk, "draw gave %d, check %d", st, chk);
        if (st != ZS_OK) {
            FZ_CHECK(zs_frame_stats(&r)->tris_submitted == 0, "a refused level drew");
            continue;
        }
        for (i = 0; i < l.cell_count; i++)
            total += l.meshes[i].triangle_count;
        FZ_CHECK(ls.tris_submitted + ls.tris_culled == total, "triangles %u + %u != %u",
                 (unsigned)ls.tris_submitted, (unsigned)ls.tris_culled, (unsigned)total);
        FZ_CHECK(ls.tris_submitted == zs_frame_stats(&r)->tris_submitted, "submitted");
        FZ_CHECK(ls.cells_drawn <= l.cell_count, "cells drawn");
        FZ_CHECK(ls.portals_tested <= ZS_LEVEL_WALK_BUDGET, "budget");
        FZ_CHECK(ls.eye_cell == eye_cell, "eye cell %d, find_cell %d", (int)ls.eye_cell, eye_cell);
        if (k == ZS_LEVEL_CULL_NONE)
            FZ_CHECK(ls.cells_drawn == l.cell_count, "cull none drew %u", (unsigned)ls.cells_drawn);
        else if (ls.eye_cell >= 0 && !ls.fallback)
            FZ_CHECK(ls.cells_drawn <= ls.pvs_cells, "drawn %u > pvs %u",
                     (unsigned)ls.cells_drawn, (unsigned)ls.pvs_cells);
        render(&r, k == 0 ? ref : img);
        /* an unmodified level, the eye at a cell's centre, which in the
         * generated levels is at least half a wall thickness from any face */
        if (pristine && centred && k == ZS_LEVEL_CULL_PORTALS && ls.eye_cell >= 0)
            FZ_CHECK(memcmp(img, ref, sizeof img) == 0, "portal culling changed the frame");
    }
    lv_built_free(&b);
    lv_free(&lv);
    return 0;
}
