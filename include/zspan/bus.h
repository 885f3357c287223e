/* SPDX-License-Identifier: MIT */
/*
 * zspan bus interface: how a panel driver talks to a display controller.
 *
 * Freestanding C99, no allocation. A bus is a small struct holding a table of
 * functions that the port (MCU HAL, Linux spidev, the host simulator, a test)
 * provides, and the counters the panel driver and the frame streamer read.
 *
 * Two kinds of writes, as on every 4-wire SPI display (D/C pin + SPI):
 *
 *  - Commands: one command byte with D/C low, then its parameter bytes with
 *    D/C high. Always blocking: the function returns when the bytes are out.
 *  - Pixel data: bytes with D/C high after a memory-write command. These may
 *    complete asynchronously (DMA): the port's `pixels` function starts the
 *    transfer and returns; when the hardware is done the port (typically its
 *    DMA-complete interrupt) calls zs_bus_pixels_done(). Until then the bus
 *    owns the buffer and nobody may write to it.
 *
 * A port whose pixel writes block simply leaves ZS_BUS_ASYNC out of the flags;
 * it must then not call zs_bus_pixels_done() (it may, harmlessly, if the
 * transfer is already finished when `pixels` returns: see below).
 *
 * At most one pixel transfer is in flight per bus. zs_bus_cmd() and
 * zs_bus_pixels() first wait until the bus is idle, calling the port's `poll`
 * hook (if any) while they wait, so a command never overtakes pixel data and a
 * D/C change never happens inside a transfer.
 *
 * Ordering rule for async ports: zs_bus_pixels() marks the bus busy *before*
 * calling the port's `pixels`, so a completion that arrives immediately (even
 * from inside `pixels`) is never lost.
 *
 * Failures: a port function that returns non-zero, a transfer the port ends
 * with zs_bus_pixels_failed(), and a completion that does not come within the
 * wait limit (zs_bus_set_wait_limit; none by default) each give a status
 * (zs_bus_status, named by zs_bus_strerror) instead of a wrong picture or a
 * hang.
 */
#ifndef ZSPAN_BUS_H
#define ZSPAN_BUS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Functions a port provides. `user` is zs_bus.user. Return 0 on success,
 * non-zero on a bus failure (the call then reports ZS_BUS_ERR_IO). */
typedef struct zs_bus_ops {
    /* Required. Send `cmd` with D/C low, then n parameter bytes with D/C high
     * (n may be 0, params may then be NULL). Blocking. */
    int (*command)(void *user, uint8_t cmd, const uint8_t *params, size_t n);
    /* Required. Send n pixel bytes with D/C high. Blocking ports return when
     * done; async ports start the transfer and later call
     * zs_bus_pixels_done() (or zs_bus_pixels_failed()). `data` stays valid
     * and unmodified until then. */
    int (*pixels)(void *user, const uint8_t *data, size_t n);
    /* Optional. Drive the reset line: level 0 = asserted (low), 1 = released. */
    void (*reset)(void *user, int level);
    /* Optional. Backlight level 0 (off) .. 255 (full). */
    void (*backlight)(void *user, uint8_t level);
    /* Optional. Wait at least ms milliseconds. Without it delays are skipped
     * (the panel may then misbehave: provide it on real hardware). */
    void (*delay_ms)(void *user, uint32_t ms);
    /* Optional. Called repeatedly while waiting for an async transfer to end
     * (service an event loop, sleep until interrupt, ...). Without it the wait
     * spins on the bus's busy flag. */
    void (*poll)(void *user);
} zs_bus_ops;

/* zs_bus.flags */
#define ZS_BUS_ASYNC 0x01u   /* pixel writes complete via zs_bus_pixels_done() */

/* Counters since zs_bus_init() or zs_bus_counters_reset(). Bytes are bytes on
 * the wire: a command counts 1 byte plus its parameters. */
typedef struct zs_bus_counters {
    uint32_t commands;        /* command bytes sent (D/C low) */
    uint32_t param_bytes;     /* parameter bytes sent after commands */
    uint32_t pixel_bytes;     /* pixel data bytes */
    uint32_t transfers;       /* pixel transfers started (after chunking) */
    uint32_t waits;           /* times a caller had to wait for the bus */
    uint32_t delay_ms;        /* total milliseconds of requested delays */
} zs_bus_counters;

/* A free-running millisecond counter of the port (it may wrap). */
typedef uint32_t (*zs_bus_clock_fn)(void *user);

typedef struct zs_bus {
    const zs_bus_ops *ops;
    void *user;
    uint32_t flags;
    /* Largest pixel transfer the port accepts (e.g. 4096 for Linux spidev's
     * default bufsiz); 0 = no limit. Longer writes are split. */
    uint32_t max_transfer;
    /* How long zs_bus_wait waits for a transfer (see zs_bus_set_wait_limit);
     * 0 = for ever (the default). */
    uint32_t wait_limit;
    zs_bus_clock_fn wait_clock;   /* the limit's clock; NULL: the limit counts polls */
    volatile uint8_t busy;    /* 1 while an async pixel transfer is in flight */
    volatile uint8_t fault;   /* an async transfer failed, not reported yet */
    uint8_t timed_out;        /* the transfer in flight was given up on */
    uint8_t error;            /* sticky: 1 after any failure (port, fault, timeout) */
    zs_bus_counters count;
} zs_bus;

/* Bus results (the panel driver maps them to its own). zs_bus_strerror()
 * gives each code's comment below as text. */
typedef enum zs_bus_status {
    ZS_BUS_OK = 0,
    ZS_BUS_ERR_NULL,      /* NULL bus, ops, or required op missing */
    ZS_BUS_ERR_IO,        /* the port reported a failure */
    ZS_BUS_ERR_ARGUMENT,  /* bad argument (e.g. data NULL with n > 0) */
    ZS_BUS_ERR_TIMEOUT,   /* a pixel transfer did not complete within the wait limit */
    ZS_BUS_STATUS_COUNT   /* number of codes, not a status */
} zs_bus_status;

/* Text of a status: "ok", each code's comment above, or "unknown bus status"
 * for a value outside the enum. Never NULL. */
const char *zs_bus_strerror(zs_bus_status s);

/* Sets up a bus. max_transfer 0 = unlimited. No wait limit (see below). */
zs_bus_status zs_bus_init(zs_bus *bus, const zs_bus_ops *ops, void *user, uint32_t flags,
                          uint32_t max_transfer);

/* Bounds every wait for an async transfer, so a completion that never comes
 * (DMA stalled, interrupt not wired) gives ZS_BUS_ERR_TIMEOUT instead of a
 * hang. With a clock (called with bus->user) the wait gives up once more than
 * `limit` milliseconds have passed; without one (NULL) the bus has no time
 * of its own, so `limit` counts rounds of the wait loop instead (one poll
 * call each: useful when poll sleeps until the next interrupt or tick).
 * limit 0 = wait for ever (the default after zs_bus_init). A timed-out
 * transfer still owns its buffer: the bus stays busy, and every later wait
 * (so every command and pixel write) fails at once with ZS_BUS_ERR_TIMEOUT
 * until the port ends it (zs_bus_pixels_done/_failed, e.g. after aborting
 * the DMA) or zs_bus_init starts over. */
void zs_bus_set_wait_limit(zs_bus *bus, uint32_t limit, zs_bus_clock_fn clock);

/* Blocking command + parameters. Waits for the bus to be idle first and
 * returns that wait's failure (nothing sent) if it fails. */
zs_bus_status zs_bus_cmd(zs_bus *bus, uint8_t cmd, const uint8_t *params, size_t n);

/* Pixel bytes. Waits until the bus is idle, then starts the transfer (split
 * into max_transfer pieces; each piece waits for the previous one). Returns
 * when the last piece has been started: with an async port the caller must
 * not touch `data` until zs_bus_idle() is true (or zs_bus_wait() returned
 * ZS_BUS_OK). A failed wait stops it (the rest is not sent). */
zs_bus_status zs_bus_pixels(zs_bus *bus, const uint8_t *data, size_t n);

/* Called by an async port when the transfer it was given has finished. Safe
 * from an interrupt handler (it only clears the busy flag). */
void zs_bus_pixels_done(zs_bus *bus);
/* Called by an async port instead of zs_bus_pixels_done() when the transfer
 * failed (DMA error, bus fault): the bus becomes idle and the next wait (so
 * the next command, pixel write or zs_bus_wait) reports ZS_BUS_ERR_IO once.
 * Safe from an interrupt handler. */
void zs_bus_pixels_failed(zs_bus *bus);

/* 1 if no pixel transfer is in flight. */
int zs_bus_idle(const zs_bus *bus);
/* Waits (polling) until no pixel transfer is in flight. ZS_BUS_OK when the
 * bus is idle and the last transfer went well; ZS_BUS_ERR_IO once after a
 * zs_bus_pixels_failed(); ZS_BUS_ERR_TIMEOUT past the wait limit (the bus
 * then still owns the buffer in flight); ZS_BUS_ERR_NULL for a NULL bus. */
zs_bus_status zs_bus_wait(zs_bus *bus);

/* Reset pulse: reset low for 10 ms, high, then 120 ms (the longest reset
 * recovery among the supported controllers). Without a reset hook only the
 * delay runs (the driver then relies on a software reset). It first waits
 * for the bus like a command and does nothing if that wait fails. */
void zs_bus_hw_reset(zs_bus *bus);
void zs_bus_backlight(zs_bus *bus, uint8_t level);
void zs_bus_delay(zs_bus *bus, uint32_t ms);

void zs_bus_counters_reset(zs_bus *bus);

/* Time the wire needs for some traffic, in nanoseconds:
 *   bytes * 8 / clock_hz  +  commands * cmd_overhead_ns
 *                         +  transfers * transfer_overhead_ns
 * The overheads model what a real port spends around each command (D/C and
 * CS toggling, a blocking round trip) and around each DMA transfer (setup,
 * interrupt). ZS_WIRE_CMD_OVERHEAD_NS / ZS_WIRE_XFER_OVERHEAD_NS are typical
 * MCU figures; pass your own measured ones if you have them. */
#define ZS_WIRE_CMD_OVERHEAD_NS 2000u
#define ZS_WIRE_XFER_OVERHEAD_NS 1000u

typedef struct zs_wire_model {
    uint32_t clock_hz;               /* SPI clock, > 0 */
    uint32_t cmd_overhead_ns;        /* per command */
    uint32_t transfer_overhead_ns;   /* per pixel transfer */
} zs_wire_model;

/* A model with the given clock and the default overheads. */
zs_wire_model zs_wire_model_default(uint32_t clock_hz);

/* Wire time of the traffic in `c` (total bytes = commands + param_bytes +
 * pixel_bytes). 0 if clock_hz is 0. */
uint64_t zs_wire_time_ns(const zs_bus_counters *c, const zs_wire_model *m);

/* c = a - b, field by field (for per-frame figures). */
zs_bus_counters zs_bus_counters_diff(const zs_bus_counters *a, const zs_bus_counters *b);
/* Total bytes on the wire: commands + param_bytes + pixel_bytes. */
uint32_t zs_bus_counters_bytes(const zs_bus_counters *c);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_BUS_H */
