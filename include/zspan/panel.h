/* SPDX-License-Identifier: MIT */
/*
 * zspan panel drivers: common code (geometry, rotation, windows, pixel
 * writes) over one operations table per controller command set (MIPI DCS,
 * SSD1351), a constant data table per module, and a frame streamer that
 * renders the next band while the previous one is on the bus.
 *
 * Freestanding C99, no allocation, no floating point.
 *
 * Coordinates and windows
 *  - Panel coordinates are the visible area at the current rotation: x right,
 *    y down, (0, 0) the top-left pixel the viewer sees, width x height pixels.
 *  - Every window in this API is HALF-OPEN: [x0, x1) x [y0, y1), like the rest
 *    of zspan. The driver converts to the controllers' INCLUSIVE wire form
 *    (CASET/RASET and SSD1351 0x15/0x75 carry start and end, both inclusive)
 *    and adds the RAM offset of the module at the current rotation.
 *
 * Rotation r (0..3) turns the picture r * 90 degrees clockwise on the glass:
 * with rotation 1 a viewer who turns the module 90 degrees counter-clockwise
 * sees it upright. The driver derives MADCTL from the table's rotation-0 value
 * (rotation 1 toggles MX|MV, 2 toggles MX|MY, 3 toggles MY|MV) and the RAM
 * offsets from the physical position of the visible area in the controller's
 * RAM, so one table entry covers all four rotations.
 *
 * Pixel formats: ZS_FMT_RGB565_BE (COLMOD 16 bpp, 2 bytes big-endian) and
 * ZS_FMT_RGB666 (COLMOD 18 bpp, 3 bytes R, G, B in bits 7..2), as each panel's
 * `formats` mask allows (ILI9488 over SPI: RGB666 only). The format is the
 * panel's (zs_panel.format): set by zs_panel_init, kept between frames,
 * changed by zs_panel_set_format. Each frame's renderer format must match it
 * (see zs_panel_stream).
 *
 * Typical use:
 *
 *     zs_bus bus;  zs_bus_init(&bus, &my_ops, &my_port, ZS_BUS_ASYNC, 0);
 *     zs_panel lcd;
 *     zs_panel_init(&lcd, zs_panel_find("st7789-240x240"), &bus,
 *                   ZS_FMT_RGB565_BE, 0);
 *     ... zs_frame_begin / zs_frame_shading (format = lcd.format) / zs_draw ...
 *     static uint8_t b0[240 * 2], b1[240 * 2];
 *     zs_panel_frame_stats st;
 *     zs_wire_model wm = zs_wire_model_default(62500000);
 *     zs_panel_stream(&lcd, &renderer, b0, b1, sizeof b0, 1, &wm, &st);
 */
#ifndef ZSPAN_PANEL_H
#define ZSPAN_PANEL_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"
#include "zspan/zspan.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Command bytes                                                        */
/* ------------------------------------------------------------------ */

/* MIPI DCS (ST7789, ILI9341, ST7735, GC9A01, ILI9488). */
#define ZS_DCS_NOP 0x00u
#define ZS_DCS_SWRESET 0x01u
#define ZS_DCS_SLPIN 0x10u
#define ZS_DCS_SLPOUT 0x11u
#define ZS_DCS_NORON 0x13u
#define ZS_DCS_INVOFF 0x20u
#define ZS_DCS_INVON 0x21u
#define ZS_DCS_DISPOFF 0x28u
#define ZS_DCS_DISPON 0x29u
#define ZS_DCS_CASET 0x2Au    /* 4 params: xs hi, xs lo, xe hi, xe lo (inclusive) */
#define ZS_DCS_RASET 0x2Bu    /* 4 params: ys hi, ys lo, ye hi, ye lo (inclusive) */
#define ZS_DCS_RAMWR 0x2Cu
#define ZS_DCS_MADCTL 0x36u   /* 1 param */
#define ZS_DCS_COLMOD 0x3Au   /* 1 param */
#define ZS_DCS_RAMWRC 0x3Cu

#define ZS_MADCTL_MY 0x80u    /* row address order */
#define ZS_MADCTL_MX 0x40u    /* column address order */
#define ZS_MADCTL_MV 0x20u    /* row/column exchange */
#define ZS_MADCTL_ML 0x10u    /* vertical refresh order */
#define ZS_MADCTL_BGR 0x08u   /* RGB/BGR order */

/* SSD1351 (128x128 colour OLED). */
#define ZS_SSD1351_SETCOLUMN 0x15u   /* 2 params: start, end (inclusive) */
#define ZS_SSD1351_SETROW 0x75u      /* 2 params: start, end (inclusive) */
#define ZS_SSD1351_WRITERAM 0x5Cu
#define ZS_SSD1351_REMAP 0xA0u       /* 1 param: remap and colour depth */
#define ZS_SSD1351_STARTLINE 0xA1u
#define ZS_SSD1351_DISPLAYOFFSET 0xA2u
#define ZS_SSD1351_NORMAL 0xA6u
#define ZS_SSD1351_INVERSE 0xA7u
#define ZS_SSD1351_SLEEP_ON 0xAEu    /* display off */
#define ZS_SSD1351_SLEEP_OFF 0xAFu   /* display on */
#define ZS_SSD1351_COMMANDLOCK 0xFDu /* 1 param: 0x12 unlock, 0x16 lock, 0xB1/0xB0 */

/* SSD1351 remap (0xA0) parameter bits. */
#define ZS_SSD1351_RM_VINC 0x01u      /* vertical address increment */
#define ZS_SSD1351_RM_COLREMAP 0x02u  /* column address 0 -> SEG127 */
#define ZS_SSD1351_RM_CBA 0x04u       /* colour sequence C, B, A */
#define ZS_SSD1351_RM_COMREMAP 0x10u  /* scan COM127 -> COM0 */
#define ZS_SSD1351_RM_COMSPLIT 0x20u  /* odd/even COM split */
#define ZS_SSD1351_RM_65K 0x40u       /* bits 7:6 = 01: 65k colours (2 bytes) */
#define ZS_SSD1351_RM_262K 0x80u      /* bits 7:6 = 10: 262k colours (3 bytes, bits 5..0) */

/* SSD1306 / SH1106 (monochrome OLED, 1-bit pages). Over 4-wire SPI every
 * byte of a command, parameters included, goes with D/C low, so the driver
 * sends each one as a parameterless bus command; over I2C a port frames a
 * command as control byte 0x00 + bytes and pixel data as 0x40 + bytes. */
#define ZS_SSD1306_MEMMODE 0x20u      /* 1 param: 0 horizontal, 1 vertical, 2 page */
#define ZS_SSD1306_COLADDR 0x21u      /* 2 params: start, end column (inclusive) */
#define ZS_SSD1306_PAGEADDR 0x22u     /* 2 params: start, end page (inclusive) */
#define ZS_SSD1306_STARTLINE 0x40u    /* | line 0..63 */
#define ZS_SSD1306_CONTRAST 0x81u     /* 1 param */
#define ZS_SSD1306_CHARGEPUMP 0x8Du   /* 1 param: 0x14 on, 0x10 off */
#define ZS_SSD1306_SEGREMAP 0xA0u     /* | 1: column 127 (SH1106: 131) -> SEG0 */
#define ZS_SSD1306_RESUME 0xA4u       /* show the RAM (0xA5: every pixel on) */
#define ZS_SSD1306_NORMAL 0xA6u
#define ZS_SSD1306_INVERSE 0xA7u
#define ZS_SSD1306_MUX 0xA8u          /* 1 param: rows - 1 */
#define ZS_SSD1306_DISPOFF 0xAEu
#define ZS_SSD1306_DISPON 0xAFu
#define ZS_SSD1306_PAGE 0xB0u         /* | page 0..7: page mode start page */
#define ZS_SSD1306_COMSCAN 0xC0u      /* | 8: scan COM[N-1] -> COM0 */
#define ZS_SSD1306_OFFSET 0xD3u       /* 1 param */
#define ZS_SSD1306_CLOCK 0xD5u        /* 1 param */
#define ZS_SSD1306_PRECHARGE 0xD9u    /* 1 param */
#define ZS_SSD1306_COMPINS 0xDAu      /* 1 param: 0x02 sequential, 0x12 alternative */
#define ZS_SSD1306_VCOMH 0xDBu        /* 1 param */
#define ZS_SH1106_DCDC 0xADu          /* 1 param: 0x8B on */
#define ZS_SSD1306_I2C_ADDR 0x3Cu     /* 7-bit address with SA0 low (0x3D high) */

/* SSD0323 (128x80 RAM of 4-bit grey, ZS_FMT_GRAY4; issue 20). Over 4-wire SPI
 * parameters go with D/C low like their command; RAM data with D/C high. */
#define ZS_SSD0323_SETCOLUMN 0x15u    /* 2 params: start, end column pair (0..63) */
#define ZS_SSD0323_SETROW 0x75u       /* 2 params: start, end row (0..79) */
#define ZS_SSD0323_CONTRAST 0x81u     /* 1 param */
#define ZS_SSD0323_CURRENT_FULL 0x86u /* full current range (0x84 quarter, 0x85 half) */
#define ZS_SSD0323_REMAP 0xA0u        /* 1 param: ZS_SSD0323_RM_* */
#define ZS_SSD0323_STARTLINE 0xA1u    /* 1 param: RAM row shown first */
#define ZS_SSD0323_OFFSET 0xA2u       /* 1 param: vertical offset of the COM lines */
#define ZS_SSD0323_NORMAL 0xA4u       /* the RAM as it is (0xA5 all on, 0xA6 all off) */
#define ZS_SSD0323_INVERSE 0xA7u
#define ZS_SSD0323_MUX 0xA8u          /* 1 param: rows - 1 (15..79) */
#define ZS_SSD0323_MASTER 0xADu       /* 1 param: 0x02 external VCC */
#define ZS_SSD0323_DISPOFF 0xAEu
#define ZS_SSD0323_DISPON 0xAFu
#define ZS_SSD0323_PHASE 0xB1u        /* 1 param: phase 1 and 2 lengths */
#define ZS_SSD0323_ROWPERIOD 0xB2u    /* 1 param */
#define ZS_SSD0323_CLOCK 0xB3u        /* 1 param: divider and oscillator */
#define ZS_SSD0323_GREYTABLE 0xB8u    /* 8 params: the grey-scale pulse widths */
#define ZS_SSD0323_PRECHARGE 0xBCu    /* 1 param */
#define ZS_SSD0323_VCOMH 0xBEu        /* 1 param */
#define ZS_SSD0323_VSL 0xBFu          /* 1 param */
#define ZS_SSD0323_RM_COLUMN 0x01u    /* column address 0 -> SEG127 */
#define ZS_SSD0323_RM_NIBBLE 0x02u    /* nibble re-map: the high nibble is the left pixel */
#define ZS_SSD0323_RM_VERTICAL 0x04u  /* vertical address increment */
#define ZS_SSD0323_RM_COM 0x10u       /* scan COM79 -> COM0 */
#define ZS_SSD0323_RM_COMSPLIT 0x40u  /* odd/even COM split */

/* SSD0303 (132x64 RAM, 1-bit pages, page addressing only): the SH1106's
 * command set plus 0xD8; its 96x16 glass on the Stellaris LM3S811 board. */
#define ZS_SSD0303_COLOR_MODE 0xD8u   /* 1 param: 0x00 monochrome, normal power */
#define ZS_SSD0303_I2C_ADDR 0x3Du     /* 7-bit address with SA0 high (0x3C low) */

/* SSD1680 (e-paper, 1-bit RAM, row-major MSB first, bit 1 = white). */
#define ZS_SSD1680_DRIVER_OUTPUT 0x01u /* 3 params: gates - 1 (low, high), scan */
#define ZS_SSD1680_DEEP_SLEEP 0x10u    /* 1 param */
#define ZS_SSD1680_DATA_ENTRY 0x11u    /* 1 param: bit 0 X+, bit 1 Y+, bit 2 Y first */
#define ZS_SSD1680_SWRESET 0x12u
#define ZS_SSD1680_TEMP_SENSOR 0x18u   /* 1 param: 0x80 internal */
#define ZS_SSD1680_ACTIVATE 0x20u      /* run the update sequence of 0x22 (BUSY) */
#define ZS_SSD1680_UPDATE_CTRL1 0x21u  /* 2 params: RAM options */
#define ZS_SSD1680_UPDATE_CTRL2 0x22u  /* 1 param: the update sequence */
#define ZS_SSD1680_WRITE_BW 0x24u      /* write the black/white RAM */
#define ZS_SSD1680_WRITE_RED 0x26u     /* write the second RAM (mode 2: the old image) */
#define ZS_SSD1680_BORDER 0x3Cu        /* 1 param */
#define ZS_SSD1680_RAM_X 0x44u         /* 2 params: start, end byte (inclusive) */
#define ZS_SSD1680_RAM_Y 0x45u         /* 4 params: start, end gate (16-bit LE, inclusive) */
#define ZS_SSD1680_RAM_X_COUNT 0x4Eu   /* 1 param */
#define ZS_SSD1680_RAM_Y_COUNT 0x4Fu   /* 2 params */
#define ZS_SSD1680_SEQ_FULL 0xF7u      /* clock, analog, temperature, LUT mode 1, display, off */
#define ZS_SSD1680_SEQ_PARTIAL 0xFFu   /* the same with LUT mode 2 (only changed pixels) */

/* ------------------------------------------------------------------ */
/* Results                                                              */
/* ------------------------------------------------------------------ */

/* zs_panel_strerror() gives each code's comment below as text. */
typedef enum zs_panel_status {
    ZS_PANEL_OK = 0,
    ZS_PANEL_ERR_NULL,         /* NULL panel, description, bus, renderer or buffer */
    ZS_PANEL_ERR_IO,           /* the bus reported a failure */
    ZS_PANEL_ERR_FORMAT,       /* pixel format not supported by this panel */
    ZS_PANEL_ERR_ROTATION,     /* rotation not 0..3, or one the controller cannot do */
    ZS_PANEL_ERR_WINDOW,       /* empty window or outside the visible area */
    ZS_PANEL_ERR_STATE,        /* panel not initialised, or pixels without an open
                                  window or past its end */
    ZS_PANEL_ERR_DESC,         /* inconsistent panel description */
    ZS_PANEL_ERR_BUFFER,       /* buffer smaller than one row, band of no rows, or
                                  not whole pixels */
    ZS_PANEL_ERR_RENDER,       /* zs_render_rows failed (see render_status) */
    ZS_PANEL_ERR_TIMEOUT,      /* the bus gave up waiting for a pixel transfer (wait limit) */
    ZS_PANEL_ERR_SIZE,         /* renderer size differs from the panel size at its rotation */
    ZS_PANEL_ERR_FRAME_FORMAT, /* the frame's pixel format is not the panel's */
    ZS_PANEL_STATUS_COUNT      /* number of codes, not a status */
} zs_panel_status;

/* Text of a status: "ok", each code's comment above, or "unknown panel
 * status" for a value outside the enum. Never NULL. */
const char *zs_panel_strerror(zs_panel_status s);

/* ------------------------------------------------------------------ */
/* Controller command sets (operations tables)                          */
/* ------------------------------------------------------------------ */

struct zs_panel;
struct zs_panel_desc;

/* Turns n bytes in zspan's pixel format into the controller's wire form
 * (as many bytes); dst may equal src. */
typedef void (*zs_panel_encode_fn)(uint8_t *dst, const uint8_t *src, size_t n);

/* What one controller family sends for each step. The common code
 * (geometry, rotation, window bounds, write accounting, frame streaming)
 * only calls these, so another family (another Solomon OLED, an e-paper
 * controller) is one more table plus a description per module. Each
 * function gets a panel whose desc, bus, format, rotation, madctl and
 * geometry are set, and returns ZS_PANEL_OK or the first failure. Required
 * unless marked optional. */
typedef struct zs_panel_ops {
    const char *name;   /* the command set, e.g. "MIPI DCS" */
    /* Optional. Whether the description can drive `format` (DCS: it has a
     * COLMOD value for it): ZS_PANEL_OK or ZS_PANEL_ERR_DESC. Runs before
     * anything is sent. */
    zs_panel_status (*check)(const struct zs_panel_desc *desc, zs_format format);
    /* Power-up: hardware and software reset, wake-up, the description's
     * init records, pixel format, orientation, inversion, display on, with
     * the datasheet delays. */
    zs_panel_status (*init)(struct zs_panel *p);
    /* Sends the pixel format p->format. */
    zs_panel_status (*format)(struct zs_panel *p);
    /* Sends the orientation p->madctl (MADCTL bits; other command sets map
     * them to their own registers). */
    zs_panel_status (*orient)(struct zs_panel *p);
    /* Sends the inversion: on when desc->invert and p->inverted differ. */
    zs_panel_status (*invert)(struct zs_panel *p);
    /* Display on or off. */
    zs_panel_status (*display)(struct zs_panel *p, int on);
    /* Sets the RAM window (inclusive wire coordinates, RAM offsets added)
     * and starts a memory write. */
    zs_panel_status (*window)(struct zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                              uint16_t ye);
    /* Optional. Runs before each pixel write of n bytes into the open window
     * (p->window_bytes does not count them yet): may refuse the size or send
     * a command (DCS: RAMWRC when p->use_ramwrc). */
    zs_panel_status (*write_begin)(struct zs_panel *p, size_t n);
    /* Optional. The conversion the wire needs for p->format, or NULL when
     * the controller takes zspan's bytes as they are (then every write is
     * zero-copy). */
    zs_panel_encode_fn (*encoder)(const struct zs_panel *p);
    /* Optional. Runs after the last band of zs_panel_stream (e-paper: the
     * refresh, and the wait for it). */
    zs_panel_status (*frame_end)(struct zs_panel *p);
} zs_panel_ops;

/* MIPI DCS (ST7789, ILI9341, ST7735, GC9A01, ILI9488): everything
 * module-specific comes from the description. */
extern const zs_panel_ops zs_panel_ops_dcs;
/* Solomon SSD1351: remap register for orientation and colour depth; at
 * 18 bpp the wire takes each channel in bits 5..0 (an encoder). */
extern const zs_panel_ops zs_panel_ops_ssd1351;
/* Solomon SSD1306 (horizontal addressing: one window, the bytes flow page
 * after page) and Sino Wealth SH1106 (page addressing only: the driver sets
 * page and column before each page, so writes must not cross a page end).
 * Format ZS_FMT_MONO_PAGE; MX -> segment remap, MY -> COM scan direction,
 * so rotations 0 and 2 (a byte is 8 pixels of a column: no exchange). */
extern const zs_panel_ops zs_panel_ops_ssd1306;
extern const zs_panel_ops zs_panel_ops_sh1106;
/* Solomon SSD0303 (issue 20): the SH1106's page addressing (the page and
 * column before each page of the window), the DC-DC converter and 0xD8's
 * monochrome mode; over I2C a port frames each command byte as 0x80 + byte
 * (Co = 1) and pixel data as 0x40 + bytes. Rotations 0 and 2. */
extern const zs_panel_ops zs_panel_ops_ssd0303;
/* Solomon SSD0323 (issue 20): ZS_FMT_GRAY4 in horizontal addressing, one
 * window whose columns are pairs of pixels (x0 even, x1 even or the width).
 * Rotation 0 only. */
extern const zs_panel_ops zs_panel_ops_ssd0323;
/* Solomon SSD1680 e-paper: ZS_FMT_MONO_MSB into the black/white RAM, then a
 * full refresh (or a partial one: see zs_panel.partial) with the BUSY wait
 * as a delay. Rotation 0 only. */
extern const zs_panel_ops zs_panel_ops_ssd1680;

/* ------------------------------------------------------------------ */
/* Panel descriptions (constant tables)                                 */
/* ------------------------------------------------------------------ */

/* Module-specific init commands, run after SLPOUT (DCS) or after the unlock
 * (SSD1351): records of
 *     cmd, n, param[0] .. param[n-1] [, delay]
 * where n's bit 7 (ZS_INIT_DELAY) says a delay byte (milliseconds) follows
 * the parameters; n & 0x7F is the parameter count. */
#define ZS_INIT_DELAY 0x80u

/* One module. The built-in tables use designated initializers; a field left
 * out is 0 (no offset, no inversion, no init records). */
typedef struct zs_panel_desc {
    const char *name;            /* e.g. "st7789-240x240" */
    const zs_panel_ops *ops;     /* the controller's command set */
    uint8_t madctl;              /* MADCTL at rotation 0 (mirror and BGR bits of
                                    this module); SSD1351: the same bits, mapped
                                    to its remap register by the driver */
    uint8_t invert;              /* 1: the glass needs INVON (IPS) for normal colours */
    uint16_t formats;            /* bit (1u << zs_format) per supported format */
    uint8_t colmod_565;          /* DCS: COLMOD for 16 bpp (0 = unsupported) */
    uint8_t colmod_666;          /* DCS: COLMOD for 18 bpp (0 = unsupported) */
    uint16_t width, height;      /* visible pixels at rotation 0 */
    uint16_t ram_width, ram_height;   /* controller RAM, columns x rows */
    uint16_t col_offset, row_offset;  /* first visible RAM column / row, counted
                                         in physical RAM (no mirroring) */
    uint32_t max_spi_hz;         /* rated write clock */
    const uint8_t *init;         /* module init records (see ZS_INIT_DELAY) */
    uint16_t init_len;           /* bytes in init */
    uint8_t rotations;           /* bit r per rotation the controller can do; 0 = all */
    uint8_t mux;                 /* SSD1306/SH1106: COM pins config (0x02, 0x12) */
    uint32_t refresh_ms;         /* e-paper: the longest full refresh (BUSY wait) */
} zs_panel_desc;

/* Built-in tables. */
extern const zs_panel_desc zs_panel_st7789_240x240;
extern const zs_panel_desc zs_panel_st7789_240x320;
extern const zs_panel_desc zs_panel_st7789_135x240;
extern const zs_panel_desc zs_panel_ili9341;        /* 240x320, 320x240 at rotation 1/3 */
extern const zs_panel_desc zs_panel_st7735_128x160;
extern const zs_panel_desc zs_panel_gc9a01;         /* 240x240 round */
extern const zs_panel_desc zs_panel_ili9488;        /* 320x480, 480x320 at rotation 1/3 */
extern const zs_panel_desc zs_panel_ssd1351;        /* 128x128 OLED */
extern const zs_panel_desc zs_panel_ssd1306_128x64; /* 0.96" OLED, I2C or SPI */
extern const zs_panel_desc zs_panel_ssd1306_128x32; /* 0.91" OLED */
extern const zs_panel_desc zs_panel_sh1106_132x64;  /* 1.3" OLED, 132-column RAM */
extern const zs_panel_desc zs_panel_ssd1680_122x250; /* 2.13" e-paper */
extern const zs_panel_desc zs_panel_ssd0323_128x64;  /* OSRAM Pictiva 128x64, 16 greys */
extern const zs_panel_desc zs_panel_ssd0303_96x16;   /* OSRAM Pictiva 96x16, 1 bit, I2C */

/* Number of built-in tables, the i-th one (NULL past the end), and lookup by
 * name (exact, NULL if unknown). */
unsigned zs_panel_count(void);
const zs_panel_desc *zs_panel_at(unsigned i);
const zs_panel_desc *zs_panel_find(const char *name);

/* ------------------------------------------------------------------ */
/* The driver                                                           */
/* ------------------------------------------------------------------ */

/* Size of each of the two buffers zs_panel_write converts const data in
 * when the wire needs other bytes than zspan's (SSD1351 at 18 bpp). */
#define ZS_PANEL_SCRATCH_BYTES 64u

/* Driver state. Read the fields; change them only through the functions. */
typedef struct zs_panel {
    const zs_panel_desc *desc;
    zs_bus *bus;
    zs_format format;          /* the panel's pixel format: kept until changed
                                  (zs_panel_init, zs_panel_set_format) */
    uint8_t rotation;          /* 0..3 */
    uint8_t madctl;            /* last MADCTL (or abstract SSD1351 orientation) sent */
    uint8_t inverted;          /* user inversion on top of the module's need */
    uint8_t ready;             /* init done */
    uint8_t use_ramwrc;        /* DCS: send RAMWRC before each later write (default 0) */
    uint8_t scratch_next;      /* the scratch buffer zs_panel_write fills next */
    uint8_t partial;           /* e-paper: the next refresh is partial (set it to 1
                                  once the glass shows what the second RAM holds,
                                  see zs_panel_ops_ssd1680) */
    uint8_t write_base;        /* e-paper: windows write the second RAM (the base a
                                  partial refresh compares with); no refresh */
    uint8_t mono_page;         /* SH1106: first page of the open window */
    uint16_t mono_col, mono_cols; /* SH1106: its first RAM column and width */
    uint16_t width, height;    /* visible size at this rotation */
    uint16_t x_offset, y_offset;  /* RAM address of visible (0, 0) at this rotation */
    uint32_t window_bytes;     /* bytes left in the current window (0 = none open) */
    uint32_t window_total;     /* bytes of the window opened last */
    /* zs_panel_write's conversion buffers: one fills while the other may
     * still be on the bus. */
    uint8_t scratch[2][ZS_PANEL_SCRATCH_BYTES];
} zs_panel;

/* Hardware reset (if the bus has a reset hook), software reset, sleep out,
 * module init records, pixel format, orientation, inversion, normal mode and
 * display on, with the datasheet delays through the bus's delay hook.
 * rotation 0..3. The backlight is not touched (see zs_panel_backlight). */
zs_panel_status zs_panel_init(zs_panel *p, const zs_panel_desc *desc, zs_bus *bus,
                              zs_format format, unsigned rotation);

/* Bytes per pixel on the wire for a format (2 or 3; 0 if the panel does not
 * support it, and for the 1-bit formats). */
unsigned zs_panel_bytes_per_pixel(const zs_panel_desc *desc, zs_format format);
/* Does the panel take `format` (any kind)? */
int zs_panel_supports(const zs_panel_desc *desc, zs_format format);
/* Bytes a w x h window takes in `format`: w * h * bytes per pixel, w per
 * page of 8 rows (ZS_FMT_MONO_PAGE), (w + 7) / 8 per row (ZS_FMT_MONO_MSB),
 * (w + 1) / 2 per row (ZS_FMT_GRAY4). */
uint32_t zs_panel_window_bytes(zs_format format, unsigned w, unsigned h);

/* MADCTL (DCS) for a rotation, with the module's mirror and BGR bits. */
uint8_t zs_panel_madctl_for(const zs_panel_desc *desc, unsigned rotation);
/* Visible size and RAM address offsets for a rotation (any pointer may be NULL). */
zs_panel_status zs_panel_geometry(const zs_panel_desc *desc, unsigned rotation, uint16_t *width,
                                  uint16_t *height, uint16_t *x_offset, uint16_t *y_offset);

zs_panel_status zs_panel_set_rotation(zs_panel *p, unsigned rotation);
/* Changes the panel's pixel format (DCS: COLMOD; SSD1351: the remap
 * register's colour depth). It stays until changed again. A format the
 * panel does not support is refused (ZS_PANEL_ERR_FORMAT, or
 * ZS_PANEL_ERR_DESC if its table lacks the value) with nothing sent. Closes
 * the open window. */
zs_panel_status zs_panel_set_format(zs_panel *p, zs_format format);
/* Inverts the displayed colours (on top of what the glass needs). */
zs_panel_status zs_panel_set_inversion(zs_panel *p, int on);
zs_panel_status zs_panel_display_on(zs_panel *p, int on);
zs_panel_status zs_panel_backlight(zs_panel *p, uint8_t level);

/* Opens the half-open window [x0, x1) x [y0, y1) (panel coordinates) and
 * starts a memory write (DCS: CASET, RASET, RAMWR; SSD1351: 0x15, 0x75, 0x5C).
 * Pixels then go row by row, left to right, top to bottom (ZS_FMT_MONO_PAGE:
 * page by page, y0 and y1 multiples of 8 or y1 the height; ZS_FMT_MONO_MSB:
 * x0 and x1 multiples of 8 or x1 the width; ZS_FMT_GRAY4: x0 and x1 even or
 * x1 the width; else ZS_PANEL_ERR_WINDOW). */
zs_panel_status zs_panel_window(zs_panel *p, uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1);

/* Sends n pixel bytes (p->format) of the open window (any chunking, not
 * necessarily whole pixels or rows). `data` is only read, so it may be in
 * flash. When the wire takes zspan's bytes as they are (every DCS panel,
 * SSD1351 at 16 bpp) data goes to the bus as it is: with an async bus it
 * belongs to the bus until zs_bus_idle(). When the wire needs other bytes
 * (SSD1351 at 18 bpp) they are converted into the panel's two small scratch
 * buffers and sent in ZS_PANEL_SCRATCH_BYTES pieces; data is then free again
 * on return. */
zs_panel_status zs_panel_write(zs_panel *p, const uint8_t *data, size_t n);

/* The zero-copy variant for writable buffers (zs_panel_stream uses it): where
 * the wire needs other bytes the driver converts `data` IN PLACE (its bytes
 * are then the wire's, not zspan's) and sends it in one go. With an async bus
 * data belongs to the bus until zs_bus_idle(), in every case. */
zs_panel_status zs_panel_write_inplace(zs_panel *p, uint8_t *data, size_t n);

/* ------------------------------------------------------------------ */
/* Frame streaming                                                      */
/* ------------------------------------------------------------------ */

typedef struct zs_panel_frame_stats {
    zs_bus_counters bus;       /* traffic of this frame (commands, bytes, ...) */
    uint32_t bytes;            /* all bytes on the wire this frame */
    uint32_t bands;            /* bands rendered and sent */
    uint32_t wire_waits;       /* bands that found the bus still busy: the
                                  wire, not the renderer, limited the rate */
    uint64_t wire_ns;          /* the wire's time for this frame (model) */
    zs_status render_status;   /* last zs_render_rows result */
} zs_panel_frame_stats;

/* Streams the current frame of r (after zs_frame_begin / zs_frame_shading /
 * zs_draw) to the whole panel: one window, then band after band.
 *
 * The contract is checked before anything is sent: the renderer's size
 * must be the panel's at its rotation (p->width x p->height, else
 * ZS_PANEL_ERR_SIZE) and the frame's pixel format p->format (else
 * ZS_PANEL_ERR_FRAME_FORMAT). The panel's format lasts between frames; the
 * frame's does not: zs_frame_begin resets the shading, format included, to
 * zs_shade_default() (RGB565 big-endian), because the core takes all of a
 * frame's look in one zs_frame_shading call. So pass p->format in every
 * frame's zs_shade_params; a frame that forgot is refused here instead of
 * reaching the glass as garbage.
 *
 * Band k renders into buf[k % 2] while band k-1 may still be on the bus; a
 * buffer is never rendered into while the bus owns it. buf1 may be NULL (one
 * buffer: the renderer then waits for the wire each band). buf_bytes is the
 * size of each buffer; band_rows (>= 1) is capped to what fits. The bands
 * are sent with zs_panel_write_inplace (the buffers' bytes may be converted).
 * wire may be NULL (no wire time). Returns when the last byte has been
 * handed to the bus and the bus is idle. After ZS_PANEL_ERR_TIMEOUT the bus
 * still owns the buffer of the lost transfer (see zs_bus_set_wait_limit). */
zs_panel_status zs_panel_stream(zs_panel *p, zs_renderer *r, uint8_t *buf0, uint8_t *buf1,
                                size_t buf_bytes, int band_rows, const zs_wire_model *wire,
                                zs_panel_frame_stats *stats);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_PANEL_H */
