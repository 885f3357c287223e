/* SPDX-License-Identifier: MIT */
/*
 * A model of the Microchip MCP2210 USB-to-SPI bridge, as far as a display
 * needs it, wired to an emulated panel (host_sim/emu):
 *
 *   GP pins: designation (GPIO / chip select / dedicated), direction, value;
 *   SPI settings: bit rate, idle and active chip-select values, delays,
 *   bytes per transaction, mode;
 *   0x42 transfers of up to 60 bytes; a transaction ends when `bytes per
 *   transaction` bytes have gone out; the engine then may still be shifting
 *   (`lag` empty transfers answered 0xF8 before "finished");
 *   the panel sees a byte only while its CS pin is driven low by the
 *   engine (pin designated "chip select", active value 0) and takes D/C and
 *   RESET from the GP pins it is wired to (designated GPIO, output).
 *
 * Faults to inject: busy (0xF8) answers every N data reports, in bursts;
 * a disconnect (no answer, the device vanishes) at the N-th data report.
 * Protocol misuse (D/C or settings changed inside a transaction, bytes past
 * the transaction length, data to a panel that is not selected) is counted in
 * `errors` with the first one described.
 */
#ifndef ZSPAN_TEST_MCP2210_MODEL_H
#define ZSPAN_TEST_MCP2210_MODEL_H

#include <stdint.h>

#include "emu.h"

typedef struct mcp_model {
    emu_panel *emu;
    /* wiring: which GP pin goes to which panel pin (-1 none) */
    int cs_pin, dc_pin, reset_pin, bl_pin;
    /* chip state */
    uint8_t designation[9];
    uint16_t gpio_value;       /* output latches */
    uint16_t gpio_dir;         /* 1 = input */
    uint32_t bit_rate;
    uint16_t idle_cs, active_cs, delay_cs_data, delay_data_cs, delay_bytes, txn_len;
    uint8_t spi_mode;
    int settings_seen;
    /* transaction */
    int in_txn;                /* bytes of a transaction still expected */
    uint32_t txn_done;
    unsigned finishing;        /* empty transfers still to answer 0xF8 */
    int reset_level;
    /* faults */
    unsigned lag;              /* busy answers to the polls after a transaction's last bytes */
    unsigned busy_every;       /* every N-th data report is refused (0 = never) */
    unsigned busy_burst;       /* ... this many times in a row (default 1) */
    unsigned busy_left;
    long disconnect_after;     /* the N-th data report gets no answer (0 = never) */
    int bus_na;                /* answer 0xF7 to data reports */
    /* counters */
    uint64_t data_reports;     /* 0x42 reports with data (attempts, refused ones too) */
    uint64_t busy_sent;        /* 0xF8 answers to data reports */
    uint64_t poll_busy_sent;   /* 0xF8 answers to end-of-transfer polls */
    uint64_t reports;
    uint64_t transactions;
    uint64_t bytes_to_panel;
    uint64_t gpio_writes, settings_writes;
    unsigned errors;
    char first_error[200];
    /* time: microseconds of the host clock already handed to the panel */
    uint64_t t0_us, delivered_ms;
    int gone;
} mcp_model;

/* Sets the model up with the panel and the wiring (power-on state: every pin
 * GPIO input, SPI settings 1 byte per transaction). */
void mcp_model_init(mcp_model *m, emu_panel *emu, int cs_pin, int dc_pin, int reset_pin,
                    int bl_pin);

/* One 64-byte command report in, its 64-byte answer out. Returns 1, or 0 when
 * the model disconnects instead of answering (disconnect_after). */
int mcp_model_handle(mcp_model *m, const uint8_t *req, uint8_t *resp);

#endif
