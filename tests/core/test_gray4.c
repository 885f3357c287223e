/* SPDX-License-Identifier: MIT */
/*
 * test_gray4: the 4-bit grey format (ZS_FMT_GRAY4, issue 20).
 *
 *  - Against an oracle written here: each frame is also rendered in GRAY8
 *    (a byte format the other suites check), and this file quantises it in
 *    double precision (nearest of the 16 levels 0, 1/15, ..., 1; or, with
 *    ZS_GRAY4_DITHER, the level below plus one where the fraction between
 *    the two levels passes the Bayer threshold (2 M + 1) / 128) and packs two
 *    pixels a byte, high nibble first; the core's bytes must equal it, on
 *    random scenes, in both visibility modes, flat and Gouraud, inverted or
 *    not, odd and even widths, bands of 1, 3, 8, 13 rows and the whole frame,
 *    through zs_render_rows and zs_render_frame, with strides past the
 *    minimum (bytes between rows untouched).
 *  - Large flat areas: with dithering the mean level is within 1/64 of
 *    15 g / 255 for every grey g; without, every pixel is the nearest level.
 *  - API: refused without ZS_CFG_MONO, bad flag bits, the stride.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEED 0x0DD17E2500000020ull

static unsigned long g_frames, g_bytes;

/* The suite's pools (zt_ctx_init_flags). */
#define POOLS 400, 1200, 400

/* The recursive 8x8 Bayer matrix, from its bit construction (not the
 * core's table): bit-reversed interleave of (x ^ y) and y. */
static int bayer(int x, int y)
{
    int v = 0;
    for (int b = 0; b < 3; b++) {
        int xb = (x >> b) & 1, yb = (y >> b) & 1;
        v |= ((xb ^ yb) << (2 * (2 - b) + 1)) | (yb << (2 * (2 - b)));
    }
    return v;
}

static int oracle_level(int g, int x, int y, int dither, int invert)
{
    double v = 15.0 * g / 255.0;
    int l;
    if (!dither) {
        l = (int)floor(v + 0.5);
    } else {
        l = (int)floor(v);
        if (v - l > (2.0 * bayer(x & 7, y & 7) + 1.0) / 128.0) l++;
    }
    return invert ? 15 - l : l;
}

/* want: h rows of (w + 1) / 2 bytes */
static void oracle_pack(const uint8_t *grey, int w, int h, int dither, int invert, uint8_t *want)
{
    size_t s = (size_t)(w + 1) / 2;
    memset(want, 0, s * (size_t)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int l = oracle_level(grey[(size_t)y * (size_t)w + (size_t)x], x, y, dither, invert);
            want[(size_t)y * s + (size_t)(x / 2)] |= (uint8_t)(x % 2 ? l : l << 4);
        }
}

/* Bands of `band` rows with stride `stride` through zs_render_rows into a
 * scratch band, copied into img (h rows of (w + 1) / 2). Checks that the
 * bytes past each row's end (up to the stride) are left alone. */
static zs_status render_rows_gray4(zt_ctx *c, uint8_t *img, int band, size_t stride)
{
    int w = c->cfg.width, h = c->cfg.height;
    size_t s = (size_t)(w + 1) / 2;
    uint8_t *buf = malloc(stride * (size_t)band);
    zs_status st = ZS_OK;
    for (int y = 0; y < h && st == ZS_OK; y += band) {
        int n = band < h - y ? band : h - y;
        memset(buf, 0xA5, stride * (size_t)band);
        st = zs_render_rows(&c->r, y, n, buf, stride);
        for (int k = 0; k < n && st == ZS_OK; k++) {
            memcpy(img + (size_t)(y + k) * s, buf + (size_t)k * stride, s);
            for (size_t i = s; i < stride; i++)
                if (buf[(size_t)k * stride + i] != 0xA5) st = ZS_STATUS_COUNT;
        }
    }
    free(buf);
    return st;
}

typedef struct band_copy {
    uint8_t *img;
    int w, next_y, bad;
} band_copy;

static int copy_band(void *user, int y0, int rows, const void *buf, size_t stride)
{
    band_copy *u = user;
    size_t s = (size_t)(u->w + 1) / 2;
    if (y0 != u->next_y) u->bad = 1;
    for (int k = 0; k < rows; k++)
        memcpy(u->img + (size_t)(y0 + k) * s, (const uint8_t *)buf + (size_t)k * stride, s);
    u->next_y = y0 + rows;
    return 0;
}

static zs_status render_frame_gray4(zt_ctx *c, uint8_t *img, int band)
{
    size_t stride = (size_t)(c->cfg.width + 1) / 2 + 2;
    uint8_t *buf = malloc(stride * (size_t)band);
    memset(buf, 0x5A, stride * (size_t)band);
    band_copy u = {img, c->cfg.width, 0, 0};
    zs_status st = zs_render_frame(&c->r, buf, stride, band, copy_band, &u);
    free(buf);
    if (st == ZS_OK && (u.bad || u.next_y != c->cfg.height)) return ZS_STATUS_COUNT;
    return st;
}

static void random_look(zt_rng *g, int k, zs_shade_params *sp)
{
    *sp = zs_shade_default();
    sp->shading = (k & 1) ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    sp->background = zt_u32(g) & 0xFFFFFFu;
    if (k & 2)
        zt_random_light(g, sp, ZS_FX(1) / 2);
}

static void against_oracle(int w, int h, int scenes, uint64_t seed)
{
    zt_rng g;
    zt_rng_seed(&g, seed);
    zt_ctx c;
    zt_ctx_init_flags(&c, w, h, POOLS, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, w, h, 128);
    size_t n = (size_t)(w + 1) / 2 * (size_t)h;
    uint8_t *grey = malloc((size_t)w * (size_t)h), *want = malloc(n), *img = malloc(n);
    static const int bands[] = {1, 3, 8, 13, 1000};
    for (int k = 0; k < scenes; k++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 8, 40), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, k % 3 == 0, k % 3 == 1);
        m.color = zt_u32(&g) & 0xFFFFFFu;
        zs_shade_params sp;
        random_look(&g, k, &sp);
        sp.format = ZS_FMT_GRAY8;
        ZT_ST(zt_begin(&c, &cam, ZS_MODE_ZLINE, &sp, &m), ZS_OK);
        ZT_ST(zs_render_rows(&c.r, 0, h, grey, (size_t)w), ZS_OK);
        for (int v = 0; v < 4; v++) {
            int dither = v & 1, invert = (v >> 1) & 1;
            zs_shade_params gp = sp;
            gp.format = ZS_FMT_GRAY4;
            gp.mono = (uint8_t)((dither ? ZS_GRAY4_DITHER : 0) | (invert ? ZS_MONO_INVERT : 0));
            oracle_pack(grey, w, h, dither, invert, want);
            for (int b = 0; b < 5; b++)
                for (int mode = 0; mode < 2; mode++) {
                    int band = bands[(b + v + k) % 5];
                    int via_frame = (b + mode + k) % 3 == 0;
                    if (band > h) band = h;
                    memset(img, 0xC3, n);
                    ZT_ST(zt_begin(&c, &cam, (zs_visibility)mode, &gp, &m), ZS_OK);
                    if (via_frame)
                        ZT_ST(render_frame_gray4(&c, img, band), ZS_OK);
                    else
                        ZT_ST(render_rows_gray4(&c, img, band,
                                                (size_t)(w + 1) / 2 + (size_t)(b % 2) * 3),
                              ZS_OK);
                    long d = zt_first_diff(want, img, n);
                    ZT_CHECK(d < 0, "%dx%d scene %d: %s%s%s band %d%s: byte %ld is %02x, the "
                             "oracle %02x", w, h, k, mode ? "zline" : "span",
                             dither ? " dithered" : " rounded", invert ? " inverted" : "", band,
                             via_frame ? " (zs_render_frame)" : "", d, d < 0 ? 0 : img[d],
                             d < 0 ? 0 : want[d]);
                    g_frames++;
                    g_bytes += n;
                }
        }
    }
    free(grey); free(want); free(img);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_against_grey_oracle(void **state)
{
    (void)state;
    against_oracle(77, 61, 60, SEED);      /* odd width: a last byte with one pixel */
    against_oracle(128, 64, 30, SEED + 1); /* the SSD0323's glass */
    print_message("GRAY4: %lu frames, %lu bytes equal to the oracle\n", g_frames, g_bytes);
}

/* One screen-filling unlit quad of grey v; the mean level and whether every
 * pixel is the nearest level. */
static double mean_level(zt_ctx *c, const zs_camera *cam, int v, unsigned mono, int *all_nearest)
{
    int w = c->cfg.width, h = c->cfg.height;
    zt_scene sc;
    zs_mesh m = zt_scene_grey_quad(&sc, w, h, v);
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_GRAY4;
    sp.mono = (uint8_t)mono;
    ZT_ST(zt_begin(c, cam, ZS_MODE_SPAN, &sp, &m), ZS_OK);
    size_t s = (size_t)(w + 1) / 2;
    uint8_t *img = calloc(s * (size_t)h, 1);
    ZT_ST(render_rows_gray4(c, img, 8, s), ZS_OK);
    long sum = 0;
    int nearest = (int)floor(15.0 * v / 255.0 + 0.5);
    *all_nearest = 1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t byte = img[(size_t)y * s + (size_t)(x / 2)];
            int l = x % 2 ? byte & 15 : byte >> 4;
            sum += l;
            if (l != nearest) *all_nearest = 0;
        }
    free(img);
    zt_scene_free(&sc);
    return (double)sum / ((double)w * h);
}

static void test_grey_levels(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init_flags(&c, 128, 64, POOLS, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    double worst = 0;
    for (int v = 0; v <= 255; v++) {
        int nearest;
        double f = mean_level(&c, &cam, v, ZS_GRAY4_DITHER, &nearest);
        double err = fabs(f - 15.0 * v / 255.0);
        if (err > worst) worst = err;
        ZT_CHECK(err <= 1.0 / 64.0 + 1e-9, "grey %d dithered: mean level %.4f, want %.4f", v, f,
                 15.0 * v / 255.0);
        (void)mean_level(&c, &cam, v, 0, &nearest);
        ZT_CHECK(nearest, "grey %d rounded: a pixel is not the nearest level", v);
    }
    print_message("GRAY4 flat greys 0..255: worst |mean level - 15 g / 255| dithered %.4f\n",
                  worst);
    zt_ctx_free(&c);
}

static void test_api(void **state)
{
    (void)state;
    zt_ctx plain, mono;
    zt_ctx_init_flags(&plain, 31, 9, POOLS, 0);
    zt_ctx_init_flags(&mono, 31, 9, POOLS, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_GRAY4;
    ZT_CHECK(zs_format_stride(ZS_FMT_GRAY4, 31) == 16, "odd stride");
    ZT_CHECK(zs_format_stride(ZS_FMT_GRAY4, 128) == 64, "even stride");
    ZT_CHECK(zs_format_bytes(ZS_FMT_GRAY4) == 0 && !zs_format_is_mono(ZS_FMT_GRAY4),
             "not a byte format, not a 1-bit one");
    ZT_ST(zt_begin(&plain, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_MODE);
    ZT_ST(zt_begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    ZT_CHECK(zs_frame_format(&mono.r) == ZS_FMT_GRAY4, "the frame's format");
    ZT_CHECK(mono.r.shade.format == ZS_FMT_GRAY8, "the scratch format");
    uint8_t buf[4 * 20];
    ZT_ST(zs_render_rows(&mono.r, 0, 1, buf, 15), ZS_ERR_BUFFER);
    ZT_ST(zs_render_rows(&mono.r, 0, 4, buf, 16), ZS_OK);
    for (unsigned bit = 1; bit < 256; bit <<= 1) {
        sp.mono = (uint8_t)bit;
        int ok = bit == ZS_GRAY4_DITHER || bit == ZS_MONO_INVERT;
        ZT_ST(zt_begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ok ? ZS_OK : ZS_ERR_ARGUMENT);
    }
    /* a refused call keeps the previous frame's format */
    sp.mono = ZS_MONO_DIFFUSE;
    ZT_ST(zs_frame_begin(&mono.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&mono.r, &sp), ZS_ERR_ARGUMENT);
    ZT_CHECK(zs_frame_format(&mono.r) == ZS_FMT_RGB565_BE, "refused: the default stays");
    zt_ctx_free(&plain);
    zt_ctx_free(&mono);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_api),
        cmocka_unit_test(test_grey_levels),
        cmocka_unit_test(test_against_grey_oracle),
    };
    return cmocka_run_group_tests_name("gray4", tests, NULL, NULL);
}
