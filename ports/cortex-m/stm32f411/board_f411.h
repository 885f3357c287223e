/* SPDX-License-Identifier: MIT */
/*
 * The STM32F411 board interface: what an application on this board needs
 * from the port. Freestanding C99.
 */
#ifndef ZSPAN_BOARD_F411_H
#define ZSPAN_BOARD_F411_H

#include "zspan/bus.h"

/* Sets the clocks (84 MHz), SPI1 (42 MHz, mode 3) with DMA2 stream 3 and the
 * panel's CS, D/C, reset and backlight lines (board_f411.c has the wiring).
 * Returns the panel's bus (asynchronous pixel writes), or NULL. */
zs_bus *port_f411_bus(void);

#endif /* ZSPAN_BOARD_F411_H */
