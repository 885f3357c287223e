/* SPDX-License-Identifier: MIT */
/* 8-bit RGB PNG writer for the emulated panels (libpng). */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emu.h"

int emu_png_write_rgb(const char *path, const uint8_t *rgb, unsigned w, unsigned h)
{
    FILE *f;
    png_structp png;
    png_infop info;
    unsigned y;

    if (path == NULL || rgb == NULL || w == 0 || h == 0)
        return -1;
    f = fopen(path, "wb");
    if (f == NULL)
        return -1;
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++)
        png_write_row(png, (png_const_bytep)(rgb + (size_t)y * w * 3));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(f) == 0 ? 0 : -1;
}

int emu_png_read_rgb(const char *path, uint8_t **rgb, unsigned *w, unsigned *h)
{
    png_image img;
    uint8_t *buf;

    *rgb = NULL;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path))
        return -1;
    img.format = PNG_FORMAT_RGB;
    buf = malloc(PNG_IMAGE_SIZE(img));
    if (buf == NULL) {
        png_image_free(&img);
        return -1;
    }
    if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&img);
        return -1;
    }
    *rgb = buf;
    *w = img.width;
    *h = img.height;
    return 0;
}
