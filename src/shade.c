/* Shading: vertex colours (lighting, fog), colour planes, pixel packing and
 * the span fills that write the line buffer. */
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

void zs_pack_pixel(zs_format fmt, uint32_t rgb, uint8_t out[4])
{
    uint32_t r = (rgb >> 16) & 255u, g = (rgb >> 8) & 255u, b = rgb & 255u;
    uint16_t v565 = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    out[0] = out[1] = out[2] = out[3] = 0;
    switch (fmt) {
    case ZS_FMT_RGB565_BE:
        out[0] = (uint8_t)(v565 >> 8);
        out[1] = (uint8_t)(v565 & 255u);
        break;
    case ZS_FMT_RGB565:
    case ZS_FMT_ID16: {
        union {
            uint16_t v;
            uint8_t b[2];
        } u;
        u.v = v565;
        out[0] = u.b[0];
        out[1] = u.b[1];
        break;
    }
    case ZS_FMT_RGB666:
        out[0] = (uint8_t)(r & 0xFCu);
        out[1] = (uint8_t)(g & 0xFCu);
        out[2] = (uint8_t)(b & 0xFCu);
        break;
    case ZS_FMT_GRAY8:
        out[0] = (uint8_t)((77u * r + 150u * g + 29u * b) >> 8);
        break;
    case ZS_FMT_RGB888:
        out[0] = (uint8_t)r;
        out[1] = (uint8_t)g;
        out[2] = (uint8_t)b;
        break;
    case ZS_FMT_COUNT:
        break;
    }
}

/* Colour at a vertex of triangle t, given its shade word, after modulation
 * and fog. */
static uint32_t vertex_rgb(const zs_renderer *r, const zs_tri *t, uint32_t shade)
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

void zs_shade_setup(const zs_renderer *r, zs_active *a, zs_active_color *ac, const zs_tri *t,
                    const zs_vert *v[3], int32_t ox, int32_t oy, const zs_recip *area2,
                    int32_t y)
{
    uint32_t c[3];
    uint8_t px[4];
    int k;
    union {
        uint32_t w;
        uint16_t h;
        uint8_t b[4];
    } u;
    if (r->shade.format == ZS_FMT_ID16) {
        a->flags &= (uint8_t)~ZS_ACT_GOURAUD;
        u.w = 0;
        u.h = (uint16_t)t->color;
        a->pixel = u.w;
        return;
    }
    if ((t->color >> 24) == 0 || !r->vshade) { /* no per-vertex colour: flat */
        c[0] = c[1] = c[2] = t->color & WHITE;
    } else {
        for (k = 0; k < 3; k++)
            c[k] = vertex_rgb(r, t, ((const uint32_t *)r->vshade)[t->v[k]]);
    }
    if (c[0] == c[1] && c[1] == c[2]) {
        a->flags &= (uint8_t)~ZS_ACT_GOURAUD;
        zs_pack_pixel(r->shade.format, c[0], px);
        u.b[0] = px[0];
        u.b[1] = px[1];
        u.b[2] = px[2];
        u.b[3] = px[3];
        a->pixel = u.w;
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

void zs_fill_gouraud(const zs_renderer *r, const zs_active_color *a, uint8_t *row, int x0, int x1)
{
    uint32_t cr = a->crow[0] + (uint32_t)a->cdx[0] * (uint32_t)x0;
    uint32_t cg = a->crow[1] + (uint32_t)a->cdx[1] * (uint32_t)x0;
    uint32_t cb = a->crow[2] + (uint32_t)a->cdx[2] * (uint32_t)x0;
    uint32_t dr = (uint32_t)a->cdx[0], dg = (uint32_t)a->cdx[1], db = (uint32_t)a->cdx[2];
    uint8_t *p = row + (size_t)x0 * r->bpp;
    int x;
#if defined(__OPTIMIZE_SIZE__)
    /* built for size: one loop packing through zs_pack_pixel */
    for (x = x0; x < x1; x++, p += r->bpp) {
        uint8_t px[4];
        unsigned k;
        zs_pack_pixel(r->shade.format, (channel(cr) << 16) | (channel(cg) << 8) | channel(cb), px);
        for (k = 0; k < r->bpp; k++)
            p[k] = px[k];
        cr += dr;
        cg += dg;
        cb += db;
    }
#else
    switch (r->shade.format) {
    case ZS_FMT_RGB565_BE:
        GOURAUD_LOOP(2, {
            uint32_t v = ((R >> 3) << 11) | ((G >> 2) << 5) | (B >> 3);
            p[0] = (uint8_t)(v >> 8);
            p[1] = (uint8_t)v;
        })
        break;
    case ZS_FMT_RGB565:
        GOURAUD_LOOP(2, {
            union {
                uint16_t v;
                uint8_t b[2];
            } u;
            u.v = (uint16_t)(((R >> 3) << 11) | ((G >> 2) << 5) | (B >> 3));
            p[0] = u.b[0];
            p[1] = u.b[1];
        })
        break;
    case ZS_FMT_RGB666:
        GOURAUD_LOOP(3, {
            p[0] = (uint8_t)(R & 0xFCu);
            p[1] = (uint8_t)(G & 0xFCu);
            p[2] = (uint8_t)(B & 0xFCu);
        })
        break;
    case ZS_FMT_GRAY8:
        GOURAUD_LOOP(1, p[0] = (uint8_t)((77u * R + 150u * G + 29u * B) >> 8))
        break;
    default:
        GOURAUD_LOOP(3, {
            p[0] = (uint8_t)R;
            p[1] = (uint8_t)G;
            p[2] = (uint8_t)B;
        })
        break;
    }
#endif
}
