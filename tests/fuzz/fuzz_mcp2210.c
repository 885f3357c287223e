/* SPDX-License-Identifier: MIT */
/*
 * fuzz_mcp2210: the MCP2210 port's response handling (ports/mcp2210/mcp2210.c)
 * against a chip whose answers come from the fuzz input (libFuzzer).
 *
 * The port talks through a zs_hid_ops table; here that table is a fake chip.
 * Each answer the port reads costs a control byte of the input: a transport
 * error, a timeout, or a report built from the next bytes (echo of the
 * command or a stray one, status OK / busy 0xF8 / bus taken 0xF7 / anything,
 * SPI engine state, GPIO read-back following the last write or not). The
 * first bytes pick the configuration (pins, SPI mode, retries, sometimes
 * invalid); the rest after init is a script of port calls: raw SPI
 * transactions, pin changes, and zs_bus command / pixel writes.
 *
 * Invariants:
 *   - no memory error, no hang (retries are bounded by the input);
 *   - every call returns 0 or -1; -1 leaves a sticky error code and a message,
 *     and after it no report is sent any more;
 *   - every report the port sends is a documented command; a 0x42 report
 *     carries at most 60 bytes; a 0x40 report's transaction length is the
 *     length of the transaction that follows it;
 *   - what the chip accepted is what was asked for: after a successful SPI
 *     transaction of n bytes the last n bytes the chip accepted are those
 *     bytes, st.spi_bytes grew by n, and they went out as one transaction of
 *     length n;
 *   - zs_bus command writes: the command byte goes out with D/C low and its
 *     parameters with D/C high (the D/C pin the chip last accepted).
 */
#include <string.h>

#include "fuzz_util.h"
#include "zs_mcp2210.h"

#define WIRE_MAX (1 << 20)

typedef struct chip {
    fz_reader *d;
    uint8_t last_req[ZS_MCP2210_REPORT];
    int have_req;
    int write_fail_at;        /* fail the n-th write (-1 never) */
    unsigned writes, reads;
    /* what the chip accepted */
    uint16_t gpio;            /* last GPIO values accepted */
    uint32_t txn_len;         /* last transaction length accepted (0x40) */
    uint32_t txn_sent;        /* bytes of the current transaction accepted */
    uint8_t *wire;            /* accepted SPI bytes */
    uint8_t *wire_dc;         /* D/C level of each */
    size_t nwire;
    int dc_pin;
    int pending_ok;           /* the answer we build is OK: commit the request */
} chip;

static int known_cmd(uint8_t c)
{
    switch (c) {
    case ZS_MCP2210_CMD_STATUS: case ZS_MCP2210_CMD_CANCEL: case ZS_MCP2210_CMD_GET_CHIP:
    case ZS_MCP2210_CMD_SET_CHIP: case ZS_MCP2210_CMD_SET_GPIO: case ZS_MCP2210_CMD_GET_GPIO:
    case ZS_MCP2210_CMD_SET_GPIO_DIR: case ZS_MCP2210_CMD_GET_GPIO_DIR:
    case ZS_MCP2210_CMD_SET_SPI: case ZS_MCP2210_CMD_GET_SPI: case ZS_MCP2210_CMD_XFER:
        return 1;
    default:
        return 0;
    }
}

static int chip_write(void *h, const uint8_t report[ZS_MCP2210_REPORT])
{
    chip *c = (chip *)h;
    FZ_CHECK(known_cmd(report[0]), "the port sent an unknown command 0x%02X", report[0]);
    if (report[0] == ZS_MCP2210_CMD_XFER)
        FZ_CHECK(report[1] <= ZS_MCP2210_MAX_CHUNK, "0x42 report with %u bytes", report[1]);
    if ((int)c->writes++ == c->write_fail_at)
        return -1;
    memcpy(c->last_req, report, ZS_MCP2210_REPORT);
    c->have_req = 1;
    return 0;
}

/* The chip takes the request the port sent (the answer is OK). */
static void accept(chip *c)
{
    const uint8_t *q = c->last_req;
    switch (q[0]) {
    case ZS_MCP2210_CMD_SET_GPIO:
        c->gpio = (uint16_t)(q[4] | q[5] << 8);
        break;
    case ZS_MCP2210_CMD_SET_SPI:
        FZ_CHECK(c->txn_sent == 0 || c->txn_sent == c->txn_len,
                 "SPI settings changed in the middle of a transaction (%u of %u bytes)",
                 c->txn_sent, c->txn_len);
        c->txn_len = (uint32_t)(q[18] | q[19] << 8);
        c->txn_sent = 0;
        break;
    case ZS_MCP2210_CMD_XFER:
        if (q[1] == 0)
            break;
        if (c->txn_sent == c->txn_len)
            c->txn_sent = 0; /* the next transaction, same length */
        FZ_CHECK(c->txn_sent + q[1] <= c->txn_len, "%u bytes sent in a transaction of %u",
                 c->txn_sent + q[1], c->txn_len);
        c->txn_sent += q[1];
        for (unsigned i = 0; i < q[1] && c->nwire < WIRE_MAX; i++) {
            c->wire[c->nwire] = q[4 + i];
            c->wire_dc[c->nwire] = c->dc_pin >= 0 ? (uint8_t)(c->gpio >> c->dc_pin & 1u) : 0;
            c->nwire++;
        }
        break;
    default:
        break;
    }
}

static int chip_read(void *h, uint8_t report[ZS_MCP2210_REPORT], int timeout_ms)
{
    chip *c = (chip *)h;
    fz_reader *d = c->d;
    (void)timeout_ms;
    c->reads++;
    FZ_CHECK(c->have_req, "the port reads an answer before sending anything");
    if (fz_left(d) == 0)
        return 0; /* the input is over: the chip is silent */
    uint8_t k = fz_u8(d);
    if (k % 16u == 0)
        return -1;
    if (k % 16u == 1)
        return 0;
    memset(report, 0, ZS_MCP2210_REPORT);
    uint8_t b1 = fz_u8(d), b3 = fz_u8(d);
    report[0] = (k & 0x10u) ? fz_u8(d) : c->last_req[0];
    switch (b1 % 8u) {
    case 0: case 1: case 2: case 3: report[1] = ZS_MCP2210_OK; break;
    case 4: case 5: report[1] = ZS_MCP2210_BUSY; break;
    case 6: report[1] = ZS_MCP2210_BUS_NA; break;
    default: report[1] = fz_u8(d); break;
    }
    switch (b3 % 4u) {
    case 0: case 1: report[3] = ZS_MCP2210_ENG_FINISHED; break;
    case 2: report[3] = ZS_MCP2210_ENG_STARTED; break;
    default: report[3] = ZS_MCP2210_ENG_PENDING; break;
    }
    if (c->last_req[0] == ZS_MCP2210_CMD_SET_GPIO) {
        if (k & 0x20u) { /* pins not following */
            report[4] = fz_u8(d);
            report[5] = fz_u8(d);
        } else {
            report[4] = c->last_req[4];
            report[5] = c->last_req[5];
        }
    }
    if (report[0] == c->last_req[0] && report[1] == ZS_MCP2210_OK)
        accept(c);
    return ZS_MCP2210_REPORT;
}

static const char *chip_error(void *h)
{
    (void)h;
    return "fuzzed transport error";
}

static const zs_hid_ops k_ops = {chip_write, chip_read, chip_error, NULL};

static void after_fail(zs_mcp2210 *m, chip *c, const char *what)
{
    FZ_CHECK(m->error != ZS_MCP2210_E_NONE, "%s returned -1 without an error code", what);
    FZ_CHECK(memchr(m->err, 0, sizeof m->err) != NULL && m->err[0] != 0,
             "%s: no error message", what);
    /* sticky: nothing more goes out */
    unsigned w = c->writes;
    uint8_t b = 0x5A;
    FZ_CHECK(zs_mcp2210_spi(m, &b, 1) == -1 && c->writes == w,
             "a port in error still sends reports");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t wire[WIRE_MAX], wire_dc[WIRE_MAX], buf[70000];
    fz_reader d;
    chip c;
    zs_mcp2210 m;
    fz_init(&d, data, size);
    memset(&c, 0, sizeof c);
    c.d = &d;
    c.wire = wire;
    c.wire_dc = wire_dc;

    zs_mcp2210_cfg cfg = zs_mcp2210_cfg_default();
    uint8_t k = fz_u8(&d);
    if (k & 1u) { /* pins and modes, valid or not */
        cfg.cs_pin = (int)(fz_u8(&d) % 11u) - 1;
        cfg.dc_pin = (int)(fz_u8(&d) % 11u) - 1;
        cfg.reset_pin = (int)(fz_u8(&d) % 11u) - 1;
        cfg.backlight_pin = (int)(fz_u8(&d) % 11u) - 1;
        cfg.spi_mode = (uint8_t)(fz_u8(&d) % 5u);
    }
    cfg.busy_retries = fz_u8(&d) % 8u;
    cfg.timeout_ms = 1;
    c.write_fail_at = (k & 2u) ? fz_u8(&d) : -1;
    c.dc_pin = cfg.dc_pin;

    memset(&m, 0, sizeof m);
    int rc = zs_mcp2210_init(&m, &k_ops, &c, &cfg);
    FZ_CHECK(rc == 0 || rc == -1, "init returned %d", rc);
    if (rc != 0) {
        after_fail(&m, &c, "init");
        return 0;
    }
    FZ_CHECK(m.error == ZS_MCP2210_E_NONE, "init OK with error %d", (int)m.error);

    for (int ops = 0; ops < 64 && fz_left(&d) > 0; ops++) {
        uint8_t op = fz_u8(&d);
        size_t n = fz_u16(&d) % 300u;
        if (op % 8u == 7u)
            n = 60u * (1u + fz_u8(&d) % 4u) + (op >> 6); /* around the chunk size */
        for (size_t i = 0; i < n; i++)
            buf[i] = (uint8_t)(i * 31u + op);
        uint64_t bytes0 = m.st.spi_bytes, txn0 = m.st.transactions;
        size_t wire0 = c.nwire;
        switch (op % 4u) {
        case 0:
        case 3:
            rc = zs_mcp2210_spi(&m, buf, n);
            if (rc == 0 && n > 0 && c.nwire < WIRE_MAX) {
                FZ_CHECK(m.st.spi_bytes == bytes0 + n && m.st.transactions == txn0 + 1,
                         "spi(%zu): bytes %llu -> %llu, transactions %llu -> %llu", n,
                         (unsigned long long)bytes0, (unsigned long long)m.st.spi_bytes,
                         (unsigned long long)txn0, (unsigned long long)m.st.transactions);
                FZ_CHECK(c.nwire - wire0 == n && memcmp(wire + wire0, buf, n) == 0,
                         "spi(%zu): the chip accepted %zu other bytes", n, c.nwire - wire0);
                FZ_CHECK(c.txn_len == n && c.txn_sent == n,
                         "spi(%zu) went out as %u bytes of a %u-byte transaction", n, c.txn_sent,
                         c.txn_len);
            }
            break;
        case 1:
            rc = zs_mcp2210_set_pin(&m, (int)(n % 11u) - 1, (int)(n & 1u));
            break;
        default: {
            const zs_bus_ops *bo = m.bus.ops;
            uint8_t cmd = (uint8_t)n;
            size_t np = n % 7u;
            if (op & 0x40u) {
                rc = bo->pixels(m.bus.user, buf, n);
                if (rc == 0 && n > 0 && c.dc_pin >= 0 && c.nwire < WIRE_MAX - 70000)
                    for (size_t i = wire0; i < c.nwire; i++)
                        FZ_CHECK(wire_dc[i] == 1, "pixel byte %zu sent with D/C low", i - wire0);
            } else {
                rc = bo->command(m.bus.user, cmd, buf, np);
                if (rc == 0 && c.dc_pin >= 0 && c.nwire < WIRE_MAX - 70000) {
                    FZ_CHECK(c.nwire - wire0 == 1 + np, "command with %zu parameters: %zu bytes",
                             np, c.nwire - wire0);
                    FZ_CHECK(wire[wire0] == cmd && wire_dc[wire0] == 0,
                             "command byte %02X sent as %02X with D/C %u", cmd, wire[wire0],
                             wire_dc[wire0]);
                    for (size_t i = 1; i <= np; i++)
                        FZ_CHECK(wire[wire0 + i] == buf[i - 1] && wire_dc[wire0 + i] == 1,
                                 "parameter %zu wrong or with D/C low", i - 1);
                }
            }
            break;
        }
        }
        FZ_CHECK(rc == 0 || rc == -1, "a port call returned %d", rc);
        if (rc != 0) {
            after_fail(&m, &c, "a port call");
            break;
        }
    }
    return 0;
}
