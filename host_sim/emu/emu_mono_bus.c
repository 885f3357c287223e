/* SPDX-License-Identifier: MIT */
/* The zs_bus port of the emulated monochrome controllers (emu_mono.h):
 * 4-wire SPI or I2C framing, with the wire clocks counted. */
#include <string.h>

#include "emu_mono.h"

/* ---- the bus port ---- */

/* One I2C write transaction, hashed into the port's stream. */
static int i2c_write(emu_mono_port *p, const uint8_t *frame, size_t n)
{
    size_t i;
    p->stream = (p->stream ^ (uint8_t)(p->addr << 1)) * 0x01000193u;
    for (i = 0; i < n; i++)
        p->stream = (p->stream ^ frame[i]) * 0x01000193u;
    return emu_mono_i2c_write(p->emu, p->addr, frame, n);
}

static int port_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    emu_mono_port *p = user;
    if (p->i2c && p->co_each) { /* 0x80 before every byte */
        uint8_t frame[2 * (1 + 64)];
        size_t i;
        if (n > 64)
            return -1;
        frame[0] = 0x80;
        frame[1] = cmd;
        for (i = 0; i < n; i++) {
            frame[2 + 2 * i] = 0x80;
            frame[3 + 2 * i] = params[i];
        }
        p->clocks += 9u * (1u + 2u * (1u + n)) + 2u;
        p->frames++;
        return i2c_write(p, frame, 2u * (1u + n)) == 0 ? 0 : -1;
    }
    if (p->i2c) {
        uint8_t frame[1 + 1 + 64];
        if (n > 64)
            return -1;
        frame[0] = 0x00; /* Co = 0, D/C# = 0: command bytes follow */
        frame[1] = cmd;
        if (n)
            memcpy(frame + 2, params, n);
        p->clocks += 9u * (1u + 2u + n) + 2u;
        p->frames++;
        return i2c_write(p, frame, n + 2) == 0 ? 0 : -1;
    }
    emu_mono_command(p->emu, cmd);
    emu_mono_data(p->emu, params, n);
    p->clocks += 8u * (1u + n);
    return 0;
}

static int port_pixels(void *user, const uint8_t *data, size_t n)
{
    emu_mono_port *p = user;
    if (p->i2c) {
        uint32_t max = p->max_frame ? p->max_frame : 4096u;
        uint8_t frame[1 + 4096];
        while (n > 0) {
            size_t k = n < max ? n : max;
            frame[0] = 0x40; /* Co = 0, D/C# = 1: data bytes follow */
            memcpy(frame + 1, data, k);
            p->clocks += 9u * (1u + 1u + k) + 2u;
            p->frames++;
            if (i2c_write(p, frame, k + 1) != 0)
                return -1;
            data += k;
            n -= k;
        }
        return 0;
    }
    emu_mono_data(p->emu, data, n);
    p->clocks += 8u * n;
    return 0;
}

static void port_reset(void *user, int level)
{
    emu_mono_port *p = user;
    emu_mono_reset_line(p->emu, level);
}

static void port_delay(void *user, uint32_t ms)
{
    emu_mono_port *p = user;
    emu_mono_delay_ms(p->emu, ms);
}

static const zs_bus_ops port_ops = {
    .command = port_command,
    .pixels = port_pixels,
    .reset = port_reset,
    .backlight = NULL,
    .delay_ms = port_delay,
    .poll = NULL,
};

int emu_mono_port_init(emu_mono_port *p, emu_mono *e, int i2c, uint8_t addr)
{
    memset(p, 0, sizeof *p);
    p->emu = e;
    p->i2c = i2c;
    p->addr = addr;
    p->stream = 0x811C9DC5u;
    return zs_bus_init(&p->bus, &port_ops, p, 0, 0) == ZS_BUS_OK ? 0 : -1;
}

double emu_mono_port_us(const emu_mono_port *p, double hz)
{
    return (double)p->clocks * 1e6 / hz;
}
