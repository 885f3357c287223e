/* SPDX-License-Identifier: MIT */
/* Partial updates of the animated programs (see zs_partial.h). */
#include "zs_partial.h"

#include <string.h>

long zs_app_send_changes(zs_panel *lcd, const uint8_t *cur, const uint8_t *prev, size_t stride,
                         unsigned bpp, uint8_t *tmp, size_t tmp_bytes, zs_panel_status *ps)
{
    unsigned w = lcd->width, h = lcd->height, y = 0;
    long rows_sent = 0;
    while (y < h) {
        unsigned y0, y1, x0 = w, x1 = 0, gap = 0, yy;
        /* Find the next changed row. */
        while (y < h && prev != NULL && memcmp(cur + y * stride, prev + y * stride, stride) == 0)
            y++;
        if (y >= h)
            break;
        y0 = y;
        y1 = y;
        for (; y < h; y++) {
            const uint8_t *a = cur + y * stride, *b = prev != NULL ? prev + y * stride : NULL;
            unsigned first, last;
            if (b != NULL && memcmp(a, b, stride) == 0) {
                if (++gap > 2)
                    break;
                continue;
            }
            gap = 0;
            y1 = y + 1;
            if (b == NULL) {
                first = 0;
                last = w - 1;
            } else {
                for (first = 0; memcmp(a + first * bpp, b + first * bpp, bpp) == 0; first++) {
                }
                for (last = w - 1; memcmp(a + last * bpp, b + last * bpp, bpp) == 0; last--) {
                }
            }
            if (first < x0)
                x0 = first;
            if (last + 1 > x1)
                x1 = last + 1;
        }
        y = y1;
        *ps = zs_panel_window(lcd, (uint16_t)x0, (uint16_t)y0, (uint16_t)x1, (uint16_t)y1);
        if (*ps != ZS_PANEL_OK)
            return -1;
        { /* tmp is scratch: the in-place write may convert it (SSD1351 RGB666) */
            size_t row_bytes = (size_t)(x1 - x0) * bpp, used = 0;
            for (yy = y0; yy < y1; yy++) {
                if (used + row_bytes > tmp_bytes) {
                    if ((*ps = zs_panel_write_inplace(lcd, tmp, used)) != ZS_PANEL_OK)
                        return -1;
                    used = 0;
                }
                memcpy(tmp + used, cur + yy * stride + (size_t)x0 * bpp, row_bytes);
                used += row_bytes;
            }
            if (used > 0 && (*ps = zs_panel_write_inplace(lcd, tmp, used)) != ZS_PANEL_OK)
                return -1;
        }
        rows_sent += (long)(y1 - y0);
    }
    return rows_sent;
}
