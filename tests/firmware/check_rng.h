/* SPDX-License-Identifier: MIT */
/* The host-vs-QEMU checks' shared pieces (check_project_m4.c,
 * check_frames_xtarget.c): a 32-bit LCG, so the random draws are the same
 * on every target, and FNV-1a over words and bytes. Each program includes
 * it once and seeds it with check_seed. */
#ifndef ZS_CHECK_RNG_H
#define ZS_CHECK_RNG_H

#include <stddef.h>
#include <stdint.h>

static uint32_t check_rng_state;

static inline void check_seed(uint32_t s)
{
    check_rng_state = s;
}

static inline uint32_t next(void)
{
    check_rng_state = check_rng_state * 1103515245u + 12345u;
    return check_rng_state >> 8; /* 24 bits */
}

static inline int32_t range(int32_t lo, int32_t hi) /* inclusive, hi - lo < 2^24 */
{
    return lo + (int32_t)(next() % (uint32_t)(hi - lo + 1));
}

/* FNV-1a of n bytes, and of a word's four bytes low first */
static inline uint32_t fnv_bytes(uint32_t h, const uint8_t *p, size_t n)
{
    while (n--) {
        h ^= *p++;
        h *= 0x01000193u;
    }
    return h;
}

static inline uint32_t fnv_word(uint32_t h, uint32_t word)
{
    int k;
    for (k = 0; k < 4; k++) {
        h ^= (word >> (8 * k)) & 255u;
        h *= 0x01000193u;
    }
    return h;
}

#endif
