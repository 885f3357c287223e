/* SPDX-License-Identifier: MIT */
/*
 * bench_cells: the scene cells of zs_draw_cells (zspan/cull.h) built as a k-d
 * tree and as a uniform grid (app/zs_cells_build.c), measured on two static
 * scenes so that the default can be picked by measurement:
 *
 *  - city: 144 buildings on a 12 x 12 block grid with streets between and
 *    100 trees along the streets (244 objects, the layout of test_cull);
 *  - forest: 1,000 trees scattered at random over 400 x 400 units.
 *
 * Each structure is seen from 24 views per scene (two in three at eye
 * height in the scene, looking along it; one in three from above, looking
 * at the centre), 240 x 240. Per structure: cells, depth and host build
 * time (best of 200 builds); per frame (mean over the views): triangles and
 * vertices that never reach the transform, and the culling work the MCU
 * does: cells visited (each a box test of 8 corners) and object boxes
 * tested (zs_draw_bounded of each object of a visible leaf). The cells
 * visited are counted exactly: the core's own test of each cell's box (a
 * one-cell scene through zs_draw_cells) decides where the walk stops.
 * Output: a Markdown table on stdout.
 *
 * bench_cells --emit FILE.c writes the same scenes, views and structures as
 * const C arrays (and FILE.h) for bench/bench_cells_fw.c, which measures the
 * instructions of the culled frames on the MCU.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../app/zs_cells_build.h"
#include "zspan/cull.h"

#define W 240
#define H 240
#define NVIEWS 24
#define MAX_OBJ 1000

static const int16_t cube_pos[] = {-64, -64, -64, 64, -64, -64, -64, 64, -64, 64, 64, -64,
                                   -64, -64, 64,  64, -64, 64,  -64, 64, 64,  64, 64, 64};
static const uint16_t cube_idx[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                    2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
static const int16_t tree_pos[] = {0, 128, 0, -40, 20, -40, 40, 20, -40, 40, 20, 40, -40, 20, 40,
                                   -8, 0, -8, 8, 0, -8, 8, 20, 8, -8, 20, 8};
static const uint16_t tree_idx[] = {0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4, 1, 2, 3, 1, 3, 4,
                                    5, 6, 7, 5, 7, 8};

typedef struct scene {
    const char *name;
    int n;
    double extent; /* half the side of the ground */
    zs_mesh cube, tree;
    zs_mat34 model[MAX_OBJ];
    zs_scene_object obj[MAX_OBJ];
    double lo[3 * MAX_OBJ], hi[3 * MAX_OBJ];
} scene;

static unsigned long lcg = 20261202u;
static double uniform(double lo, double hi)
{
    lcg = (lcg * 1103515245u + 12345u) & 0xFFFFFFFFu;
    return lo + (hi - lo) * (double)(lcg >> 8) / 16777216.0;
}

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

static zs_fixed fx(double v)
{
    return (zs_fixed)lrint(v * 65536.0);
}

/* Object k: mesh m scaled by (sx, sy, sz) with its base centre at (x, 0, z);
 * the meshes span [-1, 1] (cube: its centre raised by sy) or [0, 2] up. */
static void place(scene *s, int k, const zs_mesh *m, double x, double z, double sx, double sy,
                  double sz, int cube)
{
    double y = cube ? sy : 0;
    zs_mat34 mm = {{{fx(sx), 0, 0, fx(x)}, {0, fx(sy), 0, fx(y)}, {0, 0, fx(sz), fx(z)}}};
    s->model[k] = mm;
    s->obj[k].mesh = m;
    s->obj[k].model = &s->model[k];
    zs_mesh_bounds(m, &s->obj[k].bounds);
    /* the world box from the mesh box (positions / 64 units) */
    s->lo[3 * k] = x + sx * s->obj[k].bounds.lo[0] / 64.0;
    s->hi[3 * k] = x + sx * s->obj[k].bounds.hi[0] / 64.0;
    s->lo[3 * k + 1] = y + sy * s->obj[k].bounds.lo[1] / 64.0;
    s->hi[3 * k + 1] = y + sy * s->obj[k].bounds.hi[1] / 64.0;
    s->lo[3 * k + 2] = z + sz * s->obj[k].bounds.lo[2] / 64.0;
    s->hi[3 * k + 2] = z + sz * s->obj[k].bounds.hi[2] / 64.0;
}

static void build_city(scene *s)
{
    s->name = "city";
    s->n = 244;
    s->extent = 120;
    s->cube = make_mesh(cube_pos, 8, cube_idx, 12, ZS_RGB(180, 170, 160));
    s->tree = make_mesh(tree_pos, 9, tree_idx, 8, ZS_RGB(40, 160, 60));
    for (int k = 0; k < 144; k++)
        place(s, k, &s->cube, (k % 12 - 5.5) * 20, (k / 12 - 5.5) * 20, uniform(4, 7),
              uniform(4, 30), uniform(4, 7), 1);
    for (int t = 0; t < 100; t++)
        place(s, 144 + t, &s->tree, (t % 10 - 4.5) * 20 + 10 + uniform(-1, 1),
              (t / 10 - 4.5) * 20 + uniform(-6, 6), 2, 2, 2, 0);
}

static void build_forest(scene *s)
{
    s->name = "forest";
    s->n = 1000;
    s->extent = 200;
    s->cube = make_mesh(cube_pos, 8, cube_idx, 12, ZS_RGB(180, 170, 160));
    s->tree = make_mesh(tree_pos, 9, tree_idx, 8, ZS_RGB(40, 160, 60));
    for (int k = 0; k < s->n; k++) {
        double h = uniform(1.5, 3);
        place(s, k, &s->tree, uniform(-200, 200), uniform(-200, 200), h, h, h, 0);
    }
}

/* View v of scene s: eye and target (world units). The positions inside the
 * scene come from the generator in a fixed order: call for v = 0, 1, ... */
static void view_points(const scene *s, int v, double e[3], double t[3])
{
    double a = 2 * 3.14159265358979 * v / NVIEWS;
    if (v % 3 != 2) { /* in the scene at eye height, looking along it */
        e[0] = uniform(-0.4, 0.4) * s->extent;
        e[2] = uniform(-0.4, 0.4) * s->extent;
        e[1] = 1.7;
        t[0] = e[0] + cos(a);
        t[1] = e[1];
        t[2] = e[2] + sin(a);
    } else { /* from above and outside, at the centre */
        e[0] = 1.25 * s->extent * cos(a);
        e[2] = 1.25 * s->extent * sin(a);
        e[1] = 0.5 * s->extent;
        t[0] = t[1] = t[2] = 0;
    }
}

static void view(const double e[3], const double t[3], zs_camera *cam)
{
    zs_camera_look_at(cam, zs_vec3_make(fx(e[0]), fx(e[1]), fx(e[2])),
                      zs_vec3_make(fx(t[0]), fx(t[1]), fx(t[2])), zs_vec3_make(0, ZS_FX(1), 0));
    zs_camera_perspective(cam, ZS_FX(60), ZS_FX(1) / 4, ZS_FX(150));
}

typedef struct tally {
    double untrans_tris, untrans_verts, visited, objects_tested, tris, verts;
} tally;

/* Is cell c outside the frustum, by the core's own test (a one-cell scene)? */
static int cell_outside(zs_renderer *r, const zs_cell *c)
{
    zs_cell one = *c;
    zs_cells sc = {&one, NULL, 1, 0};
    uint32_t before = r->stats.cells_culled;
    one.first_child = one.child_count = 0;
    one.first_object = one.object_count = 0;
    if (zs_draw_cells(r, &sc) != ZS_OK)
        abort();
    return r->stats.cells_culled != before;
}

static void walk(zs_renderer *r, const zs_cells *sc, uint32_t i, tally *t)
{
    const zs_cell *c = &sc->cells[i];
    t->visited++;
    if (cell_outside(r, c))
        return;
    if (c->child_count == 0) {
        t->objects_tested += c->object_count;
        return;
    }
    for (uint32_t k = 0; k < c->child_count; k++)
        walk(r, sc, (uint32_t)c->first_child + k, t);
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void measure(zs_renderer *r, scene *s, int kind, int param, const zs_camera *cams)
{
    static zs_scene_object obj[MAX_OBJ];
    zs_cellsb_result res;
    double best = 1e300;
    for (int rep = 0; rep < 200; rep++) {
        double t0 = now();
        const char *err = zs_cellsb_build(s->lo, s->hi, (size_t)s->n, kind, param, &res);
        double t1 = now();
        if (err) {
            fprintf(stderr, "bench_cells: %s\n", err);
            exit(1);
        }
        best = t1 - t0 < best ? t1 - t0 : best;
        if (rep < 199)
            zs_cellsb_free(&res);
    }
    for (int k = 0; k < s->n; k++)
        obj[k] = s->obj[res.order[k]];
    zs_cells sc = {res.cells, obj, (uint16_t)res.cell_count, (uint16_t)s->n};
    if (zs_cells_check(&sc) != ZS_OK) {
        fprintf(stderr, "bench_cells: the builder's cells are refused\n");
        exit(1);
    }
    tally t = {0};
    for (int v = 0; v < NVIEWS; v++) {
        if (zs_frame_begin(r, &cams[v], ZS_MODE_SPAN) != ZS_OK || zs_draw_cells(r, &sc) != ZS_OK) {
            fprintf(stderr, "bench_cells: frame failed\n");
            exit(1);
        }
        t.untrans_tris += r->stats.tris_untransformed;
        t.untrans_verts += r->stats.verts_untransformed;
        t.tris += r->stats.tris_submitted;
        for (int k = 0; k < s->n; k++)
            t.verts += obj[k].mesh->vertex_count;
        zs_frame_begin(r, &cams[v], ZS_MODE_SPAN);
        walk(r, &sc, 0, &t);
    }
    char what[32];
    snprintf(what, sizeof what, kind == ZS_CELLS_KD ? "k-d, leaf %d" : "grid %dx%d", param,
             param);
    printf("| %s | %s | %zu | %d | %.1f | %.1f%% | %.1f%% | %.1f | %.1f | %.1f |\n", s->name,
           what, res.cell_count, res.depth, best * 1e6, 100 * t.untrans_tris / t.tris,
           100 * t.untrans_verts / t.verts, t.visited / NVIEWS, t.objects_tested / NVIEWS,
           (t.visited + t.objects_tested) / NVIEWS);
    zs_cellsb_free(&res);
}


/* ---- the scenes as C for the firmware (--emit) ---- */

static void emit_fixed3(FILE *f, const double v[3])
{
    fprintf(f, "{%ld, %ld, %ld}", (long)fx(v[0]), (long)fx(v[1]), (long)fx(v[2]));
}

static void emit_objects(FILE *f, const scene *s, const char *id, const uint32_t *order)
{
    fprintf(f, "static const zs_scene_object %s_obj[%d] = {\n", id, s->n);
    for (int k = 0; k < s->n; k++) {
        int o = order ? (int)order[k] : k;
        const zs_bounds *b = &s->obj[o].bounds;
        fprintf(f, "    {&%s, &%s_model[%d], {{%d, %d, %d}, {%d, %d, %d}}},\n",
                s->obj[o].mesh == &s->cube ? "cb_cube" : "cb_tree", s->name, o, b->lo[0],
                b->lo[1], b->lo[2], b->hi[0], b->hi[1], b->hi[2]);
    }
    fprintf(f, "};\n");
}

static void emit_cells(FILE *f, const char *id, const zs_cell *c, size_t n)
{
    fprintf(f, "static const zs_cell %s_cells[%zu] = {\n", id, n);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "    {{%ld, %ld, %ld}, {%ld, %ld, %ld}, %u, %u, %u, %u},\n", (long)c[i].lo[0],
                (long)c[i].lo[1], (long)c[i].lo[2], (long)c[i].hi[0], (long)c[i].hi[1],
                (long)c[i].hi[2], c[i].first_child, c[i].child_count, c[i].first_object,
                c[i].object_count);
    fprintf(f, "};\n");
}

static int emit(const char *path, scene *const *scenes, int nscenes)
{
    static const struct {
        const char *id;
        int kind, param;
    } kinds[] = {{"none", -1, 0}, {"kd4", ZS_CELLS_KD, 4}, {"kd8", ZS_CELLS_KD, 8},
                 {"grid6", ZS_CELLS_GRID, 6}, {"grid8", ZS_CELLS_GRID, 8}};
    char hpath[1024], id[64];
    size_t len = strlen(path);
    FILE *f, *h;
    int nk = (int)(sizeof kinds / sizeof kinds[0]);
    if (len < 3 || len + 1 > sizeof hpath || strcmp(path + len - 2, ".c") != 0)
        return 1;
    memcpy(hpath, path, len + 1);
    hpath[len - 1] = 'h';
    f = fopen(path, "w");
    h = fopen(hpath, "w");
    if (!f || !h)
        return 1;
    fprintf(h, "/* SPDX-License-Identifier: MIT */\n/* Generated by bench_cells --emit. */\n"
               "#ifndef CELLS_DATA_H\n#define CELLS_DATA_H\n#include \"zspan/cull.h\"\n"
               "typedef struct cb_structure {\n    const char *scene, *name;\n"
               "    zs_cells cells; /* kind \"plain\": objects drawn with zs_draw */\n"
               "} cb_structure;\n"
               "typedef struct cb_view {\n    const char *scene;\n    zs_fixed eye[3], target[3];\n"
               "} cb_view;\n"
               "extern const cb_structure cb_structures[];\nextern const int cb_structure_count;\n"
               "extern const cb_view cb_views[];\nextern const int cb_view_count;\n#endif\n");
    fprintf(f, "/* SPDX-License-Identifier: MIT */\n/* Generated by bench_cells --emit. */\n"
               "#include \"cells_data.h\"\n\n");
    fprintf(f, "static const int16_t cube_pos[24] = {");
    for (int k = 0; k < 24; k++)
        fprintf(f, "%d%s", cube_pos[k], k < 23 ? ", " : "};\n");
    fprintf(f, "static const uint16_t cube_idx[36] = {");
    for (int k = 0; k < 36; k++)
        fprintf(f, "%u%s", cube_idx[k], k < 35 ? ", " : "};\n");
    fprintf(f, "static const int16_t tree_pos[27] = {");
    for (int k = 0; k < 27; k++)
        fprintf(f, "%d%s", tree_pos[k], k < 26 ? ", " : "};\n");
    fprintf(f, "static const uint16_t tree_idx[24] = {");
    for (int k = 0; k < 24; k++)
        fprintf(f, "%u%s", tree_idx[k], k < 23 ? ", " : "};\n");
    fprintf(f, "static const zs_mesh cb_cube = {.positions = cube_pos, .indices = cube_idx, "
               ".scale = %ld, .vertex_count = 8, .triangle_count = 12, .color = 0x%06lx};\n",
            (long)(ZS_FX(1) / 64), (unsigned long)ZS_RGB(180, 170, 160));
    fprintf(f, "static const zs_mesh cb_tree = {.positions = tree_pos, .indices = tree_idx, "
               ".scale = %ld, .vertex_count = 9, .triangle_count = 8, .color = 0x%06lx};\n",
            (long)(ZS_FX(1) / 64), (unsigned long)ZS_RGB(40, 160, 60));
    for (int si = 0; si < nscenes; si++) {
        const scene *s = scenes[si];
        fprintf(f, "static const zs_mat34 %s_model[%d] = {\n", s->name, s->n);
        for (int k = 0; k < s->n; k++) {
            const zs_mat34 *m = &s->model[k];
            fprintf(f, "    {{");
            for (int r = 0; r < 3; r++)
                fprintf(f, "{%ld, %ld, %ld, %ld}%s", (long)m->m[r][0], (long)m->m[r][1],
                        (long)m->m[r][2], (long)m->m[r][3], r < 2 ? ", " : "}},\n");
        }
        fprintf(f, "};\n");
        for (int kk = 0; kk < nk; kk++) {
            zs_cellsb_result res;
            snprintf(id, sizeof id, "%s_%s", s->name, kinds[kk].id);
            if (kinds[kk].kind < 0) { /* one leaf over every object: a box per object */
                emit_objects(f, s, id, NULL);
                zs_cell root;
                memset(&root, 0, sizeof root);
                root.object_count = (uint16_t)s->n;
                for (int j = 0; j < 3; j++) {
                    root.lo[j] = -2147483647;
                    root.hi[j] = 2147483647;
                }
                emit_cells(f, id, &root, 1);
                continue;
            }
            if (zs_cellsb_build(s->lo, s->hi, (size_t)s->n, kinds[kk].kind, kinds[kk].param,
                                &res) != NULL)
                return 1;
            emit_objects(f, s, id, res.order);
            emit_cells(f, id, res.cells, res.cell_count);
            zs_cellsb_free(&res);
        }
    }
    fprintf(f, "const cb_structure cb_structures[] = {\n");
    for (int si = 0; si < nscenes; si++) {
        fprintf(f, "    {\"%s\", \"plain\", {%s_none_cells, %s_none_obj, 1, %d}},\n",
                scenes[si]->name, scenes[si]->name, scenes[si]->name, scenes[si]->n);
        for (int kk = 0; kk < nk; kk++)
            fprintf(f, "    {\"%s\", \"%s\", {%s_%s_cells, %s_%s_obj, sizeof %s_%s_cells / "
                       "sizeof %s_%s_cells[0], %d}},\n",
                    scenes[si]->name, kinds[kk].id, scenes[si]->name, kinds[kk].id,
                    scenes[si]->name, kinds[kk].id, scenes[si]->name, kinds[kk].id,
                    scenes[si]->name, kinds[kk].id, scenes[si]->n);
    }
    fprintf(f, "};\nconst int cb_structure_count = %d;\n", nscenes * (nk + 1));
    fprintf(f, "const cb_view cb_views[] = {\n");
    for (int si = 0; si < nscenes; si++)
        for (int v = 0; v < NVIEWS; v++) {
            double e[3], t[3];
            view_points(scenes[si], v, e, t);
            fprintf(f, "    {\"%s\", ", scenes[si]->name);
            emit_fixed3(f, e);
            fprintf(f, ", ");
            emit_fixed3(f, t);
            fprintf(f, "},\n");
        }
    fprintf(f, "};\nconst int cb_view_count = %d;\n", nscenes * NVIEWS);
    return fclose(f) != 0 || fclose(h) != 0;
}

int main(int argc, char **argv)
{
    static scene city, forest;
    static uint8_t arena[ZS_ARENA_BYTES(W, H, 12000, 12000, 2000)];
    zs_renderer r;
    zs_config cfg = zs_config_default(W, H, 12000, 12000, 2000);
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK) {
        fprintf(stderr, "bench_cells: zs_init\n");
        return 1;
    }
    build_city(&city);
    build_forest(&forest);
    scene *scenes[2] = {&city, &forest};
    if (argc == 3 && !strcmp(argv[1], "--emit")) {
        if (emit(argv[2], scenes, 2) != 0) {
            fprintf(stderr, "bench_cells: cannot write %s\n", argv[2]);
            return 1;
        }
        return 0;
    }
    printf("| scene | structure | cells | depth | host build (us, best of 200) | triangles "
           "never transformed | vertices never transformed | cells visited / frame | object "
           "boxes tested / frame | box tests / frame |\n");
    printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < 2; k++) {
        scene *s = scenes[k];
        zs_camera cams[NVIEWS];
        for (int v = 0; v < NVIEWS; v++) {
            double e[3], t[3];
            view_points(s, v, e, t);
            view(e, t, &cams[v]);
        }
        static const int leaves[] = {1, 2, 4, 8, 16};
        static const int grids[] = {4, 6, 8};
        for (size_t j = 0; j < sizeof leaves / sizeof leaves[0]; j++)
            measure(&r, s, ZS_CELLS_KD, leaves[j], cams);
        for (size_t j = 0; j < sizeof grids / sizeof grids[0]; j++)
            measure(&r, s, ZS_CELLS_GRID, grids[j], cams);
        /* no cells: every object's own box (zs_draw_bounded) */
        double ut = 0, tt = 0;
        for (int v = 0; v < NVIEWS; v++) {
            zs_frame_begin(&r, &cams[v], ZS_MODE_SPAN);
            for (int o = 0; o < s->n; o++)
                zs_draw_bounded(&r, s->obj[o].mesh, s->obj[o].model, &s->obj[o].bounds);
            ut += r.stats.tris_untransformed;
            tt += r.stats.tris_submitted;
        }
        printf("| %s | none (a box per object) | 0 | 0 | 0 | %.1f%% | | 0 | %d | %d |\n",
               s->name, 100 * ut / tt, s->n, s->n);
    }
    return 0;
}
