/* SPDX-License-Identifier: MIT */
/*
 * test_texture: texture mapping (ZS_CFG_TEXTURE).
 *  - span mode == z-buffer mode, byte for byte, on random textured scenes
 *    (every filter, wrap and clamp, exact and subdivided, both texture
 *    formats, flat and Gouraud, lights and fog, every byte format, bands);
 *  - untextured meshes render the same bytes whether or not the renderer
 *    was built with ZS_CFG_TEXTURE;
 *  - nearest, exact: the texel at each covered pixel against a
 *    double-precision perspective-correct reference computed from the
 *    snapped screen vertices (the setup hook) and the texture coordinates:
 *    the exact texel at >= 99.9% of covered pixels, within one everywhere;
 *  - subdivided: the measured error against the same reference stays
 *    within its stated bound (README: Texture mapping);
 *  - bilinear: within 2 LSB per channel of a double-precision bilinear
 *    filter at the reference coordinates, on random triangles;
 *  - lighting and fog modulate the texel as documented (formulas here);
 *  - bad textures and meshes get their error codes.
 * (tests/texture/test_llvmpipe.c compares with Mesa's llvmpipe.)
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 72
#define NEAR_FX (ZS_FX(1) / 4)
#define FAR_FX ZS_FX(64)

static unsigned long g_scenes, g_px, g_exact, g_off1, g_bil_px, g_sub_px;
static double g_sub_max;
static unsigned long g_clipped; /* reference scenes left out: clipped */

/* ---------------- textures ---------------- */

/* Texel (i, j) says where it is: R = i, G = j (RGB565, 32 x 64). */
static uint16_t g_coord_tex[64 * 32];
static uint16_t g_rand_tex[64 * 64];
static uint8_t g_pal_idx[32 * 16];
static uint16_t g_palette[256];

static void make_textures(zt_rng *g)
{
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 32; i++)
            g_coord_tex[j * 32 + i] = (uint16_t)((i << 11) | (j << 5) | ((i + j) & 31));
    for (int k = 0; k < 64 * 64; k++)
        g_rand_tex[k] = (uint16_t)zt_u32(g);
    for (int k = 0; k < 32 * 16; k++)
        g_pal_idx[k] = (uint8_t)zt_u32(g);
    for (int k = 0; k < 256; k++)
        g_palette[k] = (uint16_t)zt_u32(g);
}

static zs_texture tex_make(int kind, unsigned flags)
{
    zs_texture t;
    memset(&t, 0, sizeof t);
    if (kind == 0) {
        t.texels = g_coord_tex;
        t.width = 32;
        t.height = 64;
        t.format = ZS_TEX_RGB565;
    } else if (kind == 1) {
        t.texels = g_rand_tex;
        t.width = 64;
        t.height = 64;
        t.format = ZS_TEX_RGB565;
    } else {
        t.texels = g_pal_idx;
        t.palette = g_palette;
        t.width = 32;
        t.height = 16;
        t.format = ZS_TEX_PAL8;
    }
    t.flags = (uint8_t)flags;
    return t;
}

static uint32_t texel_rgb(const zs_texture *t, int i, int j)
{
    uint32_t c;
    if (t->format == ZS_TEX_PAL8)
        c = t->palette[((const uint8_t *)t->texels)[j * t->width + i]];
    else
        c = ((const uint16_t *)t->texels)[j * t->width + i];
    uint32_t r = (c >> 11) & 31, gg = (c >> 5) & 63, b = c & 31;
    return (((r << 3) | (r >> 2)) << 16) | (((gg << 2) | (gg >> 4)) << 8) | ((b << 3) | (b >> 2));
}

/* ---------------- renderer ---------------- */

static void ctx_init(zt_ctx *c, uint16_t flags) { zt_ctx_init_flags(c, W, H, 600, 1800, 512, flags); }

/* ntri random triangles of the kinds given (zt_scene_random), 64 position
 * units per world unit. */
static void random_scene(zt_rng *g, zt_scene *s, int ntri, unsigned kinds)
{
    zt_scene_init(s, W, H, 64);
    zt_scene_random(g, s, ntri, kinds, 0.25);
}

static int16_t *random_uvs(zt_rng *g, size_t nv, int spread)
{
    int16_t *uv = malloc(2 * nv * sizeof *uv + 1);
    for (size_t k = 0; k < 2 * nv; k++)
        uv[k] = (int16_t)zt_range(g, -spread * ZS_UV_ONE / 4, spread * ZS_UV_ONE / 4);
    return uv;
}

static zs_status render(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                        const zs_shade_params *sp, const zs_mesh *m, int nm, uint8_t *img,
                        int band, zt_recs *recs)
{
    if (recs) {
        zt_recs_clear(recs);
        zs_set_setup_hook(&c->r, zt_recs_hook, recs);
    } else {
        zs_set_setup_hook(&c->r, NULL, NULL);
    }
    zs_status st = zs_frame_begin(&c->r, cam, mode);
    if (st == ZS_OK)
        st = zs_frame_shading(&c->r, sp);
    for (int k = 0; k < nm && st == ZS_OK; k++)
        st = zs_draw(&c->r, &m[k], NULL);
    if (st == ZS_OK)
        st = zt_render_rows_all(&c->r, img, W, H, sp->format, band);
    return st;
}

static void random_look(zt_rng *g, int k, zs_shade_params *sp)
{
    *sp = zs_shade_default();
    sp->format = (zs_format)(k % ZS_FMT_COUNT);
    if (sp->format == ZS_FMT_ID16)
        sp->format = ZS_FMT_RGB888;
    sp->shading = (k / 5) % 2 ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    sp->background = zt_u32(g) & 0xFFFFFFu;
    int l = (k / 10) % 4;
    if (l & 1)
        zt_random_light(g, sp, ZS_FX(1) / 4);
    if (l & 2) {
        sp->fog.enabled = 1;
        sp->fog.color = zt_u32(g) & 0xFFFFFFu;
        sp->fog.start = (zs_fixed)zt_range(g, ZS_FX(1), ZS_FX(4));
        sp->fog.end = sp->fog.start + (zs_fixed)zt_range(g, ZS_FX(1), ZS_FX(20));
    }
}

/* ---------------- span == zline ---------------- */

static void test_modes_identical(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, 0x7E47E4001ull);
    make_textures(&g);
    zt_ctx c;
    ctx_init(&c, ZS_CFG_TEXTURE);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    size_t bytes = (size_t)W * H * 3;
    uint8_t *a = malloc(bytes), *b = malloc(bytes);
    for (int sc = 0; sc < 240; sc++) {
        zt_scene s;
        random_scene(&g, &s, 6 + (int)zt_below(&g, 40), ZT_SC_ALL);
        zs_texture tex = tex_make(sc % 3, (unsigned)(sc / 3) % 8);
        int16_t *uv = random_uvs(&g, s.nv, 1 + (int)zt_below(&g, 12));
        zs_mesh m[2];
        m[0] = zt_scene_mesh(&s, sc % 2, (sc / 2) % 2);
        m[0].uvs = uv;
        m[0].texture = &tex;
        /* an untextured copy, shifted in depth order by submission */
        m[1] = zt_scene_mesh(&s, 1, 0);
        int nm = 1 + (sc % 4 == 0);
        zs_shade_params sp;
        random_look(&g, sc, &sp);
        int band = (sc % 3 == 0) ? H : 1 + (int)zt_below(&g, 9);
        memset(a, 0xA5, bytes);
        memset(b, 0x5A, bytes);
        assert_int_equal(render(&c, &cam, ZS_MODE_SPAN, &sp, m, nm, a, band, NULL), ZS_OK);
        assert_int_equal(render(&c, &cam, ZS_MODE_ZLINE, &sp, m, nm, b, band, NULL), ZS_OK);
        size_t n = (size_t)W * H * zs_format_bytes(sp.format);
        long d = zt_first_diff(a, b, n);
        if (d >= 0)
            fprintf(stderr, "scene %d: first difference at byte %ld (pixel %ld,%ld), flags %u\n",
                    sc, d, (d / (long)zs_format_bytes(sp.format)) % W,
                    (d / (long)zs_format_bytes(sp.format)) / W, tex.flags);
        assert_true(d < 0);
        g_scenes++;
        free(uv);
        zt_scene_free(&s);
    }
    free(a);
    free(b);
    zt_ctx_free(&c);
}

/* ---------------- untextured output unchanged ---------------- */

static void test_untextured_unchanged(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, 0x7E47E4002ull);
    zt_ctx plain, tex;
    ctx_init(&plain, 0);
    ctx_init(&tex, ZS_CFG_TEXTURE);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    size_t bytes = (size_t)W * H * 3;
    uint8_t *a = malloc(bytes), *b = malloc(bytes);
    for (int sc = 0; sc < 60; sc++) {
        zt_scene s;
        random_scene(&g, &s, 10 + (int)zt_below(&g, 30), ZT_SC_ALL);
        zs_mesh m = zt_scene_mesh(&s, sc % 2, (sc / 2) % 2);
        zs_shade_params sp;
        random_look(&g, sc, &sp);
        for (int mode = 0; mode < 2; mode++) {
            zs_visibility v = mode ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
            assert_int_equal(render(&plain, &cam, v, &sp, &m, 1, a, H, NULL), ZS_OK);
            assert_int_equal(render(&tex, &cam, v, &sp, &m, 1, b, H, NULL), ZS_OK);
            assert_true(zt_first_diff(a, b, (size_t)W * H * zs_format_bytes(sp.format)) < 0);
        }
        zt_scene_free(&s);
    }
    free(a);
    free(b);
    zt_ctx_free(&plain);
    zt_ctx_free(&tex);
}

/* ---------------- the double-precision reference ---------------- */

/* Perspective-correct texel coordinates (texels, not wrapped) of record r
 * at the centre of pixel (px, py): screen barycentrics of the snapped
 * vertices, weighted by 1/w (proportional to A - z). uvs: the record's
 * three vertices' u, v. */
static void ref_coords(const zt_rec *r, const int16_t uv[6], const zs_texture *t, double A,
                       int px, int py, double *s, double *tt)
{
    double x = (px + 0.5) * 16, y = (py + 0.5) * 16;
    const int32_t *p = r->xy;
    double d = (double)(p[2] - p[0]) * (p[5] - p[1]) - (double)(p[4] - p[0]) * (p[3] - p[1]);
    double l1 = ((x - p[0]) * (p[5] - p[1]) - (p[4] - p[0]) * (y - p[1])) / d;
    double l2 = ((p[2] - p[0]) * (y - p[1]) - (x - p[0]) * (p[3] - p[1])) / d;
    double l[3] = {1 - l1 - l2, l1, l2}, num_s = 0, num_t = 0, den = 0;
    for (int k = 0; k < 3; k++) {
        double q = A - r->z[k] / 1073741824.0;
        num_s += l[k] * q * uv[2 * k] / ZS_UV_ONE * t->width;
        num_t += l[k] * q * uv[2 * k + 1] / ZS_UV_ONE * t->height;
        den += l[k] * q;
    }
    *s = num_s / den;
    *tt = num_t / den;
}

static int wrapi(int i, int n, int clamp)
{
    if (clamp)
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
    return ((i % n) + n) % n;
}

/* Distance between texel indices a and b (wrapping: the shorter way). */
static int texel_dist(int a, int b, int n, int clamp)
{
    int d = abs(a - b);
    return clamp ? d : (d < n - d ? d : n - d);
}

/* A scene of random front-facing triangles with no clipping (so records
 * are the mesh's triangles), one draw: tag k + 1 is triangle k. */
typedef struct ref_scene {
    zt_scene s;
    int16_t *uv;
} ref_scene;

static void ref_scene_make(zt_rng *g, ref_scene *rs, int ntri, int spread)
{
    random_scene(g, &rs->s, ntri, ZT_SC_PLAIN | ZT_SC_FLAT | ZT_SC_SHARED | ZT_SC_LAYERS);
    rs->uv = random_uvs(g, rs->s.nv, spread);
}

/* Runs the reference over every covered pixel whose nearest record is
 * known (ray caster); calls fn with the reference coordinates. */
typedef void (*ref_fn)(void *user, int px, int py, double s, double t, const uint8_t *pixel);

static void ref_walk(const ref_scene *rs, const zt_recs *recs, const zs_texture *t,
                     const uint8_t *img, unsigned bpp, ref_fn fn, void *user)
{
    zt_cast cast;
    zt_cast_alloc(&cast, W, H);
    zt_raycast(recs, &cast);
    double A = (double)FAR_FX / (double)(FAR_FX - NEAR_FX);
    for (int py = 0; py < H; py++)
        for (int px = 0; px < W; px++) {
            int bi = cast.best[py * W + px];
            if (bi < 0)
                continue;
            const zt_rec *r = &recs->v[bi];
            /* a near tie with another surface: either may be drawn */
            if (cast.z2[py * W + px] - cast.z1[py * W + px] < 1e-6)
                continue;
            const uint16_t *idx = rs->s.idx + 3u * (r->tag - 1u);
            int16_t uv[6];
            for (int k = 0; k < 3; k++) {
                uv[2 * k] = rs->uv[2 * idx[k]];
                uv[2 * k + 1] = rs->uv[2 * idx[k] + 1];
            }
            double s, tt;
            ref_coords(r, uv, t, A, px, py, &s, &tt);
            fn(user, px, py, s, tt, img + ((size_t)py * W + px) * bpp);
        }
    zt_cast_free(&cast);
}

/* The reference tests' frames: 120 random scenes from seed (4..19
 * triangles, uv spread 2 .. spread + 1 quarter-textures), scene sc drawn
 * white with the texture tex_of(sc) in RGB888, in zline mode where
 * zline_every divides sc (0: never), else span mode; every pixel of a scene
 * without clipping (records == the mesh's triangles) goes to fn, with *cur
 * pointing at the scene's texture. */
static void ref_scenes(uint64_t seed, int spread, int zline_every, zs_texture (*tex_of)(int sc),
                       const zs_texture **cur, ref_fn fn, void *acc)
{
    zt_rng g;
    zt_rng_seed(&g, seed);
    make_textures(&g);
    zt_ctx c;
    ctx_init(&c, ZS_CFG_TEXTURE);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    uint8_t *img = malloc((size_t)W * H * 3);
    for (int sc = 0; sc < 120; sc++) {
        ref_scene rs;
        ref_scene_make(&g, &rs, 4 + (int)zt_below(&g, 16), 2 + (int)zt_below(&g, (uint32_t)spread));
        zs_texture tex = tex_of(sc);
        zs_mesh m = zt_scene_mesh(&rs.s, 0, 0);
        m.color = 0xFFFFFF;
        m.uvs = rs.uv;
        m.texture = &tex;
        zs_shade_params sp = zs_shade_default();
        sp.format = ZS_FMT_RGB888;
        zt_recs recs = {0};
        zs_visibility mode = zline_every && sc % zline_every == 0 ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
        assert_int_equal(render(&c, &cam, mode, &sp, &m, 1, img, H, &recs), ZS_OK);
        *cur = &tex;
        if (c.r.stats.tris_clipped == 0)
            ref_walk(&rs, &recs, &tex, img, 3, fn, acc);
        else
            g_clipped++;
        zt_recs_free(&recs);
        free(rs.uv);
        zt_scene_free(&rs.s);
    }
    free(img);
    zt_ctx_free(&c);
}

typedef struct nearest_acc {
    const zs_texture *t;
    unsigned long px, exact, off1, worse;
    double max_err;
} nearest_acc;

static void nearest_check(void *user, int px, int py, double s, double t, const uint8_t *p)
{
    nearest_acc *a = user;
    (void)px;
    (void)py;
    int clamp = (a->t->flags & ZS_TEX_CLAMP) != 0;
    int gi = p[0] >> 3, gj = p[1] >> 2; /* the texel the renderer chose */
    int ri = wrapi((int)floor(s), a->t->width, clamp), rj = wrapi((int)floor(t), a->t->height, clamp);
    int di = texel_dist(gi, ri, a->t->width, clamp), dj = texel_dist(gj, rj, a->t->height, clamp);
    a->px++;
    if (di == 0 && dj == 0)
        a->exact++;
    else if (di <= 1 && dj <= 1)
        a->off1++;
    else {
        a->worse++;
        if (getenv("ZT_DEBUG") && a->worse < 20)
            fprintf(stderr, "px %d,%d ref %.3f %.3f (%d %d) got %d %d\n", px, py, s, t, ri, rj, gi, gj);
    }
    /* distance of the centre from the chosen texel, in texels */
    if (!clamp) {
        double es = fabs(s - floor(s) + (ri - gi) - 0.5), et = fabs(t - floor(t) + (rj - gj) - 0.5);
        (void)es;
        (void)et;
    }
}

static zs_texture nearest_tex(int sc) { return tex_make(0, (sc % 2) ? ZS_TEX_CLAMP : 0u); }

static void test_nearest_exact(void **state)
{
    (void)state;
    nearest_acc acc;
    memset(&acc, 0, sizeof acc);
    ref_scenes(0x7E47E4003ull, 16, 3, nearest_tex, &acc.t, nearest_check, &acc);
    fprintf(stderr, "nearest exact: %lu px, exact %lu (%.4f%%), off by one %lu, worse %lu\n",
            acc.px, acc.exact, 100.0 * (double)acc.exact / (double)acc.px, acc.off1, acc.worse);
    g_px += acc.px;
    g_exact += acc.exact;
    g_off1 += acc.off1;
    assert_true(acc.px > 20000);
    assert_true((double)acc.exact >= 0.999 * (double)acc.px);
    assert_int_equal(acc.worse, 0);
}

/* ---------------- subdivided ---------------- */

/* The subdivided mode's bound (texels): a segment is affine only where
 * its stray from the perspective value is within a quarter of a texel
 * (texture.c, affine_ok), plus the planes' rounding (README: Texture
 * mapping). Measured here as how far outside the drawn texel the
 * reference point lies. */
#define SUBDIV_BOUND 0.26

typedef struct sub_acc {
    const zs_texture *t;
    const uint8_t *exact_img;
    unsigned long px, diff;
    double max_err;
} sub_acc;

static void sub_check(void *user, int px, int py, double s, double t, const uint8_t *p)
{
    sub_acc *a = user;
    (void)px;
    (void)py;
    int clamp = (a->t->flags & ZS_TEX_CLAMP) != 0;
    int gi = p[0] >> 3, gj = p[1] >> 2;
    /* how far outside texel (gi, gj) the reference point lies (0 inside) */
    double fs = floor(s), ft = floor(t);
    int ri = wrapi((int)fs, a->t->width, clamp), rj = wrapi((int)ft, a->t->height, clamp);
    int di = texel_dist(gi, ri, a->t->width, clamp), dj = texel_dist(gj, rj, a->t->height, clamp);
    double es = 0, et = 0;
    if (di) {
        double in = s - fs; /* the point's place in its own texel */
        es = (di - 1) + (in < 0.5 ? in : 1 - in);
    }
    if (dj) {
        double in = t - ft;
        et = (dj - 1) + (in < 0.5 ? in : 1 - in);
    }
    double e = es > et ? es : et;
    a->px++;
    if (di || dj)
        a->diff++;
    if (e > a->max_err)
        a->max_err = e;
}

static zs_texture sub_tex(int sc)
{
    return tex_make(0, ZS_TEX_SUBDIV | ((sc % 2) ? ZS_TEX_CLAMP : 0u));
}

static void test_subdivided_bound(void **state)
{
    (void)state;
    sub_acc acc;
    memset(&acc, 0, sizeof acc);
    ref_scenes(0x7E47E4004ull, 8, 0, sub_tex, &acc.t, sub_check, &acc);
    fprintf(stderr, "subdivided: %lu px, other texel than exact %lu (%.3f%%), max error %.3f texel\n",
            acc.px, acc.diff, 100.0 * (double)acc.diff / (double)acc.px, acc.max_err);
    g_sub_px += acc.px;
    if (acc.max_err > g_sub_max)
        g_sub_max = acc.max_err;
    assert_true(acc.px > 20000);
    assert_true(acc.max_err <= SUBDIV_BOUND);
}

/* ---------------- bilinear ---------------- */

typedef struct bil_acc {
    const zs_texture *t;
    unsigned long px;
    int max_diff;
} bil_acc;

static void bil_check(void *user, int px, int py, double s, double t, const uint8_t *p)
{
    bil_acc *a = user;
    (void)px;
    (void)py;
    int clamp = (a->t->flags & ZS_TEX_CLAMP) != 0;
    /* clamp mode clamps the coordinates to the triangle's range like the
     * renderer does: only where they are inside a texture extent */
    double s0 = s - 0.5, t0 = t - 0.5;
    int i = (int)floor(s0), j = (int)floor(t0);
    double fx = s0 - i, fy = t0 - j;
    uint32_t c[4] = {texel_rgb(a->t, wrapi(i, a->t->width, clamp), wrapi(j, a->t->height, clamp)),
                     texel_rgb(a->t, wrapi(i + 1, a->t->width, clamp), wrapi(j, a->t->height, clamp)),
                     texel_rgb(a->t, wrapi(i, a->t->width, clamp), wrapi(j + 1, a->t->height, clamp)),
                     texel_rgb(a->t, wrapi(i + 1, a->t->width, clamp),
                               wrapi(j + 1, a->t->height, clamp))};
    double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    for (int ch = 0; ch < 3; ch++) {
        int sh = 16 - 8 * ch;
        double v = 0;
        for (int k = 0; k < 4; k++)
            v += w[k] * ((c[k] >> sh) & 255);
        int d = abs(p[ch] - (int)floor(v + 0.5));
        if (d > a->max_diff)
            a->max_diff = d;
    }
    a->px++;
}

static zs_texture bil_tex(int sc) { return tex_make(1 + sc % 2, ZS_TEX_BILINEAR); }

static void test_bilinear(void **state)
{
    (void)state;
    bil_acc acc;
    memset(&acc, 0, sizeof acc);
    ref_scenes(0x7E47E4005ull, 12, 2, bil_tex, &acc.t, bil_check, &acc);
    fprintf(stderr, "bilinear: %lu px, largest difference %d LSB\n", acc.px, acc.max_diff);
    g_bil_px += acc.px;
    assert_true(acc.px > 20000);
    assert_true(acc.max_diff <= 2);
}

/* ---------------- errors ---------------- */

static void test_errors(void **state)
{
    (void)state;
    static const int16_t pos[9] = {-100, -100, -400, 100, -100, -400, 0, 100, -400};
    static const uint16_t idx[3] = {0, 1, 2};
    static const int16_t uvs[6] = {0, 0, 4096, 0, 0, 4096};
    static uint16_t texels[4 * 4];
    zt_ctx c, plain;
    ctx_init(&c, ZS_CFG_TEXTURE);
    ctx_init(&plain, 0);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    zs_texture t;
    memset(&t, 0, sizeof t);
    t.texels = texels;
    t.width = 4;
    t.height = 4;
    assert_int_equal(zs_texture_check(&t), ZS_OK);
    assert_int_equal(zs_texture_check(NULL), ZS_ERR_NULL);
    zs_texture bad = t;
    bad.width = 3; /* not a power of two */
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.height = 0;
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.width = 2048; /* above ZS_TEX_MAX_DIM */
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.texels = NULL;
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.format = 7; /* unknown */
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.format = ZS_TEX_PAL8; /* no palette */
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);
    bad = t;
    bad.flags = 0x80;
    assert_int_equal(zs_texture_check(&bad), ZS_ERR_TEXTURE);

    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 64;
    m.vertex_count = 3;
    m.triangle_count = 1;
    m.color = 0xFFFFFF;
    m.uvs = uvs;
    m.texture = &t;
    assert_int_equal(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_draw(&c.r, &m, NULL), ZS_OK);
    assert_int_equal(c.r.stats.tris_submitted, 1);
    zs_mesh mb = m;
    mb.texture = &bad; /* a bad texture: the draw is refused, nothing stored */
    bad = t;
    bad.width = 6;
    assert_int_equal(zs_draw(&c.r, &mb, NULL), ZS_ERR_TEXTURE);
    mb = m;
    mb.texture = NULL;
    assert_int_equal(zs_draw(&c.r, &mb, NULL), ZS_ERR_TEXTURE);
    mb = m;
    mb.uvs = NULL;
    assert_int_equal(zs_draw(&c.r, &mb, NULL), ZS_ERR_TEXTURE);
    assert_int_equal(c.r.stats.tris_submitted, 1);
    /* the config left textures out */
    assert_int_equal(zs_frame_begin(&plain.r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_draw(&plain.r, &m, NULL), ZS_ERR_MODE);
    /* more distinct textures than a frame holds */
    {
        zs_texture many[ZS_MAX_FRAME_TEXTURES + 1];
        assert_int_equal(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
        for (unsigned k = 0; k <= ZS_MAX_FRAME_TEXTURES; k++) {
            many[k] = t;
            zs_mesh mk = m;
            mk.texture = &many[k];
            assert_int_equal(zs_draw(&c.r, &mk, NULL),
                             k < ZS_MAX_FRAME_TEXTURES ? ZS_OK : ZS_ERR_CAPACITY);
        }
        zs_mesh again = m;
        again.texture = &many[0]; /* one already in the frame */
        assert_int_equal(zs_draw(&c.r, &again, NULL), ZS_OK);
    }
    assert_true(strstr(zs_strerror(ZS_ERR_TEXTURE), "power of two") != NULL);
    { /* the A-buffer's fragments carry no texture: the two are not combined */
        zs_config both = zs_config_default(W, H, 16, 16, 16);
        both.flags = ZS_CFG_TEXTURE | ZS_CFG_ABUFFER;
        assert_int_equal(zs_arena_bytes(&both), 0);
    }
    zt_ctx_free(&c);
    zt_ctx_free(&plain);
}

/* ---------------- lighting and fog ---------------- */

/* One big flat-lit triangle with a one-colour texture: the pixel is the
 * texel times the lit colour (rounded /255), then fogged toward the fog
 * colour; formulas written here. */
static void test_modulation(void **state)
{
    (void)state;
    static const int16_t pos[9] = {-400, -400, -100, 400, -400, -100, 0, 400, -100};
    static const uint16_t idx[3] = {0, 1, 2};
    static const int16_t uvs[6] = {0, 0, 4096, 0, 0, 4096};
    static const uint16_t texels[1] = {(20u << 11) | (40u << 5) | 10u};
    zt_ctx c;
    ctx_init(&c, ZS_CFG_TEXTURE);
    zs_camera cam;
    zt_camera_std(&cam, NEAR_FX, FAR_FX);
    zs_texture t;
    memset(&t, 0, sizeof t);
    t.texels = texels;
    t.width = 1;
    t.height = 1;
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 64;
    m.vertex_count = 3;
    m.triangle_count = 1;
    m.color = ZS_RGB(200, 100, 50);
    m.uvs = uvs;
    m.texture = &t;
    uint8_t *img = malloc((size_t)W * H * 3);
    uint32_t tx = texel_rgb(&t, 0, 0);
    for (int fog = 0; fog < 2; fog++) {
        zs_shade_params sp = zs_shade_default();
        sp.format = ZS_FMT_RGB888;
        if (fog) {
            sp.fog.enabled = 1;
            sp.fog.color = ZS_RGB(10, 240, 130);
            sp.fog.start = 0;
            sp.fog.end = ZS_FX(3); /* eye depth 100/64: fog 255 * 1.5625/3 */
        }
        assert_int_equal(render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, img, H, NULL), ZS_OK);
        const uint8_t *p = img + ((size_t)(H / 2) * W + W / 2) * 3;
        uint32_t f = fog ? (uint32_t)(((int64_t)(100 * 65536 / 64) * 255) / ZS_FX(3)) : 0;
        for (int ch = 0; ch < 3; ch++) {
            int sh = 16 - 8 * ch;
            double lit = ((tx >> sh) & 255) * ((m.color >> sh) & 255) / 255.0;
            double want = lit + (((sp.fog.color >> sh) & 255) - lit) * f / 255.0;
            assert_true(fabs(p[ch] - want) <= 1.5);
        }
    }
    free(img);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_modulation),
        cmocka_unit_test(test_modes_identical),
        cmocka_unit_test(test_untextured_unchanged),
        cmocka_unit_test(test_nearest_exact),
        cmocka_unit_test(test_subdivided_bound),
        cmocka_unit_test(test_bilinear),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fprintf(stderr, "test_texture: %lu scenes span == zline; nearest %lu px, %lu exact, %lu off "
                    "by one; subdivided %lu px, max %.3f texel; bilinear %lu px\n",
            g_scenes, g_px, g_exact, g_off1, g_sub_px, g_sub_max, g_bil_px);
    return rc;
}
