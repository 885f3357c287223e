/* SPDX-License-Identifier: MIT */
/* Helpers shared by the port tests: the expected picture of a demo frame. */
#ifndef ZSPAN_TEST_PORTS_COMMON_H
#define ZSPAN_TEST_PORTS_COMMON_H

#include <stdint.h>

#include "emu.h"
#include "zspan/zspan.h"

/* Renders demo frame `frame` (span mode, Gouraud, RGB565 big-endian: what
 * zspan-linux and zspan-mcp2210 send by default) at w x h and returns it as
 * 6-bit channels (r << 12 | g << 6 | b), the emulated panel's view format.
 * malloc'd; NULL on failure. */
uint32_t *ports_demo_666(unsigned w, unsigned h, uint32_t frame);

/* Pixels of the panel's view (rotation 0) that differ from want; prints the
 * first difference. */
unsigned ports_view_diff(const emu_panel *e, const uint32_t *want, unsigned w, unsigned h);

/* Counts pixels that differ between two 6-bit images. */
unsigned ports_image_diff(const uint32_t *got, const uint32_t *want, unsigned w, unsigned h,
                          const char *what);

#endif
