/* Shared frame loop of zspan-linux and zspan-mcp2210 (see zs_app.h). */
#define _GNU_SOURCE
#include "zs_app.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "demo_scene.h"
#include "zspan/panel.h"
#ifndef ZS_APP_NO_MESH
#include "mesh_load.h"
#endif

const char zs_app_usage[] =
    "Panel and picture:\n"
    "  --panel NAME          st7789-240x240 (default); --list shows the panels\n"
    "  --rotation 0..3       quarter turns clockwise (default 0)\n"
    "  --format rgb565|rgb666  wire pixel format (default rgb565; ili9488: rgb666)\n"
    "  --mesh FILE           a mesh file (assimp formats; repeatable) instead of the demo\n"
    "  --frames N            frames to send (default 1; 0 = until Ctrl-C)\n"
    "  --start N             first demo frame (default 0)\n"
    "  --spin DEG            turn per frame (demo: camera orbit, multiples of 3; default 3)\n"
    "  --mode span|zline     visibility (default span)\n"
    "  --shade flat|gouraud  shading (default gouraud)\n"
    "  --band N              rows per band (default 16)\n"
    "  --partial             after the first frame send only the rows that changed\n"
    "                        (narrowed to the changed columns)\n"
    "  --brightness 0..255   backlight level (GPIO backlight: 0 off, else on; default 255)\n"
    "  --quiet               only errors\n";

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

int zs_opt_value(int argc, char **argv, int *i, const char *name, const char **value,
                 const char *prog)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0)
        return 0;
    if (a[n] == '=') {
        *value = a + n + 1;
        return 1;
    }
    if (a[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "%s: %s needs a value\n", prog, name);
        return -1;
    }
    *i += 1;
    *value = argv[*i];
    return 1;
}

int zs_opt_long(const char *prog, const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 0);
    if (errno != 0 || end == s || *end != '\0' || v < lo || v > hi) {
        fprintf(stderr, "%s: %s wants an integer in %ld..%ld, not '%s'\n", prog, opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

void zs_app_defaults(zs_app_opts *o, int argc)
{
    memset(o, 0, sizeof *o);
    o->panel = "st7789-240x240";
    o->frames = 1;
    o->band = 16;
    o->spin = 3.0;
    o->mode = ZS_MODE_SPAN;
    o->shade = ZS_SHADE_GOURAUD;
    o->backlight = 255;
    o->meshes = calloc((size_t)argc + 1, sizeof *o->meshes);
}

void zs_app_free(zs_app_opts *o)
{
    free(o->meshes);
    o->meshes = NULL;
}

int zs_app_option(int argc, char **argv, int *i, zs_app_opts *o, const char *prog)
{
    const char *a = argv[*i], *v;
    int m;
    if (strcmp(a, "--partial") == 0) { o->partial = 1; return 1; }
    if (strcmp(a, "--quiet") == 0) { o->quiet = 1; return 1; }
    if (strcmp(a, "--list") == 0) { o->list = 1; return 1; }
#define LONG_OPT(name, lo, hi, field)                                                          \
    if ((m = zs_opt_value(argc, argv, i, name, &v, prog)) != 0)                                \
        return m < 0 || zs_opt_long(prog, name, v, lo, hi, &o->field) != 0 ? -1 : 1;
    LONG_OPT("--rotation", 0, 3, rotation)
    LONG_OPT("--frames", 0, 100000000L, frames)
    LONG_OPT("--start", 0, 1000000L, start_frame)
    LONG_OPT("--band", 1, 2048, band)
    LONG_OPT("--brightness", 0, 255, backlight)
#undef LONG_OPT
    if ((m = zs_opt_value(argc, argv, i, "--panel", &v, prog)) != 0) {
        o->panel = v;
        return m;
    }
    if ((m = zs_opt_value(argc, argv, i, "--mesh", &v, prog)) != 0) {
        if (m > 0)
            o->meshes[o->nmeshes++] = v;
        return m;
    }
    if ((m = zs_opt_value(argc, argv, i, "--spin", &v, prog)) != 0) {
        char *end;
        if (m < 0)
            return -1;
        o->spin = strtod(v, &end);
        if (end == v || *end != '\0' || !(o->spin > -3600.0 && o->spin < 3600.0)) {
            fprintf(stderr, "%s: --spin wants degrees, not '%s'\n", prog, v);
            return -1;
        }
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--format", &v, prog)) != 0) {
        if (m < 0)
            return -1;
        if (strcmp(v, "rgb565") == 0) o->format = ZS_FMT_RGB565_BE;
        else if (strcmp(v, "rgb666") == 0) o->format = ZS_FMT_RGB666;
        else {
            fprintf(stderr, "%s: --format wants rgb565 or rgb666\n", prog);
            return -1;
        }
        o->format_set = 1;
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--mode", &v, prog)) != 0) {
        if (m < 0)
            return -1;
        if (strcmp(v, "span") == 0) o->mode = ZS_MODE_SPAN;
        else if (strcmp(v, "zline") == 0) o->mode = ZS_MODE_ZLINE;
        else {
            fprintf(stderr, "%s: --mode wants span or zline\n", prog);
            return -1;
        }
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--shade", &v, prog)) != 0) {
        if (m < 0)
            return -1;
        if (strcmp(v, "flat") == 0) o->shade = ZS_SHADE_FLAT;
        else if (strcmp(v, "gouraud") == 0) o->shade = ZS_SHADE_GOURAUD;
        else {
            fprintf(stderr, "%s: --shade wants flat or gouraud\n", prog);
            return -1;
        }
        return 1;
    }
    return 0;
}

void zs_app_list_panels(FILE *f)
{
    unsigned i;
    fprintf(f, "%-16s %-9s %-9s %s\n", "panel", "size", "max clock", "formats");
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        char size[24];
        snprintf(size, sizeof size, "%ux%u", d->width, d->height);
        fprintf(f, "%-16s %-9s %5.1f MHz %s%s\n", d->name, size, d->max_spi_hz / 1e6,
                zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? "rgb565 " : "",
                zs_panel_bytes_per_pixel(d, ZS_FMT_RGB666) ? "rgb666" : "");
    }
}

/* ---- scenes ------------------------------------------------------------------- */

typedef struct scene {
    demo_scene *demo;
#ifndef ZS_APP_NO_MESH
    sim_scene mesh;
    int have_mesh;
#endif
    uint32_t max_tris;
} scene;

static int scene_load(scene *s, const zs_app_opts *o, const char *prog)
{
    memset(s, 0, sizeof *s);
    if (o->nmeshes == 0) {
        s->demo = malloc(sizeof *s->demo);
        if (s->demo == NULL)
            return -1;
        demo_scene_init(s->demo);
        s->max_tris = DEMO_TRIANGLES * 2u + 64u;
        return 0;
    }
#ifdef ZS_APP_NO_MESH
    fprintf(stderr, "%s: built without mesh loading (assimp)\n", prog);
    return -1;
#else
    {
        int f;
        s->have_mesh = 1;
        for (f = 0; f < o->nmeshes; f++)
            if (sim_scene_load(&s->mesh, o->meshes[f], o->shade == ZS_SHADE_GOURAUD) != 0)
                return -1;
        if (s->mesh.total_tris == 0 || s->mesh.total_tris > ZS_MAX_TRIANGLES / 3) {
            fprintf(stderr, "%s: %lu triangles: need 1..%u\n", prog,
                    (unsigned long)s->mesh.total_tris, ZS_MAX_TRIANGLES / 3);
            return -1;
        }
        if (sim_scene_fit_and_colour(&s->mesh) != 0)
            return -1;
        s->max_tris = s->mesh.total_tris * 3u + 64u;
        return 0;
    }
#endif
}

static void scene_free(scene *s)
{
    free(s->demo);
#ifndef ZS_APP_NO_MESH
    if (s->have_mesh)
        sim_scene_free(&s->mesh);
#endif
}

static zs_status scene_frame(zs_renderer *r, const scene *s, const zs_app_opts *o, long k,
                             zs_format fmt)
{
    if (s->demo != NULL) {
        long step = o->spin >= 3.0 ? lround(o->spin / 3.0) : (o->spin > 0.0 ? 1 : 0);
        return demo_frame(r, s->demo, (uint32_t)(o->start_frame + k * step), o->mode, o->shade,
                          fmt);
    }
#ifdef ZS_APP_NO_MESH
    return ZS_ERR_STATE;
#else
    return sim_scene_frame(r, &s->mesh, o->mode, o->shade,
                           fmod(o->spin * (double)(k + o->start_frame), 360.0), fmt);
#endif
}

/* ---- partial updates ---------------------------------------------------------- */

/* Sends the rectangles of `cur` that differ from `prev` (everything when
 * prev is NULL): runs of changed rows (gaps of up to 2 unchanged rows are
 * merged, as a new window costs more than two short rows), each narrowed to
 * the columns that changed in it. Returns rows sent, or -1 on a bus error. */
static long send_changes(zs_panel *lcd, const uint8_t *cur, const uint8_t *prev, size_t stride,
                         unsigned bpp, uint8_t *tmp, size_t tmp_bytes, zs_panel_status *ps)
{
    unsigned w = lcd->width, h = lcd->height, y = 0;
    long rows_sent = 0;
    while (y < h) {
        unsigned y0, y1, x0 = w, x1 = 0, gap = 0, yy;
        /* Find the next changed row. */
        while (y < h && prev != NULL && memcmp(cur + y * stride, prev + y * stride, stride) == 0)
            y++;
        if (y >= h)
            break;
        y0 = y;
        y1 = y;
        for (; y < h; y++) {
            const uint8_t *a = cur + y * stride, *b = prev != NULL ? prev + y * stride : NULL;
            unsigned first, last;
            if (b != NULL && memcmp(a, b, stride) == 0) {
                if (++gap > 2)
                    break;
                continue;
            }
            gap = 0;
            y1 = y + 1;
            if (b == NULL) {
                first = 0;
                last = w - 1;
            } else {
                for (first = 0; memcmp(a + first * bpp, b + first * bpp, bpp) == 0; first++) {
                }
                for (last = w - 1; memcmp(a + last * bpp, b + last * bpp, bpp) == 0; last--) {
                }
            }
            if (first < x0)
                x0 = first;
            if (last + 1 > x1)
                x1 = last + 1;
        }
        y = y1;
        *ps = zs_panel_window(lcd, (uint16_t)x0, (uint16_t)y0, (uint16_t)x1, (uint16_t)y1);
        if (*ps != ZS_PANEL_OK)
            return -1;
        {
            size_t row_bytes = (size_t)(x1 - x0) * bpp, used = 0;
            for (yy = y0; yy < y1; yy++) {
                if (used + row_bytes > tmp_bytes) {
                    if ((*ps = zs_panel_write(lcd, tmp, used)) != ZS_PANEL_OK)
                        return -1;
                    used = 0;
                }
                memcpy(tmp + used, cur + yy * stride + (size_t)x0 * bpp, row_bytes);
                used += row_bytes;
            }
            if (used > 0 && (*ps = zs_panel_write(lcd, tmp, used)) != ZS_PANEL_OK)
                return -1;
        }
        rows_sent += (long)(y1 - y0);
    }
    return rows_sent;
}

/* ---- the run -------------------------------------------------------------------- */

static const char *port_error(const zs_app_port *port)
{
    const char *e = port->error != NULL ? port->error(port->ctx) : NULL;
    return e != NULL && e[0] != '\0' ? e : "bus failure";
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
    scene sc;
    void *arena = NULL;
    uint8_t *b0 = NULL, *cur = NULL, *prev = NULL, *tmp = NULL;
    size_t arena_size, band_bytes, stride, frame_bytes;
    unsigned bpp;
    long k, band = o->band, frames_done = 0;
    int rc = 1, have_prev = 0;
    double t_start, t_all = 0.0;
    uint64_t bytes_all = 0;
    uint32_t max_tris;

    memset(&sc, 0, sizeof sc);
    if (d == NULL) {
        fprintf(stderr, "%s: unknown panel '%s' (--list shows them)\n", prog, o->panel);
        return 2;
    }
    fmt = o->format_set ? o->format
                        : (zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? ZS_FMT_RGB565_BE
                                                                         : ZS_FMT_RGB666);
    bpp = zs_panel_bytes_per_pixel(d, fmt);
    if (bpp == 0) {
        fprintf(stderr, "%s: %s does not take %s over SPI\n", prog, d->name,
                fmt == ZS_FMT_RGB565_BE ? "rgb565" : "rgb666");
        return 2;
    }
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
               fmt == ZS_FMT_RGB565_BE ? "RGB565" : "RGB666", port->name,
               (now_s() - t_start) * 1e3);

    if (scene_load(&sc, o, prog) != 0)
        goto done;
    max_tris = sc.max_tris > ZS_MAX_TRIANGLES ? ZS_MAX_TRIANGLES : sc.max_tris;
    cfg = zs_config_default(lcd.width, lcd.height, (uint16_t)max_tris,
                            (uint16_t)(max_tris * 3u > ZS_MAX_VERTICES ? ZS_MAX_VERTICES
                                                                       : max_tris * 3u),
                            ZS_MAX_ACTIVE_EDGES);
    arena_size = zs_arena_bytes(&cfg);
    arena = arena_size ? malloc(arena_size) : NULL;
    if (arena == NULL || zs_init(&r, arena, arena_size, &cfg) != ZS_OK) {
        fprintf(stderr, "%s: cannot set up the renderer\n", prog);
        goto done;
    }
    stride = (size_t)lcd.width * bpp;
    if (band > lcd.height)
        band = lcd.height;
    band_bytes = stride * (size_t)band;
    frame_bytes = stride * lcd.height;
    b0 = malloc(band_bytes);
    tmp = malloc(band_bytes);
    if (o->partial) {
        cur = malloc(frame_bytes);
        prev = malloc(frame_bytes);
    }
    if (b0 == NULL || tmp == NULL || (o->partial && (cur == NULL || prev == NULL))) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto done;
    }
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);

    for (k = 0; o->frames == 0 || k < o->frames; k++) {
        zs_bus_counters c0 = bus->count, c1;
        zs_status st;
        double t0 = now_s(), t1;
        long rows = lcd.height;
        uint32_t bytes;
        if (stop_flag)
            break;
        st = scene_frame(&r, &sc, o, k, fmt);
        if (st != ZS_OK) {
            fprintf(stderr, "%s: frame %ld: %s\n", prog, k, zs_strerror(st));
            goto done;
        }
        if (!o->partial) {
            zs_panel_frame_stats fs;
            ps = zs_panel_stream(&lcd, &r, b0, NULL, band_bytes, (int)band, &wire, &fs);
            if (ps == ZS_PANEL_ERR_RENDER) {
                fprintf(stderr, "%s: frame %ld: %s\n", prog, k, zs_strerror(fs.render_status));
                goto done;
            }
        } else {
            int y;
            for (y = 0; y < lcd.height; y += (int)band) {
                int n = lcd.height - y < band ? lcd.height - y : (int)band;
                st = zs_render_rows(&r, y, n, cur + (size_t)y * stride, stride);
                if (st != ZS_OK) {
                    fprintf(stderr, "%s: frame %ld: %s\n", prog, k, zs_strerror(st));
                    goto done;
                }
            }
            ps = ZS_PANEL_OK;
            rows = send_changes(&lcd, cur, have_prev ? prev : NULL, stride, bpp, tmp, band_bytes,
                                &ps);
            if (rows >= 0) {
                uint8_t *t = prev;
                prev = cur;
                cur = t;
                have_prev = 1;
            }
        }
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, "%s: frame %ld: %s: %s\n", prog, k, zs_panel_strerror(ps),
                    ps == ZS_PANEL_ERR_IO ? port_error(port) : "driver error");
            rc = ps == ZS_PANEL_ERR_IO ? ZS_APP_EXIT_BUS : 1;
            goto done;
        }
        t1 = now_s();
        c1 = bus->count;
        {
            zs_bus_counters dc = zs_bus_counters_diff(&c1, &c0);
            bytes = zs_bus_counters_bytes(&dc);
        }
        t_all += t1 - t0;
        bytes_all += bytes;
        frames_done++;
        if (!o->quiet)
            printf("frame %ld: %ld rows, %u bytes, %.1f ms (%.1f KB/s)\n", k, rows, bytes,
                   (t1 - t0) * 1e3, (t1 - t0) > 0 ? bytes / (t1 - t0) / 1e3 : 0.0);
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
    scene_free(&sc);
    free(arena);
    free(b0);
    free(tmp);
    free(cur);
    free(prev);
    return rc;
}
