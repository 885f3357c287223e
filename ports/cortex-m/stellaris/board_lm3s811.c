/* SPDX-License-Identifier: MIT */
/* Stellaris LM3S811 (Cortex-M3, 64 KB flash, 8 KB SRAM; QEMU lm3s811evb)
 * at 50 MHz from the PLL (lm3s_clock_init): SysTick at 20 ns. */
#include "port.h"

const port_board port_this_board = {"lm3s811", "cortex-m3", 50000000u, 20000u};
