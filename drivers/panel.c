/* SPDX-License-Identifier: MIT */
/* zspan panel driver: the parts shared by all command sets (geometry,
 * rotation, windows, pixel writes). What goes on the wire for each step
 * comes from the description's operations table (dcs.c, ssd1351.c). */
#include "panel_internal.h"

const char *zs_panel_strerror(zs_panel_status s)
{
    /* The texts are the header's comments (tests/panel/test_panel_contract.c
     * reads panel.h and compares). */
    switch (s) {
    case ZS_PANEL_OK: return "ok";
    case ZS_PANEL_ERR_NULL: return "NULL panel, description, bus, renderer or buffer";
    case ZS_PANEL_ERR_IO: return "the bus reported a failure";
    case ZS_PANEL_ERR_FORMAT: return "pixel format not supported by this panel";
    case ZS_PANEL_ERR_ROTATION: return "rotation not 0..3, or one the controller cannot do";
    case ZS_PANEL_ERR_WINDOW: return "empty window or outside the visible area";
    case ZS_PANEL_ERR_STATE:
        return "panel not initialised, or pixels without an open window or past its end";
    case ZS_PANEL_ERR_DESC: return "inconsistent panel description";
    case ZS_PANEL_ERR_BUFFER:
        return "buffer smaller than one row, band of no rows, or not whole pixels";
    case ZS_PANEL_ERR_RENDER: return "zs_render_rows failed (see render_status)";
    case ZS_PANEL_ERR_TIMEOUT:
        return "the bus gave up waiting for a pixel transfer (wait limit)";
    case ZS_PANEL_ERR_SIZE: return "renderer size differs from the panel size at its rotation";
    case ZS_PANEL_ERR_FRAME_FORMAT: return "the frame's pixel format is not the panel's";
    case ZS_PANEL_STATUS_COUNT: break;
    }
    return "unknown panel status";
}

zs_panel_status zs__panel_from_bus(zs_bus_status s)
{
    if (s == ZS_BUS_OK)
        return ZS_PANEL_OK;
    return s == ZS_BUS_ERR_TIMEOUT ? ZS_PANEL_ERR_TIMEOUT : ZS_PANEL_ERR_IO;
}

zs_panel_status zs__panel_cmd_if(zs_panel *p, int on, uint8_t yes, uint8_t no)
{
    return zs__panel_cmd(p, on ? yes : no, NULL, 0);
}

int zs__panel_invert_wanted(const zs_panel *p)
{
    return (p->desc->invert != 0) != (p->inverted != 0);
}

zs_panel_status zs__panel_cmd(zs_panel *p, uint8_t cmd, const uint8_t *params, size_t n)
{
    return zs__panel_from_bus(zs_bus_cmd(p->bus, cmd, params, n));
}

zs_panel_status zs__panel_run_records(zs_panel *p, const uint8_t *rec, size_t len)
{
    size_t i = 0;
    while (i < len) {
        uint8_t cmd, n;
        size_t np;
        zs_panel_status s;
        if (i + 2 > len)
            return ZS_PANEL_ERR_DESC;
        cmd = rec[i];
        n = rec[i + 1];
        np = (size_t)(n & 0x7Fu);
        i += 2;
        if (i + np + ((n & ZS_INIT_DELAY) ? 1u : 0u) > len)
            return ZS_PANEL_ERR_DESC;
        s = zs__panel_cmd(p, cmd, np ? rec + i : NULL, np);
        if (s != ZS_PANEL_OK)
            return s;
        i += np;
        if (n & ZS_INIT_DELAY)
            zs_bus_delay(p->bus, rec[i++]);
    }
    return ZS_PANEL_OK;
}

int zs_panel_supports(const zs_panel_desc *desc, zs_format format)
{
    return desc != NULL && (unsigned)format < 16u && (desc->formats & (1u << (unsigned)format));
}

uint32_t zs_panel_window_bytes(zs_format format, unsigned w, unsigned h)
{
    /* 32 bits: a 240x240 window is 115,200 bytes, past a 16-bit size_t (AVR) */
    if (format == ZS_FMT_MONO_PAGE)
        return (uint32_t)w * ((h + 7u) / 8u);
    if (format == ZS_FMT_MONO_MSB)
        return (uint32_t)((w + 7u) / 8u) * h;
    if (format == ZS_FMT_GRAY4)
        return (uint32_t)((w + 1u) / 2u) * h;
    return (uint32_t)w * h * (format == ZS_FMT_RGB666 ? 3u : 2u);
}

unsigned zs_panel_bytes_per_pixel(const zs_panel_desc *desc, zs_format format)
{
    if (!zs_panel_supports(desc, format))
        return 0;
    if (format == ZS_FMT_RGB565_BE)
        return 2;
    if (format == ZS_FMT_RGB666)
        return 3;
    return 0;
}

uint8_t zs_panel_madctl_for(const zs_panel_desc *desc, unsigned rotation)
{
    static const uint8_t toggle[4] = {
        0x00u,
        (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MV),
        (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MY),
        (uint8_t)(ZS_MADCTL_MY | ZS_MADCTL_MV),
    };
    if (desc == NULL)
        return 0;
    return (uint8_t)(desc->madctl ^ toggle[rotation & 3u]);
}

zs_panel_status zs_panel_geometry(const zs_panel_desc *desc, unsigned rotation, uint16_t *width,
                                  uint16_t *height, uint16_t *x_offset, uint16_t *y_offset)
{
    uint8_t m;
    uint16_t col, row;

    if (desc == NULL)
        return ZS_PANEL_ERR_NULL;
    if (rotation > 3u || (desc->rotations != 0 && !(desc->rotations & (1u << rotation))))
        return ZS_PANEL_ERR_ROTATION;
    if (desc->width == 0 || desc->height == 0 ||
        (uint32_t)desc->col_offset + desc->width > desc->ram_width ||
        (uint32_t)desc->row_offset + desc->height > desc->ram_height)
        return ZS_PANEL_ERR_DESC;
    m = zs_panel_madctl_for(desc, rotation);
    /* Address of the visible area's first column/row once the controller
     * mirrors its address counters (MX: column n is RAM column W-1-n). */
    col = (m & ZS_MADCTL_MX)
              ? (uint16_t)(desc->ram_width - desc->width - desc->col_offset)
              : desc->col_offset;
    row = (m & ZS_MADCTL_MY)
              ? (uint16_t)(desc->ram_height - desc->height - desc->row_offset)
              : desc->row_offset;
    if (m & ZS_MADCTL_MV) {
        /* Exchange: panel columns address RAM rows and panel rows RAM columns. */
        if (width) *width = desc->height;
        if (height) *height = desc->width;
        if (x_offset) *x_offset = row;
        if (y_offset) *y_offset = col;
    } else {
        if (width) *width = desc->width;
        if (height) *height = desc->height;
        if (x_offset) *x_offset = col;
        if (y_offset) *y_offset = row;
    }
    return ZS_PANEL_OK;
}

static zs_panel_status apply_geometry(zs_panel *p, unsigned rotation)
{
    zs_panel_status s = zs_panel_geometry(p->desc, rotation, &p->width, &p->height,
                                          &p->x_offset, &p->y_offset);
    if (s != ZS_PANEL_OK)
        return s;
    p->rotation = (uint8_t)rotation;
    p->madctl = zs_panel_madctl_for(p->desc, rotation);
    return ZS_PANEL_OK;
}

/* A table the common code can drive: the required operations exist. */
static int ops_complete(const zs_panel_ops *o)
{
    return o != NULL && o->init != NULL && o->format != NULL && o->orient != NULL &&
           o->invert != NULL && o->display != NULL && o->window != NULL;
}

/* Whether the panel can take `format`: one the module supports and its
 * command set has the register values for. */
static zs_panel_status format_ok(const zs_panel_desc *desc, zs_format format)
{
    if (!zs_panel_supports(desc, format))
        return ZS_PANEL_ERR_FORMAT;
    return desc->ops->check != NULL ? desc->ops->check(desc, format) : ZS_PANEL_OK;
}

zs_panel_status zs_panel_init(zs_panel *p, const zs_panel_desc *desc, zs_bus *bus,
                              zs_format format, unsigned rotation)
{
    zs_panel_status s;

    if (p == NULL || desc == NULL || bus == NULL || bus->ops == NULL)
        return ZS_PANEL_ERR_NULL;
    p->ready = 0;
    p->desc = desc;
    p->bus = bus;
    p->inverted = 0;
    p->use_ramwrc = 0;
    p->partial = 0;
    p->write_base = 0;
    p->mono_page = 0;
    p->mono_col = p->mono_cols = 0;
    p->scratch_next = 0;
    p->window_bytes = 0;
    p->window_total = 0;
    if (!ops_complete(desc->ops))
        return ZS_PANEL_ERR_DESC;
    if ((s = format_ok(desc, format)) != ZS_PANEL_OK)
        return s;
    p->format = format;
    if ((s = apply_geometry(p, rotation)) != ZS_PANEL_OK)
        return s;
    if ((s = desc->ops->init(p)) != ZS_PANEL_OK)
        return s;
    p->ready = 1;
    return ZS_PANEL_OK;
}

/* Common checks of the functions that need an initialised panel. */
static zs_panel_status ready(const zs_panel *p)
{
    if (p == NULL || p->desc == NULL || p->bus == NULL)
        return ZS_PANEL_ERR_NULL;
    return p->ready ? ZS_PANEL_OK : ZS_PANEL_ERR_STATE;
}

zs_panel_status zs_panel_set_rotation(zs_panel *p, unsigned rotation)
{
    zs_panel_status s;
    if ((s = ready(p)) != ZS_PANEL_OK)
        return s;
    if ((s = apply_geometry(p, rotation)) != ZS_PANEL_OK)
        return s;
    p->window_bytes = 0;
    return p->desc->ops->orient(p);
}

zs_panel_status zs_panel_set_format(zs_panel *p, zs_format format)
{
    zs_panel_status s;
    if ((s = ready(p)) != ZS_PANEL_OK)
        return s;
    if ((s = format_ok(p->desc, format)) != ZS_PANEL_OK)
        return s;
    p->format = format;
    p->window_bytes = 0; /* the open window was counted in the old format */
    return p->desc->ops->format(p);
}

zs_panel_status zs_panel_set_inversion(zs_panel *p, int on)
{
    zs_panel_status s;
    if ((s = ready(p)) != ZS_PANEL_OK)
        return s;
    p->inverted = on ? 1u : 0u;
    p->window_bytes = 0;
    return p->desc->ops->invert(p);
}

zs_panel_status zs_panel_display_on(zs_panel *p, int on)
{
    zs_panel_status s;
    if ((s = ready(p)) != ZS_PANEL_OK)
        return s;
    p->window_bytes = 0;
    return p->desc->ops->display(p, on);
}

zs_panel_status zs_panel_backlight(zs_panel *p, uint8_t level)
{
    if (p == NULL || p->bus == NULL)
        return ZS_PANEL_ERR_NULL;
    zs_bus_backlight(p->bus, level);
    return ZS_PANEL_OK;
}

zs_panel_status zs_panel_window(zs_panel *p, uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1)
{
    zs_panel_status s;
    uint16_t xs, ys, xe, ye;

    if ((s = ready(p)) != ZS_PANEL_OK)
        return s;
    if (x0 >= x1 || y0 >= y1 || x1 > p->width || y1 > p->height)
        return ZS_PANEL_ERR_WINDOW;
    /* 1-bit RAM is addressed in bytes: pages of 8 rows, or 8 columns */
    if (p->format == ZS_FMT_MONO_PAGE && (y0 % 8u || (y1 % 8u && y1 != p->height)))
        return ZS_PANEL_ERR_WINDOW;
    if (p->format == ZS_FMT_MONO_MSB && (x0 % 8u || (x1 % 8u && x1 != p->width)))
        return ZS_PANEL_ERR_WINDOW;
    /* 4-bit RAM: a column address is a pair of pixels */
    if (p->format == ZS_FMT_GRAY4 && (x0 % 2u || (x1 % 2u && x1 != p->width)))
        return ZS_PANEL_ERR_WINDOW;
    xs = (uint16_t)(x0 + p->x_offset);
    xe = (uint16_t)(x1 - 1u + p->x_offset);
    ys = (uint16_t)(y0 + p->y_offset);
    ye = (uint16_t)(y1 - 1u + p->y_offset);
    p->window_bytes = 0;
    if ((s = p->desc->ops->window(p, xs, ys, xe, ye)) != ZS_PANEL_OK)
        return s;
    p->window_total = zs_panel_window_bytes(p->format, (unsigned)(x1 - x0),
                                                      (unsigned)(y1 - y0));
    p->window_bytes = p->window_total;
    return ZS_PANEL_OK;
}

/* Checks shared by both writes, then the command set's per-write step. */
static zs_panel_status write_begin(zs_panel *p, const uint8_t *data, size_t n)
{
    if (p == NULL || p->desc == NULL || p->bus == NULL || (data == NULL && n > 0))
        return ZS_PANEL_ERR_NULL;
    if (!p->ready || p->window_bytes == 0 || n > p->window_bytes)
        return ZS_PANEL_ERR_STATE;
    if (n == 0 || p->desc->ops->write_begin == NULL)
        return ZS_PANEL_OK;
    return p->desc->ops->write_begin(p, n);
}

static zs_panel_encode_fn encoder_of(const zs_panel *p)
{
    return p->desc->ops->encoder != NULL ? p->desc->ops->encoder(p) : NULL;
}

zs_panel_status zs_panel_write(zs_panel *p, const uint8_t *data, size_t n)
{
    zs_panel_status s;
    zs_panel_encode_fn enc;

    if ((s = write_begin(p, data, n)) != ZS_PANEL_OK || n == 0)
        return s;
    enc = encoder_of(p);
    if (enc == NULL) {
        s = zs__panel_from_bus(zs_bus_pixels(p->bus, data, n));
        if (s == ZS_PANEL_OK)
            p->window_bytes -= (uint32_t)n;
        return s;
    }
    /* The caller's bytes stay untouched: convert piece by piece, alternating
     * between the two scratch buffers. The bus has at most one transfer in
     * flight, the piece sent last, so the buffer filled next is free. */
    while (n > 0) {
        size_t piece = n < ZS_PANEL_SCRATCH_BYTES ? n : ZS_PANEL_SCRATCH_BYTES;
        uint8_t *buf = p->scratch[p->scratch_next];
        enc(buf, data, piece);
        if ((s = zs__panel_from_bus(zs_bus_pixels(p->bus, buf, piece))) != ZS_PANEL_OK)
            return s;
        p->scratch_next ^= 1u;
        p->window_bytes -= (uint32_t)piece;
        data += piece;
        n -= piece;
    }
    return ZS_PANEL_OK;
}

zs_panel_status zs_panel_write_inplace(zs_panel *p, uint8_t *data, size_t n)
{
    zs_panel_status s;
    zs_panel_encode_fn enc;

    if ((s = write_begin(p, data, n)) != ZS_PANEL_OK || n == 0)
        return s;
    /* The caller owns data (passing a buffer the bus still owns is already a
     * breach of the bus contract), so it may be converted where it lies. */
    if ((enc = encoder_of(p)) != NULL)
        enc(data, data, n);
    if ((s = zs__panel_from_bus(zs_bus_pixels(p->bus, data, n))) != ZS_PANEL_OK)
        return s;
    p->window_bytes -= (uint32_t)n;
    return ZS_PANEL_OK;
}
