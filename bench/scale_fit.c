/* SPDX-License-Identifier: MIT */
/* Weighted linear least squares for the scaling benchmark; see scale_fit.h. */
#include "scale_fit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define N SCALE_FIT_MAX_TERMS

/* Eigenvalues of the symmetric n x n matrix s (destroyed) by cyclic Jacobi
 * rotations: small, and accurate for the tiny matrices of a cost model. */
static void sym_eigenvalues(double s[N][N], int n, double *ev)
{
    int sweep, p, q, k;
    for (sweep = 0; sweep < 100; sweep++) {
        double off = 0.0;
        for (p = 0; p < n; p++)
            for (q = p + 1; q < n; q++)
                off += s[p][q] * s[p][q];
        if (off < 1e-300)
            break;
        for (p = 0; p < n; p++) {
            for (q = p + 1; q < n; q++) {
                double theta, t, c, sn;
                if (s[p][q] == 0.0)
                    continue;
                theta = (s[q][q] - s[p][p]) / (2.0 * s[p][q]);
                t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                c = 1.0 / sqrt(t * t + 1.0);
                sn = t * c;
                for (k = 0; k < n; k++) { /* columns p, q */
                    double kp = s[k][p], kq = s[k][q];
                    s[k][p] = c * kp - sn * kq;
                    s[k][q] = sn * kp + c * kq;
                }
                for (k = 0; k < n; k++) { /* rows p, q */
                    double pk = s[p][k], qk = s[q][k];
                    s[p][k] = c * pk - sn * qk;
                    s[q][k] = sn * pk + c * qk;
                }
            }
        }
    }
    for (k = 0; k < n; k++)
        ev[k] = s[k][k];
}

/* 2-norm condition number of the upper triangular n x n r: the square root
 * of the ratio of the extreme eigenvalues of r^T r. */
static double cond_of_r(double r[N][N], int n)
{
    double s[N][N], ev[N], lo, hi;
    int i, j, k;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            double v = 0.0;
            for (k = 0; k < n; k++)
                v += r[k][i] * r[k][j];
            s[i][j] = v;
        }
    sym_eigenvalues(s, n, ev);
    lo = hi = fabs(ev[0]);
    for (i = 1; i < n; i++) {
        if (fabs(ev[i]) < lo)
            lo = fabs(ev[i]);
        if (fabs(ev[i]) > hi)
            hi = fabs(ev[i]);
    }
    return lo > 0.0 ? sqrt(hi / lo) : INFINITY;
}

scale_fit_status scale_fit_solve(const double *x, const double *y, int m, int n,
                                 scale_fit *out)
{
    double *a, *b, scale[N], r[N][N], gamma[N];
    double mean = 0.0, ss_tot = 0.0, ss_res = 0.0;
    int i, j, k;
    scale_fit_status st = SCALE_FIT_OK;
    memset(out, 0, sizeof *out);
    out->n_runs = m;
    out->n_terms = n;
    if (n < 1 || n > N || m < 0)
        return SCALE_FIT_BAD_ARGS;
    if (m < n)
        return SCALE_FIT_TOO_FEW_RUNS;
    for (i = 0; i < m; i++) {
        if (!(y[i] > 0.0) || !isfinite(y[i]))
            return SCALE_FIT_BAD_ARGS;
        for (j = 0; j < n; j++)
            if (!isfinite(x[i * n + j]))
                return SCALE_FIT_BAD_ARGS;
    }
    a = malloc(sizeof *a * (size_t)m * (size_t)n);
    b = malloc(sizeof *b * (size_t)m);
    if (!a || !b) {
        free(a);
        free(b);
        return SCALE_FIT_BAD_ARGS;
    }
    /* weighted rows (divided by y_i: relative errors), then unit columns */
    for (i = 0; i < m; i++) {
        for (j = 0; j < n; j++)
            a[i * n + j] = x[i * n + j] / y[i];
        b[i] = 1.0;
    }
    for (j = 0; j < n; j++) {
        double s = 0.0;
        for (i = 0; i < m; i++)
            s += a[i * n + j] * a[i * n + j];
        scale[j] = sqrt(s);
        if (scale[j] == 0.0) {
            out->cond = INFINITY;
            st = SCALE_FIT_RANK;
            goto done;
        }
        for (i = 0; i < m; i++)
            a[i * n + j] /= scale[j];
    }
    /* Householder QR: column k's reflection zeroes it below the diagonal;
     * applied to the later columns and to b as it goes. */
    for (k = 0; k < n; k++) {
        double norm = 0.0, alpha, vtv, *v = NULL;
        for (i = k; i < m; i++)
            norm += a[i * n + k] * a[i * n + k];
        norm = sqrt(norm);
        if (norm == 0.0) {
            out->cond = INFINITY;
            st = SCALE_FIT_RANK;
            goto done;
        }
        alpha = a[k * n + k] > 0 ? -norm : norm; /* no cancellation in v[0] */
        v = malloc(sizeof *v * (size_t)(m - k));
        if (!v) {
            st = SCALE_FIT_BAD_ARGS;
            goto done;
        }
        for (i = k; i < m; i++)
            v[i - k] = a[i * n + k];
        v[0] -= alpha;
        vtv = 0.0;
        for (i = 0; i < m - k; i++)
            vtv += v[i] * v[i];
        for (j = k; j < n; j++) {
            double d = 0.0;
            for (i = k; i < m; i++)
                d += v[i - k] * a[i * n + j];
            d = 2.0 * d / vtv;
            for (i = k; i < m; i++)
                a[i * n + j] -= d * v[i - k];
        }
        {
            double d = 0.0;
            for (i = k; i < m; i++)
                d += v[i - k] * b[i];
            d = 2.0 * d / vtv;
            for (i = k; i < m; i++)
                b[i] -= d * v[i - k];
        }
        free(v);
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
            r[i][j] = j >= i ? a[i * n + j] : 0.0;
    out->cond = cond_of_r(r, n);
    if (!(out->cond <= SCALE_FIT_COND_LIMIT)) {
        st = SCALE_FIT_RANK;
        goto done;
    }
    for (i = n - 1; i >= 0; i--) {
        double s = b[i];
        for (j = i + 1; j < n; j++)
            s -= r[i][j] * gamma[j];
        gamma[i] = s / r[i][i];
    }
    for (j = 0; j < n; j++)
        out->coef[j] = gamma[j] / scale[j];
    for (i = 0; i < m; i++)
        mean += y[i] / m;
    for (i = 0; i < m; i++) {
        double e = y[i] - scale_fit_eval(out, x + (size_t)i * (size_t)n);
        ss_res += e * e;
        ss_tot += (y[i] - mean) * (y[i] - mean);
        if (fabs(e) / y[i] > out->max_rel_err)
            out->max_rel_err = fabs(e) / y[i];
    }
    out->r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : 1.0;
done:
    free(a);
    free(b);
    return st;
}

double scale_fit_eval(const scale_fit *fit, const double *x_row)
{
    double s = 0.0;
    int j;
    for (j = 0; j < fit->n_terms; j++)
        s += fit->coef[j] * x_row[j];
    return s;
}

const char *scale_fit_strerror(scale_fit_status st)
{
    switch (st) {
    case SCALE_FIT_OK:
        return "ok";
    case SCALE_FIT_TOO_FEW_RUNS:
        return "fewer runs than terms in the model";
    case SCALE_FIT_BAD_ARGS:
        return "bad input (term count, a non-positive instruction count, or a value that "
               "is not finite)";
    case SCALE_FIT_RANK:
        return "the runs cannot tell the terms apart (rank deficient or condition number "
               "above the limit)";
    }
    return "unknown status";
}
