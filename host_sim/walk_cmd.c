/* SPDX-License-Identifier: MIT */
/*
 * zspan-sim walk LEVEL: flies a scripted path through a portal level
 * (tools/level, zspan/portal.h) and writes one PNG per frame, with the
 * portal walk's statistics per frame. The path runs from cell 0 to the cell
 * farthest from it (in portal steps) through the midpoints of the portals
 * on the way, at a height every cell's opening allows (lv_flight). With
 * --window (SDL2) it opens a window at the path's start instead and the
 * arrow keys move the camera (every frame still written and compared).
 */
#include "level.h"
#include "png_out.h"
#include "sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if defined(__has_include)
#if __has_include(<SDL2/SDL.h>)
#define WALK_HAVE_SDL 1
#include <SDL2/SDL.h>
#endif
#endif

typedef struct walk_opts {
    const char *level, *out;
    int frames, width, height;
    zs_visibility mode;
    zs_level_cull cull;
    int compare, quiet, window;
    const char *keys; /* --keys: arrow keys to replay in the window (tests) */
} walk_opts;

static int walk_usage(void)
{
    fprintf(stderr, "usage: " SIM_PROG " walk LEVEL [--out DIR] [--frames N] [--size WxH]\n"
                    "       [--mode span|zline] [--cull none|pvs|portals] [--no-compare] [--quiet]\n"
                    "       [--window [--keys UDLR...]]\n");
    return SIM_EXIT_USAGE;
}

static int parse_opts(int argc, char **argv, walk_opts *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->out = "out/walk";
    o->frames = 48;
    o->width = 240;
    o->height = 180;
    o->mode = ZS_MODE_SPAN;
    o->cull = ZS_LEVEL_CULL_PORTALS;
    o->compare = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--out") && v) {
            o->out = v;
            i++;
        } else if (!strcmp(a, "--frames") && v) {
            o->frames = atoi(v);
            i++;
            if (o->frames < 1 || o->frames > 100000)
                return -1;
        } else if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &o->width, &o->height) != 2 || o->width < 1 ||
                o->height < 1 || o->width > ZS_MAX_DIM || o->height > ZS_MAX_DIM)
                return -1;
            i++;
        } else if (!strcmp(a, "--mode") && v) {
            if (!strcmp(v, "span"))
                o->mode = ZS_MODE_SPAN;
            else if (!strcmp(v, "zline"))
                o->mode = ZS_MODE_ZLINE;
            else
                return -1;
            i++;
        } else if (!strcmp(a, "--cull") && v) {
            if (!strcmp(v, "none"))
                o->cull = ZS_LEVEL_CULL_NONE;
            else if (!strcmp(v, "pvs"))
                o->cull = ZS_LEVEL_CULL_PVS;
            else if (!strcmp(v, "portals"))
                o->cull = ZS_LEVEL_CULL_PORTALS;
            else
                return -1;
            i++;
        } else if (!strcmp(a, "--no-compare")) {
            o->compare = 0;
        } else if (!strcmp(a, "--window")) {
            o->window = 1;
        } else if (!strcmp(a, "--keys") && v) {
            if (strspn(v, "UDLR") != strlen(v))
                return -1;
            o->keys = v;
            i++;
        } else if (!strcmp(a, "--quiet")) {
            o->quiet = 1;
        } else if (a[0] != '-' && !o->level) {
            o->level = a;
        } else {
            return -1;
        }
    }
    return o->level ? 0 : -1;
}

static zs_fixed fx(double v)
{
    return (zs_fixed)lround(v * 65536.0);
}

static int render(zs_renderer *r, const zs_level *lv, const zs_camera *cam, zs_vec3 eye,
                  const walk_opts *o, zs_level_cull cull, uint8_t *img, zs_level_stats *ls)
{
    zs_shade_params sp = zs_shade_default();
    zs_status st;
    sp.format = ZS_FMT_RGB888;
    sp.background = ZS_RGB(20, 20, 40);
    if ((st = zs_frame_begin(r, cam, o->mode)) != ZS_OK || (st = zs_frame_shading(r, &sp)) != ZS_OK ||
        (st = zs_level_draw(r, lv, eye, cull, ls)) != ZS_OK ||
        (st = sim_render_image(r, img, (size_t)o->width * 3, o->height, 1)) != ZS_OK) {
        fprintf(stderr, SIM_PROG " walk: %s\n", zs_strerror(st));
        return -1;
    }
    return 0;
}

/* What one walk renders into and counts. */
typedef struct walk_ctx {
    const walk_opts *o;
    const zs_level *lv;
    zs_renderer r;
    uint8_t *img, *ref;
    unsigned long sum_sub, sum_cull;
    int differ, frames;
} walk_ctx;

/* One frame from eye toward tgt (world, doubles): render, write the PNG,
 * compare with every cell, print the statistics. 0, or -1 after a message. */
static int walk_frame(walk_ctx *w, const double e[3], const double t[3])
{
    const walk_opts *o = w->o;
    zs_camera cam;
    zs_vec3 eye = zs_vec3_make(fx(e[0]), fx(e[1]), fx(e[2]));
    zs_vec3 tgt = zs_vec3_make(fx(t[0]), fx(t[1]), fx(t[2]));
    zs_level_stats ls;
    char path[1024];
    int f = w->frames++, same = 1;
    size_t bytes = (size_t)o->width * o->height * 3;
    if (getenv("ZS_WALK_TRACE"))
        printf("frame %d: eye %.17g %.17g %.17g target %.17g %.17g %.17g (world)\n", f, e[0], e[1],
               e[2], t[0], t[1], t[2]);
    if (zs_camera_look_at(&cam, eye, tgt, zs_vec3_make(0, ZS_FX_ONE, 0)) != ZS_OK ||
        zs_camera_perspective(&cam, ZS_FX(70), ZS_FX_ONE / 20, ZS_FX(200)) != ZS_OK) {
        fprintf(stderr, SIM_PROG " walk: bad camera at frame %d\n", f);
        return -1;
    }
    if (render(&w->r, w->lv, &cam, eye, o, o->cull, w->img, &ls) != 0)
        return -1;
    w->sum_sub += ls.tris_submitted;
    w->sum_cull += ls.tris_culled;
    snprintf(path, sizeof path, "%s/frame%04d.png", o->out, f);
    if (sim_make_parent_dirs(path) != 0 ||
        png_write_rgb8(path, o->width, o->height, w->img, (size_t)o->width * 3) != 0)
        return -1;
    if (o->compare) {
        zs_level_stats all;
        if (render(&w->r, w->lv, &cam, eye, o, ZS_LEVEL_CULL_NONE, w->ref, &all) != 0)
            return -1;
        same = memcmp(w->img, w->ref, bytes) == 0;
        w->differ += !same;
    }
    if (!o->quiet)
        printf("frame %d: cell %d pvs %u visited %u portals %u drawn %u tris %u culled %u%s%s\n", f,
               (int)ls.eye_cell, (unsigned)ls.pvs_cells, (unsigned)ls.cells_visited,
               (unsigned)ls.portals_tested, (unsigned)ls.cells_drawn, (unsigned)ls.tris_submitted,
               (unsigned)ls.tris_culled, ls.fallback ? " (fallback)" : "",
               o->compare ? (same ? " same" : " DIFFERS") : "");
    return 0;
}

#ifdef WALK_HAVE_SDL
/* Is every point within 0.1 world units of e (8 directions) in some cell?
 * Then no wall is nearer than the near plane's corners (fov 70, near 0.05). */
static int room_around(const zs_level *lv, const double e[3])
{
    int k;
    for (k = 0; k < 8; k++) {
        double a = k * 3.14159265358979 / 4;
        zs_vec3 p = zs_vec3_make(fx(e[0] + 0.1 * cos(a)), fx(e[1]), fx(e[2] + 0.1 * sin(a)));
        if (zs_level_find_cell(lv, p) < 0)
            return 0;
    }
    return zs_level_find_cell(lv, zs_vec3_make(fx(e[0]), fx(e[1]), fx(e[2]))) >= 0;
}

/* Arrow keys: up/down move 0.15 units along the view, left/right turn 5
 * degrees; a step that would come within 0.1 units of a wall is refused.
 * Escape or q ends.
 * keys (U, D, L, R) are queued first, and then the walk ends by itself. */
static int walk_window(walk_ctx *w, const double e0[3], const double t0[3], const char *keys)
{
    const walk_opts *o = w->o;
    double e[3] = {e0[0], e0[1], e0[2]}, yaw = atan2(-(t0[2] - e0[2]), t0[0] - e0[0]);
    SDL_Window *win;
    int quit = 0, dirty = 1, rc = 0;
    const int scale = 2;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, SIM_PROG " walk: no window: %s\n", SDL_GetError());
        return -1;
    }
    win = SDL_CreateWindow("zspan walk", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                           o->width * scale, o->height * scale, 0);
    if (!win || !SDL_GetWindowSurface(win)) {
        fprintf(stderr, SIM_PROG " walk: no window: %s\n", SDL_GetError());
        SDL_Quit();
        return -1;
    }
    for (; keys && *keys; keys++) {
        SDL_Event ev;
        memset(&ev, 0, sizeof ev);
        ev.type = SDL_KEYDOWN;
        ev.key.keysym.sym = *keys == 'U' ? SDLK_UP : *keys == 'D' ? SDLK_DOWN
                            : *keys == 'L' ? SDLK_LEFT : SDLK_RIGHT;
        SDL_PushEvent(&ev);
    }
    if (keys) {
        SDL_Event ev;
        memset(&ev, 0, sizeof ev);
        ev.type = SDL_QUIT;
        SDL_PushEvent(&ev);
    }
    while (!quit && rc == 0) {
        SDL_Event ev;
        if (dirty) {
            double t[3] = {e[0] + cos(yaw), e[1] * 0.95, e[2] - sin(yaw)};
            SDL_Surface *s = SDL_GetWindowSurface(win);
            int x, y;
            dirty = 0;
            if (walk_frame(w, e, t) != 0) {
                rc = -1;
                break;
            }
            if (s && SDL_LockSurface(s) == 0) {
                for (y = 0; y < s->h && y < o->height * scale; y++)
                    for (x = 0; x < s->w && x < o->width * scale; x++) {
                        const uint8_t *p = w->img + ((size_t)(y / scale) * o->width + x / scale) * 3;
                        *(uint32_t *)((uint8_t *)s->pixels + (size_t)y * s->pitch + 4 * x) =
                            SDL_MapRGB(s->format, p[0], p[1], p[2]);
                    }
                SDL_UnlockSurface(s);
                SDL_UpdateWindowSurface(win);
            }
        }
        if (!SDL_WaitEvent(&ev))
            break;
        if (ev.type == SDL_QUIT)
            quit = 1;
        else if (ev.type == SDL_KEYDOWN) {
            SDL_Keycode k = ev.key.keysym.sym;
            double step = k == SDLK_UP ? 0.15 : k == SDLK_DOWN ? -0.15 : 0;
            if (k == SDLK_ESCAPE || k == SDLK_q)
                quit = 1;
            else if (k == SDLK_LEFT || k == SDLK_RIGHT) {
                yaw += (k == SDLK_LEFT ? 5.0 : -5.0) * 3.14159265358979 / 180;
                dirty = 1;
            } else if (step != 0) {
                double n[3] = {e[0] + step * cos(yaw), e[1], e[2] - step * sin(yaw)};
                if (room_around(w->lv, n)) {
                    memcpy(e, n, sizeof e);
                    dirty = 1;
                }
            }
        }
    }
    SDL_DestroyWindow(win);
    SDL_Quit();
    return rc;
}
#endif

static int run_walk(int argc, char **argv)
{
    walk_opts o;
    lv_level lv;
    lv_built b;
    char err[512];
    double (*pe)[3] = NULL, (*pt)[3] = NULL;
    int f, rc = SIM_EXIT_OK;
    void *arena;
    walk_ctx w;
    zs_config cfg;
    if (parse_opts(argc, argv, &o) != 0)
        return walk_usage();
#ifndef WALK_HAVE_SDL
    if (o.window) {
        fprintf(stderr, SIM_PROG " walk: --window: built without SDL2\n");
        return SIM_EXIT_FAIL;
    }
#endif
    if (lv_load(o.level, &lv, err, sizeof err) != 0) {
        fprintf(stderr, SIM_PROG " walk: %s\n", err);
        return SIM_EXIT_FAIL;
    }
    if (lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err) != 0) {
        fprintf(stderr, SIM_PROG " walk: %s: %s\n", o.level, err);
        lv_free(&lv);
        return SIM_EXIT_FAIL;
    }
    lv_free(&lv);
    memset(&w, 0, sizeof w);
    w.o = &o;
    w.lv = &b.level;
    cfg = zs_config_default((uint16_t)o.width, (uint16_t)o.height,
                            (uint16_t)(b.total_tris * 2 > 65535 ? 65535 : b.total_tris * 2),
                            (uint16_t)(b.total_tris * 3 > 65535 ? 65535 : b.total_tris * 3), 1024);
    arena = malloc(zs_arena_bytes(&cfg));
    w.img = malloc((size_t)o.width * o.height * 3);
    w.ref = malloc((size_t)o.width * o.height * 3);
    if (zs_init(&w.r, arena, zs_arena_bytes(&cfg), &cfg) != ZS_OK) {
        fprintf(stderr, SIM_PROG " walk: cannot initialise the renderer\n");
        rc = SIM_EXIT_FAIL;
        goto done;
    }
    pe = malloc(sizeof *pe * (size_t)o.frames);
    pt = malloc(sizeof *pt * (size_t)o.frames);
    if (lv_flight(&b.level, o.frames, pe, pt) != 0) {
        fprintf(stderr, SIM_PROG " walk: no height is open in every cell: no path to fly\n");
        rc = SIM_EXIT_FAIL;
        goto done;
    }
#ifdef WALK_HAVE_SDL
    if (o.window) {
        if (walk_window(&w, pe[0], pt[0], o.keys) != 0)
            rc = SIM_EXIT_FAIL;
    } else
#endif
        for (f = 0; f < o.frames && rc == SIM_EXIT_OK; f++)
            if (walk_frame(&w, pe[f], pt[f]) != 0)
                rc = SIM_EXIT_FAIL;
    if (rc == SIM_EXIT_OK && !o.quiet)
        printf("%d frames in %s/: %.1f%% of the triangles never transformed%s\n", w.frames, o.out,
               100.0 * (double)w.sum_cull /
                   (double)(w.sum_cull + w.sum_sub ? w.sum_cull + w.sum_sub : 1),
               o.compare ? (w.differ ? "; SOME FRAMES DIFFER from drawing every cell"
                                     : "; every frame equals drawing every cell")
                         : "");
    if (rc == SIM_EXIT_OK && w.differ)
        rc = SIM_EXIT_FAIL;
done:
    free(pe);
    free(pt);
    free(arena);
    free(w.img);
    free(w.ref);
    lv_built_free(&b);
    return rc;
}

SIM_COMMAND(walk, "walk", run_walk,
            "  walk LEVEL [--out DIR] [--frames N] [--size WxH] [--mode span|zline]\n"
            "       [--cull none|pvs|portals] [--no-compare] [--quiet] [--window [--keys UDLR...]]\n"
            "                        fly through a portal level (zspan-level), PNG per frame\n")
