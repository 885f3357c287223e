/* SPDX-License-Identifier: MIT */
/* The products Cortex-M0 builds form from 32-bit halves (zs_mul64_small,
 * zs_umul32, zs_umul31, zs_smul32 with ZS_SPLIT_PRODUCTS) must equal plain 64-bit
 * products, zs_udiv64_32 and zs_recip61 (by reciprocals there) the 64-bit
 * quotients, and a core built with them must render what the plain core does.
 *
 * Built twice (mk/variants.mk): against the core compiled as usual and
 * compiled with -DZS_SPLIT_PRODUCTS (this file too). Each build
 *  1. checks the three helpers against the compiler's 64-bit products at the
 *     ends of their documented ranges and on random operands (exits 1 on a
 *     difference; in the plain build the helpers are the plain products);
 *  2. renders random scenes (near-plane crossings, steep and needle
 *     triangles, interpenetrating ones; span and zline mode; every colour
 *     format; flat and Gouraud) and prints one hash of all the pixels.
 * The two hashes must be equal. */
#include "../../src/zs_internal.h"

#include <stdio.h>
#include <string.h>

static uint64_t g_state = 0x5B117B0D00000001ull;

static uint64_t rnd(void)
{
    g_state ^= g_state << 13;
    g_state ^= g_state >> 7;
    g_state ^= g_state << 17;
    return g_state;
}

static int64_t rnd_range(int64_t lo, int64_t hi) /* inclusive */
{
    return lo + (int64_t)(rnd() % (uint64_t)(hi - lo + 1));
}

static unsigned long g_fail;

static void check(int ok, const char *what, long long a, long long b)
{
    if (!ok && g_fail++ < 10)
        fprintf(stderr, "split_products: %s wrong for %lld, %lld\n", what, a, b);
}

static void check_helpers(void)
{
    static const int64_t big[] = {0, 1, -1, ((int64_t)1 << 48), -((int64_t)1 << 48),
                                  ((int64_t)1 << 48) - 1, -((int64_t)1 << 48) + 1,
                                  ((int64_t)1 << 32), -((int64_t)1 << 32), 0xFFFFFFFFll,
                                  -0xFFFFFFFFll, 0x10000, -0x10000, 0xFFFF, -0xFFFF};
    static const int32_t small[] = {0, 1, -1, 32767, -32767, 1024, -1024, 4096, -4096, 255};
    unsigned i, j;
    int k;
    uint64_t saved;
    for (i = 0; i < sizeof big / sizeof big[0]; i++)
        for (j = 0; j < sizeof small / sizeof small[0]; j++) {
            int64_t a = big[i];
            int32_t b = small[j];
            /* the contract: |a| / 2^32 * |b| < 2^31 */
            if ((a < 0 ? -a : a) / 4294967296ll * (b < 0 ? -b : b) < 2147483648ll)
                check(zs_mul64_small(a, b) == a * b, "zs_mul64_small", (long long)a, b);
        }
    for (k = 0; k < 2000000; k++) {
        int64_t a = rnd_range(-((int64_t)1 << 48), (int64_t)1 << 48);
        int32_t b = (int32_t)rnd_range(-32767, 32767);
        uint32_t u = (uint32_t)rnd(), v = (uint32_t)rnd();
        int32_t s = (int32_t)rnd_range(-2147483647, 2147483647);
        int32_t t = (int32_t)rnd_range(-2147483647, 2147483647);
        if ((a < 0 ? -a : a) / 4294967296ll * (b < 0 ? -b : b) < 2147483648ll)
            check(zs_mul64_small(a, b) == a * b, "zs_mul64_small", (long long)a, b);
        check(zs_umul32(u, v) == (uint64_t)u * v, "zs_umul32", (long long)u, (long long)v);
        check(zs_umul32(0xFFFFFFFFu, v) == 0xFFFFFFFFull * v, "zs_umul32", -1, (long long)v);
        check(zs_smul32(s, t) == (int64_t)s * t, "zs_smul32", s, t);
        /* zs_umul31: both operands at most 2^31 */
        u = (uint32_t)rnd() % 0x80000001u;
        v = (k & 1) ? 0x80000000u - (uint32_t)(rnd() & 0xFFFFu) : (uint32_t)rnd() % 0x80000001u;
        check(zs_umul31(u, v) == (uint64_t)u * v, "zs_umul31", (long long)u, (long long)v);
    }
    check(zs_umul31(0x80000000u, 0x80000000u) == 0x4000000000000000ull, "zs_umul31", 1, 1);
    check(zs_umul31(0x7FFFFFFFu, 0x80000000u) == 0x7FFFFFFFull << 31, "zs_umul31", 2, 2);
    check(zs_umul31(0x7FFFFFFFu, 0x7FFFFFFFu) == 0x7FFFFFFFull * 0x7FFFFFFFull, "zs_umul31", 3, 3);
    check(zs_umul31(0x8000FFFFu & 0x7FFFFFFFu, 0x7FFFFFFFu) ==
              (uint64_t)(0x8000FFFFu & 0x7FFFFFFFu) * 0x7FFFFFFFu,
          "zs_umul31", 4, 4);
    /* zs_udiv64_32 (on Cortex-M0 by a reciprocal of v's high half): every
     * high half of the divisor, then random dividends and divisors */
    for (k = 0; k < (1 << 15); k++) {
        uint32_t v = ((uint32_t)(0x8000 + k) << 16) | (uint32_t)(rnd() & 0xFFFFu);
        uint32_t nh = (uint32_t)(rnd() % v), nl = (uint32_t)rnd();
        uint64_t n = ((uint64_t)nh << 32) | nl;
        check(zs_udiv64_32(nh, nl, v) == (uint32_t)(n / v), "zs_udiv64_32", (long long)nh,
              (long long)v);
        check(zs_udiv64_32(v - 1u, 0xFFFFFFFFu, v) == (uint32_t)((((uint64_t)(v - 1u) << 32) |
                                                                 0xFFFFFFFFu) / v),
              "zs_udiv64_32 (largest dividend)", (long long)v, 0);
        check(zs_udiv64_32(0, nl, v) == nl / v, "zs_udiv64_32 (nh 0)", (long long)nl, (long long)v);
    }
    /* zs_recip61 (on Cortex-M0 from recip15 and one Newton step): floor(2^61
     * / d) for both ends of [2^30, 2^31), around every multiple of 2^15 (the
     * divisor's split, where its estimate is farthest off) and at random */
    for (k = 0; k < 70000; k++) {
        uint32_t lo = 0x40000000u + (uint32_t)k, hi = 0x7FFFFFFFu - (uint32_t)k;
        check(zs_recip61(lo) == (uint32_t)(((uint64_t)1 << 61) / lo), "zs_recip61",
              (long long)lo, 0);
        check(zs_recip61(hi) == (uint32_t)(((uint64_t)1 << 61) / hi), "zs_recip61",
              (long long)hi, 0);
    }
    for (k = 0x8000; k < 0x10000; k++) {
        int j;
        for (j = -2; j <= 2; j++) {
            uint32_t d = (uint32_t)(k * 0x8000 + j);
            if (d >= 0x40000000u && d < 0x80000000u)
                check(zs_recip61(d) == (uint32_t)(((uint64_t)1 << 61) / d), "zs_recip61",
                      (long long)d, 0);
        }
    }
    for (k = 0; k < 2000000; k++) {
        uint32_t d = 0x40000000u | ((uint32_t)rnd() & 0x3FFFFFFFu);
        check(zs_recip61(d) == (uint32_t)(((uint64_t)1 << 61) / d), "zs_recip61", (long long)d, 0);
    }
    for (k = 0; k < 2000000; k++) {
        uint32_t v = (uint32_t)rnd() | 0x80000000u;
        uint32_t nh = (uint32_t)(rnd() % v), nl = (uint32_t)rnd();
        uint64_t n = ((uint64_t)nh << 32) | nl;
        check(zs_udiv64_32(nh, nl, v) == (uint32_t)(n / v), "zs_udiv64_32", (long long)nh,
              (long long)v);
    }
    /* zs_recip_init (on Cortex-M0 normalised by words, no 64-bit clz or
     * shift) and zs_recip_muldiv (its last shift by words) against the same
     * arithmetic in 64 bits, for divisors of every magnitude up to 2^48
     * (the scenes below keep their random numbers) */
    saved = g_state;
    for (k = 0; k < 1000000; k++) {
        int64_t d = (int64_t)(rnd() >> (16 + rnd() % 48)), num, lim = (int64_t)1 << 48;
        uint64_t a, n, q;
        int e, t = 0, sh, bits = (int)(rnd() % 20);
        zs_recip rc;
        if (d == 0)
            d = 1;
        if (rnd() & 1)
            d = -d;
        zs_recip_init(&rc, d);
        a = d < 0 ? (uint64_t)-d : (uint64_t)d;
        e = __builtin_clzll(a) - 32;
        a = e >= 0 ? a << e : a >> -e;
        check(rc.inv == (uint32_t)(0x7FFFFFFFFFFFFFFFull / a) && rc.exp == e &&
                  rc.neg == (d < 0),
              "zs_recip_init", (long long)d, rc.exp);
        num = (int64_t)(rnd() >> (2 + rnd() % 62));
        if (rnd() & 1)
            num = -num;
        n = num < 0 ? (uint64_t)-num : (uint64_t)num;
        if (n >= ((uint64_t)1 << 31)) {
            t = 33 - __builtin_clzll(n);
            n >>= t;
        }
        sh = 63 - bits - e - t;
        q = n == 0 || sh >= 64 ? 0 : sh <= 0 ? (uint64_t)lim : (n * rc.inv) >> sh;
        if (q > (uint64_t)lim)
            q = (uint64_t)lim;
        check(zs_recip_muldiv(&rc, num, bits, lim) ==
                  (((num < 0) != (d < 0)) ? -(int64_t)q : (int64_t)q),
              "zs_recip_muldiv", (long long)num, (long long)d);
    }
    g_state = saved;
}

#define W 96
#define H 72
#define NT 24
static uint8_t arena[ZS_ARENA_BYTES(W, H, 400, 400, 256)];
static uint8_t img[W * H * 3];
static int16_t pos[NT * 3 * 3];
static uint16_t idx[NT * 3];
static zs_color vcol[NT * 3];

static uint32_t render_scenes(void)
{
    uint32_t h = 2166136261u;
    int scene, fmt, mode, shade;
    for (scene = 0; scene < 60; scene++) {
        zs_mesh m;
        zs_camera cam;
        int i;
        memset(&m, 0, sizeof m);
        for (i = 0; i < NT * 3; i++) {
            int tri = i / 3;
            /* some triangles long and thin (needles), some crossing the near plane */
            int spread = (tri % 4 == 0) ? 200 : 3000;
            int base = (int)rnd_range(-6000, 6000);
            pos[3 * i + 0] = (int16_t)(base + rnd_range(-spread, spread));
            pos[3 * i + 1] = (int16_t)rnd_range(-8000, 8000);
            pos[3 * i + 2] = (int16_t)rnd_range(-9000, tri % 5 == 0 ? 9000 : 2000);
            idx[i] = (uint16_t)i;
            vcol[i] = (zs_color)(rnd() & 0xFFFFFFu);
        }
        m.positions = pos;
        m.indices = idx;
        m.vertex_colors = vcol;
        m.scale = ZS_FX_RATIO(1, 2000);
        m.vertex_count = NT * 3;
        m.triangle_count = NT;
        memset(&cam, 0, sizeof cam);
        zs_camera_look_at(&cam, zs_vec3_make(0, 0, ZS_FX(5)), zs_vec3_make(0, 0, 0),
                          zs_vec3_make(0, ZS_FX(1), 0));
        zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_RATIO(1, 4), ZS_FX(40));
        for (mode = 0; mode < 2; mode++)
            for (fmt = 0; fmt < 5; fmt++)
                for (shade = 0; shade < 2; shade++) {
                    zs_renderer r;
                    zs_config cfg = zs_config_default(W, H, 400, 400, 256);
                    zs_shade_params sp = zs_shade_default();
                    int k, n = W * H * (int)zs_format_bytes((zs_format)fmt);
                    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK)
                        return 0;
                    zs_frame_begin(&r, &cam, mode ? ZS_MODE_ZLINE : ZS_MODE_SPAN);
                    sp.format = (zs_format)fmt;
                    sp.shading = shade ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
                    zs_frame_shading(&r, &sp);
                    zs_draw(&r, &m, 0);
                    zs_render_rows(&r, 0, H, img, (size_t)W * zs_format_bytes((zs_format)fmt));
                    for (k = 0; k < n; k++) {
                        h ^= img[k];
                        h *= 16777619u;
                    }
                }
    }
    return h;
}

int main(void)
{
    uint32_t h;
    check_helpers();
    h = render_scenes();
    printf("%08x\n", (unsigned)h);
    if (g_fail) {
        fprintf(stderr, "split_products: %lu helper results wrong\n", g_fail);
        return 1;
    }
    return 0;
}
