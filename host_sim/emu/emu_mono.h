/* SPDX-License-Identifier: MIT */
/*
 * Emulated monochrome controllers: SSD1306, SH1106 and SSD0303 OLEDs (1-bit pages),
 * SSD1680 e-paper (1-bit rows, two RAMs, refresh sequences). Fed with the
 * real byte stream: D/C-low and D/C-high bytes of 4-wire SPI, or I2C write
 * transactions (address, control bytes Co/D#C). They keep their own RAM,
 * follow the addressing modes, windows, remaps and scan directions like the
 * silicon, show the glass as a 1-bit picture, and flag protocol errors that
 * real hardware would silently turn into a wrong picture.
 *
 * Host C99 (uses malloc). The module facts are written down here, apart
 * from the zspan tables, so a wrong table shows up as a wrong picture.
 */
#ifndef ZSPAN_EMU_MONO_H
#define ZSPAN_EMU_MONO_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

enum { EMU_MONO_SSD1306 = 0, EMU_MONO_SH1106 = 1, EMU_MONO_SSD1680 = 2, EMU_MONO_SSD0303 = 3 };

/* Protocol error flags (emu_mono.errors). */
enum {
    EMU_M_COMMAND = 1u << 0,   /* a byte that is no command of this controller */
    EMU_M_WINDOW = 1u << 1,    /* window start > end, outside the RAM, or data past it */
    EMU_M_STRAY = 1u << 2,     /* data (D/C high) that no command takes */
    EMU_M_BUSY = 1u << 3,      /* a byte while BUSY is high or the reset line low */
    EMU_M_I2C = 1u << 4,       /* malformed I2C transaction (control byte) */
    EMU_M_POWER = 1u << 5,     /* display on without the charge pump / DC-DC, or mux wrong */
    EMU_M_BASE = 1u << 6,      /* partial refresh whose base RAM is not what the glass shows */
    EMU_M_PARAM = 1u << 7      /* a parameter value the module cannot take */
};
#define EMU_M_COUNT 8

typedef struct emu_mono_model {
    const char *name;          /* matches the zspan table */
    int family;
    uint16_t ram_w, ram_h;     /* RAM: columns (SEG, sources) x rows (COM, gates) */
    uint16_t vis_w, vis_h;     /* glass */
    uint16_t vis_col;          /* first RAM column (SEG) wired to the glass */
    uint8_t mirror_x;          /* glass x runs against the SEG/source order */
    uint8_t mirror_y;          /* glass y runs against the COM/gate order */
    uint8_t com_alt;           /* COM pins wired for the alternative configuration */
    uint32_t refresh_ms;       /* e-paper: BUSY time of a refresh */
} emu_mono_model;

const emu_mono_model *emu_mono_model_find(const char *name);
unsigned emu_mono_model_count(void);
const emu_mono_model *emu_mono_model_at(unsigned i);

typedef struct emu_mono {
    const emu_mono_model *m;
    uint8_t *ram;              /* ram_w * ram_h, 0/1 per pixel (SSD1680: black/white RAM) */
    uint8_t *ram2;             /* SSD1680: the second RAM (0x26) */
    uint8_t *glass;            /* SSD1680: what the e-paper shows (vis_w * vis_h) */
    uint8_t i2c_addr;          /* 7-bit address it answers */
    /* OLED state */
    uint8_t display_on, inverse, all_on, pump, seg_remap, com_remap;
    uint8_t mux, offset, start_line, compins, mode; /* mode 0 horizontal, 1 vertical, 2 page */
    uint16_t col, page, col_lo, col_hi, page_lo, page_hi;
    /* SSD1680 state */
    uint8_t entry, target, seq, gates_ok;
    uint16_t x_lo, x_hi, y_lo, y_hi, xc, yc;
    /* the command being parsed */
    int cmd, need, have;
    uint8_t params[8];
    int writing;               /* data goes to RAM */
    uint8_t reset_low;
    uint64_t now_us, busy_until_us;
    /* results */
    uint32_t errors, error_count;
    char first_error[160];
    uint64_t bytes, data_bytes;
    uint32_t commands, refreshes, partial_refreshes, i2c_frames, nacks;
} emu_mono;

int emu_mono_init(emu_mono *e, const emu_mono_model *m);
void emu_mono_free(emu_mono *e);

/* 4-wire SPI and the control lines. */
void emu_mono_reset_line(emu_mono *e, int level); /* 0 = asserted */
void emu_mono_command(emu_mono *e, uint8_t b);    /* D/C low */
void emu_mono_data(emu_mono *e, const uint8_t *d, size_t n); /* D/C high */
void emu_mono_delay_ms(emu_mono *e, uint32_t ms);
/* One I2C write transaction to 7-bit address addr: 0 when acknowledged,
 * -1 when no device answers (NACK; nothing is taken). */
int emu_mono_i2c_write(emu_mono *e, uint8_t addr, const uint8_t *d, size_t n);

/* The picture a viewer sees with the module turned for `rotation` (the
 * zspan rotation, 0 or 2): w x h = vis_w x vis_h; out[y * w + x] = 1 where
 * the pixel is light (lit OLED pixel, white paper). */
void emu_mono_view(const emu_mono *e, unsigned rotation, uint8_t *out);
int emu_mono_write_png(const emu_mono *e, unsigned rotation, const char *path);
const char *emu_mono_error_name(uint32_t bit);

/* A zs_bus whose wire ends in an emulated controller, as 4-wire SPI or as
 * I2C (commands framed 0x00 + bytes, pixel data 0x40 + bytes, at most
 * max_frame data bytes a transaction). Wire time is counted in clocks: SPI
 * 8 a byte, I2C 9 a byte (ACK) plus 2 for start and stop. */
typedef struct emu_mono_port {
    zs_bus bus;
    emu_mono *emu;
    int i2c;
    uint8_t addr;              /* I2C address the port talks to */
    uint32_t max_frame;        /* I2C data bytes per transaction (0: 4096) */
    uint64_t clocks;           /* wire clocks so far */
    uint32_t frames;           /* I2C transactions */
    uint8_t co_each;           /* I2C: each command byte as 0x80 + byte (Co = 1), as
                                  the Stellaris port frames them (issue 20) */
    uint32_t stream;           /* I2C: FNV-1a 32 over every transaction's address
                                  byte (addr << 1) and bytes (from 0x811C9DC5) */
} emu_mono_port;

int emu_mono_port_init(emu_mono_port *p, emu_mono *e, int i2c, uint8_t addr);
/* Wire time of the clocks counted so far at hz, in microseconds. */
double emu_mono_port_us(const emu_mono_port *p, double hz);

#endif
