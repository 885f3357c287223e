/* SPDX-License-Identifier: MIT */
/* E-paper driver: Solomon SSD1680 (250x122 class), the zs_panel_ops_ssd1680
 * table (ZS_FMT_MONO_MSB: bit 1 = white, as zspan's 1 = light).
 *
 * Commands take their parameters with D/C high, like DCS. A frame is written
 * into the black/white RAM (0x24) through a window (0x44 bytes, 0x45 gates,
 * 0x4E/0x4F counters; data entry 0x03: X then Y increasing), then the
 * refresh runs (0x22 sequence, 0x20) while BUSY is high; the driver waits
 * the description's refresh time through the bus's delay hook.
 *
 * Partial refresh (LUT mode 2) drives only the pixels whose new value (0x24)
 * differs from the second RAM (0x26), which must hold what the glass shows.
 * Without a framebuffer the driver cannot copy it: after a refresh, stream
 * the same frame again with write_base = 1 (windows then write 0x26 and no
 * refresh runs), then set partial = 1 for the next frames. */
#include "panel_internal.h"

#define SSD1680_RESET_MS 10u
#define SSD1680_SWRESET_MS 10u

static zs_panel_status cmd(zs_panel *p, uint8_t c, const uint8_t *v, size_t n)
{
    return zs__panel_cmd(p, c, v, n);
}

static zs_panel_status cmd1(zs_panel *p, uint8_t c, uint8_t v)
{
    return cmd(p, c, &v, 1);
}

static zs_panel_status ssd1680_init(zs_panel *p)
{
    const zs_panel_desc *d = p->desc;
    uint8_t drv[3];
    zs_panel_status s;
    zs_bus_hw_reset(p->bus);
    zs_bus_delay(p->bus, SSD1680_RESET_MS);
    if ((s = cmd(p, ZS_SSD1680_SWRESET, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, SSD1680_SWRESET_MS); /* BUSY after SWRESET */
    drv[0] = (uint8_t)((d->height - 1u) & 0xFFu);
    drv[1] = (uint8_t)((d->height - 1u) >> 8);
    drv[2] = 0x00; /* gate scan G0 first */
    if ((s = cmd(p, ZS_SSD1680_DRIVER_OUTPUT, drv, 3)) != ZS_PANEL_OK ||
        (s = cmd1(p, ZS_SSD1680_DATA_ENTRY, 0x03)) != ZS_PANEL_OK)
        return s;
    return zs__panel_run_records(p, d->init, d->init_len);
}

static zs_panel_status ssd1680_nothing(zs_panel *p)
{
    (void)p;
    return ZS_PANEL_OK;
}

/* No inversion register: 0x21's RAM option could, but the glass's white is
 * RAM bit 1 and zspan's ZS_MONO_INVERT gives the other polarity. */
static zs_panel_status ssd1680_invert(zs_panel *p)
{
    return zs__panel_invert_wanted(p) ? ZS_PANEL_ERR_FORMAT : ZS_PANEL_OK;
}

static zs_panel_status ssd1680_display(zs_panel *p, int on)
{
    /* e-paper keeps its picture without power: off is deep sleep mode 1 */
    return on ? ZS_PANEL_OK : cmd1(p, ZS_SSD1680_DEEP_SLEEP, 0x01);
}

static zs_panel_status ssd1680_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                      uint16_t ye)
{
    uint8_t x[2], y[4];
    zs_panel_status s;
    x[0] = (uint8_t)(xs / 8u);
    x[1] = (uint8_t)(xe / 8u);
    y[0] = (uint8_t)(ys & 0xFFu);
    y[1] = (uint8_t)(ys >> 8);
    y[2] = (uint8_t)(ye & 0xFFu);
    y[3] = (uint8_t)(ye >> 8);
    if ((s = cmd(p, ZS_SSD1680_RAM_X, x, 2)) != ZS_PANEL_OK ||
        (s = cmd(p, ZS_SSD1680_RAM_Y, y, 4)) != ZS_PANEL_OK ||
        (s = cmd1(p, ZS_SSD1680_RAM_X_COUNT, x[0])) != ZS_PANEL_OK ||
        (s = cmd(p, ZS_SSD1680_RAM_Y_COUNT, y, 2)) != ZS_PANEL_OK)
        return s;
    return cmd(p, p->write_base ? ZS_SSD1680_WRITE_RED : ZS_SSD1680_WRITE_BW, NULL, 0);
}

static zs_panel_status ssd1680_frame_end(zs_panel *p)
{
    zs_panel_status s;
    if (p->write_base)
        return ZS_PANEL_OK;
    if ((s = cmd1(p, ZS_SSD1680_UPDATE_CTRL2,
                  p->partial ? ZS_SSD1680_SEQ_PARTIAL : ZS_SSD1680_SEQ_FULL)) != ZS_PANEL_OK ||
        (s = cmd(p, ZS_SSD1680_ACTIVATE, NULL, 0)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, p->desc->refresh_ms); /* BUSY high while the glass changes */
    return ZS_PANEL_OK;
}

const zs_panel_ops zs_panel_ops_ssd1680 = {
    .name = "SSD1680",
    .check = NULL,
    .init = ssd1680_init,
    .format = ssd1680_nothing,
    .orient = ssd1680_nothing, /* rotation 0 only (desc->rotations) */
    .invert = ssd1680_invert,
    .display = ssd1680_display,
    .window = ssd1680_window,
    .write_begin = NULL,
    .encoder = NULL,
    .frame_end = ssd1680_frame_end,
};
