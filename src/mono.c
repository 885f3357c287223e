/* SPDX-License-Identifier: MIT */
/* 1-bit output: a row rendered in GRAY8 (or line flags) is dithered to one
 * bit per pixel and packed into the caller's buffer, in SSD1306 pages or
 * row-major MSB first. Ordered dithering is a threshold test inside the
 * packing loop (one pass over the row). */
#include "zs_mono.h"

/* The 8x8 Bayer index matrix (recursive construction, values 0..63); the
 * GRAY4 stage (gray4.c) dithers with it too. */
const uint8_t zs_bayer8[8][8] = {
    {0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
    {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
    {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
    {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21},
};

/* Ordered dithering with the 8x8 Bayer index matrix M (recursive
 * construction, values 0..63): a pixel is on where 128 g > 255 (2 M + 1), so a
 * flat grey g turns on round(64 g / 255) of every 64 pixels. 255 (2 M + 1) is
 * odd, never a multiple of 128, so that is g > floor(255 (2 M + 1) / 128): the
 * thresholds below, at (x mod 8, y mod 8) of the screen. */
static const uint8_t bayer_thr[8][8] = {
    {1, 129, 33, 161, 9, 137, 41, 169},    {193, 65, 225, 97, 201, 73, 233, 105},
    {49, 177, 17, 145, 57, 185, 25, 153},  {241, 113, 209, 81, 249, 121, 217, 89},
    {13, 141, 45, 173, 5, 133, 37, 165},   {205, 77, 237, 109, 197, 69, 229, 101},
    {61, 189, 29, 157, 53, 181, 21, 149},  {253, 125, 221, 93, 245, 117, 213, 85},
};
/* Diffusion error is kept within this bound so the int16 line can never
 * overflow (Floyd-Steinberg errors stay far inside it on any input). */
#define ERR_LIMIT 2048

void zs_mono_begin(zs_renderer *r)
{
    if (r->priv.mono_err)
        memset(r->priv.mono_err, 0, (size_t)r->cfg.width * 2u);
}

static int32_t clamp_err(int32_t e)
{
    return zs_clampi(e, -ERR_LIMIT, ERR_LIMIT);
}

/* Floyd-Steinberg, left to right: 7/16 to the right, 3/16, 5/16 and 1/16 to
 * the row below. err[] holds what the row above left for this row and is
 * rewritten, one column behind, with what this row leaves for the next. The
 * four parts always sum to the error (the 7/16 takes the rounding). */
static ZS_NOINLINE void dither_diffuse(int16_t *err, uint8_t *g, int w)
{
    int32_t right = 0, below_prev = 0, below_cur = 0;
    int x;
    for (x = 0; x < w; x++) {
        int32_t v = (int32_t)g[x] + err[x] + right;
        int32_t on = v >= 128;
        int32_t e = v - (on ? 255 : 0);
        int32_t d1 = e / 16, d3 = (3 * e) / 16, d5 = (5 * e) / 16;
        g[x] = (uint8_t)on;
        if (x > 0)
            err[x - 1] = (int16_t)clamp_err(below_prev + d3);
        below_prev = below_cur + d5;
        below_cur = d1;
        right = clamp_err(e - d1 - d3 - d5);
    }
    err[w - 1] = (int16_t)clamp_err(below_prev);
}

/* One row into its page: bit y % 8 of each byte, on where g > t[x % 8]
 * (Bayer thresholds) or, without t, where g is 1 (inverted: off); the last
 * row clears the bits of its page below the screen. */
static void pack_page(const uint8_t *g, const uint8_t *t, uint8_t *out, int w, int y,
                      int last, unsigned inv)
{
    uint8_t bit = (uint8_t)(1u << (y & 7));
    uint8_t keep = (uint8_t)(last ? bit - 1 : ~bit);
    uint8_t off = inv ? bit : 0; /* the bit of a pixel that is off */
    int x;
    if (t) {
        for (x = 0; x < w; x++) {
            unsigned on = g[x] > t[x & 7];
            out[x] = (uint8_t)((out[x] & keep) | (off ^ ((0u - on) & bit)));
        }
    } else {
        x = 0;
#ifdef ZS_WORD_STORES
        if ((((uintptr_t)g | (uintptr_t)out) & 3u) == 0) {
            /* four pixels a word: each byte of g is 0 or 1, so shifted to
             * the row's bit it stays within its byte, in any byte order */
            const uint32_t ones = 0x01010101u;
            const zs_word_alias *gw = (const zs_word_alias *)(const void *)g;
            zs_word_alias *ow = (zs_word_alias *)(void *)out;
            uint32_t keepw = keep * ones, flipw = inv ? ones : 0u;
            unsigned sh = (unsigned)(y & 7);
            for (; x + 4 <= w; x += 4)
                ow[x >> 2] = (ow[x >> 2] & keepw) | ((gw[x >> 2] ^ flipw) << sh);
        }
#endif
        for (; x < w; x++)
            out[x] = (uint8_t)((out[x] & keep) | ((g[x] ^ inv) ? bit : 0));
    }
}

/* One row, MSB first, eight pixels a byte (the last byte's spare bits 0). */
static void pack_msb(const uint8_t *g, const uint8_t *t, uint8_t *out, int w, unsigned inv)
{
    unsigned acc = 0;
    int x;
    if (t) {
        unsigned flip = inv ? 0xFFu : 0u;
        for (x = 0; x + 8 <= w; x += 8) {
            const uint8_t *p = g + x;
            acc = (unsigned)(p[0] > t[0]) << 7 | (unsigned)(p[1] > t[1]) << 6 |
                  (unsigned)(p[2] > t[2]) << 5 | (unsigned)(p[3] > t[3]) << 4 |
                  (unsigned)(p[4] > t[4]) << 3 | (unsigned)(p[5] > t[5]) << 2 |
                  (unsigned)(p[6] > t[6]) << 1 | (unsigned)(p[7] > t[7]);
            out[x >> 3] = (uint8_t)(acc ^ flip);
        }
        acc = 0;
        for (; x < w; x++)
            acc = (acc << 1) | ((unsigned)(g[x] > t[x & 7]) ^ inv);
    } else {
        unsigned flip = inv ? 0xFFu : 0u;
        for (x = 0; x + 8 <= w; x += 8) { /* each byte of g is 0 or 1 */
            const uint8_t *p = g + x;
            acc = (unsigned)p[0] << 7 | (unsigned)p[1] << 6 | (unsigned)p[2] << 5 |
                  (unsigned)p[3] << 4 | (unsigned)p[4] << 3 | (unsigned)p[5] << 2 |
                  (unsigned)p[6] << 1 | (unsigned)p[7];
            out[x >> 3] = (uint8_t)(acc ^ flip);
        }
        acc = 0;
        for (; x < w; x++)
            acc = (acc << 1) | (g[x] ^ inv);
    }
    if (w & 7)
        out[w >> 3] = (uint8_t)(acc << (8 - (w & 7)));
}

void zs_mono_row(zs_renderer *r, int y, uint8_t *g, uint8_t *out)
{
    int w = r->cfg.width;
    unsigned inv = (r->shade.mono & ZS_MONO_INVERT) ? 1u : 0u;
    const uint8_t *t = 0; /* Bayer thresholds, or none: g is 0/1 */
    /* ordered dithering happens in the packing, by threshold */
    if (!(r->shade.mono & ZS_MONO_LINES)) {
        if (r->shade.mono & ZS_MONO_DIFFUSE)
            dither_diffuse(r->priv.mono_err, g, w);
        else
            t = bayer_thr[y & 7];
    }
    if (r->priv.out_format == ZS_FMT_MONO_PAGE)
        pack_page(g, t, out, w, y, y + 1 == (int)r->cfg.height, inv);
    else
        pack_msb(g, t, out, w, inv);
}
