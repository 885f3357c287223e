/* SPDX-License-Identifier: MIT */
/* The frame loop of the panel programs (see zs_app.h). */
#define _POSIX_C_SOURCE 200809L
#include "zs_app.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "zs_arena.h"
#include "zs_partial.h"
#include "zs_scene.h"

static volatile sig_atomic_t stop_flag;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static const char *port_error(const zs_app_port *port)
{
    const char *e = port->error != NULL ? port->error(port->ctx) : NULL;
    return e != NULL && e[0] != '\0' ? e : "bus failure";
}

/* The frame buffers: one band (two on an async bus) for full frames; for
 * partial updates the current and the previous frame and a gather buffer. */
typedef struct frame_bufs {
    uint8_t *b0, *b1, *cur, *prev, *tmp;
    size_t stride, band_bytes;
    int band, have_prev;
} frame_bufs;

static int bufs_alloc(frame_bufs *b, const zs_panel *lcd, zs_format fmt, long band, int async,
                      int partial)
{
    memset(b, 0, sizeof *b);
    b->stride = zs_format_stride(fmt, lcd->width);
    b->band = band > lcd->height ? lcd->height : (int)band;
    if (fmt == ZS_FMT_MONO_PAGE) /* whole pages of 8 rows */
        b->band = (b->band + 7) / 8 * 8;
    b->band_bytes = zs_panel_window_bytes(fmt, lcd->width, (unsigned)b->band);
    b->b0 = malloc(b->band_bytes);
    if (async)
        b->b1 = malloc(b->band_bytes);
    if (partial) {
        b->tmp = malloc(b->band_bytes);
        b->cur = malloc(b->stride * lcd->height);
        b->prev = malloc(b->stride * lcd->height);
    }
    return b->b0 != NULL && (!async || b->b1 != NULL) &&
                   (!partial || (b->tmp != NULL && b->cur != NULL && b->prev != NULL))
               ? 0
               : -1;
}

static void bufs_free(frame_bufs *b)
{
    free(b->b0);
    free(b->b1);
    free(b->cur);
    free(b->prev);
    free(b->tmp);
}

/* Renders the whole frame into b->cur, sends what changed since the last
 * one. Returns rows sent, or -1 (*st: a render error, else *ps: the bus). */
static long send_partial(zs_panel *lcd, zs_renderer *r, frame_bufs *b, unsigned bpp,
                         zs_status *st, zs_panel_status *ps)
{
    long rows;
    int y;

    for (y = 0; y < lcd->height; y += b->band) {
        int n = lcd->height - y < b->band ? lcd->height - y : b->band;
        *st = zs_render_rows(r, y, n, b->cur + (size_t)y * b->stride, b->stride);
        if (*st != ZS_OK)
            return -1;
    }
    *ps = ZS_PANEL_OK;
    rows = zs_app_send_changes(lcd, b->cur, b->have_prev ? b->prev : NULL, b->stride, bpp,
                               b->tmp, b->band_bytes, ps);
    if (rows >= 0) {
        uint8_t *t = b->prev;
        b->prev = b->cur;
        b->cur = t;
        b->have_prev = 1;
    }
    return rows;
}

int zs_app_run(const zs_app_opts *o, zs_bus *bus, const zs_app_port *port, const char *prog)
{
    const zs_panel_desc *d = zs_panel_find(o->panel);
    zs_format fmt;
    zs_panel lcd;
    zs_panel_status ps;
    zs_renderer r;
    zs_config cfg;
    zs_wire_model wire;
    zs_scene sc;
    frame_bufs fb;
    void *arena = NULL;
    size_t arena_size;
    unsigned bpp;
    long k, frames_done = 0;
    int rc = 1;
    double t_start, t_all = 0.0;
    uint64_t bytes_all = 0;

    memset(&sc, 0, sizeof sc);
    memset(&fb, 0, sizeof fb);
    if (d == NULL) {
        fprintf(stderr, "%s: unknown panel '%s' (--list shows them)\n", prog, o->panel);
        return 2;
    }
    if (zs_app_check(o, prog) != 0)
        return 2;
    fmt = zs_app_wire_format(o, d);
    bpp = zs_panel_bytes_per_pixel(d, fmt); /* 0 for 1-bit pages (no partial updates) */
    wire = zs_wire_model_default(port->clock_hz ? port->clock_hz : d->max_spi_hz);

    t_start = now_s();
    ps = zs_panel_init(&lcd, d, bus, fmt, (unsigned)o->rotation);
    if (ps != ZS_PANEL_OK) {
        fprintf(stderr, "%s: panel init: %s: %s\n", prog, zs_panel_strerror(ps),
                ps == ZS_PANEL_ERR_IO ? port_error(port) : "check the options");
        return ps == ZS_PANEL_ERR_IO ? ZS_APP_EXIT_BUS : 1;
    }
    if (zs_panel_backlight(&lcd, (uint8_t)o->backlight) != ZS_PANEL_OK) {
        fprintf(stderr, "%s: backlight: %s\n", prog, port_error(port));
        return ZS_APP_EXIT_BUS;
    }
    if (!o->quiet)
        printf("%s: %s %ux%u %s over %s, init %.0f ms\n", prog, d->name, lcd.width, lcd.height,
               fmt == ZS_FMT_RGB565_BE ? "RGB565" : fmt == ZS_FMT_RGB666 ? "RGB666" : "1-bit",
               port->name, (now_s() - t_start) * 1e3);

    if (zs_scene_load_meshes(&sc, o->meshes, o->nmeshes, o->shade, o->flip_winding, o->two_sided,
                             o->up_axis, prog) != 0)
        goto done;
    sc.mono = o->mono;
    cfg = zs_app_config(lcd.width, lcd.height, sc.max_tris, 0, 0);
    if (fmt == ZS_FMT_MONO_PAGE)
        cfg.flags |= ZS_CFG_MONO | ZS_CFG_LINES;
    arena = zs_app_renderer(&r, &cfg, &arena_size, prog);
    if (arena == NULL)
        goto done;
    if (bufs_alloc(&fb, &lcd, fmt, o->band, port->async, o->partial) != 0) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto done;
    }
    if (port->ready != NULL && port->ready(port->ctx, &lcd, &wire) != 0)
        goto done;
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);

    for (k = 0; o->frames == 0 || k < o->frames; k++) {
        zs_bus_counters c0 = bus->count, c1, dc;
        zs_panel_frame_stats fs;
        zs_app_frame info;
        zs_status st;
        double t0 = now_s(), t1;

        if (stop_flag)
            break;
        memset(&info, 0, sizeof info);
        info.index = k;
        info.rows = lcd.height;
        st = zs_scene_frame(&r, &sc, o->start_frame, k, o->spin, o->mode, o->shade, fmt);
        if (st != ZS_OK) {
            fprintf(stderr, "%s: frame %ld: %s\n", prog, k, zs_strerror(st));
            goto done;
        }
        if (!o->partial) {
            ps = zs_panel_stream(&lcd, &r, fb.b0, fb.b1, fb.band_bytes, fb.band, &wire, &fs);
            st = ps == ZS_PANEL_ERR_RENDER ? fs.render_status : ZS_OK;
            info.stream = &fs;
        } else {
            info.rows = send_partial(&lcd, &r, &fb, bpp, &st, &ps);
        }
        if (st != ZS_OK) {
            fprintf(stderr, "%s: frame %ld: %s\n", prog, k, zs_strerror(st));
            goto done;
        }
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, "%s: frame %ld: %s: %s\n", prog, k, zs_panel_strerror(ps),
                    ps == ZS_PANEL_ERR_IO ? port_error(port) : "driver error");
            rc = ps == ZS_PANEL_ERR_IO ? ZS_APP_EXIT_BUS : 1;
            goto done;
        }
        t1 = now_s();
        c1 = bus->count;
        dc = zs_bus_counters_diff(&c1, &c0);
        info.bytes = zs_bus_counters_bytes(&dc);
        info.seconds = t1 - t0;
        info.stats = zs_frame_stats(&r);
        t_all += info.seconds;
        bytes_all += info.bytes;
        frames_done++;
        if (!o->quiet)
            printf("frame %ld: %ld rows, %u bytes, %.1f ms (%.1f KB/s)\n", k, info.rows,
                   info.bytes, info.seconds * 1e3,
                   info.seconds > 0 ? info.bytes / info.seconds / 1e3 : 0.0);
        if (port->frame_done != NULL && port->frame_done(port->ctx, &info) != 0)
            break;
    }
    if (!o->quiet && frames_done > 0) {
        printf("%ld frames in %.2f s: %.2f fps, %.1f KB/s on the bus\n", frames_done, t_all,
               t_all > 0 ? frames_done / t_all : 0.0, t_all > 0 ? bytes_all / t_all / 1e3 : 0.0);
        if (port->report != NULL)
            port->report(port->ctx, stdout);
    }
    rc = 0;
done:
    fflush(stdout);
    zs_scene_free(&sc);
    free(arena);
    bufs_free(&fb);
    return rc;
}
