/* SPDX-License-Identifier: MIT */
/*
 * zspan-sim panel: renders frames through a panel driver into an emulated
 * display controller, exactly as they would go down the SPI wire, and shows
 * what the panel shows (PNG files and/or a live SDL2 window). The frame loop
 * is the one of zspan-linux and zspan-mcp2210 (app/zs_app.h); the emulated
 * panel is its bus.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "emu/emu.h"
#include "emu/emu_bus.h"
#include "emu/emu_mono.h"
#include "emu/emu_window.h"
#include "sim.h"
#include "zs_app.h"
#include "zs_opts.h"

int sim_panel_main(int argc, char **argv);
int sim_panel_mono(int argc, char **argv); /* panel_mono.c */
int sim_panel_gray(int argc, char **argv); /* panel_gray.c */

#define PANEL_PROG "zspan-sim panel"

static const char panel_usage[] =
    "  zspan-sim panel [options]: the scene through a panel driver into an emulated\n"
    "  display controller (the bytes of the SPI wire), then PNG and/or a window.\n"
    "  Panels: st7789-240x240, st7789-240x320, st7789-135x240, ili9341,\n"
    "  st7735-128x160, gc9a01, ili9488, ssd1351 (--list: sizes and clocks).\n"
    ZS_APP_USAGE
    "  (here --band defaults to 1; meshes are fitted to the unit sphere)\n"
    "Monochrome panels (ssd1306-128x64, ssd1306-128x32, sh1106-132x64, ssd1680-122x250):\n"
    "  the demo in 1 bit; --out FILE.png the filled, dithered frame, --lines-out FILE.png\n"
    "  the same view as a hidden-line drawing (default out/panel_lines.png); --i2c (OLEDs:\n"
    "  I2C instead of 4-wire SPI, wire time at 400 kHz and 1 MHz); --diffuse (error\n"
    "  diffusion instead of ordered dithering); --band N (multiples of 8 on OLEDs)\n"
    "Emulated panel:\n"
    "  --out FILE.png        the last frame as the panel shows it (default out/panel.png)\n"
    "  --seq PATTERN         every frame, e.g. out/seq/f_%03d.png\n"
    "  --window              live SDL2 window (needs a display; headless otherwise)\n"
    "  --scale N             window pixels per panel pixel (default 2)\n"
    "  --hold                keep the window open after the last frame until closed\n"
    "  --clock HZ            SPI clock for the wire time (default: the panel's rating)\n"
    "  --async               DMA-style bus: next band renders while one is on the wire\n"
    "  --max-transfer N      bytes per SPI transfer (e.g. 4096 for spidev; default none)\n"
    "  --trace               print the command bytes of the init and the first frame\n";

SIM_COMMAND(panel, "panel", sim_panel_main, panel_usage)

/* The options of the emulated panel, besides the common ones. */
typedef struct panel_opts {
    zs_app_opts app;
    const char *out, *seq;
    int out_set, done;
    long scale, max_transfer;
    double clock;
    int window, hold, async, trace;
} panel_opts;

/* What the loop's hooks need. */
typedef struct panel_run {
    const panel_opts *o;
    const zs_panel_desc *d;
    emu_panel emu;
    emu_port port;
    emu_window *win;
    uint8_t *rgb;
    unsigned vw, vh;
    int tty, failed, port_ok;
    uint64_t port_ns_last;
    double t_total, t_port;
    uint64_t wire_ns_total, bytes_total, cmds_total;
    uint32_t wire_waits;
    long frames_done;
    zs_stats last_stats;
    zs_wire_model wire;
} panel_run;

static int parse(int argc, char **argv, panel_opts *o)
{
    int i, m;
    const char *v;

    memset(o, 0, sizeof *o);
    zs_app_defaults(&o->app, argc);
    o->app.band = 1;
    o->out = "out/panel.png";
    o->scale = 2;
    if (o->app.meshes == NULL)
        return SIM_EXIT_FAIL;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            printf("usage: zspan-sim panel [options]\n%s", panel_usage);
            o->done = 1;
            return 0;
        } else if (zs_opt_version(a, PANEL_PROG)) {
            o->done = 1;
            return 0;
        } else if ((m = zs_app_option(argc, argv, &i, &o->app, PANEL_PROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
        } else if (strcmp(a, "--window") == 0) {
            o->window = 1;
        } else if (strcmp(a, "--hold") == 0) {
            o->hold = 1;
        } else if (strcmp(a, "--async") == 0) {
            o->async = 1;
        } else if (strcmp(a, "--trace") == 0) {
            o->trace = 1;
        } else if ((m = zs_opt_value(argc, argv, &i, "--out", &v, PANEL_PROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->out = v;
            o->out_set = 1;
        } else if ((m = zs_opt_value(argc, argv, &i, "--seq", &v, PANEL_PROG)) != 0) {
            if (m < 0 || zs_opt_seq_pattern(PANEL_PROG, "--seq", v) != 0)
                return SIM_EXIT_USAGE;
            o->seq = v;
        } else if ((m = zs_opt_value(argc, argv, &i, "--scale", &v, PANEL_PROG)) != 0) {
            if (m < 0 || zs_opt_long(PANEL_PROG, "--scale", v, 1, 8, &o->scale) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--max-transfer", &v, PANEL_PROG)) != 0) {
            if (m < 0 ||
                zs_opt_long(PANEL_PROG, "--max-transfer", v, 0, 1L << 24, &o->max_transfer) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--clock", &v, PANEL_PROG)) != 0) {
            if (m < 0 || zs_opt_double(PANEL_PROG, "--clock", v, &o->clock) != 0 ||
                o->clock < 1000.0 || o->clock > 4e9) {
                fprintf(stderr, PANEL_PROG ": --clock wants Hz, 1000 .. 4e9\n");
                return SIM_EXIT_USAGE;
            }
        } else {
            fprintf(stderr, PANEL_PROG ": unknown option '%s' (see zspan-sim panel --help)\n", a);
            return SIM_EXIT_USAGE;
        }
    }
    if (o->app.list)
        return 0;
    if (zs_app_check(&o->app, PANEL_PROG) != 0)
        return SIM_EXIT_USAGE;
    if (o->out_set && o->out[0] != '\0' && sim_check_output(o->out, "--out") != 0)
        return SIM_EXIT_USAGE;
    if (o->seq != NULL) {
        char path[4096];
        /* Frame 0's name stands for all: the directory must exist. */
        if (zs_opt_seq_path(path, sizeof path, o->seq, 0) != 0) {
            fprintf(stderr, PANEL_PROG ": --seq: the file names of '%s' are too long\n", o->seq);
            return SIM_EXIT_USAGE;
        }
        if (sim_check_output(path, "--seq") != 0)
            return SIM_EXIT_USAGE;
    }
    return 0;
}

int sim_panel_parse_check(int argc, char **argv)
{
    panel_opts o;
    int rc = parse(argc, argv, &o);

    zs_app_free(&o.app);
    return rc;
}

static void print_trace(const emu_panel *e, const char *title)
{
    size_t i;
    int col = 0;
    printf("%s:\n", title);
    for (i = 0; i < e->nev; i++) {
        const emu_event *ev = &e->ev[i];
        if (ev->kind == 'C') {
            printf("%s  cmd %02X", col ? "\n" : "", ev->byte);
            col = 1;
        } else if (ev->kind == 'P') {
            printf(" %02X", ev->byte);
        } else {
            printf(" <%lu pixel bytes>", (unsigned long)ev->n);
        }
    }
    printf("\n");
}


/* Loop hook: the init is on the panel and the renderer ready. */
static int on_ready(void *ctx, const zs_panel *lcd, const zs_wire_model *wire)
{
    panel_run *pr = ctx;
    const panel_opts *o = pr->o;

    pr->wire = *wire;
    if (o->trace) {
        print_trace(&pr->emu, "init (command and parameter bytes)");
        emu_record(&pr->emu, 1);
    }
    if (o->window) {
        char err[160];
        char title[96];
        snprintf(title, sizeof title, "zspan: %s rotation %ld", pr->d->name, o->app.rotation);
        pr->win = emu_window_open(title, pr->vw, pr->vh, (unsigned)o->scale, err, sizeof err);
        if (pr->win == NULL && !o->app.quiet)
            printf("window: %s; continuing headless\n", err);
    }
    if (!o->app.quiet)
        printf("panel %s (%s), %ux%u at rotation %ld, %s, %s bus%s, SPI %.1f MHz, band %ld\n",
               pr->d->name, pr->d->ops->name, lcd->width,
               lcd->height, o->app.rotation, lcd->format == ZS_FMT_RGB565_BE ? "RGB565" : "RGB666",
               o->async ? "async (DMA)" : "blocking", o->max_transfer ? " (chunked)" : "",
               wire->clock_hz / 1e6, o->app.band);
    fflush(stdout);
    pr->port_ns_last = pr->port.ns_in_port;
    return 0;
}

/* Loop hook: frame f is on the emulated panel. */
static int on_frame(void *ctx, const zs_app_frame *f)
{
    panel_run *pr = ctx;
    const panel_opts *o = pr->o;
    double port_s = (double)(pr->port.ns_in_port - pr->port_ns_last) / 1e9;
    long frames = o->app.frames;

    pr->port_ns_last = pr->port.ns_in_port;
    if (o->trace && f->index == 0) {
        emu_flush(&pr->emu);
        print_trace(&pr->emu, "frame 0");
        emu_record(&pr->emu, 0);
    }
    pr->t_total += f->seconds;
    pr->t_port += port_s;
    if (f->stream != NULL) {
        pr->wire_ns_total += f->stream->wire_ns;
        pr->cmds_total += f->stream->bus.commands;
        pr->wire_waits += f->stream->wire_waits;
    }
    pr->bytes_total += f->bytes;
    pr->last_stats = *f->stats;
    pr->frames_done++;
    if (o->seq != NULL) {
        char path[4096];
        if (zs_opt_seq_path(path, sizeof path, o->seq, f->index) != 0) {
            fprintf(stderr, PANEL_PROG ": --seq: the name of frame %ld is too long\n", f->index);
            pr->failed = 1;
            return 1;
        }
        if (emu_write_png(&pr->emu, (unsigned)o->app.rotation, path) != 0) {
            fprintf(stderr, PANEL_PROG ": cannot write frame %ld (%s)\n", f->index, path);
            pr->failed = 1;
            return 1;
        }
    }
    if (pr->win != NULL) {
        emu_view_rgb(&pr->emu, (unsigned)o->app.rotation, pr->rgb);
        emu_window_show(pr->win, pr->rgb, pr->vw, pr->vh);
        if (emu_window_poll(pr->win))
            return 1;
    }
    if (!o->app.quiet && frames != 1 &&
        (pr->tty || (f->index + 1) % (frames >= 10 ? frames / 10 : 1) == 0 ||
         f->index + 1 == frames)) {
        fprintf(stderr, "%sframe %ld/%ld  render %.2f ms  wire %.2f ms%s", pr->tty ? "\r" : "",
                f->index + 1, frames, (f->seconds - port_s) * 1e3,
                f->stream != NULL ? f->stream->wire_ns / 1e6 : 0.0, pr->tty ? "   " : "\n");
        fflush(stderr);
    }
    return 0;
}

static void print_report(const panel_run *pr)
{
    const panel_opts *o = pr->o;
    double render_ms = (pr->t_total - pr->t_port) * 1e3 / (double)pr->frames_done;
    double wire_ms = (double)pr->wire_ns_total / 1e6 / (double)pr->frames_done;

    printf("last frame:\n");
    sim_print_stats(stdout, &pr->last_stats);
    printf("wire per frame: %.0f bytes, %.1f commands -> %.2f ms at %.1f MHz "
           "(bytes x 8 / clock + %u ns per command + %u ns per transfer)\n",
           (double)pr->bytes_total / (double)pr->frames_done,
           (double)pr->cmds_total / (double)pr->frames_done, wire_ms, pr->wire.clock_hz / 1e6,
           pr->wire.cmd_overhead_ns, pr->wire.transfer_overhead_ns);
    printf("render per frame (this host, emulator time excluded): %.2f ms\n", render_ms);
    printf("frame rate limit: wire %.1f fps, renderer %.1f fps -> %s-bound on this host\n",
           wire_ms > 0 ? 1e3 / wire_ms : 0.0, render_ms > 0 ? 1e3 / render_ms : 0.0,
           render_ms > wire_ms ? "renderer" : "wire");
    if (o->async)
        printf("async bus: %u bands found the wire still busy over %ld frames\n",
               pr->wire_waits, pr->frames_done);
    printf("emulated %s: %llu bytes in, %llu pixels written, %u window wraps, %u errors\n",
           pr->d->name, (unsigned long long)pr->emu.bytes_in,
           (unsigned long long)pr->emu.pixels, (unsigned)pr->emu.wraps,
           (unsigned)pr->emu.error_count);
    if (o->out != NULL && o->out[0] != '\0')
        printf("wrote %s%s%s\n", o->out, o->seq ? " and the sequence " : "",
               o->seq ? o->seq : "");
}

/* After the run: the last picture, the report, the emulator's verdict. */
static int finish(panel_run *pr)
{
    const panel_opts *o = pr->o;
    unsigned i;

    if (!o->app.quiet && o->app.frames != 1 && pr->tty)
        fputc('\n', stderr);
    emu_port_drain(&pr->port);
    emu_flush(&pr->emu);
    if (o->out != NULL && o->out[0] != '\0' &&
        ((!o->out_set && sim_make_parent_dirs(o->out) != 0) ||
         emu_write_png(&pr->emu, (unsigned)o->app.rotation, o->out) != 0)) {
        fprintf(stderr, PANEL_PROG ": cannot write %s\n", o->out);
        return SIM_EXIT_FAIL;
    }
    if (!o->app.quiet && pr->frames_done > 0)
        print_report(pr);
    if (pr->emu.errors != 0 || pr->port.violations != 0) {
        for (i = 0; i < pr->emu.log_lines; i++)
            fprintf(stderr, PANEL_PROG ": protocol error: %s\n", pr->emu.log[i]);
        if (pr->port.violations)
            fprintf(stderr, PANEL_PROG ": bus contract: %s\n", pr->port.violation);
        return SIM_EXIT_FAIL;
    }
    if (pr->win != NULL && o->hold) {
        if (!o->app.quiet)
            printf("window open: close it or press q / Escape\n");
        while (!emu_window_poll(pr->win)) {
            struct timespec ts = {0, 20000000};
            nanosleep(&ts, NULL);
        }
    }
    return SIM_EXIT_OK;
}

int sim_panel_main(int argc, char **argv)
{
    static panel_run pr;
    panel_opts o;
    zs_app_opts loop;
    zs_app_port ap;
    const emu_model *model;
    int rc, i;

    /* the monochrome panels have their own emulator and loop */
    for (i = 1; i + 1 < argc; i++)
        if (strcmp(argv[i], "--panel") == 0 && emu_mono_model_find(argv[i + 1]) != NULL)
            return sim_panel_mono(argc, argv);
        else if (strcmp(argv[i], "--panel") == 0 &&
                 zs_panel_supports(zs_panel_find(argv[i + 1]), ZS_FMT_GRAY4))
            return sim_panel_gray(argc, argv); /* and the 4-bit grey ones theirs */
    rc = parse(argc, argv, &o);
    if (rc != 0 || o.app.list || o.done) {
        if (o.app.list)
            zs_app_list_panels(stdout);
        zs_app_free(&o.app);
        return rc;
    }
    memset(&pr, 0, sizeof pr);
    pr.o = &o;
    pr.tty = isatty(2);
    pr.d = zs_panel_find(o.app.panel);
    model = emu_model_find(o.app.panel);
    if (pr.d == NULL || model == NULL) {
        fprintf(stderr, PANEL_PROG ": unknown panel '%s' (try --list)\n", o.app.panel);
        zs_app_free(&o.app);
        return SIM_EXIT_USAGE;
    }
    rc = SIM_EXIT_FAIL;
    if (emu_init(&pr.emu, model) != 0) {
        fprintf(stderr, PANEL_PROG ": out of memory\n");
        zs_app_free(&o.app);
        return rc;
    }
    emu_view_size(&pr.emu, (unsigned)o.app.rotation, &pr.vw, &pr.vh);
    pr.rgb = malloc((size_t)pr.vw * pr.vh * 3);
    if (pr.rgb != NULL && emu_port_init(&pr.port, &pr.emu, o.async, o.async ? 4u : 0u,
                                        (uint32_t)o.max_transfer) == 0) {
        pr.port_ok = 1;
        emu_record(&pr.emu, o.trace);
        memset(&ap, 0, sizeof ap);
        ap.name = "emulated panel";
        ap.clock_hz = o.clock > 0 ? (uint32_t)o.clock : 0u;
        ap.async = o.async;
        ap.ready = on_ready;
        ap.frame_done = on_frame;
        ap.ctx = &pr;
        /* The loop's own lines are replaced by the report of finish(). */
        loop = o.app;
        loop.quiet = 1;
        rc = zs_app_run(&loop, &pr.port.bus, &ap, PANEL_PROG);
        if (rc == 0 && !pr.failed)
            rc = finish(&pr);
        else if (rc == 0)
            rc = SIM_EXIT_FAIL;
    }
    if (pr.win != NULL)
        emu_window_close(pr.win);
    if (pr.port_ok)
        emu_port_drain(&pr.port);
    emu_free(&pr.emu);
    free(pr.rgb);
    zs_app_free(&o.app);
    return rc;
}
