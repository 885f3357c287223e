/* Command-line parsing of the host programs (see zs_opts.h). */
#include "zs_opts.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int zs_opt_value(int argc, char **argv, int *i, const char *name, const char **value,
                 const char *prog)
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
        fprintf(stderr, "%s: %s needs a value\n", prog, name);
        return -1;
    }
    *i += 1;
    *value = argv[*i];
    return 1;
}

int zs_opt_long(const char *prog, const char *opt, const char *s, long lo, long hi, long *out)
{
    const char *p = s;
    char *end = NULL;
    long v;
    int base = 10;

    /* Decimal, or hex after 0x; a leading 0 is not octal. */
    while (isspace((unsigned char)*p))
        p++;
    if (*p == '-' || *p == '+')
        p++;
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        base = 16;
    errno = 0;
    v = strtol(s, &end, base);
    if (end == s || *end != '\0' || errno == ERANGE) {
        fprintf(stderr, "%s: %s: '%s' is not an integer\n", prog, opt, s);
        return -1;
    }
    if (v < lo || v > hi) {
        fprintf(stderr, "%s: %s: %ld is outside %ld..%ld\n", prog, opt, v, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int zs_opt_long_at(int argc, char **argv, int *i, const char *name, long lo, long hi, long *out,
                   const char *prog)
{
    const char *v;
    int m = zs_opt_value(argc, argv, i, name, &v, prog);

    if (m <= 0)
        return m;
    return zs_opt_long(prog, name, v, lo, hi, out) == 0 ? 1 : -1;
}

int zs_opt_double(const char *prog, const char *opt, const char *s, double *out)
{
    char *end = NULL;
    double v;

    errno = 0;
    while (isspace((unsigned char)*s))
        s++;
    v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v)) {
        fprintf(stderr, "%s: %s: '%s' is not a decimal number\n", prog, opt, s);
        return -1;
    }
    *out = v;
    return 0;
}

int zs_opt_doubles(const char *prog, const char *opt, const char *s, double *out, int n)
{
    char buf[256];
    char *p;
    int k;

    if (strlen(s) >= sizeof buf) {
        fprintf(stderr, "%s: %s: value too long\n", prog, opt);
        return -1;
    }
    strcpy(buf, s);
    p = buf;
    for (k = 0; k < n; k++) {
        char *comma = strchr(p, ',');
        if ((k < n - 1) != (comma != NULL)) {
            fprintf(stderr, "%s: %s: expected %d comma-separated numbers, got '%s'\n", prog,
                    opt, n, s);
            return -1;
        }
        if (comma != NULL)
            *comma = '\0';
        if (zs_opt_double(prog, opt, p, &out[k]) != 0)
            return -1;
        if (comma != NULL)
            p = comma + 1;
    }
    return 0;
}

int zs_opt_color(const char *prog, const char *opt, const char *s, zs_color *out)
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
        fprintf(stderr, "%s: %s: '%s' is not a colour RRGGBB (six hex digits)\n", prog, opt, s);
        return -1;
    }
    *out = (zs_color)v;
    return 0;
}

int zs_opt_size(const char *prog, const char *opt, const char *s, int *w, int *h)
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
    if (zs_opt_long(prog, opt, buf, 1, ZS_MAX_DIM, &lw) != 0 ||
        zs_opt_long(prog, opt, x + 1, 1, ZS_MAX_DIM, &lh) != 0)
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
bad:
    fprintf(stderr, "%s: %s: '%s' is not a size WxH\n", prog, opt, s);
    return -1;
}

int zs_opt_choice(const char *prog, const char *opt, const char *s, const char *const *words,
                  int n, int *out)
{
    int k;

    for (k = 0; k < n; k++) {
        if (strcmp(s, words[k]) == 0) {
            *out = k;
            return 0;
        }
    }
    fprintf(stderr, "%s: %s: '%s' is not one of:", prog, opt, s);
    for (k = 0; k < n; k++)
        fprintf(stderr, " %s", words[k]);
    fputc('\n', stderr);
    return -1;
}

int zs_opt_fixed(const char *prog, const char *what, double v, zs_fixed *out)
{
    double f = floor(v * 65536.0 + 0.5);

    if (!(f >= (double)INT32_MIN && f <= (double)INT32_MAX)) {
        fprintf(stderr, "%s: %s: %g is outside the Q16.16 range (+-32767.99998)\n", prog, what,
                v);
        return -1;
    }
    *out = (zs_fixed)f;
    return 0;
}

/* A typed parser of a two-word option: the words and the values they stand for. */
#define TWO_WORDS(fn, type, opt, w0, v0, w1, v1)                                               \
    int fn(const char *prog, const char *s, type *out)                                         \
    {                                                                                          \
        static const char *const words[] = {w0, w1};                                           \
        int k;                                                                                 \
        if (zs_opt_choice(prog, opt, s, words, 2, &k) != 0)                                    \
            return -1;                                                                         \
        *out = k == 0 ? v0 : v1;                                                               \
        return 0;                                                                              \
    }

TWO_WORDS(zs_opt_mode, zs_visibility, "--mode", "span", ZS_MODE_SPAN, "zline", ZS_MODE_ZLINE)
TWO_WORDS(zs_opt_shade, zs_shading, "--shade", "flat", ZS_SHADE_FLAT, "gouraud", ZS_SHADE_GOURAUD)
TWO_WORDS(zs_opt_wire_format, zs_format, "--format", "rgb565", ZS_FMT_RGB565_BE, "rgb666",
          ZS_FMT_RGB666)
