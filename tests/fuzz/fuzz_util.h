/* SPDX-License-Identifier: MIT */
/*
 * Shared helpers of the zspan fuzz harnesses: a byte reader that never fails
 * (missing bytes read as zero, so every input decodes to something) and a
 * failure macro that prints the broken invariant and aborts, which libFuzzer
 * reports as a crash with the input saved.
 */
#ifndef ZSPAN_FUZZ_UTIL_H
#define ZSPAN_FUZZ_UTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct fz_reader {
    const uint8_t *p;
    size_t n, pos;
} fz_reader;

static inline void fz_init(fz_reader *d, const uint8_t *p, size_t n)
{
    d->p = p;
    d->n = n;
    d->pos = 0;
}

static inline uint8_t fz_u8(fz_reader *d)
{
    return d->pos < d->n ? d->p[d->pos++] : 0;
}

static inline uint16_t fz_u16(fz_reader *d)
{
    uint16_t lo = fz_u8(d);
    return (uint16_t)(lo | (uint16_t)(fz_u8(d) << 8));
}

static inline uint32_t fz_u32(fz_reader *d)
{
    uint32_t lo = fz_u16(d);
    return lo | ((uint32_t)fz_u16(d) << 16);
}

static inline size_t fz_left(const fz_reader *d)
{
    return d->pos < d->n ? d->n - d->pos : 0;
}

/* An invariant failed: say which and where, then abort (libFuzzer keeps the input). */
#define FZ_CHECK(cond, ...)                                                           \
    do {                                                                              \
        if (!(cond)) {                                                                \
            fprintf(stderr, "\n%s:%d: invariant failed: %s\n  ", __FILE__, __LINE__,  \
                    #cond);                                                           \
            fprintf(stderr, __VA_ARGS__);                                             \
            fprintf(stderr, "\n");                                                    \
            abort();                                                                  \
        }                                                                             \
    } while (0)

#endif
