/* SPDX-License-Identifier: MIT */
/*
 * A live window (SDL2) that shows what an emulated panel shows.
 * emu_window_open returns NULL (and a reason in err) when no display is
 * available or the program was built without SDL2.
 */
#ifndef ZSPAN_EMU_WINDOW_H
#define ZSPAN_EMU_WINDOW_H

#include <stddef.h>
#include <stdint.h>

typedef struct emu_window emu_window;

/* Opens a window of w*scale x h*scale pixels. */
emu_window *emu_window_open(const char *title, unsigned w, unsigned h, unsigned scale, char *err,
                            size_t errlen);
/* Shows an 8-bit RGB picture of w x h pixels (each pixel scale x scale; the
 * window follows a size change). 0 on success. */
int emu_window_show(emu_window *win, const uint8_t *rgb, unsigned w, unsigned h);
/* Handles pending events (redraws after an expose); 1 if the user closed the
 * window or pressed Escape / q. */
int emu_window_poll(emu_window *win);
/* The X11 window id (0 if not on X11): lets a test take a screenshot. */
unsigned long emu_window_x11_id(emu_window *win);
void emu_window_close(emu_window *win);

#endif
