/* SPDX-License-Identifier: MIT */
/* raster.c's one-row edge step (step_one: inline assembly on Thumb-2 and
 * Thumb-1, C elsewhere) against the floor-divmod DDA it stands for: x +=
 * step; err -= rstep; if err < 0 { err += dy; x++ }, on the packed record
 * (frac = err << 16 | rstep). raster.c is compiled into this file so that
 * the static step is called as the edge loop inlines it; the image links
 * the rest of the core without raster.o. Inputs: every err, rstep < dy for
 * small dy, the extremes (dy = 1, 2^15, 2^16 - 1; err, rstep at 0, 1,
 * dy - 1), random ones over the whole allowed range, steps up to +-(2^12 -
 * 1) and x near the int32 limits; then any 32-bit frac, against the C
 * formula (the assembly takes one half from the other for every word).
 * Each build prints a hash of every result and the count of mismatches;
 * make check-edge-step compares host, Cortex-M4 and Cortex-M0 code. */
#include "../../src/raster.c"
#ifdef __arm__
#include "port.h"
#define OUT sh_printf
#else
#include <stdio.h>
#define OUT printf
#endif

static uint32_t seed = 0x5EED1234u;
static uint32_t next(void)
{
    seed = seed * 1664525u + 1013904223u;
    return seed;
}

static uint32_t hash = 0x811C9DC5u;
static void mix(uint32_t w)
{
    int k;
    for (k = 0; k < 4; k++) {
        hash ^= (w >> (8 * k)) & 255u;
        hash *= 0x01000193u;
    }
}

static unsigned long cases, bad;
/* a record in memory the compiler cannot see through, as the pool's are */
static zs_edge rec;
static zs_edge *volatile rec_at = &rec;

/* One step of e (x, err, rstep, dy, step) by the assembly, against the DDA. */
static void check(int32_t x, uint32_t err, uint32_t rstep, uint32_t dy, int32_t step)
{
    zs_edge *const ep = rec_at;
    int32_t got, want_x = x + step;
    uint32_t want_err;
    ep->x = x;
    ep->frac = err << 16 | rstep;
    ep->run = zs_edge_run(100, step);
    ep->dy = (uint16_t)dy;
    ep->lead = ep->trail = ep->pad = 0x5A5Au;
    got = step_one(ep, ep->run);
    if (err < rstep) {
        want_err = err + dy - rstep;
        want_x++;
    } else {
        want_err = err - rstep;
    }
    cases++;
    if (got != want_x || ep->x != want_x || ep->frac != (want_err << 16 | rstep) ||
        ep->dy != (uint16_t)dy || ep->run != zs_edge_run(100, step) || ep->lead != 0x5A5Au ||
        ep->trail != 0x5A5Au || ep->pad != 0x5A5Au) {
        if (bad < 10)
            OUT("E x %ld err %lu rstep %lu dy %lu step %ld: got x %ld frac %08lx\n", (long)x,
                (unsigned long)err, (unsigned long)rstep, (unsigned long)dy, (long)step,
                (long)got, (unsigned long)ep->frac);
        bad++;
    }
    mix((uint32_t)got);
    mix(ep->frac);
}

/* Any word f (outside the record's range too) against the C formula. */
static void check_word(uint32_t f, uint32_t dy)
{
    zs_edge *const ep = rec_at;
    int32_t got, want_x = 7;
    uint32_t want;
    ep->x = 7;
    ep->frac = f;
    ep->run = zs_edge_run(100, 0);
    ep->dy = (uint16_t)dy;
    ep->lead = ep->trail = ep->pad = 0;
    got = step_one(ep, ep->run);
    if (f < f << 16) {
        want = f + (dy << 16) - (f << 16);
        want_x++;
    } else {
        want = f - (f << 16);
    }
    cases++;
    if (got != want_x || ep->frac != want) {
        if (bad < 10)
            OUT("W f %08lx dy %lu: got x %ld frac %08lx\n", (unsigned long)f,
                (unsigned long)dy, (long)got, (unsigned long)ep->frac);
        bad++;
    }
    mix(ep->frac);
}

static const int32_t xs[] = {0, 1, -1, 4095, -4096, INT32_MAX - 4096, INT32_MIN + 4095};
static const int32_t steps[] = {0, 1, -1, 4095, -4095, 17, -300};

int main(void)
{
    uint32_t dy, err, rstep, k;
    static const uint32_t big[] = {1u, 2u, 3u, 16u, 17u, 0x7FFFu, 0x8000u, 0x8001u, 0xFFFEu, 0xFFFFu};
    /* every err, rstep < dy for dy up to 40 */
    for (dy = 1; dy <= 40; dy++)
        for (err = 0; err < dy; err++)
            for (rstep = 0; rstep < dy; rstep++)
                check(xs[(err + rstep) % 7], err, rstep, dy, steps[(err * 3 + rstep) % 7]);
    /* the extremes of large dy, with every x and step */
    for (k = 0; k < sizeof big / sizeof big[0]; k++) {
        const uint32_t d = big[k];
        const uint32_t v[6] = {0u, 1u, d / 2u, d > 2u ? d - 2u : 0u, d - 1u, d > 1u ? 1u : 0u};
        unsigned i, j, a, b;
        for (i = 0; i < 6; i++)
            for (j = 0; j < 6; j++)
                for (a = 0; a < 7; a++)
                    for (b = 0; b < 7; b++)
                        check(xs[a], v[i], v[j], d, steps[b]);
    }
    /* random records over the allowed range */
    for (k = 0; k < 200000u; k++) {
        const uint32_t d = (next() >> 16) | 1u; /* odd, so as not to skip 2^16 - 1 */
        const uint32_t dd = (k & 1) ? d : 1u + (next() >> 16) % 0xFFFFu;
        const int32_t st = (int32_t)(next() >> 20) - 2048;
        const int32_t x = (int32_t)(next() >> 19) - 4096;
        const uint32_t er = (next() >> 16) % dd; /* (one call a statement) */
        check(x, er, (next() >> 16) % dd, dd, st);
    }
    /* any word and dy: the same as the C */
    for (k = 0; k < 100000u; k++) {
        const uint32_t f = next();
        const uint32_t d = next() >> 16;
        check_word(f, d);
        check_word(f & 0xFFFF0000u, d);
        check_word(f | 0xFFFFu, d);
    }
    OUT("H %08lx\n", (unsigned long)hash);
    OUT("N %lu cases, %lu wrong\n", cases, bad);
    return bad != 0;
}
