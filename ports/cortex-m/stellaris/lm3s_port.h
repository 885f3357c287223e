/* SPDX-License-Identifier: MIT */
/*
 * zspan board port for the Stellaris LM3S6965 and LM3S811 (Cortex-M3;
 * issue 20): clocks, GPIO, the SSI0 (PL022) as a polled 4-wire SPI bus for
 * the SSD0323 OLED (chip select port D pin 0, data/command port C pin 7),
 * and the I2C0 master as a bus for the SSD0303 OLED, both behind zspan's
 * bus interface (zspan/bus.h). Every wait on the hardware has a limit: a
 * dead peripheral, a bus fault or a device that does not answer is an error
 * code (lm3s_port.error, and a failed bus call), never a hang.
 *
 * Freestanding C99.
 */
#ifndef ZSPAN_LM3S_PORT_H
#define ZSPAN_LM3S_PORT_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

/* What went wrong on the wire (lm3s_port.error, the first failure kept). */
typedef enum lm3s_error {
    LM3S_OK = 0,
    LM3S_ERR_SSI_TIMEOUT,   /* the SSI never drained its FIFO or stayed busy */
    LM3S_ERR_I2C_NO_DEVICE, /* nobody acknowledged the address (NACK) */
    LM3S_ERR_I2C_DATA_NACK, /* the device did not acknowledge a data byte */
    LM3S_ERR_I2C_ARBITRATION, /* another master took the bus */
    LM3S_ERR_I2C_TIMEOUT,   /* the controller stayed busy past the limit */
    LM3S_ERR_TOO_LONG       /* a command with more parameters than a frame holds */
} lm3s_error;

const char *lm3s_strerror(lm3s_error e);

/* The system clock from the PLL: 200 MHz / 4 = 50 MHz (xtal_code: the RCC
 * XTAL field of the board's crystal, 0xE for 8 MHz, 0xB for 6 MHz). Returns
 * the clock in Hz. */
uint32_t lm3s_clock_init(uint32_t xtal_code);

typedef struct lm3s_port {
    zs_bus bus;
    uint8_t i2c_addr;         /* 7-bit address of the I2C display */
    lm3s_error error;         /* first failure, LM3S_OK if none */
    uint32_t wait_limit;      /* polls before a wait gives up */
    /* FNV-1a 32 of the wire (from 0x811C9DC5): SPI over (D/C, byte) per
     * byte; I2C over (address << 1, bytes) per transaction */
    uint32_t stream;
    uint32_t transactions;    /* I2C transactions (or SPI bus calls) */
} lm3s_port;

/* SSI0 at sys_hz / spi_div (even, 2..254 x 1..256) for the SSD0323, its
 * pins and the two GPIO lines; sets up p->bus (blocking). 0 or -1. */
int lm3s_ssi_oled_init(lm3s_port *p, uint32_t sys_hz, uint32_t spi_hz);
/* I2C0 master at 100 kHz (sys_hz: the system clock) talking to addr; sets
 * up p->bus: a command byte and each parameter as 0x80 + byte (Co = 1),
 * pixel data as 0x40 + bytes, at most max_frame data bytes a transaction. */
int lm3s_i2c_oled_init(lm3s_port *p, uint32_t sys_hz, uint8_t addr);

#endif
