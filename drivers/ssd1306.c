/* SPDX-License-Identifier: MIT */
/* Monochrome OLED drivers: Solomon SSD1306, Sino Wealth SH1106 and Solomon
 * SSD0303, the zs_panel_ops_ssd1306, _sh1106 and _ssd0303 tables
 * (ZS_FMT_MONO_PAGE).
 *
 * Both take every byte of a command, parameters included, as a command
 * (D/C low on 4-wire SPI; control byte 0x00 on I2C), so each byte goes as a
 * parameterless bus command. Orientation: the abstract MX bit is the segment
 * remap (0xA1: the last RAM column drives SEG0), MY the COM scan direction
 * (0xC8), so rotation 2 turns the picture 180 degrees without touching the
 * bytes. The SSD1306 streams a window in horizontal addressing mode (0x20
 * 0x00, then 0x21 columns and 0x22 pages); the SH1106 has page addressing
 * only, so the driver sets the page (0xB0 | p) and the column (0x0L, 0x1H)
 * before each page of the window. */
#include "panel_internal.h"

#define OLED_RESET_MS 1u
#define OLED_DISPLAY_ON_MS 100u

/* Bytes of the command stream, one bus command each. */
static zs_panel_status send(zs_panel *p, const uint8_t *b, size_t n)
{
    size_t i;
    zs_panel_status s;
    for (i = 0; i < n; i++)
        if ((s = zs__panel_cmd(p, b[i], NULL, 0)) != ZS_PANEL_OK)
            return s;
    return ZS_PANEL_OK;
}

static zs_panel_status send1(zs_panel *p, uint8_t b)
{
    return send(p, &b, 1);
}

static zs_panel_status send2(zs_panel *p, uint8_t a, uint8_t b)
{
    uint8_t v[2];
    v[0] = a;
    v[1] = b;
    return send(p, v, 2);
}

static zs_panel_status oled_orient(zs_panel *p)
{
    zs_panel_status s;
    if ((s = send1(p, (uint8_t)(ZS_SSD1306_SEGREMAP | ((p->madctl & ZS_MADCTL_MX) ? 1u : 0u)))) !=
        ZS_PANEL_OK)
        return s;
    return send1(p, (uint8_t)(ZS_SSD1306_COMSCAN | ((p->madctl & ZS_MADCTL_MY) ? 8u : 0u)));
}

static zs_panel_status oled_invert(zs_panel *p)
{
    return send1(p, zs__panel_invert_wanted(p) ? ZS_SSD1306_INVERSE : ZS_SSD1306_NORMAL);
}

static zs_panel_status oled_display(zs_panel *p, int on)
{
    return send1(p, on ? ZS_SSD1306_DISPON : ZS_SSD1306_DISPOFF);
}

static zs_panel_status oled_format(zs_panel *p)
{
    (void)p; /* one format: nothing to send */
    return ZS_PANEL_OK;
}

/* The datasheets' power-up order: display off, timing and multiplex, the
 * charge pump (SSD1306) or DC-DC (SH1106), addressing, orientation, COM
 * pins, contrast and pre-charge, RAM shown, inversion, display on. */
enum { OLED_SSD1306, OLED_SH1106, OLED_SSD0303 };

static zs_panel_status oled_init(zs_panel *p, int kind)
{
    zs_panel_status s;
    const zs_panel_desc *d = p->desc;
    zs_bus_hw_reset(p->bus);
    zs_bus_delay(p->bus, OLED_RESET_MS);
    if ((s = send1(p, ZS_SSD1306_DISPOFF)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD1306_CLOCK, 0x80)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD1306_MUX, (uint8_t)(d->ram_height - 1u))) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD1306_OFFSET, 0x00)) != ZS_PANEL_OK ||
        (s = send1(p, ZS_SSD1306_STARTLINE)) != ZS_PANEL_OK)
        return s;
    if (kind == OLED_SSD0303) { /* DC-DC on; monochrome, normal power */
        if ((s = send2(p, ZS_SH1106_DCDC, 0x8B)) == ZS_PANEL_OK)
            s = send2(p, ZS_SSD0303_COLOR_MODE, 0x00);
    } else if (kind == OLED_SH1106)
        s = send2(p, ZS_SH1106_DCDC, 0x8B);
    else if ((s = send2(p, ZS_SSD1306_CHARGEPUMP, 0x14)) == ZS_PANEL_OK)
        s = send2(p, ZS_SSD1306_MEMMODE, 0x00); /* horizontal addressing */
    if (s != ZS_PANEL_OK)
        return s;
    if ((s = oled_orient(p)) != ZS_PANEL_OK ||
        (s = send2(p, ZS_SSD1306_COMPINS, d->mux)) != ZS_PANEL_OK)
        return s;
    if ((s = zs__panel_run_records(p, d->init, d->init_len)) != ZS_PANEL_OK)
        return s;
    if ((s = send1(p, ZS_SSD1306_RESUME)) != ZS_PANEL_OK || (s = oled_invert(p)) != ZS_PANEL_OK ||
        (s = oled_display(p, 1)) != ZS_PANEL_OK)
        return s;
    zs_bus_delay(p->bus, OLED_DISPLAY_ON_MS);
    return ZS_PANEL_OK;
}

static zs_panel_status ssd1306_init(zs_panel *p)
{
    return oled_init(p, OLED_SSD1306);
}

static zs_panel_status sh1106_init(zs_panel *p)
{
    return oled_init(p, OLED_SH1106);
}

static zs_panel_status ssd0303_init(zs_panel *p)
{
    return oled_init(p, OLED_SSD0303);
}

/* Horizontal addressing: columns xs..xe, pages ys/8..ye/8 (inclusive). */
static zs_panel_status ssd1306_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                      uint16_t ye)
{
    uint8_t c[6];
    c[0] = ZS_SSD1306_COLADDR;
    c[1] = (uint8_t)xs;
    c[2] = (uint8_t)xe;
    c[3] = ZS_SSD1306_PAGEADDR;
    c[4] = (uint8_t)(ys / 8u);
    c[5] = (uint8_t)(ye / 8u);
    return send(p, c, 6);
}

/* Page addressing: remember the window; each page is addressed when its
 * first byte is written (sh1106_write_begin). */
static zs_panel_status sh1106_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                     uint16_t ye)
{
    (void)ye;
    p->mono_page = (uint8_t)(ys / 8u);
    p->mono_col = xs;
    p->mono_cols = (uint16_t)(xe - xs + 1u);
    return ZS_PANEL_OK;
}

static zs_panel_status sh1106_write_begin(zs_panel *p, size_t n)
{
    uint32_t done = p->window_total - p->window_bytes;
    uint32_t in_page = done % p->mono_cols;
    uint8_t c[3];
    if (in_page + n > p->mono_cols)
        return ZS_PANEL_ERR_BUFFER; /* the RAM counter does not move to the next page */
    if (in_page != 0)
        return ZS_PANEL_OK;
    c[0] = (uint8_t)(ZS_SSD1306_PAGE | (uint8_t)(p->mono_page + done / p->mono_cols));
    c[1] = (uint8_t)(p->mono_col & 0x0Fu);
    c[2] = (uint8_t)(0x10u | (p->mono_col >> 4));
    return send(p, c, 3);
}

/* The three controllers share their commands; their tables differ in the
 * power-up and the addressing only (the SSD0303 addresses its RAM like the
 * SH1106: page mode only). */
#define OLED_OPS(label, init_fn, window_fn, write_begin_fn)                                     \
    {                                                                                          \
        .name = label, .check = NULL, .init = init_fn, .format = oled_format,                  \
        .orient = oled_orient, .invert = oled_invert, .display = oled_display,                 \
        .window = window_fn, .write_begin = write_begin_fn, .encoder = NULL, .frame_end = NULL \
    }

const zs_panel_ops zs_panel_ops_ssd1306 = OLED_OPS("SSD1306", ssd1306_init, ssd1306_window, NULL);
const zs_panel_ops zs_panel_ops_sh1106 =
    OLED_OPS("SH1106", sh1106_init, sh1106_window, sh1106_write_begin);
const zs_panel_ops zs_panel_ops_ssd0303 =
    OLED_OPS("SSD0303", ssd0303_init, sh1106_window, sh1106_write_begin);
