/*
 * zspan-sim panel: renders frames through a panel driver into an emulated
 * display controller, exactly as they would go down the SPI wire, and shows
 * what the panel shows (PNG files and/or a live SDL2 window).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "demo_scene.h"
#include "emu/emu.h"
#include "emu/emu_bus.h"
#include "emu/emu_window.h"
#include "mesh_load.h"
#include "sim.h"
#include "zspan/panel.h"

int sim_panel_main(int argc, char **argv);

static const char panel_usage[] =
    "  zspan-sim panel [options]: the scene through a panel driver into an emulated\n"
    "  display controller (the bytes of the SPI wire), then PNG and/or a window.\n"
    "  --panel NAME          st7789-240x240 (default), st7789-240x320, st7789-135x240,\n"
    "                        ili9341, st7735-128x160, gc9a01, ili9488, ssd1351\n"
    "  --list                list the panels with their sizes and clocks\n"
    "  --rotation 0..3       quarter turns clockwise (default 0)\n"
    "  --format rgb565|rgb666  wire pixel format (default rgb565; ili9488: rgb666)\n"
    "  --mesh FILE           render a mesh file (assimp; repeatable) instead of the\n"
    "                        built-in demo scene; fitted to the unit sphere\n"
    "  --frames N            frames to render (default 1)\n"
    "  --spin DEG            per frame: mesh turn about y, or demo camera orbit in\n"
    "                        multiples of 3 degrees (default 3)\n"
    "  --mode span|zline     visibility (default span)\n"
    "  --shade flat|gouraud  shading (default gouraud)\n"
    "  --out FILE.png        the last frame as the panel shows it (default out/panel.png)\n"
    "  --seq PATTERN         every frame, e.g. out/seq/f_%03d.png\n"
    "  --window              live SDL2 window (needs a display; headless otherwise)\n"
    "  --scale N             window pixels per panel pixel (default 2)\n"
    "  --hold                keep the window open after the last frame until closed\n"
    "  --clock HZ            SPI clock for the wire time (default: the panel's rating)\n"
    "  --band N              rows per band (default 1)\n"
    "  --async               DMA-style bus: next band renders while one is on the wire\n"
    "  --max-transfer N      bytes per SPI transfer (e.g. 4096 for spidev; default none)\n"
    "  --trace               print the command bytes of the init and the first frame\n"
    "  --quiet               only errors\n";

SIM_COMMAND(panel, "panel", sim_panel_main, panel_usage)

typedef struct panel_opts {
    const char *panel, *out, *seq;
    const char **meshes;
    int nmeshes;
    long rotation, frames, band, scale, max_transfer;
    double spin, clock;
    zs_format format;
    int format_set;
    zs_visibility mode;
    zs_shading shade;
    int window, hold, async, trace, quiet, list;
} panel_opts;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static int parse(int argc, char **argv, panel_opts *o)
{
    int i, m;
    const char *v;

    memset(o, 0, sizeof *o);
    o->panel = "st7789-240x240";
    o->out = "out/panel.png";
    o->frames = 1;
    o->band = 1;
    o->scale = 2;
    o->spin = 3.0;
    o->mode = ZS_MODE_SPAN;
    o->shade = ZS_SHADE_GOURAUD;
    o->meshes = calloc((size_t)argc + 1, sizeof *o->meshes);
    if (o->meshes == NULL)
        return SIM_EXIT_FAIL;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--list") == 0) o->list = 1;
        else if (strcmp(a, "--window") == 0) o->window = 1;
        else if (strcmp(a, "--hold") == 0) o->hold = 1;
        else if (strcmp(a, "--async") == 0) o->async = 1;
        else if (strcmp(a, "--trace") == 0) o->trace = 1;
        else if (strcmp(a, "--quiet") == 0) o->quiet = 1;
        else if ((m = sim_opt_value(argc, argv, &i, "--panel", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            o->panel = v;
        } else if ((m = sim_opt_value(argc, argv, &i, "--out", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            o->out = v;
        } else if ((m = sim_opt_value(argc, argv, &i, "--seq", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            o->seq = v;
        } else if ((m = sim_opt_value(argc, argv, &i, "--mesh", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            o->meshes[o->nmeshes++] = v;
        } else if ((m = sim_opt_value(argc, argv, &i, "--rotation", &v)) != 0) {
            if (m < 0 || sim_parse_long("--rotation", v, 0, 3, &o->rotation) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--frames", &v)) != 0) {
            if (m < 0 || sim_parse_long("--frames", v, 1, 1000000, &o->frames) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--band", &v)) != 0) {
            if (m < 0 || sim_parse_long("--band", v, 1, 480, &o->band) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--scale", &v)) != 0) {
            if (m < 0 || sim_parse_long("--scale", v, 1, 8, &o->scale) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--max-transfer", &v)) != 0) {
            if (m < 0 || sim_parse_long("--max-transfer", v, 0, 1L << 24, &o->max_transfer) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--spin", &v)) != 0) {
            if (m < 0 || sim_parse_double("--spin", v, &o->spin) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = sim_opt_value(argc, argv, &i, "--clock", &v)) != 0) {
            if (m < 0 || sim_parse_double("--clock", v, &o->clock) != 0 || o->clock < 1000.0 ||
                o->clock > 4e9) {
                fprintf(stderr, "zspan-sim panel: --clock wants Hz, 1000 .. 4e9\n");
                return SIM_EXIT_USAGE;
            }
        } else if ((m = sim_opt_value(argc, argv, &i, "--format", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            if (strcmp(v, "rgb565") == 0) o->format = ZS_FMT_RGB565_BE;
            else if (strcmp(v, "rgb666") == 0) o->format = ZS_FMT_RGB666;
            else {
                fprintf(stderr, "zspan-sim panel: --format wants rgb565 or rgb666\n");
                return SIM_EXIT_USAGE;
            }
            o->format_set = 1;
        } else if ((m = sim_opt_value(argc, argv, &i, "--mode", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            if (strcmp(v, "span") == 0) o->mode = ZS_MODE_SPAN;
            else if (strcmp(v, "zline") == 0) o->mode = ZS_MODE_ZLINE;
            else {
                fprintf(stderr, "zspan-sim panel: --mode wants span or zline\n");
                return SIM_EXIT_USAGE;
            }
        } else if ((m = sim_opt_value(argc, argv, &i, "--shade", &v)) != 0) {
            if (m < 0) return SIM_EXIT_USAGE;
            if (strcmp(v, "flat") == 0) o->shade = ZS_SHADE_FLAT;
            else if (strcmp(v, "gouraud") == 0) o->shade = ZS_SHADE_GOURAUD;
            else {
                fprintf(stderr, "zspan-sim panel: --shade wants flat or gouraud\n");
                return SIM_EXIT_USAGE;
            }
        } else {
            fprintf(stderr, "zspan-sim panel: unknown option '%s' (see zspan-sim --help)\n", a);
            return SIM_EXIT_USAGE;
        }
    }
    return 0;
}

static void list_panels(void)
{
    unsigned i;
    printf("%-16s %-9s %-10s %-8s %s\n", "panel", "size", "RAM", "clock", "formats");
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        char size[16], ram[16];
        snprintf(size, sizeof size, "%ux%u", d->width, d->height);
        snprintf(ram, sizeof ram, "%ux%u", d->ram_width, d->ram_height);
        printf("%-16s %-9s %-10s %4.1f MHz %s%s\n", d->name, size, ram, d->max_spi_hz / 1e6,
               zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? "rgb565 " : "",
               zs_panel_bytes_per_pixel(d, ZS_FMT_RGB666) ? "rgb666" : "");
    }
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

/* The mesh scene: loaded, fitted to the unit sphere, quantised, coloured. */
static int load_meshes(const panel_opts *o, sim_scene *scene)
{
    int f;
    for (f = 0; f < o->nmeshes; f++)
        if (sim_scene_load(scene, o->meshes[f], o->shade == ZS_SHADE_GOURAUD) != 0)
            return -1;
    if (scene->total_tris > ZS_MAX_TRIANGLES / 3) {
        fprintf(stderr, "zspan-sim panel: %lu triangles is too many\n",
                (unsigned long)scene->total_tris);
        return -1;
    }
    return sim_scene_fit_and_colour(scene);
}

static int seq_path(char *buf, size_t n, const char *pattern, long k)
{
    int len = snprintf(buf, n, pattern, (int)k);
    return len > 0 && (size_t)len < n ? 0 : -1;
}

int sim_panel_main(int argc, char **argv)
{
    panel_opts o;
    const zs_panel_desc *d;
    const emu_model *model;
    emu_panel emu;
    emu_port port;
    zs_panel lcd;
    zs_panel_status ps;
    zs_renderer r;
    zs_config cfg;
    zs_wire_model wire;
    sim_scene scene;
    demo_scene *demo = NULL;
    emu_window *win = NULL;
    void *arena = NULL;
    uint8_t *b0 = NULL, *b1 = NULL, *rgb = NULL;
    size_t arena_size, band_bytes;
    unsigned vw, vh, bpp;
    long k, frames_done = 0;
    int rc = SIM_EXIT_FAIL, emu_ok = 0, tty = isatty(2);
    double t_total = 0.0, t_port = 0.0;
    uint64_t wire_ns_total = 0, bytes_total = 0, cmds_total = 0;
    uint32_t wire_waits = 0, max_tris;
    zs_stats last_stats;

    memset(&scene, 0, sizeof scene);
    memset(&last_stats, 0, sizeof last_stats);
    rc = parse(argc, argv, &o);
    if (rc != 0) {
        free(o.meshes);
        return rc;
    }
    rc = SIM_EXIT_FAIL;
    if (o.list) {
        list_panels();
        free(o.meshes);
        return SIM_EXIT_OK;
    }
    d = zs_panel_find(o.panel);
    model = emu_model_find(o.panel);
    if (d == NULL || model == NULL) {
        fprintf(stderr, "zspan-sim panel: unknown panel '%s' (try --list)\n", o.panel);
        free(o.meshes);
        return SIM_EXIT_USAGE;
    }
    if (!o.format_set)
        o.format = zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? ZS_FMT_RGB565_BE
                                                                : ZS_FMT_RGB666;
    if (zs_panel_bytes_per_pixel(d, o.format) == 0) {
        fprintf(stderr, "zspan-sim panel: %s does not take %s over SPI\n", d->name,
                o.format == ZS_FMT_RGB565_BE ? "rgb565" : "rgb666");
        free(o.meshes);
        return SIM_EXIT_USAGE;
    }
    wire = zs_wire_model_default(o.clock > 0 ? (uint32_t)o.clock : d->max_spi_hz);

    /* The emulated panel on a bus, and the driver's init sequence. */
    if (emu_init(&emu, model) != 0) {
        fprintf(stderr, "zspan-sim panel: out of memory\n");
        goto done;
    }
    emu_ok = 1;
    if (emu_port_init(&port, &emu, o.async, o.async ? 4u : 0u, (uint32_t)o.max_transfer) != 0)
        goto done;
    emu_record(&emu, o.trace);
    ps = zs_panel_init(&lcd, d, &port.bus, o.format, (unsigned)o.rotation);
    if (ps != ZS_PANEL_OK) {
        fprintf(stderr, "zspan-sim panel: zs_panel_init: %s\n", zs_panel_strerror(ps));
        goto done;
    }
    zs_panel_backlight(&lcd, 255);
    if (o.trace) {
        print_trace(&emu, "init (command and parameter bytes)");
        emu_record(&emu, 1);
    }

    /* The scene and the renderer, at the panel's size for this rotation. */
    if (o.nmeshes > 0) {
        if (load_meshes(&o, &scene) != 0)
            goto done;
        max_tris = scene.total_tris * 3u + 64u;
    } else {
        demo = malloc(sizeof *demo);
        if (demo == NULL)
            goto done;
        demo_scene_init(demo);
        max_tris = DEMO_TRIANGLES * 2u + 64u;
    }
    if (max_tris > ZS_MAX_TRIANGLES)
        max_tris = ZS_MAX_TRIANGLES;
    cfg = zs_config_default(lcd.width, lcd.height, (uint16_t)max_tris,
                            (uint16_t)(max_tris * 3u > ZS_MAX_VERTICES ? ZS_MAX_VERTICES
                                                                       : max_tris * 3u),
                            ZS_MAX_ACTIVE_EDGES);
    arena_size = zs_arena_bytes(&cfg);
    arena = arena_size ? malloc(arena_size) : NULL;
    if (arena == NULL || zs_init(&r, arena, arena_size, &cfg) != ZS_OK) {
        fprintf(stderr, "zspan-sim panel: cannot set up the renderer\n");
        goto done;
    }
    bpp = zs_panel_bytes_per_pixel(d, o.format);
    band_bytes = (size_t)lcd.width * bpp * (size_t)o.band;
    b0 = malloc(band_bytes);
    b1 = malloc(band_bytes);
    emu_view_size(&emu, (unsigned)o.rotation, &vw, &vh);
    rgb = malloc((size_t)vw * vh * 3);
    if (b0 == NULL || b1 == NULL || rgb == NULL)
        goto done;

    if (o.window) {
        char err[160];
        char title[96];
        snprintf(title, sizeof title, "zspan: %s rotation %ld", d->name, o.rotation);
        win = emu_window_open(title, vw, vh, (unsigned)o.scale, err, sizeof err);
        if (win == NULL && !o.quiet)
            printf("window: %s; continuing headless\n", err);
    }
    if (!o.quiet)
        printf("panel %s (%s), %ux%u at rotation %ld, %s, %s bus%s, SPI %.1f MHz, band %ld\n",
               d->name, d->ops->name, lcd.width,
               lcd.height, o.rotation, o.format == ZS_FMT_RGB565_BE ? "RGB565" : "RGB666",
               o.async ? "async (DMA)" : "blocking",
               o.max_transfer ? " (chunked)" : "", wire.clock_hz / 1e6, o.band);
    fflush(stdout);

    for (k = 0; k < o.frames; k++) {
        zs_panel_frame_stats fs;
        zs_status st;
        double t0, t1;
        uint64_t port_ns0 = port.ns_in_port;

        if (demo != NULL) {
            long step = o.spin >= 3.0 ? lround(o.spin / 3.0) : 1;
            st = demo_frame(&r, demo, (uint32_t)(k * step), o.mode, o.shade, o.format);
        } else {
            st = sim_scene_frame(&r, &scene, o.mode, o.shade, fmod(o.spin * (double)k, 360.0),
                                 o.format);
        }
        if (st != ZS_OK) {
            fprintf(stderr, "zspan-sim panel: frame %ld: %s\n", k, zs_strerror(st));
            goto done;
        }
        t0 = now_s();
        ps = zs_panel_stream(&lcd, &r, b0, b1, band_bytes, (int)o.band, &wire, &fs);
        t1 = now_s();
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, "zspan-sim panel: frame %ld: %s (%s)\n", k, zs_panel_strerror(ps),
                    zs_strerror(fs.render_status));
            goto done;
        }
        if (o.trace && k == 0) {
            emu_flush(&emu);
            print_trace(&emu, "frame 0");
            emu_record(&emu, 0);
        }
        t_total += t1 - t0;
        t_port += (double)(port.ns_in_port - port_ns0) / 1e9;
        wire_ns_total += fs.wire_ns;
        bytes_total += fs.bytes;
        cmds_total += fs.bus.commands;
        wire_waits += fs.wire_waits;
        last_stats = *zs_frame_stats(&r);
        frames_done++;
        if (o.seq != NULL) {
            char path[1024];
            if (seq_path(path, sizeof path, o.seq, k) != 0 || sim_make_parent_dirs(path) != 0 ||
                emu_write_png(&emu, (unsigned)o.rotation, path) != 0) {
                fprintf(stderr, "zspan-sim panel: cannot write frame %ld (%s)\n", k, o.seq);
                goto done;
            }
        }
        if (win != NULL) {
            emu_view_rgb(&emu, (unsigned)o.rotation, rgb);
            emu_window_show(win, rgb, vw, vh);
            if (emu_window_poll(win))
                break;
        }
        if (!o.quiet && o.frames > 1 &&
            (tty ? 1 : (k + 1) % (o.frames >= 10 ? o.frames / 10 : 1) == 0 || k + 1 == o.frames)) {
            fprintf(stderr, "%sframe %ld/%ld  render %.2f ms  wire %.2f ms%s", tty ? "\r" : "",
                    k + 1, o.frames, (t1 - t0 - (double)(port.ns_in_port - port_ns0) / 1e9) * 1e3,
                    fs.wire_ns / 1e6, tty ? "   " : "\n");
            fflush(stderr);
        }
    }
    if (!o.quiet && o.frames > 1 && tty)
        fputc('\n', stderr);
    emu_port_drain(&port);
    emu_flush(&emu);

    if (o.out != NULL && o.out[0] != '\0') {
        if (sim_make_parent_dirs(o.out) != 0 || emu_write_png(&emu, (unsigned)o.rotation, o.out) != 0) {
            fprintf(stderr, "zspan-sim panel: cannot write %s\n", o.out);
            goto done;
        }
    }
    if (!o.quiet && frames_done > 0) {
        double render_ms = (t_total - t_port) * 1e3 / (double)frames_done;
        double wire_ms = (double)wire_ns_total / 1e6 / (double)frames_done;
        printf("last frame:\n");
        sim_print_stats(stdout, &last_stats);
        printf("wire per frame: %.0f bytes, %.1f commands -> %.2f ms at %.1f MHz "
               "(bytes x 8 / clock + %u ns per command + %u ns per transfer)\n",
               (double)bytes_total / (double)frames_done,
               (double)cmds_total / (double)frames_done, wire_ms, wire.clock_hz / 1e6,
               wire.cmd_overhead_ns, wire.transfer_overhead_ns);
        printf("render per frame (this host, emulator time excluded): %.2f ms\n", render_ms);
        printf("frame rate limit: wire %.1f fps, renderer %.1f fps -> %s-bound on this host\n",
               wire_ms > 0 ? 1e3 / wire_ms : 0.0, render_ms > 0 ? 1e3 / render_ms : 0.0,
               render_ms > wire_ms ? "renderer" : "wire");
        if (o.async)
            printf("async bus: %u bands found the wire still busy over %ld frames\n", wire_waits,
                   frames_done);
        printf("emulated %s: %llu bytes in, %llu pixels written, %u window wraps, %u errors\n",
               d->name, (unsigned long long)emu.bytes_in, (unsigned long long)emu.pixels,
               (unsigned)emu.wraps, (unsigned)emu.error_count);
        if (o.out != NULL && o.out[0] != '\0')
            printf("wrote %s%s%s\n", o.out, o.seq ? " and the sequence " : "",
                   o.seq ? o.seq : "");
    }
    if (emu.errors != 0 || port.violations != 0) {
        unsigned i;
        for (i = 0; i < emu.log_lines; i++)
            fprintf(stderr, "zspan-sim panel: protocol error: %s\n", emu.log[i]);
        if (port.violations)
            fprintf(stderr, "zspan-sim panel: bus contract: %s\n", port.violation);
        goto done;
    }
    if (win != NULL && o.hold) {
        if (!o.quiet)
            printf("window open: close it or press q / Escape\n");
        while (!emu_window_poll(win)) {
            struct timespec ts = {0, 20000000};
            nanosleep(&ts, NULL);
        }
    }
    rc = SIM_EXIT_OK;
done:
    if (win != NULL)
        emu_window_close(win);
    if (emu_ok) {
        emu_port_drain(&port);
        emu_free(&emu);
    }
    sim_scene_free(&scene);
    free(demo);
    free(arena);
    free(b0);
    free(b1);
    free(rgb);
    free(o.meshes);
    return rc;
}
