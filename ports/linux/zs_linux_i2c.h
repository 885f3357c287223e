/* SPDX-License-Identifier: MIT */
/*
 * zspan Linux port over I2C: a zs_bus on /dev/i2c-N (the i2c-dev driver) for
 * SSD1306 / SH1106 modules. Commands go as one I2C_RDWR write message each,
 * control byte 0x00 then the command bytes; pixel data as messages of at
 * most max_frame bytes after the control byte 0x40. Blocking bus; no reset
 * line (the usual I2C modules have none wired).
 *
 *     zs_i2c_port port;
 *     char err[256];
 *     if (zs_i2c_open(&port, "/dev/i2c-1", 0x3C, err, sizeof err) != 0) { puts(err); ... }
 *     zs_panel_init(&lcd, &zs_panel_ssd1306_128x64, &port.bus, ZS_FMT_MONO_PAGE, 0);
 *
 * zs_i2c_open says what is wrong in plain words: no such bus (i2c-dev not
 * loaded, the bus not enabled), permission denied (the i2c group), the
 * address held by a kernel driver, or no device answering (NACK) at the
 * address.
 */
#ifndef ZSPAN_PORT_LINUX_I2C_H
#define ZSPAN_PORT_LINUX_I2C_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

typedef struct zs_i2c_port {
    zs_bus bus;
    int fd;
    uint8_t addr;
    uint32_t max_frame;        /* data bytes per message (default 1024) */
    char path[64];
    char error[256];           /* why the last transfer failed */
    uint64_t bytes;            /* bytes written, control bytes included */
    uint32_t messages;
} zs_i2c_port;

/* Opens the bus, selects the address, checks that a device answers (an
 * SSD1306/SH1106 NOP command, 0xE3). 0, or -1 with the reason in err. */
int zs_i2c_open(zs_i2c_port *p, const char *dev, uint8_t addr, char *err, size_t errlen);
void zs_i2c_close(zs_i2c_port *p);
/* The reason of the last failure ("" if none). */
const char *zs_i2c_error(const zs_i2c_port *p);
/* Wire time of `bytes` in `messages` at hz: 9 clocks a byte (ACK), the
 * address byte and start/stop (2 clocks) per message. Microseconds. */
double zs_i2c_wire_us(uint64_t bytes, uint32_t messages, double hz);

#endif
