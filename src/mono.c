/* SPDX-License-Identifier: MIT */
/* 1-bit output: a row rendered in GRAY8 (or line flags) is dithered to one
 * bit per pixel and packed into the caller's buffer, in SSD1306 pages or
 * row-major MSB first. */
#include "zs_mono.h"

/* The 8x8 Bayer index matrix (recursive construction, values 0..63); the
 * GRAY4 stage (gray4.c) dithers with it too. */
const uint8_t zs_bayer8[8][8] = {
    {0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
    {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
    {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
    {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21},
};

/* Diffusion error is kept within this bound so the int16 line can never
 * overflow (Floyd-Steinberg errors stay far inside it on any input). */
#define ERR_LIMIT 2048

void zs_mono_begin(zs_renderer *r)
{
    if (r->priv.mono_err)
        memset(r->priv.mono_err, 0, (size_t)r->cfg.width * 2u);
}

/* Ordered dithering: pixel on where 128 g > 255 (2 M + 1), M the Bayer index
 * at (x mod 8, y mod 8) of the screen; a flat grey g turns on
 * round(64 g / 255) of every 64 pixels. */
static void dither_bayer(uint8_t *g, int w, int y)
{
    const uint8_t *m = zs_bayer8[y & 7];
    int x;
    for (x = 0; x < w; x++)
        g[x] = (uint8_t)(128u * g[x] > 255u * (2u * m[x & 7] + 1u));
}

static int32_t clamp_err(int32_t e)
{
    return zs_clampi(e, -ERR_LIMIT, ERR_LIMIT);
}

/* Floyd-Steinberg, left to right: 7/16 to the right, 3/16, 5/16 and 1/16 to
 * the row below. err[] holds what the row above left for this row and is
 * rewritten, one column behind, with what this row leaves for the next. The
 * four parts always sum to the error (the 7/16 takes the rounding). */
static void dither_diffuse(int16_t *err, uint8_t *g, int w)
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

void zs_mono_row(zs_renderer *r, int y, uint8_t *g, uint8_t *out)
{
    int w = r->cfg.width, x;
    unsigned inv = (r->shade.mono & ZS_MONO_INVERT) ? 1u : 0u;
    if (!(r->shade.mono & ZS_MONO_LINES)) {
        if (r->shade.mono & ZS_MONO_DIFFUSE)
            dither_diffuse(r->priv.mono_err, g, w);
        else
            dither_bayer(g, w, y);
    }
    if (r->priv.out_format == ZS_FMT_MONO_PAGE) {
        uint8_t bit = (uint8_t)(1u << (y & 7));
        /* the last row clears the bits of its page below the screen */
        uint8_t keep = (uint8_t)(y + 1 == (int)r->cfg.height ? bit - 1 : ~bit);
        for (x = 0; x < w; x++)
            out[x] = (uint8_t)((out[x] & keep) | ((g[x] ^ inv) ? bit : 0));
    } else {
        unsigned acc = 0;
        for (x = 0; x < w; x++) {
            acc = (acc << 1) | (g[x] ^ inv);
            if ((x & 7) == 7) {
                out[x >> 3] = (uint8_t)acc;
                acc = 0;
            }
        }
        if (w & 7)
            out[w >> 3] = (uint8_t)(acc << (8 - (w & 7)));
    }
}
