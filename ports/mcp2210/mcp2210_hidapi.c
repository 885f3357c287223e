/* SPDX-License-Identifier: MIT */
/*
 * The MCP2210 through hidapi (Debian: libhidapi-hidraw0, the hidraw backend).
 * The MCP2210 has no report IDs, so every output report goes out with a
 * leading 0 byte (hidapi's convention) and input reports arrive as 64 bytes.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>

#include <hidapi/hidapi.h>

#include "zs_mcp2210.h"

typedef struct hid_port {
    hid_device *dev;
    char err[200];
} hid_port;

static void note_error(hid_port *p)
{
    const wchar_t *w = hid_error(p->dev);
    size_t n;
    if (w == NULL) {
        snprintf(p->err, sizeof p->err, "%s", errno ? strerror(errno) : "unknown error");
        return;
    }
    n = wcstombs(p->err, w, sizeof p->err - 1);
    if (n == (size_t)-1)
        snprintf(p->err, sizeof p->err, "hidapi error");
    else
        p->err[n] = '\0';
}

static int h_write(void *h, const uint8_t report[ZS_MCP2210_REPORT])
{
    hid_port *p = h;
    uint8_t buf[ZS_MCP2210_REPORT + 1];
    buf[0] = 0; /* no report ID */
    memcpy(buf + 1, report, ZS_MCP2210_REPORT);
    if (hid_write(p->dev, buf, sizeof buf) < 0) {
        note_error(p);
        return -1;
    }
    return 0;
}

static int h_read(void *h, uint8_t report[ZS_MCP2210_REPORT], int timeout_ms)
{
    hid_port *p = h;
    int r = hid_read_timeout(p->dev, report, ZS_MCP2210_REPORT, timeout_ms);
    if (r < 0) {
        note_error(p);
        return -1;
    }
    if (r == 0)
        return 0;
    if (r < ZS_MCP2210_REPORT)
        memset(report + r, 0, (size_t)(ZS_MCP2210_REPORT - r));
    return ZS_MCP2210_REPORT;
}

static const char *h_error(void *h)
{
    return ((hid_port *)h)->err;
}

static void h_close(void *h)
{
    hid_port *p = h;
    hid_close(p->dev);
    free(p);
    hid_exit();
}

static const zs_hid_ops hidapi_ops = {h_write, h_read, h_error, h_close};

int zs_mcp2210_open_hidapi(zs_mcp2210 *m, const char *path, const zs_mcp2210_cfg *cfg, char *err,
                           size_t errlen)
{
    hid_port *p;
    char found[256] = "";

    memset(m, 0, sizeof *m);
    if (hid_init() != 0) {
        snprintf(err, errlen, "hidapi: hid_init failed");
        return -1;
    }
    if (path == NULL) {
        struct hid_device_info *list = hid_enumerate(ZS_MCP2210_VID, ZS_MCP2210_PID);
        if (list == NULL) {
            snprintf(err, errlen,
                     "no MCP2210 found (USB VID %04X PID %04X): is it plugged in ('lsusb')? "
                     "Is the hidraw driver loaded?",
                     ZS_MCP2210_VID, ZS_MCP2210_PID);
            hid_exit();
            return -1;
        }
        snprintf(found, sizeof found, "%s", list->path);
        hid_free_enumeration(list);
        path = found;
    }
    p = calloc(1, sizeof *p);
    if (p == NULL) {
        snprintf(err, errlen, "out of memory");
        hid_exit();
        return -1;
    }
    errno = 0;
    p->dev = hid_open_path(path);
    if (p->dev == NULL) {
        int e = errno;
        if (e == EACCES || e == EPERM)
            snprintf(err, errlen,
                     "%s: permission denied (run as root, or add a udev rule such as "
                     "SUBSYSTEM==\"hidraw\", ATTRS{idVendor}==\"04d8\", ATTRS{idProduct}==\"00de\", "
                     "MODE=\"0660\", GROUP=\"plugdev\")",
                     path);
        else if (e == ENOENT || e == ENODEV || e == ENXIO)
            snprintf(err, errlen, "%s: no such device (unplugged?)", path);
        else
            snprintf(err, errlen, "%s: cannot open: %s", path, e ? strerror(e) : "hidapi error");
        free(p);
        hid_exit();
        return -1;
    }
    if (zs_mcp2210_init(m, &hidapi_ops, p, cfg) != 0) {
        snprintf(err, errlen, "%s: %s", path, m->err);
        h_close(p);
        m->h = NULL;
        return -1;
    }
    return 0;
}
