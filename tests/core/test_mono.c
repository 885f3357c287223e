/* SPDX-License-Identifier: MIT */
/*
 * test_mono: the 1-bit formats (ZS_FMT_MONO_PAGE, ZS_FMT_MONO_MSB).
 *
 *  - Against an oracle written here: each frame is also rendered in GRAY8
 *    (a byte format the other suites check) and dithered and packed by this
 *    file's own code (Bayer by its threshold rule, Floyd-Steinberg over a
 *    whole-frame error image); the core's 1-bit bytes must equal it exactly,
 *    on random scenes, in both visibility modes (so span == zline holds in
 *    1 bit too), flat and Gouraud, inverted or not, for band heights 1, 3,
 *    8, 13 and the whole frame, through zs_render_rows and zs_render_frame.
 *  - Large flat areas: the fraction of lit pixels is within 2% of the grey
 *    level, for Bayer and for diffusion, over the whole 0..255 range.
 *  - Diffusion gives identical bytes whatever the band height (also implied
 *    by the oracle, checked on its own here with bands 1..17).
 *  - API: refusals without ZS_CFG_MONO / ZS_CFG_LINES, bad ZS_MONO_* bits,
 *    crease angles, strides, page bands; the arena figure of the flags; a
 *    page row only changes its own bit.
 */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define W 77 /* not a multiple of 8: the MSB layout's last byte is partial */
#define H 61 /* nor is the height: the last page is partial */
#define PAGES ((H + 7) / 8)
#define MSB_STRIDE ((W + 7) / 8)
#define SEED 0x0DD17E2500000016ull

static unsigned long g_frames, g_bytes;

/* The renderers: zt_ctx (zt.h) with this suite's pools. */
typedef zt_ctx ctx;
#define ctx_init(c, w, h, flags) zt_ctx_init_flags(c, w, h, 400, 1200, 400, flags)
#define ctx_free zt_ctx_free
#define begin zt_begin

/* The whole frame in a 1-bit format, bands of `band` rows through
 * zs_render_rows (page layout: into the frame's page buffer at the band's
 * first page). img: PAGES * W (page) or H * MSB_STRIDE bytes. */
static zs_status render_rows_mono(ctx *c, zs_format fmt, uint8_t *img, int band)
{
    int w = c->cfg.width, h = c->cfg.height;
    for (int y = 0; y < h; y += band) {
        int n = band < h - y ? band : h - y;
        zs_status st;
        if (fmt == ZS_FMT_MONO_PAGE)
            st = zs_render_rows(&c->r, y, n, img + (size_t)(y / 8) * (size_t)w, (size_t)w);
        else
            st = zs_render_rows(&c->r, y, n, img + (size_t)y * (size_t)((w + 7) / 8),
                                (size_t)((w + 7) / 8));
        if (st != ZS_OK) return st;
    }
    return ZS_OK;
}

typedef struct band_copy {
    uint8_t *img;
    int w, next_y, bad;
    zs_format fmt;
} band_copy;

static int copy_band(void *user, int y0, int rows, const void *buf, size_t stride)
{
    band_copy *u = user;
    if (y0 != u->next_y) u->bad = 1;
    if (u->fmt == ZS_FMT_MONO_PAGE) {
        for (int p = 0; p < (rows + 7) / 8; p++)
            memcpy(u->img + (size_t)(y0 / 8 + p) * (size_t)u->w, (const uint8_t *)buf + p * stride,
                   (size_t)u->w);
    } else {
        size_t s = (size_t)(u->w + 7) / 8;
        for (int k = 0; k < rows; k++)
            memcpy(u->img + (size_t)(y0 + k) * s, (const uint8_t *)buf + k * stride, s);
    }
    u->next_y = y0 + rows;
    return 0;
}

static zs_status render_frame_mono(ctx *c, zs_format fmt, uint8_t *img, int band)
{
    int w = c->cfg.width;
    size_t stride = fmt == ZS_FMT_MONO_PAGE ? (size_t)w + 3 : (size_t)(w + 7) / 8 + 1;
    size_t units = fmt == ZS_FMT_MONO_PAGE ? (size_t)band / 8 : (size_t)band;
    uint8_t *buf = malloc(stride * units);
    memset(buf, 0x5A, stride * units);
    band_copy u = {img, w, 0, 0, fmt};
    zs_status st = zs_render_frame(&c->r, buf, stride, band, copy_band, &u);
    free(buf);
    if (st == ZS_OK && (u.bad || u.next_y != c->cfg.height)) return ZS_STATUS_COUNT;
    return st;
}

/* ---- the oracle: this file's dithering and packing of a GRAY8 frame ---- */

static int bayer_index(int x, int y)
{
    /* bit-reversed interleave of (x ^ y) and y: the recursive Bayer matrix */
    int v = 0;
    for (int b = 0; b < 3; b++) {
        int xb = (x >> b) & 1, yb = (y >> b) & 1;
        v |= ((xb ^ yb) << (2 * (2 - b) + 1)) | (yb << (2 * (2 - b)));
    }
    return v;
}

/* bits[y * w + x] = 0/1 */
static void oracle_bits(const uint8_t *grey, int w, int h, int diffuse, uint8_t *bits)
{
    if (!diffuse) {
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int m = bayer_index(x & 7, y & 7);
                bits[y * w + x] = 128 * grey[y * w + x] > 255 * (2 * m + 1);
            }
        return;
    }
    /* whole-frame error image, one extra column on each side (dropped) */
    int *err = calloc((size_t)(w + 2) * (size_t)(h + 1), sizeof *err);
#define E(x, y) err[(size_t)(y) * (size_t)(w + 2) + (size_t)(x) + 1]
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int v = grey[y * w + x] + E(x, y);
            int on = v >= 128;
            int e = v - (on ? 255 : 0);
            int d1 = e / 16, d3 = 3 * e / 16, d5 = 5 * e / 16;
            bits[y * w + x] = (uint8_t)on;
            E(x + 1, y) += e - d1 - d3 - d5;
            E(x - 1, y + 1) += d3;
            E(x, y + 1) += d5;
            E(x + 1, y + 1) += d1;
        }
#undef E
    free(err);
}

static void oracle_pack(const uint8_t *bits, int w, int h, zs_format fmt, int invert,
                        uint8_t *out)
{
    if (fmt == ZS_FMT_MONO_PAGE) {
        memset(out, 0, (size_t)((h + 7) / 8) * (size_t)w);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                if (bits[y * w + x] ^ invert) out[(y / 8) * w + x] |= (uint8_t)(1 << (y % 8));
    } else {
        int s = (w + 7) / 8;
        memset(out, 0, (size_t)h * (size_t)s);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                if (bits[y * w + x] ^ invert) out[y * s + x / 8] |= (uint8_t)(0x80 >> (x % 8));
    }
}

static size_t mono_bytes(zs_format fmt, int w, int h)
{
    return fmt == ZS_FMT_MONO_PAGE ? (size_t)((h + 7) / 8) * (size_t)w
                                   : (size_t)h * (size_t)((w + 7) / 8);
}

static void random_look(zt_rng *g, int k, zs_shade_params *sp)
{
    *sp = zs_shade_default();
    sp->shading = (k & 1) ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    sp->background = zt_u32(g) & 0xFFFFFFu;
    if (k & 2)
        zt_random_light(g, sp, ZS_FX(1) / 2);
}

static void test_against_grey_oracle(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    ctx c;
    ctx_init(&c, W, H, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    uint8_t *grey = malloc(W * H), *bits = malloc(W * H);
    uint8_t *want = malloc(W * H), *img = malloc(W * H);
    for (int k = 0; k < 120; k++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 8, 40), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, k % 3 == 0, k % 3 == 1);
        m.color = zt_u32(&g) & 0xFFFFFFu;
        zs_shade_params sp;
        random_look(&g, k, &sp);
        sp.format = ZS_FMT_GRAY8;
        ZT_ST(begin(&c, &cam, ZS_MODE_ZLINE, &sp, &m), ZS_OK);
        ZT_ST(zs_render_rows(&c.r, 0, H, grey, W), ZS_OK);
        for (int v = 0; v < 8; v++) {
            zs_format fmt = (v & 1) ? ZS_FMT_MONO_MSB : ZS_FMT_MONO_PAGE;
            int diffuse = (v >> 1) & 1, invert = (k >> 2) & 1;
            zs_shade_params mp = sp;
            mp.format = fmt;
            mp.mono = (uint8_t)((diffuse ? ZS_MONO_DIFFUSE : 0) | (invert ? ZS_MONO_INVERT : 0));
            oracle_bits(grey, W, H, diffuse, bits);
            oracle_pack(bits, W, H, fmt, invert, want);
            size_t n = mono_bytes(fmt, W, H);
            static const int bands[] = {1, 3, 8, 13, H};
            for (int b = 0; b < 5; b++)
                for (int mode = 0; mode < ZT_NMODES; mode++) {
                    int band = bands[(b + v + k) % 5];
                    int via_frame = (v >> 2) & 1;
                    if (via_frame && fmt == ZS_FMT_MONO_PAGE) band = 8 * (1 + b % 3);
                    memset(img, 0xC3, n);
                    ZT_ST(begin(&c, &cam, ZT_MODE(mode), &mp, &m), ZS_OK);
                    if (via_frame)
                        ZT_ST(render_frame_mono(&c, fmt, img, band), ZS_OK);
                    else
                        ZT_ST(render_rows_mono(&c, fmt, img, band), ZS_OK);
                    long d = zt_first_diff(want, img, n);
                    ZT_CHECK(d < 0,
                             "scene %d: %s %s%s%s band %d%s: byte %ld is %02x, the oracle %02x",
                             k, ZT_MODE_NAME(mode), fmt == ZS_FMT_MONO_PAGE ? "page" : "msb",
                             diffuse ? " diffuse" : " bayer", invert ? " inverted" : "", band,
                             via_frame ? " (zs_render_frame)" : "", d, d < 0 ? 0 : img[d],
                             d < 0 ? 0 : want[d]);
                    g_frames++;
                    g_bytes += n;
                }
        }
    }
    free(grey); free(bits); free(want); free(img);
    zt_scene_free(&sc);
    ctx_free(&c);
}

/* One screen-filling unlit quad of grey level v; fraction of lit pixels. */
static double lit_fraction(ctx *c, const zs_camera *cam, int v, unsigned mono, zs_format fmt)
{
    int w = c->cfg.width, h = c->cfg.height;
    zt_scene sc;
    zs_mesh m = zt_scene_grey_quad(&sc, w, h, v);
    zs_shade_params sp = zs_shade_default();
    sp.format = fmt;
    sp.mono = (uint8_t)mono;
    ZT_ST(begin(c, cam, ZS_MODE_SPAN, &sp, &m), ZS_OK);
    size_t n = mono_bytes(fmt, w, h);
    uint8_t *img = calloc(n, 1);
    ZT_ST(render_rows_mono(c, fmt, img, 8), ZS_OK);
    long on = 0;
    for (size_t i = 0; i < n; i++)
        on += __builtin_popcount(img[i]);
    free(img);
    zt_scene_free(&sc);
    return (double)on / ((double)w * h);
}

static void test_grey_levels(void **state)
{
    (void)state;
    ctx c;
    ctx_init(&c, 128, 64, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    double worst[2] = {0, 0};
    for (int v = 0; v <= 255; v += 5) {
        for (int diffuse = 0; diffuse < 2; diffuse++) {
            double f = lit_fraction(&c, &cam, v, diffuse ? ZS_MONO_DIFFUSE : 0,
                                    diffuse ? ZS_FMT_MONO_MSB : ZS_FMT_MONO_PAGE);
            double err = f - v / 255.0;
            if (err < 0) err = -err;
            if (err > worst[diffuse]) worst[diffuse] = err;
            ZT_CHECK(err <= 0.02, "grey %d, %s: lit fraction %.4f, want %.4f +- 0.02", v,
                     diffuse ? "diffusion" : "bayer", f, v / 255.0);
        }
    }
    print_message("grey levels 0..255: worst |lit fraction - level| bayer %.4f, diffusion %.4f\n",
                  worst[0], worst[1]);
    ctx_free(&c);
}

static void test_diffusion_any_band(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 1);
    ctx c;
    ctx_init(&c, W, H, ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    zt_scene_random(&g, &sc, 40, ZT_SC_ALL, 0.5);
    zs_mesh m = zt_scene_mesh(&sc, 0, 1);
    zs_shade_params sp = zs_shade_default();
    sp.shading = ZS_SHADE_GOURAUD;
    sp.format = ZS_FMT_MONO_MSB;
    sp.mono = ZS_MONO_DIFFUSE;
    size_t n = mono_bytes(sp.format, W, H);
    uint8_t *ref = malloc(n), *img = malloc(n);
    ZT_ST(begin(&c, &cam, ZS_MODE_SPAN, &sp, &m), ZS_OK);
    ZT_ST(render_rows_mono(&c, sp.format, ref, H), ZS_OK);
    long ones = 0;
    for (size_t i = 0; i < n; i++) ones += __builtin_popcount(ref[i]);
    ZT_CHECK(ones > 0 && ones < (long)W * H, "the frame is neither all dark nor all lit");
    for (int band = 1; band <= 17; band++) {
        memset(img, 0x77, n);
        ZT_ST(begin(&c, &cam, ZS_MODE_SPAN, &sp, &m), ZS_OK);
        ZT_ST(render_rows_mono(&c, sp.format, img, band), ZS_OK);
        ZT_CHECK(memcmp(ref, img, n) == 0, "band %d differs from the whole frame", band);
    }
    free(ref); free(img);
    zt_scene_free(&sc);
    ctx_free(&c);
}

static void test_api(void **state)
{
    (void)state;
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zs_shade_params sp = zs_shade_default();
    ctx plain, mono, lines;
    ctx_init(&plain, W, H, 0);
    ctx_init(&mono, W, H, ZS_CFG_MONO);
    ctx_init(&lines, W, H, ZS_CFG_LINES);

    /* arena figures: what each flag adds */
    zs_config cfg = zs_config_default(W, H, 400, 1200, 400);
    size_t base = zs_arena_bytes(&cfg);
    cfg.flags = ZS_CFG_MONO;
    ZT_CHECK(zs_arena_bytes(&cfg) == base + 80 + 160, "mono adds a grey and an error line");
    ZT_CHECK(ZS_ARENA_BYTES_CFG(W, H, 400, 1200, 400, ZS_CFG_MONO) == zs_arena_bytes(&cfg),
             "macro == run time");
    cfg.flags = ZS_CFG_LINES;
    ZT_CHECK(zs_arena_bytes(&cfg) == base + 2 * 80 + 2 * 160 + 400 * (8 + 6) + 56 + 1200 * 2,
             "lines add two flag lines, two id lines, 14 B and 1 bit per record, 2 B per "
             "vertex");
    ZT_CHECK(ZS_ARENA_BYTES_CFG(W, H, 400, 1200, 400, ZS_CFG_LINES) == zs_arena_bytes(&cfg),
             "macro == run time");
    cfg.flags = 0x8000;
    ZT_CHECK(zs_arena_bytes(&cfg) == 0, "unknown flag");

    ZT_CHECK(zs_format_bytes(ZS_FMT_MONO_PAGE) == 0 && zs_format_bytes(ZS_FMT_MONO_MSB) == 0,
             "no bytes per pixel");
    ZT_CHECK(zs_format_stride(ZS_FMT_MONO_PAGE, 128) == 128, "page stride");
    ZT_CHECK(zs_format_stride(ZS_FMT_MONO_MSB, 122) == 16, "msb stride");
    ZT_CHECK(zs_format_stride(ZS_FMT_RGB666, 10) == 30, "byte stride");
    ZT_CHECK(zs_format_stride((zs_format)7, 10) == 0, "unknown");
    ZT_CHECK(!zs_format_is_mono(ZS_FMT_GRAY8) && zs_format_is_mono(ZS_FMT_MONO_MSB), "is_mono");

    /* the features a config left out, and bad arguments */
    sp.format = ZS_FMT_MONO_PAGE;
    ZT_ST(begin(&plain, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_MODE);
    ZT_ST(begin(&lines, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_MODE);
    sp.mono = ZS_MONO_LINES;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_MODE);
    ZT_ST(begin(&lines, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    sp.crease_deg = 180;
    ZT_ST(begin(&lines, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_ARGUMENT);
    sp.crease_deg = 179;
    ZT_ST(begin(&lines, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    sp.mono = 0x08;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_ARGUMENT);
    sp.format = (zs_format)7;
    sp.mono = 0;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_FORMAT);
    sp.format = (zs_format)11; /* 10 is ZS_FMT_GRAY4 */
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_ERR_FORMAT);
    sp.format = ZS_FMT_GRAY8;
    sp.mono = 0xFF; /* ignored with a byte format */
    ZT_ST(begin(&plain, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    ZT_CHECK(plain.r.shade.format == ZS_FMT_GRAY8, "byte format kept");

    /* strides and bands */
    uint8_t buf[PAGES * (W + 1)];
    sp = zs_shade_default();
    sp.format = ZS_FMT_MONO_PAGE;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    ZT_CHECK(mono.r.shade.format == ZS_FMT_GRAY8, "the scratch format is visible");
    ZT_ST(zs_render_rows(&mono.r, 0, 8, buf, W - 1), ZS_ERR_BUFFER);
    ZT_ST(zs_render_rows(&mono.r, 0, 16, buf, SIZE_MAX / 2), ZS_ERR_BUFFER); /* two pages */
    ZT_ST(zs_render_frame(&mono.r, buf, W, 4, zt_sink, NULL), ZS_ERR_ROW);
    /* a page row changes its bit only: background black, bit 3 cleared */
    memset(buf, 0xFF, sizeof buf);
    ZT_ST(zs_render_rows(&mono.r, 3, 1, buf, W), ZS_OK);
    for (int x = 0; x < W; x++) ZT_CHECK(buf[x] == 0xF7, "column %d: %02x", x, buf[x]);
    ZT_CHECK(buf[W] == 0xFF, "the next page untouched");
    /* rows 4..12 span two pages: the buffer starts at row 4's page */
    memset(buf, 0x00, sizeof buf);
    sp.background = 0xFFFFFF;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    ZT_ST(zs_render_rows(&mono.r, 4, 9, buf, W + 1), ZS_OK);
    ZT_CHECK(buf[0] == 0xF0 && buf[W + 1] == 0x1F && buf[2 * (W + 1)] == 0, "%02x %02x", buf[0],
             buf[W + 1]);
    sp.format = ZS_FMT_MONO_MSB;
    ZT_ST(begin(&mono, &cam, ZS_MODE_SPAN, &sp, NULL), ZS_OK);
    ZT_ST(zs_render_rows(&mono.r, 0, 2, buf, MSB_STRIDE - 1), ZS_ERR_BUFFER);
    ZT_ST(zs_render_rows(&mono.r, 0, 2, buf, MSB_STRIDE), ZS_OK);
    ZT_CHECK(buf[0] == 0xFF && buf[MSB_STRIDE - 1] == 0xF8, "white rows, padding bits 0: %02x",
             buf[MSB_STRIDE - 1]);
    ctx_free(&plain);
    ctx_free(&mono);
    ctx_free(&lines);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_api),
        cmocka_unit_test(test_grey_levels),
        cmocka_unit_test(test_diffusion_any_band),
        cmocka_unit_test(test_against_grey_oracle),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    print_message("mono: %lu frames (%lu bytes) equal to the grey oracle\n", g_frames, g_bytes);
    return rc;
}
