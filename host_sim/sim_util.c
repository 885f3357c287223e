/* SPDX-License-Identifier: MIT */
/* zspan-sim: statistics, files and image capture shared by the subcommands. */
#include "sim.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

void sim_print_stats(FILE *f, const zs_stats *s)
{
    fprintf(f, "  triangles: %lu submitted, %lu culled, %lu rejected, %lu clipped, %lu empty, "
               "%lu dropped, %lu stored, %lu drawn\n",
            (unsigned long)s->tris_submitted, (unsigned long)s->tris_culled,
            (unsigned long)s->tris_rejected, (unsigned long)s->tris_clipped,
            (unsigned long)s->tris_empty, (unsigned long)s->tris_dropped,
            (unsigned long)s->tris_stored, (unsigned long)s->tris_drawn);
    fprintf(f, "  vertices: %lu stored, %lu dropped; records dropped (pools full): %lu, skipped (active pool full): %lu; saturated: %lu\n",
            (unsigned long)s->verts_stored, (unsigned long)s->verts_dropped,
            (unsigned long)s->records_dropped, (unsigned long)s->records_skipped,
            (unsigned long)s->saturated);
    fprintf(f, "  rows: %lu, spans: %lu, max active edges: %lu, depth evals: %lu, "
               "crossings: %lu, pixels shaded: %lu\n",
            (unsigned long)s->rows, (unsigned long)s->spans, (unsigned long)s->max_active_edges,
            (unsigned long)s->depth_evals, (unsigned long)s->crossings,
            (unsigned long)s->pixels_shaded);
    if (s->windows)
        fprintf(f, "  warnock: %lu windows visited, %lu pixel decisions\n",
                (unsigned long)s->windows, (unsigned long)s->pixel_decisions);
    if (s->bsp_nodes || s->sort_pairs || s->sort_splits || s->sort_giveups || s->cells_culled ||
        s->tris_untransformed)
        fprintf(f, "  priority: BSP nodes visited %lu, triangles pruned %lu; sort: pairs "
                   "resolved %lu, moves %lu, splits %lu, give-ups %lu; culled: %lu cells, %lu "
                   "triangles and %lu vertices never transformed\n",
                (unsigned long)s->bsp_nodes, (unsigned long)s->bsp_pruned,
                (unsigned long)s->sort_pairs, (unsigned long)s->sort_swaps,
                (unsigned long)s->sort_splits, (unsigned long)s->sort_giveups,
                (unsigned long)s->cells_culled, (unsigned long)s->tris_untransformed,
                (unsigned long)s->verts_untransformed);
}

/* Longest path accepted (the Linux PATH_MAX less its terminator). */
#define SIM_PATH_MAX 4095u

int sim_check_output(const char *path, const char *opt)
{
    char *dir;
    const char *slash;
    struct stat sb;
    size_t n = strlen(path);

    if (n == 0) {
        fprintf(stderr, "zspan-sim: %s: the file name is empty\n", opt);
        return -1;
    }
    if (n > SIM_PATH_MAX) {
        fprintf(stderr, "zspan-sim: %s: the path is too long (%lu characters, at most %u)\n",
                opt, (unsigned long)n, SIM_PATH_MAX);
        return -1;
    }
    if (path[n - 1] == '/' || (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))) {
        fprintf(stderr, "zspan-sim: %s: %s is a directory, not a file name\n", opt, path);
        return -1;
    }
    slash = strrchr(path, '/');
    if (slash == NULL || slash == path)
        return 0; /* the current directory or / */
    dir = malloc((size_t)(slash - path) + 1u);
    if (dir == NULL)
        return 0; /* the write will say what is wrong */
    memcpy(dir, path, (size_t)(slash - path));
    dir[slash - path] = '\0';
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        fprintf(stderr, "zspan-sim: %s: cannot write %s: the directory %s does not exist "
                        "(zspan-sim creates no directories but the default out/)\n",
                opt, path, dir);
        free(dir);
        return -1;
    }
    free(dir);
    return 0;
}

int sim_make_parent_dirs(const char *path)
{
    char buf[4096];
    char *p;

    if (strlen(path) >= sizeof buf) {
        fprintf(stderr, "zspan-sim: %s: the path is too long\n", path);
        return -1;
    }
    strcpy(buf, path);
    for (p = buf + 1; *p != '\0'; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            fprintf(stderr, "zspan-sim: cannot create directory %s: %s\n", buf, strerror(errno));
            return -1;
        }
        *p = '/';
    }
    return 0;
}

uint32_t sim_fnv1a(const void *data, size_t n)
{
    const uint8_t *p = data;
    uint32_t h = 2166136261u;
    size_t i;

    for (i = 0; i < n; i++) {
        h ^= p[i];
        h *= 16777619u;
    }
    return h;
}

const char *sim_mode_name(zs_visibility mode)
{
    return mode == ZS_MODE_WARNOCK    ? "warnock"
           : mode == ZS_MODE_ZLINE    ? "zline"
           : mode == ZS_MODE_PRIORITY ? "priority"
                                      : "span";
}

typedef struct band_sink {
    uint8_t *img;
    size_t stride;
    int height;
} band_sink;

static int copy_band(void *user, int y0, int rows, const void *buf, size_t stride)
{
    band_sink *b = user;
    int k;

    for (k = 0; k < rows; k++) {
        int y = y0 + k;
        if (y < 0 || y >= b->height)
            continue;
        memcpy(b->img + (size_t)y * b->stride, (const uint8_t *)buf + (size_t)k * stride,
               b->stride);
    }
    return 0;
}

zs_status sim_render_image(zs_renderer *r, uint8_t *img, size_t stride, int height,
                           int band_rows)
{
    band_sink sink;
    uint8_t *band;
    zs_status st;

    if (band_rows < 1)
        band_rows = 1;
    if (band_rows > height)
        band_rows = height;
    band = malloc((size_t)band_rows * stride);
    if (band == NULL)
        return ZS_ERR_ARGUMENT;
    sink.img = img;
    sink.stride = stride;
    sink.height = height;
    st = zs_render_frame(r, band, stride, band_rows, copy_band, &sink);
    free(band);
    return st;
}
