/* SPDX-License-Identifier: MIT */
/* LIBS: app/zs_cells_build.c */
/*
 * test_cull: culling by boxes before the transform (zspan/cull.h).
 *
 *  - city: a block of 144 buildings and 100 trees (244 objects, shared
 *    meshes placed by model matrices) seen from street level in many
 *    directions. Each view is rendered three ways, in ID16 and RGB565:
 *    every object with zs_draw (the reference), every object with
 *    zs_draw_bounded, and zs_draw_cells over a k-d tree and over a uniform
 *    grid. The images must be byte-identical, the statistics must add up,
 *    and for the typical (street) views at least 70% of the triangles must
 *    never reach the transform (tris_untransformed).
 *  - bad cells: layouts zs_cells_check must refuse (ZS_ERR_BSP), and a
 *    bad scene draws nothing.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../app/zs_cells_build.h"
#include "zspan/cull.h"

#define W 120
#define H 80
#define NB 144
#define NT 100
#define NOBJ (NB + NT)

/* a unit cube [-1, 1]^3 and a tree (a four-sided cone on a trunk) */
static const int16_t cube_pos[] = {-64, -64, -64, 64, -64, -64, -64, 64, -64, 64, 64, -64,
                                   -64, -64, 64,  64, -64, 64,  -64, 64, 64,  64, 64, 64};
static const uint16_t cube_idx[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                    2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
static const int16_t tree_pos[] = {0, 128, 0, -40, 20, -40, 40, 20, -40, 40, 20, 40, -40, 20, 40,
                                   -8, 0, -8, 8, 0, -8, 8, 20, 8, -8, 20, 8};
static const uint16_t tree_idx[] = {0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4, 1, 2, 3, 1, 3, 4,
                                    5, 6, 7, 5, 7, 8};

typedef struct city {
    zs_mesh cube, tree;
    zs_mat34 model[NOBJ];
    zs_scene_object obj[NOBJ];  /* in the cells' order */
    double lo[3 * NOBJ], hi[3 * NOBJ];
} city;

static zs_mesh make_mesh(const int16_t *pos, unsigned nv, const uint16_t *idx, unsigned nt,
                         zs_color color)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 64;
    m.vertex_count = (uint16_t)nv;
    m.triangle_count = (uint16_t)nt;
    m.color = color;
    return m;
}

static void build_city(city *c, zt_rng *g)
{
    zs_scene_object raw[NOBJ];
    c->cube = make_mesh(cube_pos, 8, cube_idx, 12, ZS_RGB(180, 170, 160));
    c->tree = make_mesh(tree_pos, 9, tree_idx, 8, ZS_RGB(40, 160, 60));
    for (int k = 0; k < NOBJ; k++) {
        double x, z, sx, sy, sz;
        const zs_mesh *m;
        if (k < NB) { /* 12 x 12 blocks, 20 units apart, streets between */
            x = (k % 12 - 5.5) * 20;
            z = (k / 12 - 5.5) * 20;
            sx = zt_uniform(g, 4, 7);
            sz = zt_uniform(g, 4, 7);
            sy = zt_uniform(g, 4, 30);
            m = &c->cube;
            c->model[k] = zs_mat34_mul(&(zs_mat34){{{ZS_FX(1), 0, 0, (zs_fixed)(x * 65536)},
                                                    {0, ZS_FX(1), 0, (zs_fixed)(sy * 65536)},
                                                    {0, 0, ZS_FX(1), (zs_fixed)(z * 65536)}}},
                                       &(zs_mat34){{{(zs_fixed)(sx * 65536), 0, 0, 0},
                                                    {0, (zs_fixed)(sy * 65536), 0, 0},
                                                    {0, 0, (zs_fixed)(sz * 65536), 0}}});
            c->lo[3 * k] = x - sx;
            c->hi[3 * k] = x + sx;
            c->lo[3 * k + 1] = 0;
            c->hi[3 * k + 1] = 2 * sy;
            c->lo[3 * k + 2] = z - sz;
            c->hi[3 * k + 2] = z + sz;
        } else { /* trees along the streets */
            int t = k - NB;
            x = (t % 10 - 4.5) * 20 + 10 + zt_uniform(g, -1, 1);
            z = (t / 10 - 4.5) * 20 + zt_uniform(g, -6, 6);
            m = &c->tree;
            c->model[k] = zs_mat34_mul(&(zs_mat34){{{ZS_FX(1), 0, 0, (zs_fixed)(x * 65536)},
                                                    {0, ZS_FX(1), 0, 0},
                                                    {0, 0, ZS_FX(1), (zs_fixed)(z * 65536)}}},
                                       &(zs_mat34){{{ZS_FX(2), 0, 0, 0},
                                                    {0, ZS_FX(2), 0, 0},
                                                    {0, 0, ZS_FX(2), 0}}});
            c->lo[3 * k] = x - 1.25;
            c->hi[3 * k] = x + 1.25;
            c->lo[3 * k + 1] = 0;
            c->hi[3 * k + 1] = 4;
            c->lo[3 * k + 2] = z - 1.25;
            c->hi[3 * k + 2] = z + 1.25;
        }
        raw[k].mesh = m;
        raw[k].model = &c->model[k];
        zs_mesh_bounds(m, &raw[k].bounds);
    }
    memcpy(c->obj, raw, sizeof raw);
}

static void look(zs_camera *cam, double ex, double ey, double ez, double tx, double ty, double tz)
{
    ZT_ST(zs_camera_look_at(cam,
                            zs_vec3_make((zs_fixed)lrint(ex * 65536), (zs_fixed)lrint(ey * 65536),
                                         (zs_fixed)lrint(ez * 65536)),
                            zs_vec3_make((zs_fixed)lrint(tx * 65536), (zs_fixed)lrint(ty * 65536),
                                         (zs_fixed)lrint(tz * 65536)),
                            zs_vec3_make(0, ZS_FX(1), 0)),
          ZS_OK);
    ZT_ST(zs_camera_perspective(cam, ZS_FX(60), ZS_FX(1) / 4, ZS_FX(100)), ZS_OK);
}

/* how: 0 zs_draw, 1 zs_draw_bounded, 2 zs_draw_cells */
static void render(zt_ctx *c, const zs_camera *cam, zs_format fmt, const zs_scene_object *obj,
                   const zs_cells *cells, int how, uint8_t *img)
{
    zs_shade_params sp = zs_shade_default();
    sp.format = fmt;
    sp.ambient = ZS_FX(1) / 2;
    sp.light_count = 1;
    sp.lights[0].direction = zs_vec3_make(ZS_FX(1), ZS_FX(2), ZS_FX(1) / 2);
    sp.lights[0].intensity = ZS_FX(1) / 2;
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    if (how == 2) {
        ZT_ST(zs_draw_cells(&c->r, cells), ZS_OK);
    } else {
        for (int k = 0; k < NOBJ; k++) {
            if (how == 0)
                ZT_ST(zs_draw(&c->r, obj[k].mesh, obj[k].model), ZS_OK);
            else
                ZT_ST(zs_draw_bounded(&c->r, obj[k].mesh, obj[k].model, &obj[k].bounds), ZS_OK);
        }
    }
    ZT_ST(zt_render_rows_all(&c->r, img, W, H, fmt, 8), ZS_OK);
    const zs_stats *s = &c->r.stats;
    ZT_CHECK(s->tris_submitted == s->tris_culled + s->tris_rejected + s->tris_empty +
                                      s->tris_dropped + s->tris_stored,
             "stats do not add up (how %d)", how);
    ZT_CHECK(s->tris_dropped == 0 && s->records_skipped == 0, "pools too small");
}

static void test_city(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, 0xC17E5EEDull);
    static city ct;
    build_city(&ct, &g);
    zs_cellsb_result kd, gr;
    const char *err = zs_cellsb_build(ct.lo, ct.hi, NOBJ, ZS_CELLS_KD, 4, &kd);
    ZT_CHECK(err == NULL, "k-d build: %s", err ? err : "");
    err = zs_cellsb_build(ct.lo, ct.hi, NOBJ, ZS_CELLS_GRID, 6, &gr);
    ZT_CHECK(err == NULL, "grid build: %s", err ? err : "");
    static zs_scene_object obj_kd[NOBJ], obj_gr[NOBJ];
    for (int k = 0; k < NOBJ; k++) {
        obj_kd[k] = ct.obj[kd.order[k]];
        obj_gr[k] = ct.obj[gr.order[k]];
    }
    /* every grid size and leaf size gives a layout the core accepts (a grid
     * of 8 x 8 once wrote through a moved cell array: ASan would say so) */
    for (int p = 1; p <= 8; p++) {
        for (int kind = 0; kind < 2; kind++) {
            zs_cellsb_result t;
            ZT_CHECK(zs_cellsb_build(ct.lo, ct.hi, NOBJ, kind, p, &t) == NULL, "build %d %d",
                     kind, p);
            static zs_scene_object o[NOBJ];
            for (int k = 0; k < NOBJ; k++)
                o[k] = ct.obj[t.order[k]];
            zs_cells cs = {t.cells, o, (uint16_t)t.cell_count, NOBJ};
            ZT_ST(zs_cells_check(&cs), ZS_OK);
            zs_cellsb_free(&t);
        }
    }
    zs_cells cells_kd = {kd.cells, obj_kd, (uint16_t)kd.cell_count, NOBJ};
    zs_cells cells_gr = {gr.cells, obj_gr, (uint16_t)gr.cell_count, NOBJ};
    ZT_ST(zs_cells_check(&cells_kd), ZS_OK);
    ZT_ST(zs_cells_check(&cells_gr), ZS_OK);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 3000, 3000, 1000);
    static uint8_t ref[W * H * 2], img[W * H * 2];
    unsigned long tris = 0, untrans[3] = {0}, verts = 0, vuntrans = 0, cells_culled[2] = {0},
                  street_views = 0, below70 = 0;
    double worst = 1.0;
    const int nviews = 24;
    for (int v = 0; v < nviews; v++) {
        zs_camera cam;
        double a = 2 * 3.14159265 * v / nviews;
        int street = v % 3 != 2; /* two in three at eye height in a street */
        /* street level: on a street crossing near the middle (streets run
         * between the blocks, at multiples of 20 units) */
        double ex = street ? 20.0 * (double)zt_range(&g, -2, 2) + zt_uniform(&g, -2, 2)
                           : 150 * cos(a);
        double ez = street ? 20.0 * (double)zt_range(&g, -2, 2) + zt_uniform(&g, -2, 2)
                           : 150 * sin(a);
        double ey = street ? 1.7 : 60;
        if (street)
            look(&cam, ex, ey, ez, ex + cos(a), ey, ez + sin(a));
        else
            look(&cam, ex, ey, ez, 0, 0, 0);
        for (int f = 0; f < 2; f++) {
            zs_format fmt = f ? ZS_FMT_RGB565_BE : ZS_FMT_ID16;
            /* the reference in the k-d order; the grid's order is another
             * submission order, so it has its own reference */
            for (int which = 0; which < 2; which++) {
                const zs_scene_object *obj = which ? obj_gr : obj_kd;
                const zs_cells *cells = which ? &cells_gr : &cells_kd;
                render(&c, &cam, fmt, obj, cells, 0, ref);
                uint32_t n_tris = c.r.stats.tris_submitted, n_verts = 0;
                for (int k = 0; k < NOBJ; k++)
                    n_verts += obj[k].mesh->vertex_count;
                for (int how = 1; how <= 2; how++) {
                    render(&c, &cam, fmt, obj, cells, how, img);
                    long d = zt_first_diff(ref, img, sizeof ref);
                    ZT_CHECK(d < 0, "view %d format %d %s: %s differs from zs_draw at byte %ld", v,
                             (int)fmt, which ? "grid" : "k-d",
                             how == 1 ? "zs_draw_bounded" : "zs_draw_cells", d);
                    ZT_CHECK(c.r.stats.tris_submitted == n_tris, "view %d: submitted %u of %u", v,
                             c.r.stats.tris_submitted, n_tris);
                    if (f == 0) {
                        int slot = how == 1 ? 0 : 1 + which;
                        untrans[slot] += c.r.stats.tris_untransformed;
                        if (how == 2)
                            cells_culled[which] += c.r.stats.cells_culled;
                        if (how == 2 && which == 0) {
                            tris += n_tris;
                            verts += n_verts;
                            vuntrans += c.r.stats.verts_untransformed;
                            if (street) {
                                double frac = (double)c.r.stats.tris_untransformed / n_tris;
                                street_views++;
                                below70 += frac < 0.70;
                                worst = frac < worst ? frac : worst;
                            }
                        }
                    }
                }
            }
        }
    }
    printf("test_cull city: %d objects (%d buildings, %d trees), %d views (%lu at street level); "
           "k-d tree %zu cells (depth %d), grid %zu cells; triangles never transformed: "
           "bounded draws %.1f%%, k-d cells %.1f%%, grid cells %.1f%% (of %lu); vertices %.1f%% "
           "(of %lu); cells culled whole: k-d %lu, grid %lu; street views: worst %.1f%% "
           "untransformed, %lu below 70%%; images byte-identical to zs_draw\n",
           NOBJ, NB, NT, nviews, street_views, kd.cell_count, kd.depth, gr.cell_count,
           100.0 * untrans[0] / tris / 2, 100.0 * untrans[1] / tris, 100.0 * untrans[2] / tris,
           tris, 100.0 * vuntrans / verts, verts, cells_culled[0], cells_culled[1], 100 * worst,
           below70);
    ZT_CHECK(below70 == 0, "%lu street views keep less than 70%% from the transform", below70);
    zs_cellsb_free(&kd);
    zs_cellsb_free(&gr);
    zt_ctx_free(&c);
}

static void test_bad_cells(void **state)
{
    (void)state;
    zs_mesh cube = make_mesh(cube_pos, 8, cube_idx, 12, 0xFFFFFF);
    zs_scene_object obj[3];
    for (int k = 0; k < 3; k++) {
        obj[k].mesh = &cube;
        obj[k].model = NULL;
        zs_mesh_bounds(&cube, &obj[k].bounds);
    }
    const zs_cell good[3] = {
        {{-ZS_FX(2), -ZS_FX(2), -ZS_FX(2)}, {ZS_FX(2), ZS_FX(2), ZS_FX(2)}, 1, 2, 0, 3},
        {{-ZS_FX(2), -ZS_FX(2), -ZS_FX(2)}, {ZS_FX(2), ZS_FX(2), ZS_FX(2)}, 0, 0, 0, 1},
        {{-ZS_FX(2), -ZS_FX(2), -ZS_FX(2)}, {ZS_FX(2), ZS_FX(2), ZS_FX(2)}, 0, 0, 1, 2}};
    zs_cells s = {good, obj, 3, 3};
    ZT_ST(zs_cells_check(&s), ZS_OK);
    zs_cell bad[3];
    for (int k = 0; k < 8; k++) {
        memcpy(bad, good, sizeof good);
        zs_cells b = {bad, obj, 3, 3};
        const char *what = "";
        switch (k) {
        case 0: bad[0].first_child = 2; what = "first child not next"; break;
        case 1: bad[0].child_count = 3; what = "children past the cells"; break;
        case 2: bad[2].child_count = 1; bad[2].first_child = 0; what = "child pointing back (cycle)"; break;
        case 3: bad[1].object_count = 2; what = "leaf ranges overlap"; break;
        case 4: bad[2].first_object = 2; bad[2].object_count = 1; what = "an object left out"; break;
        case 5: bad[0].object_count = 4; what = "range past the objects"; break;
        case 6: bad[1].lo[0] = ZS_FX(3); what = "box lo > hi"; break;
        case 7: b.cell_count = 2; bad[0].child_count = 1; what = "cell not reached"; b.cell_count = 3; break;
        }
        zs_status st = zs_cells_check(&b);
        ZT_CHECK(st == ZS_ERR_BSP, "%s: %s", what, zs_strerror(st));
    }
    /* deeper than ZS_CELLS_MAX_DEPTH: a chain of single children */
    static zs_cell chain[ZS_CELLS_MAX_DEPTH + 1];
    for (int k = 0; k <= ZS_CELLS_MAX_DEPTH; k++) {
        chain[k] = good[1];
        chain[k].first_child = (uint16_t)(k + 1);
        chain[k].child_count = k < ZS_CELLS_MAX_DEPTH ? 1 : 0;
        chain[k].first_object = 0;
        chain[k].object_count = 1;
    }
    chain[ZS_CELLS_MAX_DEPTH].first_child = 0;
    zs_cells deep = {chain, obj, ZS_CELLS_MAX_DEPTH + 1, 1};
    ZT_ST(zs_cells_check(&deep), ZS_ERR_BSP);
    ZT_ST(zs_cells_check(NULL), ZS_ERR_NULL);
    zt_ctx c;
    zt_ctx_init(&c, 32, 32, 64, 64, 64);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    memcpy(bad, good, sizeof good);
    bad[0].first_child = 2;
    zs_cells b = {bad, obj, 3, 3};
    ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_draw_cells(&c.r, &b), ZS_ERR_BSP);
    ZT_CHECK(c.r.stats.tris_submitted == 0, "a bad scene submitted triangles");
    zs_bounds inv = {{1, 1, 1}, {0, 0, 0}};
    ZT_ST(zs_draw_bounded(&c.r, &cube, NULL, &inv), ZS_ERR_ARGUMENT);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_city),
        cmocka_unit_test(test_bad_cells),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stdout);
    return rc;
}
