/* SPDX-License-Identifier: MIT */
/* Smoke test of the port: semihosting output, command line, SysTick
 * calibration, stack painting, exit status. */
#include "port.h"

int main(void)
{
    char cmd[64];
    size_t free_bytes;
    uint32_t ipt;
    uint64_t t0, t1;
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
    t0 = port_ticks();
    port_spin(500000u);
    t1 = port_ticks();
    (void)port_free_ram(&free_bytes);
    sh_printf("hello from %s (%s)\n", port_this_board.name, port_this_board.cpu);
    sh_printf("instructions per tick x1000: measured %u, nominal %u\n", (unsigned)ipt,
              (unsigned)port_this_board.nominal_ipt_milli);
    sh_printf("1000000-instruction loop: %u ticks = %u instructions\n", (unsigned)(t1 - t0),
              (unsigned)(((t1 - t0) * ipt + 500u) / 1000u));
    sh_printf("static RAM %u, free RAM %u, stack %u (used %u)\n", (unsigned)port_static_ram(),
              (unsigned)free_bytes, (unsigned)port_stack_size(),
              (unsigned)port_stack_high_water());
    if (sh_get_cmdline(cmd, sizeof cmd) == 0)
        sh_printf("cmdline: '%s'\n", cmd);
    sh_printf("%d %5d|%-5d|%05d %x %X %lld %llu\n", -42, 7, 7, -7, 0xbeefu, 0xbeefu,
              -1234567890123ll, 18446744073709551615ull);
    return 3;
}
