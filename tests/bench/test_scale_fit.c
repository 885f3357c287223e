/* SPDX-License-Identifier: MIT */
/*
 * The least-squares fit of the scaling benchmark (bench/scale_fit.c) against
 * independent oracles: exact recovery of known coefficients, the weighted
 * normal equations solved by Gaussian elimination in long double, the
 * optimality condition of the residuals, a one-term fit worked out by hand,
 * the condition number of designs whose answer is known, and every refusal.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "scale_fit.h"

#define RUNS 30
#define T 5

static uint32_t rng_state;

static double rnd(void) /* [0, 1), a fixed-seed LCG */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

/* Designs shaped like the bench's: rows, submitted, drawn, edge events, pixels. */
static void make_design(double *x, int m)
{
    int i;
    rng_state = 12345u;
    for (i = 0; i < m; i++) {
        double rows = 120 + 200 * rnd(), subm = 50 + 16000 * rnd();
        x[i * T + 0] = rows;
        x[i * T + 1] = subm;
        x[i * T + 2] = subm * (0.05 + 0.4 * rnd());
        x[i * T + 3] = rows * (4 + 60 * rnd());
        x[i * T + 4] = rows * (120 + 360 * rnd());
    }
}

static const double beta[T] = {130.0, 290.0, 1270.0, 218.0, 1.13};

static void product(const double *x, int m, double *y)
{
    int i, j;
    for (i = 0; i < m; i++) {
        y[i] = 0;
        for (j = 0; j < T; j++)
            y[i] += x[i * T + j] * beta[j];
    }
}

static void test_exact_recovery(void **state)
{
    double x[RUNS * T], y[RUNS];
    scale_fit f;
    int j;
    (void)state;
    make_design(x, RUNS);
    product(x, RUNS, y);
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_OK);
    for (j = 0; j < T; j++)
        assert_true(fabs(f.coef[j] - beta[j]) <= 1e-9 * beta[j]);
    assert_true(f.r2 > 1.0 - 1e-12);
    assert_true(f.max_rel_err < 1e-10);
    assert_true(f.cond >= 1.0 && f.cond < SCALE_FIT_COND_LIMIT);
    assert_int_equal(f.n_runs, RUNS);
    assert_int_equal(f.n_terms, T);
}

/* Weighted normal equations (X^T W X) b = X^T W y, W = diag(1 / y_i^2),
 * by Gaussian elimination with partial pivoting in long double. */
static void normal_equations(const double *x, const double *y, int m, double *b)
{
    long double a[T][T + 1];
    int i, j, k, r;
    memset(a, 0, sizeof a);
    for (i = 0; i < m; i++) {
        long double w = 1.0L / ((long double)y[i] * y[i]);
        for (j = 0; j < T; j++) {
            for (k = 0; k < T; k++)
                a[j][k] += w * x[i * T + j] * x[i * T + k];
            a[j][T] += w * x[i * T + j] * y[i];
        }
    }
    for (k = 0; k < T; k++) {
        int p = k;
        for (r = k + 1; r < T; r++)
            if (fabsl(a[r][k]) > fabsl(a[p][k]))
                p = r;
        for (j = 0; j <= T; j++) {
            long double t = a[k][j];
            a[k][j] = a[p][j];
            a[p][j] = t;
        }
        for (r = k + 1; r < T; r++) {
            long double q = a[r][k] / a[k][k];
            for (j = k; j <= T; j++)
                a[r][j] -= q * a[k][j];
        }
    }
    for (k = T - 1; k >= 0; k--) {
        long double s = a[k][T];
        for (j = k + 1; j < T; j++)
            s -= a[k][j] * b[j];
        b[k] = (double)(s / a[k][k]);
    }
}

static void test_noisy_matches_normal_equations(void **state)
{
    double x[RUNS * T], y[RUNS], b[T];
    scale_fit f;
    int i, j;
    (void)state;
    make_design(x, RUNS);
    product(x, RUNS, y);
    for (i = 0; i < RUNS; i++)
        y[i] *= 1.0 + 0.06 * (rnd() - 0.5); /* +-3% */
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_OK);
    normal_equations(x, y, RUNS, b);
    for (j = 0; j < T; j++)
        assert_true(fabs(f.coef[j] - b[j]) <= 1e-7 * fabs(b[j]));
    /* optimality: the weighted residuals are orthogonal to every weighted column */
    for (j = 0; j < T; j++) {
        double dot = 0, norm = 0;
        for (i = 0; i < RUNS; i++) {
            double t[T];
            memcpy(t, x + i * T, sizeof t);
            dot += (x[i * T + j] / y[i]) * (1.0 - scale_fit_eval(&f, t) / y[i]);
            norm += fabs(x[i * T + j] / y[i]);
        }
        assert_true(fabs(dot) <= 1e-10 * norm);
    }
    assert_true(f.max_rel_err > 0.0 && f.max_rel_err < 0.06);
    assert_true(f.r2 > 0.99 && f.r2 < 1.0);
}

/* One term, worked by hand: x = 1, 2, 3, y = 1, 2, 4; x_i / y_i = 1, 1, 3/4,
 * so c = sum(x/y) / sum((x/y)^2) = 2.75 / 2.5625; R^2 from the residuals. */
static void test_one_term_by_hand(void **state)
{
    const double x[3] = {1, 2, 3}, y[3] = {1, 2, 4};
    const double c = 2.75 / 2.5625;
    double ss_res = 0, ss_tot = 0, mean = 7.0 / 3.0;
    scale_fit f;
    int i;
    (void)state;
    assert_int_equal(scale_fit_solve(x, y, 3, 1, &f), SCALE_FIT_OK);
    assert_true(fabs(f.coef[0] - c) < 1e-14);
    for (i = 0; i < 3; i++) {
        ss_res += (y[i] - c * x[i]) * (y[i] - c * x[i]);
        ss_tot += (y[i] - mean) * (y[i] - mean);
    }
    assert_true(fabs(f.r2 - (1.0 - ss_res / ss_tot)) < 1e-14);
    assert_true(fabs(f.max_rel_err - fabs(4.0 - 3.0 * c) / 4.0) < 1e-14);
    assert_true(fabs(f.cond - 1.0) < 1e-14); /* one column: perfectly conditioned */
}

/* Orthogonal weighted columns (x = identity, y = 1): condition number 1. */
static void test_cond_orthogonal(void **state)
{
    double x[T * T], y[T];
    scale_fit f;
    int i, j;
    (void)state;
    for (i = 0; i < T; i++) {
        for (j = 0; j < T; j++)
            x[i * T + j] = i == j ? (j + 1) * 1000.0 : 0.0; /* scaled columns */
        y[i] = 1.0;
    }
    assert_int_equal(scale_fit_solve(x, y, T, T, &f), SCALE_FIT_OK);
    assert_true(fabs(f.cond - 1.0) < 1e-12);
    for (j = 0; j < T; j++)
        assert_true(fabs(f.coef[j] - 1.0 / ((j + 1) * 1000.0)) < 1e-15);
}

/* Two columns at 45 degrees (after scaling): singular values 1 +- cos 45. */
static void test_cond_known(void **state)
{
    const double x[2 * 2] = {1, 1, 0, 1}, y[2] = {1, 1};
    const double expect = (1 + sqrt(0.5)) / (1 - sqrt(0.5));
    scale_fit f;
    (void)state;
    assert_int_equal(scale_fit_solve(x, y, 2, 2, &f), SCALE_FIT_OK);
    /* scaled columns (1,0) and (1,1)/sqrt2: Gram eigenvalues 1 +- 1/sqrt2 */
    assert_true(fabs(f.cond - sqrt(expect)) < 1e-12);
    assert_true(fabs(f.coef[0] - 0.0) < 1e-12 && fabs(f.coef[1] - 1.0) < 1e-12);
}

static void test_column_scale_invariance(void **state)
{
    double x[RUNS * T], y[RUNS];
    scale_fit a, b;
    int i, j;
    (void)state;
    make_design(x, RUNS);
    product(x, RUNS, y);
    for (i = 0; i < RUNS; i++)
        y[i] *= 1.0 + 0.04 * (rnd() - 0.5);
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &a), SCALE_FIT_OK);
    for (i = 0; i < RUNS; i++)
        x[i * T + 4] *= 1e-6;
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &b), SCALE_FIT_OK);
    for (j = 0; j < 4; j++)
        assert_true(fabs(a.coef[j] - b.coef[j]) <= 1e-9 * fabs(a.coef[j]));
    assert_true(fabs(a.coef[4] - b.coef[4] * 1e-6) <= 1e-9 * fabs(a.coef[4]));
    assert_true(fabs(a.cond - b.cond) <= 1e-9 * a.cond);
}

static void test_refusals(void **state)
{
    double x[RUNS * T], y[RUNS];
    scale_fit f;
    int i;
    (void)state;
    make_design(x, RUNS);
    product(x, RUNS, y);
    assert_int_equal(scale_fit_solve(x, y, T - 1, T, &f), SCALE_FIT_TOO_FEW_RUNS);
    assert_int_equal(scale_fit_solve(x, y, RUNS, 0, &f), SCALE_FIT_BAD_ARGS);
    assert_int_equal(scale_fit_solve(x, y, RUNS, SCALE_FIT_MAX_TERMS + 1, &f),
                     SCALE_FIT_BAD_ARGS);
    y[3] = 0.0;
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_BAD_ARGS);
    y[3] = -5.0;
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_BAD_ARGS);
    product(x, RUNS, y);
    x[7] = NAN;
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_BAD_ARGS);
    make_design(x, RUNS);
    /* a term that is zero in every run */
    for (i = 0; i < RUNS; i++)
        x[i * T + 3] = 0.0;
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_RANK);
    /* two terms in a fixed ratio (drawn always half of submitted) */
    make_design(x, RUNS);
    for (i = 0; i < RUNS; i++)
        x[i * T + 2] = 0.5 * x[i * T + 1];
    assert_int_equal(scale_fit_solve(x, y, RUNS, T, &f), SCALE_FIT_RANK);
    assert_true(f.cond > SCALE_FIT_COND_LIMIT);
    /* every status has its own text */
    assert_string_not_equal(scale_fit_strerror(SCALE_FIT_RANK),
                            scale_fit_strerror(SCALE_FIT_BAD_ARGS));
    assert_string_not_equal(scale_fit_strerror(SCALE_FIT_TOO_FEW_RUNS),
                            scale_fit_strerror(SCALE_FIT_OK));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_recovery),
        cmocka_unit_test(test_noisy_matches_normal_equations),
        cmocka_unit_test(test_one_term_by_hand),
        cmocka_unit_test(test_cond_orthogonal),
        cmocka_unit_test(test_cond_known),
        cmocka_unit_test(test_column_scale_invariance),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests_name("scale_fit", tests, NULL, NULL);
}
