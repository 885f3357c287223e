/* SPDX-License-Identifier: MIT */
/*
 * src/span.c as it is, compiled with its two span fills routed through a
 * counter, for the fuzz build of the core only (build/fuzz/: this object
 * replaces span.o there). Every fill of the span walk first reports the
 * columns it writes to fuzz_span_fill(), so the frame harness can check that
 * each pixel of every row is written exactly once, by spans inside [0, width).
 *
 * zs_internal.h is included first (it is include-guarded), then the two fill
 * names become function-like macros, then span.c is included: span.c's own
 * #include of zs_internal.h is a no-op and its calls expand to the report
 * followed by the real fill (a macro's name is not expanded again inside its
 * own expansion, so the types are whatever the core declares). If span.c
 * stops filling through zs_fill_flat / zs_fill_gouraud, the harness sees no
 * fills in a span frame and says so (not silently passing).
 */
#include "zs_internal.h"

void fuzz_span_fill(const uint8_t *row, int x0, int x1);

/* The harnesses that do not render define nothing: a no-op default. */
__attribute__((weak)) void fuzz_span_fill(const uint8_t *row, int x0, int x1)
{
    (void)row;
    (void)x0;
    (void)x1;
}

#define zs_fill_flat(row, x0, x1, bpp, pixel)                                         \
    (fuzz_span_fill((row), (x0), (x1)), zs_fill_flat((row), (x0), (x1), (bpp), (pixel)))
#define zs_fill_gouraud(r, a, dy, row, x0, x1)                                        \
    (fuzz_span_fill((row), (x0), (x1)), zs_fill_gouraud((r), (a), (dy), (row), (x0), (x1)))
#include "span.c"
