/* SPDX-License-Identifier: MIT */
/*
 * test_activate: activation's shortcuts against the Warnock mode, which
 * makes every record's plane on its own (the canonical order sorted afresh).
 *
 * A lazy triangle (span and zline modes) keeps its canonical vertices in its
 * unused plane record: zs_make_plane takes them from there, and so does
 * zs_continue_edge while the plane is still lazy (once made, the record holds
 * the plane and the vertices are sorted again). The scenes are tall
 * triangles whose middle vertex lies rows below the top, each with a
 * partner that overlaps it either in its top rows (so its plane is made
 * before the lower short edge starts) or only below the middle vertex (so it
 * is still lazy there), some sharing edges (twins), in ID16 and RGB565:
 * span, zline and Warnock must agree byte for byte.
 */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define W 48
#define H 64
#define NSCENES 300
#define SEED 0xAC71FA7E00000001ull

static unsigned long g_scenes, g_tris, g_bytes, g_renders;

/* A tall front triangle from row ytop to row ybot near eye depth d, its
 * middle vertex rows between, left or right of the long edge; its long edge
 * (out[0], out[1]) that of the previous one where shared_with >= 0. */
static void tall(zt_rng *g, zt_scene *s, double ytop, double ybot, double d, int shared_with,
                 int *out)
{
    double x0 = zt_uniform(g, 2, W - 2), x1 = zt_uniform(g, 2, W - 2);
    double ym = zt_uniform(g, ytop + 3, ybot - 3);
    double xm = zt_uniform(g, 0, W);
    zs_color c = zt_u32(g) & 0xFFFFFFu;
    int a, b, m;
    if (shared_with >= 0) { /* reuse the partner's long edge: a twin */
        a = out[0] = shared_with;
        b = out[1];
    } else {
        a = zt_scene_vertex_px(s, x0, ytop, d + zt_uniform(g, -0.3, 0.3), c);
        b = zt_scene_vertex_px(s, x1, ybot, d + zt_uniform(g, -0.3, 0.3), c);
        out[0] = a;
        out[1] = b;
    }
    m = zt_scene_vertex_px(s, xm, ym, d + zt_uniform(g, -0.3, 0.3), c);
    zt_scene_tri_front(s, a, m, b, c);
    g_tris++;
}

static void test_lazy_canonical_vertices(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 200, 600, 400);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    size_t cap = (size_t)W * H * 3;
    uint8_t *ref = malloc(cap), *img = malloc(cap);
    for (int k = 0; k < NSCENES; k++) {
        zt_scene_reset(&sc);
        int pairs = (int)zt_range(&g, 2, 8);
        for (int p = 0; p < pairs; p++) {
            int v[2];
            double ytop = zt_uniform(&g, -4, H / 2), ybot = ytop + zt_uniform(&g, 12, H);
            double d = zt_uniform(&g, 2, 8);
            tall(&g, &sc, ytop, ybot, d, -1, v);
            if (zt_below(&g, 3) == 0) { /* across the long edge: shares it */
                tall(&g, &sc, ytop, ybot, d + zt_uniform(&g, -1, 1), v[0], v);
            } else if (zt_below(&g, 2)) { /* over the top rows: plane made early */
                tall(&g, &sc, ytop - zt_uniform(&g, 0, 4), ytop + zt_uniform(&g, 4, 8),
                     d + zt_uniform(&g, -1, 1), -1, v);
            } else { /* only below: still lazy where the lower edge starts */
                tall(&g, &sc, ybot - zt_uniform(&g, 2, 6), ybot + zt_uniform(&g, 2, 10),
                     d + zt_uniform(&g, -1, 1), -1, v);
            }
        }
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        for (int f = 0; f < 2; f++) {
            zs_shade_params sp = zs_shade_default();
            sp.format = f ? ZS_FMT_RGB565 : ZS_FMT_ID16;
            size_t n = (size_t)W * H * zs_format_bytes(sp.format);
            memset(ref, 0x5A, cap);
            ZT_ST(zt_frame(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, 1, NULL, ref, H), ZS_OK);
            g_renders++;
            for (int mi = 0; mi < 2; mi++) {
                memset(img, 0xA5, cap);
                ZT_ST(zt_frame(&c, &cam, ZT_MODE(mi), &sp, &m, 1, NULL, img, 1 + k % 5),
                      ZS_OK);
                g_renders++;
                long d = zt_first_diff(ref, img, n);
                if (d >= 0) {
                    long px = d / (long)zs_format_bytes(sp.format);
                    ZT_FAIL("scene %d (seed %llx): %s differs from Warnock at pixel (%ld,%ld), "
                            "format %d",
                            k, (unsigned long long)SEED, ZT_MODE_NAME(mi), px % W, px / W,
                            (int)sp.format);
                }
                g_bytes += n;
            }
        }
        g_scenes++;
    }
    free(ref);
    free(img);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lazy_canonical_vertices),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_activate: seed %llx, %lu scenes (%lu tall triangles), %lu renders, %lu bytes "
           "span and zline equal to Warnock; %d failed\n",
           (unsigned long long)SEED, g_scenes, g_tris, g_renders, g_bytes, rc);
    return rc;
}
