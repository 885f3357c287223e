/* zspan-sim: option parsing, statistics and small helpers shared by the subcommands. */
#include "sim.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

int sim_parse_double(const char *opt, const char *s, double *out)
{
    char *end = NULL;
    double v;

    errno = 0;
    while (isspace((unsigned char)*s))
        s++;
    v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v)) {
        fprintf(stderr, "zspan-sim: %s: '%s' is not a decimal number\n", opt, s);
        return -1;
    }
    *out = v;
    return 0;
}

int sim_parse_doubles(const char *opt, const char *s, double *out, int n)
{
    char buf[256];
    char *p;
    int k;

    if (strlen(s) >= sizeof buf) {
        fprintf(stderr, "zspan-sim: %s: value too long\n", opt);
        return -1;
    }
    strcpy(buf, s);
    p = buf;
    for (k = 0; k < n; k++) {
        char *comma = strchr(p, ',');
        if (k < n - 1) {
            if (comma == NULL) {
                fprintf(stderr, "zspan-sim: %s: expected %d comma-separated numbers, got '%s'\n",
                        opt, n, s);
                return -1;
            }
            *comma = '\0';
        } else if (comma != NULL) {
            fprintf(stderr, "zspan-sim: %s: expected %d comma-separated numbers, got '%s'\n", opt,
                    n, s);
            return -1;
        }
        if (sim_parse_double(opt, p, &out[k]) != 0)
            return -1;
        if (comma != NULL)
            p = comma + 1;
    }
    return 0;
}

int sim_parse_long(const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end = NULL;
    long v;

    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE) {
        fprintf(stderr, "zspan-sim: %s: '%s' is not an integer\n", opt, s);
        return -1;
    }
    if (v < lo || v > hi) {
        fprintf(stderr, "zspan-sim: %s: %ld is outside %ld..%ld\n", opt, v, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int sim_parse_color(const char *opt, const char *s, zs_color *out)
{
    const char *p = s;
    unsigned long v = 0;
    int k;

    if (*p == '#')
        p++;
    else if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        p += 2;
    for (k = 0; k < 6; k++) {
        int c = (unsigned char)p[k];
        if (!isxdigit(c))
            break;
        v = v * 16u + (unsigned long)(isdigit(c) ? c - '0' : tolower(c) - 'a' + 10);
    }
    if (k != 6 || p[6] != '\0') {
        fprintf(stderr, "zspan-sim: %s: '%s' is not a colour RRGGBB (six hex digits)\n", opt, s);
        return -1;
    }
    *out = (zs_color)v;
    return 0;
}

int sim_parse_size(const char *opt, const char *s, int *w, int *h)
{
    char buf[64];
    char *x;
    long lw, lh;

    if (strlen(s) >= sizeof buf)
        goto bad;
    strcpy(buf, s);
    x = strchr(buf, 'x');
    if (x == NULL)
        x = strchr(buf, 'X');
    if (x == NULL)
        goto bad;
    *x = '\0';
    if (sim_parse_long(opt, buf, 1, ZS_MAX_DIM, &lw) != 0 ||
        sim_parse_long(opt, x + 1, 1, ZS_MAX_DIM, &lh) != 0)
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
bad:
    fprintf(stderr, "zspan-sim: %s: '%s' is not a size WxH\n", opt, s);
    return -1;
}

int sim_to_fixed(const char *what, double v, zs_fixed *out)
{
    double f = floor(v * 65536.0 + 0.5);

    if (!(f >= (double)INT32_MIN && f <= (double)INT32_MAX)) {
        fprintf(stderr, "zspan-sim: %s: %g is outside the Q16.16 range (+-32767.99998)\n", what,
                v);
        return -1;
    }
    *out = (zs_fixed)f;
    return 0;
}

int sim_opt_value(int argc, char **argv, int *i, const char *name, const char **value)
{
    const char *a = argv[*i];
    size_t n = strlen(name);

    if (strncmp(a, name, n) != 0)
        return 0;
    if (a[n] == '=') {
        *value = a + n + 1;
        return 1;
    }
    if (a[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "zspan-sim: %s needs a value\n", name);
        return -1;
    }
    *i += 1;
    *value = argv[*i];
    return 1;
}

void sim_print_stats(FILE *f, const zs_stats *s)
{
    fprintf(f, "  triangles: %lu submitted, %lu culled, %lu rejected, %lu clipped, %lu empty, "
               "%lu dropped, %lu stored, %lu drawn\n",
            (unsigned long)s->tris_submitted, (unsigned long)s->tris_culled,
            (unsigned long)s->tris_rejected, (unsigned long)s->tris_clipped,
            (unsigned long)s->tris_empty, (unsigned long)s->tris_dropped,
            (unsigned long)s->tris_stored, (unsigned long)s->tris_drawn);
    fprintf(f, "  vertices: %lu stored, %lu dropped; records skipped (active pool full): %lu; saturated: %lu\n",
            (unsigned long)s->verts_stored, (unsigned long)s->verts_dropped,
            (unsigned long)s->records_skipped, (unsigned long)s->saturated);
    fprintf(f, "  rows: %lu, spans: %lu, max active edges: %lu, depth evals: %lu, "
               "crossings: %lu, pixels shaded: %lu\n",
            (unsigned long)s->rows, (unsigned long)s->spans, (unsigned long)s->max_active_edges,
            (unsigned long)s->depth_evals, (unsigned long)s->crossings,
            (unsigned long)s->pixels_shaded);
}

int sim_make_parent_dirs(const char *path)
{
    char buf[4096];
    char *p;

    if (strlen(path) >= sizeof buf)
        return -1;
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
    return mode == ZS_MODE_ZLINE ? "zline" : "span";
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
