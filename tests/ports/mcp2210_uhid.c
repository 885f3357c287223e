/* SPDX-License-Identifier: MIT */
/*
 * mcp2210-uhid: the MCP2210 model as a real HID device through /dev/uhid.
 * The kernel's hid core + hid-generic + hidraw turn it into /dev/hidrawN with
 * USB VID 0x04D8 / PID 0x00DE, so hidapi (hidraw backend) finds and opens it
 * like the chip. The SPI bytes end in host_sim's emulated panel.
 *
 *   mcp2210-uhid [--panel NAME] [--busy-every N] [--busy-burst N] [--lag N]
 *                [--disconnect-after N] [--out FILE] [--tag TEXT]
 *
 * Runs until SIGTERM/SIGINT (or the injected disconnect), then writes to
 * --out (a raw serial port in the VM test):
 *   "ZSMODEL <tag> <w> <h> model_errors=E panel_errors=0xP busy=B poll_busy=Q
 *    reports=R bytes=N transactions=T gone=G\n", then w*h*3 bytes (6-bit
 *   R, G, B of the panel's view), then "ZSEND\n";
 * and a one-line summary on stdout.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include <linux/uhid.h>

#include "emu.h"
#include "mcp2210_model.h"

static volatile sig_atomic_t stop;

static void on_signal(int s)
{
    (void)s;
    stop = 1;
}

/* Vendor-defined page, one 64-byte input and one 64-byte output report, no
 * report IDs (as the MCP2210). */
static const uint8_t rdesc[] = {
    0x06, 0x00, 0xFF,       /* Usage Page (Vendor 0xFF00) */
    0x09, 0x01,             /* Usage (1) */
    0xA1, 0x01,             /* Collection (Application) */
    0x19, 0x01, 0x29, 0x40, /*   Usage Minimum 1, Maximum 64 */
    0x15, 0x00, 0x26, 0xFF, 0x00, /* Logical 0..255 */
    0x75, 0x08, 0x95, 0x40, /*   Report Size 8, Count 64 */
    0x81, 0x00,             /*   Input (Data, Array, Absolute) */
    0x19, 0x01, 0x29, 0x40, /*   Usage Minimum 1, Maximum 64 */
    0x91, 0x00,             /*   Output (Data, Array, Absolute) */
    0xC0                    /* End Collection */
};

static int uhid_send(int fd, const struct uhid_event *ev)
{
    ssize_t r = write(fd, ev, sizeof *ev);
    return r == (ssize_t)sizeof *ev ? 0 : -1;
}

static int create_device(int fd)
{
    struct uhid_event ev;
    memset(&ev, 0, sizeof ev);
    ev.type = UHID_CREATE2;
    snprintf((char *)ev.u.create2.name, sizeof ev.u.create2.name, "Microchip MCP2210 (zspan model)");
    snprintf((char *)ev.u.create2.phys, sizeof ev.u.create2.phys, "zspan-model");
    memcpy(ev.u.create2.rd_data, rdesc, sizeof rdesc);
    ev.u.create2.rd_size = sizeof rdesc;
    ev.u.create2.bus = 0x03; /* BUS_USB */
    ev.u.create2.vendor = 0x04D8;
    ev.u.create2.product = 0x00DE;
    ev.u.create2.version = 0x0002;
    return uhid_send(fd, &ev);
}

static void dump(const char *out, const char *tag, mcp_model *m, emu_panel *e)
{
    unsigned w, h, i;
    uint32_t *view;
    uint8_t *rgb;
    FILE *f;
    emu_flush(e);
    emu_view_size(e, 0, &w, &h);
    printf("model[%s]: %llu reports, %llu data reports, %llu busy + %llu poll-busy injected, "
           "%llu bytes to the panel in %llu transactions, model errors %u%s%s, panel errors "
           "0x%X, %s\n",
           tag, (unsigned long long)m->reports, (unsigned long long)m->data_reports,
           (unsigned long long)m->busy_sent, (unsigned long long)m->poll_busy_sent,
           (unsigned long long)m->bytes_to_panel, (unsigned long long)m->transactions,
           m->errors, m->errors ? ": " : "", m->errors ? m->first_error : "",
           (unsigned)e->errors, m->gone ? "disconnected" : "still connected");
    fflush(stdout);
    if (out == NULL)
        return;
    view = malloc((size_t)w * h * sizeof *view);
    rgb = malloc((size_t)w * h * 3u);
    f = fopen(out, "w");
    if (view == NULL || rgb == NULL || f == NULL) {
        fprintf(stderr, "model: cannot write %s\n", out);
        free(view);
        free(rgb);
        if (f != NULL)
            fclose(f);
        return;
    }
    {
        struct termios t;
        if (tcgetattr(fileno(f), &t) == 0) {
            cfmakeraw(&t);
            tcsetattr(fileno(f), TCSANOW, &t);
        }
    }
    emu_view_666(e, 0, view);
    for (i = 0; i < w * h; i++) {
        rgb[3 * i] = (uint8_t)(view[i] >> 12 & 63);
        rgb[3 * i + 1] = (uint8_t)(view[i] >> 6 & 63);
        rgb[3 * i + 2] = (uint8_t)(view[i] & 63);
    }
    fprintf(f,
            "ZSMODEL %s %u %u model_errors=%u panel_errors=0x%X busy=%llu poll_busy=%llu "
            "reports=%llu bytes=%llu transactions=%llu gone=%d\n",
            tag, w, h, m->errors, (unsigned)e->errors, (unsigned long long)m->busy_sent,
            (unsigned long long)m->poll_busy_sent, (unsigned long long)m->reports,
            (unsigned long long)m->bytes_to_panel, (unsigned long long)m->transactions, m->gone);
    fwrite(rgb, 1, (size_t)w * h * 3u, f);
    fprintf(f, "ZSEND\n");
    fclose(f);
    free(view);
    free(rgb);
}

int main(int argc, char **argv)
{
    const char *panel = "st7789-240x240", *out = NULL, *tag = "run";
    emu_panel emu;
    mcp_model m;
    struct uhid_event ev;
    int fd, i, started = 0;
    long busy_every = 0, busy_burst = 1, lag = 0, disconnect_after = 0;

    for (i = 1; i + 1 < argc; i += 2) {
        const char *a = argv[i], *v = argv[i + 1];
        if (strcmp(a, "--panel") == 0) panel = v;
        else if (strcmp(a, "--out") == 0) out = v;
        else if (strcmp(a, "--tag") == 0) tag = v;
        else if (strcmp(a, "--busy-every") == 0) busy_every = atol(v);
        else if (strcmp(a, "--busy-burst") == 0) busy_burst = atol(v);
        else if (strcmp(a, "--lag") == 0) lag = atol(v);
        else if (strcmp(a, "--disconnect-after") == 0) disconnect_after = atol(v);
        else {
            fprintf(stderr, "mcp2210-uhid: unknown option %s\n", a);
            return 2;
        }
    }
    if (emu_model_find(panel) == NULL || emu_init(&emu, emu_model_find(panel)) != 0) {
        fprintf(stderr, "mcp2210-uhid: unknown panel %s\n", panel);
        return 2;
    }
    /* Wiring: GP0 chip select, GP1 D/C, GP2 reset (zspan-mcp2210's defaults). */
    mcp_model_init(&m, &emu, 0, 1, 2, -1);
    m.busy_every = (unsigned)busy_every;
    m.busy_burst = (unsigned)busy_burst;
    m.lag = (unsigned)lag;
    m.disconnect_after = disconnect_after;

    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    fd = open("/dev/uhid", O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        fprintf(stderr, "mcp2210-uhid: /dev/uhid: %s (modprobe uhid; root)\n", strerror(errno));
        return 1;
    }
    if (create_device(fd) != 0) {
        fprintf(stderr, "mcp2210-uhid: UHID_CREATE2: %s\n", strerror(errno));
        return 1;
    }
    while (!stop) {
        struct pollfd p = {fd, POLLIN, 0};
        int r = poll(&p, 1, 100);
        if (r < 0 && errno != EINTR)
            break;
        if (r <= 0)
            continue;
        if (read(fd, &ev, sizeof ev) <= 0)
            continue;
        switch (ev.type) {
        case UHID_START:
            if (!started)
                printf("model[%s]: device started\n", tag);
            started = 1;
            fflush(stdout);
            break;
        case UHID_OUTPUT: {
            uint8_t req[64], resp[64];
            const uint8_t *d = ev.u.output.data;
            size_t n = ev.u.output.size;
            struct uhid_event in;
            if (n == 65 && d[0] == 0) { /* report ID 0 in front */
                d++;
                n--;
            }
            memset(req, 0, sizeof req);
            memcpy(req, d, n < 64 ? n : 64);
            if (!mcp_model_handle(&m, req, resp)) {
                /* Injected disconnect: the device vanishes mid-frame. */
                memset(&in, 0, sizeof in);
                in.type = UHID_DESTROY;
                uhid_send(fd, &in);
                stop = 1;
                break;
            }
            memset(&in, 0, sizeof in);
            in.type = UHID_INPUT2;
            in.u.input2.size = 64;
            memcpy(in.u.input2.data, resp, 64);
            if (uhid_send(fd, &in) != 0)
                fprintf(stderr, "mcp2210-uhid: UHID_INPUT2: %s\n", strerror(errno));
            break;
        }
        case UHID_GET_REPORT: {
            struct uhid_event rep;
            memset(&rep, 0, sizeof rep);
            rep.type = UHID_GET_REPORT_REPLY;
            rep.u.get_report_reply.id = ev.u.get_report.id;
            rep.u.get_report_reply.err = EIO;
            uhid_send(fd, &rep);
            break;
        }
        case UHID_SET_REPORT: {
            struct uhid_event rep;
            memset(&rep, 0, sizeof rep);
            rep.type = UHID_SET_REPORT_REPLY;
            rep.u.set_report_reply.id = ev.u.set_report.id;
            rep.u.set_report_reply.err = EIO;
            uhid_send(fd, &rep);
            break;
        }
        default:
            break;
        }
    }
    if (!m.gone) {
        memset(&ev, 0, sizeof ev);
        ev.type = UHID_DESTROY;
        uhid_send(fd, &ev);
    }
    dump(out, tag, &m, &emu);
    close(fd);
    emu_free(&emu);
    return 0;
}
