/* SPDX-License-Identifier: MIT */
/*
 * test_meshc_llvmpipe: the converted duck (t_duck, zspan-meshc --texture
 * auto, compiled in) against Mesa's llvmpipe (OSMesa), as tests/core/
 * test_llvmpipe.c does for random triangles: the converter's real mesh and
 * texture coordinates, seen from twelve directions, with the duck's texture
 * swapped for a 32 x 64 one whose texels encode their own column and row
 * (R, G), nearest filtering, perspective-correct. GL draws the renderer's
 * snapped screen triangles (the setup hook) with clip w following the
 * window depth, so both interpolate the same perspective.
 *
 * Over the pixels where the nearest surface is clear (a ray caster over the
 * same records): the same texel at >= 99 % of them in the exact mode, never
 * more than one texel off; the subdivided mode within one texel everywhere.
 * And the RGB565 frame (the fill's direct path) holds the same texels as
 * the RGB888 one (its general path), pixel for pixel.
 */
#include "zt_test.h"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "t_duck.h"
#include "zt_gl.h"

#define W 128
#define H 96
#define TW 32
#define TH 64
#define NEAR_FX (ZS_FX(1) / 4)
#define FAR_FX ZS_FX(64)

const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libOSMesa\n"; /* Mesa's blocks for the life of the process */
}

static uint16_t g_code[TW * TH];
static OSMesaContext g_gl;
static uint8_t *g_gl_rgba;

static int setup(void **state)
{
    const char *name;
    (void)state;
    for (int j = 0; j < TH; j++)
        for (int i = 0; i < TW; i++)
            g_code[j * TW + i] = (uint16_t)(i << 11 | j << 5 | 8);
    g_gl = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    g_gl_rgba = malloc((size_t)W * H * 4);
    if (!g_gl || !g_gl_rgba || !OSMesaMakeCurrent(g_gl, g_gl_rgba, GL_UNSIGNED_BYTE, W, H))
        return -1;
    name = (const char *)glGetString(GL_RENDERER);
    fprintf(stderr, "test_meshc_llvmpipe: GL_RENDERER %s\n", name ? name : "(none)");
    return name && strstr(name, "llvmpipe") ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    OSMesaDestroyContext(g_gl);
    free(g_gl_rgba);
    return 0;
}

/* The records with the duck's uvs: record tag t is mesh triangle t - 1. */
static void gl_frame(const zt_recs *recs)
{
    zt_gl_draw_records(recs, t_duck.indices, t_duck.uvs, g_code, TW, TH, W, H,
                       (double)FAR_FX / (double)(FAR_FX - NEAR_FX), 0);
}

static int wrap_dist(int a, int b, int n)
{
    int d = abs(a - b);
    return d < n - d ? d : n - d;
}

typedef struct tally {
    unsigned long px, same, one, more, views, direct_px;
} tally;

static void compare(const zt_recs *recs, const uint8_t *img, tally *t)
{
    zt_cast cast;
    zt_cast_alloc(&cast, W, H);
    zt_raycast(recs, &cast);
    for (int py = 0; py < H; py++)
        for (int px = 0; px < W; px++) {
            int k = py * W + px;
            const uint8_t *g = g_gl_rgba + ((size_t)(H - 1 - py) * W + px) * 4, *p = img + 3 * k;
            if (cast.best[k] < 0 || cast.z2[k] - cast.z1[k] < 1e-6 || g[3] == 0)
                continue; /* no clear nearest surface, or GL's edge rule left it */
            int di = wrap_dist(p[0] >> 3, g[0] >> 3, TW), dj = wrap_dist(p[1] >> 2, g[1] >> 2, TH);
            t->px++;
            t->same += !di && !dj;
            t->one += (di || dj) && di <= 1 && dj <= 1;
            t->more += di > 1 || dj > 1;
        }
    zt_cast_free(&cast);
}

static void run(unsigned flags, tally *t)
{
    zs_config cfg = zs_config_default(W, H, 8000, 8000, 2000);
    size_t bytes;
    void *arena;
    zs_renderer r;
    zs_camera cam;
    uint8_t *img = malloc((size_t)W * H * 3);
    zs_texture code;
    zs_mesh m = t_duck;
    cfg.flags = ZS_CFG_TEXTURE;
    bytes = zs_arena_bytes(&cfg);
    arena = malloc(bytes);
    assert_non_null(arena);
    assert_non_null(img);
    assert_int_equal(zs_init(&r, arena, bytes, &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(0, ZS_FX(1) / 2, ZS_FX(2)),
                                       zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), NEAR_FX, FAR_FX), ZS_OK);
    memset(&code, 0, sizeof code);
    code.texels = g_code;
    code.width = TW;
    code.height = TH;
    code.format = ZS_TEX_RGB565;
    code.flags = (uint8_t)flags;
    m.texture = &code;
    m.color = 0xFFFFFF;
    for (int view = 0; view < 12; view++) {
        zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(30 * view)), rx = zs_mat34_rotate_x(ZS_FX(view % 3 * 20 - 20));
        zs_mat34 model = zs_mat34_mul(&rx, &ry);
        zs_shade_params sp = zs_shade_default();
        zt_recs recs = {0};
        sp.format = ZS_FMT_RGB888;
        sp.ambient = ZS_FX_ONE; /* unlit: the texel as it is */
        sp.light_count = 0;
        zs_set_setup_hook(&r, zt_recs_hook, &recs);
        assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
        assert_int_equal(zs_frame_shading(&r, &sp), ZS_OK);
        assert_int_equal(zs_draw(&r, &m, &model), ZS_OK);
        assert_int_equal(zt_render_rows_all(&r, img, W, H, sp.format, H), ZS_OK);
        assert_int_equal(r.stats.tris_clipped, 0); /* records are the mesh's triangles */
        assert_int_equal(r.stats.tris_dropped, 0);
        gl_frame(&recs);
        compare(&recs, img, t);
        for (int be = 0; be < 2; be++) { /* RGB565 rows take the direct fill (texels
                                            * stored as they are): the same texels as the
                                            * RGB888 rows of the general one */
            static uint8_t img16[W * H * 2];
            zs_shade_params sp16 = sp;
            sp16.format = be ? ZS_FMT_RGB565_BE : ZS_FMT_RGB565;
            assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
            assert_int_equal(zs_frame_shading(&r, &sp16), ZS_OK);
            assert_int_equal(zs_draw(&r, &m, &model), ZS_OK);
            assert_int_equal(zt_render_rows_all(&r, img16, W, H, sp16.format, H), ZS_OK);
            for (int k = 0; k < W * H; k++) {
                const uint8_t *q = img + 3 * k, *g16 = img16 + 2 * k;
                unsigned want = (unsigned)(q[0] >> 3) << 11 | (unsigned)(q[1] >> 2) << 5 | q[2] >> 3;
                unsigned got = be ? (unsigned)g16[0] << 8 | g16[1] : (unsigned)g16[1] << 8 | g16[0];
                if (got != want)
                    fail_msg("view %d pixel %d (%s): RGB565 %04x, RGB888 %02x%02x%02x", view, k,
                             be ? "BE" : "LE", got, q[0], q[1], q[2]);
            }
            t->direct_px += W * H;
        }
        t->views++;
        zt_recs_free(&recs);
    }
    free(img);
    free(arena);
}

static void test_duck_exact(void **state)
{
    tally t;
    (void)state;
    memset(&t, 0, sizeof t);
    run(0, &t);
    fprintf(stderr, "llvmpipe, converted duck, exact: %lu views, %lu px, same texel %lu "
                    "(%.3f%%), one off %lu, more %lu\n",
            t.views, t.px, t.same, 100.0 * (double)t.same / (double)t.px, t.one, t.more);
    assert_true(t.px > 20000);
    assert_true((double)t.same >= 0.99 * (double)t.px);
    assert_int_equal(t.more, 0);
}

static void test_duck_subdivided(void **state)
{
    tally t;
    (void)state;
    memset(&t, 0, sizeof t);
    run(ZS_TEX_SUBDIV, &t);
    fprintf(stderr, "llvmpipe, converted duck, subdivided: %lu px, same texel %lu (%.3f%%), one "
                    "off %lu, more %lu\n",
            t.px, t.same, 100.0 * (double)t.same / (double)t.px, t.one, t.more);
    assert_true(t.px > 20000);
    assert_int_equal(t.more, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_duck_exact),
        cmocka_unit_test(test_duck_subdivided),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
