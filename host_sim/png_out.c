/* SPDX-License-Identifier: MIT */
/* zspan-sim: PNG writing with libpng (host only). */
#include "png_out.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Writes height rows (each already in PNG byte order) to path. */
static int write_png(const char *path, int width, int height, int bit_depth, int color_type,
                     png_bytepp rows)
{
    FILE *fp;
    png_structp png;
    png_infop info;
    int ok;

    fp = fopen(path, "wb");
    if (fp == NULL) {
        fprintf(stderr, "zspan-sim: cannot write %s: %s\n", path, strerror(errno));
        return -1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL) {
        png_destroy_write_struct(&png, &info);
        fclose(fp);
        fprintf(stderr, "zspan-sim: %s: libpng initialisation failed\n", path);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(fp);
        fprintf(stderr, "zspan-sim: %s: libpng write error\n", path);
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, bit_depth, color_type,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    ok = fflush(fp) == 0 && !ferror(fp);
    if (fclose(fp) != 0)
        ok = 0;
    if (!ok) {
        fprintf(stderr, "zspan-sim: error writing %s: %s\n", path, strerror(errno));
        return -1;
    }
    return 0;
}

int png_write_rgb8(const char *path, int width, int height, const uint8_t *rgb, size_t stride)
{
    png_bytepp rows;
    int y, rc;

    rows = malloc((size_t)height * sizeof *rows);
    if (rows == NULL) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        return -1;
    }
    for (y = 0; y < height; y++)
        rows[y] = (png_bytep)(uintptr_t)(rgb + (size_t)y * stride);
    rc = write_png(path, width, height, 8, PNG_COLOR_TYPE_RGB, rows);
    free(rows);
    return rc;
}

int png_write_gray16(const char *path, int width, int height, const void *values,
                     size_t stride)
{
    png_bytepp rows;
    uint8_t *be;
    int x, y, rc;

    rows = malloc((size_t)height * sizeof *rows);
    be = malloc((size_t)width * (size_t)height * 2u);
    if (rows == NULL || be == NULL) {
        free(rows);
        free(be);
        fprintf(stderr, "zspan-sim: out of memory\n");
        return -1;
    }
    for (y = 0; y < height; y++) {
        const uint8_t *src = (const uint8_t *)values + (size_t)y * stride;
        uint8_t *dst = be + (size_t)y * (size_t)width * 2u;
        for (x = 0; x < width; x++) {
            uint16_t v;
            memcpy(&v, src + (size_t)x * 2u, sizeof v);
            dst[2 * x] = (uint8_t)(v >> 8);      /* PNG samples are big-endian */
            dst[2 * x + 1] = (uint8_t)(v & 0xFFu);
        }
        rows[y] = dst;
    }
    rc = write_png(path, width, height, 16, PNG_COLOR_TYPE_GRAY, rows);
    free(rows);
    free(be);
    return rc;
}
