/* SPDX-License-Identifier: MIT */
/* Generic SPI + DMA bus port; see spi_dma_port.h. Freestanding C99. */
#include "spi_dma_port.h"

static int port_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    spi_dma_port *p = user;
    const spi_dma_hw *hw = p->hw;
    hw->cs(1);
    hw->dc(0);
    hw->spi_write(&cmd, 1);
    hw->dc(1);
    if (n)
        hw->spi_write(params, n);
    hw->cs(0);
    return 0;
}

static int port_pixels(void *user, const uint8_t *data, size_t n)
{
    spi_dma_port *p = user;
    const spi_dma_hw *hw = p->hw;
    if (n == 0) {
        zs_bus_pixels_done(p->bus);
        return 0;
    }
    hw->cs(1);
    hw->dc(1);
    p->in_flight = 1;
    hw->dma_start(data, n);
    return 0;
}

static void port_reset(void *user, int level)
{
    spi_dma_port *p = user;
    if (p->hw->reset)
        p->hw->reset(level);
}

static void port_backlight(void *user, uint8_t level)
{
    spi_dma_port *p = user;
    if (p->hw->backlight)
        p->hw->backlight(level);
}

static void port_delay(void *user, uint32_t ms)
{
    spi_dma_port *p = user;
    if (p->hw->delay_ms)
        p->hw->delay_ms(ms);
}

static void port_poll(void *user)
{
    spi_dma_port *p = user;
    if (p->hw->idle)
        p->hw->idle();
}

const zs_bus_ops spi_dma_bus_ops = {
    port_command, port_pixels, port_reset, port_backlight, port_delay, port_poll,
};

zs_bus_status spi_dma_port_init(spi_dma_port *port, const spi_dma_hw *hw, zs_bus *bus)
{
    if (!port || !hw || !bus || !hw->cs || !hw->dc || !hw->spi_write || !hw->dma_start ||
        !hw->spi_drain)
        return ZS_BUS_ERR_NULL;
    port->hw = hw;
    port->bus = bus;
    port->in_flight = 0;
    return zs_bus_init(bus, &spi_dma_bus_ops, port, ZS_BUS_ASYNC, hw->max_dma);
}

void spi_dma_port_irq(spi_dma_port *port)
{
    if (!port->in_flight)
        return;
    /* DMA-complete means the last byte reached the SPI data register, not the
     * wire: wait for the shifter before releasing CS. */
    port->hw->spi_drain();
    port->hw->cs(0);
    port->in_flight = 0;
    zs_bus_pixels_done(port->bus);
}
