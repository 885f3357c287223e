/* SPDX-License-Identifier: MIT */
/*
 * test_arena_paths: the arena size has two paths, ZS_ARENA_BYTES_CFG in
 * size_t and the 32-bit figure the core takes where size_t is 16 bits (AVR;
 * ZS_ARENA_BYTES_T_(uint32_t, ...)), which decides there whether a config
 * fits the address space. They must agree for every flag combination the
 * core accepts (ZS_CFG_ALL) over a range of sizes up to the limits, and
 * zs_arena_bytes must equal both (0 where the flags are refused). An earlier
 * 32-bit path left out the 1-bit and hidden-line pools and summed the
 * A-buffer in size_t.
 */
#include "zt_test.h"

#include <string.h>

static const uint16_t k_dim[] = {1, 2, 7, 8, 9, 63, 64, 65, 128, 240, 320, 1023, ZS_MAX_DIM};
static const uint16_t k_count[] = {1, 3, 7, 8, 9, 100, 1000, 4097, 30000, ZS_MAX_TRIANGLES};
static const uint16_t k_edges[] = {2, 3, 7, 8, 9, 15, 16, 17, 64, 256, 1001, 4095,
                                   ZS_MAX_ACTIVE_EDGES};
#define N(a) (sizeof(a) / sizeof((a)[0]))

static uint64_t s_lcg = 0x2545F4914F6CDD1Dull;
static unsigned pick(unsigned n)
{
    s_lcg = s_lcg * 6364136223846793005ull + 1442695040888963407ull;
    return (unsigned)((s_lcg >> 33) % n);
}

static void check_one(const zs_config *c, unsigned long *checked)
{
    size_t run = zs_arena_bytes(c);
    size_t wide = ZS_ARENA_BYTES_CFG(c->width, c->height, c->max_triangles, c->max_vertices,
                                     c->max_active_edges, c->flags);
    uint32_t narrow = ZS_ARENA_BYTES_T_(uint32_t, c->width, c->height, c->max_triangles,
                                        c->max_vertices, c->max_active_edges, c->flags);
    ZT_CHECK((uint64_t)narrow == (uint64_t)wide,
             "flags %#x %ux%u tris %u verts %u edges %u: 32-bit %lu, size_t %zu", c->flags,
             c->width, c->height, c->max_triangles, c->max_vertices, c->max_active_edges,
             (unsigned long)narrow, wide);
    if (!ZS_CFG_FLAGS_OK(c->flags))
        ZT_CHECK(run == 0, "flags %#x refused, zs_arena_bytes %zu", c->flags, run);
    else
        ZT_CHECK(run == wide, "flags %#x: zs_arena_bytes %zu, macro %zu", c->flags, run, wide);
    ++*checked;
}

static void test_paths_agree(void **state)
{
    (void)state;
    unsigned long checked = 0;
    ZT_CHECK(ZS_CFG_ALL == 0xFFu, "ZS_CFG_ALL %#x: a new flag needs a look here", ZS_CFG_ALL);
    for (unsigned flags = 0; flags <= ZS_CFG_ALL; flags++) {
        zs_config c;
        if (flags & ~(unsigned)ZS_CFG_ALL)
            continue;
        /* every dimension, count and edge figure at least once, then a random mix */
        for (unsigned i = 0; i < N(k_dim); i++) {
            c = zs_config_default(k_dim[i], k_dim[N(k_dim) - 1 - i], 1000, 800, 256);
            c.flags = (uint16_t)flags;
            check_one(&c, &checked);
        }
        for (unsigned i = 0; i < N(k_count); i++) {
            c = zs_config_default(240, 240, k_count[i], k_count[N(k_count) - 1 - i], 256);
            c.flags = (uint16_t)flags;
            check_one(&c, &checked);
        }
        for (unsigned i = 0; i < N(k_edges); i++) {
            c = zs_config_default(240, 240, 1000, 800, k_edges[i]);
            c.flags = (uint16_t)flags;
            check_one(&c, &checked);
        }
        for (unsigned i = 0; i < 400; i++) {
            c = zs_config_default(k_dim[pick(N(k_dim))], k_dim[pick(N(k_dim))],
                                  k_count[pick(N(k_count))], k_count[pick(N(k_count))],
                                  k_edges[pick(N(k_edges))]);
            c.flags = (uint16_t)flags;
            check_one(&c, &checked);
        }
        c = zs_config_default(ZS_MAX_DIM, ZS_MAX_DIM, ZS_MAX_TRIANGLES, ZS_MAX_VERTICES,
                              ZS_MAX_ACTIVE_EDGES);
        c.flags = (uint16_t)flags;
        check_one(&c, &checked);
    }
    print_message("test_arena_paths: %lu configs, both paths equal\n", checked);
}

/* Each pool a flag adds (or, for ZS_CFG_PRIORITY_ONLY, leaves out) shows in
 * both paths by the same amount (the 32-bit path once missed MONO and LINES). */
static void test_flags_cost_the_same(void **state)
{
    (void)state;
    static const uint16_t add[] = {ZS_CFG_MONO, ZS_CFG_LINES, ZS_CFG_PRIORITY, ZS_CFG_TEXTURE,
                                   ZS_CFG_ABUFFER};
    for (unsigned i = 0; i < N(add); i++) {
        size_t w0 = ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256, 0u);
        size_t w1 = ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256, add[i]);
        uint32_t n0 = ZS_ARENA_BYTES_T_(uint32_t, 240, 240, 1000, 800, 256, 0u);
        uint32_t n1 = ZS_ARENA_BYTES_T_(uint32_t, 240, 240, 1000, 800, 256, add[i]);
        ZT_CHECK(w1 > w0, "flag %#x adds nothing to the size_t figure", add[i]);
        ZT_CHECK((uint64_t)(n1 - n0) == (uint64_t)(w1 - w0),
                 "flag %#x: 32-bit path adds %lu, size_t path %zu", add[i],
                 (unsigned long)(n1 - n0), w1 - w0);
    }
    {
        size_t w0 = ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256, 0u);
        size_t w1 = ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256, ZS_CFG_PRIORITY_ONLY);
        uint32_t n0 = ZS_ARENA_BYTES_T_(uint32_t, 240, 240, 1000, 800, 256, 0u);
        uint32_t n1 = ZS_ARENA_BYTES_T_(uint32_t, 240, 240, 1000, 800, 256, ZS_CFG_PRIORITY_ONLY);
        ZT_CHECK(w0 - w1 == 128u * ZS_ACTIVE_PLANE_BYTES && n0 - n1 == w0 - w1,
                 "ZS_CFG_PRIORITY_ONLY saves %zu (size_t) and %lu (32-bit), not 128 planes",
                 w0 - w1, (unsigned long)(n0 - n1));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paths_agree),
        cmocka_unit_test(test_flags_cost_the_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
