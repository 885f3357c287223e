/* SPDX-License-Identifier: MIT */
/*
 * fuzz_gray: the emulated SSD0323 (host_sim/emu/emu_gray.c, issue 20)
 * decoding arbitrary 4-wire SPI streams (libFuzzer).
 *
 * Input: a program of operations: a command byte (D/C low: commands and
 * their parameters), a run of data bytes (D/C high), the reset line, or
 * reading the glass back.
 *
 * The program runs on two controllers: A gets every data run in one
 * emu_gray_data call, B one call per byte (a wire has no call boundaries).
 * Invariants: no memory error whatever the bytes; A and B end in the same
 * state (RAM, windows, counters, registers, errors); window and counters
 * inside the RAM; view pixels are levels 0..15; error flags documented bits
 * only; bytes taken <= bytes fed.
 */
#include <stdlib.h>
#include <string.h>

#include "emu_gray.h"
#include "fuzz_util.h"

#define MAX_OPS 4096

static void same(const emu_gray *a, const emu_gray *b)
{
#define SAME(f) FZ_CHECK(a->f == b->f, "whole-run vs byte-by-byte: " #f " %llu != %llu", \
                         (unsigned long long)a->f, (unsigned long long)b->f)
    SAME(remap); SAME(start_line); SAME(offset); SAME(mux); SAME(mode); SAME(display_on);
    SAME(col); SAME(row); SAME(col_lo); SAME(col_hi); SAME(row_lo); SAME(row_hi); SAME(cmd);
    SAME(have); SAME(reset_low); SAME(errors); SAME(bytes); SAME(data_bytes); SAME(commands);
#undef SAME
    FZ_CHECK(memcmp(a->ram, b->ram, sizeof a->ram) == 0, "whole-run vs byte-by-byte: RAM differs");
}

static void check(const emu_gray *e, uint64_t fed)
{
    FZ_CHECK(e->col < EMU_GRAY_RAM_COLS && e->col_lo < EMU_GRAY_RAM_COLS &&
                 e->col_hi < EMU_GRAY_RAM_COLS && e->row < EMU_GRAY_RAM_ROWS &&
                 e->row_lo < EMU_GRAY_RAM_ROWS && e->row_hi < EMU_GRAY_RAM_ROWS,
             "address counters outside the RAM: col %u (%u..%u) row %u (%u..%u)", e->col,
             e->col_lo, e->col_hi, e->row, e->row_lo, e->row_hi);
    FZ_CHECK(e->mux < EMU_GRAY_RAM_ROWS && e->start_line < EMU_GRAY_RAM_ROWS &&
                 e->offset < EMU_GRAY_RAM_ROWS,
             "mux %u start %u offset %u", e->mux, e->start_line, e->offset);
    FZ_CHECK((e->errors & ~((1u << EMU_M_COUNT) - 1u)) == 0, "undocumented error bits %#x",
             e->errors);
    FZ_CHECK(e->data_bytes <= fed && e->bytes <= fed, "took %llu data bytes of %llu fed",
             (unsigned long long)e->data_bytes, (unsigned long long)fed);
}

static void view(const emu_gray *e)
{
    static uint8_t px[EMU_GRAY_W * EMU_GRAY_H];
    size_t i;
    uint8_t any = 0;
    emu_gray_view(e, px);
    for (i = 0; i < sizeof px; i++)
        any |= px[i];
    FZ_CHECK(any <= 15, "a view pixel holds %u", any);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t run[64];
    static emu_gray a, b;
    fz_reader d;
    uint64_t fed = 0;
    fz_init(&d, data, size);
    emu_gray_init(&a);
    emu_gray_init(&b);
    for (int ops = 0; ops < MAX_OPS && fz_left(&d) > 0; ops++) {
        uint8_t op = fz_u8(&d);
        switch (op % 5u) {
        case 0:
        case 1: { /* a byte with D/C low */
            uint8_t c = fz_u8(&d);
            emu_gray_command(&a, c);
            emu_gray_command(&b, c);
            fed++;
            break;
        }
        case 2: { /* data run */
            size_t n = fz_u8(&d) % 64u + 1u, i;
            for (i = 0; i < n; i++)
                run[i] = fz_u8(&d);
            emu_gray_data(&a, run, n);
            for (i = 0; i < n; i++)
                emu_gray_data(&b, &run[i], 1);
            fed += n;
            break;
        }
        case 3: { /* the reset line */
            int level = fz_u8(&d) & 1;
            emu_gray_reset_line(&a, level);
            emu_gray_reset_line(&b, level);
            break;
        }
        default:
            view(&a);
            break;
        }
    }
    same(&a, &b);
    check(&a, fed);
    view(&a);
    return 0;
}
