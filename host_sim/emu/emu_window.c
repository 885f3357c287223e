/* SPDX-License-Identifier: MIT */
/* SDL2 window for the emulated panels. */
#include "emu_window.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__has_include)
#if __has_include(<SDL2/SDL.h>)
#define EMU_HAVE_SDL 1
#endif
#endif

#ifdef EMU_HAVE_SDL
#include <SDL2/SDL.h>
#include <SDL2/SDL_syswm.h>

struct emu_window {
    SDL_Window *win;
    unsigned scale;
    unsigned w, h;        /* picture size */
    uint8_t *last;        /* last picture, for redraws */
};

emu_window *emu_window_open(const char *title, unsigned w, unsigned h, unsigned scale, char *err,
                            size_t errlen)
{
    emu_window *ew;
    const char *display = getenv("DISPLAY");
    const char *wayland = getenv("WAYLAND_DISPLAY");

    if ((display == NULL || display[0] == '\0') && (wayland == NULL || wayland[0] == '\0')) {
        snprintf(err, errlen, "no display (DISPLAY is not set)");
        return NULL;
    }
    if (scale == 0)
        scale = 1;
    /* A plain X11/Wayland framebuffer: no GL renderer behind the surface
     * (SDL would otherwise re-create the window for it, changing its id). */
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        snprintf(err, errlen, "SDL video: %s", SDL_GetError());
        return NULL;
    }
    ew = calloc(1, sizeof *ew);
    if (ew == NULL) {
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    ew->scale = scale;
    ew->w = w;
    ew->h = h;
    ew->win = SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                               (int)(w * scale), (int)(h * scale), SDL_WINDOW_SHOWN);
    if (ew->win == NULL) {
        snprintf(err, errlen, "SDL window: %s", SDL_GetError());
        free(ew);
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        return NULL;
    }
    if (SDL_GetWindowSurface(ew->win) == NULL) {
        snprintf(err, errlen, "SDL window surface: %s", SDL_GetError());
        SDL_DestroyWindow(ew->win);
        free(ew);
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        return NULL;
    }
    return ew;
}

static int draw(emu_window *ew)
{
    SDL_Surface *s = SDL_GetWindowSurface(ew->win);
    unsigned x, y, sc = ew->scale;
    if (s == NULL || ew->last == NULL)
        return -1;
    if (SDL_LockSurface(s) != 0)
        return -1;
    for (y = 0; y < ew->h * sc && y < (unsigned)s->h; y++) {
        uint8_t *row = (uint8_t *)s->pixels + (size_t)y * (size_t)s->pitch;
        const uint8_t *src = ew->last + (size_t)(y / sc) * ew->w * 3;
        for (x = 0; x < ew->w * sc && x < (unsigned)s->w; x++) {
            const uint8_t *p = src + (size_t)(x / sc) * 3;
            Uint32 v = SDL_MapRGB(s->format, p[0], p[1], p[2]);
            switch (s->format->BytesPerPixel) {
            case 4: memcpy(row + (size_t)x * 4, &v, 4); break;
            case 2: {
                Uint16 v16 = (Uint16)v;
                memcpy(row + (size_t)x * 2, &v16, 2);
                break;
            }
            default: {
                SDL_Rect r;
                SDL_UnlockSurface(s);
                r.x = (int)x;
                r.y = (int)y;
                r.w = r.h = 1;
                SDL_FillRect(s, &r, v);
                SDL_LockSurface(s);
                break;
            }
            }
        }
    }
    SDL_UnlockSurface(s);
    return SDL_UpdateWindowSurface(ew->win) == 0 ? 0 : -1;
}

int emu_window_show(emu_window *ew, const uint8_t *rgb, unsigned w, unsigned h)
{
    size_t n = (size_t)w * h * 3;
    if (ew == NULL || rgb == NULL)
        return -1;
    if (w != ew->w || h != ew->h || ew->last == NULL) {
        uint8_t *b = realloc(ew->last, n);
        if (b == NULL)
            return -1;
        ew->last = b;
        if (w != ew->w || h != ew->h)
            SDL_SetWindowSize(ew->win, (int)(w * ew->scale), (int)(h * ew->scale));
        ew->w = w;
        ew->h = h;
    }
    memcpy(ew->last, rgb, n);
    return draw(ew);
}

int emu_window_poll(emu_window *ew)
{
    SDL_Event ev;
    int quit = 0;
    if (ew == NULL)
        return 0;
    while (SDL_PollEvent(&ev)) {
        if (ev.type == SDL_QUIT)
            quit = 1;
        else if (ev.type == SDL_KEYDOWN &&
                 (ev.key.keysym.sym == SDLK_ESCAPE || ev.key.keysym.sym == SDLK_q))
            quit = 1;
        else if (ev.type == SDL_WINDOWEVENT && (ev.window.event == SDL_WINDOWEVENT_EXPOSED ||
                                                ev.window.event == SDL_WINDOWEVENT_SIZE_CHANGED ||
                                                ev.window.event == SDL_WINDOWEVENT_SHOWN))
            draw(ew);
    }
    return quit;
}

unsigned long emu_window_x11_id(emu_window *ew)
{
    SDL_SysWMinfo info;
    if (ew == NULL)
        return 0;
    SDL_VERSION(&info.version);
    if (!SDL_GetWindowWMInfo(ew->win, &info))
        return 0;
#if defined(SDL_VIDEO_DRIVER_X11)
    if (info.subsystem == SDL_SYSWM_X11)
        return (unsigned long)info.info.x11.window;
#endif
    return 0;
}

void emu_window_close(emu_window *ew)
{
    if (ew == NULL)
        return;
    SDL_DestroyWindow(ew->win);
    free(ew->last);
    free(ew);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

#else /* no SDL2 */

emu_window *emu_window_open(const char *title, unsigned w, unsigned h, unsigned scale, char *err,
                            size_t errlen)
{
    (void)title;
    (void)w;
    (void)h;
    (void)scale;
    snprintf(err, errlen, "built without SDL2 (install libsdl2-dev: make deps)");
    return NULL;
}
int emu_window_show(emu_window *win, const uint8_t *rgb, unsigned w, unsigned h)
{
    (void)win;
    (void)rgb;
    (void)w;
    (void)h;
    return -1;
}
int emu_window_poll(emu_window *win)
{
    (void)win;
    return 0;
}
unsigned long emu_window_x11_id(emu_window *win)
{
    (void)win;
    return 0;
}
void emu_window_close(emu_window *win)
{
    (void)win;
}

#endif
