/* SPDX-License-Identifier: MIT */
/*
 * A zspan bus (zspan/bus.h) whose wire ends in an emulated panel.
 *
 * Blocking mode: bytes reach the emulator before the bus call returns.
 * Async mode: a pixel write only records the buffer; the bytes are read and
 * delivered to the emulator when the transfer "completes", after `latency`
 * calls of the bus's poll hook (0: completes from inside the pixels call, the
 * fastest DMA). Until then the port owns the buffer and checks that nobody
 * touches it: a checksum taken at submission must still match at completion,
 * and under AddressSanitizer the buffer is poisoned in between, so any access
 * aborts on the spot. Every breach of the bus contract is counted in
 * `violations` with the first one described in `violation`.
 */
#ifndef ZSPAN_EMU_BUS_H
#define ZSPAN_EMU_BUS_H

#include "emu.h"
#include "zspan/bus.h"

typedef struct emu_port {
    zs_bus bus;
    emu_panel *emu;
    int async;
    unsigned latency;          /* polls until an async transfer completes */
    uint32_t jitter_seed;      /* non-zero: latency varies 0..latency per transfer */
    int no_poison;             /* 1: checksum check only (tests of the checker itself) */
    /* in flight */
    const uint8_t *inflight;
    size_t inflight_n;
    uint64_t inflight_sum;
    unsigned polls_left;
    /* results */
    unsigned violations;
    char violation[160];
    uint64_t completions;
    uint64_t polls;
    uint8_t backlight;
    uint64_t ns_in_port;       /* wall time spent inside the port (emulator work) */
} emu_port;

/* Sets up the port and its bus (p->bus). max_transfer as in zs_bus_init. */
int emu_port_init(emu_port *p, emu_panel *emu, int async, unsigned latency,
                  uint32_t max_transfer);
/* Completes a transfer still in flight (end of a test or program). */
void emu_port_drain(emu_port *p);

#endif
