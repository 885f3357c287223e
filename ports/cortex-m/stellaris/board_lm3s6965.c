/* SPDX-License-Identifier: MIT */
/* Stellaris LM3S6965 (Cortex-M3, 256 KB flash, 64 KB SRAM; QEMU lm3s6965evb)
 * at 50 MHz from the PLL (lm3s_clock_init): SysTick at 20 ns. */
#include "port.h"

const port_board port_this_board = {"lm3s6965", "cortex-m3", 50000000u, 20000u};
