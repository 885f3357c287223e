/* SPDX-License-Identifier: MIT */
/* Emulated SSD1306, SH1106 and SSD1680 controllers (see emu_mono.h). */
#include "emu_mono.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emu.h"

/* name, family, RAM w x h, glass w x h, first SEG, mirror x, mirror y,
 * COM alternative, refresh ms */
static const emu_mono_model models[] = {
    /* 0.96" modules: SEG0 at the right edge, COM0 at the bottom edge */
    {"ssd1306-128x64", EMU_MONO_SSD1306, 128, 64, 128, 64, 0, 1, 1, 1, 0},
    {"ssd1306-128x32", EMU_MONO_SSD1306, 128, 64, 128, 32, 0, 1, 1, 0, 0},
    /* 1.3": 132 SEG lines, the glass on SEG2..SEG129 */
    {"sh1106-132x64", EMU_MONO_SH1106, 132, 64, 128, 64, 2, 1, 1, 1, 0},
    /* 2.13" e-paper: 176 x 296 RAM, glass on sources 0..121, gates 0..249 */
    {"ssd1680-122x250", EMU_MONO_SSD1680, 176, 296, 122, 250, 0, 0, 0, 0, 4000},
    /* OSRAM Pictiva 96x16 (Stellaris LM3S811 board): 132 SEG lines, the glass
     * on SEG36..SEG131 left to right and COM0..COM15 top down, in sequence
     * (last: the fuzz corpus picks models by index) */
    {"ssd0303-96x16", EMU_MONO_SSD0303, 132, 64, 96, 16, 36, 0, 0, 0, 0},
};

unsigned emu_mono_model_count(void)
{
    return (unsigned)(sizeof models / sizeof models[0]);
}

const emu_mono_model *emu_mono_model_at(unsigned i)
{
    return i < emu_mono_model_count() ? &models[i] : NULL;
}

const emu_mono_model *emu_mono_model_find(const char *name)
{
    unsigned i;
    for (i = 0; name && i < emu_mono_model_count(); i++)
        if (strcmp(models[i].name, name) == 0)
            return &models[i];
    return NULL;
}

static const char *const names[EMU_M_COUNT] = {
    "a byte that is no command of this controller",
    "window outside the RAM, start after end, or data past it",
    "data bytes that no command takes",
    "a byte while BUSY is high or the reset line is low",
    "malformed I2C transaction",
    "display on without charge pump/DC-DC, or a multiplex ratio the glass does not have",
    "partial refresh against a base RAM that is not what the glass shows",
    "a parameter value the module cannot take",
};

const char *emu_mono_error_name(uint32_t bit)
{
    unsigned i;
    for (i = 0; i < EMU_M_COUNT; i++)
        if (bit == (1u << i))
            return names[i];
    return "unknown error";
}

static void flag(emu_mono *e, uint32_t bit, const char *fmt, ...)
{
    e->errors |= bit;
    if (e->error_count++ == 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->first_error, sizeof e->first_error, fmt, ap);
        va_end(ap);
    }
}

static void power_on_state(emu_mono *e)
{
    const emu_mono_model *m = e->m;
    e->display_on = 0;
    e->inverse = 0;
    e->all_on = 0;
    e->pump = m->family == EMU_MONO_SH1106; /* SH1106: DC-DC on after reset */
    e->seg_remap = e->com_remap = 0;
    e->mux = 63;
    e->offset = e->start_line = 0;
    e->compins = 0x12;
    e->mode = 2; /* page addressing after reset */
    e->col = e->page = 0;
    e->col_lo = 0;
    e->col_hi = (uint16_t)(m->ram_w - 1u);
    e->page_lo = 0;
    e->page_hi = 7;
    e->entry = 0x03;
    e->target = 0x24;
    e->seq = 0xFF;
    e->gates_ok = 0;
    e->x_lo = 0;
    e->x_hi = (uint16_t)(m->ram_w / 8u - 1u);
    e->y_lo = 0;
    e->y_hi = (uint16_t)(m->ram_h - 1u);
    e->xc = e->yc = 0;
    e->cmd = -1;
    e->writing = 0;
}

int emu_mono_init(emu_mono *e, const emu_mono_model *m)
{
    size_t n = (size_t)m->ram_w * m->ram_h, i;
    memset(e, 0, sizeof *e);
    e->m = m;
    e->ram = malloc(n);
    e->ram2 = malloc(n);
    e->glass = malloc((size_t)m->vis_w * m->vis_h);
    if (!e->ram || !e->ram2 || !e->glass)
        return -1;
    /* power-on RAM is noise; e-paper glass keeps its last picture (grey here: stripes) */
    for (i = 0; i < n; i++) {
        e->ram[i] = (uint8_t)(((i * 2654435761u) >> 31) & 1u);
        e->ram2[i] = (uint8_t)((i * 40503u) >> 15 & 1u);
    }
    for (i = 0; i < (size_t)m->vis_w * m->vis_h; i++)
        e->glass[i] = (uint8_t)((i / 7) & 1u);
    e->i2c_addr = m->family == EMU_MONO_SSD0303 ? 0x3D : 0x3C; /* SA0 high on the LM3S811 board */
    power_on_state(e);
    return 0;
}

void emu_mono_free(emu_mono *e)
{
    free(e->ram);
    free(e->ram2);
    free(e->glass);
    e->ram = e->ram2 = e->glass = NULL;
}

void emu_mono_delay_ms(emu_mono *e, uint32_t ms)
{
    e->now_us += (uint64_t)ms * 1000u;
}

void emu_mono_reset_line(emu_mono *e, int level)
{
    if (!level) {
        e->reset_low = 1;
    } else if (e->reset_low) {
        e->reset_low = 0;
        power_on_state(e);
        e->busy_until_us = e->now_us + 1000u; /* ready after 1 ms */
    }
}

static int ready(emu_mono *e, uint8_t b)
{
    e->bytes++;
    if (e->reset_low || e->now_us < e->busy_until_us) {
        flag(e, EMU_M_BUSY, "byte 0x%02X %s", b, e->reset_low ? "in reset" : "while BUSY");
        return 0;
    }
    return 1;
}

/* ---- OLED ---- */

/* Parameter count of an OLED command byte; -1 if it is none. */
static int oled_params(const emu_mono *e, uint8_t c)
{
    /* the SSD0303 has the SH1106's page-only command set, and 0xD8 */
    int sh = e->m->family == EMU_MONO_SH1106 || e->m->family == EMU_MONO_SSD0303;
    if (c == 0xD8)
        return e->m->family == EMU_MONO_SSD0303 ? 1 : -1;
    if (c <= 0x1F || (c >= 0x40 && c <= 0x7F) || (c >= 0xB0 && c <= 0xB7))
        return 0;
    switch (c) {
    case 0x81: case 0xA8: case 0xD3: case 0xD5: case 0xD9: case 0xDA: case 0xDB:
        return 1;
    case 0xA0: case 0xA1: case 0xA4: case 0xA5: case 0xA6: case 0xA7: case 0xAE: case 0xAF:
    case 0xC0: case 0xC8: case 0xE3:
        return 0;
    case 0x20: case 0x8D: case 0x2E:
        return sh ? -1 : (c == 0x2E ? 0 : 1);
    case 0x21: case 0x22:
        return sh ? -1 : 2;
    case 0xAD:
        return sh ? 1 : -1;
    case 0x30: case 0x31: case 0x32: case 0x33: case 0xE0: case 0xEE:
        return sh ? 0 : -1;
    default:
        return -1;
    }
}

static void oled_apply(emu_mono *e, uint8_t c, const uint8_t *p)
{
    const emu_mono_model *m = e->m;
    if (c <= 0x0F) {
        e->col = (uint16_t)((e->col & 0xF0u) | c);
    } else if (c <= 0x1F) {
        e->col = (uint16_t)((e->col & 0x0Fu) | ((c & 0x0Fu) << 4));
    } else if (c >= 0x40 && c <= 0x7F) {
        e->start_line = (uint8_t)(c & 0x3F);
    } else if (c >= 0xB0 && c <= 0xB7) {
        e->page = (uint16_t)(c & 7u);
    } else {
        switch (c) {
        case 0x20:
            if (p[0] > 2)
                flag(e, EMU_M_PARAM, "addressing mode %u", p[0]);
            e->mode = (uint8_t)(p[0] & 3u);
            break;
        case 0x21:
            if (p[0] > p[1] || p[1] >= m->ram_w)
                flag(e, EMU_M_WINDOW, "columns %u..%u", p[0], p[1]);
            e->col_lo = p[0];
            e->col_hi = p[1];
            e->col = p[0];
            break;
        case 0x22:
            if (p[0] > p[1] || p[1] > 7)
                flag(e, EMU_M_WINDOW, "pages %u..%u", p[0], p[1]);
            e->page_lo = p[0] & 7u;
            e->page_hi = p[1] & 7u;
            e->page = e->page_lo;
            break;
        case 0x8D: e->pump = (p[0] & 0x04u) != 0; break;
        case 0xAD: e->pump = (p[0] & 0x01u) != 0; break;
        case 0xA0: case 0xA1: e->seg_remap = c & 1u; break;
        case 0xA4: case 0xA5: e->all_on = c & 1u; break;
        case 0xA6: case 0xA7: e->inverse = c & 1u; break;
        case 0xA8: e->mux = (uint8_t)(p[0] & 0x3F); break;
        case 0xAE: case 0xAF:
            e->display_on = c & 1u;
            if (e->display_on && !e->pump)
                flag(e, EMU_M_POWER, "display on without the charge pump");
            if (e->display_on && e->mux + 1u != m->vis_h)
                flag(e, EMU_M_POWER, "multiplex ratio %u for %u rows", e->mux + 1u, m->vis_h);
            break;
        case 0xC0: case 0xC8: e->com_remap = (c & 8u) != 0; break;
        case 0xD3: e->offset = (uint8_t)(p[0] & 0x3F); break;
        case 0xDA: e->compins = p[0]; break;
        default: break; /* timing, contrast, levels: no effect on the picture */
        }
    }
}

static void oled_data(emu_mono *e, uint8_t b)
{
    const emu_mono_model *m = e->m;
    unsigned k;
    if (e->col >= m->ram_w || e->page > 7) {
        flag(e, EMU_M_WINDOW, "data at column %u page %u", e->col, e->page);
        return;
    }
    for (k = 0; k < 8; k++)
        e->ram[(size_t)(e->page * 8u + k) * m->ram_w + e->col] = (uint8_t)((b >> k) & 1u);
    e->data_bytes++;
    if (e->mode == 0 || e->mode == 1) {
        /* horizontal: along the columns, then the next page; vertical: the reverse */
        int horiz = e->mode == 0;
        if (horiz ? e->col < e->col_hi : e->page < e->page_hi) {
            if (horiz) e->col++; else e->page++;
        } else {
            if (horiz) e->col = e->col_lo; else e->page = e->page_lo;
            if (horiz ? e->page < e->page_hi : e->col < e->col_hi) {
                if (horiz) e->page++; else e->col++;
            } else {
                if (horiz) e->page = e->page_lo; else e->col = e->col_lo;
            }
        }
    } else if (++e->col >= m->ram_w) {
        if (m->family == EMU_MONO_SSD1306)
            e->col = 0; /* wraps within the page */
        /* SH1106: the counter stops past the RAM; the next byte is flagged */
    }
}

/* ---- SSD1680 ---- */

static int epd_params(uint8_t c)
{
    switch (c) {
    case 0x01: return 3;
    case 0x10: case 0x11: case 0x18: case 0x22: case 0x3C: case 0x4E: return 1;
    case 0x12: case 0x20: return 0;
    case 0x21: case 0x44: case 0x4F: return 2;
    case 0x45: return 4;
    case 0x24: case 0x26: return -2; /* data until the next command */
    default: return -1;
    }
}

static void epd_refresh(emu_mono *e)
{
    const emu_mono_model *m = e->m;
    unsigned x, y;
    if (!(e->seq & 0x04u))
        return; /* no display step in the sequence */
    if (!e->gates_ok)
        flag(e, EMU_M_PARAM, "refresh with the gate count never set to %u", m->vis_h);
    if (e->seq & 0x08u) { /* mode 2: only pixels that differ from the base are driven */
        for (y = 0; y < m->vis_h; y++)
            for (x = 0; x < m->vis_w; x++)
                if (e->ram2[(size_t)y * m->ram_w + x] != e->glass[(size_t)y * m->vis_w + x]) {
                    flag(e, EMU_M_BASE, "base RAM differs from the glass at (%u,%u)", x, y);
                    y = m->vis_h;
                    break;
                }
        e->partial_refreshes++;
    }
    for (y = 0; y < m->vis_h; y++)
        for (x = 0; x < m->vis_w; x++)
            e->glass[(size_t)y * m->vis_w + x] = e->ram[(size_t)y * m->ram_w + x];
    e->refreshes++;
    e->busy_until_us = e->now_us + (uint64_t)m->refresh_ms * 1000u;
}

static void epd_apply(emu_mono *e, uint8_t c, const uint8_t *p)
{
    const emu_mono_model *m = e->m;
    switch (c) {
    case 0x01: {
        unsigned g = (unsigned)p[0] + ((unsigned)(p[1] & 1u) << 8) + 1u;
        e->gates_ok = g == m->vis_h && p[2] == 0;
        if (!e->gates_ok)
            flag(e, EMU_M_PARAM, "driver output: %u gates, scan 0x%02X", g, p[2]);
        break;
    }
    case 0x11:
        e->entry = p[0];
        if (p[0] & 0x04u)
            flag(e, EMU_M_PARAM, "data entry with Y first");
        break;
    case 0x12:
        power_on_state(e);
        e->busy_until_us = e->now_us + 2000u;
        break;
    case 0x22: e->seq = p[0]; break;
    case 0x20: epd_refresh(e); break;
    case 0x44:
        if (p[0] > p[1] || p[1] >= m->ram_w / 8u)
            flag(e, EMU_M_WINDOW, "X bytes %u..%u", p[0], p[1]);
        e->x_lo = p[0];
        e->x_hi = p[1];
        break;
    case 0x45: {
        uint16_t a = (uint16_t)(p[0] | ((p[1] & 1u) << 8)), b = (uint16_t)(p[2] | ((p[3] & 1u) << 8));
        if (a > b || b >= m->ram_h)
            flag(e, EMU_M_WINDOW, "Y gates %u..%u", a, b);
        e->y_lo = a;
        e->y_hi = b;
        break;
    }
    case 0x4E: e->xc = p[0]; break;
    case 0x4F: e->yc = (uint16_t)(p[0] | ((p[1] & 1u) << 8)); break;
    default: break; /* sleep, border, temperature, RAM options */
    }
}

static void epd_data(emu_mono *e, uint8_t b)
{
    const emu_mono_model *m = e->m;
    uint8_t *ram = e->target == 0x26 ? e->ram2 : e->ram;
    unsigned k;
    if (e->xc >= m->ram_w / 8u || e->yc >= m->ram_h) {
        flag(e, EMU_M_WINDOW, "data at X byte %u, Y %u", e->xc, e->yc);
        return;
    }
    for (k = 0; k < 8; k++)
        ram[(size_t)e->yc * m->ram_w + e->xc * 8u + k] = (uint8_t)((b >> (7 - k)) & 1u);
    e->data_bytes++;
    /* X first; bit 0 of the entry mode: X increments, bit 1: Y increments */
    if ((e->entry & 1u) ? e->xc < e->x_hi : e->xc > e->x_lo) {
        e->xc = (uint16_t)((e->entry & 1u) ? e->xc + 1u : e->xc - 1u);
    } else {
        e->xc = (e->entry & 1u) ? e->x_lo : e->x_hi;
        if ((e->entry & 2u) ? e->yc < e->y_hi : e->yc > e->y_lo)
            e->yc = (uint16_t)((e->entry & 2u) ? e->yc + 1u : e->yc - 1u);
        else
            e->yc = (e->entry & 2u) ? e->y_lo : e->y_hi;
    }
}

/* ---- the wire ---- */

static int is_epd(const emu_mono *e)
{
    return e->m->family == EMU_MONO_SSD1680;
}

static void finish(emu_mono *e)
{
    if (e->cmd >= 0 && e->have < e->need)
        flag(e, EMU_M_COMMAND, "command 0x%02X with %d of %d parameters", e->cmd, e->have,
             e->need);
    e->cmd = -1;
}

void emu_mono_command(emu_mono *e, uint8_t b)
{
    int n;
    if (!ready(e, b))
        return;
    if (is_epd(e)) {
        finish(e);
        e->writing = 0;
        n = epd_params(b);
        e->commands++;
        if (n == -1) {
            flag(e, EMU_M_COMMAND, "0x%02X is no SSD1680 command here", b);
            return;
        }
        if (n == -2) {
            e->writing = 1;
            e->target = b;
            return;
        }
        e->cmd = b;
        e->need = n;
        e->have = 0;
        if (n == 0) {
            epd_apply(e, b, e->params);
            e->cmd = -1;
        }
        return;
    }
    /* OLED: parameters are command bytes too */
    if (e->cmd >= 0) {
        e->params[e->have++] = b;
        if (e->have == e->need) {
            oled_apply(e, (uint8_t)e->cmd, e->params);
            e->cmd = -1;
        }
        return;
    }
    e->commands++;
    n = oled_params(e, b);
    if (n < 0) {
        flag(e, EMU_M_COMMAND, "0x%02X is no %s command", b,
             e->m->family == EMU_MONO_SH1106    ? "SH1106"
             : e->m->family == EMU_MONO_SSD0303 ? "SSD0303"
                                                : "SSD1306");
        return;
    }
    if (n == 0) {
        oled_apply(e, b, e->params);
        return;
    }
    e->cmd = b;
    e->need = n;
    e->have = 0;
}

void emu_mono_data(emu_mono *e, const uint8_t *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (!ready(e, d[i]))
            continue;
        if (is_epd(e)) {
            if (e->cmd >= 0) {
                e->params[e->have++] = d[i];
                if (e->have == e->need) {
                    epd_apply(e, (uint8_t)e->cmd, e->params);
                    e->cmd = -1;
                }
            } else if (e->writing) {
                epd_data(e, d[i]);
            } else {
                flag(e, EMU_M_STRAY, "data byte 0x%02X after no command that takes it", d[i]);
            }
        } else {
            if (e->cmd >= 0)
                flag(e, EMU_M_COMMAND, "data while command 0x%02X waits for parameters", e->cmd);
            oled_data(e, d[i]);
        }
    }
}

int emu_mono_i2c_write(emu_mono *e, uint8_t addr, const uint8_t *d, size_t n)
{
    size_t i = 0;
    if (addr != e->i2c_addr || is_epd(e)) {
        e->nacks++;
        return -1;
    }
    e->i2c_frames++;
    while (i < n) {
        uint8_t ctrl = d[i++];
        int co = (ctrl & 0x80u) != 0, dc = (ctrl & 0x40u) != 0;
        if (ctrl & 0x3Fu)
            flag(e, EMU_M_I2C, "control byte 0x%02X", ctrl);
        if (i >= n) {
            flag(e, EMU_M_I2C, "control byte 0x%02X with nothing after it", ctrl);
            break;
        }
        if (co) { /* one byte, then another control byte */
            if (dc) emu_mono_data(e, &d[i], 1); else emu_mono_command(e, d[i]);
            i++;
            continue;
        }
        /* Co = 0: the rest of the transaction is of one kind */
        if (dc) {
            emu_mono_data(e, d + i, n - i);
        } else {
            for (; i < n; i++)
                emu_mono_command(e, d[i]);
        }
        break;
    }
    return 0;
}

/* ---- the glass ---- */

static uint8_t oled_pixel(const emu_mono *e, unsigned gx, unsigned gy)
{
    const emu_mono_model *m = e->m;
    unsigned seg = m->mirror_x ? m->vis_col + m->vis_w - 1u - gx : m->vis_col + gx;
    unsigned col = e->seg_remap ? m->ram_w - 1u - seg : seg;
    unsigned com = m->mirror_y ? m->vis_h - 1u - gy : gy, row, mux = e->mux + 1u;
    uint8_t v;
    if (!e->display_on || !e->pump || e->reset_low)
        return 0;
    if (((e->compins & 0x10u) != 0) != (m->com_alt != 0)) /* pins wired the other way */
        com = (com % 2u) * (mux / 2u) + com / 2u;
    if (com >= mux)
        return 0;
    row = e->com_remap ? mux - 1u - com : com;
    row = (row + e->start_line + e->offset) % m->ram_h;
    v = e->all_on ? 1u : e->ram[(size_t)row * m->ram_w + col];
    return (uint8_t)(v ^ e->inverse);
}

void emu_mono_view(const emu_mono *e, unsigned rotation, uint8_t *out)
{
    const emu_mono_model *m = e->m;
    unsigned x, y;
    for (y = 0; y < m->vis_h; y++)
        for (x = 0; x < m->vis_w; x++) {
            unsigned gx = rotation == 2 ? m->vis_w - 1u - x : x;
            unsigned gy = rotation == 2 ? m->vis_h - 1u - y : y;
            uint8_t v;
            if (is_epd(e)) {
                if (m->mirror_x) gx = m->vis_w - 1u - gx;
                if (m->mirror_y) gy = m->vis_h - 1u - gy;
                v = e->glass[(size_t)gy * m->vis_w + gx];
            } else {
                v = oled_pixel(e, gx, gy);
            }
            out[(size_t)y * m->vis_w + x] = v;
        }
}

int emu_mono_write_png(const emu_mono *e, unsigned rotation, const char *path)
{
    size_t n = (size_t)e->m->vis_w * e->m->vis_h, i;
    uint8_t *bits = malloc(n), *rgb = malloc(3 * n);
    int rc = -1;
    if (bits && rgb) {
        emu_mono_view(e, rotation, bits);
        for (i = 0; i < n; i++) {
            /* OLED: lit pixels pale blue on black; e-paper: black on paper */
            static const uint8_t oled_on[3] = {200, 230, 255}, paper[3] = {235, 232, 220};
            const uint8_t *c = bits[i] ? (is_epd(e) ? paper : oled_on) : (const uint8_t *)"\0\0\0";
            if (!bits[i] && is_epd(e)) c = (const uint8_t *)"\x20\x20\x20";
            memcpy(rgb + 3 * i, c, 3);
        }
        rc = emu_png_write_rgb(path, rgb, e->m->vis_w, e->m->vis_h);
    }
    free(bits);
    free(rgb);
    return rc;
}
