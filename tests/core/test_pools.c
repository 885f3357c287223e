/* SPDX-License-Identifier: MIT */
/*
 * test_pools: every pool of the arena overflowed (triangle records, vertices,
 * active edges, and all of them at once with tiny random capacities). The
 * policy (README.md (Robustness)): no fault, zs_draw still returns ZS_OK, the
 * triangles and edges that do not fit are dropped and counted, the first
 * triangles submitted are the ones kept, and what is drawn is still right.
 * Every frame goes through zt_guarded_frame (guarded buffers, the documented
 * accounting tris_submitted == culled + rejected + empty + dropped + stored,
 * peaks within the capacities, records == setup-hook calls); the triangle
 * and vertex pool frames are also compared with the ray caster.
 */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define RW 64
#define RH 64
#define SEED 0x50B057AA00000009ull

/* many on-screen triangles that all span the middle rows */
static void overlapping_scene(zt_scene *sc, zt_rng *g, int ntri, int own_vertices)
{
    zt_scene_reset(sc);
    int shared[3] = {-1, -1, -1};
    for (int t = 0; t < ntri; t++) {
        int v[3];
        for (int k = 0; k < 3; k++) {
            if (!own_vertices && shared[k] >= 0 && t % 2) {
                v[k] = shared[k];
                continue;
            }
            double px = k == 0 ? zt_uniform(g, 2, 20) : k == 1 ? zt_uniform(g, 44, 62)
                                                            : zt_uniform(g, 10, 54);
            double py = k == 2 ? zt_uniform(g, 56, 62) : zt_uniform(g, 2, 8);
            v[k] = zt_scene_vertex_px(sc, px, py, zt_uniform(g, 2, 10), 0);
            shared[k] = v[k];
        }
        zt_scene_tri_front(sc, v[0], v[1], v[2], 0);
    }
}

/* Triangle pool: 10 records, 50 triangles: the last 40 are dropped. */
static void test_triangle_pool(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9001);
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 256);
    zt_gframe *f = zt_gframe_new(RW, RH);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    /* 1. triangle pool: 10 records, 50 triangles -> the last 40 dropped */
    {
        zt_ctx c;
        zt_ctx_init(&c, RW, RH, 10, 400, 400);
        overlapping_scene(&sc, &g, 50, 1);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 4);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.records == 10 && f->st.tris_stored == 10,
                     "triangle pool 10: records %u stored %u", f->st.records, f->st.tris_stored);
            ZT_CHECK(f->st.tris_dropped == 40, "triangle pool 10 with 50 triangles: dropped %u",
                     f->st.tris_dropped);
            for (size_t i = 0; i < f->recs.n; i++)
                ZT_CHECK(f->recs.v[i].tag == i + 1,
                         "the first triangles are kept (policy: the last are dropped): record "
                         "%zu has tag %u",
                         i, f->recs.v[i].tag);
            ZT_CHECK(zt_vs_raycast(f, "triangle pool") == 0, "triangle pool overflow output wrong");
        }
        /* a second draw in the same frame is dropped whole, still ZS_OK */
        ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_CHECK(zs_frame_stats(&c.r)->tris_dropped == 90, "two draws: dropped %u",
                 zs_frame_stats(&c.r)->tris_dropped);
        zt_ctx_free(&c);
    }
    /* 2. a triangle through the near plane is cut into pieces; with room for
     * one record the first piece is kept and the triangle counts as stored,
     * so only records_dropped reports the pieces lost (both windings: one is
     * the front face) */
    {
        zt_scene_reset(&sc);
        int a = zt_scene_vertex_world(&sc, -3, -2, -4, 0);
        int b = zt_scene_vertex_world(&sc, 3, -2, -4, 0);
        int d = zt_scene_vertex_world(&sc, 0, 2, 2, 0);
        zt_scene_tri(&sc, a, b, d, 0);
        zt_scene_tri(&sc, a, d, b, 0);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        zt_ctx big, one;
        zt_ctx_init(&big, RW, RH, 16, 64, 64);
        zt_ctx_init(&one, RW, RH, 1, 64, 64);
        zt_guarded_frame(&big, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, 4);
        ZT_ST(f->draw_st, ZS_OK);
        uint32_t pieces = f->st.records;
        ZT_CHECK(f->st.tris_clipped >= 1 && pieces >= 2 && f->st.records_dropped == 0,
                 "near-plane triangle: clipped %u, %u pieces, %u records dropped with room",
                 f->st.tris_clipped, pieces, f->st.records_dropped);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&one, &cam, (zs_visibility)mode, &m, 1, NULL, f, 4);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.records == 1 && f->st.tris_stored == 1 && f->st.tris_dropped == 0 &&
                         f->st.records_dropped == pieces - 1,
                     "one record for %u pieces: records %u stored %u tris_dropped %u "
                     "records_dropped %u",
                     pieces, f->st.records, f->st.tris_stored, f->st.tris_dropped,
                     f->st.records_dropped);
        }
        zt_ctx_free(&big);
        zt_ctx_free(&one);
    }
    zt_gframe_free(f);
    zt_scene_free(&sc);
}

/* Vertex pool: 12 vertices, 30 triangles with their own vertices. */
static void test_vertex_pool(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9002);
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 256);
    zt_gframe *f = zt_gframe_new(RW, RH);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    /* 2. vertex pool: 12 vertices, 30 triangles with their own vertices */
    {
        zt_ctx c;
        zt_ctx_init(&c, RW, RH, 200, 12, 400);
        overlapping_scene(&sc, &g, 30, 1);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 64);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.verts_dropped > 0, "vertex pool 12 with 90 vertices: none dropped");
            ZT_CHECK(f->st.verts_stored <= 12, "verts_stored %u", f->st.verts_stored);
            ZT_CHECK(f->st.tris_dropped > 0, "vertex pool overflow: no triangle counted dropped");
            ZT_CHECK(f->st.tris_stored >= 1, "vertex pool 12: not even the first triangles stored");
            ZT_CHECK(zt_vs_raycast(f, "vertex pool") == 0, "vertex pool overflow output wrong");
        }
        zt_ctx_free(&c);
    }
    zt_gframe_free(f);
    zt_scene_free(&sc);
}

/* Active edge pool: 4 edges (2 triangles per row), then the minimum of 2. */
static void test_edge_pool(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9003);
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 256);
    zt_gframe *f = zt_gframe_new(RW, RH);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    /* 3. active edge pool: 4 edges (2 triangles per row), 12 triangles over
     * the same rows */
    {
        zt_ctx c;
        zt_ctx_init(&c, RW, RH, 200, 400, 4);
        overlapping_scene(&sc, &g, 12, 0);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 1 + mode * 7);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.records_skipped > 0, "edge pool 4 with 12 overlapping triangles: none "
                     "dropped");
            ZT_CHECK(f->st.max_active_edges <= 4, "max_active_edges %u", f->st.max_active_edges);
            ZT_CHECK(f->st.tris_drawn < f->st.records, "edge pool: drawn %u of %u records",
                     f->st.tris_drawn, f->st.records);
        }
        /* the minimum pool (2 edges) and 3-row bands */
        zt_ctx_free(&c);
        zt_ctx_init(&c, RW, RH, 200, 400, 2);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 3);
            ZT_ST(f->draw_st, ZS_OK);
            ZT_CHECK(f->st.records_skipped > 0, "edge pool 2: none dropped");
        }
        zt_ctx_free(&c);
    }
    zt_gframe_free(f);
    zt_scene_free(&sc);
}

/* Every pool small at once: random scenes, random tiny capacities. */
static void test_tiny_pools(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9004);
    zt_scene sc;
    zt_scene_init(&sc, RW, RH, 256);
    zt_gframe *f = zt_gframe_new(RW, RH);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(50));
    /* 4. everything at once, random scenes, tiny pools */
    for (int n = 0; n < 60; n++) {
        zt_ctx c;
        zt_ctx_init(&c, RW, RH, (int)zt_range(&g, 1, 20), (int)zt_range(&g, 3, 40),
                    (int)zt_range(&g, 2, 12));
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 40), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int mode = 0; mode < 2; mode++) {
            zt_guarded_frame(&c, &cam, (zs_visibility)mode, &m, 1, NULL, f, 1 + n % 5);
            ZT_ST(f->draw_st, ZS_OK);
        }
        zt_ctx_free(&c);
    }
    zt_gframe_free(f);
    zt_scene_free(&sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_triangle_pool), cmocka_unit_test(test_vertex_pool),
        cmocka_unit_test(test_edge_pool),     cmocka_unit_test(test_tiny_pools),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_pools: seed %llx, %lu guarded frames %dx%d; totals: %lu dropped triangles, "
           "%lu dropped vertices, %lu edge-pool drops; ray-cast pixels %lu, near ties excluded "
           "%lu; %d failed\n",
           (unsigned long long)SEED, zt_tot.frames, RW, RH, zt_tot.dropped, zt_tot.vdropped,
           zt_tot.edropped, zt_tot.px, zt_tot.excluded, rc);
    fflush(stdout);
    return rc;
}
