/* SPDX-License-Identifier: MIT */
/*
 * Tests of the mesh converter (build/zspan-meshc).
 *
 *  - Round trip: tests/tools/data/known.obj and assimp's sphereWithHole.stl are
 *    converted at build time (mk/firmware.mk) and compiled in; the positions
 *    must equal the source ones (after the requested transform) within the
 *    quantisation error, the triangles must cover the same oriented area, and
 *    the core must accept the meshes. Face normals are checked by what they
 *    are, not by the converter's formula: unit length, perpendicular to the
 *    stored triangle's edges, on the side the core treats as the front (it
 *    culls the triangle from the other side), and for the quad of known.obj
 *    equal to its plane's normal written down from the file.
 *  - Errors: every file of assimp's invalid/ folder, a missing file, an
 *    oversized model, bad options: a clear "error:" message and a non-zero
 *    exit status (never a crash).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "t_known.h"
#include "t_known_nc.h"
#include "t_sphere.h"
#include "run_cmd.h"


/* The source of known.obj (faces as written, 1-based). */
static const double known_v[7][3] = {
    {0.125, -1.5, 1.5625}, {3.75, -1.25, -0.1875}, {3.5, 2.0, 0.75},  {-0.5, 1.875, 2.71875},
    {-2.25, 0.3333, 0.1},  {4.0, 0.0, 3.0},        {0.125, -1.5, 1.5625},
};
static const int known_faces[3][4] = {{1, 2, 3, 4}, {7, 4, 5, 0}, {2, 6, 3, 0}};

/* ---- helpers ----------------------------------------------------------- */


static double model_coord(const zs_mesh *m, unsigned v, int axis)
{
    return (double)m->positions[3 * v + (unsigned)axis] * (double)m->scale / 65536.0;
}

static void cross3(const double a[3], const double b[3], const double c[3], double n[3])
{
    double e1[3], e2[3];
    int r;
    for (r = 0; r < 3; r++) {
        e1[r] = b[r] - a[r];
        e2[r] = c[r] - a[r];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* Every output vertex must be within the quantisation error of some source
 * vertex transformed by (p - shift) * k; returns the largest error seen. */
static double check_positions(const zs_mesh *m, const double (*src)[3], size_t nsrc,
                              const double shift[3], double k)
{
    double tol = (double)m->scale / 131072.0 + 1e-9, worst = 0;
    unsigned v;
    for (v = 0; v < m->vertex_count; v++) {
        double best = 1e30;
        size_t i;
        for (i = 0; i < nsrc; i++) {
            double d = 0;
            int r;
            for (r = 0; r < 3; r++) {
                double e = fabs(model_coord(m, v, r) - (src[i][r] - shift[r]) * k);
                if (e > d)
                    d = e;
            }
            if (d < best)
                best = d;
        }
        if (best > tol)
            fail_msg("vertex %u is %g from every source vertex (tolerance %g)", v, best, tol);
        if (best > worst)
            worst = best;
    }
    return worst;
}

/* Sum of the triangles' area vectors (orientation included). */
static void area_vector(const zs_mesh *m, double out[3])
{
    unsigned t;
    out[0] = out[1] = out[2] = 0;
    for (t = 0; t < m->triangle_count; t++) {
        double p[3][3], n[3];
        int c, r;
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++)
                p[c][r] = model_coord(m, m->indices[3 * t + (unsigned)c], r);
        cross3(p[0], p[1], p[2], n);
        for (r = 0; r < 3; r++)
            out[r] += n[r] / 2;
    }
}

static void known_area_vector(const double shift[3], double k, double out[3])
{
    int f, r;
    out[0] = out[1] = out[2] = 0;
    for (f = 0; f < 3; f++) {
        int nv = known_faces[f][3] ? 4 : 3, j;
        for (j = 1; j + 1 < nv; j++) { /* planar faces: any fan gives the same vector */
            double p[3][3], n[3];
            int c;
            int idx[3];
            idx[0] = known_faces[f][0] - 1;
            idx[1] = known_faces[f][j] - 1;
            idx[2] = known_faces[f][j + 1] - 1;
            for (c = 0; c < 3; c++)
                for (r = 0; r < 3; r++)
                    p[c][r] = (known_v[idx[c]][r] - shift[r]) * k;
            cross3(p[0], p[1], p[2], n);
            for (r = 0; r < 3; r++)
                out[r] += n[r] / 2;
        }
    }
}

/* 1 if the three corners of triangle t, mapped back to known.obj's
 * coordinates (p / k + shift), lie on the quad's plane z = 2 - x/2 + y/4. */
static int on_known_plane(const zs_mesh *m, unsigned t, const double shift[3], double k)
{
    int c;
    for (c = 0; c < 3; c++) {
        unsigned v = m->indices[3 * t + (unsigned)c];
        double x = model_coord(m, v, 0) / k + shift[0], y = model_coord(m, v, 1) / k + shift[1],
               z = model_coord(m, v, 2) / k + shift[2];
        if (fabs(z - (2 - x / 2 + y / 4)) > 1e-3)
            return 0;
    }
    return 1;
}

/* The converter's face normal of triangle t, checked by what a face normal
 * is rather than by computing it again:
 *  - unit length in Q1.14 within the rounding of its components;
 *  - perpendicular to the three edges of the stored (quantised) triangle,
 *    within what quantising the positions and the normal can tilt them;
 *  - pointing to the side the triangle's front faces: the core itself (which
 *    culls by the counter-clockwise winding, include/zspan/zspan.h) draws the
 *    triangle for a camera on that side and culls it for one on the other. */
static void check_face_normal(const zs_mesh *m, unsigned t)
{
    static uint8_t arena[ZS_ARENA_BYTES(32, 32, 8, 16, 8)];
    const int16_t *nq = &m->face_normals[3 * t];
    double n[3], p[3][3], len = 0, centre[3] = {0, 0, 0}, size = 0;
    double q = (double)m->scale / 131072.0; /* position error, per axis */
    int c, r, side;
    for (r = 0; r < 3; r++) {
        n[r] = nq[r] / 16384.0;
        len += n[r] * n[r];
    }
    len = sqrt(len);
    if (fabs(len * 16384.0 - 16384.0) > 1.0)
        fail_msg("triangle %u: normal %d %d %d has length %.2f in Q1.14, not 16384", t, nq[0],
                 nq[1], nq[2], len * 16384.0);
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) {
            p[c][r] = model_coord(m, m->indices[3 * t + (unsigned)c], r);
            centre[r] += p[c][r] / 3;
        }
    for (c = 0; c < 3; c++) {
        const double *a = p[c], *b = p[(c + 1) % 3];
        double e[3], el = 0, d = 0, tol;
        for (r = 0; r < 3; r++) {
            e[r] = b[r] - a[r];
            el += e[r] * e[r];
        }
        el = sqrt(el);
        if (el > size)
            size = el;
        for (r = 0; r < 3; r++)
            d += e[r] / el * n[r] / len;
        tol = 2 * sqrt(3.0) * q / el + 1e-4;
        if (fabs(d) > tol)
            fail_msg("triangle %u: normal %d %d %d is not perpendicular to edge %d (cos %.2g, "
                     "tolerance %.2g)",
                     t, nq[0], nq[1], nq[2], c, d, tol);
    }
    for (side = 1; side >= -1; side -= 2) {
        zs_renderer rd;
        zs_config cfg = zs_config_default(32, 32, 8, 16, 8);
        zs_camera cam;
        zs_mesh one = *m;
        int up = 0;
        zs_vec3 eye, target;
        const zs_stats *st;
        /* up: the axis least along the normal */
        for (r = 1; r < 3; r++)
            if (fabs(n[r]) < fabs(n[up]))
                up = r;
        eye = zs_vec3_make((zs_fixed)lround((centre[0] + side * size * n[0] / len) * 65536.0),
                           (zs_fixed)lround((centre[1] + side * size * n[1] / len) * 65536.0),
                           (zs_fixed)lround((centre[2] + side * size * n[2] / len) * 65536.0));
        target = zs_vec3_make((zs_fixed)lround(centre[0] * 65536.0),
                              (zs_fixed)lround(centre[1] * 65536.0),
                              (zs_fixed)lround(centre[2] * 65536.0));
        one.indices = m->indices + 3 * t;
        one.triangle_count = 1;
        one.face_colors = NULL;
        one.face_normals = NULL;
        assert_int_equal(zs_init(&rd, arena, sizeof arena, &cfg), ZS_OK);
        assert_int_equal(zs_camera_look_at(&cam, eye, target,
                                           zs_vec3_make(up == 0 ? ZS_FX(1) : 0,
                                                        up == 1 ? ZS_FX(1) : 0,
                                                        up == 2 ? ZS_FX(1) : 0)),
                         ZS_OK);
        assert_int_equal(zs_camera_perspective(&cam, ZS_FX(90), ZS_FX(1) / 16,
                                               (zs_fixed)lround(size * 4 * 65536.0)),
                         ZS_OK);
        assert_int_equal(zs_frame_begin(&rd, &cam, ZS_MODE_SPAN), ZS_OK);
        assert_int_equal(zs_draw(&rd, &one, NULL), ZS_OK);
        st = zs_frame_stats(&rd);
        assert_int_equal(st->tris_submitted, 1);
        if (side > 0 && st->tris_culled != 0)
            fail_msg("triangle %u: culled for a camera on the side its normal %d %d %d points to",
                     t, nq[0], nq[1], nq[2]);
        if (side < 0 && st->tris_culled != 1)
            fail_msg("triangle %u: not culled for a camera behind its normal %d %d %d (stored %u, "
                     "rejected %u)",
                     t, nq[0], nq[1], nq[2], st->tris_stored, st->tris_rejected);
    }
}

/* ---- round trip ----------------------------------------------------------- */

static void test_round_trip_known(void **state)
{
    static const double zero[3] = {0, 0, 0};
    double a[3], b[3], worst;
    int r;
    (void)state;
    assert_int_equal(t_known.triangle_count, 4);  /* quad -> 2, plus 2 triangles */
    assert_int_equal(t_known.vertex_count, 6);    /* vertex 7 merged into vertex 1 */
    assert_int_equal(T_KNOWN_TRIANGLE_COUNT, 4);
    assert_int_equal(t_known.scale, T_KNOWN_SCALE);
    /* smallest scale keeping |4.0| within int16: ceil(4 * 65536 / 32767) */
    assert_int_equal(t_known.scale, 9);
    assert_null(t_known.face_colors);
    assert_null(t_known.vertex_colors);
    assert_null(t_known.face_normals);
    assert_null(t_known.vertex_normals);
    worst = check_positions(&t_known, known_v, 7, zero, 1.0);
    print_message("known.obj: worst position error %.3g (bound %.3g)\n", worst,
                  9.0 / 131072.0);
    area_vector(&t_known, a);
    known_area_vector(zero, 1.0, b);
    for (r = 0; r < 3; r++)
        assert_true(fabs(a[r] - b[r]) < 1e-3);
    {
        unsigned i;
        for (i = 0; i < 3u * t_known.triangle_count; i++)
            assert_true(t_known.indices[i] < t_known.vertex_count);
    }
}

static void test_round_trip_options(void **state)
{
    /* --center --scale 100 --colors index --normals face */
    const double shift[3] = {(-2.25 + 4.0) / 2, (-1.5 + 2.0) / 2, (-0.1875 + 3.0) / 2};
    double a[3], b[3];
    unsigned t;
    int r, on_plane = 0;
    (void)state;
    assert_int_equal(t_known_nc.triangle_count, 4);
    assert_int_equal(t_known_nc.vertex_count, 6);
    check_positions(&t_known_nc, known_v, 7, shift, 100.0);
    area_vector(&t_known_nc, a);
    known_area_vector(shift, 100.0, b);
    for (r = 0; r < 3; r++)
        assert_true(fabs(a[r] - b[r]) < 0.05 * (fabs(b[r]) + 1));
    assert_non_null(t_known_nc.face_colors);
    assert_non_null(t_known_nc.face_normals);
    assert_null(t_known_nc.vertex_normals);
    for (t = 0; t < t_known_nc.triangle_count; t++) {
        assert_true(t_known_nc.face_colors[t] <= 0xFFFFFFu);
        assert_true(t_known_nc.face_colors[t] != 0);
        check_face_normal(&t_known_nc, t);
        if (on_known_plane(&t_known_nc, t, shift, 100.0)) {
            /* the quad's plane z = 2 - x/2 + y/4 (known.obj) has the normal
             * (2, -1, 4) / sqrt(21), up to the sign; seen from +z the quad's
             * corners 1 2 3 4 run counter-clockwise in the xy plane (right,
             * up, left), and that normal has +z: it is the front one */
            const int16_t *n = &t_known_nc.face_normals[3 * t];
            const double want[3] = {2 / sqrt(21.0), -1 / sqrt(21.0), 4 / sqrt(21.0)};
            for (r = 0; r < 3; r++)
                if (fabs(n[r] - 16384.0 * want[r]) > 1.0)
                    fail_msg("triangle %u of the quad: normal %d %d %d, expected %.1f %.1f %.1f", t,
                             n[0], n[1], n[2], 16384 * want[0], 16384 * want[1], 16384 * want[2]);
            on_plane++;
        }
    }
    assert_int_equal(on_plane, 2); /* the quad's two triangles */
}

static void test_round_trip_sphere(void **state)
{
    double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9}, maxd = 0;
    double tol = (double)t_sphere.scale / 131072.0 * 2;
    unsigned v;
    int r;
    (void)state;
    /* Debian's assimp test model: 285 triangles, 146 distinct positions. */
    assert_int_equal(t_sphere.triangle_count, 285);
    assert_int_equal(t_sphere.vertex_count, 146);
    assert_non_null(t_sphere.vertex_normals);
    for (v = 0; v < t_sphere.vertex_count; v++) {
        double p[3], d = 0, dot = 0, nl = 0;
        for (r = 0; r < 3; r++) {
            p[r] = model_coord(&t_sphere, v, r);
            if (p[r] < lo[r])
                lo[r] = p[r];
            if (p[r] > hi[r])
                hi[r] = p[r];
            d += p[r] * p[r];
        }
        d = sqrt(d);
        if (d > maxd)
            maxd = d;
        for (r = 0; r < 3; r++) {
            double n = t_sphere.vertex_normals[3 * v + (unsigned)r] / 16384.0;
            dot += n * p[r] / d;
            nl += n * n;
        }
        assert_true(fabs(sqrt(nl) - 1.0) < 2e-4);
        assert_true(dot > 0.9); /* smooth normals of a sphere point outward */
    }
    /* --normalize: bounding-box centre at the origin, largest distance 1. */
    for (r = 0; r < 3; r++)
        assert_true(fabs((lo[r] + hi[r]) / 2) < tol);
    assert_true(fabs(maxd - 1.0) < tol * 2);
}

static void test_core_accepts_meshes(void **state)
{
    static uint8_t arena[ZS_ARENA_BYTES(64, 64, 400, 400, 256)];
    const zs_mesh *meshes[3];
    zs_renderer r;
    zs_config cfg = zs_config_default(64, 64, 400, 400, 256);
    zs_camera cam;
    zs_mat34 id = zs_mat34_identity();
    int i;
    (void)state;
    meshes[0] = &t_known;
    meshes[1] = &t_known_nc;
    meshes[2] = &t_sphere;
    memset(&cam, 0, sizeof cam);
    assert_int_equal(zs_init(&r, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_camera_set_view(&cam, &id), ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(1000)),
                     ZS_OK);
    for (i = 0; i < 3; i++) {
        zs_mat34 mv = zs_mat34_translate(0, 0, i == 1 ? ZS_FX(-900) : ZS_FX(-10));
        uint8_t line[64 * 2];
        int y;
        assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
        assert_int_equal(zs_draw(&r, meshes[i], &mv), ZS_OK);
        for (y = 0; y < 64; y++)
            assert_int_equal(zs_render_rows(&r, y, 1, line, sizeof line), ZS_OK);
        assert_int_equal(zs_frame_stats(&r)->tris_submitted, meshes[i]->triangle_count);
    }
}

/* ---- errors ----------------------------------------------------------------- */

static void expect_error(const char *what, const run_result *res, int code, const char *needle)
{
    if (!res->exited)
        fail_msg("%s: the converter did not exit normally:\n%s", what, res->out);
    if (res->status == 0)
        fail_msg("%s: exit status 0, expected an error:\n%s", what, res->out);
    if (code && res->status != code)
        fail_msg("%s: exit status %d, expected %d:\n%s", what, res->status, code, res->out);
    if (!strstr(res->out, "error:"))
        fail_msg("%s: no 'error:' message:\n%s", what, res->out);
    if (needle && !strstr(res->out, needle))
        fail_msg("%s: message lacks '%s':\n%s", what, needle, res->out);
}

static void test_invalid_folder(void **state)
{
    DIR *d = opendir(ASSIMP_MODELS "/invalid");
    struct dirent *e;
    int files = 0;
    (void)state;
    if (!d)
        fail_msg("cannot open %s/invalid (install assimp-testmodels)", ASSIMP_MODELS);
    while ((e = readdir(d)) != NULL) {
        char path[1024];
        run_result res;
        if (e->d_name[0] == '.')
            continue;
        snprintf(path, sizeof path, "%s/invalid/%s", ASSIMP_MODELS, e->d_name);
        run(&res, "'%s' -o /tmp/zspan-meshc-invalid-out '%s'", MESHC, path);
        expect_error(path, &res, 0, path);
        assert_true(res.status == 3 || res.status == 4);
        print_message("%s: exit %d: %.*s\n", e->d_name, res.status,
                      (int)strcspn(res.out, "\n"), res.out);
        files++;
    }
    closedir(d);
    assert_true(files >= 15);
}

static void test_missing_and_usage(void **state)
{
    run_result res;
    (void)state;
    run(&res, "'%s' /nonexistent/model.obj", MESHC);
    expect_error("missing file", &res, 3, "cannot open");
    run(&res, "'%s'", MESHC);
    assert_true(res.exited && res.status == 2);
    run(&res, "'%s' --frobnicate '%s/known.obj'", MESHC, TOOLS_DATA);
    expect_error("unknown option", &res, 2, "--frobnicate");
    run(&res, "'%s' -n 9lives '%s/known.obj'", MESHC, TOOLS_DATA);
    expect_error("bad name", &res, 2, "not a C identifier");
    run(&res, "'%s' --colors plaid '%s/known.obj'", MESHC, TOOLS_DATA);
    expect_error("bad colour source", &res, 2, "plaid");
    run(&res, "'%s' --max-triangles 0 '%s/known.obj'", MESHC, TOOLS_DATA);
    expect_error("bad limit", &res, 2, "--max-triangles");
    run(&res, "'%s' -q -o /nonexistent/dir/out '%s/known.obj'", MESHC, TOOLS_DATA);
    expect_error("unwritable output", &res, 5, "cannot write");
    run(&res, "'%s' --info --lenient '%s/OBJ/testpoints.obj'", MESHC, ASSIMP_MODELS);
    expect_error("points only", &res, 3, "no triangles");
    run(&res, "'%s' --help", MESHC);
    assert_true(res.exited && res.status == 0 && strstr(res.out, "usage:"));
}

/* Bugs the fuzzer found: a long mesh name overflowed a declaration buffer,
 * and a malformed PLY made the importer loop forever. */
static void test_fuzz_regressions(void **state)
{
    run_result res;
    char dir[] = "/tmp/zspan-meshc-regress.XXXXXX";
    const char *name = "a_mesh_name_much_longer_than_the_sixty_four_bytes_the_old_buffer_had";
    (void)state;
    assert_non_null(mkdtemp(dir));
    run(&res, "'%s' -q -n %s -o '%s/long' '%s/OFF/Cube.off'", MESHC, name, dir, ASSIMP_MODELS);
    assert_true(res.exited && res.status == 0);
    run(&res, "grep -c '%s_positions' '%s/long.c'", name, dir);
    assert_true(res.exited && res.status == 0);
    run(&res, "ZSPAN_MESHC_IMPORT_SECONDS=2 '%s' -q -o '%s/hang' '%s/ply-hang.ply'", MESHC, dir,
        TOOLS_DATA);
    expect_error("importer hang", &res, 3, "did not finish in");
    run(&res, "rm -rf '%s'", dir);
}

static char tmpdir[64];

static int make_tmpdir(void **state)
{
    (void)state;
    strcpy(tmpdir, "/tmp/zspan-meshc-test.XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int remove_tmpdir(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

static void test_oversized(void **state)
{
    char grid[256], big[256], base[256], hdr[300];
    FILE *f;
    int i, j, n = 200;
    run_result res;
    (void)state;
    /* 200 x 200 quads = 80,000 triangles, 40,401 vertices: over 65,535. */
    snprintf(grid, sizeof grid, "%s/grid.obj", tmpdir);
    f = fopen(grid, "w");
    assert_non_null(f);
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            fprintf(f, "v %d %d %g\n", i, j, 0.001 * ((i * 7 + j * 13) % 17));
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            int a = j * (n + 1) + i + 1;
            fprintf(f, "f %d %d %d %d\n", a, a + 1, a + n + 2, a + n + 1);
        }
    fclose(f);
    run(&res, "'%s' --info '%s'", MESHC, grid);
    expect_error("80,000 triangles", &res, 4, "oversized model");
    /* With a decimation limit it converts. */
    snprintf(base, sizeof base, "%s/grid_small", tmpdir);
    run(&res, "'%s' -q --max-triangles 3000 -n grid_small -o '%s' '%s'", MESHC, base, grid);
    if (!res.exited || res.status != 0)
        fail_msg("decimation failed:\n%s", res.out);
    snprintf(hdr, sizeof hdr, "%s.h", base);
    f = fopen(hdr, "r");
    assert_non_null(f);
    {
        char line[256];
        long tris = -1;
        while (fgets(line, sizeof line, f))
            if (sscanf(line, "#define GRID_SMALL_TRIANGLE_COUNT %ldu", &tris) == 1)
                break;
        fclose(f);
        assert_true(tris > 100 && tris <= 3000);
    }
    /* Coordinates beyond the core's +-32767 model units. */
    snprintf(big, sizeof big, "%s/big.obj", tmpdir);
    f = fopen(big, "w");
    assert_non_null(f);
    fprintf(f, "v 0 0 0\nv 100000 0 0\nv 0 100000 0\nf 1 2 3\n");
    fclose(f);
    run(&res, "'%s' --info '%s'", MESHC, big);
    expect_error("huge coordinates", &res, 4, "oversized coordinates");
    run(&res, "'%s' --info --normalize '%s'", MESHC, big);
    assert_true(res.exited && res.status == 0);
}

int main(void)
{
    const struct CMUnitTest round_trip[] = {
        cmocka_unit_test(test_round_trip_known),
        cmocka_unit_test(test_round_trip_options),
        cmocka_unit_test(test_round_trip_sphere),
        cmocka_unit_test(test_core_accepts_meshes),
    };
    const struct CMUnitTest errors[] = {
        cmocka_unit_test(test_invalid_folder),
        cmocka_unit_test(test_missing_and_usage),
        cmocka_unit_test(test_fuzz_regressions),
        cmocka_unit_test(test_oversized),
    };
    int fails = cmocka_run_group_tests_name("meshc_round_trip", round_trip, NULL, NULL);
    fails += cmocka_run_group_tests_name("meshc_errors", errors, make_tmpdir, remove_tmpdir);
    return fails ? 1 : 0;
}
