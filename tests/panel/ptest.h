/* SPDX-License-Identifier: MIT */
/* Shared helpers of the panel test suites (header only). */
#ifndef ZSPAN_TESTS_PANEL_PTEST_H
#define ZSPAN_TESTS_PANEL_PTEST_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "emu.h"
#include "emu_bus.h"
#include "zspan/panel.h"

static const zs_format pt_formats[2] = {ZS_FMT_RGB565_BE, ZS_FMT_RGB666};

/* One emulated panel on a bus, with the driver initialised. */
typedef struct pt_rig {
    emu_panel emu;
    emu_port port;
    zs_panel panel;
} pt_rig;

static inline void pt_print_errors(const emu_panel *e)
{
    unsigned i;
    for (i = 0; i < e->log_lines; i++)
        print_message("    emu: %s\n", e->log[i]);
}

/* Sets up emulator + port + driver; returns the driver status. */
static inline zs_panel_status pt_rig_open(pt_rig *r, const zs_panel_desc *d, zs_format fmt,
                                          unsigned rot, int async, unsigned latency,
                                          uint32_t max_transfer)
{
    const emu_model *m = emu_model_find(d->name);
    assert_non_null(m);
    assert_int_equal(emu_init(&r->emu, m), 0);
    assert_int_equal(emu_port_init(&r->port, &r->emu, async, latency, max_transfer), 0);
    return zs_panel_init(&r->panel, d, &r->port.bus, fmt, rot);
}

static inline void pt_rig_close(pt_rig *r)
{
    emu_port_drain(&r->port);
    emu_free(&r->emu);
}

/* A test picture: every pixel different enough that a flip, a transpose,
 * an offset or a channel swap changes it. Writes the wire bytes of pixel
 * (x, y) in fmt to out. */
static inline void pt_pattern_pixel(unsigned x, unsigned y, zs_format fmt, uint8_t *out)
{
    uint32_t h = (x * 73856093u) ^ (y * 19349663u) ^ ((x + 3u * y) * 83492791u);
    unsigned r = (h >> 3) & 0xFFu, g = (h >> 11) & 0xFFu, b = (h >> 19) & 0xFFu;
    if (fmt == ZS_FMT_RGB565_BE) {
        unsigned v = (r >> 3) << 11 | (g >> 2) << 5 | (b >> 3);
        out[0] = (uint8_t)(v >> 8);
        out[1] = (uint8_t)v;
    } else {
        out[0] = (uint8_t)(r & 0xFCu);
        out[1] = (uint8_t)(g & 0xFCu);
        out[2] = (uint8_t)(b & 0xFCu);
    }
}

static inline uint32_t pt_666(zs_format fmt, const uint8_t *p)
{
    return fmt == ZS_FMT_RGB565_BE ? emu_666_from_565be(p) : emu_666_from_666(p);
}

/* Compares the viewer's picture with an image in wire format (w x h, rows of
 * w*bpp bytes). Returns the number of differing pixels (prints the first). */
static inline unsigned pt_compare_view(const emu_panel *e, unsigned rot, const uint8_t *img,
                                       unsigned w, unsigned h, zs_format fmt)
{
    unsigned vw, vh, x, y, bad = 0, bpp = fmt == ZS_FMT_RGB565_BE ? 2u : 3u;
    uint32_t *view;
    emu_view_size(e, rot, &vw, &vh);
    assert_int_equal(vw, w);
    assert_int_equal(vh, h);
    view = malloc((size_t)w * h * sizeof *view);
    assert_non_null(view);
    emu_view_666(e, rot, view);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            uint32_t want = pt_666(fmt, img + ((size_t)y * w + x) * bpp);
            uint32_t got = view[(size_t)y * w + x];
            if (want != got) {
                if (bad == 0)
                    print_message("    first difference at (%u, %u): want %05X got %05X\n", x,
                                  y, (unsigned)want, (unsigned)got);
                bad++;
            }
        }
    free(view);
    return bad;
}

#endif
