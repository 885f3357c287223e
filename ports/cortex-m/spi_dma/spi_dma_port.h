/* SPDX-License-Identifier: MIT */
/*
 * Generic SPI + DMA port of the zspan bus (include/zspan/bus.h) for any
 * Cortex-M with a memory-mapped SPI and a DMA channel that can feed its
 * transmit register: the CMSIS way of doing it (plain register access, one
 * DMA-complete interrupt, no vendor HAL).
 *
 * A chip provides the small `spi_dma_hw` table (GPIO lines, blocking SPI
 * writes, starting a memory-to-SPI DMA transfer, waiting for the SPI to
 * drain); this file turns it into zs_bus_ops with asynchronous pixel writes:
 *
 *   command(): CS low, D/C low, command byte, D/C high, parameters, CS high
 *              (blocking, polled SPI);
 *   pixels():  CS low, D/C high, start DMA, return at once;
 *   the DMA-complete interrupt calls spi_dma_port_irq(): wait until the SPI
 *   has shifted the last byte out, CS high, zs_bus_pixels_done().
 *
 * With zs_panel_stream() and two line buffers, the renderer fills one line
 * while DMA sends the other. See ports/cortex-m/stm32f411/ for a complete
 * board (STM32F411 SPI1 + DMA2 stream 3) and README.md (Meshes, firmware and the benchmark).
 */
#ifndef ZSPAN_SPI_DMA_PORT_H
#define ZSPAN_SPI_DMA_PORT_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

typedef struct spi_dma_hw {
    void (*cs)(int selected);                  /* chip select (active low on the wire) */
    void (*dc)(int data);                      /* D/C: 0 = command, 1 = data */
    void (*reset)(int level);                  /* optional: 0 = asserted */
    void (*backlight)(uint8_t level);          /* optional */
    void (*spi_write)(const uint8_t *p, size_t n); /* blocking, returns when drained */
    void (*dma_start)(const uint8_t *p, size_t n); /* starts memory -> SPI TX */
    void (*spi_drain)(void);                   /* waits until TX empty and not busy */
    void (*delay_ms)(uint32_t ms);             /* optional */
    void (*idle)(void);                        /* optional: called while waiting (e.g. WFI) */
    uint32_t max_dma;                          /* largest DMA transfer, bytes (0 = no limit) */
} spi_dma_hw;

typedef struct spi_dma_port {
    const spi_dma_hw *hw;
    zs_bus *bus;                  /* set by spi_dma_port_init */
    volatile uint8_t in_flight;   /* a DMA transfer is running */
} spi_dma_port;

extern const zs_bus_ops spi_dma_bus_ops;

/* Sets up `port` and the async bus on top of it. */
zs_bus_status spi_dma_port_init(spi_dma_port *port, const spi_dma_hw *hw, zs_bus *bus);

/* Call from the DMA transfer-complete interrupt (after clearing its flag). */
void spi_dma_port_irq(spi_dma_port *port);

#endif
