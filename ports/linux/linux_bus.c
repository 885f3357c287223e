/* SPDX-License-Identifier: MIT */
/*
 * zspan Linux port: spidev (or bit-banged SPI) + libgpiod lines as a zs_bus.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <linux/spi/spidev.h>

#include "zs_linux.h"

#define SPIDEV_BUFSIZ_PARAM "/sys/module/spidev/parameters/bufsiz"
#define SPIDEV_DEFAULT_BUFSIZ 4096u

zs_linux_cfg zs_linux_cfg_default(void)
{
    zs_linux_cfg c;
    memset(&c, 0, sizeof c);
    c.spi_dev = "/dev/spidev0.0";
    c.hz = 32000000u;
    c.spi_mode = 0;
    c.bits = 8;
    c.gpiochip = "gpiochip0";
    c.dc = -1;
    c.reset = -1;
    c.backlight = -1;
    c.sclk = c.mosi = c.cs = -1;
    return c;
}

uint32_t zs_spidev_bufsiz(void)
{
    FILE *f = fopen(SPIDEV_BUFSIZ_PARAM, "r");
    unsigned long v = 0;
    if (f == NULL)
        return SPIDEV_DEFAULT_BUFSIZ;
    if (fscanf(f, "%lu", &v) != 1 || v == 0 || v > (1ul << 24))
        v = SPIDEV_DEFAULT_BUFSIZ;
    fclose(f);
    return (uint32_t)v;
}

static void sleep_ms(uint32_t ms)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(ms / 1000u);
    ts.tv_nsec = (long)(ms % 1000u) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

/* ---- the transports ------------------------------------------------------ */

static int set_line(zs_linux_port *p, void *line, int value)
{
    if (line == NULL)
        return 0;
    p->st.gpio_writes++;
    if (p->gpio->line_set(line, value) != 0) {
        snprintf(p->err, sizeof p->err, "GPIO write failed: %s", strerror(errno));
        return -1;
    }
    return 0;
}

static int spidev_write(zs_linux_port *p, const uint8_t *d, size_t n)
{
    while (n > 0) {
        struct spi_ioc_transfer t;
        size_t k = n < p->bufsiz ? n : p->bufsiz;
        memset(&t, 0, sizeof t);
        t.tx_buf = (uint64_t)(uintptr_t)d;
        t.len = (uint32_t)k;
        t.speed_hz = p->cfg.hz;
        t.bits_per_word = p->cfg.bits;
        if (ioctl(p->spi_fd, SPI_IOC_MESSAGE(1), &t) < 0) {
            int e = errno;
            snprintf(p->err, sizeof p->err, "%s: SPI message of %zu bytes failed: %s%s",
                     p->cfg.spi_dev, k, strerror(e),
                     e == EMSGSIZE ? " (larger than the spidev bufsiz)" : "");
            return -1;
        }
        p->st.messages++;
        p->st.bytes += k;
        if (k > p->st.max_message)
            p->st.max_message = (uint32_t)k;
        d += k;
        n -= k;
    }
    return 0;
}

/* Bit-banged SPI, MSB first. CPOL = idle clock level; CPHA 0 = data valid
 * before the leading edge, CPHA 1 = data changes on the leading edge. */
static int bb_write(zs_linux_port *p, const uint8_t *d, size_t n)
{
    int cpol = (p->cfg.spi_mode & 2) ? 1 : 0, cpha = p->cfg.spi_mode & 1;
    size_t i;
    if (set_line(p, p->line_cs, 0) != 0)
        return -1;
    for (i = 0; i < n; i++) {
        int b;
        for (b = 7; b >= 0; b--) {
            int v = (d[i] >> b) & 1;
            if (cpha) {
                if (set_line(p, p->line_sclk, !cpol) != 0)
                    return -1;
            }
            if (v != p->mosi_level) {
                if (set_line(p, p->line_mosi, v) != 0)
                    return -1;
                p->mosi_level = v;
            }
            if (!cpha) {
                if (set_line(p, p->line_sclk, !cpol) != 0)
                    return -1;
            }
            if (set_line(p, p->line_sclk, cpol) != 0)
                return -1;
            p->st.bitbang_bits++;
        }
    }
    p->st.messages++;
    p->st.bytes += n;
    if (n > p->st.max_message)
        p->st.max_message = (uint32_t)n;
    return set_line(p, p->line_cs, 1);
}

static int spi_write(zs_linux_port *p, const uint8_t *d, size_t n)
{
    if (n == 0)
        return 0;
    return p->cfg.bitbang ? bb_write(p, d, n) : spidev_write(p, d, n);
}

static int set_dc(zs_linux_port *p, int level)
{
    if (p->dc_level == level)
        return 0;
    if (set_line(p, p->line_dc, level) != 0)
        return -1;
    p->dc_level = level;
    return 0;
}

/* ---- bus ops --------------------------------------------------------------- */

static int op_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    zs_linux_port *p = user;
    if (set_dc(p, 0) != 0 || spi_write(p, &cmd, 1) != 0)
        return -1;
    if (n == 0)
        return 0;
    if (set_dc(p, 1) != 0)
        return -1;
    return spi_write(p, params, n);
}

static int op_pixels(void *user, const uint8_t *data, size_t n)
{
    zs_linux_port *p = user;
    if (set_dc(p, 1) != 0)
        return -1;
    return spi_write(p, data, n);
}

static void op_reset(void *user, int level)
{
    zs_linux_port *p = user;
    (void)set_line(p, p->line_reset, level);
}

static void op_backlight(void *user, uint8_t level)
{
    zs_linux_port *p = user;
    (void)set_line(p, p->line_bl, level > 0);
}

static void op_delay(void *user, uint32_t ms)
{
    (void)user;
    sleep_ms(ms);
}

static const zs_bus_ops linux_ops = {op_command, op_pixels, op_reset, op_backlight, op_delay,
                                     NULL};

/* ---- open / close ------------------------------------------------------------ */

static int open_spidev(zs_linux_port *p, char *err, size_t n)
{
    const char *dev = p->cfg.spi_dev;
    uint8_t mode = p->cfg.spi_mode, bits = p->cfg.bits;
    uint32_t hz = p->cfg.hz;

    p->spi_fd = open(dev, O_RDWR | O_CLOEXEC);
    if (p->spi_fd < 0) {
        int e = errno;
        if (e == ENOENT || e == ENODEV || e == ENXIO)
            snprintf(err, n,
                     "%s: no such SPI device (is SPI enabled and spidev bound? on a Raspberry "
                     "Pi: dtparam=spi=on in config.txt; 'ls /dev/spidev*' lists the devices)",
                     dev);
        else if (e == EACCES || e == EPERM)
            snprintf(err, n,
                     "%s: permission denied (run as root or add the user to the group owning "
                     "the device, e.g. 'spi')",
                     dev);
        else if (e == EBUSY)
            snprintf(err, n, "%s: device busy (another program has it open)", dev);
        else
            snprintf(err, n, "%s: %s", dev, strerror(e));
        return -1;
    }
    if (ioctl(p->spi_fd, SPI_IOC_WR_MODE, &mode) < 0) {
        snprintf(err, n, "%s: cannot set SPI mode %u: %s", dev, mode, strerror(errno));
        return -1;
    }
    if (ioctl(p->spi_fd, SPI_IOC_WR_BITS_PER_WORD, &bits) < 0) {
        snprintf(err, n, "%s: cannot set %u bits per word: %s", dev, bits, strerror(errno));
        return -1;
    }
    if (ioctl(p->spi_fd, SPI_IOC_WR_MAX_SPEED_HZ, &hz) < 0) {
        snprintf(err, n, "%s: cannot set the clock to %u Hz: %s", dev, (unsigned)hz,
                 strerror(errno));
        return -1;
    }
    /* Read back what the controller took (it may round the clock down). */
    if (ioctl(p->spi_fd, SPI_IOC_RD_MAX_SPEED_HZ, &hz) == 0 && hz != 0)
        p->cfg.hz = hz;
    p->bufsiz = p->cfg.bufsiz ? p->cfg.bufsiz : zs_spidev_bufsiz();
    return 0;
}

static int request(zs_linux_port *p, void **line, int offset, int value, const char *role,
                   char *err, size_t n)
{
    char why[200];
    if (offset < 0)
        return 0;
    *line = p->gpio->line_request(p->chip, (unsigned)offset, value, why, sizeof why);
    if (*line == NULL) {
        snprintf(err, n, "%s (%s line on %s)", why, role, p->cfg.gpiochip);
        return -1;
    }
    return 0;
}

int zs_linux_open(zs_linux_port *p, const zs_linux_cfg *cfg, char *err, size_t n)
{
    char why[200];
    memset(p, 0, sizeof *p);
    p->cfg = *cfg;
    p->spi_fd = -1;
    p->dc_level = -1;
    p->mosi_level = -1;
    p->gpio = cfg->gpio != NULL ? cfg->gpio : zs_gpio_libgpiod();
    if (cfg->dc < 0) {
        snprintf(err, n, "the D/C line is required (--dc N)");
        return -1;
    }
    if (cfg->bits == 0 || cfg->spi_mode > 3 || cfg->hz == 0) {
        snprintf(err, n, "bad SPI settings (mode 0..3, bits per word > 0, clock > 0)");
        return -1;
    }
    if (cfg->bitbang && (cfg->sclk < 0 || cfg->mosi < 0)) {
        snprintf(err, n, "bit-banged SPI needs --sclk N and --mosi N");
        return -1;
    }
    if (!cfg->bitbang && open_spidev(p, err, n) != 0)
        goto fail;
    if (cfg->bitbang)
        p->bufsiz = cfg->bufsiz ? cfg->bufsiz : 65536u;
    p->chip = p->gpio->chip_open(cfg->gpiochip, why, sizeof why);
    if (p->chip == NULL) {
        snprintf(err, n, "%s", why);
        goto fail;
    }
    if (request(p, &p->line_dc, cfg->dc, 1, "D/C", err, n) != 0 ||
        request(p, &p->line_reset, cfg->reset, 1, "reset", err, n) != 0 ||
        request(p, &p->line_bl, cfg->backlight, 0, "backlight", err, n) != 0)
        goto fail;
    p->dc_level = 1;
    if (cfg->bitbang) {
        int cpol = (cfg->spi_mode & 2) ? 1 : 0;
        if (request(p, &p->line_sclk, cfg->sclk, cpol, "SCLK", err, n) != 0 ||
            request(p, &p->line_mosi, cfg->mosi, 0, "MOSI", err, n) != 0 ||
            request(p, &p->line_cs, cfg->cs, 1, "CS", err, n) != 0)
            goto fail;
        p->mosi_level = 0;
    }
    if (zs_bus_init(&p->bus, &linux_ops, p, 0, p->bufsiz) != ZS_BUS_OK) {
        snprintf(err, n, "zs_bus_init failed");
        goto fail;
    }
    return 0;
fail:
    zs_linux_close(p);
    return -1;
}

void zs_linux_close(zs_linux_port *p)
{
    void **lines[] = {&p->line_dc,   &p->line_reset, &p->line_bl,
                      &p->line_sclk, &p->line_mosi,  &p->line_cs};
    size_t i;
    if (p->gpio != NULL)
        for (i = 0; i < sizeof lines / sizeof lines[0]; i++)
            if (*lines[i] != NULL) {
                p->gpio->line_release(*lines[i]);
                *lines[i] = NULL;
            }
    if (p->chip != NULL && p->gpio != NULL)
        p->gpio->chip_close(p->chip);
    p->chip = NULL;
    if (p->spi_fd >= 0)
        close(p->spi_fd);
    p->spi_fd = -1;
}
