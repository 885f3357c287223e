/* SPDX-License-Identifier: MIT */
/* LIBS: -lOSMesa */
/*
 * test_llvmpipe: texture mapping against Mesa's llvmpipe (OSMesa, an
 * offscreen context; Debian's libosmesa6-dev). Both draw the same random
 * triangles with a 32 x 64 texture whose texels encode their own
 * coordinates (R = column, G = row), nearest filtering, perspective-correct:
 * GL gets the renderer's snapped screen vertices (the setup hook) as clip
 * coordinates whose w follows the window depth (1/w ~ A - z), so both
 * interpolate the same perspective over the same triangles.
 *
 * Over the pixels both cover with a clear nearest surface (ray caster):
 *  - exact mode: the same texel at >= 99% of them, within one texel at all;
 *  - subdivided mode: within one texel at all (its bound, 1/4 texel, is
 *    measured against a double reference in test_texture), and the share
 *    of exact texels is reported.
 */
#include "zt_test.h"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "zt_gl.h"

#define W 128
#define H 96
#define NEAR_FX (ZS_FX(1) / 4)
#define FAR_FX ZS_FX(64)
#define TW 32
#define TH 64

/* Mesa keeps a few blocks for the life of the process: not ours to free. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libOSMesa\n";
}

static uint16_t g_tex[TW * TH];
static OSMesaContext g_gl;
static uint8_t *g_glbuf;

static int gl_setup(void **state)
{
    (void)state;
    for (int j = 0; j < TH; j++)
        for (int i = 0; i < TW; i++)
            g_tex[j * TW + i] = (uint16_t)((i << 11) | (j << 5) | 16);
    g_gl = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!g_gl) {
        fprintf(stderr, "test_llvmpipe: OSMesaCreateContextExt failed\n");
        return -1;
    }
    g_glbuf = malloc((size_t)W * H * 4);
    if (!OSMesaMakeCurrent(g_gl, g_glbuf, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "test_llvmpipe: OSMesaMakeCurrent failed\n");
        return -1;
    }
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    fprintf(stderr, "test_llvmpipe: GL_RENDERER %s\n", renderer ? renderer : "(none)");
    if (!renderer || !strstr(renderer, "llvmpipe")) {
        fprintf(stderr, "test_llvmpipe: not llvmpipe\n");
        return -1;
    }
    return 0;
}

static int gl_teardown(void **state)
{
    (void)state;
    OSMesaDestroyContext(g_gl);
    free(g_glbuf);
    return 0;
}

static void ctx_init(zt_ctx *c)
{
    memset(c, 0, sizeof *c);
    c->cfg = zs_config_default(W, H, 400, 1200, 400);
    c->cfg.flags = ZS_CFG_TEXTURE;
    c->arena_size = zs_arena_bytes(&c->cfg);
    c->arena = malloc(c->arena_size);
    assert_non_null(c->arena);
    assert_int_equal(zs_init(&c->r, c->arena, c->arena_size, &c->cfg), ZS_OK);
}

/* GL draws the records (the renderer's screen triangles) with the texture
 * coordinates of their mesh triangles. */
static void gl_draw(const zt_recs *recs, const zt_scene *s, const int16_t *uv, int clamp)
{
    zt_gl_draw_records(recs, s->idx, uv, g_tex, TW, TH, W, H,
                       (double)FAR_FX / (double)(FAR_FX - NEAR_FX), clamp);
}

static int texel_dist(int a, int b, int n, int clamp)
{
    int d = abs(a - b);
    return clamp ? d : (d < n - d ? d : n - d);
}

typedef struct acc {
    unsigned long px, exact, off1, worse, gl_empty;
} acc;

static void compare(const zt_recs *recs, const uint8_t *img, int clamp, acc *a)
{
    zt_cast cast;
    zt_cast_alloc(&cast, W, H);
    zt_raycast(recs, &cast);
    for (int py = 0; py < H; py++)
        for (int px = 0; px < W; px++) {
            int k = py * W + px;
            if (cast.best[k] < 0 || cast.z2[k] - cast.z1[k] < 1e-6)
                continue;
            const uint8_t *g = g_glbuf + ((size_t)(H - 1 - py) * W + px) * 4; /* GL: bottom up */
            const uint8_t *p = img + (size_t)k * 3;
            if (g[3] == 0) { /* GL left it empty: an edge centre decided the other way */
                a->gl_empty++;
                continue;
            }
            int di = texel_dist(p[0] >> 3, g[0] >> 3, TW, clamp);
            int dj = texel_dist(p[1] >> 2, g[1] >> 2, TH, clamp);
            a->px++;
            if (!di && !dj)
                a->exact++;
            else if (di <= 1 && dj <= 1)
                a->off1++;
            else
                a->worse++;
        }
    zt_cast_free(&cast);
}

static void run(unsigned flags, acc *a)
{
    zt_rng g;
    zt_rng_seed(&g, 0x11F3E0001ull);
    zt_ctx c;
    ctx_init(&c);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    uint8_t *img = malloc((size_t)W * H * 3);
    for (int sc = 0; sc < 100; sc++) {
        zt_scene s;
        zt_scene_init(&s, W, H, 64);
        zt_scene_random(&g, &s, 4 + (int)zt_below(&g, 16),
                        ZT_SC_PLAIN | ZT_SC_FLAT | ZT_SC_SHARED | ZT_SC_LAYERS, 0.25);
        int spread = 2 + (int)zt_below(&g, 16);
        int16_t *uv = malloc(2 * s.nv * sizeof *uv + 1);
        for (size_t k = 0; k < 2 * s.nv; k++)
            uv[k] = (int16_t)zt_range(&g, -spread * ZS_UV_ONE / 4, spread * ZS_UV_ONE / 4);
        int clamp = sc % 2;
        zs_texture tex;
        memset(&tex, 0, sizeof tex);
        tex.texels = g_tex;
        tex.width = TW;
        tex.height = TH;
        tex.format = ZS_TEX_RGB565;
        tex.flags = (uint8_t)(flags | (clamp ? ZS_TEX_CLAMP : 0u));
        zs_mesh m = zt_scene_mesh(&s, 0, 0);
        m.color = 0xFFFFFF;
        m.uvs = uv;
        m.texture = &tex;
        zs_shade_params sp = zs_shade_default();
        sp.format = ZS_FMT_RGB888;
        zt_recs recs = {0};
        zs_set_setup_hook(&c.r, zt_recs_hook, &recs);
        assert_int_equal(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
        assert_int_equal(zs_frame_shading(&c.r, &sp), ZS_OK);
        assert_int_equal(zs_draw(&c.r, &m, NULL), ZS_OK);
        assert_int_equal(zt_render_rows_all(&c.r, img, W, H, sp.format, H), ZS_OK);
        if (c.r.stats.tris_clipped == 0) { /* records are the mesh's triangles */
            gl_draw(&recs, &s, uv, clamp);
            compare(&recs, img, clamp, a);
        }
        zt_recs_free(&recs);
        free(uv);
        zt_scene_free(&s);
    }
    free(img);
    zt_ctx_free(&c);
}

static void test_nearest_exact(void **state)
{
    (void)state;
    acc a;
    memset(&a, 0, sizeof a);
    run(0, &a);
    fprintf(stderr,
            "llvmpipe, exact: %lu px, same texel %lu (%.3f%%), one texel off %lu, more %lu; "
            "%lu px GL left empty\n",
            a.px, a.exact, 100.0 * (double)a.exact / (double)a.px, a.off1, a.worse, a.gl_empty);
    assert_true(a.px > 50000);
    assert_true((double)a.exact >= 0.99 * (double)a.px);
    assert_int_equal(a.worse, 0);
}

static void test_nearest_subdivided(void **state)
{
    (void)state;
    acc a;
    memset(&a, 0, sizeof a);
    run(ZS_TEX_SUBDIV, &a);
    fprintf(stderr,
            "llvmpipe, subdivided: %lu px, same texel %lu (%.3f%%), one texel off %lu, more %lu\n",
            a.px, a.exact, 100.0 * (double)a.exact / (double)a.px, a.off1, a.worse);
    assert_true(a.px > 50000);
    assert_true((double)a.exact >= 0.98 * (double)a.px);
    assert_int_equal(a.worse, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_exact),
        cmocka_unit_test(test_nearest_subdivided),
    };
    return cmocka_run_group_tests(tests, gl_setup, gl_teardown);
}
