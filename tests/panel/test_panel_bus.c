/* SPDX-License-Identifier: MIT */
/* The bus layer on its own: counters, chunking, the async ownership rules,
 * reset/backlight/delay hooks and the wire-time formula. */
#include "ptest.h"

typedef struct fake {
    zs_bus *bus;
    int async, complete_inside;
    unsigned cmds, pixel_calls, resets[8], nresets, delays, bl;
    size_t sizes[16];
    int busy_seen_at_cmd, not_busy_at_pixels;
    unsigned polls, complete_after;
} fake;

static int f_cmd(void *u, uint8_t c, const uint8_t *p, size_t n)
{
    fake *f = u;
    (void)c;
    (void)p;
    (void)n;
    if (f->bus->busy)
        f->busy_seen_at_cmd = 1;
    f->cmds++;
    return c == 0xEE ? -1 : 0; /* 0xEE: an I/O failure */
}

static int f_pixels(void *u, const uint8_t *d, size_t n)
{
    fake *f = u;
    (void)d;
    if (f->pixel_calls < 16)
        f->sizes[f->pixel_calls] = n;
    f->pixel_calls++;
    if (f->async && !f->bus->busy)
        f->not_busy_at_pixels = 1;
    if (f->async && f->complete_inside)
        zs_bus_pixels_done(f->bus);
    return 0;
}

static void f_poll(void *u)
{
    fake *f = u;
    if (++f->polls >= f->complete_after) {
        f->polls = 0;
        zs_bus_pixels_done(f->bus);
    }
}

static void f_reset(void *u, int level)
{
    fake *f = u;
    if (f->nresets < 8)
        f->resets[f->nresets++] = (unsigned)level;
}

static void f_delay(void *u, uint32_t ms)
{
    fake *f = u;
    f->delays += ms;
}

static void f_bl(void *u, uint8_t level)
{
    fake *f = u;
    f->bl = level;
}

static const zs_bus_ops ops = {f_cmd, f_pixels, f_reset, f_bl, f_delay, f_poll};

static void test_counters_and_chunking(void **state)
{
    zs_bus bus;
    fake f;
    static uint8_t data[10000];
    uint8_t p[4] = {1, 2, 3, 4};
    (void)state;
    memset(&f, 0, sizeof f);
    f.bus = &bus;
    assert_int_equal(zs_bus_init(&bus, &ops, &f, 0, 4096), ZS_BUS_OK);
    assert_int_equal(zs_bus_cmd(&bus, 0x2A, p, 4), ZS_BUS_OK);
    assert_int_equal(zs_bus_cmd(&bus, 0x2C, NULL, 0), ZS_BUS_OK);
    assert_int_equal(zs_bus_pixels(&bus, data, sizeof data), ZS_BUS_OK);
    assert_int_equal(f.pixel_calls, 3);
    assert_int_equal(f.sizes[0], 4096);
    assert_int_equal(f.sizes[1], 4096);
    assert_int_equal(f.sizes[2], 10000 - 8192);
    assert_int_equal(bus.count.commands, 2);
    assert_int_equal(bus.count.param_bytes, 4);
    assert_int_equal(bus.count.pixel_bytes, 10000);
    assert_int_equal(bus.count.transfers, 3);
    assert_int_equal(zs_bus_counters_bytes(&bus.count), 10006);
    assert_int_equal(zs_bus_cmd(&bus, 0xEE, NULL, 0), ZS_BUS_ERR_IO);
    assert_int_equal(bus.error, 1);
    assert_int_equal(zs_bus_cmd(&bus, 0x2A, NULL, 2), ZS_BUS_ERR_ARGUMENT);
    assert_int_equal(zs_bus_pixels(&bus, NULL, 2), ZS_BUS_ERR_ARGUMENT);
    assert_int_equal(zs_bus_init(&bus, NULL, &f, 0, 0), ZS_BUS_ERR_NULL);
}

static void test_async_waits_and_ordering(void **state)
{
    zs_bus bus;
    fake f;
    static uint8_t data[300];
    (void)state;
    memset(&f, 0, sizeof f);
    f.bus = &bus;
    f.async = 1;
    f.complete_after = 3;
    assert_int_equal(zs_bus_init(&bus, &ops, &f, ZS_BUS_ASYNC, 100), ZS_BUS_OK);
    assert_int_equal(zs_bus_pixels(&bus, data, sizeof data), ZS_BUS_OK);
    /* three pieces: each waited for the previous one; the last is in flight */
    assert_int_equal(f.pixel_calls, 3);
    assert_false(zs_bus_idle(&bus));
    assert_int_equal(bus.count.waits, 2);
    assert_int_equal(f.not_busy_at_pixels, 0);
    /* a command waits until the pixels are out */
    assert_int_equal(zs_bus_cmd(&bus, 0x00, NULL, 0), ZS_BUS_OK);
    assert_int_equal(f.busy_seen_at_cmd, 0);
    assert_true(zs_bus_idle(&bus));
    /* completion from inside the pixels call (ISR right at DMA start) */
    f.complete_inside = 1;
    assert_int_equal(zs_bus_pixels(&bus, data, 50), ZS_BUS_OK);
    assert_true(zs_bus_idle(&bus));
}

static void test_hooks(void **state)
{
    zs_bus bus;
    fake f;
    zs_bus_ops noreset = ops;
    (void)state;
    memset(&f, 0, sizeof f);
    f.bus = &bus;
    assert_int_equal(zs_bus_init(&bus, &ops, &f, 0, 0), ZS_BUS_OK);
    zs_bus_hw_reset(&bus);
    assert_int_equal(f.nresets, 3);
    assert_int_equal(f.resets[0], 1);
    assert_int_equal(f.resets[1], 0);
    assert_int_equal(f.resets[2], 1);
    assert_true(f.delays >= 130);
    zs_bus_backlight(&bus, 77);
    assert_int_equal(f.bl, 77);
    noreset.reset = NULL;
    noreset.backlight = NULL;
    noreset.delay_ms = NULL;
    assert_int_equal(zs_bus_init(&bus, &noreset, &f, 0, 0), ZS_BUS_OK);
    zs_bus_hw_reset(&bus); /* only the (skipped) delay */
    zs_bus_backlight(&bus, 1);
    assert_int_equal(f.nresets, 3);
    assert_int_equal(bus.count.delay_ms, 120);
}

static void test_wire_time(void **state)
{
    zs_bus_counters c;
    zs_wire_model m = zs_wire_model_default(62500000u);
    (void)state;
    memset(&c, 0, sizeof c);
    c.pixel_bytes = 115200; /* 240 x 240 x 2 */
    assert_int_equal(zs_wire_time_ns(&c, &m), 14745600u);
    c.commands = 3;
    c.param_bytes = 8;
    c.transfers = 240;
    assert_int_equal(zs_wire_time_ns(&c, &m), (uint64_t)(115211u * 8u) * 16u +
                                                   3u * ZS_WIRE_CMD_OVERHEAD_NS +
                                                   240u * ZS_WIRE_XFER_OVERHEAD_NS);
    m.clock_hz = 0;
    assert_int_equal(zs_wire_time_ns(&c, &m), 0);
    /* no overflow for the largest counts: 4 GB at 1 MHz */
    memset(&c, 0, sizeof c);
    c.pixel_bytes = 0xFFFFFFFFu;
    m = zs_wire_model_default(1000000u);
    m.cmd_overhead_ns = m.transfer_overhead_ns = 0;
    assert_int_equal(zs_wire_time_ns(&c, &m), (uint64_t)0xFFFFFFFFu * 8000u);
    /* rounded to nearest: 1 byte at 3 Hz is 2.666.. s */
    c.pixel_bytes = 1;
    m.clock_hz = 3;
    assert_int_equal(zs_wire_time_ns(&c, &m), 2666666667u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counters_and_chunking),
        cmocka_unit_test(test_async_waits_and_ordering),
        cmocka_unit_test(test_hooks),
        cmocka_unit_test(test_wire_time),
    };
    return cmocka_run_group_tests_name("panel_bus", tests, NULL, NULL);
}
