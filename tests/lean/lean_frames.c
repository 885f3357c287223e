/* SPDX-License-Identifier: MIT */
/*
 * The lean configuration on the host (make check-lean, mk/lean.mk). Built
 * twice from the same source: on the core compiled -DZS_LEAN (lean_frames)
 * and on the full core (lean_frames_full).
 *
 * 1. Refusals: every feature ZS_LEAN leaves out, asked for, must give the
 *    documented code (zspan.h: ZS_NO_TEXTURE ...) and change nothing; the
 *    full build must accept the same calls (ZS_OK). Checked here, per build.
 * 2. Frames: what the lean build supports (flat and lit faces, span mode,
 *    RGB565 both byte orders, a background, near-plane clipping,
 *    interpenetrating boxes, ties) rendered after the refused calls; one
 *    line "F name checksum" each. The recipe compares the two builds'
 *    lines: they must be identical (the full build is the oracle, itself
 *    checked against the ray caster and the half-space reference by the
 *    core suites).
 * Exit status 0 when every refusal matched.
 */
#include <stdio.h>
#include <string.h>

#include "zspan/priority.h"
#include "zspan/zspan.h"

#define W 96
#define H 72

static uint8_t arena[ZS_ARENA_BYTES_CFG(W, H, 64, 96, 64, ZS_CFG_TEXTURE | ZS_CFG_PRIORITY) +
                     ZS_ABUFFER_BYTES(W, H, 64, 64)];
static int failures;

static void expect(const char *what, zs_status got, zs_status lean, zs_status full)
{
#ifdef ZS_LEAN
    zs_status want = lean;
    (void)full;
#else
    zs_status want = full;
    (void)lean;
#endif
    if (got != want) {
        printf("FAIL %s: status %d, expected %d\n", what, (int)got, (int)want);
        failures++;
    }
}

/* A box of half-size 1/4 units (units of 1/256): 8 corners, 12 faces, one colour each. */
static const int16_t box_pos[8 * 3] = {-64, -64, -64, 64, -64, -64, 64, 64, -64, -64, 64, -64,
                                       -64, -64, 64,  64, -64, 64,  64, 64, 64,  -64, 64, 64};
static const uint16_t box_idx[12 * 3] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         3, 6, 2, 3, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
static const zs_color box_col[12] = {0xFF0000, 0xE01010, 0x00FF00, 0x10E010, 0x0000FF, 0x1010E0,
                                     0xFFFF00, 0xE0E010, 0xFF00FF, 0xE010E0, 0x00FFFF, 0x10E0E0};
/* A ground quad from 0.5 behind to 8 units ahead of the eye: clipped at the near plane. */
static const int16_t ground_pos[4 * 3] = {-512, -128, 128, 512, -128, 128, 512, -128, -2048,
                                          -512, -128, -2048};
static const uint16_t ground_idx[2 * 3] = {0, 1, 2, 0, 2, 3};
static const int16_t ground_uv[4 * 2] = {0, 0, 4096, 0, 4096, 4096, 0, 4096};
static const uint16_t texels[4] = {0xF800, 0x07E0, 0x001F, 0xFFFF};
static const zs_texture tex = {texels, 0, 2, 2, ZS_TEX_RGB565, 0};

static zs_mesh mesh_of(const int16_t *pos, const uint16_t *idx, uint16_t nv, uint16_t nt,
                       const zs_color *fc, zs_color color)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1) / 64; /* box: half-size 1; ground: 8 units wide */
    m.vertex_count = nv;
    m.triangle_count = nt;
    m.face_colors = fc;
    m.color = color;
    return m;
}

static zs_status camera(zs_camera *cam)
{
    zs_mat34 id = zs_mat34_identity();
    zs_status st;
    memset(cam, 0, sizeof *cam);
    st = zs_camera_set_view(cam, &id);
    return st != ZS_OK ? st : zs_camera_perspective(cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(100));
}

static zs_status init(zs_renderer *r, uint16_t flags)
{
    zs_config c = zs_config_default(W, H, 64, 96, 64);
    c.flags = flags;
    return zs_init(r, arena, sizeof arena, &c);
}

/* Every refused feature on renderer r (left usable). */
static void refusals(zs_renderer *r, const zs_camera *cam)
{
    static const zs_format fmts[] = {ZS_FMT_RGB666, ZS_FMT_GRAY8, ZS_FMT_RGB888, ZS_FMT_ID16};
    zs_shade_params sp;
    zs_mesh g = mesh_of(ground_pos, ground_idx, 4, 2, 0, 0x808080);
    unsigned k;
    expect("ZS_CFG_TEXTURE", init(r, ZS_CFG_TEXTURE), ZS_ERR_ARGUMENT, ZS_OK);
    expect("ZS_CFG_ABUFFER", init(r, ZS_CFG_ABUFFER), ZS_ERR_ARGUMENT, ZS_OK);
    expect("ZS_CFG_PRIORITY", init(r, ZS_CFG_PRIORITY), ZS_ERR_ARGUMENT, ZS_OK);
    expect("ZS_CFG_PRIORITY_ONLY", init(r, ZS_CFG_PRIORITY_ONLY), ZS_ERR_ARGUMENT, ZS_OK);
    expect("ZS_CFG_MONO", init(r, ZS_CFG_MONO), ZS_ERR_ARGUMENT, ZS_OK);
    expect("ZS_CFG_LINES", init(r, ZS_CFG_LINES), ZS_ERR_ARGUMENT, ZS_OK);
    /* the rest on a renderer with every flag this build takes */
    expect("init", init(r, (uint16_t)(ZS_CFG_BUILT & (ZS_CFG_TEXTURE | ZS_CFG_PRIORITY))),
           ZS_OK, ZS_OK);
    expect("ZS_MODE_ZLINE", zs_frame_begin(r, cam, ZS_MODE_ZLINE), ZS_ERR_MODE, ZS_OK);
    expect("ZS_MODE_WARNOCK", zs_frame_begin(r, cam, ZS_MODE_WARNOCK), ZS_ERR_MODE, ZS_OK);
    expect("ZS_MODE_PRIORITY", zs_frame_begin(r, cam, ZS_MODE_PRIORITY), ZS_ERR_MODE, ZS_OK);
    expect("zs_depth_sort", zs_depth_sort(r, ZS_SORT_DEPTH, 0), ZS_ERR_MODE, ZS_OK);
    expect("ZS_MODE_SPAN", zs_frame_begin(r, cam, ZS_MODE_SPAN), ZS_OK, ZS_OK);
    sp = zs_shade_default();
    sp.shading = ZS_SHADE_GOURAUD;
    expect("ZS_SHADE_GOURAUD", zs_frame_shading(r, &sp), ZS_ERR_MODE, ZS_OK);
    sp = zs_shade_default();
    sp.fog.enabled = 1;
    sp.fog.start = ZS_FX(1);
    sp.fog.end = ZS_FX(9);
    expect("fog", zs_frame_shading(r, &sp), ZS_ERR_MODE, ZS_OK);
    for (k = 0; k < sizeof fmts / sizeof fmts[0]; k++) {
        char what[32];
        sp = zs_shade_default();
        sp.format = fmts[k];
        snprintf(what, sizeof what, "format %d", (int)fmts[k]);
        expect(what, zs_frame_shading(r, &sp), ZS_ERR_FORMAT, ZS_OK);
    }
    sp = zs_shade_default();
    sp.format = ZS_FMT_MONO_PAGE; /* needs ZS_CFG_MONO in a full build too */
    expect("ZS_FMT_MONO_PAGE", zs_frame_shading(r, &sp), ZS_ERR_FORMAT, ZS_ERR_MODE);
    sp.format = ZS_FMT_GRAY4;
    expect("ZS_FMT_GRAY4", zs_frame_shading(r, &sp), ZS_ERR_FORMAT, ZS_ERR_MODE);
    sp = zs_shade_default();
    expect("shading", zs_frame_shading(r, &sp), ZS_OK, ZS_OK);
    expect("zs_frame_antialias", zs_frame_antialias(r, ZS_AA_EDGES), ZS_ERR_MODE, ZS_ERR_MODE);
    expect("zs_draw_opacity", zs_draw_opacity(r, 128), ZS_ERR_MODE, ZS_ERR_MODE);
#ifdef ZS_LEAN /* a full build needs a valid tree here (the priority suites test it) */
    {
        static const zs_bsp_node node = {0};
        zs_bsp bsp;
        memset(&bsp, 0, sizeof bsp);
        bsp.mesh = &g;
        bsp.nodes = &node;
        bsp.node_count = 1;
        expect("zs_draw_bsp", zs_draw_bsp(r, &bsp, 0), ZS_ERR_MODE, ZS_OK);
    }
#endif
    g.uvs = ground_uv;
    g.texture = &tex;
    expect("textured zs_draw", zs_draw(r, &g, 0), ZS_ERR_MODE, ZS_OK);
}

/* One frame of the supported features; prints its checksum. */
static void frame(zs_renderer *r, const zs_camera *cam, const char *name, int f, zs_format fmt,
                  int lit)
{
    static uint8_t row[W * 2];
    zs_shade_params sp = zs_shade_default();
    zs_mesh box = mesh_of(box_pos, box_idx, 8, 12, box_col, 0);
    zs_mesh g = mesh_of(ground_pos, ground_idx, 4, 2, 0, 0x5AA03C);
    zs_mat34 t = zs_mat34_translate(0, 0, -ZS_FX(4) - ZS_FX(f) / 4);
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(17 + 23 * f)), rx = zs_mat34_rotate_x(ZS_FX(11 * f));
    zs_mat34 rxy = zs_mat34_mul(&rx, &ry), m1 = zs_mat34_mul(&t, &rxy);
    zs_mat34 t2 = zs_mat34_translate(ZS_FX(1) / 2, ZS_FX(1) / 3, -ZS_FX(4) - ZS_FX(f) / 4);
    zs_mat34 m2 = zs_mat34_mul(&t2, &ry); /* a second box through the first */
    zs_status st;
    uint32_t h = 0x811C9DC5u;
    int y;
    size_t i;
    sp.format = fmt;
    sp.background = ZS_RGB(20, 30, 60);
    if (lit && !ZS_HAS_LIGHTING) { /* ZS_NO_LIGHTING: refused, and the frame not drawn */
        sp.ambient = ZS_FX_RATIO(3, 10);
        expect("lighting", zs_frame_begin(r, cam, ZS_MODE_SPAN) == ZS_OK
                               ? zs_frame_shading(r, &sp) : ZS_ERR_STATE, ZS_ERR_MODE, ZS_ERR_MODE);
        return;
    }
    if (lit) {
        sp.ambient = ZS_FX_RATIO(3, 10);
        sp.light_count = 1;
        sp.lights[0].direction = zs_vec3_make(ZS_FX(-1), ZS_FX(2), ZS_FX(2));
        sp.lights[0].intensity = ZS_FX_RATIO(8, 10);
    }
    if ((st = zs_frame_begin(r, cam, ZS_MODE_SPAN)) != ZS_OK ||
        (st = zs_frame_shading(r, &sp)) != ZS_OK || (st = zs_draw(r, &g, 0)) != ZS_OK ||
        (st = zs_draw(r, &box, &m1)) != ZS_OK || (st = zs_draw(r, &box, &m2)) != ZS_OK ||
        (st = zs_draw(r, &box, &m2)) != ZS_OK) { /* the same box twice: exact ties */
        printf("FAIL %s %d: status %d\n", name, f, (int)st);
        failures++;
        return;
    }
    for (y = 0; y < H; y++) {
        if ((st = zs_render_rows(r, y, 1, row, sizeof row)) != ZS_OK) {
            printf("FAIL %s %d row %d: status %d\n", name, f, y, (int)st);
            failures++;
            return;
        }
        for (i = 0; i < sizeof row; i++)
            h = (h ^ row[i]) * 0x01000193u;
    }
    printf("F %s %d %08lx records=%lu clipped=%lu\n", name, f, (unsigned long)h,
           (unsigned long)r->stats.records, (unsigned long)r->stats.tris_clipped);
}

int main(void)
{
    static zs_renderer r;
    zs_camera cam;
    int f;
    if (camera(&cam) != ZS_OK)
        return 2;
    refusals(&r, &cam);
    for (f = 0; f < 6; f++) {
        frame(&r, &cam, "flat-be", f, ZS_FMT_RGB565_BE, 0);
        frame(&r, &cam, "lit-native", f, ZS_FMT_RGB565, 1);
    }
    /* a flat-only renderer without the z-buffer line's RAM: the lean RAM layout */
    if (init(&r, ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE) != ZS_OK)
        return 2;
    for (f = 0; f < 6; f++)
        frame(&r, &cam, "flat-nozline", f, ZS_FMT_RGB565_BE, f & 1);
    printf("%s: %d refusals wrong\n",
#ifdef ZS_LEAN
           "lean",
#else
           "full",
#endif
           failures);
    return failures ? 1 : 0;
}
