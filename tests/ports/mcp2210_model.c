/* SPDX-License-Identifier: MIT */
/* MCP2210 model (see mcp2210_model.h). Report layouts: datasheet DS22288A, section 3. */
#define _GNU_SOURCE
#include "mcp2210_model.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

static uint64_t now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

static void misuse(mcp_model *m, const char *fmt, ...)
{
    va_list ap;
    if (m->errors++ == 0) {
        va_start(ap, fmt);
        vsnprintf(m->first_error, sizeof m->first_error, fmt, ap);
        va_end(ap);
    }
}

/* The panel lives in real time: hand it the milliseconds that passed. */
static void tick(mcp_model *m)
{
    uint64_t ms = (now_us() - m->t0_us) / 1000u;
    if (ms > m->delivered_ms) {
        emu_delay_ms(m->emu, (uint32_t)(ms - m->delivered_ms));
        m->delivered_ms = ms;
    }
}

static uint16_t get16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static void put16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)(v >> 8);
}

static int is_output(const mcp_model *m, int pin)
{
    return pin >= 0 && m->designation[pin] == 0x00 && !((m->gpio_dir >> pin) & 1u);
}

/* Level the panel sees on a GPIO-wired pin (a floating input reads high:
 * the modules have pull-ups). */
static int pin_level(const mcp_model *m, int pin)
{
    if (!is_output(m, pin))
        return 1;
    return (m->gpio_value >> pin) & 1;
}

static void apply_pins(mcp_model *m)
{
    int r = m->reset_pin >= 0 ? pin_level(m, m->reset_pin) : 1;
    if (r != m->reset_level) {
        tick(m);
        emu_reset_line(m->emu, r);
        m->reset_level = r;
    }
    if (m->bl_pin >= 0)
        m->emu->backlight = (uint8_t)(pin_level(m, m->bl_pin) ? 255 : 0);
}

void mcp_model_init(mcp_model *m, emu_panel *emu, int cs_pin, int dc_pin, int reset_pin,
                    int bl_pin)
{
    memset(m, 0, sizeof *m);
    m->emu = emu;
    m->cs_pin = cs_pin;
    m->dc_pin = dc_pin;
    m->reset_pin = reset_pin;
    m->bl_pin = bl_pin;
    m->gpio_dir = 0x1FF;
    m->idle_cs = 0x1FF;
    m->active_cs = 0x1FF;
    m->txn_len = 1;
    m->bit_rate = 12000000u;
    m->busy_burst = 1;
    m->reset_level = 1;
    m->t0_us = now_us();
}

/* Does the engine select the panel during a transaction? */
static int panel_selected(const mcp_model *m)
{
    if (m->cs_pin < 0)
        return 1; /* CS tied low */
    if (m->designation[m->cs_pin] != 0x01)
        return 0;
    return !((m->active_cs >> m->cs_pin) & 1u) && ((m->idle_cs >> m->cs_pin) & 1u);
}

static void xfer(mcp_model *m, const uint8_t *req, uint8_t *resp)
{
    unsigned n = req[1];
    if (n > 60) {
        misuse(m, "0x42 with %u bytes (max 60)", n);
        resp[1] = 0xF8;
        return;
    }
    if (n == 0) {
        /* A poll: is the transaction over? */
        if (m->finishing > 0) {
            m->finishing--;
            m->poll_busy_sent++;
            resp[1] = 0xF8;
            return;
        }
        resp[1] = 0x00;
        resp[2] = 0;
        resp[3] = m->in_txn ? 0x30 : 0x10;
        return;
    }
    m->data_reports++;
    if (m->bus_na) {
        resp[1] = 0xF7;
        return;
    }
    if (m->busy_left == 0 && m->busy_every > 0 && m->data_reports % m->busy_every == 0)
        m->busy_left = m->busy_burst;
    if (m->busy_left > 0 || m->finishing > 0) {
        if (m->busy_left > 0)
            m->busy_left--;
        else
            m->finishing--;
        m->busy_sent++;
        resp[1] = 0xF8; /* not accepted: send it again */
        return;
    }
    if (!m->in_txn) {
        m->in_txn = 1;
        m->txn_done = 0;
    }
    if (m->txn_done + n > m->txn_len) {
        misuse(m, "%u bytes past the transaction length %u", m->txn_done + n - m->txn_len,
               m->txn_len);
        n = m->txn_len - m->txn_done;
    }
    tick(m);
    if (!panel_selected(m)) {
        misuse(m, "SPI data while the panel's chip select (GP%d) is not driven active",
               m->cs_pin);
    } else if (m->dc_pin >= 0 && !pin_level(m, m->dc_pin)) {
        unsigned i;
        for (i = 0; i < n; i++)
            emu_command(m->emu, req[4 + i]);
    } else {
        emu_data(m->emu, req + 4, n);
    }
    m->bytes_to_panel += n;
    resp[1] = 0x00;
    resp[2] = (uint8_t)n; /* received bytes (MISO reads 0) */
    if (m->txn_done == 0 && m->txn_done + n < m->txn_len) {
        m->txn_done += n;
        resp[3] = 0x20;
        return;
    }
    m->txn_done += n;
    if (m->txn_done >= m->txn_len) {
        m->in_txn = 0;
        m->transactions++;
        if (m->lag > 0) {
            /* The last bytes are still being shifted out. */
            m->finishing = m->lag;
            resp[3] = 0x30;
        } else {
            resp[3] = 0x10;
        }
        return;
    }
    resp[3] = 0x30;
}

int mcp_model_handle(mcp_model *m, const uint8_t *req, uint8_t *resp)
{
    int i;
    memset(resp, 0, 64);
    resp[0] = req[0];
    if (m->gone)
        return 0;
    m->reports++;
    if (req[0] == 0x42 && req[1] > 0 && m->disconnect_after > 0 &&
        (long)m->data_reports + 1 >= m->disconnect_after) {
        m->gone = 1;
        return 0;
    }
    switch (req[0]) {
    case 0x10: /* status */
        resp[1] = 0x00;
        resp[2] = 0x01;
        resp[3] = m->in_txn ? 0x01 : 0x00;
        break;
    case 0x11: /* cancel */
        m->in_txn = 0;
        m->finishing = 0;
        resp[1] = 0x00;
        break;
    case 0x20: /* get chip settings */
        resp[1] = 0x00;
        memcpy(resp + 4, m->designation, 9);
        put16(resp + 13, m->gpio_value);
        put16(resp + 15, m->gpio_dir);
        break;
    case 0x21: /* set chip settings */
        if (m->in_txn || m->finishing) {
            misuse(m, "chip settings changed inside an SPI transaction");
            resp[1] = 0xF8;
            break;
        }
        for (i = 0; i < 9; i++) {
            if (req[4 + i] > 2)
                misuse(m, "GP%d designation 0x%02X", i, req[4 + i]);
            m->designation[i] = req[4 + i];
        }
        m->gpio_value = get16(req + 13) & 0x1FF;
        m->gpio_dir = get16(req + 15) & 0x1FF;
        apply_pins(m);
        resp[1] = 0x00;
        break;
    case 0x30: /* set GPIO values */
        if (m->in_txn || m->finishing)
            misuse(m, "GPIO values changed inside an SPI transaction (D/C would glitch)");
        m->gpio_value = get16(req + 4) & 0x1FF;
        m->gpio_writes++;
        apply_pins(m);
        resp[1] = 0x00;
        {
            uint16_t back = 0;
            for (i = 0; i < 9; i++)
                if (m->designation[i] == 0x00 && (is_output(m, i) ? (m->gpio_value >> i) & 1 : 1))
                    back |= (uint16_t)(1u << i);
            put16(resp + 4, back);
        }
        break;
    case 0x31: /* get GPIO values */
        resp[1] = 0x00;
        put16(resp + 4, m->gpio_value);
        break;
    case 0x32: /* set GPIO direction */
        if (m->in_txn || m->finishing)
            misuse(m, "GPIO directions changed inside an SPI transaction");
        m->gpio_dir = get16(req + 4) & 0x1FF;
        apply_pins(m);
        resp[1] = 0x00;
        break;
    case 0x33: /* get GPIO direction */
        resp[1] = 0x00;
        put16(resp + 4, m->gpio_dir);
        break;
    case 0x40: /* set SPI transfer settings */
        if (m->in_txn || m->finishing) {
            misuse(m, "SPI settings changed inside an SPI transaction");
            resp[1] = 0xF8;
            break;
        }
        m->bit_rate = (uint32_t)req[4] | ((uint32_t)req[5] << 8) | ((uint32_t)req[6] << 16) |
                      ((uint32_t)req[7] << 24);
        m->idle_cs = get16(req + 8);
        m->active_cs = get16(req + 10);
        m->delay_cs_data = get16(req + 12);
        m->delay_data_cs = get16(req + 14);
        m->delay_bytes = get16(req + 16);
        m->txn_len = get16(req + 18);
        m->spi_mode = req[20];
        if (m->txn_len == 0)
            misuse(m, "SPI settings with 0 bytes per transaction");
        if (m->bit_rate == 0 || m->bit_rate > 12000000u)
            misuse(m, "bit rate %u out of range", (unsigned)m->bit_rate);
        if (m->spi_mode > 3)
            misuse(m, "SPI mode %u", m->spi_mode);
        m->settings_seen = 1;
        m->settings_writes++;
        memcpy(resp + 4, req + 4, 17);
        resp[1] = 0x00;
        break;
    case 0x41: /* get SPI transfer settings */
        resp[1] = 0x00;
        resp[2] = 17;
        resp[4] = (uint8_t)m->bit_rate;
        resp[5] = (uint8_t)(m->bit_rate >> 8);
        resp[6] = (uint8_t)(m->bit_rate >> 16);
        resp[7] = (uint8_t)(m->bit_rate >> 24);
        put16(resp + 8, m->idle_cs);
        put16(resp + 10, m->active_cs);
        put16(resp + 12, m->delay_cs_data);
        put16(resp + 14, m->delay_data_cs);
        put16(resp + 16, m->delay_bytes);
        put16(resp + 18, m->txn_len);
        resp[20] = m->spi_mode;
        break;
    case 0x42:
        xfer(m, req, resp);
        break;
    default:
        misuse(m, "unknown command 0x%02X", req[0]);
        resp[1] = 0xF9;
        break;
    }
    return 1;
}
