/* SPDX-License-Identifier: MIT */
/*
 * test_sim: the programs as a new user meets them (issue 12), run as
 * processes: build/zspan-sim, build/zspan-meshc and, when built, the Linux
 * and MCP2210 programs.
 *
 *  - licence and version: LICENSE, CHANGELOG.md and the header agree on the
 *    version; every program prints it with --version; SPDX lines;
 *  - --help after every subcommand;
 *  - a runaway import (tests/tools/data/ply-hang.ply) stops with a message
 *    in render and panel --mesh;
 *  - --seq takes exactly one integer conversion (a %s once crashed it);
 *  - zspan-meshc -n refuses C keywords and reserved names, and what it
 *    accepts compiles (the C compiler is the oracle);
 *  - output paths: no directory is made but the default out/, over-long
 *    paths and directories are refused with a message;
 *  - inputs: a directory and a file without triangles are errors in the
 *    simulator and the converter alike;
 *  - meshes as they come: --flip-winding, --two-sided, the normals warning,
 *    --up z, a model over 65535 triangles (the message's commands work),
 *    the converter's binary meshes (good and broken);
 *  - messages name the option the user typed; options are checked before
 *    files are read or devices opened.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <sys/stat.h>
#include <unistd.h>

#include "sim_run.h"
#include "zspan/zspan.h"

#ifndef TOP
#define TOP "."
#endif
#ifndef LINUX_PROG
#define LINUX_PROG "build/zspan-linux"
#endif
#ifndef MCP2210_PROG
#define MCP2210_PROG "build/zspan-mcp2210"
#endif

static char g_dir[64];

#define CONTAINS(res, text)                                                                    \
    do {                                                                                       \
        if (strstr((res)->out, (text)) == NULL)                                                \
            fail_msg("output lacks '%s':\n%s", (text), (res)->out);                            \
    } while (0)
#define LACKS(res, text)                                                                       \
    do {                                                                                       \
        if (strstr((res)->out, (text)) != NULL)                                                \
            fail_msg("output has '%s':\n%s", (text), (res)->out);                              \
    } while (0)
#define STATUS(res, want)                                                                      \
    do {                                                                                       \
        if (!(res)->exited || (res)->status != (want))                                         \
            fail_msg("status %d (exited normally: %d), want %d:\n%s", (res)->status,           \
                     (res)->exited, (want), (res)->out);                                       \
    } while (0)

static int exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    if (buf != NULL) {
        size_t got = fread(buf, 1, (size_t)n, f);
        buf[got] = 0;
    }
    fclose(f);
    return buf;
}

/* ---- licence and version ----------------------------------------------- */

static void test_version(void **state)
{
    char want[64], line[128], *text;
    run_result r;
    (void)state;
    snprintf(want, sizeof want, "%d.%d.%d", ZSPAN_VERSION_MAJOR, ZSPAN_VERSION_MINOR,
             ZSPAN_VERSION_PATCH);
    assert_string_equal(want, ZSPAN_VERSION_STRING);

    run(&r, "'%s' --version", SIM);
    STATUS(&r, 0);
    snprintf(line, sizeof line, "zspan-sim %s\n", want);
    assert_string_equal(r.out, line);
    run(&r, "'%s' demo --version", SIM);
    STATUS(&r, 0);
    assert_string_equal(r.out, line);
    run(&r, "'%s' render --version", SIM);
    STATUS(&r, 0);
    assert_string_equal(r.out, line);
    run(&r, "'%s' panel --version", SIM);
    STATUS(&r, 0);
    snprintf(line, sizeof line, "zspan-sim panel %s\n", want);
    assert_string_equal(r.out, line);
    run(&r, "'%s' --version", MESHC);
    STATUS(&r, 0);
    snprintf(line, sizeof line, "zspan-meshc %s\n", want);
    assert_string_equal(r.out, line);
    if (exists(LINUX_PROG)) {
        run(&r, "'%s' --version", LINUX_PROG);
        STATUS(&r, 0);
        snprintf(line, sizeof line, "zspan-linux %s\n", want);
        assert_string_equal(r.out, line);
    } else {
        print_message("%s not built: its --version not checked\n", LINUX_PROG);
    }
    if (exists(MCP2210_PROG)) {
        run(&r, "'%s' --version", MCP2210_PROG);
        STATUS(&r, 0);
        snprintf(line, sizeof line, "zspan-mcp2210 %s\n", want);
        assert_string_equal(r.out, line);
    } else {
        print_message("%s not built: its --version not checked\n", MCP2210_PROG);
    }

    /* The changelog's newest entry is this version; the licence is MIT. */
    text = read_text(TOP "/CHANGELOG.md");
    assert_non_null(text);
    snprintf(line, sizeof line, "## [%s]", want);
    if (strstr(text, line) == NULL || strstr(text, "## [") != strstr(text, line))
        fail_msg("CHANGELOG.md: the first entry is not '%s'", line);
    free(text);
    text = read_text(TOP "/LICENSE");
    assert_non_null(text);
    assert_non_null(strstr(text, "MIT License"));
    assert_non_null(strstr(text, "Permission is hereby granted, free of charge"));
    free(text);
}

/* Every source and build file names its licence on its first line. */
static void test_spdx(void **state)
{
    run_result r;
    (void)state;
    run(&r,
        "cd '%s' && for f in $(find src include app host_sim tools drivers ports bench examples "
        "tests -name '*.[ch]' -o -name '*.ld') ; do head -1 \"$f\" | grep -qxF '/* SPDX-License-Identifier: MIT */' "
        "|| echo \"no SPDX line: $f\"; done; for f in Makefile .ci/run mk/*.mk $(find tests bench -name "
        "'*.sh'); do head -2 \"$f\" | grep -qxF '# SPDX-License-Identifier: MIT' || echo \"no "
        "SPDX line: $f\"; done",
        TOP);
    STATUS(&r, 0);
    if (r.out[0] != 0)
        fail_msg("%s", r.out);
}

/* ---- help ------------------------------------------------------------- */

static void test_help(void **state)
{
    static const char *const cmds[] = {"demo", "render", "panel"};
    run_result r;
    char want[64];
    size_t k;
    (void)state;
    for (k = 0; k < 3; k++) {
        snprintf(want, sizeof want, "usage: zspan-sim %s", cmds[k]);
        run(&r, "'%s' %s --help", SIM, cmds[k]);
        STATUS(&r, 0);
        if (strncmp(r.out, want, strlen(want)) != 0)
            fail_msg("'%s --help' printed:\n%s", cmds[k], r.out);
        run(&r, "'%s' %s -h", SIM, cmds[k]);
        STATUS(&r, 0);
        assert_int_equal(strncmp(r.out, want, strlen(want)), 0);
    }
    /* After other arguments too, before anything is loaded. */
    run(&r, "'%s' render /nonexistent.obj --fov 0 --help", SIM);
    STATUS(&r, 0);
    CONTAINS(&r, "usage: zspan-sim render");
    run(&r, "'%s' --help", SIM);
    STATUS(&r, 0);
    CONTAINS(&r, "zspan-sim COMMAND --help");
    run(&r, "'%s' --help", MESHC);
    STATUS(&r, 0);
    CONTAINS(&r, "usage: zspan-meshc");
    if (exists(LINUX_PROG)) {
        run(&r, "'%s' --help", LINUX_PROG);
        STATUS(&r, 0);
        CONTAINS(&r, "usage: zspan-linux");
    }
    if (exists(MCP2210_PROG)) {
        run(&r, "'%s' --help", MCP2210_PROG);
        STATUS(&r, 0);
        CONTAINS(&r, "usage: zspan-mcp2210");
    }
}

/* ---- crashes and hangs ------------------------------------------------- */

static void test_import_timeout(void **state)
{
    run_result r;
    (void)state;
    /* Before the fix this ran at 100% CPU until killed (status 124 here). */
    run(&r, "ZSPAN_IMPORT_SECONDS=2 '%s' render '%s/ply-hang.ply' --out '%s/h.png'", SIM,
        TOOLS_DATA, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "ply-hang.ply: the model importer did not finish in 2 s");
    run(&r, "ZSPAN_IMPORT_SECONDS=2 '%s' panel --mesh '%s/ply-hang.ply' --out '%s/h.png' --quiet",
        SIM, TOOLS_DATA, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "the model importer did not finish in 2 s");
    run(&r, "ZSPAN_IMPORT_SECONDS=2 '%s' -q -o '%s/hang' '%s/ply-hang.ply'", MESHC, g_dir,
        TOOLS_DATA);
    STATUS(&r, 3);
    CONTAINS(&r, "did not finish in 2 s");
}

static void test_seq_pattern(void **state)
{
    static const char *const bad[] = {
        "%s.png", "f_%d_%d.png", "f.png", "f_%n.png", "f_%ld.png", "f_%5$d.png", "f_%*d.png",
        "f_%.*d.png", "f_%#d.png", "f_%08x.png", "f_%123456d.png", "f_%", "f_%%.png",
    };
    char p0[300], p1[300];
    run_result r;
    size_t k;
    (void)state;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        /* Before the fix, "%s" was a format string with no argument: SIGSEGV. */
        run(&r, "'%s' panel --frames 2 --seq '%s/%s' --quiet", SIM, g_dir, bad[k]);
        STATUS(&r, 2);
        CONTAINS(&r, "--seq");
        CONTAINS(&r, "exactly one integer conversion");
    }
    run(&r, "'%s' panel --frames 2 --seq '%s/f_%%03d.png' --out '' --quiet", SIM, g_dir);
    STATUS(&r, 0);
    snprintf(p0, sizeof p0, "%s/f_000.png", g_dir);
    snprintf(p1, sizeof p1, "%s/f_001.png", g_dir);
    assert_true(exists(p0) && exists(p1));
    run(&r, "'%s' panel --frames 1 --seq '%s/p%%%%_%%u.png' --out '' --quiet", SIM, g_dir);
    STATUS(&r, 0);
    snprintf(p0, sizeof p0, "%s/p%%_0.png", g_dir);
    assert_true(exists(p0));
}

/* ---- zspan-meshc -n ---------------------------------------------------- */

static void test_meshc_names(void **state)
{
    /* C89/C99 keywords: the compiler refuses each as an identifier. */
    static const char *const keywords[] = {"int", "char", "for", "while", "static", "return",
                                           "struct", "union", "inline", "restrict", "sizeof",
                                           "double", "signed", "goto", "void", "typedef"};
    static const char *const reserved[] = {"_mesh", "_Bool", "__x", "bool", "class", "new",
                                           "printf", "size_t", "mesh_t", "zs_mesh", "ZS_X",
                                           "strip", "memo", "isle", "tone", "EDOM", "SIGX",
                                           "int8_t", "INT8_MAX", "main", "NULL", "1abc", "a-b"};
    static const char *const good[] = {"mesh_int", "integer", "my_model", "Mesh2", "bunny",
                                       "st", "i", "Int"};
    run_result r;
    size_t k;
    (void)state;
    for (k = 0; k < sizeof keywords / sizeof keywords[0]; k++) {
        run(&r, "printf 'int %s = 1;\\n' | cc -std=c99 -x c -fsyntax-only - ", keywords[k]);
        if (r.status == 0)
            fail_msg("the compiler takes '%s' as an identifier: not a keyword", keywords[k]);
        run(&r, "'%s' -q -n %s -o '%s/kw' '%s/known.obj'", MESHC, keywords[k], g_dir, TOOLS_DATA);
        STATUS(&r, 2);
        CONTAINS(&r, "is a C keyword");
    }
    for (k = 0; k < sizeof reserved / sizeof reserved[0]; k++) {
        run(&r, "'%s' -q -n '%s' -o '%s/rs' '%s/known.obj'", MESHC, reserved[k], g_dir,
            TOOLS_DATA);
        STATUS(&r, 2);
        CONTAINS(&r, "--name");
    }
    for (k = 0; k < sizeof good / sizeof good[0]; k++) {
        run(&r, "'%s' -q -n %s -o '%s/%s' '%s/known.obj' && cc -std=c99 -Wall -Wextra -Werror "
                "-pedantic -I'%s/include' -c '%s/%s.c' -o '%s/%s.o'",
            MESHC, good[k], g_dir, good[k], TOOLS_DATA, TOP, g_dir, good[k], g_dir, good[k]);
        STATUS(&r, 0);
    }
    /* A name taken from the file: int.obj would give the keyword int. */
    run(&r, "cp '%s/known.obj' '%s/int.obj' && cd '%s' && '%s' -q int.obj && grep -c "
            "'^const zs_mesh mesh_int = ' mesh_int.c && cc -std=c99 -Wall -Werror -I'%s/include' -c "
            "mesh_int.c",
        TOOLS_DATA, g_dir, g_dir, MESHC, TOP);
    STATUS(&r, 0);
}

/* ---- file handling ----------------------------------------------------- */

static void test_output_paths(void **state)
{
    char missing[300], longpath[5200], cmd[400];
    run_result r;
    (void)state;
    snprintf(missing, sizeof missing, "%s/no/such/dir", g_dir);
    /* Before the fix the directories were created silently. */
    run(&r, "'%s' render '%s/known.obj' --fit --out '%s/x.png'", SIM, TOOLS_DATA, missing);
    STATUS(&r, 2);
    CONTAINS(&r, "does not exist");
    assert_false(exists(missing));
    run(&r, "'%s' demo --out '%s/x.png'", SIM, missing);
    STATUS(&r, 2);
    CONTAINS(&r, "--out");
    run(&r, "'%s' panel --out '%s/x.png' --quiet", SIM, missing);
    STATUS(&r, 2);
    run(&r, "'%s' panel --seq '%s/f_%%d.png' --quiet", SIM, missing);
    STATUS(&r, 2);
    CONTAINS(&r, "--seq");
    run(&r, "'%s' render '%s/known.obj' --fit --dump-tris '%s/t.txt' --out '%s/y.png'", SIM,
        TOOLS_DATA, missing, g_dir);
    STATUS(&r, 2);
    CONTAINS(&r, "--dump-tris");
    assert_false(exists(missing));
    snprintf(cmd, sizeof cmd, "%s/no", g_dir);
    assert_false(exists(cmd));

    /* Over-long: said, not failed silently. */
    memset(longpath, 'a', 5000);
    longpath[0] = '/';
    longpath[5000] = 0;
    run(&r, "'%s' render '%s/known.obj' --out '%s'", SIM, TOOLS_DATA, longpath);
    STATUS(&r, 2);
    CONTAINS(&r, "too long");
    run(&r, "'%s' demo --out '%s'", SIM, longpath);
    STATUS(&r, 2);
    CONTAINS(&r, "too long");
    run(&r, "'%s' panel --seq '%s%%d.png' --quiet", SIM, longpath);
    STATUS(&r, 2);
    CONTAINS(&r, "too long");
    /* A directory as the output. */
    run(&r, "'%s' render '%s/known.obj' --out '%s'", SIM, TOOLS_DATA, g_dir);
    STATUS(&r, 2);
    CONTAINS(&r, "is a directory");

    /* The default out/ is created, as documented. */
    run(&r, "mkdir -p '%s/cwd' && cd '%s/cwd' && '%s' demo --no-compare && test -f out/demo.png",
        g_dir, g_dir, SIM);
    STATUS(&r, 0);
}

static void test_input_files(void **state)
{
    run_result r;
    (void)state;
    run(&r, "'%s' render '%s' --out '%s/d.png'", SIM, g_dir, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "is a directory");
    run(&r, "'%s' panel --mesh '%s' --out '' --quiet", SIM, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "is a directory");
    run(&r, "'%s' -q -o '%s/d' '%s'", MESHC, g_dir, g_dir);
    STATUS(&r, 3);
    CONTAINS(&r, "is a directory");
    /* No triangles: before, the simulator wrote an empty image and said 0. */
    run(&r, "'%s' render '%s/points_lines.obj' --out '%s/p.png'", SIM, TOOLS_DATA, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "has no triangles");
    run(&r, "'%s' -q -o '%s/p' '%s/points_lines.obj'", MESHC, g_dir, TOOLS_DATA);
    STATUS(&r, 3);
    CONTAINS(&r, "has no triangles");
    run(&r, "'%s' render '%s/does-not-exist.obj' --out '%s/p.png'", SIM, g_dir, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "cannot open");
}

/* ---- meshes as they come ----------------------------------------------- */

/* Renders as ids to g_dir/NAME.png and reads it back. */
static void render_ids(const char *args, const char *name, image *img)
{
    run_result r;
    char out[300];
    snprintf(out, sizeof out, "%s/%s.png", g_dir, name);
    run(&r, "'%s' render %s --shade ids --size 120x120 --out '%s' --quiet", SIM, args, out);
    STATUS(&r, 0);
    assert_int_equal(read_png(out, img), 0);
}

static void test_winding_options(void **state)
{
    char args[400];
    image plain, flip, two, two_z;
    int i;
    (void)state;
    snprintf(args, sizeof args, "'%s/cw_triangle.obj'", TOOLS_DATA);
    render_ids(args, "plain", &plain);
    assert_int_equal(covered(&plain), 0); /* a back face: culled */
    snprintf(args, sizeof args, "'%s/cw_triangle.obj' --flip-winding", TOOLS_DATA);
    render_ids(args, "flip", &flip);
    assert_true(covered(&flip) > 1000);
    snprintf(args, sizeof args, "'%s/cw_triangle.obj' --two-sided", TOOLS_DATA);
    render_ids(args, "two", &two);
    snprintf(args, sizeof args, "'%s/cw_triangle.obj' --two-sided --mode zline", TOOLS_DATA);
    render_ids(args, "two_z", &two_z);
    assert_true(same_image(&two, &two_z));
    /* The same pixels as the flipped triangle; the copy's tag is 2. */
    for (i = 0; i < 120 * 120; i++) {
        assert_int_equal(pixel(&two, i) != 0, pixel(&flip, i) != 0);
        assert_true(pixel(&two, i) == 0 || pixel(&two, i) == 2);
    }
    free_image(&plain);
    free_image(&flip);
    free_image(&two);
    free_image(&two_z);

    /* panel --mesh: the back face shows only with the options. */
    {
        static const char *const opts[] = {"", "--flip-winding", "--two-sided"};
        image pic[3];
        char out[300];
        run_result r;
        int k;
        for (k = 0; k < 3; k++) {
            snprintf(out, sizeof out, "%s/panel%d.png", g_dir, k);
            run(&r, "'%s' panel --mesh '%s/cw_triangle.obj' %s --shade flat --out '%s' --quiet",
                SIM, TOOLS_DATA, opts[k], out);
            STATUS(&r, 0);
            assert_int_equal(read_png(out, &pic[k]), 0);
        }
        assert_false(same_image(&pic[0], &pic[1]));
        assert_true(same_image(&pic[1], &pic[2]));
        for (k = 0; k < 3; k++)
            free_image(&pic[k]);
    }
}

static void test_normals_warning(void **state)
{
    run_result r;
    (void)state;
    run(&r, "'%s' render '%s/against_normals.obj' --shade gouraud --out '%s/n.png'", SIM,
        TOOLS_DATA, g_dir);
    STATUS(&r, 0);
    CONTAINS(&r, "warning:");
    CONTAINS(&r, "normals point against the winding of 2 of 2 triangles");
    CONTAINS(&r, "--flip-winding");
    CONTAINS(&r, "--smooth");
    run(&r, "'%s' render '%s/against_normals.obj' --shade gouraud --quiet --out '%s/n.png'", SIM,
        TOOLS_DATA, g_dir);
    STATUS(&r, 0);
    LACKS(&r, "warning");
    run(&r, "'%s' render '%s/known.obj' --fit --shade gouraud --out '%s/n.png'", SIM, TOOLS_DATA,
        g_dir);
    STATUS(&r, 0);
    LACKS(&r, "warning");
}

/* Bounding box of the covered pixels: *w, *h. */
static void extent(const image *img, int *w, int *h)
{
    int x0 = img->w, x1 = -1, y0 = img->h, y1 = -1, x, y;
    for (y = 0; y < img->h; y++)
        for (x = 0; x < img->w; x++)
            if (pixel(img, y * img->w + x) != 0) {
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
            }
    *w = x1 - x0 + 1;
    *h = y1 - y0 + 1;
}

static void test_up_axis(void **state)
{
    char args[400];
    image lying, standing, standing2;
    int w, h;
    (void)state;
    /* A post along +z seen from +z: its end, a small square. */
    snprintf(args, sizeof args, "'%s/tall_z.obj' --fit", TOOLS_DATA);
    render_ids(args, "lying", &lying);
    extent(&lying, &w, &h);
    assert_true(w > 0 && abs(w - h) <= 2);
    snprintf(args, sizeof args, "'%s/tall_z.obj' --fit --up z", TOOLS_DATA);
    render_ids(args, "standing", &standing);
    extent(&standing, &w, &h);
    if (!(h > 3 * w))
        fail_msg("--up z: the post is %dx%d pixels, not standing", w, h);
    snprintf(args, sizeof args, "'%s/tall_z.obj' --fit --up-axis z", TOOLS_DATA);
    render_ids(args, "standing2", &standing2);
    assert_true(same_image(&standing, &standing2));
    free_image(&standing2);
    /* A file that says it is Z-up (Collada's up_axis) stands by default. */
    snprintf(args, sizeof args, "'%s/tall_z_up.dae' --fit", TOOLS_DATA);
    render_ids(args, "standing3", &standing2);
    extent(&standing2, &w, &h);
    if (!(h > 3 * w))
        fail_msg("Z_UP Collada: the post is %dx%d pixels, not standing", w, h);
    free_image(&standing2);
    /* The converter turns it too: its binary mesh stands as it is. */
    {
        run_result r;
        run(&r, "'%s' -q --up-axis z -o '%s/post' --format zsm '%s/tall_z.obj'", MESHC, g_dir,
            TOOLS_DATA);
        STATUS(&r, 0);
        snprintf(args, sizeof args, "'%s/post.zsm' --fit", g_dir);
        render_ids(args, "standing4", &standing2);
        extent(&standing2, &w, &h);
        if (!(h > 3 * w))
            fail_msg("zspan-meshc --up-axis z: the post is %dx%d pixels", w, h);
    }
    free_image(&lying);
    free_image(&standing);
    free_image(&standing2);
}

static void test_big_model(void **state)
{
    char path[300];
    run_result r;
    image img;
    FILE *f;
    int n = 190, i, j; /* 190 x 190 quads: 72200 triangles */
    (void)state;
    snprintf(path, sizeof path, "%s/grid.obj", g_dir);
    f = fopen(path, "w");
    assert_non_null(f);
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            fprintf(f, "v %d %d %d\n", i, j, (i * j) % 3);
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            int a = j * (n + 1) + i + 1;
            fprintf(f, "f %d %d %d %d\n", a, a + 1, a + n + 2, a + n + 1);
        }
    assert_int_equal(fclose(f), 0);
    run(&r, "'%s' render '%s' --fit --out '%s/g.png'", SIM, path, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "too many triangles (72200");
    CONTAINS(&r, "zspan-meshc --max-triangles 60000 --format zsm -o out/model");
    /* The commands it gives work (out/ -> g_dir). */
    run(&r, "'%s' -q --max-triangles 60000 --format zsm -o '%s/model' '%s'", MESHC, g_dir, path);
    STATUS(&r, 0);
    run(&r, "'%s' render '%s/model.zsm' --fit --shade ids --out '%s/g.png'", SIM, g_dir, g_dir);
    STATUS(&r, 0);
    snprintf(path, sizeof path, "%s/g.png", g_dir);
    assert_int_equal(read_png(path, &img), 0);
    assert_true(covered(&img) > 1000);
    free_image(&img);
}

static void test_binary_mesh(void **state)
{
    char a[300], b[300];
    run_result r;
    image s, z, orig;
    long n_zsm, n_orig;
    (void)state;
    /* spider.obj through the converter's binary form, and as it is. */
    run(&r, "'%s' -q --colors index -o '%s/spider' --format zsm '%s/OBJ/spider.obj' && ls '%s/spider.zsm'",
        MESHC, g_dir, ASSIMP_MODELS, g_dir);
    STATUS(&r, 0);
    snprintf(a, sizeof a, "'%s/spider.zsm' --fit", g_dir);
    render_ids(a, "zsm_s", &s);
    snprintf(a, sizeof a, "'%s/spider.zsm' --fit --mode zline", g_dir);
    render_ids(a, "zsm_z", &z);
    assert_true(same_image(&s, &z));
    snprintf(b, sizeof b, "'%s/OBJ/spider.obj' --fit", ASSIMP_MODELS);
    render_ids(b, "orig", &orig);
    n_zsm = covered(&s);
    n_orig = covered(&orig);
    /* Same shape (the converter merges vertices and drops degenerate
     * triangles; the silhouette stays within a few per cent). */
    if (!(n_zsm > 200 && labs(n_zsm - n_orig) * 20 < n_orig))
        fail_msg("spider: %ld pixels from the .zsm, %ld from the .obj", n_zsm, n_orig);
    free_image(&s);
    free_image(&z);
    free_image(&orig);

    /* Broken binary meshes: refused with a message. */
    run(&r, "head -c 100 '%s/spider.zsm' > '%s/cut.zsm' && '%s' render '%s/cut.zsm' --out '%s/c.png'",
        g_dir, g_dir, SIM, g_dir, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "not a valid zspan-meshc binary mesh");
    run(&r, "'%s' -q -o '%s/known' --format zsm '%s/known.obj' && cp '%s/known.zsm' '%s/idx.zsm' "
            "&& printf '\\377\\377' | dd of='%s/idx.zsm' bs=1 seek=$((24 + 6 * $(od -An -tu2 -j20 "
            "-N2 '%s/known.zsm'))) conv=notrunc status=none && '%s' render '%s/idx.zsm' --out "
            "'%s/c.png'",
        MESHC, g_dir, TOOLS_DATA, g_dir, g_dir, g_dir, g_dir, SIM, g_dir, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "a triangle index is not below the vertex count");
    run(&r, "printf 'ZSMESH1\\n' > '%s/short.zsm' && '%s' render '%s/short.zsm' --out '%s/c.png'",
        g_dir, SIM, g_dir, g_dir);
    STATUS(&r, 1);
    CONTAINS(&r, "truncated header");
}

/* ---- messages ---------------------------------------------------------- */

/* --painter: each order painted back to front into the whole image gives the
 * band image (the same PNG) and reports its overdraw; it needs priority mode. */
static void test_painter(void **state)
{
    static const char *const orders[] = {"bsp", "nns", "sort"};
    char out[2][1024];
    run_result r;
    int k, p;
    (void)state;
    for (k = 0; k < 3; k++) {
        image img[2];
        for (p = 0; p < 2; p++) {
            snprintf(out[p], sizeof out[p], "%s/painter_%s_%d.png", g_dir, orders[k], p);
            run(&r, "'%s' render '%s/OBJ/WusonOBJ.obj' --size 96x72 --shade gouraud --mode "
                    "priority --order %s %s --out '%s'",
                SIM, ASSIMP_MODELS, orders[k], p ? "--painter" : "", out[p]);
            STATUS(&r, 0);
            if (p)
                CONTAINS(&r, "painter: ");
            else
                LACKS(&r, "painter: ");
            assert_int_equal(read_png(out[p], &img[p]), 0);
        }
        assert_true(covered(&img[0]) > 500);
        assert_true(same_image(&img[0], &img[1]));
        free_image(&img[0]);
        free_image(&img[1]);
    }
    run(&r, "'%s' render '%s/OBJ/WusonOBJ.obj' --size 32x24 --painter --out '%s/x.png'", SIM,
        ASSIMP_MODELS, g_dir);
    STATUS(&r, 2);
    CONTAINS(&r, "--painter need --mode priority");
}

/* --cells kd|grid: the 55 chunks of regr01.obj as scene cells; part of them
 * outside the view is never transformed, and the image is the one without. */
static void test_cells(void **state)
{
    static const char *const kinds[] = {"", "--cells kd", "--cells grid"};
    image img[3];
    run_result r;
    char out[1024];
    int k;
    (void)state;
    for (k = 0; k < 3; k++) {
        snprintf(out, sizeof out, "%s/cells_%d.png", g_dir, k);
        run(&r, "'%s' render '%s/OBJ/regr01.obj' --fit --eye 0.3,0.2,0.6 --target 0.5,0,0 "
                "--size 120x90 %s --out '%s'",
            SIM, ASSIMP_MODELS, kinds[k], out);
        STATUS(&r, 0);
        if (k) {
            CONTAINS(&r, "cells: 55 chunks in ");
            CONTAINS(&r, "1836 triangles and 1159 vertices never transformed");
        }
        assert_int_equal(read_png(out, &img[k]), 0);
    }
    assert_true(covered(&img[0]) > 1000);
    assert_true(same_image(&img[0], &img[1]));
    assert_true(same_image(&img[0], &img[2]));
    for (k = 0; k < 3; k++)
        free_image(&img[k]);
    run(&r, "'%s' render '%s/OBJ/regr01.obj' --cells kd --mode priority --order bsp --out "
            "'%s/x.png'",
        SIM, ASSIMP_MODELS, g_dir);
    STATUS(&r, 2);
    CONTAINS(&r, "--cells: not with --order bsp");
}

static void test_messages(void **state)
{
    static const struct {
        const char *args, *says;
    } cases[] = {
        {"--fov 0.001", "--fov: 0.001 degrees is too narrow"},
        {"--fov 180", "--fov: 180 is outside"},
        {"--fov -5", "--fov"},
        {"--near 0", "--near"},
        {"--near 2 --far 1", "--far: 1 must be beyond --near 2"},
        {"--far 40000", "--far"},
        {"--eye 1,2,3 --target 1,2,3", "--eye and --target are the same point"},
        {"--up 0,0,1", "--up 0,0,1 is zero or parallel"},
        {"--up 0,0,0", "--up 0,0,0"},
        {"--size 2000x10", "--size: 2000 is outside 1..1024"},
        {"--light 0,0,0", "--light"},
        {"--up-axis w", "--up-axis"},
        {"--up w", "'w' is not an axis"},
        {"--up auto", "--up-axis auto"},
        {"--band 0", "--band"},
    };
    run_result r;
    size_t k;
    (void)state;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        /* The file does not exist: the options are checked first. */
        run(&r, "'%s' render '%s/none.obj' %s --out '%s/m.png'", SIM, g_dir, cases[k].args, g_dir);
        STATUS(&r, 2);
        CONTAINS(&r, cases[k].says);
        LACKS(&r, "zs_camera");
        LACKS(&r, "none.obj");
    }
    run(&r, "'%s' panel --panel nosuch --quiet", SIM);
    STATUS(&r, 2);
    CONTAINS(&r, "--panel: unknown panel 'nosuch'");
    /* Checked before the device is opened (no device error first). */
    if (exists(LINUX_PROG)) {
        run(&r, "'%s' --panel nosuch --dc 1 --spi /nonexistent/spidev", LINUX_PROG);
        STATUS(&r, 2);
        CONTAINS(&r, "--panel: unknown panel 'nosuch'");
        LACKS(&r, "/nonexistent/spidev");
        run(&r, "'%s' --panel ili9488 --format rgb565 --dc 1 --spi /nonexistent/spidev",
            LINUX_PROG);
        STATUS(&r, 2);
        CONTAINS(&r, "--format");
        LACKS(&r, "/nonexistent/spidev");
    }
    if (exists(MCP2210_PROG)) {
        run(&r, "'%s' --panel nosuch", MCP2210_PROG);
        STATUS(&r, 2);
        CONTAINS(&r, "--panel: unknown panel 'nosuch'");
        LACKS(&r, "hid");
    }
}

static int setup(void **state)
{
    (void)state;
    strcpy(g_dir, "/tmp/zspan-test-sim.XXXXXX");
    return mkdtemp(g_dir) != NULL ? 0 : -1;
}

static int teardown(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version),         cmocka_unit_test(test_spdx),
        cmocka_unit_test(test_help),            cmocka_unit_test(test_import_timeout),
        cmocka_unit_test(test_seq_pattern),     cmocka_unit_test(test_meshc_names),
        cmocka_unit_test(test_output_paths),    cmocka_unit_test(test_input_files),
        cmocka_unit_test(test_winding_options), cmocka_unit_test(test_normals_warning),
        cmocka_unit_test(test_up_axis),         cmocka_unit_test(test_big_model),
        cmocka_unit_test(test_binary_mesh),     cmocka_unit_test(test_messages),
        cmocka_unit_test(test_painter),         cmocka_unit_test(test_cells),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
