/* SPDX-License-Identifier: MIT */
/*
 * Emulated SSD0323 (4-bit greyscale OLED controller, 128 x 80 RAM of
 * nibbles) with the OSRAM Pictiva 128x64 glass of the Stellaris LM3S6965
 * board, fed with the 4-wire SPI byte stream (D/C low: commands and their
 * parameters; D/C high: RAM data). It follows the column/row windows, the
 * horizontal or vertical address increment, the re-map bits (column, nibble,
 * COM, COM split), start line, offset, multiplex ratio, display modes, and
 * shows the glass as 16 grey levels; protocol errors are flagged with the
 * EMU_M_* bits of emu_mono.h. Written from the datasheet, apart from the
 * zspan tables (issue 20).
 *
 * Host C99.
 */
#ifndef ZSPAN_EMU_GRAY_H
#define ZSPAN_EMU_GRAY_H

#include <stddef.h>
#include <stdint.h>

#include "emu_mono.h"
#include "zspan/bus.h"

#define EMU_GRAY_RAM_COLS 64 /* column addresses: pairs of pixels */
#define EMU_GRAY_RAM_ROWS 80
#define EMU_GRAY_W 128       /* the glass */
#define EMU_GRAY_H 64

typedef struct emu_gray {
    uint8_t ram[EMU_GRAY_RAM_ROWS][EMU_GRAY_RAM_COLS]; /* bytes as written */
    uint8_t remap, start_line, offset, mux, mode; /* mode: 0xA4..0xA7 */
    uint8_t display_on;
    uint8_t col, row, col_lo, col_hi, row_lo, row_hi;
    int cmd, need, have;
    uint8_t params[8];
    uint8_t reset_low;
    uint32_t errors, error_count;
    char first_error[160];
    uint64_t bytes, data_bytes;
    uint32_t commands;
} emu_gray;

void emu_gray_init(emu_gray *e);
void emu_gray_reset_line(emu_gray *e, int level); /* 0 = asserted */
void emu_gray_command(emu_gray *e, uint8_t b);    /* D/C low */
void emu_gray_data(emu_gray *e, const uint8_t *d, size_t n); /* D/C high */
/* The glass: out[y * 128 + x] = level 0..15 (0 dark). */
void emu_gray_view(const emu_gray *e, uint8_t *out);
int emu_gray_write_png(const emu_gray *e, const char *path);

/* A blocking zs_bus over 4-wire SPI into the emulator. stream is FNV-1a 32
 * over (D/C, byte) for every byte on the wire (D/C 0 or 1), the figure the
 * Stellaris firmware reports for its own SPI stream. */
typedef struct emu_gray_port {
    zs_bus bus;
    emu_gray *emu;
    uint32_t stream;
    uint64_t clocks;
} emu_gray_port;

int emu_gray_port_init(emu_gray_port *p, emu_gray *e);

#endif
