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

/* (A small build divides by libgcc's helper instead: the same quotients, no
 * table.) */
#if defined(ZS_SPLIT_MUL) && !ZS_SMALL_
#define RECIP_DIGITS 1
#endif

#ifdef RECIP_DIGITS
/* Cortex-M0 has no divide instruction: a 32/16 quotient by libgcc's
 * __aeabi_uidivmod costs about 90 instructions, and the long division below
 * needs two. There both digits divide by the same d = v >> 16 in [2^15, 2^16),
 * so d's reciprocal is made once, from a table and one Newton step, and the
 * digits come from products (16 x 16 bits each: single multiplies), then
 * exact corrections: the results are those of the divisions. */

/* 2^31 / (2^15 + 256 i + 128), rounded: the reciprocal at the middle of the
 * i-th run of 256 divisors (relative error below 2^-8 over the run). */
static const uint16_t k_recip15[128] = {
    65281u, 64777u, 64281u, 63792u, 63310u, 62836u, 62369u, 61909u,
    61455u, 61008u, 60568u, 60133u, 59705u, 59283u, 58867u, 58457u,
    58053u, 57654u, 57260u, 56872u, 56489u, 56111u, 55738u, 55370u,
    55007u, 54649u, 54295u, 53946u, 53601u, 53261u, 52925u, 52593u,
    52265u, 51942u, 51622u, 51306u, 50995u, 50686u, 50382u, 50081u,
    49784u, 49490u, 49200u, 48913u, 48630u, 48349u, 48072u, 47798u,
    47528u, 47260u, 46995u, 46733u, 46474u, 46218u, 45965u, 45714u,
    45467u, 45222u, 44979u, 44739u, 44502u, 44267u, 44035u, 43805u,
    43577u, 43352u, 43129u, 42908u, 42690u, 42474u, 42260u, 42048u,
    41838u, 41631u, 41425u, 41222u, 41020u, 40820u, 40623u, 40427u,
    40233u, 40041u, 39851u, 39662u, 39476u, 39291u, 39108u, 38926u,
    38746u, 38568u, 38392u, 38217u, 38044u, 37872u, 37702u, 37533u,
    37366u, 37200u, 37036u, 36873u, 36712u, 36552u, 36393u, 36236u,
    36080u, 35926u, 35772u, 35620u, 35470u, 35320u, 35172u, 35026u,
    34880u, 34735u, 34592u, 34450u, 34309u, 34169u, 34031u, 33893u,
    33757u, 33622u, 33487u, 33354u, 33222u, 33091u, 32961u, 32832u,
};

/* floor(2^31 / d) for d in [2^15, 2^16) (at most 2^16). */
static ZS_INLINE_ALWAYS uint32_t recip15(uint32_t d)
{
    uint32_t x = k_recip15[(d >> 8) - 128u], p;
    /* one Newton step x += x (2^31 - d x) / 2^31: |2^31 - d x| < 2^23, so
     * e / 2^9 fits 15 bits and x * (e / 2^9) stays below 2^31 */
    uint32_t dx = d * x; /* within 2^31 +- 2^23 */
    int32_t e = dx <= 0x80000000u ? (int32_t)(0x80000000u - dx) : -(int32_t)(dx - 0x80000000u);
    int32_t c = (int32_t)x * zs_asr32(e, 9);
    x = (uint32_t)((int32_t)x + zs_asr32(c, 22));
    /* now within a few units of the floor: exact by the remainder */
    p = d * x;
    while (p > 0x80000000u) {
        x--;
        p -= d;
    }
    while (0x80000000u - p >= d) {
        x++;
        p += d;
    }
    return x;
}

/* floor(n / d) for any n, d in [2^15, 2^16), inv = floor(2^31 / d); the
 * remainder in *rem. The product estimate is at most 3 short of the
 * quotient (inv is short of 2^31 / d by under 1, n < 2^32). */
static uint32_t div_by_recip(uint32_t n, uint32_t d, uint32_t inv, uint32_t *rem)
{
    uint32_t q = (((n >> 16) * inv) + (((n & 0xFFFFu) * inv) >> 16)) >> 15;
    uint32_t r = n - q * d;
    while (r >= d) {
        r -= d;
        q++;
    }
    *rem = r;
    return q;
}
#endif

/* Long division of the 64-bit (nh, nl) by v (top bit set, nh < v) in two
 * base-2^16 digits, each estimated from v's high half and corrected at most
 * twice (the classic schoolbook bound): 32-bit divisions and products only,
 * so no 64-bit division helper is called. */
uint32_t zs_udiv64_32(uint32_t nh, uint32_t nl, uint32_t v)
{
    uint32_t vh = v >> 16, vl = v & 0xFFFFu, n1 = nl >> 16, n0 = nl & 0xFFFFu;
    uint32_t qh, ql, r, rem;
#ifdef RECIP_DIGITS
    const uint32_t inv = recip15(vh);
    qh = div_by_recip(nh, vh, inv, &r);
#else
    qh = nh / vh;
    r = nh - qh * vh;
#endif
    while (qh > 0xFFFFu || qh * vl > ((r << 16) | n1)) {
        qh--;
        r += vh;
        if (r > 0xFFFFu)
            break;
    }
    /* the partial remainder (nh, n1) - qh * v is below v: mod 2^32 is exact */
    rem = ((nh << 16) | n1) - qh * v;
#ifdef RECIP_DIGITS
    ql = div_by_recip(rem, vh, inv, &r);
#else
    ql = rem / vh;
    r = rem - ql * vh;
#endif
    while (ql > 0xFFFFu || ql * vl > ((r << 16) | n0)) {
        ql--;
        r += vh;
        if (r > 0xFFFFu)
            break;
    }
    return (qh << 16) + ql;
}

#ifdef RECIP_DIGITS
/* floor(2^61 / d) for d in [2^30, 2^31) in 32-bit products (one a projected
 * vertex, so not the long division's two digits): with d = 2^15 dh + dl,
 * x = floor(2^31 / dh) and r = 2^31 - dh x, y0 = 2^15 x is off by
 * e = 2^61 - d y0 = 2^15 E, E = 2^15 r - dl x in (-2^31, 2^31), so
 * eps = e / 2^61 = E / 2^46 and |eps| <= 2^-15. Then
 * 2^61 / d = y0 (1 + eps + eps^2 + ...): y0 eps = x E / 2^31 and y0 eps^2
 * = (y0 eps) E / 2^46, formed in 1/256 units; every truncation rounds down
 * (as does the -16/256), so y is the floor or one short, which the 32-bit
 * remainder 2^61 - d y in [0, 2d) settles. Checked for all 2^30 divisors
 * against the division (tests/variants/split_products.c samples). */
static uint32_t recip61_digits(uint32_t d)
{
    uint32_t dh = d >> 15, dl = d & 0x7FFFu;
    uint32_t x = recip15(dh); /* (2^15, 2^16] */
    uint32_t r = 0x80000000u - dh * x, el, rem, y;
    int32_t e = zs_s32((r << 15) - dl * x), eh, a, t8, t2;
    eh = zs_asr32(e, 16); /* e = 2^16 eh + el */
    el = (uint32_t)e & 0xFFFFu;
    a = (int32_t)x * eh; /* |x eh| <= 2^31 */
    /* floor(x e / 2^23) = floor((a + floor(x el / 2^16)) / 2^7) */
    t8 = zs_asr32(a, 7) + (int32_t)((((uint32_t)a & 0x7Fu) + ((x * el) >> 16)) >> 7);
    t2 = zs_asr32(zs_asr32(t8, 9) * eh, 21); /* t8 e / 2^46, |t8 / 2^9| <= 2^15 */
    y = (x << 15) + (uint32_t)zs_asr32(t8 + t2 - 16, 8);
    rem = 0u - d * y; /* 2^61 - d y mod 2^32, exact: below 2d < 2^32 */
    return rem >= d ? y + 1u : y;
}
#endif

uint32_t zs_recip61(uint32_t d)
{
#ifdef RECIP_DIGITS
    return recip61_digits(d);
#elif defined(ZS_SPLIT_MUL)
    return zs_udiv64_32((uint32_t)1 << 30, 0u, d << 1); /* 2^62 / 2d */
#else
    return zs_recip61_fast(d); /* one 32-bit division and products */
#endif
}

#ifdef ZS_SPLIT_MUL
/* Leading zeros of v > 0 by zs_norm_shift's steps (Cortex-M0 has no clz:
 * __clzsi2 is a call). */
static ZS_INLINE_ALWAYS int clz32_split(uint32_t v)
{
    uint32_t n;
    return v >= 0x80000000u ? 0 : (int)zs_norm_shift(v, &n) + 1;
}
#endif

void zs_recip_init(zs_recip *rc, int64_t d)
{
    uint64_t a = d < 0 ? (uint64_t)0 - (uint64_t)d : (uint64_t)d;
#ifdef ZS_SPLIT_MUL
    /* by words: no 64-bit clz or shift helper (|d| < 2^63: hi < 2^31) */
    const uint32_t hi = (uint32_t)(a >> 32), lo = (uint32_t)(a & 0xFFFFFFFFu);
    int e;
    if (hi == 0) {
        e = clz32_split(lo);
        a = lo << e;
    } else {
        const int k = 32 - clz32_split(hi); /* 1..31 */
        e = -k;
        a = lo >> k | hi << (32 - k);
    }
#else
    int e = (int)clz64(a) - 32; /* a * 2^e in [2^31, 2^32) */
    if (e >= 0)
        a <<= e;
    else
        a >>= -e;
#endif
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
    else {
#ifdef ZS_SPLIT_MUL
        /* the shift by words (a 64-bit shift is a helper call on Cortex-M0) */
        const uint64_t m = zs_umul32((uint32_t)n, rc->inv); /* n < 2^31 */
        const uint32_t hi = (uint32_t)(m >> 32);
        if (sh >= 32)
            q = hi >> (sh - 32);
        else
            q = (uint64_t)(hi >> sh) << 32 | zs_shr64_lo(m, (unsigned)sh);
#else
        q = zs_umul32((uint32_t)n, rc->inv) >> sh; /* n < 2^31 */
#endif
    }
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
