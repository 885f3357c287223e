/* SPDX-License-Identifier: MIT */
/* SSD1351 128x128 colour OLED driver (Solomon command set): the
 * zs_panel_ops_ssd1351 table.
 *
 * Orientation uses the same abstract MY/MX/MV/BGR bits as MADCTL, mapped to
 * the remap register 0xA0: MV -> vertical address increment, MX -> column
 * address remap, MY -> COM scan remap, BGR -> colour order C-B-A. With MV the
 * counter runs down a RAM column, so the window's column range (0x15) is the
 * panel's row range and its row range (0x75) the panel's column range. */
#include "panel_internal.h"

#define SSD1351_RESET_MS 1u
#define SSD1351_DISPLAY_ON_MS 100u

/* The remap (0xA0) parameter for the panel's orientation and format. */
static uint8_t ssd1351_remap(const zs_panel *p)
{
    uint8_t m = p->madctl;
    uint8_t v = ZS_SSD1351_RM_COMSPLIT;
    v = (uint8_t)(v | (p->format == ZS_FMT_RGB666 ? ZS_SSD1351_RM_262K : ZS_SSD1351_RM_65K));
    if (m & ZS_MADCTL_MV)
        v = (uint8_t)(v | ZS_SSD1351_RM_VINC);
    if (m & ZS_MADCTL_MX)
        v = (uint8_t)(v | ZS_SSD1351_RM_COLREMAP);
    if (m & ZS_MADCTL_MY)
        v = (uint8_t)(v | ZS_SSD1351_RM_COMREMAP);
    if (m & ZS_MADCTL_BGR)
        v = (uint8_t)(v | ZS_SSD1351_RM_CBA);
    return v;
}

static zs_panel_status cmd1(zs_panel *p, uint8_t cmd, uint8_t v)
{
    return zs__panel_cmd(p, cmd, &v, 1);
}

static zs_panel_status ssd1351_orient(zs_panel *p)
{
    return cmd1(p, ZS_SSD1351_REMAP, ssd1351_remap(p));
}

static zs_panel_status ssd1351_invert(zs_panel *p)
{
    return zs__panel_cmd_if(p, zs__panel_invert_wanted(p), ZS_SSD1351_INVERSE, ZS_SSD1351_NORMAL);
}

static zs_panel_status ssd1351_display(zs_panel *p, int on)
{
    return zs__panel_cmd_if(p, on, ZS_SSD1351_SLEEP_OFF, ZS_SSD1351_SLEEP_ON);
}

static zs_panel_status ssd1351_init(zs_panel *p)
{
    zs_panel_status s;

    zs_bus_hw_reset(p->bus);
    zs_bus_delay(p->bus, SSD1351_RESET_MS);
    /* Unlock the driver, then the protected registers (A2, B1, B3, BB, BE, C1). */
    if ((s = cmd1(p, ZS_SSD1351_COMMANDLOCK, 0x12)) != ZS_PANEL_OK)
        return s;
    if ((s = cmd1(p, ZS_SSD1351_COMMANDLOCK, 0xB1)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_cmd(p, ZS_SSD1351_SLEEP_ON, NULL, 0)) != ZS_PANEL_OK)
        return s;
    s = zs__panel_run_records(p, p->desc->init, p->desc->init_len);
    if (s != ZS_PANEL_OK)
        return s;
    if ((s = cmd1(p, ZS_SSD1351_DISPLAYOFFSET, 0x00)) != ZS_PANEL_OK)
        return s;
    if ((s = cmd1(p, ZS_SSD1351_STARTLINE, 0x00)) != ZS_PANEL_OK)
        return s;
    if ((s = ssd1351_orient(p)) != ZS_PANEL_OK)
        return s;
    if ((s = ssd1351_invert(p)) != ZS_PANEL_OK)
        return s;
    if ((s = ssd1351_display(p, 1)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, SSD1351_DISPLAY_ON_MS);
    return ZS_PANEL_OK;
}

static zs_panel_status ssd1351_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                      uint16_t ye)
{
    uint8_t c[2], r[2];
    zs_panel_status s;

    if (p->madctl & ZS_MADCTL_MV) {
        c[0] = (uint8_t)ys;
        c[1] = (uint8_t)ye;
        r[0] = (uint8_t)xs;
        r[1] = (uint8_t)xe;
    } else {
        c[0] = (uint8_t)xs;
        c[1] = (uint8_t)xe;
        r[0] = (uint8_t)ys;
        r[1] = (uint8_t)ye;
    }
    if ((s = zs__panel_cmd(p, ZS_SSD1351_SETCOLUMN, c, 2)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_cmd(p, ZS_SSD1351_SETROW, r, 2)) != ZS_PANEL_OK)
        return s;
    return zs__panel_cmd(p, ZS_SSD1351_WRITERAM, NULL, 0);
}

/* At 262k colours the SSD1351 takes each channel's 6 bits in bits 5..0;
 * zspan's RGB666 holds them in bits 7..2. */
static void ssd1351_encode_666(uint8_t *dst, const uint8_t *src, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        dst[i] = (uint8_t)(src[i] >> 2);
}

static zs_panel_encode_fn ssd1351_encoder(const zs_panel *p)
{
    return p->format == ZS_FMT_RGB666 ? ssd1351_encode_666 : NULL;
}

const zs_panel_ops zs_panel_ops_ssd1351 = {
    .name = "SSD1351",
    .check = NULL, /* no per-module register values: any format in desc->formats works */
    .init = ssd1351_init,
    .format = ssd1351_orient, /* the colour depth lives in the remap register */
    .orient = ssd1351_orient,
    .invert = ssd1351_invert,
    .display = ssd1351_display,
    .window = ssd1351_window,
    .write_begin = NULL,
    .encoder = ssd1351_encoder,
};
