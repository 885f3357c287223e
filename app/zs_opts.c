/* SPDX-License-Identifier: MIT */
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

int zs_opt_mode(const char *prog, const char *s, zs_visibility *out)
{
    static const char *const words[] = {"span", "zline", "warnock"};
    static const zs_visibility modes[] = {ZS_MODE_SPAN, ZS_MODE_ZLINE, ZS_MODE_WARNOCK};
    int k;
    if (zs_opt_choice(prog, "--mode", s, words, 3, &k) != 0)
        return -1;
    *out = modes[k];
    return 0;
}
TWO_WORDS(zs_opt_shade, zs_shading, "--shade", "flat", ZS_SHADE_FLAT, "gouraud", ZS_SHADE_GOURAUD)
TWO_WORDS(zs_opt_wire_format, zs_format, "--format", "rgb565", ZS_FMT_RGB565_BE, "rgb666",
          ZS_FMT_RGB666)

int zs_opt_version(const char *arg, const char *prog)
{
    if (strcmp(arg, "--version") != 0)
        return 0;
    printf("%s %s\n", prog, ZSPAN_VERSION_STRING);
    return 1;
}

/* Finds the one conversion of a pattern: *at its '%', *len its length.
 * Returns 0, or -1 with *why set. */
static int seq_scan(const char *p, size_t *at, size_t *len, const char **why)
{
    size_t i = 0, found = 0;
    int n = 0;

    *why = NULL;
    while (p[i] != '\0') {
        size_t s = i, w;
        if (p[i] != '%') {
            i++;
            continue;
        }
        if (p[i + 1] == '%') {
            i += 2;
            continue;
        }
        i++;
        while (p[i] != '\0' && strchr("0-+ ", p[i]) != NULL)
            i++;
        for (w = 0; isdigit((unsigned char)p[i]); w++)
            i++;
        if (w > 3) {
            *why = "a field width of more than 3 digits";
            return -1;
        }
        if (p[i] == '.') {
            i++;
            for (w = 0; isdigit((unsigned char)p[i]); w++)
                i++;
            if (w > 3) {
                *why = "a precision of more than 3 digits";
                return -1;
            }
        }
        if (p[i] != 'd' && p[i] != 'i' && p[i] != 'u') {
            *why = "a conversion other than %d, %i or %u (or a length modifier)";
            return -1;
        }
        i++;
        n++;
        found = s;
        *len = i - s;
    }
    if (n != 1) {
        *why = n == 0 ? "no %d for the frame number" : "more than one conversion";
        return -1;
    }
    *at = found;
    return 0;
}

int zs_opt_seq_pattern(const char *prog, const char *opt, const char *pattern)
{
    size_t at, len;
    const char *why;

    if (strlen(pattern) > 4000) {
        fprintf(stderr, "%s: %s: the pattern is too long (%lu characters, at most 4000)\n", prog,
                opt, (unsigned long)strlen(pattern));
        return -1;
    }
    if (seq_scan(pattern, &at, &len, &why) != 0) {
        fprintf(stderr,
                "%s: %s: '%s' has %s: it needs exactly one integer conversion such as %%d or "
                "%%03d (%%%% for a plain %%)\n",
                prog, opt, pattern, why);
        return -1;
    }
    return 0;
}

int zs_opt_seq_path(char *buf, size_t size, const char *pattern, long n)
{
    char spec[16];
    size_t at, len, k, o = 0;
    const char *why;
    int w;

    if (size == 0 || seq_scan(pattern, &at, &len, &why) != 0 || len >= sizeof spec)
        return -1;
    memcpy(spec, pattern + at, len);
    spec[len] = '\0';
    /* The text around the conversion, with %% made %; the conversion alone
     * is the format string (checked above: one int conversion). */
    for (k = 0; k < at; k++) {
        if (o + 1 >= size)
            return -1;
        buf[o++] = pattern[k];
        if (pattern[k] == '%')
            k++;
    }
    if (n < 0 || n > 2147483647L)
        return -1;
    w = spec[len - 1] == 'u' ? snprintf(buf + o, size - o, spec, (unsigned)n)
                             : snprintf(buf + o, size - o, spec, (int)n);
    if (w < 0 || (size_t)w >= size - o)
        return -1;
    o += (size_t)w;
    for (k = at + len; pattern[k] != '\0'; k++) {
        if (o + 1 >= size)
            return -1;
        buf[o++] = pattern[k];
        if (pattern[k] == '%')
            k++;
    }
    buf[o] = '\0';
    return 0;
}

int zs_opt_up_axis(const char *prog, const char *opt, const char *s, int *out)
{
    static const char *const names[] = {"auto", "x", "y", "z", "-x", "-y", "-z"};
    int k;

    for (k = 0; k < 7; k++)
        if (strcmp(s, names[k]) == 0 ||
            (k >= 1 && k <= 3 && s[0] == '+' && strcmp(s + 1, names[k]) == 0)) {
            *out = k;
            return 0;
        }
    fprintf(stderr, "%s: %s: '%s' is not an axis (auto, x, y, z, -x, -y, -z)\n", prog, opt, s);
    return -1;
}
