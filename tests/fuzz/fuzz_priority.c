/* SPDX-License-Identifier: MIT */
/*
 * fuzz_priority: list priority and culling (zspan/priority.h, zspan/cull.h)
 * from arbitrary bytes (libFuzzer).
 *
 * The input builds a small mesh (up to 24 vertices, 32 triangles), a BSP
 * node array (up to 40 nodes, every field from the bytes), a cell array over
 * a few objects, and a camera. Then: zs_bsp_check and zs_draw_bsp in
 * ZS_MODE_PRIORITY; zs_cells_check and zs_draw_cells; the mesh drawn again
 * and zs_depth_sort (NNS or plain, a small budget); every frame rendered.
 * The sorted frame is made twice: rendered in rows and painted back to front
 * (zs_paint_frame), and the two images must be equal byte for byte, the
 * painter writing nothing past a row; zs_priority_order must give every
 * record once, back to front, and zs_record_get each of them.
 *
 * Invariants: the checks give ZS_OK or ZS_ERR_BSP (ZS_ERR_NULL never, as
 * nothing is NULL); a draw of a refused tree or scene gives the same error
 * and submits nothing; a good tree's walk visits every node once; the
 * statistics add up; the sort keeps within the pools and its budget
 * (pairs resolved <= budget); a renderer without depth planes
 * (ZS_CFG_PRIORITY_ONLY) gives the same sorted rows. ASan and UBSan
 * catch the rest; -timeout catches a walk or sort that does not end.
 */
#include <stdint.h>
#include <string.h>

#include "fuzz_util.h"
#include "zspan/cull.h"
#include "zspan/priority.h"

#define FW 40
#define FH 30
#define NV 24
#define NT 32
#define NN 40
#define NC 12

static void render(zs_renderer *r)
{
    static uint8_t row[FW * 2];
    int y;
    for (y = 0; y < FH; y++)
        FZ_CHECK(zs_render_rows(r, y, 1, row, sizeof row) == ZS_OK, "row %d", y);
}

/* The frame's rows into img (FH rows of FW * 2 bytes). */
static void render_full(zs_renderer *r, uint8_t *img)
{
    FZ_CHECK(zs_render_rows(r, 0, FH, img, FW * 2) == ZS_OK, "rows");
}

static void check_stats(const zs_stats *s)
{
    FZ_CHECK(s->tris_submitted ==
                 s->tris_culled + s->tris_rejected + s->tris_empty + s->tris_dropped + s->tris_stored,
             "statistics do not add up");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t arena[ZS_ARENA_BYTES_CFG(FW, FH, 400, 600, 256, ZS_CFG_PRIORITY)];
    static uint8_t arena_po[ZS_ARENA_BYTES_CFG(FW, FH, 400, 600, 256,
                                               ZS_CFG_PRIORITY | ZS_CFG_PRIORITY_ONLY)];
    static uint8_t po_img[FW * 2 * FH];
    zs_renderer rp; /* without depth planes (ZS_CFG_PRIORITY_ONLY) */
    zs_config cfg_po;
    static int16_t pos[3 * NV];
    static uint16_t idx[3 * NT];
    static zs_bsp_node nodes[NN];
    static zs_cell cells[NC];
    static zs_scene_object objs[4];
    fz_reader d;
    zs_renderer r;
    zs_config cfg = zs_config_default(FW, FH, 400, 600, 256);
    zs_camera cam;
    zs_mesh mesh;
    zs_bsp bsp;
    zs_cells sc;
    static uint8_t rows_img[FW * 2 * FH], paint_img[(FW * 2 + 3) * FH], seen[400];
    static uint16_t order[400];
    zs_status chk, st;
    zs_sort_kind kind;
    uint32_t nv, nt, nn, nc, k, budget, count = 0, skipped = 0;
    int pass, y;
    fz_init(&d, data, size);
    cfg.flags = ZS_CFG_PRIORITY;
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK)
        return 0;
    cfg_po = cfg;
    cfg_po.flags = ZS_CFG_PRIORITY | ZS_CFG_PRIORITY_ONLY;
    FZ_CHECK(zs_init(&rp, arena_po, sizeof arena_po, &cfg_po) == ZS_OK, "priority-only init");
    nv = 3 + fz_u8(&d) % (NV - 2);
    nt = 1 + fz_u8(&d) % NT;
    for (k = 0; k < 3 * nv; k++)
        pos[k] = (int16_t)((int8_t)fz_u8(&d) * 4);
    for (k = 0; k < 3 * nt; k++)
        idx[k] = (uint16_t)(fz_u8(&d) % nv);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos;
    mesh.indices = idx;
    mesh.scale = ZS_FX(1) / 64;
    mesh.vertex_count = (uint16_t)nv;
    mesh.triangle_count = (uint16_t)nt;
    mesh.color = 0xFFFFFF;
    /* nodes: mostly near-valid (children next, ranges small), any field may be off */
    nn = 1 + fz_u8(&d) % NN;
    for (k = 0; k < nn; k++) {
        zs_bsp_node *n = &nodes[k];
        uint8_t how = fz_u8(&d);
        n->n[0] = (int8_t)fz_u8(&d);
        n->n[1] = (int8_t)fz_u8(&d);
        n->n[2] = (int8_t)fz_u8(&d);
        n->d = (int64_t)(int16_t)fz_u16(&d);
        n->front = (how & 1) && k + 1 < nn ? (uint16_t)(k + 1) : ZS_BSP_NONE;
        n->back = (how & 2) ? (uint16_t)(k + 1 + fz_u8(&d) % 8) : ZS_BSP_NONE;
        n->first = (uint16_t)(fz_u8(&d) % (nt + 2));
        n->n_front = (uint16_t)(fz_u8(&d) % 4);
        n->n_back = (uint16_t)(fz_u8(&d) % 4);
        if (how & 0x80) /* wild */
            n->front = fz_u16(&d), n->n[1] = (int32_t)fz_u32(&d);
    }
    bsp.nodes = nodes;
    bsp.mesh = &mesh;
    bsp.node_count = (uint16_t)nn;
    if (zs_camera_look_at(&cam, zs_vec3_make((int8_t)fz_u8(&d) * 4096, (int8_t)fz_u8(&d) * 4096,
                                             ZS_FX(3) + (int8_t)fz_u8(&d) * 2048),
                          zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)) != ZS_OK ||
        zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 10, ZS_FX(50)) != ZS_OK)
        return 0;

    chk = zs_bsp_check(&bsp);
    FZ_CHECK(chk == ZS_OK || chk == ZS_ERR_BSP, "bsp check gave %d", (int)chk);
    FZ_CHECK(zs_frame_begin(&r, &cam, ZS_MODE_PRIORITY) == ZS_OK, "frame_begin");
    st = zs_draw_bsp(&r, &bsp, NULL);
    if (chk != ZS_OK) {
        FZ_CHECK(st == chk && r.stats.tris_submitted == 0, "a refused tree drew (%d)", (int)st);
    } else if (st == ZS_OK) {
        FZ_CHECK(r.stats.bsp_nodes == nn, "%u nodes visited of %u", r.stats.bsp_nodes, nn);
    } else {
        FZ_CHECK(st == ZS_ERR_INDEX || st == ZS_ERR_MESH, "draw_bsp gave %d", (int)st);
    }
    check_stats(&r.stats);
    render(&r);

    /* cells over up to 4 objects (the same mesh) */
    nc = 1 + fz_u8(&d) % NC;
    for (k = 0; k < 4; k++) {
        objs[k].mesh = &mesh;
        objs[k].model = NULL;
        zs_mesh_bounds(&mesh, &objs[k].bounds);
    }
    for (k = 0; k < nc; k++) {
        zs_cell *c = &cells[k];
        int j;
        for (j = 0; j < 3; j++) {
            c->lo[j] = -(zs_fixed)(fz_u8(&d) * 1024);
            c->hi[j] = (zs_fixed)((int8_t)fz_u8(&d) * 1024);
        }
        c->first_child = (uint16_t)(fz_u8(&d) % (nc + 1));
        c->child_count = (uint16_t)(fz_u8(&d) % 3);
        c->first_object = (uint16_t)(fz_u8(&d) % 5);
        c->object_count = (uint16_t)(fz_u8(&d) % 5);
    }
    sc.cells = cells;
    sc.objects = objs;
    sc.cell_count = (uint16_t)nc;
    sc.object_count = (uint16_t)(fz_u8(&d) % 5);
    chk = zs_cells_check(&sc);
    FZ_CHECK(chk == ZS_OK || chk == ZS_ERR_BSP, "cells check gave %d", (int)chk);
    FZ_CHECK(zs_frame_begin(&r, &cam, ZS_MODE_SPAN) == ZS_OK, "frame_begin");
    st = zs_draw_cells(&r, &sc);
    if (chk != ZS_OK)
        FZ_CHECK(st == chk && r.stats.tris_submitted == 0, "a refused scene drew (%d)", (int)st);
    if (st == ZS_OK)
        FZ_CHECK(r.stats.tris_submitted == (uint32_t)sc.object_count * nt, "submitted %u",
                 r.stats.tris_submitted);
    check_stats(&r.stats);
    render(&r);

    /* the depth sort on the mesh, twice over */
    budget = 1 + fz_u8(&d) * 8u;
    kind = (fz_u8(&d) & 1) ? ZS_SORT_NNS : ZS_SORT_DEPTH;
    for (pass = 0; pass < 2; pass++) { /* rows, then painted */
        FZ_CHECK(zs_frame_begin(&r, &cam, ZS_MODE_PRIORITY) == ZS_OK, "frame_begin");
        st = zs_draw(&r, &mesh, NULL);
        if (st == ZS_OK)
            st = zs_draw(&r, &mesh, NULL);
        if (st != ZS_OK)
            return 0;
        st = zs_depth_sort(&r, kind, budget);
        FZ_CHECK(st == ZS_OK, "depth sort gave %d", (int)st);
        FZ_CHECK(r.stats.sort_pairs <= budget, "past the budget");
        FZ_CHECK(r.priv.n_tris <= cfg.max_triangles && r.priv.n_verts <= cfg.max_vertices,
                 "pools overrun");
        if (pass == 0) {
            render_full(&r, rows_img);
            skipped = r.stats.records_skipped;
            /* the same frame without depth planes: the same rows; the
             * other modes refused */
            FZ_CHECK(zs_frame_begin(&rp, &cam, ZS_MODE_SPAN) == ZS_ERR_MODE, "span accepted");
            FZ_CHECK(zs_frame_begin(&rp, &cam, ZS_MODE_PRIORITY) == ZS_OK, "frame_begin");
            FZ_CHECK(zs_draw(&rp, &mesh, NULL) == ZS_OK && zs_draw(&rp, &mesh, NULL) == ZS_OK,
                     "priority-only draws");
            FZ_CHECK(zs_depth_sort(&rp, kind, budget) == ZS_OK, "priority-only sort");
            FZ_CHECK(zs_render_rows(&rp, 0, FH, po_img, FW * 2) == ZS_OK, "priority-only rows");
            FZ_CHECK(memcmp(po_img, rows_img, sizeof po_img) == 0,
                     "priority-only rows differ from the full renderer's");
            continue;
        }
        FZ_CHECK(zs_priority_order(&r, order, 400, &count) == ZS_OK && count == r.priv.n_tris,
                 "order of %u records", count);
        memset(seen, 0, sizeof seen);
        for (k = 0; k < count; k++) {
            zs_record_tri rt;
            FZ_CHECK(order[k] < count && !seen[order[k]], "record %u twice or out of range",
                     order[k]);
            FZ_CHECK(k == 0 || order[k] < order[k - 1], "not back to front");
            seen[order[k]] = 1;
            FZ_CHECK(zs_record_get(&r, order[k], &rt) == ZS_OK, "record_get %u", order[k]);
        }
        memset(paint_img, 0xEE, sizeof paint_img);
        FZ_CHECK(zs_paint_frame(&r, paint_img, FW * 2 + 3) == ZS_OK, "paint");
        for (y = 0; y < FH; y++) {
            /* the walk skips records its full active pool cannot take; the painter does not */
            FZ_CHECK(skipped || !memcmp(paint_img + y * (FW * 2 + 3), rows_img + y * FW * 2, FW * 2),
                     "painted row %d differs from the rendered one", y);
            for (k = FW * 2; k < FW * 2 + 3; k++)
                FZ_CHECK(paint_img[y * (FW * 2 + 3) + (int)k] == 0xEE, "painted past row %d", y);
        }
    }
    return 0;
}
