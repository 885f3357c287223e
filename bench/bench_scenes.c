/* SPDX-License-Identifier: MIT */
/* The benchmark scenes; see bench_scenes.h. */
#include "bench_scenes.h"

#include <string.h>

#include "bench_caps.h"
#include "cluster.h"
#include "cubes.h"
#include "sphere285.h"
#include "wuson.h"

const bench_scene bench_scenes[BENCH_SCENE_COUNT] = {
    {"sphere285", &bench_sphere285, ZS_FX(-3), 0, BENCH_CAPS_SPHERE285},
    {"cubes", &bench_cubes, ZS_FX(-8), ZS_FX(20), BENCH_CAPS_CUBES},
    {"wuson", &bench_wuson, ZS_FX(-3), 0, BENCH_CAPS_WUSON},
    {"cluster", &bench_cluster, ZS_FX(-3), ZS_FX(20), BENCH_CAPS_CLUSTER},
};

zs_mat34 bench_model_view(const bench_scene *s, int frame)
{
    zs_mat34 t = zs_mat34_translate(0, 0, s->tz);
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(30 + 2 * frame));
    zs_mat34 m;
    if (s->rx_deg) {
        zs_mat34 rx = zs_mat34_rotate_x(s->rx_deg);
        zs_mat34 rxy = zs_mat34_mul(&rx, &ry);
        m = zs_mat34_mul(&t, &rxy);
    } else {
        m = zs_mat34_mul(&t, &ry);
    }
    return m;
}

zs_config bench_config(const bench_scene *s)
{
    /* the scenes are flat and unlit: no per-vertex shading pools */
    zs_config c = zs_config_default(BENCH_W, BENCH_H, s->max_triangles, s->max_vertices,
                                    s->max_active_edges);
    c.flags = ZS_CFG_FLAT_ONLY;
    return c;
}

zs_status bench_camera(zs_camera *cam)
{
    static const zs_camera zero;
    zs_mat34 id = zs_mat34_identity();
    zs_status st;
    *cam = zero;
    st = zs_camera_set_view(cam, &id);
    if (st != ZS_OK)
        return st;
    return zs_camera_perspective(cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(100));
}

zs_status bench_submit(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int frame,
                       zs_visibility mode)
{
    zs_mat34 mv = bench_model_view(s, frame);
    zs_status st = zs_frame_begin(r, cam, mode);
    if (st != ZS_OK)
        return st;
    return zs_draw(r, s->mesh, &mv);
}

const char *const bench_mono_names[BENCH_MONO_VARIANTS] = {
    "mono-bayer", "mono-diffuse", "mono-lines", "gray4", "gray4-dither"};

zs_status bench_mono_frame(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int k,
                           uint32_t *sum)
{
    static uint8_t page[BENCH_W]; /* one page of 8 rows, or one row of bits */
    zs_mat34 mv = bench_model_view(s, 0);
    zs_shade_params sp = zs_shade_default();
    zs_status st = zs_frame_begin(r, cam, ZS_MODE_SPAN);
    int y;
    int rows = k == 1 || k == 2 ? 8 : 1; /* pages of 8 rows, or single rows */
    size_t n = k == 0 ? BENCH_W / 8 : k >= 3 ? BENCH_W / 2 : BENCH_W;
    if (st != ZS_OK)
        return st;
    sp.format = k == 0 ? ZS_FMT_MONO_MSB : k >= 3 ? ZS_FMT_GRAY4 : ZS_FMT_MONO_PAGE;
    sp.mono = (uint8_t)(k == 1   ? ZS_MONO_DIFFUSE
                        : k == 2 ? ZS_MONO_LINES
                        : k == 4 ? ZS_GRAY4_DITHER
                                 : 0u);
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK || (st = zs_draw(r, s->mesh, &mv)) != ZS_OK)
        return st;
    *sum = BENCH_FNV_BASIS;
    for (y = 0; st == ZS_OK && y < BENCH_H; y += rows) {
        st = zs_render_rows(r, y, rows, page, n);
        *sum = bench_fnv1a(*sum, page, n);
    }
    return st;
}

uint32_t bench_fnv1a(uint32_t h, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x01000193u;
    }
    return h;
}

/* ---- the textured scene (bench_tex_frame) ---- */

/* Texels as compile-time expressions of their index n, so the tables are
 * constant data in flash without a generated file. 64 x 64 RGB565: a red
 * ramp along x, a green ramp down y, blue checks of 8 texels. */
#define TEX_RGB(n)                                                                          \
    (uint16_t)(((((n) & 63u) >> 1) << 11) | (((n) >> 6) << 5) |                           \
               (((((n) & 63u) >> 3) ^ ((n) >> 9)) & 1u ? 28u : 6u))
/* 32 x 32 palette indices: diagonal bands; the palette a colour wheel. */
#define TEX_IDX(n) (uint8_t)(((((n) & 31u) + ((n) >> 5)) * 5u + (((n) >> 7) & 1u) * 128u) & 255u)
#define TEX_PAL(n)                                                                          \
    (uint16_t)((((n) * 7u & 31u) << 11) | (((255u - (n)) >> 2) << 5) | (((n) >> 3) & 31u))
#define REP4(M, n) M(n), M((n) + 1u), M((n) + 2u), M((n) + 3u)
#define REP16(M, n) REP4(M, n), REP4(M, (n) + 4u), REP4(M, (n) + 8u), REP4(M, (n) + 12u)
#define REP64(M, n) REP16(M, n), REP16(M, (n) + 16u), REP16(M, (n) + 32u), REP16(M, (n) + 48u)
#define REP256(M, n) REP64(M, n), REP64(M, (n) + 64u), REP64(M, (n) + 128u), REP64(M, (n) + 192u)
#define REP1024(M, n)                                                                       \
    REP256(M, n), REP256(M, (n) + 256u), REP256(M, (n) + 512u), REP256(M, (n) + 768u)

static const uint16_t tex_rgb_texels[64 * 64] = {
    REP1024(TEX_RGB, 0u), REP1024(TEX_RGB, 1024u), REP1024(TEX_RGB, 2048u),
    REP1024(TEX_RGB, 3072u)};
static const uint8_t tex_pal_texels[32 * 32] = {REP1024(TEX_IDX, 0u)};
static const uint16_t tex_palette[256] = {REP256(TEX_PAL, 0u)};

static const zs_texture tex_rgb = {tex_rgb_texels, 0, 64, 64, ZS_TEX_RGB565, 0};
static const zs_texture tex_rgb_sub = {tex_rgb_texels, 0, 64, 64, ZS_TEX_RGB565, ZS_TEX_SUBDIV};
static const zs_texture tex_rgb_bil = {tex_rgb_texels, 0, 64, 64, ZS_TEX_RGB565,
                                       ZS_TEX_BILINEAR};
static const zs_texture tex_pal_lit = {tex_pal_texels, tex_palette, 32, 32, ZS_TEX_PAL8,
                                       ZS_TEX_BILINEAR | ZS_TEX_SUBDIV | ZS_TEX_CLAMP};

/* A ground trapezoid 1.5 below the eye from 1.2 to 30 units ahead, inside
 * the guard band (no clipping), texture coordinates world x / 6 and -z / 6
 * (the texture repeats about 13 x 5 times); 1/256 units. */
static const int16_t ground_pos[4 * 3] = {-512,   -384, -307,  512,   -384, -307,
                                          10240, -384, -7680, -10240, -384, -7680};
static const int16_t ground_uv[4 * 2] = {-1365, 819, 1365, 819, 27307, 20480, -27307, 20480};
static const uint16_t ground_idx[2 * 3] = {0, 1, 2, 0, 2, 3};
static const int16_t ground_vn[4 * 3] = {0, 16384, 0, 0, 16384, 0, 0, 16384, 0, 0, 16384, 0};
static const zs_color ground_vc[4] = {0xFFFFFF, 0xFFE0C0, 0xC0E0FF, 0xE0FFE0};

/* A cube of side 1.2: four vertices per face, each face the whole texture. */
#define C 154
static const int16_t cube_pos[24 * 3] = {
    -C, -C, C,  C,  -C, C,  C,  C,  C,  -C, C,  C,  /* +z */
    C,  -C, -C, -C, -C, -C, -C, C,  -C, C,  C,  -C, /* -z */
    C,  -C, C,  C,  -C, -C, C,  C,  -C, C,  C,  C,  /* +x */
    -C, -C, -C, -C, -C, C,  -C, C,  C,  -C, C,  -C, /* -x */
    -C, C,  C,  C,  C,  C,  C,  C,  -C, -C, C,  -C, /* +y */
    -C, -C, -C, C,  -C, -C, C,  -C, C,  -C, -C, C,  /* -y */
};
#undef C
static const int16_t cube_vn[24 * 3] = {
    0, 0, 16384, 0, 0, 16384, 0, 0, 16384, 0, 0, 16384,
    0, 0, -16384, 0, 0, -16384, 0, 0, -16384, 0, 0, -16384,
    16384, 0, 0, 16384, 0, 0, 16384, 0, 0, 16384, 0, 0,
    -16384, 0, 0, -16384, 0, 0, -16384, 0, 0, -16384, 0, 0,
    0, 16384, 0, 0, 16384, 0, 0, 16384, 0, 0, 16384, 0,
    0, -16384, 0, 0, -16384, 0, 0, -16384, 0, 0, -16384, 0,
};
#define FACE(b) (b), (b) + 1, (b) + 2, (b), (b) + 2, (b) + 3
static const uint16_t cube_idx[12 * 3] = {FACE(0), FACE(4), FACE(8), FACE(12), FACE(16), FACE(20)};
#undef FACE
#define FACE_UV 0, 4095, 4095, 4095, 4095, 0, 0, 0
static const int16_t cube_uv[24 * 2] = {FACE_UV, FACE_UV, FACE_UV, FACE_UV, FACE_UV, FACE_UV};
#undef FACE_UV

const char *const bench_tex_names[BENCH_TEX_VARIANTS] = {
    "tex-plain", "tex-nearest", "tex-nearest-zline", "tex-subdiv", "tex-bilinear", "tex-lit-fog"};

zs_config bench_tex_config(void)
{
    /* fits the microbit's RAM; no frame drops anything (checked) */
    zs_config c = zs_config_default(BENCH_W, BENCH_H, 24, 48, 32);
    c.flags = ZS_CFG_TEXTURE;
    return c;
}

/* T(0, -0.25, -3.5) * Rx(20) * Ry(30), out of line so its matrices are off
 * the caller's frame. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void bench_tex_model(zs_mat34 *model)
{
    zs_mat34 t = zs_mat34_translate(0, -ZS_FX(1) / 4, -ZS_FX_RATIO(7, 2));
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(30)), rx = zs_mat34_rotate_x(ZS_FX(20));
    zs_mat34 rxy = zs_mat34_mul(&rx, &ry);
    *model = zs_mat34_mul(&t, &rxy);
}

/* The textured scene's frame: texture variant k, in mode, with A-buffer mode
 * aa (ZS_AA_TRANSPARENT: the cube at opacity 160). */
static zs_status tex_scene_frame(zs_renderer *r, const zs_camera *cam, int k, zs_visibility mode,
                                 zs_aa_mode aa, uint32_t *sum, uint32_t *covered);

zs_status bench_tex_frame(zs_renderer *r, const zs_camera *cam, int k, uint32_t *sum,
                          uint32_t *covered)
{
    return tex_scene_frame(r, cam, k, k == 2 ? ZS_MODE_ZLINE : ZS_MODE_SPAN, ZS_AA_OFF, sum,
                           covered);
}

const char *const bench_extra_names[BENCH_EXTRA_VARIANTS] = {"warnock", "aa-edges",
                                                              "aa-transparent"};

zs_config bench_extra_config(void)
{
    /* the scene's 14 triangles and 28 vertices, with room for the sifive_e
     * image's RAM (RV32, 16 KB); no frame drops anything (checked) */
    zs_config c = zs_config_default(BENCH_W, BENCH_H, 16, 32, 24);
    c.flags = ZS_CFG_ABUFFER;
    return c;
}

zs_status bench_extra_frame(zs_renderer *r, const zs_camera *cam, int k, uint32_t *sum)
{
    return tex_scene_frame(r, cam, 0, k == 0 ? ZS_MODE_WARNOCK : ZS_MODE_SPAN,
                           k == 0 ? ZS_AA_OFF : k == 1 ? ZS_AA_EDGES : ZS_AA_TRANSPARENT, sum, 0);
}

static zs_status tex_scene_frame(zs_renderer *r, const zs_camera *cam, int k, zs_visibility mode,
                                 zs_aa_mode aa, uint32_t *sum, uint32_t *covered)
{
    static uint8_t line[BENCH_W * 2];
    static const zs_texture *const texs[BENCH_TEX_VARIANTS] = {
        0, &tex_rgb, &tex_rgb, &tex_rgb_sub, &tex_rgb_bil, &tex_pal_lit};
    /* static, not on the stack: the microbit's 1536 B stack also holds the
     * clipper's frames under zs_draw */
    static zs_mesh ground, cube;
    static zs_mat34 model;
    static zs_shade_params sp;
    zs_status st = zs_frame_begin(r, cam, mode);
    int y;
    if (st != ZS_OK)
        return st;
    bench_tex_model(&model);
    sp = zs_shade_default();
    memset(&ground, 0, sizeof ground);
    ground.positions = ground_pos;
    ground.indices = ground_idx;
    ground.scale = ZS_FX(1) / 256;
    ground.vertex_count = 4;
    ground.triangle_count = 2;
    ground.color = k == 0 ? ZS_RGB(90, 160, 60) : 0xFFFFFF;
    ground.vertex_normals = ground_vn;
    cube = ground;
    cube.positions = cube_pos;
    cube.indices = cube_idx;
    cube.vertex_count = 24;
    cube.triangle_count = 12;
    cube.color = k == 0 ? ZS_RGB(200, 120, 40) : 0xFFFFFF;
    cube.vertex_normals = cube_vn;
    if (texs[k]) {
        ground.uvs = ground_uv;
        ground.texture = texs[k];
        cube.uvs = cube_uv;
        cube.texture = texs[k];
    }
    sp.background = ZS_RGB(20, 30, 60);
    if (k >= 4) { /* lit: flat (k 4), Gouraud with vertex colours and fog (k 5) */
        sp.ambient = ZS_FX_RATIO(3, 10);
        sp.light_count = 1;
        sp.lights[0].direction = zs_vec3_make(ZS_FX(-1), ZS_FX(2), ZS_FX(2));
        sp.lights[0].intensity = ZS_FX_RATIO(8, 10);
    }
    if (k == 5) {
        sp.shading = ZS_SHADE_GOURAUD;
        ground.vertex_colors = ground_vc;
        sp.fog.enabled = 1;
        sp.fog.color = ZS_RGB(20, 30, 60);
        sp.fog.start = ZS_FX(4);
        sp.fog.end = ZS_FX(30);
    }
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK ||
        (aa != ZS_AA_OFF && (st = zs_frame_antialias(r, aa)) != ZS_OK) ||
        (st = zs_draw(r, &ground, 0)) != ZS_OK ||
        (aa == ZS_AA_TRANSPARENT && (st = zs_draw_opacity(r, 160)) != ZS_OK) ||
        (st = zs_draw(r, &cube, &model)) != ZS_OK)
        return st;
    *sum = BENCH_FNV_BASIS;
    if (covered)
        *covered = 0;
    for (y = 0; st == ZS_OK && y < BENCH_H; y++) {
        st = zs_render_rows(r, y, 1, line, sizeof line);
        *sum = bench_fnv1a(*sum, line, sizeof line);
        if (covered) { /* the background in RGB565 big-endian */
            unsigned x, bg = ((20u >> 3) << 11) | ((30u >> 2) << 5) | (60u >> 3);
            for (x = 0; x < BENCH_W; x++)
                *covered += ((unsigned)line[2 * x] << 8 | line[2 * x + 1]) != bg;
        }
    }
    return st;
}
