/* SPDX-License-Identifier: MIT */
/* zspan bus port feeding an emulated panel, blocking or asynchronous. */
#include "emu_bus.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#if defined(__SANITIZE_ADDRESS__)
#define EMU_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EMU_ASAN 1
#endif
#endif
#ifdef EMU_ASAN
#include <sanitizer/asan_interface.h>
#define POISON(p, n) ASAN_POISON_MEMORY_REGION((p), (n))
#define UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION((p), (n))
#else
#define POISON(p, n) ((void)(p), (void)(n))
#define UNPOISON(p, n) ((void)(p), (void)(n))
#endif

static uint64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static uint64_t checksum(const uint8_t *d, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= d[i];
        h *= 1099511628211ull;
    }
    return h;
}

static void violate(emu_port *p, const char *what)
{
    if (p->violations == 0)
        snprintf(p->violation, sizeof p->violation, "%s", what);
    p->violations++;
}

static void complete(emu_port *p)
{
    const uint8_t *d = p->inflight;
    size_t n = p->inflight_n;
    if (d == NULL)
        return;
    if (!p->no_poison)
        UNPOISON(d, n);
    if (checksum(d, n) != p->inflight_sum)
        violate(p, "a buffer owned by the bus was modified before the transfer completed");
    {
        uint64_t t0 = now_ns();
        emu_data(p->emu, d, n);
        p->ns_in_port += now_ns() - t0;
    }
    p->inflight = NULL;
    p->inflight_n = 0;
    p->completions++;
    zs_bus_pixels_done(&p->bus);
}

static int op_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    emu_port *p = user;
    uint64_t t0 = now_ns();
    if (p->inflight != NULL)
        violate(p, "command while a pixel transfer was in flight");
    emu_command(p->emu, cmd);
    if (n > 0)
        emu_data(p->emu, params, n);
    p->ns_in_port += now_ns() - t0;
    return 0;
}

static int op_pixels(void *user, const uint8_t *data, size_t n)
{
    emu_port *p = user;
    if (!p->async) {
        uint64_t t0 = now_ns();
        emu_data(p->emu, data, n);
        p->ns_in_port += now_ns() - t0;
        return 0;
    }
    if (p->inflight != NULL) {
        violate(p, "pixel transfer started while another was in flight");
        complete(p);
    }
    if (!p->bus.busy)
        violate(p, "async transfer started without the bus marked busy");
    p->inflight = data;
    p->inflight_n = n;
    p->inflight_sum = checksum(data, n);
    p->polls_left = p->latency;
    if (p->jitter_seed != 0) {
        p->jitter_seed ^= p->jitter_seed << 13;
        p->jitter_seed ^= p->jitter_seed >> 17;
        p->jitter_seed ^= p->jitter_seed << 5;
        p->polls_left = p->latency ? p->jitter_seed % (p->latency + 1u) : 0;
    }
    if (p->polls_left == 0) {
        complete(p); /* done at once: from "inside the interrupt" */
        return 0;
    }
    if (!p->no_poison)
        POISON(data, n);
    return 0;
}

static void op_poll(void *user)
{
    emu_port *p = user;
    p->polls++;
    if (p->inflight == NULL)
        return;
    if (p->polls_left > 0)
        p->polls_left--;
    if (p->polls_left == 0)
        complete(p);
}

static void op_reset(void *user, int level)
{
    emu_port *p = user;
    emu_reset_line(p->emu, level);
}

static void op_backlight(void *user, uint8_t level)
{
    emu_port *p = user;
    p->backlight = level;
    p->emu->backlight = level;
}

static void op_delay(void *user, uint32_t ms)
{
    emu_port *p = user;
    emu_delay_ms(p->emu, ms);
}

static const zs_bus_ops emu_ops = {op_command, op_pixels, op_reset, op_backlight, op_delay,
                                   op_poll};

int emu_port_init(emu_port *p, emu_panel *emu, int async, unsigned latency,
                  uint32_t max_transfer)
{
    memset(p, 0, sizeof *p);
    p->emu = emu;
    p->async = async;
    p->latency = latency;
    return zs_bus_init(&p->bus, &emu_ops, p, async ? ZS_BUS_ASYNC : 0u, max_transfer) == ZS_BUS_OK
               ? 0
               : -1;
}

void emu_port_drain(emu_port *p)
{
    complete(p);
}
