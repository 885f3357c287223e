/* SPDX-License-Identifier: MIT */
/* zspan-sim: PNG writing with libpng (host only). */
#ifndef ZSPAN_SIM_PNG_OUT_H
#define ZSPAN_SIM_PNG_OUT_H

#include <stddef.h>
#include <stdint.h>

/* 8-bit RGB: rows of width*3 bytes R, G, B at rgb + y*stride.
 * Returns 0, or -1 with a message on stderr. */
int png_write_rgb8(const char *path, int width, int height, const uint8_t *rgb, size_t stride);

/* 16-bit greyscale from native uint16_t values, row y at
 * (const uint8_t *)values + y*stride. Returns 0, or -1 with a message on stderr. */
int png_write_gray16(const char *path, int width, int height, const void *values,
                     size_t stride);

#endif /* ZSPAN_SIM_PNG_OUT_H */
