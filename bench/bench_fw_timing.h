/* SPDX-License-Identifier: MIT */
/* Timing shared by the firmware benchmarks (bench_fw.c, bench_lean_fw.c):
 * the cost of a timed section with nothing inside, subtracted from every
 * section a benchmark times on its own, and the frame's rows timed one call
 * at a time (a board with no room for a framebuffer). Include after the
 * board's port.h (port_ticks). */
#ifndef BENCH_FW_TIMING_H
#define BENCH_FW_TIMING_H

#include "bench_scenes.h"

#include <stdint.h>

/* x1000 instructions, for ipt_milli instructions per tick (x1000), measured
 * with the same code shape as the benchmarks' per-row sections. */
static uint32_t bench_section_overhead_milli(uint32_t ipt_milli)
{
    uint64_t acc = 0;
    int i;
    for (i = 0; i < 4096; i++) {
        uint64_t a = port_ticks();
        uint64_t b = port_ticks();
        acc += b - a;
    }
    return (uint32_t)(acc * ipt_milli / 4096u);
}

/* The frame's rows rendered one at a time into line (size bytes, one row),
 * each call timed on its own: its ticks added to *ticks, one section each
 * to *sections, the rows folded into the checksum *sum. */
static zs_status bench_timed_rows(zs_renderer *r, uint8_t *line, size_t size, uint64_t *ticks,
                                  uint32_t *sections, uint32_t *sum)
{
    zs_status st = ZS_OK;
    int y;
    for (y = 0; st == ZS_OK && y < BENCH_H; y++) {
        uint64_t a = port_ticks(), b;
        st = zs_render_rows(r, y, 1, line, size);
        b = port_ticks();
        *ticks += b - a;
        (*sections)++;
        *sum = bench_fnv1a(*sum, line, size);
    }
    return st;
}

#endif
