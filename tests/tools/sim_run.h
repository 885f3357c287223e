/* SPDX-License-Identifier: MIT */
/*
 * Helpers of the command-line suites (test_sim, test_sim_models): run a
 * program (run_cmd.h); read back the PNG files zspan-sim writes (libpng), as
 * 8-bit RGB or 16-bit grey.
 */
#ifndef ZSPAN_TESTS_SIM_RUN_H
#define ZSPAN_TESTS_SIM_RUN_H

#include <png.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "run_cmd.h"

typedef struct image {
    int w, h, bytes;   /* bytes per pixel: 3 (RGB8) or 2 (grey 16, host order) */
    uint8_t *px;
} image;

/* Reads an RGB8 or GRAY16 PNG; 0 or -1. */
static int read_png(const char *path, image *img)
{
    FILE *f = fopen(path, "rb");
    png_structp png;
    png_infop info;
    png_bytepp rows = NULL;
    int y, ct, depth;

    memset(img, 0, sizeof *img);
    if (f == NULL)
        return -1;
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (info == NULL || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        free(rows);
        free(img->px);
        img->px = NULL;
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    img->w = (int)png_get_image_width(png, info);
    img->h = (int)png_get_image_height(png, info);
    ct = png_get_color_type(png, info);
    depth = png_get_bit_depth(png, info);
    if (!((ct == PNG_COLOR_TYPE_RGB && depth == 8) || (ct == PNG_COLOR_TYPE_GRAY && depth == 16)))
        png_error(png, "unexpected PNG type");
    img->bytes = ct == PNG_COLOR_TYPE_RGB ? 3 : 2;
    if (img->bytes == 2)
        png_set_swap(png); /* samples in host order (little-endian hosts) */
    img->px = malloc((size_t)img->w * (size_t)img->h * (size_t)img->bytes);
    rows = malloc((size_t)img->h * sizeof *rows);
    if (img->px == NULL || rows == NULL)
        png_error(png, "out of memory");
    for (y = 0; y < img->h; y++)
        rows[y] = img->px + (size_t)y * (size_t)img->w * (size_t)img->bytes;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    fclose(f);
    return 0;
}

static void free_image(image *img)
{
    free(img->px);
    img->px = NULL;
}

/* Pixel value: the id of a grey-16 image, or 0xRRGGBB. */
static uint32_t pixel(const image *img, int i)
{
    const uint8_t *p = img->px + (size_t)i * (size_t)img->bytes;
    uint16_t v;
    if (img->bytes == 3)
        return ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
    memcpy(&v, p, 2);
    return v;
}

static int same_image(const image *a, const image *b)
{
    return a->w == b->w && a->h == b->h && a->bytes == b->bytes &&
           memcmp(a->px, b->px, (size_t)a->w * (size_t)a->h * (size_t)a->bytes) == 0;
}

/* Pixels whose value is not 0 (the background of the suites' renders). */
static long covered(const image *img)
{
    long n = 0;
    int i;
    for (i = 0; i < img->w * img->h; i++)
        n += pixel(img, i) != 0;
    return n;
}

#endif
