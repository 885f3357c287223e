/* SPDX-License-Identifier: MIT */
/* zspan Linux port over I2C (i2c-dev), see zs_linux_i2c.h. */
#define _GNU_SOURCE
#include "zs_linux_i2c.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <linux/i2c-dev.h>
#include <linux/i2c.h>

#define I2C_CTRL_CMD 0x00u
#define I2C_CTRL_DATA 0x40u
#define I2C_MAX_FRAME 1024u

static int is_nack(int e)
{
    /* adapters report a missing ACK as ENXIO, EREMOTEIO or EIO */
    return e == ENXIO || e == EREMOTEIO || e == EIO;
}

static void describe(zs_i2c_port *p, int e, const char *what)
{
    if (is_nack(e))
        snprintf(p->error, sizeof p->error,
                 "%s: no device answers at 0x%02X on %s (NACK): check the wiring, the power "
                 "and the address (0x3C, or 0x3D with SA0 high)",
                 what, p->addr, p->path);
    else
        snprintf(p->error, sizeof p->error, "%s on %s at 0x%02X: %s", what, p->path, p->addr,
                 strerror(e));
}

/* One write message: control byte, then n bytes. */
static int write_msg(zs_i2c_port *p, uint8_t ctrl, uint8_t first, int has_first, const uint8_t *d,
                     size_t n, const char *what)
{
    uint8_t buf[2 + I2C_MAX_FRAME];
    struct i2c_msg msg;
    struct i2c_rdwr_ioctl_data x;
    size_t len = 0;
    buf[len++] = ctrl;
    if (has_first)
        buf[len++] = first;
    if (n > sizeof buf - len)
        return -1;
    if (n)
        memcpy(buf + len, d, n);
    len += n;
    msg.addr = p->addr;
    msg.flags = 0;
    msg.len = (uint16_t)len;
    msg.buf = buf;
    x.msgs = &msg;
    x.nmsgs = 1;
    if (ioctl(p->fd, I2C_RDWR, &x) < 0) {
        describe(p, errno, what);
        return -1;
    }
    p->bytes += len;
    p->messages++;
    return 0;
}

static int i2c_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    zs_i2c_port *p = user;
    return write_msg(p, I2C_CTRL_CMD, cmd, 1, params, n, "command");
}

static int i2c_pixels(void *user, const uint8_t *data, size_t n)
{
    zs_i2c_port *p = user;
    while (n > 0) {
        size_t k = n < p->max_frame ? n : p->max_frame;
        if (write_msg(p, I2C_CTRL_DATA, 0, 0, data, k, "pixel data") != 0)
            return -1;
        data += k;
        n -= k;
    }
    return 0;
}

static void i2c_delay(void *user, uint32_t ms)
{
    struct timespec ts;
    (void)user;
    ts.tv_sec = (time_t)(ms / 1000u);
    ts.tv_nsec = (long)(ms % 1000u) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR)
        ;
}

static const zs_bus_ops i2c_ops = {
    .command = i2c_command,
    .pixels = i2c_pixels,
    .reset = NULL,
    .backlight = NULL,
    .delay_ms = i2c_delay,
    .poll = NULL,
};

int zs_i2c_open(zs_i2c_port *p, const char *dev, uint8_t addr, char *err, size_t errlen)
{
    static const uint8_t nop = 0xE3; /* SSD1306 / SH1106 NOP */
    memset(p, 0, sizeof *p);
    p->fd = -1;
    p->addr = addr;
    p->max_frame = I2C_MAX_FRAME;
    snprintf(p->path, sizeof p->path, "%s", dev ? dev : "(null)");
    if (dev == NULL || addr > 0x77) {
        snprintf(err, errlen, "bad I2C bus or address (0x%02X)", addr);
        return -1;
    }
    p->fd = open(dev, O_RDWR | O_CLOEXEC);
    if (p->fd < 0) {
        int e = errno;
        if (e == ENOENT || e == ENODEV || e == ENXIO)
            snprintf(err, errlen,
                     "no I2C bus %s: load the i2c-dev module (modprobe i2c-dev) and enable the "
                     "bus (Raspberry Pi: raspi-config, Interface Options, I2C)",
                     dev);
        else if (e == EACCES || e == EPERM)
            snprintf(err, errlen,
                     "permission denied on %s: add the user to the i2c group (usermod -aG i2c "
                     "USER, then log in again) or run as root",
                     dev);
        else
            snprintf(err, errlen, "cannot open %s: %s", dev, strerror(e));
        return -1;
    }
    if (ioctl(p->fd, I2C_SLAVE, (unsigned long)addr) < 0) {
        int e = errno;
        if (e == EBUSY)
            snprintf(err, errlen, "address 0x%02X on %s is held by a kernel driver (EBUSY)",
                     addr, dev);
        else
            snprintf(err, errlen, "%s: I2C_SLAVE 0x%02X: %s (is it an i2c-dev node?)", dev, addr,
                     strerror(e));
        zs_i2c_close(p);
        return -1;
    }
    if (write_msg(p, I2C_CTRL_CMD, nop, 1, NULL, 0, "probe") != 0) {
        snprintf(err, errlen, "%s", p->error);
        zs_i2c_close(p);
        return -1;
    }
    if (zs_bus_init(&p->bus, &i2c_ops, p, 0, 0) != ZS_BUS_OK) {
        snprintf(err, errlen, "bus init failed");
        zs_i2c_close(p);
        return -1;
    }
    p->bytes = 0;
    p->messages = 0;
    return 0;
}

void zs_i2c_close(zs_i2c_port *p)
{
    if (p->fd >= 0)
        close(p->fd);
    p->fd = -1;
}

const char *zs_i2c_error(const zs_i2c_port *p)
{
    return p->error;
}

double zs_i2c_wire_us(uint64_t bytes, uint32_t messages, double hz)
{
    return ((double)(bytes + messages) * 9.0 + 2.0 * messages) * 1e6 / hz;
}
