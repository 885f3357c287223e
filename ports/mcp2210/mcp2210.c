/* SPDX-License-Identifier: MIT */
/*
 * MCP2210 protocol (command/response reports) and the zs_bus on top of it.
 * Report layouts from the MCP2210 datasheet (DS22288A, section 3).
 */
#define _GNU_SOURCE
#include <errno.h>
#include <sched.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "zs_mcp2210.h"

/* Largest piece of one pixel write sent as one SPI transaction: below the
 * 16-bit transaction length and a multiple of 2 and 3, so a chip-select
 * cycle never splits an RGB565 or RGB666 pixel. */
#define PIECE 65520u

zs_mcp2210_cfg zs_mcp2210_cfg_default(void)
{
    zs_mcp2210_cfg c;
    memset(&c, 0, sizeof c);
    c.bit_rate = 12000000u;
    c.spi_mode = 0;
    c.cs_pin = 0;
    c.dc_pin = 1;
    c.reset_pin = 2;
    c.backlight_pin = -1;
    c.timeout_ms = 1000;
    c.busy_retries = 2000;
    return c;
}

const char *zs_mcp2210_strerror(zs_mcp2210_err e)
{
    switch (e) {
    case ZS_MCP2210_E_NONE: return "no error";
    case ZS_MCP2210_E_GONE: return "the MCP2210 disappeared (unplugged?)";
    case ZS_MCP2210_E_TIMEOUT: return "the MCP2210 did not answer in time";
    case ZS_MCP2210_E_BUSY: return "the MCP2210 stayed busy (0xF8) for too long";
    case ZS_MCP2210_E_PROTOCOL: return "unexpected answer from the MCP2210";
    case ZS_MCP2210_E_BUS_NA: return "the SPI bus is owned by an external master (0xF7)";
    case ZS_MCP2210_E_ARG: return "bad configuration";
    }
    return "unknown error";
}

static int fail(zs_mcp2210 *m, zs_mcp2210_err e, const char *fmt, ...)
{
    va_list ap;
    if (m->error != ZS_MCP2210_E_NONE)
        return -1; /* keep the first failure */
    m->error = e;
    va_start(ap, fmt);
    vsnprintf(m->err, sizeof m->err, fmt, ap);
    va_end(ap);
    return -1;
}

static const char *hid_err(zs_mcp2210 *m)
{
    const char *s = m->hid->error != NULL ? m->hid->error(m->h) : NULL;
    return s != NULL && s[0] != '\0' ? s : "no details";
}

/* One report out, its answer in. Answers that do not echo the command (a
 * late answer to an earlier report) are skipped. */
static int exchange(zs_mcp2210 *m, const uint8_t *req, uint8_t *resp)
{
    int tries;
    if (m->error != ZS_MCP2210_E_NONE)
        return -1;
    if (m->hid->write(m->h, req) != 0)
        return fail(m, ZS_MCP2210_E_GONE, "MCP2210 disconnected: writing command 0x%02X failed (%s)",
                    req[0], hid_err(m));
    m->st.reports++;
    for (tries = 0; tries < 4; tries++) {
        int r = m->hid->read(m->h, resp, m->cfg.timeout_ms);
        if (r < 0)
            return fail(m, ZS_MCP2210_E_GONE,
                        "MCP2210 disconnected: reading the answer to 0x%02X failed (%s)", req[0],
                        hid_err(m));
        if (r == 0)
            return fail(m, ZS_MCP2210_E_TIMEOUT, "MCP2210: no answer to command 0x%02X within %d ms",
                        req[0], m->cfg.timeout_ms);
        if (resp[0] == req[0])
            return 0;
    }
    return fail(m, ZS_MCP2210_E_PROTOCOL, "MCP2210: answers to 0x%02X echo 0x%02X", req[0], resp[0]);
}

/* A command whose answer must be status 0x00; 0xF8 answers are resent. */
static int command(zs_mcp2210 *m, const uint8_t *req, uint8_t *resp)
{
    unsigned busy = 0;
    for (;;) {
        if (exchange(m, req, resp) != 0)
            return -1;
        if (resp[1] == ZS_MCP2210_OK)
            return 0;
        if (resp[1] == ZS_MCP2210_BUS_NA)
            return fail(m, ZS_MCP2210_E_BUS_NA, "MCP2210: command 0x%02X: %s", req[0],
                        zs_mcp2210_strerror(ZS_MCP2210_E_BUS_NA));
        if (resp[1] != ZS_MCP2210_BUSY)
            return fail(m, ZS_MCP2210_E_PROTOCOL, "MCP2210: command 0x%02X answered status 0x%02X",
                        req[0], resp[1]);
        m->st.busy++;
        if (++busy > m->cfg.busy_retries)
            return fail(m, ZS_MCP2210_E_BUSY, "MCP2210: command 0x%02X still busy after %u resends",
                        req[0], m->cfg.busy_retries);
        sched_yield();
    }
}

static void put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
}

static int set_spi_settings(zs_mcp2210 *m, uint32_t txn_len)
{
    uint8_t req[ZS_MCP2210_REPORT], resp[ZS_MCP2210_REPORT];
    uint32_t cs = 1u << m->cfg.cs_pin;
    memset(req, 0, sizeof req);
    req[0] = ZS_MCP2210_CMD_SET_SPI;
    req[4] = (uint8_t)(m->cfg.bit_rate & 0xFFu);
    req[5] = (uint8_t)((m->cfg.bit_rate >> 8) & 0xFFu);
    req[6] = (uint8_t)((m->cfg.bit_rate >> 16) & 0xFFu);
    req[7] = (uint8_t)((m->cfg.bit_rate >> 24) & 0xFFu);
    put16(req + 8, 0x1FFu);        /* idle chip-select values: every CS pin high */
    put16(req + 10, 0x1FFu & ~cs); /* active: our chip-select pin low */
    put16(req + 12, m->cfg.cs_to_data_delay);
    put16(req + 14, m->cfg.data_to_cs_delay);
    put16(req + 16, m->cfg.byte_delay);
    put16(req + 18, txn_len);
    req[20] = m->cfg.spi_mode;
    if (command(m, req, resp) != 0)
        return -1;
    m->st.settings++;
    m->txn_len = txn_len;
    return 0;
}

static int write_gpio(zs_mcp2210 *m, uint16_t value)
{
    uint8_t req[ZS_MCP2210_REPORT], resp[ZS_MCP2210_REPORT];
    memset(req, 0, sizeof req);
    req[0] = ZS_MCP2210_CMD_SET_GPIO;
    put16(req + 4, value);
    if (command(m, req, resp) != 0)
        return -1;
    m->st.gpio++;
    m->gpio = value;
    /* The answer reads the pins back: an output that does not follow is not
     * designated as GPIO (or is shorted). */
    if (m->cfg.dc_pin >= 0) {
        unsigned back = ((unsigned)resp[4] | ((unsigned)resp[5] << 8)) >> m->cfg.dc_pin & 1u;
        if (back != ((unsigned)value >> m->cfg.dc_pin & 1u))
            return fail(m, ZS_MCP2210_E_PROTOCOL,
                        "MCP2210: GP%d (D/C) reads back %u after writing %u: not a GPIO output?",
                        m->cfg.dc_pin, back, (unsigned)value >> m->cfg.dc_pin & 1u);
    }
    return 0;
}

int zs_mcp2210_set_pin(zs_mcp2210 *m, int pin, int level)
{
    uint16_t v;
    if (pin < 0 || pin > 8)
        return 0;
    v = level ? (uint16_t)(m->gpio | (1u << pin)) : (uint16_t)(m->gpio & ~(1u << pin));
    if (v == m->gpio)
        return 0;
    return write_gpio(m, v);
}

int zs_mcp2210_spi(zs_mcp2210 *m, const uint8_t *d, size_t n)
{
    uint8_t req[ZS_MCP2210_REPORT], resp[ZS_MCP2210_REPORT];
    size_t off = 0;
    uint8_t engine = 0;
    unsigned busy = 0;

    if (m->error != ZS_MCP2210_E_NONE)
        return -1;
    if (n == 0)
        return 0;
    if (n > ZS_MCP2210_MAX_TXN)
        return fail(m, ZS_MCP2210_E_ARG, "MCP2210: transaction of %zu bytes (max %u)", n,
                    ZS_MCP2210_MAX_TXN);
    if (m->txn_len != n && set_spi_settings(m, (uint32_t)n) != 0)
        return -1;
    while (off < n) {
        size_t k = n - off < ZS_MCP2210_MAX_CHUNK ? n - off : ZS_MCP2210_MAX_CHUNK;
        memset(req, 0, sizeof req);
        req[0] = ZS_MCP2210_CMD_XFER;
        req[1] = (uint8_t)k;
        memcpy(req + 4, d + off, k);
        if (exchange(m, req, resp) != 0)
            return -1;
        if (resp[1] == ZS_MCP2210_BUSY) {
            /* Not accepted: the engine is busy. Send the same bytes again. */
            m->st.busy++;
            if (++busy > m->cfg.busy_retries)
                return fail(m, ZS_MCP2210_E_BUSY,
                            "MCP2210: SPI data refused (busy) %u times in a row", busy - 1);
            sched_yield();
            continue;
        }
        if (resp[1] == ZS_MCP2210_BUS_NA)
            return fail(m, ZS_MCP2210_E_BUS_NA, "MCP2210: %s",
                        zs_mcp2210_strerror(ZS_MCP2210_E_BUS_NA));
        if (resp[1] != ZS_MCP2210_OK)
            return fail(m, ZS_MCP2210_E_PROTOCOL, "MCP2210: SPI transfer answered status 0x%02X",
                        resp[1]);
        busy = 0;
        engine = resp[3];
        m->st.xfer_reports++;
        m->st.spi_bytes += k;
        off += k;
    }
    /* Wait until the engine has clocked the last byte out (empty transfers;
     * busy answers are expected while it is still shifting). */
    while (engine != ZS_MCP2210_ENG_FINISHED) {
        memset(req, 0, sizeof req);
        req[0] = ZS_MCP2210_CMD_XFER;
        if (exchange(m, req, resp) != 0)
            return -1;
        m->st.poll_reports++;
        if (resp[1] == ZS_MCP2210_BUSY) {
            m->st.busy++;
        } else if (resp[1] == ZS_MCP2210_OK) {
            engine = resp[3];
            if (engine == ZS_MCP2210_ENG_FINISHED)
                break;
        } else {
            return fail(m, ZS_MCP2210_E_PROTOCOL, "MCP2210: end of transfer answered status 0x%02X",
                        resp[1]);
        }
        if (++busy > m->cfg.busy_retries)
            return fail(m, ZS_MCP2210_E_BUSY,
                        "MCP2210: the SPI transfer did not finish after %u polls", busy - 1);
        sched_yield();
    }
    m->st.transactions++;
    return 0;
}

/* ---- bus ops ------------------------------------------------------------------ */

static int op_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    zs_mcp2210 *m = user;
    if (zs_mcp2210_set_pin(m, m->cfg.dc_pin, 0) != 0 || zs_mcp2210_spi(m, &cmd, 1) != 0)
        return -1;
    if (n == 0)
        return 0;
    if (zs_mcp2210_set_pin(m, m->cfg.dc_pin, 1) != 0)
        return -1;
    return zs_mcp2210_spi(m, params, n);
}

static int op_pixels(void *user, const uint8_t *data, size_t n)
{
    zs_mcp2210 *m = user;
    if (zs_mcp2210_set_pin(m, m->cfg.dc_pin, 1) != 0)
        return -1;
    while (n > 0) {
        size_t k = n < PIECE ? n : PIECE;
        if (zs_mcp2210_spi(m, data, k) != 0)
            return -1;
        data += k;
        n -= k;
    }
    return 0;
}

static void op_reset(void *user, int level)
{
    zs_mcp2210 *m = user;
    (void)zs_mcp2210_set_pin(m, m->cfg.reset_pin, level);
}

static void op_backlight(void *user, uint8_t level)
{
    zs_mcp2210 *m = user;
    (void)zs_mcp2210_set_pin(m, m->cfg.backlight_pin, level > 0);
}

static void op_delay(void *user, uint32_t ms)
{
    struct timespec ts;
    (void)user;
    ts.tv_sec = (time_t)(ms / 1000u);
    ts.tv_nsec = (long)(ms % 1000u) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

static const zs_bus_ops mcp_ops = {op_command, op_pixels, op_reset, op_backlight, op_delay, NULL};

/* ---- setup ---------------------------------------------------------------------- */

static int pin_ok(int pin, int optional)
{
    return (optional && pin == -1) || (pin >= 0 && pin <= 8);
}

int zs_mcp2210_init(zs_mcp2210 *m, const zs_hid_ops *ops, void *h, const zs_mcp2210_cfg *cfg)
{
    uint8_t req[ZS_MCP2210_REPORT], resp[ZS_MCP2210_REPORT];
    uint16_t outputs = 0, value = 0;
    int i;
    const int *pins[3];

    memset(m, 0, sizeof *m);
    m->hid = ops;
    m->h = h;
    m->cfg = *cfg;
    if (m->cfg.timeout_ms <= 0)
        m->cfg.timeout_ms = 1000;
    if (ops == NULL || ops->write == NULL || ops->read == NULL)
        return fail(m, ZS_MCP2210_E_ARG, "MCP2210: no transport");
    if (!pin_ok(cfg->cs_pin, 0) || !pin_ok(cfg->dc_pin, 0) || !pin_ok(cfg->reset_pin, 1) ||
        !pin_ok(cfg->backlight_pin, 1))
        return fail(m, ZS_MCP2210_E_ARG, "MCP2210: pins are GP0..GP8 (chip select and D/C required)");
    if (cfg->spi_mode > 3 || cfg->bit_rate == 0)
        return fail(m, ZS_MCP2210_E_ARG, "MCP2210: SPI mode 0..3 and a bit rate > 0");
    pins[0] = &m->cfg.dc_pin;
    pins[1] = &m->cfg.reset_pin;
    pins[2] = &m->cfg.backlight_pin;
    for (i = 0; i < 3; i++) {
        if (*pins[i] < 0)
            continue;
        if (*pins[i] == cfg->cs_pin)
            return fail(m, ZS_MCP2210_E_ARG, "MCP2210: GP%d cannot be chip select and a GPIO",
                        cfg->cs_pin);
        outputs |= (uint16_t)(1u << *pins[i]);
    }
    /* Idle levels: D/C high (data), reset released (high), backlight off. */
    value = (uint16_t)(1u << cfg->dc_pin);
    if (cfg->reset_pin >= 0)
        value |= (uint16_t)(1u << cfg->reset_pin);

    /* Chip settings (0x21): pin roles, default outputs and directions
     * (direction bit 1 = input, 0 = output). */
    memset(req, 0, sizeof req);
    req[0] = ZS_MCP2210_CMD_SET_CHIP;
    for (i = 0; i <= 8; i++)
        req[4 + i] = i == cfg->cs_pin ? ZS_MCP2210_PIN_CS : ZS_MCP2210_PIN_GPIO;
    put16(req + 13, value);
    put16(req + 15, (uint16_t)(0x1FFu & ~outputs));
    req[17] = 0; /* no remote wake-up, no interrupt counting, SPI bus release enabled */
    if (command(m, req, resp) != 0)
        return -1;
    /* Directions and values again through the GPIO commands (the chip-settings
     * defaults apply at power-up; these apply now). */
    memset(req, 0, sizeof req);
    req[0] = ZS_MCP2210_CMD_SET_GPIO_DIR;
    put16(req + 4, (uint16_t)(0x1FFu & ~outputs));
    if (command(m, req, resp) != 0)
        return -1;
    if (write_gpio(m, value) != 0)
        return -1;
    if (set_spi_settings(m, 1) != 0)
        return -1;
    if (zs_bus_init(&m->bus, &mcp_ops, m, 0, PIECE) != ZS_BUS_OK)
        return fail(m, ZS_MCP2210_E_ARG, "zs_bus_init failed");
    return 0;
}

void zs_mcp2210_close(zs_mcp2210 *m)
{
    if (m->hid != NULL && m->hid->close != NULL && m->h != NULL)
        m->hid->close(m->h);
    m->h = NULL;
}
