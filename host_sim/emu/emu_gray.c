/* SPDX-License-Identifier: MIT */
/* Emulated SSD0323 with its 128x64 glass (see emu_gray.h). */
#include "emu_gray.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emu.h"

/* The module's wiring: the 64 COM lines of the glass are the first 64 of
 * the controller, wired odd/even (the COM split setting shows them in
 * order); SEG0 at the left edge. */
#define GLASS_COM_SPLIT 1

static void flag(emu_gray *e, uint32_t bit, const char *fmt, ...)
{
    e->errors |= bit;
    if (e->error_count++ == 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->first_error, sizeof e->first_error, fmt, ap);
        va_end(ap);
    }
}

static void power_on_state(emu_gray *e)
{
    e->remap = 0;
    e->start_line = e->offset = 0;
    e->mux = 79;
    e->mode = 0xA4;
    e->display_on = 0;
    e->col = e->row = 0;
    e->col_lo = 0;
    e->col_hi = EMU_GRAY_RAM_COLS - 1;
    e->row_lo = 0;
    e->row_hi = EMU_GRAY_RAM_ROWS - 1;
    e->cmd = -1;
}

void emu_gray_init(emu_gray *e)
{
    unsigned r, c;
    memset(e, 0, sizeof *e);
    /* power-on RAM is noise */
    for (r = 0; r < EMU_GRAY_RAM_ROWS; r++)
        for (c = 0; c < EMU_GRAY_RAM_COLS; c++)
            e->ram[r][c] = (uint8_t)(((r * 64u + c) * 2654435761u) >> 24);
    power_on_state(e);
}

void emu_gray_reset_line(emu_gray *e, int level)
{
    if (!level) {
        e->reset_low = 1;
    } else if (e->reset_low) {
        e->reset_low = 0;
        power_on_state(e);
    }
}

/* Parameter count of a command byte; -1 if it is none. */
static int params_of(uint8_t c)
{
    switch (c) {
    case 0x15: case 0x75: return 2;
    case 0x81: case 0xA0: case 0xA1: case 0xA2: case 0xA8: case 0xAD:
    case 0xB1: case 0xB2: case 0xB3: case 0xBC: case 0xBE: case 0xBF:
        return 1;
    case 0xB8: return 8;
    case 0x84: case 0x85: case 0x86: case 0xA4: case 0xA5: case 0xA6: case 0xA7:
    case 0xAE: case 0xAF: case 0xE3:
        return 0;
    default: return -1;
    }
}

static void apply(emu_gray *e, uint8_t c, const uint8_t *p)
{
    switch (c) {
    case 0x15:
        if (p[0] > p[1] || p[1] >= EMU_GRAY_RAM_COLS)
            flag(e, EMU_M_WINDOW, "columns %u..%u", p[0], p[1]);
        e->col_lo = e->col = (uint8_t)(p[0] % EMU_GRAY_RAM_COLS);
        e->col_hi = (uint8_t)(p[1] % EMU_GRAY_RAM_COLS);
        break;
    case 0x75:
        if (p[0] > p[1] || p[1] >= EMU_GRAY_RAM_ROWS)
            flag(e, EMU_M_WINDOW, "rows %u..%u", p[0], p[1]);
        e->row_lo = e->row = (uint8_t)(p[0] % EMU_GRAY_RAM_ROWS);
        e->row_hi = (uint8_t)(p[1] % EMU_GRAY_RAM_ROWS);
        break;
    case 0xA0:
        if (p[0] & 0xA8u)
            flag(e, EMU_M_PARAM, "re-map 0x%02X sets reserved bits", p[0]);
        e->remap = p[0];
        break;
    case 0xA1: case 0xA2:
        if (p[0] >= EMU_GRAY_RAM_ROWS)
            flag(e, EMU_M_PARAM, "%s %u", c == 0xA1 ? "start line" : "offset", p[0]);
        if (c == 0xA1) e->start_line = (uint8_t)(p[0] % EMU_GRAY_RAM_ROWS);
        else e->offset = (uint8_t)(p[0] % EMU_GRAY_RAM_ROWS);
        break;
    case 0xA8:
        if (p[0] < 15 || p[0] > 79)
            flag(e, EMU_M_PARAM, "multiplex ratio %u", p[0] + 1u);
        e->mux = (uint8_t)(p[0] > 79 ? 79 : p[0]);
        break;
    case 0xA4: case 0xA5: case 0xA6: case 0xA7: e->mode = c; break;
    case 0xAE: case 0xAF:
        e->display_on = c & 1u;
        if (e->display_on && e->mux + 1u != EMU_GRAY_H)
            flag(e, EMU_M_POWER, "multiplex ratio %u for %u rows", e->mux + 1u, EMU_GRAY_H);
        break;
    default: break; /* contrast, current, timing, grey table, levels: not the picture */
    }
}

void emu_gray_command(emu_gray *e, uint8_t b)
{
    int n;
    e->bytes++;
    if (e->reset_low) {
        flag(e, EMU_M_BUSY, "byte 0x%02X in reset", b);
        return;
    }
    if (e->cmd >= 0) { /* a parameter (D/C low too) */
        e->params[e->have++] = b;
        if (e->have == e->need) {
            apply(e, (uint8_t)e->cmd, e->params);
            e->cmd = -1;
        }
        return;
    }
    e->commands++;
    n = params_of(b);
    if (n < 0) {
        flag(e, EMU_M_COMMAND, "0x%02X is no SSD0323 command", b);
        return;
    }
    if (n == 0) {
        apply(e, b, e->params);
        return;
    }
    e->cmd = b;
    e->need = n;
    e->have = 0;
}

static void ram_write(emu_gray *e, uint8_t b)
{
    e->ram[e->row][e->col] = b;
    e->data_bytes++;
    if (e->remap & 0x04u) { /* vertical: down the rows, then the next column */
        if (e->row < e->row_hi) {
            e->row++;
        } else {
            e->row = e->row_lo;
            e->col = e->col < e->col_hi ? (uint8_t)(e->col + 1u) : e->col_lo;
        }
    } else if (e->col < e->col_hi) {
        e->col++;
    } else {
        e->col = e->col_lo;
        e->row = e->row < e->row_hi ? (uint8_t)(e->row + 1u) : e->row_lo;
    }
}

void emu_gray_data(emu_gray *e, const uint8_t *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        e->bytes++;
        if (e->reset_low) {
            flag(e, EMU_M_BUSY, "byte 0x%02X in reset", d[i]);
            continue;
        }
        if (e->cmd >= 0) {
            flag(e, EMU_M_COMMAND, "data while command 0x%02X waits for parameters", e->cmd);
            e->cmd = -1;
        }
        ram_write(e, d[i]);
    }
}

static uint8_t pixel(const emu_gray *e, unsigned x, unsigned y)
{
    unsigned com = y, mux = e->mux + 1u, row, seg, col, first;
    uint8_t b, v;
    if (!e->display_on || e->reset_low || e->mode == 0xA6)
        return 0;
    if (e->mode == 0xA5)
        return 15;
    if (((e->remap & 0x40u) != 0) != GLASS_COM_SPLIT) /* pins wired the other way */
        com = (com % 2u) * (mux / 2u) + com / 2u;
    if (com >= mux)
        return 0;
    row = (e->remap & 0x10u) ? mux - 1u - com : com;
    row = (row + e->start_line + e->offset) % EMU_GRAY_RAM_ROWS;
    /* column address c drives SEG 2c and 2c+1 (SEG 127-2c and 126-2c re-mapped);
     * the byte's first pixel is its low nibble, its high one with nibble re-map */
    seg = (e->remap & 0x01u) ? 127u - x : x;
    col = seg / 2u;
    first = (seg % 2u) == 0;
    b = e->ram[row][col];
    v = (uint8_t)(first == ((e->remap & 0x02u) != 0) ? b >> 4 : b & 15u);
    return (uint8_t)(e->mode == 0xA7 ? 15u - v : v);
}

void emu_gray_view(const emu_gray *e, uint8_t *out)
{
    unsigned x, y;
    for (y = 0; y < EMU_GRAY_H; y++)
        for (x = 0; x < EMU_GRAY_W; x++)
            out[y * EMU_GRAY_W + x] = pixel(e, x, y);
}

int emu_gray_write_png(const emu_gray *e, const char *path)
{
    static uint8_t lv[EMU_GRAY_W * EMU_GRAY_H], rgb[3 * EMU_GRAY_W * EMU_GRAY_H];
    size_t i;
    emu_gray_view(e, lv);
    for (i = 0; i < sizeof lv; i++) /* the Pictiva's yellow-green at 16 steps */
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = (uint8_t)(lv[i] * 17u);
    return emu_png_write_rgb(path, rgb, EMU_GRAY_W, EMU_GRAY_H);
}

/* ---- the bus port ---- */

static uint32_t fnv(uint32_t h, uint8_t b)
{
    return (h ^ b) * 0x01000193u;
}

static int port_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    emu_gray_port *p = user;
    size_t i;
    emu_gray_command(p->emu, cmd);
    p->stream = fnv(fnv(p->stream, 0), cmd);
    emu_gray_data(p->emu, params, n);
    for (i = 0; i < n; i++)
        p->stream = fnv(fnv(p->stream, 1), params[i]);
    p->clocks += 8u * (1u + n);
    return 0;
}

static int port_pixels(void *user, const uint8_t *data, size_t n)
{
    emu_gray_port *p = user;
    size_t i;
    emu_gray_data(p->emu, data, n);
    for (i = 0; i < n; i++)
        p->stream = fnv(fnv(p->stream, 1), data[i]);
    p->clocks += 8u * n;
    return 0;
}

static void port_reset(void *user, int level)
{
    emu_gray_port *p = user;
    emu_gray_reset_line(p->emu, level);
}

static const zs_bus_ops port_ops = {
    .command = port_command,
    .pixels = port_pixels,
    .reset = port_reset,
    .backlight = NULL,
    .delay_ms = NULL,
    .poll = NULL,
};

int emu_gray_port_init(emu_gray_port *p, emu_gray *e)
{
    memset(p, 0, sizeof *p);
    p->emu = e;
    p->stream = 0x811C9DC5u;
    return zs_bus_init(&p->bus, &port_ops, p, 0, 0) == ZS_BUS_OK ? 0 : -1;
}
