/* SPDX-License-Identifier: MIT */
/*
 * Textures in the converter (zspan-meshc --texture) and the simulator
 * (zspan-sim render --textures, .zsm textures).
 *
 *  - Texels: the converter's texels equal an area-average resample computed
 *    here from the image (decoded here: the duck's TGA by hand, PNG and JPEG
 *    with libpng / libjpeg), by counting the cells of a common grid that
 *    each source pixel and each texel share (the converter intersects
 *    intervals instead), each channel rounded to nearest, then RGB565 by
 *    round(c * 31 / 255). Sizes: non-power-of-two images, integer and
 *    fractional ratios, the size limit, an embedded PNG (.glb) and the same
 *    image as a file beside the model (.gltf).
 *  - uvs: u as written, v turned over (1 - v), Q3.12, whole repeats taken
 *    off; after --bsp every vertex (split ones too) keeps the affine uv
 *    function tex_planes.obj was written with.
 *  - The simulator draws a converted .zsm byte for byte like the library
 *    draws the same mesh compiled in (t_duck), and the texture shows.
 *  - Errors: unreadable, corrupt, unsupported, oversized images and
 *    impossible requests: a clear "error:" message and exit 3 or 4.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <jpeglib.h>

#include "t_duck.h"
#include "t_texbsp.h"
#include "run_cmd.h"


/* ---- helpers ----------------------------------------------------------- */


static void expect_ok(const char *what, const run_result *res)
{
    if (!res->exited || res->status != 0)
        fail_msg("%s: exit %d:\n%s", what, res->status, res->out);
}

static void expect_error(const char *what, const run_result *res, int code, const char *needle)
{
    if (!res->exited)
        fail_msg("%s: the converter did not exit normally:\n%s", what, res->out);
    if (res->status != code)
        fail_msg("%s: exit status %d, expected %d:\n%s", what, res->status, code, res->out);
    if (!strstr(res->out, "error:"))
        fail_msg("%s: no 'error:' message:\n%s", what, res->out);
    if (needle && !strstr(res->out, needle))
        fail_msg("%s: message lacks '%s':\n%s", what, needle, res->out);
}

static char g_dir[64];

static int make_dir(void **state)
{
    (void)state;
    strcpy(g_dir, "/tmp/zspan-meshc-tex.XXXXXX");
    return mkdtemp(g_dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_dir);
    return system(cmd) == 0 ? 0 : -1;
}

/* An 8-bit RGB image, row 0 at the top. */
typedef struct image {
    unsigned w, h;
    uint8_t *rgb;
} image;

static void write_png(const char *path, const image *im)
{
    png_image p;
    memset(&p, 0, sizeof p);
    p.version = PNG_IMAGE_VERSION;
    p.width = im->w;
    p.height = im->h;
    p.format = PNG_FORMAT_RGB;
    assert_true(png_image_write_to_file(&p, path, 0, im->rgb, 0, NULL));
}

static image read_png(const char *path)
{
    png_image p;
    image im;
    memset(&p, 0, sizeof p);
    p.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&p, path))
        fail_msg("cannot read %s: %s", path, p.message);
    p.format = PNG_FORMAT_RGB;
    im.w = p.width;
    im.h = p.height;
    im.rgb = malloc((size_t)im.w * im.h * 3);
    assert_non_null(im.rgb);
    assert_true(png_image_finish_read(&p, NULL, im.rgb, 0, NULL));
    return im;
}

static void write_jpeg(const char *path, const image *im)
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr e;
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    c.err = jpeg_std_error(&e);
    jpeg_create_compress(&c);
    jpeg_stdio_dest(&c, f);
    c.image_width = im->w;
    c.image_height = im->h;
    c.input_components = 3;
    c.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 90, TRUE);
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = im->rgb + (size_t)c.next_scanline * im->w * 3;
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    fclose(f);
}

static image read_jpeg(const char *path)
{
    struct jpeg_decompress_struct d;
    struct jpeg_error_mgr e;
    image im;
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    d.err = jpeg_std_error(&e);
    jpeg_create_decompress(&d);
    jpeg_stdio_src(&d, f);
    jpeg_read_header(&d, TRUE);
    d.out_color_space = JCS_RGB;
    jpeg_start_decompress(&d);
    im.w = d.output_width;
    im.h = d.output_height;
    im.rgb = malloc((size_t)im.w * im.h * 3);
    assert_non_null(im.rgb);
    while (d.output_scanline < d.output_height) {
        JSAMPROW row = im.rgb + (size_t)d.output_scanline * im.w * 3;
        jpeg_read_scanlines(&d, &row, 1);
    }
    jpeg_finish_decompress(&d);
    jpeg_destroy_decompress(&d);
    fclose(f);
    return im;
}

/* An uncompressed 24-bit TGA (the duck's), read by its header. */
static image read_tga24(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t h[18];
    image im;
    unsigned x, y;
    assert_non_null(f);
    assert_int_equal(fread(h, 1, 18, f), 18);
    assert_int_equal(h[2], 2);
    assert_int_equal(h[16], 24);
    im.w = (unsigned)h[12] | (unsigned)h[13] << 8;
    im.h = (unsigned)h[14] | (unsigned)h[15] << 8;
    im.rgb = malloc((size_t)im.w * im.h * 3);
    assert_non_null(im.rgb);
    fseek(f, 18 + h[0], SEEK_SET);
    for (y = 0; y < im.h; y++) {
        unsigned row = (h[17] & 0x20) ? y : im.h - 1 - y; /* bottom-up unless bit 5 */
        for (x = 0; x < im.w; x++) {
            uint8_t bgr[3];
            assert_int_equal(fread(bgr, 1, 3, f), 3);
            im.rgb[((size_t)row * im.w + x) * 3] = bgr[2];
            im.rgb[((size_t)row * im.w + x) * 3 + 1] = bgr[1];
            im.rgb[((size_t)row * im.w + x) * 3 + 2] = bgr[0];
        }
    }
    fclose(f);
    return im;
}

static unsigned gcd(unsigned a, unsigned b)
{
    while (b) {
        unsigned t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* share[i * src + s]: cells of the common grid (lcm(src, dst) cells) that
 * texel i and source pixel s both hold. */
static unsigned *shares(unsigned src, unsigned dst)
{
    unsigned l = src / gcd(src, dst) * dst, k;
    unsigned *c = calloc((size_t)src * dst, sizeof *c);
    assert_non_null(c);
    for (k = 0; k < l; k++)
        c[(size_t)(k / (l / dst)) * src + k / (l / src)]++;
    return c;
}

static uint16_t rgb565(double r, double g, double b)
{
    return (uint16_t)(lround(r * 31 / 255) << 11 | lround(g * 63 / 255) << 5 | lround(b * 31 / 255));
}

/* The area-average resample of im to w x h in RGB565 (and 8-bit in rgb). */
static uint16_t *reference(const image *im, unsigned w, unsigned h, uint8_t *rgb)
{
    unsigned *cx = shares(im->w, w), *cy = shares(im->h, h), i, j, s, t, c;
    uint16_t *out = malloc((size_t)w * h * sizeof *out);
    assert_non_null(out);
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            uint64_t sum[3] = {0, 0, 0}, n = 0;
            uint8_t v[3];
            for (t = 0; t < im->h; t++) {
                unsigned wy = cy[(size_t)j * im->h + t];
                if (!wy)
                    continue;
                for (s = 0; s < im->w; s++) {
                    uint64_t wgt = (uint64_t)wy * cx[(size_t)i * im->w + s];
                    for (c = 0; c < 3; c++)
                        sum[c] += wgt * im->rgb[((size_t)t * im->w + s) * 3 + c];
                    n += wgt;
                }
            }
            for (c = 0; c < 3; c++) /* nearest, halves up */
                v[c] = (uint8_t)((2 * sum[c] + n) / (2 * n));
            out[(size_t)j * w + i] = rgb565(v[0], v[1], v[2]);
            if (rgb)
                memcpy(rgb + ((size_t)j * w + i) * 3, v, 3);
        }
    free(cx);
    free(cy);
    return out;
}

/* A .zsm as the converter writes it (app/zs_model.h). */
typedef struct zsm {
    unsigned flags, nv, nt, tw, th, tformat, tflags;
    int16_t *pos, *uv;
    uint16_t *texels, pal[256];
    uint8_t *idx8;
} zsm;

static unsigned le(const uint8_t *p, int n)
{
    unsigned v = 0;
    while (n--)
        v = v << 8 | p[n];
    return v;
}

static zsm read_zsm(const char *path)
{
    FILE *f = fopen(path, "rb");
    static uint8_t buf[1 << 20];
    size_t n, off, i;
    zsm z;
    memset(&z, 0, sizeof z);
    assert_non_null(f);
    n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    assert_true(n > 24 && memcmp(buf, "ZSMESH1\n", 8) == 0);
    z.flags = le(buf + 8, 4);
    z.nv = le(buf + 20, 2);
    z.nt = le(buf + 22, 2);
    z.pos = malloc(z.nv * 6 + 1);
    for (i = 0; i < z.nv * 3u; i++)
        z.pos[i] = (int16_t)le(buf + 24 + 2 * i, 2);
    off = 24 + (size_t)z.nv * 6 + (size_t)z.nt * 6;
    off += (z.flags & 1 ? z.nt * 4u : 0) + (z.flags & 2 ? z.nv * 4u : 0) +
           (z.flags & 4 ? z.nt * 6u : 0) + (z.flags & 8 ? z.nv * 6u : 0);
    if (!(z.flags & 16))
        return z;
    z.uv = malloc(z.nv * 4 + 1);
    for (i = 0; i < z.nv * 2u; i++)
        z.uv[i] = (int16_t)le(buf + off + 2 * i, 2);
    off += z.nv * 4u;
    z.tw = le(buf + off, 2);
    z.th = le(buf + off + 2, 2);
    z.tformat = buf[off + 4];
    z.tflags = buf[off + 5];
    off += 8;
    if (z.tformat == ZS_TEX_PAL8) {
        for (i = 0; i < 256; i++)
            z.pal[i] = (uint16_t)le(buf + off + 2 * i, 2);
        off += 512;
        z.idx8 = malloc((size_t)z.tw * z.th);
        memcpy(z.idx8, buf + off, (size_t)z.tw * z.th);
        off += (size_t)z.tw * z.th;
    } else {
        z.texels = malloc((size_t)z.tw * z.th * 2);
        for (i = 0; i < (size_t)z.tw * z.th; i++)
            z.texels[i] = (uint16_t)le(buf + off + 2 * i, 2);
        off += (size_t)z.tw * z.th * 2;
    }
    assert_int_equal(off, n); /* nothing after the texture */
    return z;
}

static void free_zsm(zsm *z)
{
    free(z->pos);
    free(z->uv);
    free(z->texels);
    free(z->idx8);
}

/* A pattern with many colours, no two neighbours alike. */
static image pattern(unsigned w, unsigned h, unsigned seed)
{
    image im;
    unsigned x, y;
    im.w = w;
    im.h = h;
    im.rgb = malloc((size_t)w * h * 3);
    assert_non_null(im.rgb);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            uint8_t *p = im.rgb + ((size_t)y * w + x) * 3;
            uint32_t k = (x * 73856093u) ^ (y * 19349663u) ^ (seed * 83492791u);
            p[0] = (uint8_t)(x * 255 / (w - 1));
            p[1] = (uint8_t)(y * 255 / (h > 1 ? h - 1 : 1));
            p[2] = (uint8_t)((k >> 7) & 255);
        }
    return im;
}

/* A textured quad in OBJ with its MTL (map_Kd image). */
static void write_quad(const char *name, const char *image_name)
{
    char path[256];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s.mtl", g_dir, name);
    f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "newmtl m\nKd 1 1 1\nmap_Kd %s\n", image_name);
    fclose(f);
    snprintf(path, sizeof path, "%s/%s.obj", g_dir, name);
    f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "mtllib %s.mtl\nusemtl m\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
               "vt 0.25 0.125\nvt 2.75 0.125\nvt 2.75 0.875\nvt 0.25 0.875\n"
               "f 1/1 2/2 3/3 4/4\n", name);
    fclose(f);
}

/* ---- texels ----------------------------------------------------------------- */

static void test_duck_texels(void **state)
{
    image tga = read_tga24(ASSIMP_MODELS "/Collada/duckCM.tga");
    uint16_t *ref;
    size_t i, n = (size_t)T_DUCK_TEXTURE_WIDTH * T_DUCK_TEXTURE_HEIGHT;
    (void)state;
    assert_int_equal(tga.w, 512);
    assert_int_equal(T_DUCK_TEXTURE_WIDTH, 64); /* the default --texture-size */
    assert_int_equal(T_DUCK_TEXTURE_HEIGHT, 64);
    assert_int_equal(t_duck_texture.format, ZS_TEX_RGB565);
    assert_int_equal(t_duck_texture.flags, 0);
    assert_int_equal(zs_texture_check(&t_duck_texture), ZS_OK);
    assert_ptr_equal(t_duck.texture, &t_duck_texture);
    assert_non_null(t_duck.uvs);
    ref = reference(&tga, 64, 64, NULL);
    for (i = 0; i < n; i++)
        if (((const uint16_t *)t_duck_texture.texels)[i] != ref[i])
            fail_msg("duck texel %zu: %04x, the resample here gives %04x", i,
                     ((const uint16_t *)t_duck_texture.texels)[i], ref[i]);
    print_message("duck: 512 x 512 TGA -> 64 x 64, %zu texels equal the reference\n", n);
    free(ref);
    free(tga.rgb);
}

/* PNG 100 x 60 -> 64 x 32 (and 32 x 32 under --texture-size 32), fractional
 * ratios; the uvs of the quad; pal8 of the same. */
static void test_png_resample(void **state)
{
    image im = pattern(100, 60, 1);
    char png[256];
    run_result r;
    zsm z;
    uint16_t *ref;
    uint8_t ref8[64 * 32 * 3];
    size_t i;
    double err = 0;
    static const double vt[4][2] = {{0.25, 0.125}, {2.75, 0.125}, {2.75, 0.875}, {0.25, 0.875}};
    (void)state;
    snprintf(png, sizeof png, "%s/pat.png", g_dir);
    write_png(png, &im);
    write_quad("quad", "pat.png");
    run(&r, "'%s' -q --texture auto --texture-size 128 --format zsm -o '%s/q1' '%s/quad.obj'",
        MESHC, g_dir, g_dir);
    expect_ok("png 128", &r);
    z = read_zsm(strcat(strcpy(png, g_dir), "/q1.zsm"));
    assert_int_equal(z.flags & 16, 16);
    assert_int_equal(z.tw, 64);
    assert_int_equal(z.th, 32);
    ref = reference(&im, 64, 32, ref8);
    for (i = 0; i < 64 * 32; i++)
        if (z.texels[i] != ref[i])
            fail_msg("png texel %zu: %04x, reference %04x", i, z.texels[i], ref[i]);
    /* uvs: u shifted by whole repeats to sit about 0 (u 0.25..2.75 -> -0.75..1.75),
     * v turned over (1 - v) */
    assert_int_equal(z.nv, 4);
    for (i = 0; i < 4; i++) {
        int16_t *p = &z.pos[3 * i], *uv = &z.uv[2 * i];
        int k = p[0] < 0 ? (p[1] < 0 ? 0 : 3) : (p[1] < 0 ? 1 : 2);
        assert_int_equal(uv[0], lround((vt[k][0] - 1.0) * ZS_UV_ONE));
        assert_int_equal(uv[1], lround((1.0 - vt[k][1]) * ZS_UV_ONE));
    }
    free(ref);
    free_zsm(&z);

    run(&r, "'%s' -q --texture auto --texture-size 32 --format zsm -o '%s/q2' '%s/quad.obj'",
        MESHC, g_dir, g_dir);
    expect_ok("png 32", &r);
    z = read_zsm(strcat(strcpy(png, g_dir), "/q2.zsm"));
    assert_int_equal(z.tw, 32);
    assert_int_equal(z.th, 32);
    ref = reference(&im, 32, 32, NULL);
    assert_memory_equal(z.texels, ref, 32 * 32 * 2);
    free(ref);
    free_zsm(&z);

    /* pal8 of 2048 distinct colours: a median cut; each texel's palette colour
     * near the resampled one */
    run(&r, "'%s' -q --texture auto --texture-format pal8 --format zsm -o '%s/q3' '%s/quad.obj'",
        MESHC, g_dir, g_dir);
    expect_ok("png pal8", &r);
    z = read_zsm(strcat(strcpy(png, g_dir), "/q3.zsm"));
    assert_int_equal(z.tformat, ZS_TEX_PAL8);
    assert_int_equal(z.tw, 64);
    for (i = 0; i < 64 * 32; i++) {
        uint16_t c = z.pal[z.idx8[i]];
        double d = fabs(((c >> 11) & 31) * 255.0 / 31 - ref8[3 * i]) +
                   fabs(((c >> 5) & 63) * 255.0 / 63 - ref8[3 * i + 1]) +
                   fabs((c & 31) * 255.0 / 31 - ref8[3 * i + 2]);
        err += d / 3;
    }
    err /= 64 * 32;
    print_message("pal8 of a 2048-colour texture: mean error %.2f of 255 a channel\n", err);
    assert_true(err < 10.0);
    free_zsm(&z);
    free(im.rgb);
}

/* A 32 x 32 image of 16 colours: pal8 keeps them exactly; --no-resample takes
 * it as it is. */
static void test_pal8_exact(void **state)
{
    image im;
    char path[256];
    run_result r;
    zsm z;
    unsigned i;
    (void)state;
    im.w = im.h = 32;
    im.rgb = malloc(32 * 32 * 3);
    assert_non_null(im.rgb);
    for (i = 0; i < 32 * 32; i++) {
        unsigned k = ((i % 32) / 8) * 4 + (i / 32) / 8;
        im.rgb[3 * i] = (uint8_t)(k * 16);
        im.rgb[3 * i + 1] = (uint8_t)(255 - k * 8);
        im.rgb[3 * i + 2] = (uint8_t)(k * 5);
    }
    snprintf(path, sizeof path, "%s/pal.png", g_dir);
    write_png(path, &im);
    write_quad("palq", "pal.png");
    run(&r, "'%s' -q --texture auto --no-resample --texture-size 32 --texture-format pal8 "
            "--texture-filter bilinear --texture-wrap clamp --format zsm -o '%s/p' '%s/palq.obj'",
        MESHC, g_dir, g_dir);
    /* clamp keeps u 0.25..2.75 as it is: within Q3.12 */
    expect_ok("pal8 exact", &r);
    z = read_zsm(strcat(strcpy(path, g_dir), "/p.zsm"));
    assert_int_equal(z.tw, 32);
    assert_int_equal(z.tflags, ZS_TEX_BILINEAR | ZS_TEX_CLAMP);
    for (i = 0; i < 32 * 32; i++)
        assert_int_equal(z.pal[z.idx8[i]], rgb565(im.rgb[3 * i], im.rgb[3 * i + 1], im.rgb[3 * i + 2]));
    assert_int_equal(z.uv[0] == lround(0.25 * ZS_UV_ONE) || z.uv[0] == lround(2.75 * ZS_UV_ONE), 1);
    free_zsm(&z);
    free(im.rgb);
}

static void test_jpeg(void **state)
{
    image im = pattern(80, 48, 2), dec;
    char path[256];
    run_result r;
    zsm z;
    uint16_t *ref;
    (void)state;
    snprintf(path, sizeof path, "%s/pat.jpg", g_dir);
    write_jpeg(path, &im);
    dec = read_jpeg(path);
    write_quad("jq", "pat.jpg");
    run(&r, "'%s' -q --texture auto --format zsm -o '%s/j' '%s/jq.obj'", MESHC, g_dir, g_dir);
    expect_ok("jpeg", &r);
    z = read_zsm(strcat(strcpy(path, g_dir), "/j.zsm"));
    assert_int_equal(z.tw, 64);
    assert_int_equal(z.th, 32);
    ref = reference(&dec, 64, 32, NULL);
    assert_memory_equal(z.texels, ref, 64 * 32 * 2);
    print_message("jpeg 80 x 48 -> 64 x 32: texels equal the reference\n");
    free(ref);
    free_zsm(&z);
    free(im.rgb);
    free(dec.rgb);
}

/* glTF's box: the PNG embedded in the .glb and the same PNG beside the .gltf
 * give the same texels, those of the reference (211 x 211 -> 128 x 128). */
static void test_embedded(void **state)
{
    image im = read_png(ASSIMP_MODELS "/glTF2/BoxTextured-glTF/CesiumLogoFlat.png");
    char path[256];
    run_result r;
    zsm a, b;
    uint16_t *ref;
    (void)state;
    run(&r, "'%s' -q --texture auto --texture-size 128 --format zsm -o '%s/glb' "
            "'%s/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'", MESHC, g_dir, ASSIMP_MODELS);
    expect_ok("glb", &r);
    run(&r, "'%s' -q --texture auto --texture-size 128 --format zsm -o '%s/gltf' "
            "'%s/glTF2/BoxTextured-glTF/BoxTextured.gltf'", MESHC, g_dir, ASSIMP_MODELS);
    expect_ok("gltf", &r);
    run(&r, "'%s' --info --texture auto '%s/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'",
        MESHC, ASSIMP_MODELS);
    expect_ok("glb info", &r);
    assert_non_null(strstr(r.out, "texture *0: 211 x 211 -> 64 x 64 rgb565, 8192 bytes"));
    a = read_zsm(strcat(strcpy(path, g_dir), "/glb.zsm"));
    b = read_zsm(strcat(strcpy(path, g_dir), "/gltf.zsm"));
    assert_int_equal(a.tw, 128);
    assert_int_equal(a.th, 128);
    ref = reference(&im, 128, 128, NULL);
    assert_memory_equal(a.texels, ref, 128 * 128 * 2);
    assert_memory_equal(b.texels, ref, 128 * 128 * 2);
    assert_int_equal(a.nv, b.nv);
    assert_memory_equal(a.uv, b.uv, a.nv * 4u);
    free(ref);
    free_zsm(&a);
    free_zsm(&b);
    free(im.rgb);
}

/* --bsp: split vertices get interpolated uvs. tex_planes.obj's uvs are
 * u = 0.5 + (x + y/2 + z/4)/16, v = 0.5 + (y - z/2 + x/4)/16 everywhere, so
 * every output vertex must keep them (within the rounding of the split
 * vertex's position and of the uv). */
static void test_bsp_uvs(void **state)
{
    unsigned i, split = 0;
    double worst = 0, unit = (double)T_TEXBSP_SCALE / 65536.0;
    (void)state;
    assert_true(T_TEXBSP_VERTEX_COUNT > 12); /* the quads were cut */
    assert_true(T_TEXBSP_BSP_NODE_COUNT >= 3);
    assert_ptr_equal(t_texbsp.texture, &t_texbsp_texture);
    assert_int_equal(T_TEXBSP_TEXTURE_WIDTH, 16);
    for (i = 0; i < T_TEXBSP_VERTEX_COUNT; i++) {
        double x = t_texbsp.positions[3 * i] * unit, y = t_texbsp.positions[3 * i + 1] * unit,
               z = t_texbsp.positions[3 * i + 2] * unit;
        double u = (0.5 + (x + y / 2 + z / 4) / 16) * ZS_UV_ONE;
        double v = (1.0 - (0.5 + (y - z / 2 + x / 4) / 16)) * ZS_UV_ONE;
        double d = fmax(fabs(t_texbsp.uvs[2 * i] - u), fabs(t_texbsp.uvs[2 * i + 1] - v));
        if (d > worst)
            worst = d;
        split += fabs(x) > 1e-3 && fabs(x) < 3.999 && fabs(z) > 1e-3 && fabs(z) < 3.999 &&
                 fabs(y - 0.5) > 1e-3;
    }
    print_message("BSP: %u vertices (12 before), worst uv off the plane function %.3f / 4096\n",
                  (unsigned)T_TEXBSP_VERTEX_COUNT, worst);
    /* one position unit moves uv by at most 1.75/16 * 4096 * unit */
    assert_true(worst <= 0.5 + 1.75 / 16 * ZS_UV_ONE * unit * 0.87 + 1e-9);
    (void)split;
}

/* ---- the simulator and the library draw the same ---------------------------------- */

static void render_lib(const zs_mesh *m, unsigned w, unsigned h, uint8_t *img)
{
    static uint8_t arena[ZS_ARENA_BYTES_CFG(160, 120, 20000, 20000, 4096, ZS_CFG_TEXTURE)];
    zs_config cfg = zs_config_default(160, 120, 20000, 20000, 4096);
    zs_renderer r;
    zs_camera cam;
    zs_shade_params sp = zs_shade_default();
    cfg.flags |= ZS_CFG_TEXTURE;
    assert_int_equal(zs_init(&r, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(0, ZS_FX(1) / 2, ZS_FX(3)),
                                       zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), (zs_fixed)lround(0.1 * 65536),
                                           ZS_FX(100)), ZS_OK);
    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    sp.shading = ZS_SHADE_FLAT;
    sp.format = ZS_FMT_RGB888;
    sp.ambient = ZS_FX_ONE;
    sp.light_count = 0;
    sp.background = 0;
    assert_int_equal(zs_frame_shading(&r, &sp), ZS_OK);
    assert_int_equal(zs_draw(&r, m, NULL), ZS_OK);
    assert_int_equal(zs_render_rows(&r, 0, (int)h, img, w * 3), ZS_OK);
}

static void test_sim_matches_library(void **state)
{
    char path[256];
    run_result r;
    image sim;
    static uint8_t lib[160 * 120 * 3], plain[160 * 120 * 3];
    zs_mesh untextured = t_duck;
    size_t i, covered = 0, differ = 0;
    zsm z;
    (void)state;
    /* the same conversion as t_duck's (mk/meshtex.mk), as a .zsm */
    run(&r, "'%s' -q --normalize --texture auto --format zsm -o '%s/duck' '%s/Collada/duck.dae'", MESHC,
        g_dir, ASSIMP_MODELS);
    expect_ok("duck zsm", &r);
    z = read_zsm(strcat(strcpy(path, g_dir), "/duck.zsm"));
    assert_int_equal(z.nv, T_DUCK_VERTEX_COUNT);
    assert_memory_equal(z.uv, t_duck.uvs, z.nv * 4u);
    assert_memory_equal(z.texels, t_duck_texture.texels, 64 * 64 * 2);
    free_zsm(&z);
    run(&r, "'%s' render '%s/duck.zsm' --size 160x120 --eye 0,0.5,3 --target 0,0,0 --fov 60 "
            "--near 0.1 --far 100 --unlit -q --out '%s/sim.png'", SIM, g_dir, g_dir);
    expect_ok("sim render", &r);
    sim = read_png(strcat(strcpy(path, g_dir), "/sim.png"));
    assert_int_equal(sim.w, 160);
    assert_int_equal(sim.h, 120);
    render_lib(&t_duck, 160, 120, lib);
    untextured.uvs = NULL;
    untextured.texture = NULL;
    render_lib(&untextured, 160, 120, plain);
    if (getenv("TEX_DUMP")) {
        image d = {160, 120, lib};
        write_png(getenv("TEX_DUMP"), &d);
    }
    assert_memory_equal(sim.rgb, lib, sizeof lib);
    for (i = 0; i < 160 * 120; i++) {
        int bg = !lib[3 * i] && !lib[3 * i + 1] && !lib[3 * i + 2];
        covered += !bg;
        differ += !bg && memcmp(lib + 3 * i, plain + 3 * i, 3) != 0;
    }
    print_message("duck: sim == library over 160 x 120; the texture changes %zu of %zu covered "
                  "pixels\n", differ, covered);
    assert_true(covered > 2000);
    assert_true(differ * 10 > covered * 9);
    free(sim.rgb);
}

/* The simulator's own texture loading (assimp file, --textures): the duck
 * looks textured (many colours), and without --textures it does not. */
static void test_sim_textures_option(void **state)
{
    run_result r;
    char path[256];
    image a, b;
    size_t i, differ = 0;
    (void)state;
    run(&r, "'%s' render '%s/Collada/duck.dae' --fit --unlit --textures --texture-size 64 -q "
            "--out '%s/t.png'", SIM, ASSIMP_MODELS, g_dir);
    expect_ok("sim --textures", &r);
    run(&r, "'%s' render '%s/Collada/duck.dae' --fit --unlit -q --out '%s/u.png'", SIM,
        ASSIMP_MODELS, g_dir);
    expect_ok("sim untextured", &r);
    a = read_png(strcat(strcpy(path, g_dir), "/t.png"));
    b = read_png(strcat(strcpy(path, g_dir), "/u.png"));
    for (i = 0; i < (size_t)a.w * a.h; i++)
        differ += memcmp(a.rgb + 3 * i, b.rgb + 3 * i, 3) != 0;
    assert_true(differ > 1000);
    run(&r, "'%s' render '%s/Collada/duck.dae' --textures --aa -q --out '%s/x.png'", SIM,
        ASSIMP_MODELS, g_dir);
    assert_true(r.exited && r.status == 2 && strstr(r.out, "do not go with textures"));
    run(&r, "'%s' render '%s/Collada/duck.dae' --textures --texture-size 48 -q --out '%s/x.png'",
        SIM, ASSIMP_MODELS, g_dir);
    assert_true(r.exited && r.status == 2 && strstr(r.out, "power of two"));
    free(a.rgb);
    free(b.rgb);
}

/* ---- errors ----------------------------------------------------------------- */

static void test_errors(void **state)
{
    char path[256];
    run_result r;
    FILE *f;
    image big = pattern(20000, 1, 3), sq = pattern(64, 64, 4);
    (void)state;
    /* unreadable: missing, a directory, corrupt */
    write_quad("missing", "nothere.png");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/missing.obj'", MESHC, g_dir, g_dir);
    expect_error("missing image", &r, 3, "cannot read image");
    snprintf(path, sizeof path, "%s/adir.png", g_dir);
    assert_int_equal(mkdir(path, 0700), 0);
    write_quad("dir", "adir.png");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/dir.obj'", MESHC, g_dir, g_dir);
    expect_error("directory image", &r, 3, "directory");
    snprintf(path, sizeof path, "%s/bad.png", g_dir);
    f = fopen(path, "wb");
    assert_non_null(f);
    fwrite("\x89PNG\r\n\x1a\n\0\0\0\rIHDRgarbage-garbage", 1, 32, f);
    fclose(f);
    write_quad("corrupt", "bad.png");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/corrupt.obj'", MESHC, g_dir, g_dir);
    expect_error("corrupt png", &r, 3, "corrupt PNG");
    snprintf(path, sizeof path, "%s/bad.jpg", g_dir);
    f = fopen(path, "wb");
    assert_non_null(f);
    fwrite("\xff\xd8\xff\xe0garbage", 1, 11, f);
    fclose(f);
    write_quad("corruptj", "bad.jpg");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/corruptj.obj'", MESHC, g_dir, g_dir);
    expect_error("corrupt jpeg", &r, 3, "corrupt JPEG");
    /* unsupported: a GIF */
    snprintf(path, sizeof path, "%s/a.gif", g_dir);
    f = fopen(path, "wb");
    assert_non_null(f);
    fwrite("GIF89a\1\0\1\0\0\0\0;", 1, 14, f);
    fclose(f);
    write_quad("gif", "a.gif");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/gif.obj'", MESHC, g_dir, g_dir);
    expect_error("gif", &r, 3, "unsupported image format");
    /* oversized: beyond the decoder's limit; not a power of two with
     * --no-resample; over --texture-size with --no-resample */
    snprintf(path, sizeof path, "%s/big.png", g_dir);
    write_png(path, &big);
    write_quad("big", "big.png");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/big.obj'", MESHC, g_dir, g_dir);
    expect_error("20000 pixels wide", &r, 4, "oversized image: 20000 x 1");
    snprintf(path, sizeof path, "%s/pat.png", g_dir);
    write_png(path, &sq); /* 64 x 64 */
    write_quad("sq", "pat.png");
    run(&r, "'%s' -q --texture auto --no-resample --texture-size 32 -o '%s/o' '%s/sq.obj'", MESHC,
        g_dir, g_dir);
    expect_error("64 x 64 over 32", &r, 4, "oversized texture");
    run(&r, "'%s' -q --texture auto --no-resample -o '%s/o' '%s/sq.obj'", MESHC, g_dir, g_dir);
    expect_ok("64 x 64 within 64", &r);
    /* no texture coordinates for --texture FILE; two textures; bad options */
    run(&r, "'%s' -q --texture '%s' -o '%s/o' '%s/known.obj'", MESHC, path, g_dir, TOOLS_DATA);
    expect_error("no uvs", &r, 3, "no texture coordinates");
    run(&r, "'%s' -q --texture auto -o '%s/o' '%s/OBJ/spider.obj'", MESHC, g_dir, ASSIMP_MODELS);
    expect_error("two textures", &r, 3, "more than one texture");
    run(&r, "'%s' -q --texture auto --texture-size 100 '%s/sq.obj'", MESHC, g_dir);
    expect_error("size not a power of two", &r, 2, "power of two");
    run(&r, "'%s' -q --texture auto --texture-format bmp '%s/sq.obj'", MESHC, g_dir);
    expect_error("bad format", &r, 2, "bmp");
    /* the sim reports the same */
    run(&r, "'%s' render '%s/gif.obj' --textures -q --out '%s/x.png'", SIM, g_dir, g_dir);
    assert_true(r.exited && r.status != 0 && strstr(r.out, "unsupported image format"));
    /* a truncated textured .zsm */
    run(&r, "'%s' -q --texture auto --format zsm -o '%s/sq' '%s/sq.obj' && head -c 300 "
            "'%s/sq.zsm' > '%s/cut.zsm' && '%s' render '%s/cut.zsm' -q --out '%s/x.png'",
        MESHC, g_dir, g_dir, g_dir, g_dir, SIM, g_dir, g_dir);
    assert_true(r.exited && r.status != 0 && strstr(r.out, "not a valid zspan-meshc binary mesh"));
    free(big.rgb);
    free(sq.rgb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_duck_texels),   cmocka_unit_test(test_png_resample),
        cmocka_unit_test(test_pal8_exact),    cmocka_unit_test(test_jpeg),
        cmocka_unit_test(test_embedded),      cmocka_unit_test(test_bsp_uvs),
        cmocka_unit_test(test_sim_matches_library), cmocka_unit_test(test_sim_textures_option),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("meshc_textures", tests, make_dir, remove_dir) ? 1 : 0;
}
