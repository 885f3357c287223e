/* SPDX-License-Identifier: MIT */
/* Pixel formats: bytes per pixel, and packing an RGB888 colour into the
 * bytes the line buffer holds (the panel's byte order). */
#include "zs_internal.h"

#if defined(__OPTIMIZE_SIZE__)
void zs_fill_flat(uint8_t *row, int x0, int x1, unsigned bpp, uint32_t pixel)
{
    zs_fill_flat_body(row, x0, x1, ZS_ONLY_565_ ? 2u : bpp, pixel);
}
#endif

unsigned zs_format_bytes(zs_format fmt)
{
    switch (fmt) {
    case ZS_FMT_RGB565_BE:
    case ZS_FMT_RGB565:
    case ZS_FMT_ID16:
        return 2;
    case ZS_FMT_RGB666:
    case ZS_FMT_RGB888:
        return 3;
    case ZS_FMT_GRAY8:
        return 1;
    default:
        break;
    }
    return 0;
}

size_t zs_format_stride(zs_format fmt, unsigned width)
{
    if (fmt == ZS_FMT_MONO_PAGE)
        return width;
    if (fmt == ZS_FMT_MONO_MSB)
        return (width + 7u) / 8u;
    if (fmt == ZS_FMT_GRAY4)
        return (width + 1u) / 2u;
    return (size_t)width * zs_format_bytes(fmt);
}

int zs_format_is_mono(zs_format fmt)
{
    return fmt == ZS_FMT_MONO_PAGE || fmt == ZS_FMT_MONO_MSB;
}

void zs_pack_pixel(zs_format fmt, uint32_t rgb, uint8_t out[4])
{
    uint32_t r = (rgb >> 16) & 255u, g = (rgb >> 8) & 255u, b = rgb & 255u;
    out[0] = out[1] = out[2] = out[3] = 0;
    if (ZS_ONLY_565_) { /* the only formats zs_frame_shading takes */
        if (fmt == ZS_FMT_RGB565_BE)
            zs_store_rgb565_be(out, r, g, b);
        else
            zs_store_rgb565(out, r, g, b);
        return;
    }
    switch (fmt) {
    case ZS_FMT_RGB565_BE:
        zs_store_rgb565_be(out, r, g, b);
        break;
    case ZS_FMT_RGB565:
    case ZS_FMT_ID16:
        zs_store_rgb565(out, r, g, b);
        break;
    case ZS_FMT_RGB666:
        zs_store_rgb666(out, r, g, b);
        break;
    case ZS_FMT_GRAY8:
        zs_store_gray8(out, r, g, b);
        break;
    case ZS_FMT_RGB888:
        zs_store_rgb888(out, r, g, b);
        break;
    default:
        break;
    }
}

uint32_t zs_pixel_word(zs_format fmt, uint32_t rgb)
{
    union {
        uint32_t w;
        uint8_t b[4];
    } u;
    zs_pack_pixel(fmt, rgb, u.b);
    if (ZS_ONLY_565_ || fmt == ZS_FMT_RGB565_BE || fmt == ZS_FMT_RGB565 ||
        fmt == ZS_FMT_ID16) { /* 2 bytes */
        u.b[2] = u.b[0];
        u.b[3] = u.b[1];
    }
    return u.w;
}

uint32_t zs_background_word(const zs_renderer *r)
{
    /* ID16 marks "no triangle" with tag 0, whatever the background colour */
    return zs_pixel_word(r->shade.format,
                         !ZS_ONLY_565_ && r->shade.format == ZS_FMT_ID16 ? 0
                                                                         : r->shade.background);
}
