/* SPDX-License-Identifier: MIT */
/* QEMU mps2-an386: Cortex-M4, 25 MHz system clock (SysTick at 40 ns).
 * PORT_BOARD_NAME / PORT_CPU_NAME let the benchmark tag a build of Cortex-M0
 * code run on this machine (same instructions, more RAM). */
#include "port.h"

#ifndef PORT_BOARD_NAME
#define PORT_BOARD_NAME "mps2-an386"
#endif
#ifndef PORT_CPU_NAME
#define PORT_CPU_NAME "cortex-m4"
#endif

const port_board port_this_board = {PORT_BOARD_NAME, PORT_CPU_NAME, 25000000u, 40000u};
