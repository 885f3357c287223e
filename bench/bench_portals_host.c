/* SPDX-License-Identifier: MIT */
/*
 * Host build of bench/bench_portals_fw.c: the same program on a stand-in for
 * ports/cortex-m/port.h (stdout for semihosting, no timer), so that
 * check-portals-m4 can compare the M4's frame checksums with the host's.
 * BENCH_ARGS in the environment plays the part of the semihosting command
 * line. Instruction counts print as 0 here.
 */
#include "port.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const port_board port_this_board = {"host", "host", 1000000000u, 1000u};

static uint8_t g_ram[1u << 20];

uint8_t *port_free_ram(size_t *bytes)
{
    *bytes = sizeof g_ram;
    return g_ram;
}
size_t port_stack_high_water(void)
{
    return 0;
}
size_t port_stack_size(void)
{
    return 0;
}
size_t port_static_ram(void)
{
    return 0;
}
void sh_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}
int sh_get_cmdline(char *buf, size_t size)
{
    const char *a = getenv("BENCH_ARGS");
    if (!a || strlen(a) + 1 > size)
        return -1;
    memcpy(buf, a, strlen(a) + 1);
    return 0;
}
void port_timer_start(void)
{
}
uint64_t port_ticks(void)
{
    return 0;
}
uint32_t port_calibrate_ipt_milli(void)
{
    return 0;
}
