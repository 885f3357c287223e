/* SPDX-License-Identifier: MIT */
/*
 * Least-squares fit of a linear cost model for the scaling benchmark
 * (bench/bench_scale.c): instructions ~= sum_j coef[j] * x[j] over the runs.
 *
 * Host code (double precision). The fit minimises the sum of squared
 * relative errors, sum_i ((y_i - x_i . coef) / y_i)^2, so a run of 50 k
 * instructions counts as much as one of 50 M; it solves by Householder QR on
 * the column-scaled, weighted design (no normal equations, which would square
 * the condition number).
 */
#ifndef ZSPAN_BENCH_SCALE_FIT_H
#define ZSPAN_BENCH_SCALE_FIT_H

#define SCALE_FIT_MAX_TERMS 8
/* Above this 2-norm condition number (of the column-scaled, weighted design)
 * the terms cannot be told apart by the runs: the fit is refused. */
#define SCALE_FIT_COND_LIMIT 1e8

typedef enum scale_fit_status {
    SCALE_FIT_OK = 0,
    SCALE_FIT_TOO_FEW_RUNS,   /* fewer runs than terms */
    SCALE_FIT_BAD_ARGS,       /* terms outside 1..SCALE_FIT_MAX_TERMS, a y_i <= 0
                                 or a value that is not finite */
    SCALE_FIT_RANK            /* a term is zero in every run, or the terms are
                                 (nearly) linearly dependent over the runs */
} scale_fit_status;

typedef struct scale_fit {
    int n_runs, n_terms;
    double coef[SCALE_FIT_MAX_TERMS];
    double cond;          /* condition number described above (also set on RANK) */
    double r2;            /* 1 - SS_res / SS_tot, on the instruction counts */
    double max_rel_err;   /* largest |y_i - fit_i| / y_i */
} scale_fit;

/* x: n_runs rows of n_terms values (row-major), y: n_runs positive values. */
scale_fit_status scale_fit_solve(const double *x, const double *y, int n_runs, int n_terms,
                                 scale_fit *out);
/* The model's value for one run's terms. */
double scale_fit_eval(const scale_fit *fit, const double *x_row);
const char *scale_fit_strerror(scale_fit_status st);

#endif
