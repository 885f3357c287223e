/* SPDX-License-Identifier: MIT */
/* The VM's static MCP2210 model never writes PNG files: no libpng in it. */
#include "emu.h"

int emu_png_write_rgb(const char *path, const uint8_t *rgb, unsigned w, unsigned h)
{
    (void)path;
    (void)rgb;
    (void)w;
    (void)h;
    return -1;
}
