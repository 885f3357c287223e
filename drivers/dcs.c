/* SPDX-License-Identifier: MIT */
/* Generic MIPI-DCS panel driver (ST7789, ILI9341, ST7735, GC9A01, ILI9488):
 * the zs_panel_ops_dcs table. Everything module-specific comes from the
 * zs_panel_desc table. */
#include "panel_internal.h"

/* Datasheet delays (ST7789V/ILI9341): 5 ms after SWRESET before the next
 * command and 120 ms before SLPOUT; 5 ms after SLPOUT before the next command
 * and 120 ms before SLPIN. We wait the long figure after both. */
#define DCS_SWRESET_MS 150u
#define DCS_SLPOUT_MS 120u
#define DCS_NORON_MS 10u
#define DCS_DISPON_MS 20u

static uint8_t colmod_for(const zs_panel_desc *d, zs_format format)
{
    return format == ZS_FMT_RGB666 ? d->colmod_666 : d->colmod_565;
}

static zs_panel_status dcs_check(const zs_panel_desc *d, zs_format format)
{
    return colmod_for(d, format) != 0 ? ZS_PANEL_OK : ZS_PANEL_ERR_DESC;
}

static zs_panel_status dcs_format(zs_panel *p)
{
    uint8_t v = colmod_for(p->desc, p->format);
    return zs__panel_cmd(p, ZS_DCS_COLMOD, &v, 1);
}

static zs_panel_status dcs_orient(zs_panel *p)
{
    uint8_t v = p->madctl;
    return zs__panel_cmd(p, ZS_DCS_MADCTL, &v, 1);
}

static zs_panel_status dcs_invert(zs_panel *p)
{
    return zs__panel_cmd_if(p, zs__panel_invert_wanted(p), ZS_DCS_INVON, ZS_DCS_INVOFF);
}

static zs_panel_status dcs_display(zs_panel *p, int on)
{
    return zs__panel_cmd_if(p, on, ZS_DCS_DISPON, ZS_DCS_DISPOFF);
}

static zs_panel_status dcs_init(zs_panel *p)
{
    zs_panel_status s;

    zs_bus_hw_reset(p->bus);
    if ((s = zs__panel_cmd(p, ZS_DCS_SWRESET, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_SWRESET_MS);
    s = zs__panel_run_records(p, p->desc->init, p->desc->init_len);
    if (s != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_cmd(p, ZS_DCS_SLPOUT, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_SLPOUT_MS);
    if ((s = dcs_format(p)) != ZS_PANEL_OK)
        return s;
    if ((s = dcs_orient(p)) != ZS_PANEL_OK)
        return s;
    if ((s = dcs_invert(p)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_cmd(p, ZS_DCS_NORON, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_NORON_MS);
    if ((s = dcs_display(p, 1)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_DISPON_MS);
    return ZS_PANEL_OK;
}

/* Wire coordinates, inclusive, RAM offsets already added. */
static zs_panel_status dcs_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                  uint16_t ye)
{
    uint8_t b[4];
    zs_panel_status s;

    b[0] = (uint8_t)(xs >> 8);
    b[1] = (uint8_t)(xs & 0xFFu);
    b[2] = (uint8_t)(xe >> 8);
    b[3] = (uint8_t)(xe & 0xFFu);
    if ((s = zs__panel_cmd(p, ZS_DCS_CASET, b, 4)) != ZS_PANEL_OK)
        return s;
    b[0] = (uint8_t)(ys >> 8);
    b[1] = (uint8_t)(ys & 0xFFu);
    b[2] = (uint8_t)(ye >> 8);
    b[3] = (uint8_t)(ye & 0xFFu);
    if ((s = zs__panel_cmd(p, ZS_DCS_RASET, b, 4)) != ZS_PANEL_OK)
        return s;
    return zs__panel_cmd(p, ZS_DCS_RAMWR, NULL, 0);
}

/* RAMWRC continues the memory write where the last one stopped; it is only
 * defined on pixel boundaries, so with it every write must be whole pixels. */
static zs_panel_status dcs_write_begin(zs_panel *p, size_t n)
{
    unsigned bpp;
    if (!p->use_ramwrc)
        return ZS_PANEL_OK;
    bpp = zs_panel_bytes_per_pixel(p->desc, p->format);
    if (bpp == 0 || n % bpp != 0 || (p->window_total - p->window_bytes) % bpp != 0)
        return ZS_PANEL_ERR_BUFFER;
    if (p->window_bytes == p->window_total)
        return ZS_PANEL_OK; /* the window's RAMWR is still current */
    return zs__panel_cmd(p, ZS_DCS_RAMWRC, NULL, 0);
}

const zs_panel_ops zs_panel_ops_dcs = {
    .name = "MIPI DCS",
    .check = dcs_check,
    .init = dcs_init,
    .format = dcs_format,
    .orient = dcs_orient,
    .invert = dcs_invert,
    .display = dcs_display,
    .window = dcs_window,
    .write_begin = dcs_write_begin,
    .encoder = NULL, /* the DCS wire takes zspan's RGB565 BE and RGB666 bytes as they are */
};
