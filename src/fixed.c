/* SPDX-License-Identifier: MIT */
/* Fixed-point arithmetic: Q16.16 scalars, trigonometry, square roots, 3x4
 * matrices. Every product is formed in 64 bits and saturated back, so no
 * input can overflow (signed overflow is undefined behaviour in C). */
#include "zs_internal.h"

/* Leading zeros of a non-zero 64-bit value. */
static unsigned clz64(uint64_t v)
{
#if defined(__GNUC__)
    return (unsigned)__builtin_clzll(v);
#else
    unsigned n = 0;
    while (!(v & ((uint64_t)1 << 63))) {
        v <<= 1;
        n++;
    }
    return n;
#endif
}

/* Long division of the 64-bit (nh, nl) by v (top bit set, nh < v) in two
 * base-2^16 digits, each estimated from v's high half and corrected at most
 * twice (the classic schoolbook bound): 32-bit divisions and products only,
 * so no 64-bit division helper is called. */
uint32_t zs_udiv64_32(uint32_t nh, uint32_t nl, uint32_t v)
{
    uint32_t vh = v >> 16, vl = v & 0xFFFFu, n1 = nl >> 16, n0 = nl & 0xFFFFu;
    uint32_t qh, ql, r, rem;
    qh = nh / vh;
    r = nh - qh * vh;
    while (qh > 0xFFFFu || qh * vl > ((r << 16) | n1)) {
        qh--;
        r += vh;
        if (r > 0xFFFFu)
            break;
    }
    /* the partial remainder (nh, n1) - qh * v is below v: mod 2^32 is exact */
    rem = ((nh << 16) | n1) - qh * v;
    ql = rem / vh;
    r = rem - ql * vh;
    while (ql > 0xFFFFu || ql * vl > ((r << 16) | n0)) {
        ql--;
        r += vh;
        if (r > 0xFFFFu)
            break;
    }
    return (qh << 16) + ql;
}

uint32_t zs_recip61(uint32_t d)
{
    return zs_udiv64_32((uint32_t)1 << 30, 0u, d << 1); /* 2^62 / 2d */
}

void zs_recip_init(zs_recip *rc, int64_t d)
{
    uint64_t a = d < 0 ? (uint64_t)0 - (uint64_t)d : (uint64_t)d;
    int e = (int)clz64(a) - 32; /* a * 2^e in [2^31, 2^32) */
    if (e >= 0)
        a <<= e;
    else
        a >>= -e;
    /* (2^63 - 1) / a, in (2^31, 2^32) */
    rc->inv = zs_udiv64_32(0x7FFFFFFFu, 0xFFFFFFFFu, (uint32_t)a);
    rc->exp = e;
    rc->neg = d < 0;
}

int64_t zs_recip_muldiv(const zs_recip *rc, int64_t num, int bits, int64_t limit)
{
    uint64_t n = num < 0 ? (uint64_t)0 - (uint64_t)num : (uint64_t)num, q;
    int t = 0, sh;
    if (n >= ((uint64_t)1 << 31)) { /* keep 31 significant bits: n * inv < 2^63 */
        t = 33 - (int)clz64(n);
        n >>= t;
    }
    sh = 63 - bits - rc->exp - t; /* num * 2^bits / d = n * inv * 2^-sh */
    if (n == 0 || sh >= 64)
        q = 0;
    else if (sh <= 0)
        q = (uint64_t)limit;
    else
        q = zs_umul32((uint32_t)n, rc->inv) >> sh; /* n < 2^31 */
    if (q > (uint64_t)limit)
        q = (uint64_t)limit;
    return ((num < 0) != rc->neg) ? -(int64_t)q : (int64_t)q;
}

/* round(a * b / 65536) for |a| < 2^47, |b| <= 2^31: a split so that no
 * product passes 2^62 (a * b itself may not fit 64 bits). */
int64_t zs_mul_q16_wide(int64_t a, int32_t b)
{
    int64_t hi = zs_asr64(a, 16), lo = a - hi * 65536; /* lo in [0, 65536) */
    return hi * b + zs_asr64(lo * b + 32768, 16);
}

/* The 128-bit product of two 64-bit unsigned values. */
static void mul_64x64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    *lo = (mid << 32) | (p00 & 0xFFFFFFFFu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

int64_t zs_muldiv64(int64_t a, int64_t b, int64_t c, int round)
{
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t uc = (uint64_t)c, hi, lo, q, rem;
    int i;
    mul_64x64(ua, (uint64_t)b, &hi, &lo);
    if (hi == 0) { /* the common case: one division */
        q = lo / uc;
        rem = lo - q * uc;
    } else {
        /* b <= c keeps the quotient below 2^63, so hi < c: long division
         * by bits, the remainder staying below 2c < 2^64 */
        q = 0;
        rem = hi;
        for (i = 63; i >= 0; i--) {
            rem = (rem << 1) | ((lo >> i) & 1u);
            q <<= 1;
            if (rem >= uc) {
                rem -= uc;
                q |= 1u;
            }
        }
    }
    if (round && rem >= uc - rem)
        q++;
    return a < 0 ? -(int64_t)q : (int64_t)q;
}

/* Public results saturate to the full int32 range. */
static ZS_NOINLINE int32_t clamp32(int64_t v)
{
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : (int32_t)v);
}

zs_vec3 zs_vec3_make(zs_fixed x, zs_fixed y, zs_fixed z)
{
    zs_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

zs_fixed zs_fx_mul(zs_fixed a, zs_fixed b)
{
    int64_t p = (int64_t)a * b;
    return clamp32(zs_asr64(p + 32768, 16));
}

zs_fixed zs_fx_div(zs_fixed a, zs_fixed b)
{
    if (b == 0)
        return a < 0 ? -INT32_MAX : INT32_MAX;
    return clamp32(((int64_t)a * 65536) / b);
}

uint32_t zs_isqrt64(uint64_t v)
{
    uint64_t res = 0;
    uint64_t bit = (uint64_t)1 << 62;
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= res + bit) {
            v -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)res;
}

/* a * b in Q30, rounded half up; |a|, |b| <= 2^31. */
static int64_t mul_q30(int64_t a, int64_t b)
{
    return zs_asr64(a * b + ((int64_t)1 << 29), 30);
}

/* Taylor series of sin x / x and cos x for 0 <= x <= pi/4, in Horner form:
 * 1 - x2/6 (1 - x2/20 (1 - ...)), innermost divisor first, 0 ends a list. */
static const uint8_t taylor_div[2][7] = {{110, 72, 42, 20, 6, 0}, {132, 90, 56, 30, 12, 2, 0}};

int32_t zs_sin_q30(zs_fixed deg)
{
    const int32_t full = 360 * 65536;
    const int32_t quarter = 90 * 65536;
    /* pi / 180 in Q40, so degrees Q16 * this >> 26 is radians Q30 */
    const int64_t rad_per_deg_q40 = 19190098281LL;
    const int64_t one = (int64_t)1 << 30;
    int32_t a = deg % full;
    int neg = 0, use_cos;
    const uint8_t *d;
    int64_t x, x2, t = one;
    if (a < 0)
        a += full;
    if (a >= full / 2) { /* sin(a) = -sin(a - 180) */
        a -= full / 2;
        neg = 1;
    }
    if (a > quarter) /* sin(a) = sin(180 - a) */
        a = full / 2 - a;
    /* now 0 <= a <= 90 degrees; beyond 45 it is cos(90 - a) */
    use_cos = a > quarter / 2;
    if (use_cos)
        a = quarter - a;
    x = zs_asr64(a * rad_per_deg_q40 + ((int64_t)1 << 25), 26);
    x2 = mul_q30(x, x);
    /* x2, t <= 2^30 keep each product's quotient below 2^31: a 32-bit
     * division gives the same (non-negative) quotient */
    for (d = taylor_div[use_cos]; *d; d++)
        t = one - (int64_t)((uint32_t)mul_q30(x2, t) / *d);
    if (!use_cos)
        t = mul_q30(x, t);
    if (t > one)
        t = one;
    if (t < 0)
        t = 0;
    return (int32_t)(neg ? -t : t);
}

zs_fixed zs_fx_sin_deg(zs_fixed deg)
{
    return zs_asr32(zs_sin_q30(deg) + 8192, 14); /* |sin| <= 2^30: no overflow */
}

zs_fixed zs_fx_cos_deg(zs_fixed deg)
{
    /* cos(a) = sin(a + 90); reduce first so the addition cannot overflow */
    return zs_fx_sin_deg(deg % (360 * 65536) + 90 * 65536);
}

/* The largest |v[i]| (callers' components are far from INT64_MIN). */
static ZS_NOINLINE int64_t max_abs3(const int64_t v[3])
{
    int64_t m = 0;
    int i;
    for (i = 0; i < 3; i++) {
        int64_t a = v[i] < 0 ? -v[i] : v[i];
        if (a > m)
            m = a;
    }
    return m;
}

void zs_shrink3(int64_t v[3], int64_t limit)
{
    int i;
    while (max_abs3(v) >= limit)
        for (i = 0; i < 3; i++)
            v[i] /= 2;
}

int zs_normalize3(const int64_t v[3], int32_t out[3])
{
    int64_t t[3], m;
    uint64_t len2 = 0;
    uint32_t len;
    int i;
    for (i = 0; i < 3; i++)
        t[i] = v[i];
    /* keep components below 2^30 so the squares sum below 2^62 */
    zs_shrink3(t, (int64_t)1 << 30);
    /* and above 2^20 where possible, for precision */
    while ((m = max_abs3(t)) != 0 && m < ((int64_t)1 << 20))
        for (i = 0; i < 3; i++)
            t[i] *= 2;
    for (i = 0; i < 3; i++)
        len2 += (uint64_t)(t[i] * t[i]);
    len = zs_isqrt64(len2);
    for (i = 0; i < 3; i++) {
        /* round(t * 65536 / len), halves up: floor division, then the
         * remainder against the rest of the divisor (no overflow) */
        int64_t a = t[i] * 65536, q, rem;
        if (len == 0) {
            out[i] = 0;
            continue;
        }
        q = a / len;
        rem = a % len;
        if (rem < 0) {
            q--;
            rem += len;
        }
        if (rem >= (int64_t)len - rem)
            q++;
        out[i] = (int32_t)q;
    }
    return len != 0;
}

void zs_cross3(const int32_t a[3], const int32_t b[3], int64_t out[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        int k1 = k == 2 ? 0 : k + 1, k2 = k == 0 ? 2 : k - 1;
        out[k] = (int64_t)a[k1] * b[k2] - (int64_t)a[k2] * b[k1];
    }
}

int64_t zs_dot3_q16(const int32_t a[3], const int32_t b[3])
{
    int64_t hi = 0, lo = 0;
    int i;
    for (i = 0; i < 3; i++) {
        int64_t p = (int64_t)a[i] * b[i];
        int64_t q = zs_asr64(p, 16);
        hi += q;
        lo += p - q * 65536;
    }
    return hi + zs_asr64(lo + 32768, 16);
}

const zs_mat34 zs_identity34 = {
    {{ZS_FX_ONE, 0, 0, 0}, {0, ZS_FX_ONE, 0, 0}, {0, 0, ZS_FX_ONE, 0}}};

zs_mat34 zs_mat34_identity(void)
{
    return zs_identity34;
}

zs_mat34 zs_mat34_mul(const zs_mat34 *a, const zs_mat34 *b)
{
    zs_mat34 o;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 4; j++) {
            int32_t col[3];
            int64_t s;
            col[0] = b->m[0][j];
            col[1] = b->m[1][j];
            col[2] = b->m[2][j];
            s = zs_dot3_q16(a->m[i], col);
            if (j == 3)
                s += a->m[i][3];
            o.m[i][j] = clamp32(s);
        }
    }
    return o;
}

zs_mat34 zs_mat34_translate(zs_fixed x, zs_fixed y, zs_fixed z)
{
    zs_mat34 m = zs_mat34_identity();
    m.m[0][3] = x;
    m.m[1][3] = y;
    m.m[2][3] = z;
    return m;
}

zs_mat34 zs_mat34_scale(zs_fixed sx, zs_fixed sy, zs_fixed sz)
{
    zs_mat34 m;
    memset(&m, 0, sizeof m);
    m.m[0][0] = sx;
    m.m[1][1] = sy;
    m.m[2][2] = sz;
    return m;
}

/* Rotation in the plane of axes a -> b (counter-clockwise about the third). */
static ZS_NOINLINE zs_mat34 rotation(zs_fixed deg, int a, int b)
{
    zs_mat34 m = zs_mat34_identity();
    zs_fixed c = zs_fx_cos_deg(deg), s = zs_fx_sin_deg(deg);
    m.m[a][a] = c;
    m.m[a][b] = -s;
    m.m[b][a] = s;
    m.m[b][b] = c;
    return m;
}

zs_mat34 zs_mat34_rotate_x(zs_fixed deg)
{
    return rotation(deg, 1, 2);
}

zs_mat34 zs_mat34_rotate_y(zs_fixed deg)
{
    return rotation(deg, 2, 0);
}

zs_mat34 zs_mat34_rotate_z(zs_fixed deg)
{
    return rotation(deg, 0, 1);
}

zs_vec3 zs_mat34_apply(const zs_mat34 *m, zs_vec3 p)
{
    int32_t in[3];
    int32_t out[3];
    int i;
    in[0] = p.x;
    in[1] = p.y;
    in[2] = p.z;
    for (i = 0; i < 3; i++) {
        int64_t s = zs_dot3_q16(m->m[i], in) + m->m[i][3];
        out[i] = clamp32(s);
    }
    return zs_vec3_make(out[0], out[1], out[2]);
}
