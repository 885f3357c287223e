/* SPDX-License-Identifier: MIT */
/* QEMU microbit: nRF51822, Cortex-M0 at 16 MHz (SysTick at 62.5 ns), 16 KB RAM. */
#include "port.h"

const port_board port_this_board = {"microbit", "cortex-m0", 16000000u, 62500u};
