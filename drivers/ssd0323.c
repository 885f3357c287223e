/* SPDX-License-Identifier: MIT */
/* Solomon SSD0323 4-bit greyscale OLED driver (128 x 80 RAM, 16 levels): the
 * zs_panel_ops_ssd0323 table, format ZS_FMT_GRAY4.
 *
 * Over 4-wire SPI the SSD0323 takes a command's parameters with D/C low too,
 * so every byte goes as a parameterless bus command; only RAM data goes with
 * D/C high, and needs no "write RAM" command. The RAM holds two pixels a
 * byte: a column address (0x15, 0..63) is a pair of pixels, so windows start
 * on an even column and end on an odd one (or the last one). The re-map
 * register (0xA0) is set with its nibble re-map bit, so the high nibble of a
 * byte is the left pixel of the pair, as in ZS_FMT_GRAY4; horizontal address
 * increment, COM split odd/even (the glass's wiring). Rotation 0 only. */
#include "panel_internal.h"

#define SSD0323_RESET_MS 1u
#define SSD0323_DISPLAY_ON_MS 100u

static zs_panel_status send(zs_panel *p, const uint8_t *b, size_t n)
{
    size_t i;
    zs_panel_status s;
    for (i = 0; i < n; i++)
        if ((s = zs__panel_cmd(p, b[i], NULL, 0)) != ZS_PANEL_OK)
            return s;
    return ZS_PANEL_OK;
}

static zs_panel_status send2(zs_panel *p, uint8_t a, uint8_t b)
{
    uint8_t v[2];
    v[0] = a;
    v[1] = b;
    return send(p, v, 2);
}

static zs_panel_status ssd0323_orient(zs_panel *p)
{
    uint8_t remap = (uint8_t)(ZS_SSD0323_RM_NIBBLE | ZS_SSD0323_RM_COMSPLIT);
    if (p->madctl & ZS_MADCTL_MX)
        remap = (uint8_t)(remap | ZS_SSD0323_RM_COLUMN);
    if (p->madctl & ZS_MADCTL_MY)
        remap = (uint8_t)(remap | ZS_SSD0323_RM_COM);
    return send2(p, ZS_SSD0323_REMAP, remap);
}

static zs_panel_status ssd0323_invert(zs_panel *p)
{
    return zs__panel_cmd_if(p, zs__panel_invert_wanted(p), ZS_SSD0323_INVERSE, ZS_SSD0323_NORMAL);
}

static zs_panel_status ssd0323_display(zs_panel *p, int on)
{
    return zs__panel_cmd_if(p, on, ZS_SSD0323_DISPON, ZS_SSD0323_DISPOFF);
}

static zs_panel_status ssd0323_format(zs_panel *p)
{
    (void)p; /* one format: nothing to send */
    return ZS_PANEL_OK;
}

/* The datasheet's power-up order: display off, re-map, start line and
 * offset, multiplex ratio, then the module's analogue settings (contrast,
 * current range, phase and row periods, clock, grey-scale table, levels),
 * normal display, display on. */
static zs_panel_status ssd0323_init(zs_panel *p)
{
    zs_panel_status s;
    const zs_panel_desc *d = p->desc;
    zs_bus_hw_reset(p->bus);
    zs_bus_delay(p->bus, SSD0323_RESET_MS);
    if ((s = ssd0323_display(p, 0)) != ZS_PANEL_OK || (s = ssd0323_orient(p)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD0323_STARTLINE, 0x00)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD0323_OFFSET, 0x00)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD0323_MUX, (uint8_t)(d->height - 1u))) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_run_records(p, d->init, d->init_len)) != ZS_PANEL_OK)
        return s;
    if ((s = ssd0323_invert(p)) != ZS_PANEL_OK || (s = ssd0323_display(p, 1)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, SSD0323_DISPLAY_ON_MS);
    return ZS_PANEL_OK;
}

/* Columns in pairs of pixels (xs even; xe odd, or the last pixel), rows. */
static zs_panel_status ssd0323_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                      uint16_t ye)
{
    uint8_t c[6];
    c[0] = ZS_SSD0323_SETCOLUMN;
    c[1] = (uint8_t)(xs / 2u);
    c[2] = (uint8_t)(xe / 2u);
    c[3] = ZS_SSD0323_SETROW;
    c[4] = (uint8_t)ys;
    c[5] = (uint8_t)ye;
    return send(p, c, 6);
}

const zs_panel_ops zs_panel_ops_ssd0323 = {
    .name = "SSD0323",
    .check = NULL,
    .init = ssd0323_init,
    .format = ssd0323_format,
    .orient = ssd0323_orient,
    .invert = ssd0323_invert,
    .display = ssd0323_display,
    .window = ssd0323_window,
    .write_begin = NULL,
    .encoder = NULL,
    .frame_end = NULL,
};
