/* SPDX-License-Identifier: MIT */
/* Shading: vertex colours (lighting, fog), colour planes and the Gouraud
 * span fill (pixel packing is in format.c). */
#include "zs_internal.h"

#define WHITE 0xFFFFFFu

uint32_t zs_light_color(uint32_t rgb, zs_fixed intensity)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s < 24; s += 8) {
        uint32_t c = (uint32_t)(((int64_t)((rgb >> s) & 255u) * intensity + 32768) >> 16);
        out |= (c > 255u ? 255u : c) << s;
    }
    return out;
}

static uint32_t modulate(uint32_t a, uint32_t b)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s < 24; s += 8)
        out |= ((((a >> s) & 255u) * ((b >> s) & 255u) + 127u) / 255u) << s;
    return out;
}

static uint32_t fog_mix(uint32_t c, uint32_t fog, uint32_t f)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s < 24; s += 8) {
        int32_t a = (int32_t)((c >> s) & 255u), b = (int32_t)((fog >> s) & 255u);
        int32_t v = a + ((b - a) * (int32_t)f + (b >= a ? 127 : -127)) / 255;
        out |= (uint32_t)v << s;
    }
    return out;
}

/* Colour at a vertex of triangle t, given its shade word, after modulation
 * and fog. */
static ZS_NOINLINE uint32_t vertex_rgb(const zs_renderer *r, const zs_tri *t, uint32_t shade)
{
    uint32_t flags = t->color >> 24;
    uint32_t c = t->color & WHITE;
    if (flags & ZS_TRI_MODULATE)
        c = modulate(c, shade & WHITE);
    if (flags & ZS_TRI_FOG)
        c = fog_mix(c, r->shade.fog.color, shade >> 24);
    return c;
}

/* Q8.16 colour gradient per pixel, clamped to 4096 levels per pixel. */
static int32_t color_gradient(int64_t num, const zs_recip *area2)
{
    return (int32_t)zs_recip_muldiv(area2, num, 4, (int64_t)1 << 28);
}

/* zs_pixel_word for one triangle's flat colour: the 2-byte formats (the
 * panels' usual ones) packed inline, the others through format.c. */
static ZS_INLINE_ALWAYS uint32_t flat_word(zs_format fmt, uint32_t rgb)
{
    union {
        uint32_t w;
        uint8_t b[4];
    } u;
    const uint32_t R = (rgb >> 16) & 255u, G = (rgb >> 8) & 255u, B = rgb & 255u;
    if (fmt == ZS_FMT_RGB565_BE)
        zs_store_rgb565_be(u.b, R, G, B);
    else if (ZS_ONLY_565_ || fmt == ZS_FMT_RGB565)
        zs_store_rgb565(u.b, R, G, B);
    else
        return zs_pixel_word(fmt, rgb);
    u.b[2] = u.b[0]; /* held twice, as zs_pixel_word does */
    u.b[3] = u.b[1];
    return u.w;
}

uint32_t zs_flat_pixel(const zs_renderer *r, uint32_t color)
{
    if (!ZS_ONLY_565_ && r->shade.format == ZS_FMT_ID16)
        return (color & 0xFFFFu) * 0x10001u; /* the tag twice (see zs_pixel_word) */
    return flat_word(r->shade.format, color & WHITE);
}

void zs_shade_setup(const zs_renderer *r, zs_active *a, zs_active_color *ac, const zs_tri *t,
                    const zs_vert *v[3], int32_t ox, int32_t oy, const zs_recip *area2,
                    int32_t y)
{
    uint32_t c[3];
    int k;
    union {
        uint32_t w;
        uint16_t h;
        uint8_t b[4];
    } u;
    if (!ZS_ONLY_565_ && r->shade.format == ZS_FMT_ID16) {
        a->flags &= (uint8_t)~ZS_ACT_GOURAUD;
        u.h = (uint16_t)t->color;
        a->pixel = (uint32_t)u.h * 0x10001u; /* the tag twice (see zs_pixel_word) */
        return;
    }
    /* no per-vertex colour (or none built): flat */
    if (!ZS_HAS_PLANES_ || (t->color >> 24) == 0 || !r->priv.vshade) {
        c[0] = c[1] = c[2] = t->color & WHITE;
    } else {
        for (k = 0; k < 3; k++)
            c[k] = vertex_rgb(r, t, r->priv.vshade[t->v[k]]);
        /* a textured record's light always gets planes: its fill goes
         * through zs_fill_gouraud to texture.c (bit 26 is no channel's) */
        c[0] ^= ((t->color >> 24) & ZS_TRI_TEXTURED) << 24;
    }
    if (!ZS_HAS_PLANES_ || (c[0] == c[1] && c[1] == c[2])) {
        a->flags &= (uint8_t)~ZS_ACT_GOURAUD;
        a->pixel = zs_pixel_word(r->shade.format, c[0]); /* equal vertex colours: rare */
        return;
    }
    a->flags |= ZS_ACT_GOURAUD;
    a->pixel = 0;
    {
        int64_t dx1 = (int64_t)v[1]->x - v[0]->x, dy1 = (int64_t)v[1]->y - v[0]->y;
        int64_t dx2 = (int64_t)v[2]->x - v[0]->x, dy2 = (int64_t)v[2]->y - v[0]->y;
        int64_t offx = 16 * (int64_t)ox + 8 - v[0]->x, offy = 16 * (int64_t)oy + 8 - v[0]->y;
        for (k = 0; k < 3; k++) {
            int s = 16 - 8 * k; /* channel k: R, G, B */
            int64_t c0 = (int64_t)((c[0] >> s) & 255u) * 65536;
            int64_t d1 = (int64_t)((c[1] >> s) & 255u) * 65536 - c0;
            int64_t d2 = (int64_t)((c[2] >> s) & 255u) * 65536 - c0;
            int64_t co;
            ac->cdx[k] = color_gradient(d1 * dy2 - d2 * dy1, area2);
            ac->cdy[k] = color_gradient(d2 * dx1 - d1 * dx2, area2);
            /* value at the origin pixel centre, +0.5 so truncation rounds */
            co = c0 + 32768 +
                 zs_asr64((int64_t)ac->cdx[k] * offx + (int64_t)ac->cdy[k] * offy, 4);
            ac->crow[k] = (uint32_t)(co + (int64_t)ac->cdy[k] * ((int64_t)y - oy) -
                                     (int64_t)ac->cdx[k] * ox);
        }
    }
}

static uint32_t channel(uint32_t acc)
{
    if (acc & 0x80000000u)
        return 0; /* slightly below zero from rounding (or a clamped sliver) */
    acc >>= 16;
    return acc > 255u ? 255u : acc;
}

/* The colour planes stepped along a span, one loop per format. */
#define GOURAUD_LOOP(BPP, STORE)                                                          \
    for (x = x0; x < x1; x++, p += (BPP)) {                                               \
        uint32_t R = channel(cr), G = channel(cg), B = channel(cb);                       \
        STORE;                                                                            \
        cr += dr;                                                                         \
        cg += dg;                                                                         \
        cb += db;                                                                         \
    }

void zs_fill_gouraud(const zs_renderer *r, const zs_active_color *a, int32_t dy, uint8_t *row,
                     int x0, int x1)
{
    /* wrapping products equal the sums of steps they replace */
    uint32_t cr = a->crow[0] + (uint32_t)a->cdy[0] * (uint32_t)dy + (uint32_t)a->cdx[0] * (uint32_t)x0;
    uint32_t cg = a->crow[1] + (uint32_t)a->cdy[1] * (uint32_t)dy + (uint32_t)a->cdx[1] * (uint32_t)x0;
    uint32_t cb = a->crow[2] + (uint32_t)a->cdy[2] * (uint32_t)dy + (uint32_t)a->cdx[2] * (uint32_t)x0;
    uint32_t dr = (uint32_t)a->cdx[0], dg = (uint32_t)a->cdx[1], db = (uint32_t)a->cdx[2];
    uint8_t *p = row + (size_t)x0 * r->priv.bpp;
    int x;
    /* ZS_CFG_TEXTURE: a textured record's fill is texture.c's */
    if (ZS_HAS_TEXTURE && r->priv.atex) {
        uint16_t ai = (uint16_t)(a - r->priv.acolor);
        const zs_active *act = &r->priv.active[ai];
        if ((r->priv.tris[act->tri].color >> 24) & ZS_TRI_TEXTURED) {
            zs_fill_textured(r, ai, dy + act->y0, row, x0, x1);
            return;
        }
    }
#if defined(__OPTIMIZE_SIZE__)
    /* built for size: one loop packing through zs_pack_pixel */
    for (x = x0; x < x1; x++, p += r->priv.bpp) {
        uint8_t px[4];
        unsigned k;
        zs_pack_pixel(r->shade.format, (channel(cr) << 16) | (channel(cg) << 8) | channel(cb), px);
        for (k = 0; k < r->priv.bpp; k++)
            p[k] = px[k];
        cr += dr;
        cg += dg;
        cb += db;
    }
#else
    switch (r->shade.format) {
    case ZS_FMT_RGB565_BE:
        GOURAUD_LOOP(2, zs_store_rgb565_be(p, R, G, B))
        break;
    case ZS_FMT_RGB565:
        GOURAUD_LOOP(2, zs_store_rgb565(p, R, G, B))
        break;
    case ZS_FMT_RGB666:
        GOURAUD_LOOP(3, zs_store_rgb666(p, R, G, B))
        break;
    case ZS_FMT_GRAY8:
        GOURAUD_LOOP(1, zs_store_gray8(p, R, G, B))
        break;
    default:
        GOURAUD_LOOP(3, zs_store_rgb888(p, R, G, B))
        break;
    }
#endif
}

uint32_t zs_vertex_rgb(const zs_renderer *r, const zs_tri *t, uint32_t shade)
{
    return vertex_rgb(r, t, shade);
}
