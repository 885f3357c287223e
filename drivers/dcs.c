/* Generic MIPI-DCS panel driver (ST7789, ILI9341, ST7735, GC9A01, ILI9488):
 * everything panel-specific comes from the zs_panel_desc table. */
#include "panel_internal.h"

/* Datasheet delays (ST7789V/ILI9341): 5 ms after SWRESET before the next
 * command and 120 ms before SLPOUT; 5 ms after SLPOUT before the next command
 * and 120 ms before SLPIN. We wait the long figure after both. */
#define DCS_SWRESET_MS 150u
#define DCS_SLPOUT_MS 120u
#define DCS_NORON_MS 10u
#define DCS_DISPON_MS 20u

static uint8_t colmod_of(const zs_panel *p)
{
    return p->format == ZS_FMT_RGB666 ? p->desc->colmod_666 : p->desc->colmod_565;
}

zs_panel_status zs__dcs_init(zs_panel *p)
{
    zs_panel_status s;
    uint8_t v;

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
    v = colmod_of(p);
    if ((s = zs__panel_cmd(p, ZS_DCS_COLMOD, &v, 1)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__dcs_orient(p)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__dcs_invert(p)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_cmd(p, ZS_DCS_NORON, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_NORON_MS);
    if ((s = zs__dcs_display(p, 1)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, DCS_DISPON_MS);
    return ZS_PANEL_OK;
}

zs_panel_status zs__dcs_orient(zs_panel *p)
{
    uint8_t v = p->madctl;
    return zs__panel_cmd(p, ZS_DCS_MADCTL, &v, 1);
}

zs_panel_status zs__dcs_invert(zs_panel *p)
{
    int on = (p->desc->invert != 0) != (p->inverted != 0);
    return zs__panel_cmd(p, on ? ZS_DCS_INVON : ZS_DCS_INVOFF, NULL, 0);
}

zs_panel_status zs__dcs_display(zs_panel *p, int on)
{
    return zs__panel_cmd(p, on ? ZS_DCS_DISPON : ZS_DCS_DISPOFF, NULL, 0);
}

/* Wire coordinates, inclusive, RAM offsets already added. */
zs_panel_status zs__dcs_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe, uint16_t ye)
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
