/* SPDX-License-Identifier: MIT */
/*
 * Command-line parsing shared by every host program (zspan-sim, zspan-linux,
 * zspan-mcp2210): "--name VALUE" / "--name=VALUE" and typed values. Each
 * parser returns 0, or -1 after printing "PROG: ..." on stderr.
 */
#ifndef ZSPAN_APP_OPTS_H
#define ZSPAN_APP_OPTS_H

#include "zspan/zspan.h"

/* Matches "--name VALUE" and "--name=VALUE" at argv[*i]: 1 (*value set, *i
 * advanced past it), 0 (argv[*i] is another option), -1 (value missing). */
int zs_opt_value(int argc, char **argv, int *i, const char *name, const char **value,
                 const char *prog);

/* An integer in [lo, hi], decimal or 0x hex. */
int zs_opt_long(const char *prog, const char *opt, const char *s, long lo, long hi, long *out);
/* "--name N" at argv[*i] with N in [lo, hi]: 1 (*out set), 0 (another
 * option), -1 (missing or bad value). */
int zs_opt_long_at(int argc, char **argv, int *i, const char *name, long lo, long hi, long *out,
                   const char *prog);
/* A finite decimal number, the whole string. */
int zs_opt_double(const char *prog, const char *opt, const char *s, double *out);
/* n comma-separated decimal numbers. */
int zs_opt_doubles(const char *prog, const char *opt, const char *s, double *out, int n);
/* RRGGBB (six hex digits, optional leading '#' or 0x). */
int zs_opt_color(const char *prog, const char *opt, const char *s, zs_color *out);
/* WxH, each 1..ZS_MAX_DIM. */
int zs_opt_size(const char *prog, const char *opt, const char *s, int *w, int *h);
/* One of n words: *out = its index. */
int zs_opt_choice(const char *prog, const char *opt, const char *s, const char *const *words,
                  int n, int *out);
/* A decimal value -> Q16.16, rounded to nearest; -1 outside the Q16.16 range. */
int zs_opt_fixed(const char *prog, const char *what, double v, zs_fixed *out);

/* "--version": prints "PROG VERSION" (ZSPAN_VERSION_STRING) on stdout and
 * returns 1; any other argument: 0. */
int zs_opt_version(const char *arg, const char *prog);

/* A file-name pattern with exactly one integer conversion (%d, %i or %u with
 * optional flags 0-+ space, width of up to 3 digits and precision; "%%" is a plain %), e.g.
 * out/f_%03d.png. 0, or -1 after a message naming opt. */
int zs_opt_seq_pattern(const char *prog, const char *opt, const char *pattern);
/* The pattern (checked by zs_opt_seq_pattern) with n in it, into buf. 0, or
 * -1 if it does not fit (no message). */
int zs_opt_seq_path(char *buf, size_t size, const char *pattern, long n);

/* A file's up axis: "auto" 0, "x" 1, "y" 2, "z" 3, "-x" 4, "-y" 5, "-z" 6
 * (the ZS_UP_* of zs_model.h; "+x" etc. too). 0, or -1 after a message. */
int zs_opt_up_axis(const char *prog, const char *opt, const char *s, int *out);

/* The choices every renderer front end takes. */
int zs_opt_mode(const char *prog, const char *s, zs_visibility *out); /* span|zline|warnock */
int zs_opt_shade(const char *prog, const char *s, zs_shading *out);          /* flat|gouraud */
int zs_opt_wire_format(const char *prog, const char *s, zs_format *out);     /* rgb565|rgb666 */

#endif /* ZSPAN_APP_OPTS_H */
