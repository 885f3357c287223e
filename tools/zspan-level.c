/* SPDX-License-Identifier: MIT */
/*
 * zspan-level: portal levels for the core's zs_level_draw (zspan/portal.h).
 *
 *   zspan-level gen maze|building COLSxROWS SEED [-o FILE]   random level file
 *   zspan-level import MESH [--unit N] [-o FILE]             a level file from a mesh
 *                                                            (groups cell_NAME, portal_A_B)
 *   zspan-level info FILE                                    check, PVS summary
 *   zspan-level c FILE -n NAME -o BASE [-p FRAMES]           BASE.c and BASE.h
 *     (-p: also NAME_path, FRAMES eye and target points of lv_flight in Q16.16)
 *
 * Exit status: 0 success, 1 a bad level file or an output error (the message
 * names the file and line), 2 a bad command line.
 */
#include "level.h"
#include "level_import.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void usage(FILE *f)
{
    fprintf(f, "usage: zspan-level gen maze|building COLSxROWS SEED [-o FILE]\n"
               "       zspan-level import MESH [--unit N] [-o FILE]\n"
               "       zspan-level info FILE\n"
               "       zspan-level c FILE -n NAME -o BASE [-p FRAMES]\n");
}

static double cpu_ms(clock_t a, clock_t b)
{
    return 1000.0 * (double)(b - a) / CLOCKS_PER_SEC;
}

static int cmd_gen(int argc, char **argv)
{
    lv_level lv;
    int cols, rows;
    unsigned long seed;
    char *end;
    const char *out = NULL;
    FILE *f = stdout;
    lv_kind kind;
    if (argc != 4 && !(argc == 6 && !strcmp(argv[4], "-o"))) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "maze"))
        kind = LV_MAZE;
    else if (!strcmp(argv[1], "building"))
        kind = LV_BUILDING;
    else {
        fprintf(stderr, "zspan-level: unknown kind \"%s\" (maze or building)\n", argv[1]);
        return 2;
    }
    if (sscanf(argv[2], "%dx%d", &cols, &rows) != 2 || cols < 1 || rows < 1 || cols > 32 ||
        rows > 32) {
        fprintf(stderr, "zspan-level: size \"%s\" must be COLSxROWS, each 1..32\n", argv[2]);
        return 2;
    }
    seed = strtoul(argv[3], &end, 10);
    if (*end || end == argv[3]) {
        fprintf(stderr, "zspan-level: seed \"%s\" is not a number\n", argv[3]);
        return 2;
    }
    if (argc == 6)
        out = argv[5];
    lv_generate(&lv, kind, cols, rows, (uint32_t)seed);
    if (out && !(f = fopen(out, "w"))) {
        perror(out);
        lv_free(&lv);
        return 1;
    }
    if (lv_write(f, &lv) != 0 || (out && fclose(f) != 0)) {
        fprintf(stderr, "zspan-level: cannot write %s\n", out ? out : "stdout");
        lv_free(&lv);
        return 1;
    }
    lv_free(&lv);
    return 0;
}

static int cmd_import(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    int unit = 16, i;
    lv_level lv;
    char err[600];
    FILE *f = stdout;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--unit") && i + 1 < argc)
            unit = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!in && argv[i][0] != '-')
            in = argv[i];
        else {
            usage(stderr);
            return 2;
        }
    }
    if (!in) {
        usage(stderr);
        return 2;
    }
    if (lv_import_mesh(in, unit, &lv, err, sizeof err) != 0) {
        fprintf(stderr, "zspan-level: %s\n", err);
        return 1;
    }
    if (out && !(f = fopen(out, "w"))) {
        perror(out);
        lv_free(&lv);
        return 1;
    }
    if (lv_write(f, &lv) != 0 || (out && fclose(f) != 0)) {
        fprintf(stderr, "zspan-level: cannot write %s\n", out ? out : "stdout");
        lv_free(&lv);
        return 1;
    }
    lv_free(&lv);
    return 0;
}

static int load_built(const char *path, lv_built *b, lv_pvs_stats *ps, double *ms)
{
    lv_level lv;
    char err[512];
    clock_t t0, t1;
    uint8_t *pvs;
    if (lv_load(path, &lv, err, sizeof err) != 0) {
        fprintf(stderr, "zspan-level: %s\n", err);
        return -1;
    }
    t0 = clock();
    pvs = lv_compute_pvs(&lv, ps);
    t1 = clock();
    *ms = cpu_ms(t0, t1);
    if (lv_build(&lv, pvs, b, err, sizeof err) != 0) {
        fprintf(stderr, "zspan-level: %s: %s\n", path, err);
        lv_free(&lv);
        return -1;
    }
    lv_free(&lv);
    if (zs_level_check(&b->level) != ZS_OK) {
        fprintf(stderr, "zspan-level: %s: the core refuses the built level (%s)\n", path,
                zs_strerror(zs_level_check(&b->level)));
        lv_built_free(b);
        return -1;
    }
    return 0;
}

static int cmd_info(int argc, char **argv)
{
    lv_built b;
    lv_pvs_stats ps;
    double ms;
    unsigned long total = 0;
    int c, j, worst = 0;
    if (argc != 2) {
        usage(stderr);
        return 2;
    }
    if (load_built(argv[1], &b, &ps, &ms) != 0)
        return 1;
    for (c = 0; c < b.level.cell_count; c++) {
        int n = 0;
        for (j = 0; j < b.level.cell_count; j++)
            n += (b.pvs[c * ((b.level.cell_count + 7) / 8) + j / 8] >> (j % 8)) & 1;
        total += (unsigned long)n;
        worst = n > worst ? n : worst;
    }
    printf("%s: %u cells, %u directed portals, %d triangles\n", argv[1], b.level.cell_count,
           b.level.portal_count, b.total_tris);
    printf("pvs: mean %.2f cells, largest %d; %llu sequences tested, %llu stabbable, deepest %d; "
           "%.1f ms cpu\n",
           (double)total / b.level.cell_count, worst, (unsigned long long)ps.sequences,
           (unsigned long long)ps.stabbable, ps.max_depth, ms);
    lv_built_free(&b);
    return 0;
}

static int cmd_c(int argc, char **argv)
{
    const char *name = NULL, *base = NULL, *in = NULL;
    int frames = 0, total_verts = 0;
    char path[1024];
    lv_built b;
    lv_pvs_stats ps;
    double ms;
    FILE *f;
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-n") && i + 1 < argc)
            name = argv[++i];
        else if (!strcmp(argv[i], "-o") && i + 1 < argc)
            base = argv[++i];
        else if (!strcmp(argv[i], "-p") && i + 1 < argc) {
            frames = atoi(argv[++i]);
            if (frames < 1 || frames > 10000) {
                fprintf(stderr, "zspan-level: -p needs 1..10000 frames\n");
                return 2;
            }
        }
        else if (!in && argv[i][0] != '-')
            in = argv[i];
        else {
            usage(stderr);
            return 2;
        }
    }
    if (!name || !base || !in) {
        usage(stderr);
        return 2;
    }
    for (i = 0; name[i]; i++)
        if (!((name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
              name[i] == '_' || (i > 0 && name[i] >= '0' && name[i] <= '9'))) {
            fprintf(stderr, "zspan-level: \"%s\" is not a C identifier\n", name);
            return 2;
        }
    if (load_built(in, &b, &ps, &ms) != 0)
        return 1;
    snprintf(path, sizeof path, "%s.c", base);
    f = fopen(path, "w");
    if (f && frames) {
        double (*pe)[3] = malloc(sizeof *pe * (size_t)frames), (*pt)[3] = malloc(sizeof *pt * (size_t)frames);
        int k;
        if (lv_flight(&b.level, frames, pe, pt) != 0) {
            fprintf(stderr, "zspan-level: %s: no height is open in every cell: no path\n", in);
            fclose(f);
            lv_built_free(&b);
            return 1;
        }
        if (lv_emit_c(f, &b, name) == 0) {
            fprintf(f, "/* lv_flight: eye x, y, z and target x, y, z per frame, Q16.16 */\n"
                       "const zs_fixed %s_path[%d][6] = {\n", name, frames);
            for (k = 0; k < frames; k++)
                fprintf(f, "    {%ld, %ld, %ld, %ld, %ld, %ld},\n", lround(pe[k][0] * 65536),
                        lround(pe[k][1] * 65536), lround(pe[k][2] * 65536),
                        lround(pt[k][0] * 65536), lround(pt[k][1] * 65536),
                        lround(pt[k][2] * 65536));
            fprintf(f, "};\n");
        }
        free(pe);
        free(pt);
    }
    if (!f || (!frames && lv_emit_c(f, &b, name) != 0) || ferror(f) || fclose(f) != 0) {
        fprintf(stderr, "zspan-level: cannot write %s\n", path);
        lv_built_free(&b);
        return 1;
    }
    for (i = 0; i < b.level.cell_count; i++)
        total_verts += b.level.meshes[i].vertex_count;
    snprintf(path, sizeof path, "%s.h", base);
    f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "zspan-level: cannot write %s\n", path);
        lv_built_free(&b);
        return 1;
    }
    fprintf(f, "/* Generated by zspan-level from %s. */\n#ifndef %s_H\n#define %s_H\n"
               "#include \"zspan/portal.h\"\n#define %s_TRIANGLES %d\n#define %s_VERTICES %d\n"
               "extern const zs_level %s;\n",
            in, name, name, name, b.total_tris, name, total_verts, name);
    if (frames)
        fprintf(f, "#define %s_PATH_FRAMES %d\nextern const zs_fixed %s_path[%d][6];\n", name,
                frames, name, frames);
    fprintf(f, "#endif\n");
    if (fclose(f) != 0) {
        fprintf(stderr, "zspan-level: cannot write %s\n", path);
        lv_built_free(&b);
        return 1;
    }
    lv_built_free(&b);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "gen"))
        return cmd_gen(argc - 1, argv + 1);
    if (argc >= 2 && !strcmp(argv[1], "import"))
        return cmd_import(argc - 1, argv + 1);
    if (argc >= 2 && !strcmp(argv[1], "info"))
        return cmd_info(argc - 1, argv + 1);
    if (argc >= 2 && !strcmp(argv[1], "c"))
        return cmd_c(argc - 1, argv + 1);
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        usage(stdout);
        return 0;
    }
    usage(stderr);
    return 2;
}
