/* SPDX-License-Identifier: MIT */
/*
 * fuzz_mono: the emulated monochrome controllers (host_sim/emu/emu_mono.c:
 * SSD1306, SH1106, SSD1680, SSD0303) decoding arbitrary wire streams (libFuzzer).
 *
 * Input: byte 0 picks the model; the rest is a program of operations: a
 * command byte (D/C low), a run of data bytes (D/C high), an I2C write
 * transaction (any address and control bytes), a delay, the reset line, or
 * reading the picture back at rotation 0 or 2.
 *
 * The program runs on two controllers of the same model: A gets every data
 * run in one emu_mono_data call, B one call per byte (a wire has no call
 * boundaries). Invariants: no memory error whatever the bytes; A and B end
 * in the same state (RAMs, glass, counters, windows, registers, errors,
 * counts); RAM cells and view pixels are 0 or 1; error flags documented
 * bits only; data bytes taken <= bytes fed.
 */
#include <stdlib.h>
#include <string.h>

#include "emu_mono.h"
#include "fuzz_util.h"

#define MAX_OPS 4096

static void same(const emu_mono *a, const emu_mono *b)
{
    const emu_mono_model *m = a->m;
    size_t n = (size_t)m->ram_w * m->ram_h;
#define SAME(f) FZ_CHECK(a->f == b->f, "whole-run vs byte-by-byte: " #f " %llu != %llu", \
                         (unsigned long long)a->f, (unsigned long long)b->f)
    SAME(display_on); SAME(inverse); SAME(all_on); SAME(pump); SAME(seg_remap);
    SAME(com_remap); SAME(mux); SAME(offset); SAME(start_line); SAME(compins); SAME(mode);
    SAME(col); SAME(page); SAME(col_lo); SAME(col_hi); SAME(page_lo); SAME(page_hi);
    SAME(entry); SAME(target); SAME(seq); SAME(x_lo); SAME(x_hi); SAME(y_lo); SAME(y_hi);
    SAME(xc); SAME(yc); SAME(cmd); SAME(have); SAME(writing); SAME(errors); SAME(bytes);
    SAME(data_bytes); SAME(commands); SAME(refreshes); SAME(partial_refreshes);
#undef SAME
    FZ_CHECK(memcmp(a->ram, b->ram, n) == 0 && memcmp(a->ram2, b->ram2, n) == 0,
             "whole-run vs byte-by-byte: RAM differs");
    FZ_CHECK(memcmp(a->glass, b->glass, (size_t)m->vis_w * m->vis_h) == 0,
             "whole-run vs byte-by-byte: glass differs");
}

static void check(const emu_mono *e, uint64_t fed)
{
    const emu_mono_model *m = e->m;
    size_t n = (size_t)m->ram_w * m->ram_h, i;
    uint8_t any = 0;
    for (i = 0; i < n; i++)
        any |= (uint8_t)(e->ram[i] | e->ram2[i]);
    FZ_CHECK(any <= 1, "a RAM cell holds %u", any);
    FZ_CHECK((e->errors & ~((1u << EMU_M_COUNT) - 1u)) == 0, "undocumented error bits %#x",
             e->errors);
    FZ_CHECK(e->data_bytes <= fed && e->bytes <= fed, "took %llu data bytes of %llu fed",
             (unsigned long long)e->data_bytes, (unsigned long long)fed);
}

static void view(const emu_mono *e, unsigned rot)
{
    size_t n = (size_t)e->m->vis_w * e->m->vis_h, i;
    uint8_t *px = malloc(n), any = 0;
    emu_mono_view(e, rot, px);
    for (i = 0; i < n; i++)
        any |= px[i];
    FZ_CHECK(any <= 1, "a view pixel holds %u", any);
    free(px);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t run[256 + 255 * 16];
    static emu_mono a, b;
    fz_reader d;
    uint64_t fed = 0;
    fz_init(&d, data, size);
    const emu_mono_model *m = emu_mono_model_at(fz_u8(&d) % emu_mono_model_count());
    FZ_CHECK(emu_mono_init(&a, m) == 0 && emu_mono_init(&b, m) == 0, "emu_mono_init failed");
    for (int ops = 0; ops < MAX_OPS && fz_left(&d) > 0; ops++) {
        uint8_t op = fz_u8(&d);
        switch (op % 7u) {
        case 0:
        case 1: { /* command */
            uint8_t c = fz_u8(&d);
            emu_mono_command(&a, c);
            emu_mono_command(&b, c);
            fed++;
            break;
        }
        case 2: { /* data run */
            size_t n = fz_u8(&d) % 64u + 1u, i;
            for (i = 0; i < n; i++)
                run[i] = fz_u8(&d);
            emu_mono_data(&a, run, n);
            for (i = 0; i < n; i++)
                emu_mono_data(&b, &run[i], 1);
            fed += n;
            break;
        }
        case 3: { /* long data run: a whole frame of a pattern */
            size_t n = 256u + (size_t)fz_u8(&d) * 16u, i;
            uint8_t p = fz_u8(&d);
            for (i = 0; i < n; i++)
                run[i] = (uint8_t)(p + i * 37u);
            emu_mono_data(&a, run, n);
            for (i = 0; i < n; i++)
                emu_mono_data(&b, &run[i], 1);
            fed += n;
            break;
        }
        case 4: { /* I2C transaction (the same on both: its boundaries count) */
            size_t n = fz_u8(&d) % 48u, i;
            uint8_t addr = (uint8_t)((fz_u8(&d) & 1u) ? a.i2c_addr : fz_u8(&d) & 0x7Fu);
            for (i = 0; i < n; i++)
                run[i] = fz_u8(&d);
            int ra = emu_mono_i2c_write(&a, addr, run, n);
            int rb = emu_mono_i2c_write(&b, addr, run, n);
            FZ_CHECK(ra == rb && (ra == 0 || ra == -1), "i2c results %d, %d", ra, rb);
            /* 0x3C, the SSD0303's 0x3D (SA0 high on its board) */
            FZ_CHECK(ra == -1 || (addr == (m->family == EMU_MONO_SSD0303 ? 0x3D : 0x3C) &&
                                  m->family != EMU_MONO_SSD1680),
                     "acknowledged address 0x%02X", addr);
            fed += n;
            break;
        }
        case 5: { /* time or the reset line */
            uint8_t k = fz_u8(&d);
            if (k < 200) {
                emu_mono_delay_ms(&a, k);
                emu_mono_delay_ms(&b, k);
            } else {
                emu_mono_reset_line(&a, k & 1);
                emu_mono_reset_line(&b, k & 1);
            }
            break;
        }
        default:
            view(&a, (op & 8u) ? 2u : 0u);
            break;
        }
    }
    same(&a, &b);
    check(&a, fed);
    view(&a, 0);
    emu_mono_free(&a);
    emu_mono_free(&b);
    return 0;
}
