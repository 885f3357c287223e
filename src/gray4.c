/* SPDX-License-Identifier: MIT */
/* 4-bit grey output (ZS_FMT_GRAY4, the SSD0323's RAM format): a row rendered
 * in GRAY8 into the scratch line is quantised to 16 levels, or dithered
 * between two levels with the 8x8 Bayer matrix, and packed two pixels a
 * byte, the left one in the high nibble. */
#include "zs_mono.h"

/* The level of grey g at Bayer index m (dither) or the nearest one. With
 * t = 15 g the level is t / 255 plus one where the remainder f = t % 255
 * passes the threshold: 128 f > 255 (2 m + 1), the 1-bit rule of mono.c
 * applied to the fraction between two levels. */
static unsigned gray4_level(unsigned g, unsigned m, int dither)
{
    unsigned t = 15u * g, lo = t / 255u;
    if (!dither)
        return (t + 127u) / 255u;
    return lo + (128u * (t - 255u * lo) > 255u * (2u * m + 1u) ? 1u : 0u);
}

void zs_gray4_row(const zs_renderer *r, int y, const uint8_t *g, uint8_t *out)
{
    int w = (int)r->cfg.width, x;
    int dither = (r->shade.mono & ZS_GRAY4_DITHER) != 0;
    unsigned inv = (r->shade.mono & ZS_MONO_INVERT) ? 15u : 0u;
    const uint8_t *m = zs_bayer8[y & 7];
    for (x = 0; x + 1 < w; x += 2) {
        unsigned hi = gray4_level(g[x], m[x & 7], dither) ^ inv;
        unsigned lo = gray4_level(g[x + 1], m[(x + 1) & 7], dither) ^ inv;
        out[x >> 1] = (uint8_t)((hi << 4) | lo);
    }
    if (w & 1) /* the last pixel alone: its byte's low nibble stays 0 */
        out[x >> 1] = (uint8_t)((gray4_level(g[x], m[x & 7], dither) ^ inv) << 4);
}
