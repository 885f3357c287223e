/* SPDX-License-Identifier: MIT */
/*
 * test_fixed: fixed-point primitives against exact integer or double oracles.
 *
 *  - zs_fx_mul: exact round-to-nearest of a*b/65536 (either neighbour accepted
 *    only on an exact .5 tie), saturated to [INT32_MIN, INT32_MAX].
 *  - zs_fx_div: exact truncation of a*65536/b, saturated; b == 0 -> +-INT32_MAX.
 *  - zs_fx_sin_deg / cos_deg: |error| <= SIN_TOL_LSB (8 LSB = 1.22e-4) against
 *    libm on the exactly reduced angle; at multiples of 90 degrees within
 *    SIN_QUAD_TOL_LSB (1 LSB).
 *  - zs_isqrt64: exact floor: r*r <= v < (r+1)^2.
 *  - zs_recip61 (the projection's reciprocal): floor(2^61 / d) equal to the
 *    compiler's 64-bit division for every d in [2^30, 2^31) near the ends,
 *    near powers of two, 16-bit digit boundaries and the rounding points of
 *    its 32-bit division's divisor, and 2M random ones (all 2^30 were checked
 *    once, outside the suite).
 *  - zs_project / zs_project_fast: equal to the projection's arithmetic in
 *    plain 64-bit operations (ref_project) for random screens, depth ranges
 *    and vertices within the guard band and beyond it to 7 w.
 *  - zs_mat34_*: identity/translate/scale exact, mul and apply within 2 LSB of
 *    double math (exact saturation when the result leaves int32), rotations
 *    within the sine tolerance of the double rotation matrices.
 */
#include "zt_test.h"
#include "../../src/zs_internal.h" /* zs_recip61 */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SIN_TOL_LSB 8
#define SIN_QUAD_TOL_LSB 1
#define MAT_TOL_LSB 2
#define SEED 0x5EEDF1ED00000001ull
#define ZT_PI 3.14159265358979323846
/* The header: "saturated to the int32 range", so a negative overflow gives
 * INT32_MIN. (If the header is changed to symmetric +-INT32_MAX saturation,
 * change this to -INT32_MAX; exactly representable results such as
 * INT32_MIN * 1.0 must be exact either way.) */
#define SAT_MIN INT32_MIN

static zt_rng g_rng;
static double g_max_sin_err; /* in LSB */
static unsigned long g_checks;

static int64_t clamp64(int64_t v)
{
    if (v > INT32_MAX) return INT32_MAX;
    if (v < INT32_MIN) return SAT_MIN;
    return v;
}

/* floor division by 65536 for int64 */
static int64_t floordiv16(int64_t p) { return p >= 0 ? p / 65536 : -((-p + 65535) / 65536); }

static void check_mul(int32_t a, int32_t b)
{
    int64_t p = (int64_t)a * (int64_t)b;
    int64_t f = floordiv16(p);
    int64_t rem = p - f * 65536; /* 0..65535 */
    int32_t got = zs_fx_mul(a, b);
    g_checks++;
    if (rem == 32768) {
        int64_t lo = clamp64(f), hi = clamp64(f + 1);
        ZT_CHECK(got == lo || got == hi,
                 "zs_fx_mul(%d, %d) = %d, expected %lld or %lld (tie)", a, b, got,
                 (long long)lo, (long long)hi);
    } else {
        int64_t want = clamp64(rem < 32768 ? f : f + 1);
        ZT_CHECK(got == want, "zs_fx_mul(%d, %d) = %d, expected %lld (seed %llx)", a, b, got,
                 (long long)want, (unsigned long long)SEED);
    }
}

static void check_div(int32_t a, int32_t b)
{
    int32_t got = zs_fx_div(a, b);
    g_checks++;
    if (b == 0) {
        if (a > 0)
            ZT_CHECK(got == INT32_MAX, "zs_fx_div(%d, 0) = %d, expected INT32_MAX", a, got);
        else if (a < 0)
            ZT_CHECK(got == -INT32_MAX, "zs_fx_div(%d, 0) = %d, expected -INT32_MAX", a, got);
        else /* 0/0: the header only says +-INT32_MAX; accept that or 0 */
            ZT_CHECK(got == INT32_MAX || got == -INT32_MAX || got == 0,
                     "zs_fx_div(0, 0) = %d", got);
        return;
    }
    int64_t want = clamp64(((int64_t)a * 65536) / (int64_t)b); /* C truncates */
    ZT_CHECK(got == want, "zs_fx_div(%d, %d) = %d, expected %lld", a, b, got, (long long)want);
}

static int32_t rand_i32(zt_rng *g)
{
    switch (zt_below(g, 6)) {
    case 0: return (int32_t)zt_u32(g);                           /* full range */
    case 1: return (int32_t)zt_range(g, -ZS_FX(4), ZS_FX(4));    /* small */
    case 2: return (int32_t)zt_range(g, -300, 300);              /* tiny */
    case 3: {                                                    /* powers of two +-1 */
        int sh = (int)zt_below(g, 31);
        int32_t v = (int32_t)(1u << sh) + (int32_t)zt_range(g, -1, 1);
        return zt_below(g, 2) ? v : -v;
    }
    case 4: {                                                    /* extremes */
        static const int32_t ex[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1,
                                     0, 1, -1, 65536, -65536, 32768, -32768, 65535, -65535};
        return ex[zt_below(g, (uint32_t)(sizeof ex / sizeof ex[0]))];
    }
    default: return (int32_t)zt_range(g, -ZS_FX(32767), ZS_FX(32767));
    }
}

static void test_mul(void **state)
{
    (void)state;
    static const int32_t ex[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, 0, 1, -1,
                                 2, -2, 32767, 32768, -32768, 65535, 65536, -65536, 65537,
                                 ZS_FX(181), ZS_FX(182), -ZS_FX(182), 0x7FFF8000, -0x7FFF8000};
    size_t nex = sizeof ex / sizeof ex[0];
    /* exactly representable results at the bottom of the range */
    ZT_CHECK(zs_fx_mul(INT32_MIN, ZS_FX_ONE) == INT32_MIN, "zs_fx_mul(INT32_MIN, 1.0) = %d",
             zs_fx_mul(INT32_MIN, ZS_FX_ONE));
    ZT_CHECK(zs_fx_mul(INT32_MIN / 2, ZS_FX(2)) == INT32_MIN, "zs_fx_mul(-2^30, 2.0) = %d",
             zs_fx_mul(INT32_MIN / 2, ZS_FX(2)));
    for (size_t i = 0; i < nex; i++)
        for (size_t j = 0; j < nex; j++) check_mul(ex[i], ex[j]);
    /* identity and exact values */
    for (int k = 0; k < 20000; k++) {
        int32_t a = rand_i32(&g_rng);
        ZT_CHECK(zs_fx_mul(a, ZS_FX_ONE) == a, "zs_fx_mul(%d, 1.0) != %d", a, a);
        ZT_CHECK(zs_fx_mul(ZS_FX_ONE, a) == a, "zs_fx_mul(1.0, %d) != %d", a, a);
        ZT_CHECK(zs_fx_mul(a, 0) == 0, "zs_fx_mul(%d, 0) != 0", a);
    }
    /* the rounding ties: 0.5 LSB and -0.5 LSB products */
    check_mul(1, 32768);
    check_mul(-1, 32768);
    check_mul(3, 32768);
    check_mul(-3, 32768);
    /* just below and above ties */
    check_mul(32767, 1);
    check_mul(32769, 1);
    check_mul(-32767, 1);
    check_mul(-32769, 1);
    /* 2.0 * 3.5 = 7.0, -1.5 * 2.25 = -3.375 */
    ZT_CHECK(zs_fx_mul(ZS_FX(2), ZS_FX(7) / 2) == ZS_FX(7), "2*3.5");
    ZT_CHECK(zs_fx_mul(-ZS_FX(3) / 2, ZS_FX(9) / 4) == -(ZS_FX(27) / 8), "-1.5*2.25");
    /* saturation */
    ZT_CHECK(zs_fx_mul(INT32_MIN, -ZS_FX(1)) == INT32_MAX, "INT32_MIN * -1 must saturate high");
    ZT_CHECK(zs_fx_mul(INT32_MAX, INT32_MAX) == INT32_MAX, "max*max");
    ZT_CHECK(zs_fx_mul(INT32_MIN, INT32_MAX) == SAT_MIN, "min*max");
    ZT_CHECK(zs_fx_mul(ZS_FX(30000), ZS_FX(30000)) == INT32_MAX, "30000^2");
    ZT_CHECK(zs_fx_mul(ZS_FX(-30000), ZS_FX(30000)) == SAT_MIN, "-30000*30000");
    for (int k = 0; k < 300000; k++) {
        int32_t a = rand_i32(&g_rng), b = rand_i32(&g_rng);
        check_mul(a, b);
        if (zs_fx_mul(a, b) != zs_fx_mul(b, a))
            ZT_FAIL("zs_fx_mul not commutative for %d, %d", a, b);
    }
}

static void test_div(void **state)
{
    (void)state;
    static const int32_t ex[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, 0, 1, -1,
                                 2, -2, 3, 32767, 32768, -32768, 65535, 65536, -65536, 65537,
                                 ZS_FX(100), -ZS_FX(100), ZS_FX(32767), -ZS_FX(32767)};
    size_t nex = sizeof ex / sizeof ex[0];
    ZT_CHECK(zs_fx_div(INT32_MIN, ZS_FX_ONE) == INT32_MIN, "zs_fx_div(INT32_MIN, 1.0) = %d",
             zs_fx_div(INT32_MIN, ZS_FX_ONE));
    ZT_CHECK(zs_fx_div(INT32_MIN / 2, ZS_FX_ONE / 2) == INT32_MIN, "zs_fx_div(-2^30, 0.5) = %d",
             zs_fx_div(INT32_MIN / 2, ZS_FX_ONE / 2));
    for (size_t i = 0; i < nex; i++)
        for (size_t j = 0; j < nex; j++) check_div(ex[i], ex[j]);
    /* known values */
    ZT_CHECK(zs_fx_div(ZS_FX(7), ZS_FX(2)) == ZS_FX(7) / 2, "7/2");
    ZT_CHECK(zs_fx_div(ZS_FX(1), ZS_FX(3)) == 21845, "1/3 -> 21845 (trunc)");
    ZT_CHECK(zs_fx_div(-ZS_FX(1), ZS_FX(3)) == -21845, "-1/3 -> -21845 (toward zero)");
    ZT_CHECK(zs_fx_div(ZS_FX(2), ZS_FX(3)) == 43690, "2/3 -> 43690 (trunc, not 43691)");
    ZT_CHECK(zs_fx_div(ZS_FX(-2), ZS_FX(3)) == -43690, "-2/3 toward zero");
    ZT_CHECK(zs_fx_div(ZS_FX(2), ZS_FX(-3)) == -43690, "2/-3 toward zero");
    ZT_CHECK(zs_fx_div(1, 3) == 21845, "tiny");
    /* saturation and division by zero */
    ZT_CHECK(zs_fx_div(INT32_MIN, -ZS_FX(1)) == INT32_MAX, "INT32_MIN / -1");
    ZT_CHECK(zs_fx_div(ZS_FX(20000), 1) == INT32_MAX, "20000 / 2^-16");
    ZT_CHECK(zs_fx_div(-ZS_FX(20000), 1) == SAT_MIN, "-20000 / 2^-16");
    ZT_CHECK(zs_fx_div(ZS_FX(5), 0) == INT32_MAX, "5/0");
    ZT_CHECK(zs_fx_div(-ZS_FX(5), 0) == -INT32_MAX, "-5/0");
    ZT_CHECK(zs_fx_div(INT32_MIN, 0) == -INT32_MAX, "INT32_MIN/0");
    ZT_CHECK(zs_fx_div(1, 0) == INT32_MAX, "1/0");
    for (int k = 0; k < 300000; k++) {
        int32_t a = rand_i32(&g_rng), b = rand_i32(&g_rng);
        check_div(a, b);
    }
}

static double ref_sin_deg(int32_t deg)
{
    double d = fmod((double)deg / 65536.0, 360.0); /* exact */
    return sin(d * (ZT_PI / 180.0));
}
static double ref_cos_deg(int32_t deg)
{
    double d = fmod((double)deg / 65536.0, 360.0);
    return cos(d * (ZT_PI / 180.0));
}

static void check_sincos(int32_t deg, int tol)
{
    double rs = ref_sin_deg(deg) * 65536.0, rc = ref_cos_deg(deg) * 65536.0;
    int32_t s = zs_fx_sin_deg(deg), c = zs_fx_cos_deg(deg);
    double es = fabs(s - rs), ec = fabs(c - rc);
    g_checks += 2;
    if (es > g_max_sin_err) g_max_sin_err = es;
    if (ec > g_max_sin_err) g_max_sin_err = ec;
    ZT_CHECK(es <= tol, "sin_deg(%d = %.6f deg) = %d, libm %.2f (tol %d LSB)", deg,
             deg / 65536.0, s, rs, tol);
    ZT_CHECK(ec <= tol, "cos_deg(%d = %.6f deg) = %d, libm %.2f (tol %d LSB)", deg,
             deg / 65536.0, c, rc, tol);
    ZT_CHECK(s >= -65536 && s <= 65536 && c >= -65536 && c <= 65536,
             "sin/cos out of [-1,1] at %d: %d %d", deg, s, c);
}

static void test_sincos(void **state)
{
    (void)state;
    /* multiples of 90 degrees, many turns either way */
    for (int q = -364; q <= 364; q++) check_sincos(ZS_FX(90) * q, SIN_QUAD_TOL_LSB);
    ZT_CHECK(zs_fx_sin_deg(0) == 0 && zs_fx_cos_deg(0) == ZS_FX_ONE, "sin/cos 0");
    /* every 1/16 degree over [-720, 720] */
    for (int32_t d = -ZS_FX(720); d <= ZS_FX(720); d += ZS_FX(1) / 16) check_sincos(d, SIN_TOL_LSB);
    /* odd fractions, large angles, extremes */
    static const int32_t ex[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, 1, -1,
                                 ZS_FX(360) - 1, ZS_FX(360) + 1, ZS_FX(-360), ZS_FX(32767),
                                 ZS_FX(-32768), ZS_FX(30) , ZS_FX(45), ZS_FX(60)};
    for (size_t i = 0; i < sizeof ex / sizeof ex[0]; i++) check_sincos(ex[i], SIN_TOL_LSB);
    for (int k = 0; k < 200000; k++) check_sincos((int32_t)zt_u32(&g_rng), SIN_TOL_LSB);
    /* identities: sin(-x) == -sin(x) within tolerance, sin(x+360) == sin(x) */
    for (int k = 0; k < 20000; k++) {
        int32_t d = (int32_t)zt_range(&g_rng, -ZS_FX(10000), ZS_FX(10000));
        int32_t a = zs_fx_sin_deg(d), b = zs_fx_sin_deg(d + ZS_FX(360));
        ZT_CHECK(abs(a - b) <= 2 * SIN_TOL_LSB, "sin periodicity at %d: %d vs %d", d, a, b);
    }
}

static void check_isqrt(uint64_t v)
{
    uint32_t r = zs_isqrt64(v);
    g_checks++;
    uint64_t r2 = (uint64_t)r * r;
    ZT_CHECK(r2 <= v, "zs_isqrt64(%llu) = %u too big", (unsigned long long)v, r);
    if (r != UINT32_MAX) {
        uint64_t n2 = ((uint64_t)r + 1) * ((uint64_t)r + 1);
        ZT_CHECK(n2 > v, "zs_isqrt64(%llu) = %u too small", (unsigned long long)v, r);
    }
}

static void check_recip61(uint32_t d)
{
    uint32_t want = (uint32_t)(((uint64_t)1 << 61) / d), got = zs_recip61(d);
    ZT_CHECK(got == want, "zs_recip61(%lu) = %lu, 2^61 / d = %lu", (unsigned long)d,
             (unsigned long)got, (unsigned long)want);
}

static void test_recip61(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, 0x2EC1B61000000001ull);
    for (uint32_t k = 0; k < 70000; k++) {
        check_recip61(0x40000000u + k);
        check_recip61(0x7FFFFFFFu - k);
    }
    /* around every multiple of 2^16 (the divisor's digit split) and the
     * divisors whose first quotient digit needs correcting */
    for (uint32_t hi = 0x4000u; hi < 0x8000u; hi++)
        for (uint32_t lo = 0; lo < 4; lo++) {
            check_recip61((hi << 16) | lo);
            check_recip61((hi << 16) | (0xFFFFu - lo));
        }
    /* around the rounding points of the 32-bit division's divisor (d / 2^15
     * rounded: odd multiples of 2^14), where its estimate is farthest off */
    for (uint32_t hi = 0x8000u; hi < 0x10000u; hi++)
        for (uint32_t lo = 0; lo < 3; lo++) {
            check_recip61(hi * 0x8000u + 0x4000u - 1u - lo);
            check_recip61(hi * 0x8000u + 0x4000u + lo);
        }
    for (int k = 0; k < 2000000; k++)
        check_recip61(0x40000000u + zt_below(&g, 0x40000000u));
}

/* The projection's arithmetic (setup.c) in plain 64-bit operations, the
 * reciprocal by the compiler's division: the reference for zs_project and
 * zs_project_fast. For |xc|, |yc| <= 7 w and w < 2^31 every product fits. */
static int64_t floor_shift(int64_t p, unsigned k)
{
    return p >= 0 ? p >> k : -((-p + ((int64_t)1 << k) - 1) >> k);
}

static int64_t clamp16(int64_t v)
{
    return v < -32767 ? -32767 : (v > 32767 ? 32767 : v);
}

static void ref_project(int32_t width, int32_t height, int32_t near_z, int64_t ds, int64_t xc,
                        int64_t yc, int32_t w, int16_t *x, int16_t *y, uint32_t *z)
{
    unsigned s = 0;
    while (((uint32_t)w << s) < 0x40000000u)
        s++;
    uint64_t inv = ((uint64_t)1 << 61) / ((uint32_t)w << s);
    int64_t hw = 8 * (int64_t)width, hh = 8 * (int64_t)height;
    int64_t nx = floor_shift(xc * (int64_t)inv, 33u - s);
    int64_t ny = floor_shift(yc * (int64_t)inv, 33u - s);
    int64_t q = (int64_t)(((uint64_t)near_z * inv) >> (31u - s));
    int64_t zz = q >= ((int64_t)1 << 30) ? 0 : (int64_t)((((uint64_t)1 << 30) - (uint64_t)q) * (uint64_t)ds >> 30);
    *x = (int16_t)clamp16(hw + floor_shift(nx * hw + ((int64_t)1 << 27), 28));
    *y = (int16_t)clamp16(hh - floor_shift(ny * hh + ((int64_t)1 << 27), 28));
    *z = (uint32_t)(zz > ((int64_t)1 << 30) ? ((int64_t)1 << 30) : zz);
}

/* zs_project_fast (the 32-bit projection of the draw loop) and zs_project
 * against ref_project: random screens, depth ranges and vertices, inside the
 * guard band (inside set: no clamps) and out to 7 w (clamped), w at near,
 * far and powers of two, x and y at the band's edges. */
static void test_project_fast(void **state)
{
    (void)state;
    zt_rng g;
    unsigned long bad = 0;
    zt_rng_seed(&g, 0x9E0FA57000000001ull);
    for (int k = 0; k < 400000; k++) {
        zs_renderer r;
        zs_proj p;
        memset(&r, 0, sizeof r);
        r.cfg.width = (uint16_t)zt_range(&g, 1, ZS_MAX_DIM);
        r.cfg.height = (uint16_t)zt_range(&g, 1, ZS_MAX_DIM);
        uint32_t dim = r.cfg.width > r.cfg.height ? r.cfg.width : r.cfg.height;
        int32_t guard = (int32_t)(32767u / (8u * dim)) - 1;
        guard = guard > ZS_GUARD_MAX ? ZS_GUARD_MAX : guard;
        r.priv.guard = guard;
        /* w up to 2^29 (where ref_project's products fit): zs_project's
         * 64-bit path from 2^28, or for |xc| past 2^31 */
        int32_t n = (int32_t)zt_range(&g, 1, (k & 1) ? 1 << 12 : 1 << 22);
        int32_t f = (int32_t)zt_range(&g, n + 1, (k & 4) ? (1 << 29) - 1 : (1 << 24));
        r.cam.near_z = n;
        r.cam.far_z = f;
        if (!((int64_t)f < 8 * ((int64_t)f - n)))
            continue; /* depth_scale 0: zs_project's division */
        r.priv.depth_scale = ((int64_t)f << 30) / ((int64_t)f - n);
        zs_proj_init(&r, &p);
        int32_t w;
        switch (k % 5) {
        case 0: w = n; break;
        case 1: w = f; break;
        case 2: {
            int32_t e = 31 - __builtin_clz((uint32_t)f);
            w = (int32_t)1 << zt_below(&g, (uint32_t)e + 1u);
            if (w < n) w = n;
            break;
        }
        default: w = (int32_t)zt_range(&g, n, f); break;
        }
        int in_band = (k & 2) != 0;
        int64_t lim = in_band ? (int64_t)guard * w : 7 * (int64_t)w;
        int64_t xc = (k % 11) == 3 ? lim : zt_range(&g, -lim, lim);
        int64_t yc = (k % 13) == 4 ? -lim : zt_range(&g, -lim, lim);
        int16_t rx, ry, gx, gy;
        uint32_t rz, gz;
        ref_project(r.cfg.width, r.cfg.height, n, r.priv.depth_scale, xc, yc, w, &rx, &ry, &rz);
        zs_project(&r, xc, yc, w, &gx, &gy, &gz);
        g_checks++;
        if (gx != rx || gy != ry || gz != rz) {
            if (bad++ < 5)
                ZT_CHECK(0, "zs_project w=%ld xc=%lld yc=%lld: (%d,%d,%lu) want (%d,%d,%lu)",
                         (long)w, (long long)xc, (long long)yc, gx, gy, (unsigned long)gz, rx, ry,
                         (unsigned long)rz);
        }
        if (xc <= INT32_MAX && xc >= -INT32_MAX && yc <= INT32_MAX && yc >= -INT32_MAX) {
            zs_vert v;
            zs_project_fast(&p, (int32_t)xc, (int32_t)yc, w, &v, 0);
            if (v.x != rx || v.y != ry || v.z != rz) {
                if (bad++ < 5)
                    ZT_CHECK(0, "zs_project_fast w=%ld xc=%lld yc=%lld: (%d,%d,%lu) want (%d,%d,%lu)",
                             (long)w, (long long)xc, (long long)yc, v.x, v.y, (unsigned long)v.z,
                             rx, ry, (unsigned long)rz);
            }
            if (in_band) {
                zs_project_fast(&p, (int32_t)xc, (int32_t)yc, w, &v, 1);
                if (v.x != rx || v.y != ry || v.z != rz) {
                    if (bad++ < 5)
                        ZT_CHECK(0, "zs_project_fast (inside) w=%ld xc=%lld yc=%lld: (%d,%d,%lu) "
                                    "want (%d,%d,%lu)",
                                 (long)w, (long long)xc, (long long)yc, v.x, v.y,
                                 (unsigned long)v.z, rx, ry, (unsigned long)rz);
                }
            }
        }
    }
    ZT_CHECK(bad == 0, "%lu projections differ", bad);
}

static void check_udiv(uint32_t nh, uint32_t nl, uint32_t v)
{
    uint64_t n = ((uint64_t)nh << 32) | nl;
    uint32_t want = (uint32_t)(n / v), got = zs_udiv64_32(nh, nl, v);
    ZT_CHECK(got == want, "zs_udiv64_32(%lx:%08lx / %08lx) = %08lx, want %08lx",
             (unsigned long)nh, (unsigned long)nl, (unsigned long)v, (unsigned long)got,
             (unsigned long)want);
    g_checks++;
}

/* zs_udiv64_32 (the reciprocal of a triangle's area, and zs_recip61) against
 * the compiler's 64-bit division: the area reciprocal's numerator 2^63 - 1 for
 * divisors near the ends, the 16-bit digit boundaries and at random; random
 * numerators with nh < v; the largest numerators for each divisor. */
static void test_udiv64_32(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, 0x0D1F643200000001ull);
    for (uint32_t k = 0; k < 70000; k++) {
        check_udiv(0x7FFFFFFFu, 0xFFFFFFFFu, 0x80000000u + k);
        check_udiv(0x7FFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu - k);
    }
    for (uint32_t hi = 0x8000u; hi <= 0xFFFFu; hi++)
        for (uint32_t lo = 0; lo < 3; lo++) {
            check_udiv(0x7FFFFFFFu, 0xFFFFFFFFu, (hi << 16) | lo);
            check_udiv(0x7FFFFFFFu, 0xFFFFFFFFu, (hi << 16) | (0xFFFFu - lo));
        }
    for (int k = 0; k < 2000000; k++) {
        uint32_t v = 0x80000000u | zt_u32(&g);
        uint32_t nh = zt_below(&g, v), nl = zt_u32(&g);
        check_udiv(nh, nl, v);
        check_udiv(v - 1u, 0xFFFFFFFFu, v); /* the largest numerator */
        check_udiv(0x7FFFFFFFu, 0xFFFFFFFFu, v);
    }
}

static void test_isqrt(void **state)
{
    (void)state;
    ZT_CHECK(zs_isqrt64(0) == 0, "isqrt(0)");
    ZT_CHECK(zs_isqrt64(1) == 1, "isqrt(1)");
    ZT_CHECK(zs_isqrt64(2) == 1, "isqrt(2)");
    ZT_CHECK(zs_isqrt64(3) == 1, "isqrt(3)");
    ZT_CHECK(zs_isqrt64(4) == 2, "isqrt(4)");
    ZT_CHECK(zs_isqrt64(UINT64_MAX) == UINT32_MAX, "isqrt(UINT64_MAX) = %u",
             zs_isqrt64(UINT64_MAX));
    uint64_t top = (uint64_t)UINT32_MAX * UINT32_MAX;
    ZT_CHECK(zs_isqrt64(top) == UINT32_MAX, "isqrt((2^32-1)^2)");
    ZT_CHECK(zs_isqrt64(top - 1) == UINT32_MAX - 1, "isqrt((2^32-1)^2 - 1)");
    for (uint64_t v = 0; v < 70000; v++) check_isqrt(v);
    for (int b = 0; b < 64; b++) {
        uint64_t p = (uint64_t)1 << b;
        check_isqrt(p);
        check_isqrt(p - 1);
        check_isqrt(p + 1);
    }
    for (int k = 0; k < 100000; k++) {
        uint64_t r = zt_u64(&g_rng) >> zt_below(&g_rng, 33); /* r up to 2^64-1 -> use 32 bits */
        uint32_t s = (uint32_t)(r >> 32) | (uint32_t)zt_below(&g_rng, 2);
        uint64_t sq = (uint64_t)s * s;
        ZT_CHECK(zs_isqrt64(sq) == s, "isqrt(%u^2) = %u", s, zs_isqrt64(sq));
        if (sq) check_isqrt(sq - 1);
        check_isqrt(sq + 1);
        check_isqrt(zt_u64(&g_rng) >> zt_below(&g_rng, 64));
    }
}

/* ---------------- matrices ---------------- */

typedef struct {
    double m[3][4];
} dmat;

static dmat to_d(const zs_mat34 *a)
{
    dmat d;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) d.m[i][j] = a->m[i][j] / 65536.0;
    return d;
}

static dmat dmul(const dmat *a, const dmat *b)
{
    dmat o;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double s = j == 3 ? a->m[i][3] : 0.0;
            for (int k = 0; k < 3; k++) s += a->m[i][k] * b->m[k][j];
            o.m[i][j] = s;
        }
    return o;
}

/* |got - want| <= tol LSB, or exact saturation when want leaves the range */
static void check_fx_near(int32_t got, double want, double tol, const char *what, int i, int j)
{
    double w = want * 65536.0;
    g_checks++;
    if (w >= 2147483647.5) {
        ZT_CHECK(got == INT32_MAX, "%s[%d][%d] = %d, expected saturation to INT32_MAX (%.1f)",
                 what, i, j, got, w);
    } else if (w <= -2147483648.5) {
        ZT_CHECK(got == SAT_MIN, "%s[%d][%d] = %d, expected saturation to INT32_MIN (%.1f)",
                 what, i, j, got, w);
    } else {
        ZT_CHECK(fabs(got - w) <= tol, "%s[%d][%d] = %d, expected %.3f (tol %.1f LSB)", what,
                 i, j, got, w, tol);
    }
}

static void check_mat(const zs_mat34 *got, const dmat *want, double tol, const char *what)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) check_fx_near(got->m[i][j], want->m[i][j], tol, what, i, j);
}

static zs_mat34 rand_mat(zt_rng *g, int32_t lim)
{
    zs_mat34 m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) m.m[i][j] = (int32_t)zt_range(g, -lim, lim);
    return m;
}

static void test_mat_basic(void **state)
{
    (void)state;
    zs_mat34 id = zs_mat34_identity();
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            ZT_CHECK(id.m[i][j] == (i == j ? ZS_FX_ONE : 0), "identity[%d][%d] = %d", i, j,
                     id.m[i][j]);
    zs_vec3 v = zs_vec3_make(INT32_MIN, INT32_MAX, -7);
    ZT_CHECK(v.x == INT32_MIN && v.y == INT32_MAX && v.z == -7, "vec3_make");

    zs_mat34 t = zs_mat34_translate(ZS_FX(3), -ZS_FX(5), 123);
    zs_mat34 s = zs_mat34_scale(ZS_FX(2), -ZS_FX(1) / 2, 7);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            ZT_CHECK(t.m[i][j] == (i == j ? ZS_FX_ONE : 0), "translate[%d][%d]", i, j);
            int32_t sd[3] = {ZS_FX(2), -ZS_FX(1) / 2, 7};
            ZT_CHECK(s.m[i][j] == (i == j ? sd[i] : 0), "scale[%d][%d]", i, j);
        }
    ZT_CHECK(t.m[0][3] == ZS_FX(3) && t.m[1][3] == -ZS_FX(5) && t.m[2][3] == 123, "translate col");
    ZT_CHECK(s.m[0][3] == 0 && s.m[1][3] == 0 && s.m[2][3] == 0, "scale col");

    /* identity is neutral (exactly) for random matrices */
    for (int k = 0; k < 2000; k++) {
        zs_mat34 a = rand_mat(&g_rng, ZS_FX(1000));
        zs_mat34 l = zs_mat34_mul(&id, &a), r = zs_mat34_mul(&a, &id);
        ZT_CHECK(memcmp(&l, &a, sizeof a) == 0, "I*A != A");
        ZT_CHECK(memcmp(&r, &a, sizeof a) == 0, "A*I != A");
        zs_vec3 p = zs_vec3_make((int32_t)zt_u32(&g_rng), (int32_t)zt_u32(&g_rng),
                                 (int32_t)zt_u32(&g_rng));
        zs_vec3 q = zs_mat34_apply(&id, p);
        ZT_CHECK(q.x == p.x && q.y == p.y && q.z == p.z, "identity apply (%d,%d,%d)", p.x, p.y,
                 p.z);
    }
    /* translate applies exactly, scale applies as zs_fx_mul */
    zs_vec3 p = zs_mat34_apply(&t, zs_vec3_make(ZS_FX(1), ZS_FX(2), ZS_FX(3)));
    ZT_CHECK(p.x == ZS_FX(4) && p.y == -ZS_FX(3) && p.z == ZS_FX(3) + 123, "translate apply");
    p = zs_mat34_apply(&s, zs_vec3_make(ZS_FX(1), ZS_FX(2), ZS_FX(3)));
    ZT_CHECK(p.x == ZS_FX(2) && p.y == -ZS_FX(1) && abs(p.z - 21) <= 1, "scale apply %d %d %d",
             p.x, p.y, p.z);
}

static void test_mat_mul_apply(void **state)
{
    (void)state;
    /* order: a*b applies b first */
    zs_mat34 tr = zs_mat34_translate(ZS_FX(1), 0, 0), rz = zs_mat34_rotate_z(ZS_FX(90));
    zs_mat34 m = zs_mat34_mul(&tr, &rz);
    zs_vec3 p = zs_mat34_apply(&m, zs_vec3_make(ZS_FX(1), 0, 0));
    ZT_CHECK(abs(p.x - ZS_FX(1)) <= 2 && abs(p.y - ZS_FX(1)) <= 2 && abs(p.z) <= 2,
             "translate*rotz(90) on (1,0,0) = (%d,%d,%d), expected (1,1,0)", p.x, p.y, p.z);

    for (int k = 0; k < 20000; k++) {
        int32_t lim = zt_below(&g_rng, 2) ? ZS_FX(4) : ZS_FX(200);
        zs_mat34 a = rand_mat(&g_rng, lim), b = rand_mat(&g_rng, lim);
        dmat da = to_d(&a), db = to_d(&b);
        zs_mat34 c = zs_mat34_mul(&a, &b);
        dmat dc = dmul(&da, &db);
        check_mat(&c, &dc, MAT_TOL_LSB, "mul");
        /* apply against double */
        zs_vec3 v = zs_vec3_make((int32_t)zt_range(&g_rng, -ZS_FX(300), ZS_FX(300)),
                                 (int32_t)zt_range(&g_rng, -ZS_FX(300), ZS_FX(300)),
                                 (int32_t)zt_range(&g_rng, -ZS_FX(300), ZS_FX(300)));
        zs_vec3 r = zs_mat34_apply(&a, v);
        double dv[3] = {v.x / 65536.0, v.y / 65536.0, v.z / 65536.0};
        int32_t rg[3] = {r.x, r.y, r.z};
        for (int i = 0; i < 3; i++) {
            double w = da.m[i][3];
            for (int j = 0; j < 3; j++) w += da.m[i][j] * dv[j];
            check_fx_near(rg[i], w, MAT_TOL_LSB, "apply", i, 0);
        }
    }
    /* saturation of products and sums */
    zs_mat34 big = zs_mat34_scale(ZS_FX(30000), ZS_FX(30000), ZS_FX(-30000));
    zs_mat34 bb = zs_mat34_mul(&big, &big);
    dmat dbig = to_d(&big), dbb = dmul(&dbig, &dbig);
    check_mat(&bb, &dbb, MAT_TOL_LSB, "mul(sat)");
    zs_mat34 nb = zs_mat34_scale(ZS_FX(-30000), ZS_FX(30000), ZS_FX(1));
    zs_mat34 nbb = zs_mat34_mul(&nb, &big);
    dmat dnb = to_d(&nb), dnbb = dmul(&dnb, &dbig);
    check_mat(&nbb, &dnbb, MAT_TOL_LSB, "mul(sat-)");
    zs_mat34 t1 = zs_mat34_translate(ZS_FX(20000), -ZS_FX(20000), ZS_FX(1));
    zs_mat34 tt = zs_mat34_mul(&t1, &t1);
    ZT_CHECK(tt.m[0][3] == INT32_MAX && tt.m[1][3] == SAT_MIN && tt.m[2][3] == ZS_FX(2),
             "translate sum saturation: %d %d %d", tt.m[0][3], tt.m[1][3], tt.m[2][3]);
    zs_vec3 e = zs_mat34_apply(&big, zs_vec3_make(ZS_FX(32767), -ZS_FX(32767), INT32_MIN));
    ZT_CHECK(e.x == INT32_MAX && e.y == SAT_MIN && e.z == INT32_MAX,
             "apply saturation: %d %d %d", e.x, e.y, e.z);
    e = zs_mat34_apply(&t1, zs_vec3_make(INT32_MAX, INT32_MIN, INT32_MAX));
    ZT_CHECK(e.x == INT32_MAX && e.y == SAT_MIN && e.z == INT32_MAX,
             "apply translate saturation: %d %d %d", e.x, e.y, e.z);
    /* int16 mesh extremes times a scale, as the transform sees them */
    zs_mat34 sc = zs_mat34_scale(ZS_FX(1), ZS_FX(1), ZS_FX(1));
    e = zs_mat34_apply(&sc, zs_vec3_make(ZS_FX(-32768), ZS_FX(32767), 0));
    ZT_CHECK(e.x == ZS_FX(-32768) && e.y == ZS_FX(32767) && e.z == 0, "int16 extremes apply");
}

static void rot_ref(int axis, double deg, dmat *o)
{
    double a = fmod(deg, 360.0) * ZT_PI / 180.0, c = cos(a), s = sin(a);
    memset(o, 0, sizeof *o);
    if (axis == 0) {
        o->m[0][0] = 1;
        o->m[1][1] = c;
        o->m[1][2] = -s;
        o->m[2][1] = s;
        o->m[2][2] = c;
    } else if (axis == 1) {
        o->m[1][1] = 1;
        o->m[0][0] = c;
        o->m[0][2] = s;
        o->m[2][0] = -s;
        o->m[2][2] = c;
    } else {
        o->m[2][2] = 1;
        o->m[0][0] = c;
        o->m[0][1] = -s;
        o->m[1][0] = s;
        o->m[1][1] = c;
    }
}

static zs_mat34 rot(int axis, int32_t deg)
{
    return axis == 0 ? zs_mat34_rotate_x(deg) : axis == 1 ? zs_mat34_rotate_y(deg)
                                                          : zs_mat34_rotate_z(deg);
}

static void test_mat_rotate(void **state)
{
    (void)state;
    /* direction: +90 about x takes y to z; about y takes z to x; about z takes x to y */
    zs_vec3 p;
    zs_mat34 m = zs_mat34_rotate_x(ZS_FX(90));
    p = zs_mat34_apply(&m, zs_vec3_make(0, ZS_FX(1), 0));
    ZT_CHECK(abs(p.x) <= 1 && abs(p.y) <= 1 && abs(p.z - ZS_FX(1)) <= 1, "rotx(90) y -> (%d,%d,%d)",
             p.x, p.y, p.z);
    m = zs_mat34_rotate_y(ZS_FX(90));
    p = zs_mat34_apply(&m, zs_vec3_make(0, 0, ZS_FX(1)));
    ZT_CHECK(abs(p.x - ZS_FX(1)) <= 1 && abs(p.y) <= 1 && abs(p.z) <= 1, "roty(90) z -> (%d,%d,%d)",
             p.x, p.y, p.z);
    m = zs_mat34_rotate_z(ZS_FX(90));
    p = zs_mat34_apply(&m, zs_vec3_make(ZS_FX(1), 0, 0));
    ZT_CHECK(abs(p.x) <= 1 && abs(p.y - ZS_FX(1)) <= 1 && abs(p.z) <= 1, "rotz(90) x -> (%d,%d,%d)",
             p.x, p.y, p.z);
    for (int axis = 0; axis < 3; axis++) {
        for (int k = 0; k < 5000; k++) {
            int32_t deg = k < 16 ? ZS_FX(45) * (k - 8) : (int32_t)zt_range(&g_rng, -ZS_FX(1000), ZS_FX(1000));
            if (k == 16) deg = INT32_MIN;
            if (k == 17) deg = INT32_MAX;
            zs_mat34 r = rot(axis, deg);
            dmat d;
            rot_ref(axis, deg / 65536.0, &d);
            check_mat(&r, &d, SIN_TOL_LSB, axis == 0 ? "rotx" : axis == 1 ? "roty" : "rotz");
        }
    }
    /* composition: four 90-degree turns about z return a vector to itself */
    m = zs_mat34_identity();
    zs_mat34 q = zs_mat34_rotate_z(ZS_FX(90));
    for (int i = 0; i < 4; i++) m = zs_mat34_mul(&q, &m);
    p = zs_mat34_apply(&m, zs_vec3_make(ZS_FX(3), ZS_FX(5), ZS_FX(7)));
    ZT_CHECK(abs(p.x - ZS_FX(3)) <= 16 && abs(p.y - ZS_FX(5)) <= 16 && abs(p.z - ZS_FX(7)) <= 16,
             "rotz(90)^4 (%d,%d,%d)", p.x, p.y, p.z);
}

int main(void)
{
    zt_rng_seed(&g_rng, SEED);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mul),          cmocka_unit_test(test_div),
        cmocka_unit_test(test_sincos),       cmocka_unit_test(test_isqrt),
        cmocka_unit_test(test_mat_basic),    cmocka_unit_test(test_mat_mul_apply),
        cmocka_unit_test(test_mat_rotate),   cmocka_unit_test(test_recip61), cmocka_unit_test(test_udiv64_32),
        cmocka_unit_test(test_project_fast),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    printf("test_fixed: seed %llx, %lu value checks, max sin/cos error %.2f LSB (tol %d, quadrants "
           "%d), %d failed\n",
           (unsigned long long)SEED, g_checks, g_max_sin_err, SIN_TOL_LSB, SIN_QUAD_TOL_LSB, rc);
    fflush(stdout);
    return rc;
}
