/* SPDX-License-Identifier: MIT */
/*
 * zspan MCP2210 port: a zs_bus over the Microchip MCP2210 USB-to-SPI bridge
 * (USB HID, VID 0x04D8, PID 0x00DE) through hidapi.
 *
 * Every exchange is one 64-byte HID output report answered by one 64-byte
 * input report. The port:
 *  - sets the chip settings (0x21): the chip-select pin as "chip select", the
 *    D/C, reset and backlight pins as GPIO outputs with their idle levels;
 *  - sets the SPI transfer settings (0x40): bit rate, idle/active chip-select
 *    values, the three delays, SPI mode, and bytes per transaction, rewritten
 *    whenever a write needs another transaction length;
 *  - sends each write as one SPI transaction of at most 60 data bytes per
 *    0x42 report, resending a report answered with 0xF8 (busy: the engine is
 *    still shifting the previous bytes), and after the last report polls
 *    with empty 0x42 reports until the engine reports "finished" (0x10), so
 *    that D/C never changes while bytes are still on the wire;
 *  - toggles D/C (and reset, backlight) with "set GPIO values" (0x30).
 *
 * Throughput is bounded by USB full-speed HID: one 64-byte report each way
 * per 1 ms frame, i.e. about 60 KB/s of pixels; a 240x240 RGB565 frame
 * (115,200 bytes) takes about 2 s. Use partial updates.
 *
 * Host C. The HID transport is a small table (zs_hid_ops) so tests can put an
 * emulated chip behind it; zs_mcp2210_open_hidapi() uses hidapi.
 */
#ifndef ZSPAN_PORT_MCP2210_H
#define ZSPAN_PORT_MCP2210_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZS_MCP2210_VID 0x04D8u
#define ZS_MCP2210_PID 0x00DEu
#define ZS_MCP2210_REPORT 64
#define ZS_MCP2210_MAX_CHUNK 60   /* SPI bytes per 0x42 report */
#define ZS_MCP2210_MAX_TXN 65535u /* bytes per SPI transaction (16-bit setting) */

/* Command codes (first byte of a report). */
#define ZS_MCP2210_CMD_STATUS 0x10u
#define ZS_MCP2210_CMD_CANCEL 0x11u
#define ZS_MCP2210_CMD_GET_CHIP 0x20u
#define ZS_MCP2210_CMD_SET_CHIP 0x21u
#define ZS_MCP2210_CMD_SET_GPIO 0x30u
#define ZS_MCP2210_CMD_GET_GPIO 0x31u
#define ZS_MCP2210_CMD_SET_GPIO_DIR 0x32u
#define ZS_MCP2210_CMD_GET_GPIO_DIR 0x33u
#define ZS_MCP2210_CMD_SET_SPI 0x40u
#define ZS_MCP2210_CMD_GET_SPI 0x41u
#define ZS_MCP2210_CMD_XFER 0x42u

/* Response status (byte 1). */
#define ZS_MCP2210_OK 0x00u
#define ZS_MCP2210_BUS_NA 0xF7u   /* SPI bus owned by an external master */
#define ZS_MCP2210_BUSY 0xF8u     /* transfer in progress: resend */

/* SPI engine status (byte 3 of a 0x42 response). */
#define ZS_MCP2210_ENG_FINISHED 0x10u
#define ZS_MCP2210_ENG_STARTED 0x20u
#define ZS_MCP2210_ENG_PENDING 0x30u

/* Pin designations (chip settings bytes 4..12). */
#define ZS_MCP2210_PIN_GPIO 0x00u
#define ZS_MCP2210_PIN_CS 0x01u
#define ZS_MCP2210_PIN_DEDICATED 0x02u

/* The HID transport. */
typedef struct zs_hid_ops {
    /* Sends one 64-byte output report. 0, or -1 (device gone, I/O error). */
    int (*write)(void *h, const uint8_t report[ZS_MCP2210_REPORT]);
    /* Reads one 64-byte input report: 64, 0 on timeout, -1 on error. */
    int (*read)(void *h, uint8_t report[ZS_MCP2210_REPORT], int timeout_ms);
    /* Optional: text of the last transport error. */
    const char *(*error)(void *h);
    /* Optional: closes the transport. */
    void (*close)(void *h);
} zs_hid_ops;

typedef struct zs_mcp2210_cfg {
    uint32_t bit_rate;        /* SPI bit rate, Hz (default 12 MHz, the chip's maximum) */
    uint8_t spi_mode;         /* 0..3 */
    int cs_pin;               /* GP pin used as chip select (0..8; default 0) */
    int dc_pin;               /* GP pin wired to D/C (required; default 1) */
    int reset_pin;            /* GP pin wired to RESET, -1 none (default 2) */
    int backlight_pin;        /* GP pin wired to the backlight, -1 none (default -1) */
    uint16_t cs_to_data_delay;   /* in 100 us quanta (default 0) */
    uint16_t data_to_cs_delay;   /* last byte to CS release, 100 us quanta (default 0) */
    uint16_t byte_delay;         /* between bytes, 100 us quanta (default 0) */
    int timeout_ms;           /* per report answer (default 1000) */
    unsigned busy_retries;    /* resends of a busy (0xF8) report before giving up (default 2000) */
} zs_mcp2210_cfg;

zs_mcp2210_cfg zs_mcp2210_cfg_default(void);

typedef struct zs_mcp2210_stats {
    uint64_t reports;         /* output reports sent (answers read) */
    uint64_t xfer_reports;    /* 0x42 reports carrying data */
    uint64_t poll_reports;    /* empty 0x42 reports waiting for "finished" */
    uint64_t busy;            /* 0xF8 answers (each one resent) */
    uint64_t spi_bytes;       /* bytes clocked out */
    uint64_t transactions;    /* SPI transactions (chip-select cycles) */
    uint64_t settings;        /* 0x40 reports (transaction length changes) */
    uint64_t gpio;            /* 0x30 reports */
} zs_mcp2210_stats;

typedef enum zs_mcp2210_err {
    ZS_MCP2210_E_NONE = 0,
    ZS_MCP2210_E_GONE,        /* the device disappeared (read/write failed) */
    ZS_MCP2210_E_TIMEOUT,     /* no answer within timeout_ms */
    ZS_MCP2210_E_BUSY,        /* still busy after busy_retries resends */
    ZS_MCP2210_E_PROTOCOL,    /* unexpected answer (wrong echo, status) */
    ZS_MCP2210_E_BUS_NA,      /* 0xF7: an external master owns the SPI bus */
    ZS_MCP2210_E_ARG          /* bad configuration */
} zs_mcp2210_err;

typedef struct zs_mcp2210 {
    zs_bus bus;               /* give &m.bus to zs_panel_init */
    const zs_hid_ops *hid;
    void *h;
    zs_mcp2210_cfg cfg;
    uint16_t gpio;            /* GPIO output values last written */
    uint32_t txn_len;         /* bytes per transaction in the chip's settings (0 = unknown) */
    zs_mcp2210_err error;     /* first failure (sticky) */
    char err[256];
    zs_mcp2210_stats st;
} zs_mcp2210;

/* Sets up the chip behind an open transport (chip settings, GPIO levels, SPI
 * settings) and m->bus (blocking). Returns 0, or -1 with m->error / m->err. */
int zs_mcp2210_init(zs_mcp2210 *m, const zs_hid_ops *ops, void *h, const zs_mcp2210_cfg *cfg);

/* Opens the chip with hidapi: `path` (a hidraw path such as /dev/hidraw0) or,
 * if NULL, the first device with VID 0x04D8 / PID 0x00DE, then
 * zs_mcp2210_init. Returns 0, or -1 with a message in err. */
int zs_mcp2210_open_hidapi(zs_mcp2210 *m, const char *path, const zs_mcp2210_cfg *cfg, char *err,
                           size_t errlen);

/* One SPI transaction of n bytes (n <= ZS_MCP2210_MAX_TXN) with the current
 * D/C level. 0, or -1 (see m->error). */
int zs_mcp2210_spi(zs_mcp2210 *m, const uint8_t *d, size_t n);
/* Sets GP pin `pin` to level (0/1). */
int zs_mcp2210_set_pin(zs_mcp2210 *m, int pin, int level);

/* Closes the transport (if it has a close op). */
void zs_mcp2210_close(zs_mcp2210 *m);

const char *zs_mcp2210_strerror(zs_mcp2210_err e);

#ifdef __cplusplus
}
#endif

#endif
