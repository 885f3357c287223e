/* SPDX-License-Identifier: MIT */
/* zspan panel tables: one constant description per supported module.
 *
 * Init records: cmd, n (| ZS_INIT_DELAY), params..., [delay ms]. They hold the
 * module's power, timing and gamma settings and run before SLPOUT (DCS) or
 * after the command unlock (SSD1351); the driver itself sends reset, sleep
 * out, COLMOD, MADCTL, inversion, normal mode and display on. */
#include <string.h>

#include "zspan/panel.h"

#define FMT_BIT(f) ((uint8_t)(1u << (f)))
#define FMT_565_666 ((uint8_t)(FMT_BIT(ZS_FMT_RGB565_BE) | FMT_BIT(ZS_FMT_RGB666)))

/* ST7789V: porch, gate, VCOM, LCM, VDV/VRH, frame rate, power, gamma. */
static const uint8_t st7789_init[] = {
    0xB2, 5, 0x0C, 0x0C, 0x00, 0x33, 0x33, /* PORCTRL: porch setting */
    0xB7, 1, 0x35,                         /* GCTRL: VGH 13.26 V, VGL -10.43 V */
    0xBB, 1, 0x20,                         /* VCOMS: 0.9 V */
    0xC0, 1, 0x2C,                         /* LCMCTRL */
    0xC2, 2, 0x01, 0xFF,                   /* VDVVRHEN: VDV/VRH from commands */
    0xC3, 1, 0x12,                         /* VRHS */
    0xC4, 1, 0x20,                         /* VDVS */
    0xC6, 1, 0x0F,                         /* FRCTRL2: 60 Hz */
    0xD0, 2, 0xA4, 0xA1,                   /* PWCTRL1: AVDD 6.8, AVCL -4.8, VDDS 2.3 */
    0xE0, 14, 0xD0, 0x04, 0x0D, 0x11, 0x13, 0x2B, 0x3F, 0x54, 0x4C, 0x18, 0x0D, 0x0B,
    0x1F, 0x23,                            /* PVGAMCTRL */
    0xE1, 14, 0xD0, 0x04, 0x0C, 0x11, 0x13, 0x2C, 0x3F, 0x44, 0x51, 0x2F, 0x1F, 0x1F,
    0x20, 0x23,                            /* NVGAMCTRL */
};

/* ILI9341: extended power/timing registers, VCOM, frame rate, gamma. */
static const uint8_t ili9341_init[] = {
    0xCF, 3, 0x00, 0xC1, 0x30,             /* power control B */
    0xED, 4, 0x64, 0x03, 0x12, 0x81,       /* power on sequence */
    0xE8, 3, 0x85, 0x00, 0x78,             /* driver timing control A */
    0xCB, 5, 0x39, 0x2C, 0x00, 0x34, 0x02, /* power control A */
    0xF7, 1, 0x20,                         /* pump ratio */
    0xEA, 2, 0x00, 0x00,                   /* driver timing control B */
    0xC0, 1, 0x23,                         /* PWCTR1: GVDD 4.6 V */
    0xC1, 1, 0x10,                         /* PWCTR2 */
    0xC5, 2, 0x3E, 0x28,                   /* VMCTR1 */
    0xC7, 1, 0x86,                         /* VMCTR2 */
    0xB1, 2, 0x00, 0x18,                   /* FRMCTR1: 79 Hz */
    0xB6, 3, 0x08, 0x82, 0x27,             /* display function control */
    0xF2, 1, 0x00,                         /* 3-gamma off */
    0x26, 1, 0x01,                         /* gamma curve 1 */
    0xE0, 15, 0x0F, 0x31, 0x2B, 0x0C, 0x0E, 0x08, 0x4E, 0xF1, 0x37, 0x07, 0x10, 0x03,
    0x0E, 0x09, 0x00,                      /* PGAMCTRL */
    0xE1, 15, 0x00, 0x0E, 0x14, 0x03, 0x11, 0x07, 0x31, 0xC1, 0x48, 0x08, 0x0F, 0x0C,
    0x31, 0x36, 0x0F,                      /* NGAMCTRL */
};

/* ST7735R/S: frame rates, inversion control, power, gamma. */
static const uint8_t st7735_init[] = {
    0xB1, 3, 0x01, 0x2C, 0x2D,             /* FRMCTR1 normal mode */
    0xB2, 3, 0x01, 0x2C, 0x2D,             /* FRMCTR2 idle mode */
    0xB3, 6, 0x01, 0x2C, 0x2D, 0x01, 0x2C, 0x2D, /* FRMCTR3 partial mode */
    0xB4, 1, 0x07,                         /* INVCTR: column inversion */
    0xC0, 3, 0xA2, 0x02, 0x84,             /* PWCTR1 */
    0xC1, 1, 0xC5,                         /* PWCTR2 */
    0xC2, 2, 0x0A, 0x00,                   /* PWCTR3 */
    0xC3, 2, 0x8A, 0x2A,                   /* PWCTR4 */
    0xC4, 2, 0x8A, 0xEE,                   /* PWCTR5 */
    0xC5, 1, 0x0E,                         /* VMCTR1 */
    0xE0, 16, 0x02, 0x1C, 0x07, 0x12, 0x37, 0x32, 0x29, 0x2D, 0x29, 0x25, 0x2B, 0x39,
    0x00, 0x01, 0x03, 0x10,                /* GMCTRP1 */
    0xE1, 16, 0x03, 0x1D, 0x07, 0x06, 0x2E, 0x2C, 0x29, 0x2D, 0x2E, 0x2E, 0x37, 0x3F,
    0x00, 0x00, 0x02, 0x10,                /* GMCTRN1 */
};

/* GC9A01: inter-register enables, then voltage and gamma registers. */
static const uint8_t gc9a01_init[] = {
    0xFE, 0,                               /* inter register enable 1 */
    0xEF, 0,                               /* inter register enable 2 */
    0xB6, 2, 0x00, 0x00,                   /* display function control */
    0xC3, 1, 0x13,                         /* VREG1A */
    0xC4, 1, 0x13,                         /* VREG1B */
    0xC9, 1, 0x22,                         /* VREG2A */
    0xF0, 6, 0x45, 0x09, 0x08, 0x08, 0x26, 0x2A, /* SET_GAMMA1 */
    0xF1, 6, 0x43, 0x70, 0x72, 0x36, 0x37, 0x6F, /* SET_GAMMA2 */
    0xF2, 6, 0x45, 0x09, 0x08, 0x08, 0x26, 0x2A, /* SET_GAMMA3 */
    0xF3, 6, 0x43, 0x70, 0x72, 0x36, 0x37, 0x6F, /* SET_GAMMA4 */
};

/* ILI9488: gamma, power, VCOM, interface, frame rate, inversion, image. */
static const uint8_t ili9488_init[] = {
    0xE0, 15, 0x00, 0x03, 0x09, 0x08, 0x16, 0x0A, 0x3F, 0x78, 0x4C, 0x09, 0x0A, 0x08,
    0x16, 0x1A, 0x0F,                      /* PGAMCTRL */
    0xE1, 15, 0x00, 0x16, 0x19, 0x03, 0x0F, 0x05, 0x32, 0x45, 0x46, 0x04, 0x0E, 0x0D,
    0x35, 0x37, 0x0F,                      /* NGAMCTRL */
    0xC0, 2, 0x17, 0x15,                   /* power control 1 */
    0xC1, 1, 0x41,                         /* power control 2 */
    0xC5, 3, 0x00, 0x12, 0x80,             /* VCOM control */
    0xB0, 1, 0x00,                         /* interface mode: SDO used */
    0xB1, 1, 0xA0,                         /* frame rate 60 Hz */
    0xB4, 1, 0x02,                         /* display inversion control: 2-dot */
    0xB6, 3, 0x02, 0x02, 0x3B,             /* display function control */
    0xE9, 1, 0x00,                         /* set image function: 24-bit bus off */
    0xF7, 4, 0xA9, 0x51, 0x2C, 0x82,       /* adjust control 3 */
};

/* SSD1351: clock, multiplex, GPIO, regulator, precharge, VCOMH, contrast,
 * segment low voltage, second precharge. Needs the 0xFD 0xB1 unlock that
 * the driver sends first (0xB1, 0xB3, 0xBE, 0xC1 are locked otherwise). */
static const uint8_t ssd1351_init[] = {
    0xB3, 1, 0xF1,                         /* clock divider / oscillator */
    0xCA, 1, 0x7F,                         /* multiplex ratio: 128 rows */
    0xB5, 1, 0x00,                         /* GPIO0/1 off */
    0xAB, 1, 0x01,                         /* function select: internal VDD */
    0xB1, 1, 0x32,                         /* phase 1 and 2 periods */
    0xBE, 1, 0x05,                         /* VCOMH 0.82 x VCC */
    0xC1, 3, 0xC8, 0x80, 0xC8,             /* contrast A, B, C */
    0xC7, 1, 0x0F,                         /* master contrast */
    0xB4, 3, 0xA0, 0xB5, 0x55,             /* VSL external */
    0xB6, 1, 0x01,                         /* second precharge period */
};

/* Designated initializers: every field named, left-out fields are 0. */
#define INIT(a) .init = (a), .init_len = (uint16_t)sizeof(a)

/* 1.3"/1.54" IPS: 240x240 at the top of the 240x320 RAM (80 rows unused:
 * the offset shows up as RASET 80..319 when MY is set). */
const zs_panel_desc zs_panel_st7789_240x240 = {
    .name = "st7789-240x240",
    .ops = &zs_panel_ops_dcs,
    .madctl = 0x00,
    .invert = 1,
    .formats = FMT_565_666,
    .colmod_565 = 0x55,
    .colmod_666 = 0x66,
    .width = 240,
    .height = 240,
    .ram_width = 240,
    .ram_height = 320,
    .max_spi_hz = 62500000u,
    INIT(st7789_init),
};

/* 2.0"/2.4" IPS: the whole 240x320 RAM. */
const zs_panel_desc zs_panel_st7789_240x320 = {
    .name = "st7789-240x320",
    .ops = &zs_panel_ops_dcs,
    .madctl = 0x00,
    .invert = 1,
    .formats = FMT_565_666,
    .colmod_565 = 0x55,
    .colmod_666 = 0x66,
    .width = 240,
    .height = 320,
    .ram_width = 240,
    .ram_height = 320,
    .max_spi_hz = 62500000u,
    INIT(st7789_init),
};

/* 1.14" IPS: 135x240 centred in the 240x320 RAM (columns 52..186, rows 40..279). */
const zs_panel_desc zs_panel_st7789_135x240 = {
    .name = "st7789-135x240",
    .ops = &zs_panel_ops_dcs,
    .madctl = 0x00,
    .invert = 1,
    .formats = FMT_565_666,
    .colmod_565 = 0x55,
    .colmod_666 = 0x66,
    .width = 135,
    .height = 240,
    .ram_width = 240,
    .ram_height = 320,
    .col_offset = 52,
    .row_offset = 40,
    .max_spi_hz = 62500000u,
    INIT(st7789_init),
};

/* 2.2"-2.8" TN modules: BGR glass, source outputs wired mirrored (MX). */
const zs_panel_desc zs_panel_ili9341 = {
    .name = "ili9341",
    .ops = &zs_panel_ops_dcs,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_BGR),
    .invert = 0,
    .formats = FMT_565_666,
    .colmod_565 = 0x55,
    .colmod_666 = 0x66,
    .width = 240,
    .height = 320,
    .ram_width = 240,
    .ram_height = 320,
    .max_spi_hz = 10000000u,
    INIT(ili9341_init),
};

/* 1.8" TN: ST7735S with 132x162 RAM, glass mounted turned 180 degrees
 * (rotation 0 needs MX|MY), visible area at column 2, row 1. */
const zs_panel_desc zs_panel_st7735_128x160 = {
    .name = "st7735-128x160",
    .ops = &zs_panel_ops_dcs,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MY),
    .invert = 0,
    .formats = FMT_565_666,
    .colmod_565 = 0x05,
    .colmod_666 = 0x06,
    .width = 128,
    .height = 160,
    .ram_width = 132,
    .ram_height = 162,
    .col_offset = 2,
    .row_offset = 1,
    .max_spi_hz = 15000000u,
    INIT(st7735_init),
};

/* 1.28" round IPS: BGR glass, needs inversion. */
const zs_panel_desc zs_panel_gc9a01 = {
    .name = "gc9a01",
    .ops = &zs_panel_ops_dcs,
    .madctl = ZS_MADCTL_BGR,
    .invert = 1,
    .formats = FMT_565_666,
    .colmod_565 = 0x05,
    .colmod_666 = 0x06,
    .width = 240,
    .height = 240,
    .ram_width = 240,
    .ram_height = 240,
    .max_spi_hz = 50000000u,
    INIT(gc9a01_init),
};

/* 3.5" TN: BGR glass, mirrored sources; 18 bpp only over SPI. */
const zs_panel_desc zs_panel_ili9488 = {
    .name = "ili9488",
    .ops = &zs_panel_ops_dcs,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_BGR),
    .invert = 0,
    .formats = FMT_BIT(ZS_FMT_RGB666),
    .colmod_565 = 0x00,
    .colmod_666 = 0x66,
    .width = 320,
    .height = 480,
    .ram_width = 320,
    .ram_height = 480,
    .max_spi_hz = 20000000u,
    INIT(ili9488_init),
};

/* 1.5" OLED: COM scan reversed (MY) and colour order C-B-A (BGR) at rotation 0.
 * No COLMOD: the colour depth is part of the remap register. */
const zs_panel_desc zs_panel_ssd1351 = {
    .name = "ssd1351",
    .ops = &zs_panel_ops_ssd1351,
    .madctl = (uint8_t)(ZS_MADCTL_MY | ZS_MADCTL_BGR),
    .invert = 0,
    .formats = FMT_565_666,
    .width = 128,
    .height = 128,
    .ram_width = 128,
    .ram_height = 128,
    .max_spi_hz = 20000000u,
    INIT(ssd1351_init),
};

/* SSD1306 / SH1106 modules: contrast, pre-charge and VCOMH (the driver
 * sends the rest). */
static const uint8_t oled_init[] = {
    ZS_SSD1306_CONTRAST, 0, 0xCF, 0,    /* contrast, then its value */
    ZS_SSD1306_PRECHARGE, 0, 0xF1, 0,   /* pre-charge: phase 1 1, phase 2 15 clocks */
    ZS_SSD1306_VCOMH, 0, 0x40, 0,       /* VCOMH deselect level */
};

#define MONO_PAGE_ONLY ((uint16_t)(1u << ZS_FMT_MONO_PAGE))
#define ROT_0_2 ((uint8_t)0x05u)

/* 0.96" 128x64 modules mount the glass with SEG0 on the right and COM0 at
 * the bottom: upright needs remap and reversed scan (MX|MY) at rotation 0;
 * the 64 COM lines are wired alternately (COM pins 0x12). */
const zs_panel_desc zs_panel_ssd1306_128x64 = {
    .name = "ssd1306-128x64",
    .ops = &zs_panel_ops_ssd1306,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MY),
    .formats = MONO_PAGE_ONLY,
    .width = 128,
    .height = 64,
    .ram_width = 128,
    .ram_height = 64,
    .max_spi_hz = 10000000u,
    .rotations = ROT_0_2,
    .mux = 0x12,
    INIT(oled_init),
};

/* 0.91" 128x32: 32 multiplexed rows wired in sequence (COM pins 0x02). */
const zs_panel_desc zs_panel_ssd1306_128x32 = {
    .name = "ssd1306-128x32",
    .ops = &zs_panel_ops_ssd1306,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MY),
    .formats = MONO_PAGE_ONLY,
    .width = 128,
    .height = 32,
    .ram_width = 128,
    .ram_height = 32,
    .max_spi_hz = 10000000u,
    .rotations = ROT_0_2,
    .mux = 0x02,
    INIT(oled_init),
};

/* 1.3" 128x64 on an SH1106: 132 RAM columns, the glass on SEG2..SEG129. */
const zs_panel_desc zs_panel_sh1106_132x64 = {
    .name = "sh1106-132x64",
    .ops = &zs_panel_ops_sh1106,
    .madctl = (uint8_t)(ZS_MADCTL_MX | ZS_MADCTL_MY),
    .formats = MONO_PAGE_ONLY,
    .width = 128,
    .height = 64,
    .ram_width = 132,
    .ram_height = 64,
    .col_offset = 2,
    .max_spi_hz = 4000000u,
    .rotations = ROT_0_2,
    .mux = 0x12,
    INIT(oled_init),
};

/* SSD1680 2.13" e-paper, 122 x 250 (portrait): sources S8.. (0x21's second
 * byte 0x80), border follows LUT1, internal temperature sensor. */
static const uint8_t ssd1680_init[] = {
    ZS_SSD1680_BORDER, 1, 0x05,
    ZS_SSD1680_UPDATE_CTRL1, 2, 0x00, 0x80,
    ZS_SSD1680_TEMP_SENSOR, 1, 0x80,
};

const zs_panel_desc zs_panel_ssd1680_122x250 = {
    .name = "ssd1680-122x250",
    .ops = &zs_panel_ops_ssd1680,
    .formats = (uint16_t)(1u << ZS_FMT_MONO_MSB),
    .width = 122,
    .height = 250,
    .ram_width = 128,  /* 16 bytes of a RAM row hold the 122 columns */
    .ram_height = 250,
    .max_spi_hz = 20000000u,
    .rotations = 0x01,
    .refresh_ms = 4000u,
    INIT(ssd1680_init),
};

/* SSD0323 + OSRAM Pictiva 128x64 (the Stellaris LM3S6965 board): current
 * range, contrast, phase and row periods, clock, a linear grey-scale table,
 * pre-charge, VCOMH and VSL levels, external VCC; each byte its own record
 * (parameters go with D/C low). The glass shows 64 of the 80 RAM rows. */
static const uint8_t ssd0323_init[] = {
    ZS_SSD0323_MASTER, 0, 0x02, 0,
    ZS_SSD0323_CURRENT_FULL, 0,
    ZS_SSD0323_CONTRAST, 0, 0x33, 0,
    ZS_SSD0323_PHASE, 0, 0x22, 0,
    ZS_SSD0323_ROWPERIOD, 0, 0x46, 0,
    ZS_SSD0323_CLOCK, 0, 0x91, 0,
    ZS_SSD0323_GREYTABLE, 0, 0x01, 0, 0x11, 0, 0x22, 0, 0x32, 0, 0x43, 0, 0x54, 0, 0x65, 0,
    0x76, 0,
    ZS_SSD0323_PRECHARGE, 0, 0x10, 0,
    ZS_SSD0323_VCOMH, 0, 0x02, 0,
    ZS_SSD0323_VSL, 0, 0x0D, 0,
};

const zs_panel_desc zs_panel_ssd0323_128x64 = {
    .name = "ssd0323-128x64",
    .ops = &zs_panel_ops_ssd0323,
    .formats = (uint16_t)(1u << ZS_FMT_GRAY4),
    .width = 128,
    .height = 64,
    .ram_width = 128,
    .ram_height = 80,
    .max_spi_hz = 4000000u,
    .rotations = 0x01,
    INIT(ssd0323_init),
};

/* SSD0303 + OSRAM Pictiva 96x16 (the Stellaris LM3S811 board, I2C): the
 * glass on SEG36..SEG131 and the first 16 COM lines, wired in sequence. */
const zs_panel_desc zs_panel_ssd0303_96x16 = {
    .name = "ssd0303-96x16",
    .ops = &zs_panel_ops_ssd0303,
    .madctl = 0x00,
    .formats = MONO_PAGE_ONLY,
    .width = 96,
    .height = 16,
    .ram_width = 132,
    .ram_height = 16,
    .col_offset = 36,
    .max_spi_hz = 400000u, /* I2C fast mode */
    .rotations = ROT_0_2,
    .mux = 0x02,
    INIT(oled_init),
};

static const zs_panel_desc *const all_panels[] = {
    &zs_panel_st7789_240x240, &zs_panel_st7789_240x320, &zs_panel_st7789_135x240,
    &zs_panel_ili9341,        &zs_panel_st7735_128x160, &zs_panel_gc9a01,
    &zs_panel_ili9488,        &zs_panel_ssd1351,        &zs_panel_ssd1306_128x64,
    &zs_panel_ssd1306_128x32, &zs_panel_sh1106_132x64,  &zs_panel_ssd1680_122x250,
    &zs_panel_ssd0323_128x64, &zs_panel_ssd0303_96x16,
};

unsigned zs_panel_count(void)
{
    return (unsigned)(sizeof all_panels / sizeof all_panels[0]);
}

const zs_panel_desc *zs_panel_at(unsigned i)
{
    return i < zs_panel_count() ? all_panels[i] : NULL;
}

const zs_panel_desc *zs_panel_find(const char *name)
{
    unsigned i;
    if (name == NULL)
        return NULL;
    for (i = 0; i < zs_panel_count(); i++)
        if (strcmp(all_panels[i]->name, name) == 0)
            return all_panels[i];
    return NULL;
}
