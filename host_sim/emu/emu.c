/* SPDX-License-Identifier: MIT */
/* Emulated display controllers: MIPI-DCS (ST7789, ILI9341, ST7735, GC9A01,
 * ILI9488) and SSD1351, fed with the bytes of the SPI wire. See emu.h. */
#include "emu.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* Module facts                                                         */
/* ------------------------------------------------------------------ */

/* name, family, ram_w, ram_h, vis_w, vis_h, vis_col, vis_row, mirror_x,
 * mirror_y, bgr, inverted (IPS), spi_no_16bpp, default_bpp, clock */
static const emu_model models[] = {
    /* ST7789V: 240x320 RAM; 1.3"/1.54" IPS glass shows RAM rows 0..239. */
    {"st7789-240x240", EMU_DCS, 240, 320, 240, 240, 0, 0, 0, 0, 0, 1, 0, 18, 62500000u},
    {"st7789-240x320", EMU_DCS, 240, 320, 240, 320, 0, 0, 0, 0, 0, 1, 0, 18, 62500000u},
    /* 1.14" IPS: the glass sits in the middle of the RAM (columns 52.., rows 40..). */
    {"st7789-135x240", EMU_DCS, 240, 320, 135, 240, 52, 40, 0, 0, 0, 1, 0, 18, 62500000u},
    /* ILI9341 modules: BGR filter, sources wired right to left. */
    {"ili9341", EMU_DCS, 240, 320, 240, 320, 0, 0, 1, 0, 1, 0, 0, 18, 10000000u},
    /* ST7735S 132x162 RAM; 1.8" glass at column 2, row 1, mounted turned 180. */
    {"st7735-128x160", EMU_DCS, 132, 162, 128, 160, 2, 1, 1, 1, 0, 0, 0, 18, 15000000u},
    /* GC9A01 round IPS, BGR filter. */
    {"gc9a01", EMU_DCS, 240, 240, 240, 240, 0, 0, 0, 0, 1, 1, 0, 18, 50000000u},
    /* ILI9488: BGR, sources right to left; SPI has no 16 bpp mode. */
    {"ili9488", EMU_DCS, 320, 480, 320, 480, 0, 0, 1, 0, 1, 0, 1, 18, 20000000u},
    /* SSD1351: COM lines wired bottom to top, colour order C-B-A. */
    {"ssd1351", EMU_SSD1351, 128, 128, 128, 128, 0, 0, 0, 1, 1, 0, 0, 16, 20000000u},
};

unsigned emu_model_count(void)
{
    return (unsigned)(sizeof models / sizeof models[0]);
}

const emu_model *emu_model_at(unsigned i)
{
    return i < emu_model_count() ? &models[i] : NULL;
}

const emu_model *emu_model_find(const char *name)
{
    unsigned i;
    if (name == NULL)
        return NULL;
    for (i = 0; i < emu_model_count(); i++)
        if (strcmp(models[i].name, name) == 0)
            return &models[i];
    return NULL;
}

/* ------------------------------------------------------------------ */
/* Errors and the event record                                          */
/* ------------------------------------------------------------------ */

static const char *const error_names[EMU_E_COUNT] = {
    "pixel data while asleep (before SLPOUT)",
    "pixel data while the display is off (before DISPON)",
    "window start after end, or outside the controller RAM",
    "wrong parameter count",
    "unsupported parameter value",
    "data bytes no command takes",
    "command in the middle of a pixel",
    "command too soon after reset, SWRESET or SLPOUT",
    "command while the interface is locked",
    "262k pixel byte with bits 7..6 set (wants bits 5..0)",
    "bytes while the reset line is held low",
};

const char *emu_error_name(uint32_t bit)
{
    unsigned i;
    for (i = 0; i < EMU_E_COUNT; i++)
        if (bit == (1u << i))
            return error_names[i];
    return "unknown error";
}

static void flag(emu_panel *e, uint32_t bit, const char *fmt, ...)
{
    e->errors |= bit;
    e->error_count++;
    if (e->log_lines < EMU_LOG_LINES) {
        va_list ap;
        char msg[80];
        va_start(ap, fmt);
        vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        snprintf(e->log[e->log_lines], sizeof e->log[0], "byte %llu: %s: %s",
                 (unsigned long long)e->bytes_in, emu_error_name(bit), msg);
        e->log_lines++;
    }
}

static void push_event(emu_panel *e, uint8_t kind, uint8_t byte, uint32_t n)
{
    if (!e->record)
        return;
    if (kind == 'D' && e->nev > 0 && e->ev[e->nev - 1].kind == 'D') {
        e->ev[e->nev - 1].n += n;
        return;
    }
    if (e->nev == e->capev) {
        size_t cap = e->capev ? e->capev * 2 : 256;
        emu_event *ev = realloc(e->ev, cap * sizeof *ev);
        if (ev == NULL)
            return;
        e->ev = ev;
        e->capev = cap;
    }
    e->ev[e->nev].kind = kind;
    e->ev[e->nev].byte = byte;
    e->ev[e->nev].n = n;
    e->nev++;
}

void emu_record(emu_panel *e, int on)
{
    e->record = on;
    e->nev = 0;
}

/* ------------------------------------------------------------------ */
/* Reset state                                                          */
/* ------------------------------------------------------------------ */

static void soft_reset(emu_panel *e)
{
    e->sleeping = e->m->family == EMU_DCS ? 1 : 0;
    e->display_on = 0;
    e->inverted = 0;
    e->idle = 0;
    e->madctl = e->m->family == EMU_DCS ? 0x00 : 0x40;
    e->bpp = e->m->default_bpp;
    e->writing = 0;
    e->ssd_locked = 0;
    e->ssd_protected = 1;
    e->xs = 0;
    e->ys = 0;
    e->xe = (uint16_t)(e->m->ram_w - 1);
    e->ye = (uint16_t)(e->m->ram_h - 1);
    e->cx = 0;
    e->cy = 0;
    e->win_ok = 0;
    e->cmd = -1;
    e->expect = 0;
    e->nparams = 0;
    e->npart = 0;
    e->last_cmd = -1;
    e->extra_is_count = 0;
}

int emu_init(emu_panel *e, const emu_model *m)
{
    size_t i, n;
    uint32_t x = 0x12345678u;

    memset(e, 0, sizeof *e);
    if (m == NULL)
        return -1;
    e->m = m;
    n = (size_t)m->ram_w * m->ram_h;
    e->ram = malloc(n * sizeof *e->ram);
    if (e->ram == NULL)
        return -1;
    for (i = 0; i < n; i++) { /* power-on RAM: noise */
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        e->ram[i] = x & 0x3FFFFu;
    }
    soft_reset(e);
    e->backlight = 255;
    return 0;
}

void emu_free(emu_panel *e)
{
    free(e->ram);
    free(e->ev);
    e->ram = NULL;
    e->ev = NULL;
    e->nev = e->capev = 0;
}

void emu_delay_ms(emu_panel *e, uint32_t ms)
{
    e->now_us += (uint64_t)ms * 1000u;
}

void emu_reset_line(emu_panel *e, int level)
{
    if (level == 0) {
        e->reset_low = 1;
        return;
    }
    if (e->reset_low) {
        e->reset_low = 0;
        soft_reset(e);
        e->seen_hwreset = 1;
        e->t_hwreset = e->now_us;
        e->seen_swreset = 0;
        e->seen_slpout = 0;
    }
}

/* ------------------------------------------------------------------ */
/* Command tables                                                       */
/* ------------------------------------------------------------------ */

/* Parameter count of a command the model understands; -1 = unknown to the
 * emulator (vendor registers: any count accepted, no effect). */
static int dcs_count(uint8_t c)
{
    switch (c) {
    case 0x00: case 0x01: case 0x10: case 0x11: case 0x12: case 0x13:
    case 0x20: case 0x21: case 0x28: case 0x29: case 0x2C: case 0x34:
    case 0x38: case 0x39: case 0x3C:
        return 0;
    case 0x26: case 0x35: case 0x36: case 0x3A:
        return 1;
    case 0x37:
        return 2;
    case 0x2A: case 0x2B: case 0x30:
        return 4;
    case 0x33:
        return 6;
    default:
        return -1;
    }
}

static int ssd_count(uint8_t c)
{
    switch (c) {
    case 0x5C: case 0x5D: case 0xA4: case 0xA5: case 0xA6: case 0xA7:
    case 0xAD: case 0xAE: case 0xAF: case 0xB0: case 0xB9: case 0xD1:
    case 0xE3: case 0x9E: case 0x9F:
        return 0;
    case 0xA0: case 0xA1: case 0xA2: case 0xAB: case 0xB1: case 0xB3:
    case 0xB5: case 0xB6: case 0xBB: case 0xBE: case 0xC7: case 0xCA:
    case 0xFD:
        return 1;
    case 0x15: case 0x75:
        return 2;
    case 0xB4: case 0xC1: case 0xB2:
        return 3;
    case 0x96:
        return 5;
    case 0xB8:
        return 63;
    default:
        return -1;
    }
}

static int ssd_protected_cmd(uint8_t c)
{
    return c == 0xA2 || c == 0xB1 || c == 0xB3 || c == 0xBB || c == 0xBE || c == 0xC1;
}

/* ------------------------------------------------------------------ */
/* Applying commands                                                    */
/* ------------------------------------------------------------------ */

static void dcs_start_write(emu_panel *e, int reset_counters)
{
    uint32_t col_lim, row_lim;
    int mv = (e->madctl & 0x20) != 0;
    col_lim = mv ? e->m->ram_h : e->m->ram_w;
    row_lim = mv ? e->m->ram_w : e->m->ram_h;
    e->win_ok = 1;
    if (e->xs > e->xe || e->ys > e->ye || e->xe >= col_lim || e->ye >= row_lim) {
        flag(e, EMU_E_WINDOW, "columns %u..%u rows %u..%u, RAM %ux%u%s", e->xs, e->xe, e->ys,
             e->ye, e->m->ram_w, e->m->ram_h, mv ? " (exchanged)" : "");
        e->win_ok = 0;
    }
    if (reset_counters) {
        e->cx = e->xs;
        e->cy = e->ys;
    }
    e->writing = 1;
    e->pix_flagged = 0;
    if (reset_counters)
        e->wrap_pending = 0;
    e->frames_written++;
}

static void dcs_apply(emu_panel *e, uint8_t c, const uint8_t *p)
{
    switch (c) {
    case 0x01:
        soft_reset(e);
        e->seen_swreset = 1;
        e->t_swreset = e->now_us;
        e->seen_slpout = 0;
        break;
    case 0x10:
        if (e->seen_slpout && e->now_us - e->t_slpout < 120000u)
            flag(e, EMU_E_TIMING, "SLPIN within 120 ms of SLPOUT");
        e->sleeping = 1;
        break;
    case 0x11:
        if (e->seen_swreset && e->now_us - e->t_swreset < 120000u)
            flag(e, EMU_E_TIMING, "SLPOUT %llu us after SWRESET (needs 120 ms)",
                 (unsigned long long)(e->now_us - e->t_swreset));
        if (e->seen_hwreset && e->now_us - e->t_hwreset < 120000u)
            flag(e, EMU_E_TIMING, "SLPOUT within 120 ms of the hardware reset");
        e->sleeping = 0;
        e->seen_slpout = 1;
        e->t_slpout = e->now_us;
        break;
    case 0x13: break;
    case 0x20: e->inverted = 0; break;
    case 0x21: e->inverted = 1; break;
    case 0x28: e->display_on = 0; break;
    case 0x29: e->display_on = 1; break;
    case 0x38: e->idle = 0; break;
    case 0x39: e->idle = 1; break;
    case 0x2A:
    case 0x2B: {
        uint16_t s = (uint16_t)(p[0] << 8 | p[1]);
        uint16_t en = (uint16_t)(p[2] << 8 | p[3]);
        if (s > en) {
            flag(e, EMU_E_WINDOW, "%s start %u > end %u", c == 0x2A ? "CASET" : "RASET", s, en);
            break;
        }
        if (c == 0x2A) {
            e->xs = s;
            e->xe = en;
        } else {
            e->ys = s;
            e->ye = en;
        }
        break;
    }
    case 0x2C: dcs_start_write(e, 1); break;
    case 0x3C: dcs_start_write(e, 0); break;
    case 0x36: e->madctl = p[0]; break;
    case 0x3A: {
        unsigned v = p[0] & 0x0Fu;
        if (v == 5 && !e->m->spi_no_16bpp)
            e->bpp = 16;
        else if (v == 6)
            e->bpp = 18;
        else
            flag(e, EMU_E_PARAM_VALUE, "COLMOD 0x%02X not available on this SPI panel", p[0]);
        break;
    }
    default: break;
    }
}

static void ssd_apply(emu_panel *e, uint8_t c, const uint8_t *p)
{
    if (c == 0xFD) {
        if (p[0] == 0x12) e->ssd_locked = 0;
        else if (p[0] == 0x16) e->ssd_locked = 1;
        else if (p[0] == 0xB1) e->ssd_protected = 0;
        else if (p[0] == 0xB0) e->ssd_protected = 1;
        else flag(e, EMU_E_PARAM_VALUE, "command lock 0x%02X", p[0]);
        return;
    }
    if (e->ssd_locked) {
        flag(e, EMU_E_LOCKED, "command 0x%02X while locked (0xFD 0x16)", c);
        return;
    }
    if (ssd_protected_cmd(c) && e->ssd_protected) {
        flag(e, EMU_E_LOCKED, "command 0x%02X needs 0xFD 0xB1 first", c);
        return;
    }
    switch (c) {
    case 0x15:
    case 0x75:
        if (p[0] > p[1] || p[1] > 127) {
            flag(e, EMU_E_WINDOW, "%s %u..%u", c == 0x15 ? "column" : "row", p[0], p[1]);
            break;
        }
        e->wrap_pending = 0;
        if (c == 0x15) {
            e->xs = p[0];
            e->xe = p[1];
            e->cx = p[0];
        } else {
            e->ys = p[0];
            e->ye = p[1];
            e->cy = p[0];
        }
        break;
    case 0x5C:
        e->writing = 1;
        e->pix_flagged = 0;
        e->win_ok = 1;
        e->frames_written++;
        break;
    case 0xA0:
        if ((p[0] & 0xC0u) == 0xC0u) {
            flag(e, EMU_E_PARAM_VALUE, "remap 0x%02X: 262k format 2 is for 16-bit buses", p[0]);
            break;
        }
        e->madctl = p[0];
        e->bpp = (p[0] & 0xC0u) == 0x80u ? 18 : 16;
        break;
    case 0xA6: e->inverted = 0; break;
    case 0xA7: e->inverted = 1; break;
    case 0xAE: e->display_on = 0; break;
    case 0xAF: e->display_on = 1; break;
    default: break;
    }
}

static void finish_pending(emu_panel *e)
{
    if (e->cmd < 0)
        return;
    if (e->expect >= 0 && e->nparams < (unsigned)e->expect)
        flag(e, EMU_E_PARAM_COUNT, "command 0x%02X got %u of %d parameters", (unsigned)e->cmd,
             e->nparams, e->expect);
    e->cmd = -1;
}

static void apply(emu_panel *e, uint8_t c, const uint8_t *p)
{
    if (e->m->family == EMU_DCS)
        dcs_apply(e, c, p);
    else
        ssd_apply(e, c, p);
}

/* ------------------------------------------------------------------ */
/* The wire                                                             */
/* ------------------------------------------------------------------ */

void emu_command(emu_panel *e, uint8_t c)
{
    int n;
    e->bytes_in++;
    push_event(e, 'C', c, 0);
    if (e->reset_low) {
        flag(e, EMU_E_IN_RESET, "command 0x%02X", c);
        return;
    }
    e->commands++;
    finish_pending(e);
    if (e->npart != 0) {
        flag(e, EMU_E_PARTIAL_PIXEL, "command 0x%02X after %u byte(s) of a pixel", c, e->npart);
        e->npart = 0;
    }
    e->writing = 0; /* any command ends a memory write */
    e->extra_is_count = 0;
    if (e->m->family == EMU_DCS) {
        if (e->seen_hwreset && e->now_us - e->t_hwreset < 5000u)
            flag(e, EMU_E_TIMING, "command 0x%02X within 5 ms of the hardware reset", c);
        else if (e->seen_swreset && e->now_us - e->t_swreset < 5000u)
            flag(e, EMU_E_TIMING, "command 0x%02X within 5 ms of SWRESET", c);
        else if (e->seen_slpout && e->now_us - e->t_slpout < 5000u)
            flag(e, EMU_E_TIMING, "command 0x%02X within 5 ms of SLPOUT", c);
        n = dcs_count(c);
    } else {
        n = ssd_count(c);
    }
    e->nparams = 0;
    if (n == 0) {
        e->cmd = -1;
        e->last_cmd = c;
        e->extra_is_count = 1;
        apply(e, c, e->params);
        return;
    }
    e->cmd = c;
    e->expect = n;
}

static void store_pixel(emu_panel *e, uint32_t v)
{
    const emu_model *m = e->m;
    unsigned a, b, px, py;

    if (e->wrap_pending) { /* a pixel past the window's end: back at its start */
        e->wraps++;
        e->wrap_pending = 0;
    }

    if (e->m->family == EMU_DCS) {
        int mv = (e->madctl & 0x20) != 0;
        a = mv ? e->cy : e->cx;
        b = mv ? e->cx : e->cy;
        px = (e->madctl & 0x40) ? m->ram_w - 1u - a : a;
        py = (e->madctl & 0x80) ? m->ram_h - 1u - b : b;
        if (e->win_ok && a < m->ram_w && b < m->ram_h)
            e->ram[(size_t)py * m->ram_w + px] = v;
        if (++e->cx > e->xe) {
            e->cx = e->xs;
            if (++e->cy > e->ye) {
                e->cy = e->ys;
                e->wrap_pending = 1;
            }
        }
    } else {
        px = (e->madctl & 0x02) ? 127u - e->cx : e->cx;
        py = e->cy;
        if (px < m->ram_w && py < m->ram_h)
            e->ram[(size_t)py * m->ram_w + px] = v;
        if (e->madctl & 0x01) { /* vertical increment */
            if (++e->cy > e->ye) {
                e->cy = e->ys;
                if (++e->cx > e->xe) {
                    e->cx = e->xs;
                    e->wrap_pending = 1;
                }
            }
        } else if (++e->cx > e->xe) {
            e->cx = e->xs;
            if (++e->cy > e->ye) {
                e->cy = e->ys;
                e->wrap_pending = 1;
            }
        }
    }
    e->pixels++;
}

uint32_t emu_666_from_565be(const uint8_t *p)
{
    unsigned v = (unsigned)p[0] << 8 | p[1];
    unsigned r5 = v >> 11, g6 = (v >> 5) & 63u, b5 = v & 31u;
    unsigned r6 = r5 << 1 | r5 >> 4, b6 = b5 << 1 | b5 >> 4;
    return (uint32_t)(r6 << 12 | g6 << 6 | b6);
}

uint32_t emu_666_from_666(const uint8_t *p)
{
    return (uint32_t)((unsigned)(p[0] >> 2) << 12 | (unsigned)(p[1] >> 2) << 6 |
                      (unsigned)(p[2] >> 2));
}

static void pixel_byte(emu_panel *e, uint8_t byte)
{
    unsigned need = e->bpp == 18 ? 3u : 2u;
    uint32_t v;

    e->part[e->npart++] = byte;
    if (e->npart < need)
        return;
    e->npart = 0;
    if (need == 2) {
        v = emu_666_from_565be(e->part);
    } else if (e->m->family == EMU_SSD1351) {
        if ((e->part[0] | e->part[1] | e->part[2]) & 0xC0u) {
            if (!(e->errors & EMU_E_PIXEL_BITS))
                flag(e, EMU_E_PIXEL_BITS, "pixel %02X %02X %02X", e->part[0], e->part[1],
                     e->part[2]);
            else
                e->error_count++;
        }
        v = (uint32_t)((e->part[0] & 63u) << 12 | (e->part[1] & 63u) << 6 | (e->part[2] & 63u));
    } else {
        v = emu_666_from_666(e->part);
    }
    store_pixel(e, v);
}

void emu_data(emu_panel *e, const uint8_t *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        uint8_t byte = d[i];
        e->bytes_in++;
        if (e->reset_low) {
            push_event(e, 'P', byte, 0);
            flag(e, EMU_E_IN_RESET, "data byte 0x%02X", byte);
            continue;
        }
        if (e->cmd >= 0) {
            push_event(e, 'P', byte, 0);
            if (e->nparams < EMU_MAX_PARAMS)
                e->params[e->nparams] = byte;
            e->nparams++;
            if (e->expect >= 0 && e->nparams == (unsigned)e->expect) {
                uint8_t c = (uint8_t)e->cmd;
                e->cmd = -1;
                e->last_cmd = c;
                e->extra_is_count = 1;
                apply(e, c, e->params);
            }
            continue;
        }
        if (e->writing) {
            push_event(e, 'D', 0, 1);
            if ((e->sleeping || !e->display_on) && !e->pix_flagged) {
                flag(e, e->sleeping ? EMU_E_SLEEP : EMU_E_DISPOFF, "memory write");
                e->pix_flagged = 1;
            }
            pixel_byte(e, byte);
            continue;
        }
        push_event(e, 'P', byte, 0);
        if (e->extra_is_count)
            flag(e, EMU_E_PARAM_COUNT, "extra byte 0x%02X after command 0x%02X", byte,
                 (unsigned)e->last_cmd);
        else
            flag(e, EMU_E_STRAY_DATA, "byte 0x%02X with no command", byte);
        /* One report per run of surplus bytes is enough. */
        e->extra_is_count = 0;
        while (i + 1 < n && !e->reset_low) {
            i++;
            e->bytes_in++;
            push_event(e, 'P', d[i], 0);
        }
    }
}

void emu_flush(emu_panel *e)
{
    finish_pending(e);
    if (e->npart != 0 && e->writing) {
        flag(e, EMU_E_PARTIAL_PIXEL, "stream ended after %u byte(s) of a pixel", e->npart);
        e->npart = 0;
    }
}

/* ------------------------------------------------------------------ */
/* What the viewer sees                                                 */
/* ------------------------------------------------------------------ */

void emu_view_size(const emu_panel *e, unsigned rotation, unsigned *w, unsigned *h)
{
    unsigned vw = e->m->vis_w, vh = e->m->vis_h;
    if (rotation & 1u) {
        *w = vh;
        *h = vw;
    } else {
        *w = vw;
        *h = vh;
    }
}

/* Colour at glass position (gx, gy) of the unrotated view. */
static uint32_t glass_pixel(const emu_panel *e, unsigned vx, unsigned vy)
{
    const emu_model *m = e->m;
    unsigned gx = m->mount_mirror_x ? m->vis_w - 1u - vx : vx;
    unsigned gy = m->mount_mirror_y ? m->vis_h - 1u - vy : vy;
    unsigned px, py;
    uint32_t v;
    int bgr, inv;

    if (e->sleeping || !e->display_on)
        return 0;
    if (m->family == EMU_DCS) {
        px = m->vis_col + gx;
        py = m->vis_row + gy;
        bgr = (e->madctl & 0x08) != 0;
    } else {
        px = gx;
        py = (e->madctl & 0x10) ? 127u - gy : gy; /* COM scan direction */
        bgr = (e->madctl & 0x04) != 0;
    }
    v = e->ram[(size_t)py * m->ram_w + px];
    if (bgr != (m->glass_bgr != 0))
        v = (v & 0x00FC0u) | (v >> 12) | ((v & 63u) << 12);
    inv = (e->inverted != 0) != (m->glass_inverted != 0);
    if (inv)
        v ^= 0x3FFFFu;
    return v;
}

void emu_view_666(const emu_panel *e, unsigned rotation, uint32_t *out)
{
    unsigned w, h, x, y;
    emu_view_size(e, rotation, &w, &h);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            unsigned vx, vy;
            /* The driver turned the picture rotation * 90 degrees clockwise
             * onto the glass; turn it back. */
            switch (rotation & 3u) {
            case 0: vx = x; vy = y; break;
            case 1: vx = h - 1u - y; vy = x; break;
            case 2: vx = w - 1u - x; vy = h - 1u - y; break;
            default: vx = y; vy = w - 1u - x; break;
            }
            out[(size_t)y * w + x] = glass_pixel(e, vx, vy);
        }
    }
}

void emu_view_rgb(const emu_panel *e, unsigned rotation, uint8_t *out)
{
    unsigned w, h;
    size_t i, n;
    uint32_t *tmp;
    emu_view_size(e, rotation, &w, &h);
    n = (size_t)w * h;
    tmp = malloc(n * sizeof *tmp);
    if (tmp == NULL) {
        memset(out, 0, n * 3);
        return;
    }
    emu_view_666(e, rotation, tmp);
    for (i = 0; i < n; i++) {
        unsigned r = (tmp[i] >> 12) & 63u, g = (tmp[i] >> 6) & 63u, b = tmp[i] & 63u;
        out[3 * i + 0] = (uint8_t)(r << 2 | r >> 4);
        out[3 * i + 1] = (uint8_t)(g << 2 | g >> 4);
        out[3 * i + 2] = (uint8_t)(b << 2 | b >> 4);
    }
    free(tmp);
}

int emu_write_png(const emu_panel *e, unsigned rotation, const char *path)
{
    unsigned w, h;
    uint8_t *rgb;
    int rc;
    emu_view_size(e, rotation, &w, &h);
    rgb = malloc((size_t)w * h * 3);
    if (rgb == NULL)
        return -1;
    emu_view_rgb(e, rotation, rgb);
    rc = emu_png_write_rgb(path, rgb, w, h);
    free(rgb);
    return rc;
}
