/* SPDX-License-Identifier: MIT */
/* zspan bus: command/pixel split, async completion, counters, wire time. */
#include "zspan/bus.h"

const char *zs_bus_strerror(zs_bus_status s)
{
    /* The texts are the header's comments (tests/panel/test_panel_contract.c
     * reads bus.h and compares). */
    switch (s) {
    case ZS_BUS_OK: return "ok";
    case ZS_BUS_ERR_NULL: return "NULL bus, ops, or required op missing";
    case ZS_BUS_ERR_IO: return "the port reported a failure";
    case ZS_BUS_ERR_ARGUMENT: return "bad argument (e.g. data NULL with n > 0)";
    case ZS_BUS_ERR_TIMEOUT: return "a pixel transfer did not complete within the wait limit";
    case ZS_BUS_STATUS_COUNT: break;
    }
    return "unknown bus status";
}

zs_bus_status zs_bus_init(zs_bus *bus, const zs_bus_ops *ops, void *user, uint32_t flags,
                          uint32_t max_transfer)
{
    if (bus == NULL || ops == NULL || ops->command == NULL || ops->pixels == NULL)
        return ZS_BUS_ERR_NULL;
    bus->ops = ops;
    bus->user = user;
    bus->flags = flags;
    bus->max_transfer = max_transfer;
    bus->wait_limit = 0;
    bus->wait_clock = NULL;
    bus->busy = 0;
    bus->fault = 0;
    bus->timed_out = 0;
    bus->error = 0;
    zs_bus_counters_reset(bus);
    return ZS_BUS_OK;
}

void zs_bus_set_wait_limit(zs_bus *bus, uint32_t limit, zs_bus_clock_fn clock)
{
    if (bus == NULL)
        return;
    bus->wait_limit = limit;
    bus->wait_clock = clock;
}

void zs_bus_counters_reset(zs_bus *bus)
{
    if (bus == NULL)
        return;
    bus->count.commands = 0;
    bus->count.param_bytes = 0;
    bus->count.pixel_bytes = 0;
    bus->count.transfers = 0;
    bus->count.waits = 0;
    bus->count.delay_ms = 0;
}

int zs_bus_idle(const zs_bus *bus)
{
    return bus == NULL || bus->busy == 0;
}

zs_bus_status zs_bus_wait(zs_bus *bus)
{
    uint32_t start = 0, rounds = 0;

    if (bus == NULL || bus->ops == NULL)
        return ZS_BUS_ERR_NULL;
    if (bus->busy != 0) {
        /* A transfer already given up on is not waited for again: one lost
         * completion costs one wait limit, not one per later call. (Only
         * this side writes timed_out; the port's interrupt touches busy and
         * fault alone.) */
        if (bus->timed_out != 0)
            return ZS_BUS_ERR_TIMEOUT;
        bus->count.waits++;
        if (bus->wait_limit != 0 && bus->wait_clock != NULL)
            start = bus->wait_clock(bus->user);
        while (bus->busy != 0) {
            if (bus->ops->poll != NULL)
                bus->ops->poll(bus->user);
            if (bus->wait_limit == 0 || bus->busy == 0)
                continue;
            /* Clock: more than `limit` ms on a whole-ms counter means at least
             * `limit` ms really passed. Unsigned difference: wrap-safe. */
            if (bus->wait_clock != NULL
                    ? bus->wait_clock(bus->user) - start > bus->wait_limit
                    : ++rounds >= bus->wait_limit) {
                bus->timed_out = 1;
                bus->error = 1;
                return ZS_BUS_ERR_TIMEOUT;
            }
        }
    }
    if (bus->fault != 0) {
        bus->fault = 0;
        return ZS_BUS_ERR_IO;
    }
    return ZS_BUS_OK;
}

void zs_bus_pixels_done(zs_bus *bus)
{
    if (bus != NULL)
        bus->busy = 0;
}

void zs_bus_pixels_failed(zs_bus *bus)
{
    if (bus != NULL) {
        /* fault before busy: a waiter that sees the bus idle sees the fault */
        bus->fault = 1;
        bus->error = 1;
        bus->busy = 0;
    }
}

zs_bus_status zs_bus_cmd(zs_bus *bus, uint8_t cmd, const uint8_t *params, size_t n)
{
    zs_bus_status s;
    if (bus == NULL || bus->ops == NULL)
        return ZS_BUS_ERR_NULL;
    if (params == NULL && n > 0)
        return ZS_BUS_ERR_ARGUMENT;
    if ((s = zs_bus_wait(bus)) != ZS_BUS_OK)
        return s;
    bus->count.commands++;
    bus->count.param_bytes += (uint32_t)n;
    if (bus->ops->command(bus->user, cmd, params, n) != 0) {
        bus->error = 1;
        return ZS_BUS_ERR_IO;
    }
    return ZS_BUS_OK;
}

zs_bus_status zs_bus_pixels(zs_bus *bus, const uint8_t *data, size_t n)
{
    zs_bus_status s;
    if (bus == NULL || bus->ops == NULL)
        return ZS_BUS_ERR_NULL;
    if (data == NULL && n > 0)
        return ZS_BUS_ERR_ARGUMENT;
    while (n > 0) {
        size_t piece = n;
        if (bus->max_transfer != 0 && piece > bus->max_transfer)
            piece = bus->max_transfer;
        if ((s = zs_bus_wait(bus)) != ZS_BUS_OK)
            return s;
        bus->count.transfers++;
        bus->count.pixel_bytes += (uint32_t)piece;
        bus->timed_out = 0; /* a new transfer gets its own wait limit */
        /* Busy before the call: a completion from inside `pixels` (or an
         * interrupt right after the DMA start) must find the flag set. */
        if ((bus->flags & ZS_BUS_ASYNC) != 0)
            bus->busy = 1;
        if (bus->ops->pixels(bus->user, data, piece) != 0) {
            bus->busy = 0;
            bus->error = 1;
            return ZS_BUS_ERR_IO;
        }
        data += piece;
        n -= piece;
    }
    return ZS_BUS_OK;
}

void zs_bus_delay(zs_bus *bus, uint32_t ms)
{
    if (bus == NULL || bus->ops == NULL)
        return;
    bus->count.delay_ms += ms;
    if (bus->ops->delay_ms != NULL && ms > 0)
        bus->ops->delay_ms(bus->user, ms);
}

void zs_bus_hw_reset(zs_bus *bus)
{
    if (bus == NULL || bus->ops == NULL || zs_bus_wait(bus) != ZS_BUS_OK)
        return;
    if (bus->ops->reset != NULL) {
        bus->ops->reset(bus->user, 1);
        zs_bus_delay(bus, 1);
        bus->ops->reset(bus->user, 0);
        zs_bus_delay(bus, 10);
        bus->ops->reset(bus->user, 1);
    }
    zs_bus_delay(bus, 120);
}

void zs_bus_backlight(zs_bus *bus, uint8_t level)
{
    if (bus != NULL && bus->ops != NULL && bus->ops->backlight != NULL)
        bus->ops->backlight(bus->user, level);
}

zs_wire_model zs_wire_model_default(uint32_t clock_hz)
{
    zs_wire_model m;
    m.clock_hz = clock_hz;
    m.cmd_overhead_ns = ZS_WIRE_CMD_OVERHEAD_NS;
    m.transfer_overhead_ns = ZS_WIRE_XFER_OVERHEAD_NS;
    return m;
}

uint32_t zs_bus_counters_bytes(const zs_bus_counters *c)
{
    if (c == NULL)
        return 0;
    return c->commands + c->param_bytes + c->pixel_bytes;
}

uint64_t zs_wire_time_ns(const zs_bus_counters *c, const zs_wire_model *m)
{
    uint64_t bits, ns;
    if (c == NULL || m == NULL || m->clock_hz == 0)
        return 0;
    bits = (uint64_t)zs_bus_counters_bytes(c) * 8u;
    /* bits * 1e9 / clock without overflow for any 32-bit byte count. */
    ns = (bits / m->clock_hz) * 1000000000u +
         ((bits % m->clock_hz) * 1000000000u + m->clock_hz / 2u) / m->clock_hz;
    ns += (uint64_t)c->commands * m->cmd_overhead_ns;
    ns += (uint64_t)c->transfers * m->transfer_overhead_ns;
    return ns;
}

zs_bus_counters zs_bus_counters_diff(const zs_bus_counters *a, const zs_bus_counters *b)
{
    zs_bus_counters d;
    d.commands = a->commands - b->commands;
    d.param_bytes = a->param_bytes - b->param_bytes;
    d.pixel_bytes = a->pixel_bytes - b->pixel_bytes;
    d.transfers = a->transfers - b->transfers;
    d.waits = a->waits - b->waits;
    d.delay_ms = a->delay_ms - b->delay_ms;
    return d;
}
