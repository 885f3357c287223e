/* SPDX-License-Identifier: MIT */
/*
 * zspan Linux port: a zs_bus over spidev (or bit-banged SPI on GPIO lines),
 * with D/C, reset and backlight on GPIO lines through libgpiod (v1 or v2 API,
 * chosen at build time: ZS_GPIOD_V2 is defined when pkg-config reports
 * libgpiod >= 2).
 *
 * Host C (POSIX, malloc, stdio). Blocking bus: every write has left the
 * kernel when the bus call returns.
 *
 *     zs_linux_cfg c = zs_linux_cfg_default();
 *     c.spi_dev = "/dev/spidev0.0"; c.gpiochip = "gpiochip0"; c.dc = 25; c.reset = 27;
 *     zs_linux_port port;
 *     char err[256];
 *     if (zs_linux_open(&port, &c, err, sizeof err) != 0) { puts(err); ... }
 *     zs_panel_init(&lcd, desc, &port.bus, ZS_FMT_RGB565_BE, 0);
 *     ...
 *     zs_linux_close(&port);
 *
 * spidev limits one message to `bufsiz` bytes (module parameter, 4096 by
 * default, /sys/module/spidev/parameters/bufsiz). The port reads it and sends
 * every write as messages of at most that many bytes; the bus's max_transfer
 * is set to it as well.
 */
#ifndef ZSPAN_PORT_LINUX_H
#define ZSPAN_PORT_LINUX_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/bus.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- GPIO seam: the few libgpiod operations the port needs --------------
 * zs_gpio_libgpiod() is the real one (v1 or v2 API); tests may pass their
 * own. A line handle is one requested output line. Functions returning int
 * give 0 on success and -1 with errno set and a message in err. */
typedef struct zs_gpio_ops {
    /* Opens a chip: a name ("gpiochip0"), a number ("0") or a path. */
    void *(*chip_open)(const char *chip, char *err, size_t errlen);
    void (*chip_close)(void *chip);
    /* Requests one line as an output with an initial value, consumer "zspan". */
    void *(*line_request)(void *chip, unsigned offset, int value, char *err, size_t errlen);
    int (*line_set)(void *line, int value);
    void (*line_release)(void *line);
    const char *api;   /* "libgpiod v1 (1.6)", ... */
} zs_gpio_ops;

/* The libgpiod-backed table. */
const zs_gpio_ops *zs_gpio_libgpiod(void);

/* ---- configuration ------------------------------------------------------ */
typedef struct zs_linux_cfg {
    const char *spi_dev;      /* "/dev/spidev0.0"; NULL with bitbang */
    uint32_t hz;              /* SPI clock (spidev max_speed_hz); default 32 MHz */
    uint8_t spi_mode;         /* 0..3 (SPI_MODE_x); default 0 */
    uint8_t bits;             /* bits per word; default 8 */
    uint32_t bufsiz;          /* 0: read /sys/module/spidev/parameters/bufsiz (4096 if absent) */
    const char *gpiochip;     /* chip for the lines below ("gpiochip0") */
    int dc, reset, backlight; /* line offsets; -1 = not wired (dc is required) */
    /* Bit-banged SPI on GPIO lines of `gpiochip` instead of spidev. */
    int bitbang;
    int sclk, mosi, cs;       /* cs -1: tied low */
    const zs_gpio_ops *gpio;  /* NULL: zs_gpio_libgpiod() */
} zs_linux_cfg;

zs_linux_cfg zs_linux_cfg_default(void);

/* Traffic counters of the transport (what reached the kernel). */
typedef struct zs_linux_stats {
    uint64_t messages;        /* SPI_IOC_MESSAGE calls */
    uint64_t bytes;           /* bytes in them */
    uint32_t max_message;     /* largest message, bytes */
    uint64_t gpio_writes;     /* line value changes requested */
    uint64_t bitbang_bits;    /* bits clocked by the bit-banged mode */
} zs_linux_stats;

typedef struct zs_linux_port {
    zs_bus bus;               /* give &port.bus to zs_panel_init */
    zs_linux_cfg cfg;
    const zs_gpio_ops *gpio;
    int spi_fd;
    uint32_t bufsiz;          /* message limit in use */
    void *chip;
    void *line_dc, *line_reset, *line_bl, *line_sclk, *line_mosi, *line_cs;
    int dc_level;             /* last D/C value written, -1 unknown */
    int mosi_level;
    zs_linux_stats st;
    char err[256];            /* the last failure, for messages */
} zs_linux_port;

/* Opens spidev (or the bit-bang lines) and the GPIO lines and sets up
 * port->bus (blocking, max_transfer = bufsiz). Returns 0, or -1 with a
 * message in err (missing device, permission, busy line, ...). */
int zs_linux_open(zs_linux_port *port, const zs_linux_cfg *cfg, char *err, size_t errlen);
void zs_linux_close(zs_linux_port *port);

/* spidev's message limit: the module parameter if readable, else 4096. */
uint32_t zs_spidev_bufsiz(void);

#ifdef __cplusplus
}
#endif

#endif
