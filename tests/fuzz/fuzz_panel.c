/* SPDX-License-Identifier: MIT */
/*
 * fuzz_panel: the emulated display controllers (host_sim/emu/emu.c) decoding
 * arbitrary wire streams (libFuzzer).
 *
 * Input: byte 0 picks the model (every built-in one); the rest is a program
 * of wire operations: a command byte (D/C low), a run of data bytes (D/C
 * high), a long pixel run from a repeated pattern (to fill whole windows),
 * a delay, the reset line low or high, a flush, or reading the picture back
 * in one of the four rotations.
 *
 * The program runs on two panels of the same model: A gets every data run in
 * one emu_data call, B gets the same bytes one emu_data call per byte (a real
 * wire has no call boundaries). Invariants:
 *   - no memory error (ASan/UBSan), whatever the bytes;
 *   - A and B end in the same state: RAM, window, address counters, mode
 *     registers, bytes, commands, pixels and wraps; their error flags differ
 *     at most in EMU_E_STRAY_DATA (one report per run of surplus bytes, and a
 *     run ends with the emu_data call);
 *   - every RAM cell and every read-back pixel holds 6-bit channels only
 *     (< 2^18); error flags are documented bits only; the log has at most
 *     EMU_LOG_LINES lines; pixels written <= data bytes / 2;
 *   - SSD1351 address counters stay inside its 128 x 128 RAM.
 */
#include <string.h>

#include "emu.h"
#include "fuzz_util.h"

#define MAX_OPS 4096

typedef struct two {
    emu_panel a, b;
} two;

static void check_panel(const emu_panel *e, uint64_t fed, const char *which)
{
    size_t n = (size_t)e->m->ram_w * e->m->ram_h;
    FZ_CHECK(e->bytes_in == fed, "%s: bytes_in %llu, %llu fed", which,
             (unsigned long long)e->bytes_in, (unsigned long long)fed);
    FZ_CHECK((e->errors & ~((1u << EMU_E_COUNT) - 1u)) == 0, "%s: undocumented error bits %#x",
             which, e->errors);
    FZ_CHECK(e->error_count >= (uint32_t)__builtin_popcount(e->errors),
             "%s: %u errors counted for flags %#x", which, e->error_count, e->errors);
    FZ_CHECK(e->log_lines <= EMU_LOG_LINES, "%s: %u log lines", which, e->log_lines);
    for (unsigned i = 0; i < e->log_lines; i++)
        FZ_CHECK(memchr(e->log[i], 0, sizeof e->log[i]) != NULL, "%s: log line %u unterminated",
                 which, i);
    FZ_CHECK(e->pixels * 2 <= fed, "%s: %llu pixels from %llu bytes", which,
             (unsigned long long)e->pixels, (unsigned long long)fed);
    FZ_CHECK(e->bpp == 16 || e->bpp == 18, "%s: bpp %u", which, e->bpp);
    if (e->m->family == EMU_SSD1351)
        FZ_CHECK(e->cx < 128 && e->cy < 128 && e->xe < 128 && e->ye < 128,
                 "%s: SSD1351 counters %u,%u window end %u,%u", which, e->cx, e->cy, e->xe, e->ye);
    uint32_t any = 0;
    for (size_t i = 0; i < n; i++)
        any |= e->ram[i];
    FZ_CHECK(any <= 0x3FFFFu, "%s: a RAM cell has bits above 18 (%#x)", which, any);
}

static void same_state(const emu_panel *a, const emu_panel *b)
{
    size_t n = (size_t)a->m->ram_w * a->m->ram_h;
#define SAME(f) FZ_CHECK(a->f == b->f, "whole-run vs byte-by-byte: " #f " %llu != %llu", \
                         (unsigned long long)a->f, (unsigned long long)b->f)
    SAME(reset_low); SAME(sleeping); SAME(display_on); SAME(inverted); SAME(idle);
    SAME(madctl); SAME(bpp); SAME(writing); SAME(ssd_locked); SAME(ssd_protected);
    SAME(xs); SAME(xe); SAME(ys); SAME(ye); SAME(cx); SAME(cy); SAME(win_ok);
    SAME(wrap_pending); SAME(cmd); SAME(npart); SAME(bytes_in); SAME(commands);
    SAME(pixels); SAME(wraps); SAME(frames_written);
#undef SAME
    FZ_CHECK(memcmp(a->ram, b->ram, n * sizeof *a->ram) == 0,
             "whole-run vs byte-by-byte: RAM differs");
    FZ_CHECK(((a->errors ^ b->errors) & ~(uint32_t)EMU_E_STRAY_DATA) == 0 &&
                 (a->errors & ~b->errors) == 0,
             "whole-run errors %#x, byte-by-byte %#x", a->errors, b->errors);
}

static void view(const emu_panel *e, unsigned rot)
{
    unsigned w, h;
    emu_view_size(e, rot, &w, &h);
    FZ_CHECK(w * h == (unsigned)e->m->vis_w * e->m->vis_h, "view %ux%u of %ux%u glass", w, h,
             e->m->vis_w, e->m->vis_h);
    uint32_t *px = malloc((size_t)w * h * sizeof *px);
    emu_view_666(e, rot, px);
    uint32_t any = 0;
    for (size_t i = 0; i < (size_t)w * h; i++)
        any |= px[i];
    FZ_CHECK(any <= 0x3FFFFu, "a view pixel has bits above 18 (%#x)", any);
    free(px);
}

/* emu_init once per model (it allocates the RAM and fills it with noise);
 * each input starts from a copy of that power-on state. */
#define MAX_MODELS 16
static emu_panel g_power_on[MAX_MODELS];
static uint32_t *g_ram[MAX_MODELS][2];

static void fresh(emu_panel *e, unsigned mi, int which)
{
    emu_panel *p = &g_power_on[mi];
    size_t n;
    if (!p->m) {
        FZ_CHECK(emu_init(p, emu_model_at(mi)) == 0, "emu_init(%u) failed", mi);
        n = (size_t)p->m->ram_w * p->m->ram_h;
        g_ram[mi][0] = malloc(n * sizeof(uint32_t));
        g_ram[mi][1] = malloc(n * sizeof(uint32_t));
    }
    n = (size_t)p->m->ram_w * p->m->ram_h;
    *e = *p;
    e->ram = g_ram[mi][which];
    memcpy(e->ram, p->ram, n * sizeof(uint32_t));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static two t;
    static uint8_t run[65536];
    fz_reader d;
    uint64_t fed = 0;
    size_t long_budget = 1u << 18;
    fz_init(&d, data, size);
    unsigned mi = fz_u8(&d) % emu_model_count();
    const emu_model *m = emu_model_at(mi);
    FZ_CHECK(m != NULL && mi < MAX_MODELS, "no model %u", mi);
    fresh(&t.a, mi, 0);
    fresh(&t.b, mi, 1);
    int views = 0;
    for (int ops = 0; ops < MAX_OPS && fz_left(&d) > 0; ops++) {
        uint8_t op = fz_u8(&d);
        switch (op % 9u) {
        case 0:
        case 1: { /* command */
            uint8_t c = fz_u8(&d);
            emu_command(&t.a, c);
            emu_command(&t.b, c);
            fed++;
            break;
        }
        case 2:
        case 3: { /* a data run, as given */
            size_t n = fz_u8(&d);
            if (n > fz_left(&d))
                n = fz_left(&d);
            memcpy(run, d.p + d.pos, n);
            d.pos += n;
            emu_data(&t.a, run, n);
            for (size_t i = 0; i < n; i++)
                emu_data(&t.b, run + i, 1);
            fed += n;
            break;
        }
        case 4: { /* a long pixel run: a pattern of 1..3 bytes repeated */
            size_t n = fz_u16(&d), k = 1 + fz_u8(&d) % 3u;
            if (n > long_budget)
                n = long_budget; /* bounded work per input: a full 240x320 frame */
            long_budget -= n;
            uint8_t pat[3] = {fz_u8(&d), fz_u8(&d), fz_u8(&d)};
            for (size_t i = 0; i < n; i++)
                run[i] = pat[i % k];
            emu_data(&t.a, run, n);
            /* B in a few uneven pieces */
            for (size_t i = 0; i < n;) {
                size_t piece = 1 + (i * 7u + 3u) % 61u;
                if (piece > n - i)
                    piece = n - i;
                emu_data(&t.b, run + i, piece);
                i += piece;
            }
            fed += n;
            break;
        }
        case 5: { /* delay */
            uint8_t v = fz_u8(&d);
            uint32_t ms = v < 200 ? v : (uint32_t)(v - 199) * 1000u;
            emu_delay_ms(&t.a, ms);
            emu_delay_ms(&t.b, ms);
            break;
        }
        case 6: { /* reset line */
            int level = fz_u8(&d) & 1;
            emu_reset_line(&t.a, level);
            emu_reset_line(&t.b, level);
            break;
        }
        case 7:
            emu_flush(&t.a);
            emu_flush(&t.b);
            break;
        default: {
            unsigned rot = fz_u8(&d) & 3u;
            if (views++ < 2) /* reading back is slow: a few per input */
                view(&t.a, rot);
            break;
        }
        }
    }
    emu_flush(&t.a);
    emu_flush(&t.b);
    check_panel(&t.a, fed, "whole-run");
    check_panel(&t.b, fed, "byte-by-byte");
    same_state(&t.a, &t.b);
    if (getenv("FUZZ_VERBOSE")) {
        fprintf(stderr, "%s: %llu bytes, %u commands, %llu pixels, %u wraps, errors %#x (%u)\n",
                m->name, (unsigned long long)fed, t.a.commands, (unsigned long long)t.a.pixels,
                t.a.wraps, t.a.errors, t.a.error_count);
        for (unsigned i = 0; i < t.a.log_lines; i++)
            fprintf(stderr, "  %s\n", t.a.log[i]);
    }
    return 0;
}
