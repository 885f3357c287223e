/* SPDX-License-Identifier: MIT */
/*
 * test_modes: the spanning-scanline mode and the scanline z-buffer mode must
 * produce byte-identical output, for every pixel format, flat and Gouraud,
 * with and without lights and fog, whatever the band size (1, 3, 8, the whole
 * frame, through zs_render_rows and zs_render_frame, and when the first rows
 * are skipped), on random scenes with penetrations, abutting pairs sharing
 * edges, coplanar duplicates, near-plane crossings and large tilted planes.
 *
 * Depth-range decisions (the span walk orders triangles whose depth ranges
 * are disjoint without evaluating planes) are covered by the layered scenes
 * and checked to happen by test_depth_ranges.
 *
 * Pixel packing is checked separately against formulas written here: one big
 * flat triangle of a known colour, ambient 1.0 and no lights, every format.
 */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define W 80
#define H 60
#define NSCENES 600
#define SEED 0x30DE5AAA00000005ull

static unsigned long g_windows, g_pixel_decisions, g_warnock;
static unsigned long g_id_covered, g_id_px, g_renders, g_scenes, g_tris, g_bytes, g_crossings, g_packed;

static void look(zt_rng *g, int k, zs_shade_params *sp)
{
    *sp = zs_shade_default();
    sp->format = (zs_format)(k % ZS_FMT_COUNT);
    sp->shading = ((k / ZS_FMT_COUNT) % 2) ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    sp->background = zt_u32(g) & 0xFFFFFFu;
    int l = (k / (2 * ZS_FMT_COUNT)) % 4;
    if (l == 1 || l == 3) {
        sp->ambient = (zs_fixed)zt_range(g, 0, ZS_FX(1) / 2);
        sp->light_count = (uint8_t)(1 + zt_below(g, 2));
        for (int i = 0; i < sp->light_count; i++) {
            sp->lights[i].direction =
                zs_vec3_make((zs_fixed)zt_range(g, -ZS_FX(2), ZS_FX(2)),
                             (zs_fixed)zt_range(g, -ZS_FX(2), ZS_FX(2)), ZS_FX(1));
            sp->lights[i].intensity = (zs_fixed)zt_range(g, ZS_FX(1) / 4, ZS_FX(3) / 2);
        }
    }
    if (l == 2 || l == 3) {
        sp->fog.enabled = 1;
        sp->fog.color = zt_u32(g) & 0xFFFFFFu;
        sp->fog.start = (zs_fixed)zt_range(g, ZS_FX(1), ZS_FX(5));
        sp->fog.end = sp->fog.start + (zs_fixed)zt_range(g, ZS_FX(1), ZS_FX(20));
    }
}

/* render one frame of the scene; returns status */
static zs_status frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                       const zs_shade_params *sp, const zs_mesh *m, uint8_t *img, int band,
                       int via_frame, int skip)
{
    zs_status st = zs_frame_begin(&c->r, cam, mode);
    if (st != ZS_OK) return st;
    st = zs_frame_shading(&c->r, sp);
    if (st != ZS_OK) return st;
    st = zs_draw(&c->r, m, NULL);
    if (st != ZS_OK) return st;
    g_renders++;
    size_t stride = (size_t)W * zs_format_bytes(sp->format);
    if (skip) {
        /* rows 0..skip-1 are skipped over, not rendered */
        return zs_render_rows(&c->r, skip, H - skip, img + (size_t)skip * stride, stride);
    }
    if (via_frame) return zt_render_frame_all(&c->r, img, W, H, sp->format, band);
    return zt_render_rows_all(&c->r, img, W, H, sp->format, band);
}

static void test_span_equals_zline(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 400, 1200, 400);
    zs_camera cam;
    const double near_d = 0.5;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    size_t cap = (size_t)W * H * 3;
    uint8_t *ref = malloc(cap), *img = malloc(cap);
    for (int k = 0; k < NSCENES; k++) {
        zt_scene_reset(&sc);
        int ntri = (int)zt_range(&g, 10, 45);
        unsigned flags = ZT_SC_ALL;
        if (k % 5 == 1) flags = ZT_SC_PLAIN | ZT_SC_DUP;
        if (k % 5 == 2) flags = ZT_SC_SHARED | ZT_SC_FLAT | ZT_SC_DUP;
        if (k % 5 == 3) flags = ZT_SC_NEAR | ZT_SC_PLAIN;
        if (k % 5 == 4) flags = ZT_SC_LAYERS | ZT_SC_PLAIN;
        zt_scene_random(&g, &sc, ntri, flags, near_d);
        int colours = k % 3; /* face colours, vertex colours, mesh colour */
        zs_mesh m = zt_scene_mesh(&sc, colours == 0, colours == 1);
        m.color = zt_u32(&g) & 0xFFFFFFu;
        zs_shade_params sp;
        look(&g, k, &sp);
        size_t n = (size_t)W * H * zs_format_bytes(sp.format);
        size_t stride = (size_t)W * zs_format_bytes(sp.format);

        memset(ref, 0x5A, cap);
        ZT_ST(frame(&c, &cam, ZS_MODE_ZLINE, &sp, &m, ref, H, 0, 0), ZS_OK);
        if (sp.format == ZS_FMT_ID16) {
            for (int i = 0; i < W * H; i++) g_id_covered += zt_id_at(ref, W, i % W, i / W) != 0;
            g_id_px += W * H;
        }
        static const int bands[] = {1, 3, 8, H};
        for (int v = 0; v < 8; v++) {
            zs_visibility mode = v < 5 ? ZS_MODE_SPAN : ZS_MODE_ZLINE;
            int band = v < 4 ? bands[v] : v == 4 ? 8 : v == 5 ? 1 : 3;
            int via = (v == 4 || v == 6);
            memset(img, 0xA5, cap);
            ZT_ST(frame(&c, &cam, mode, &sp, &m, img, band, via, 0), ZS_OK);
            if (mode == ZS_MODE_SPAN && v == 0) g_crossings += zs_frame_stats(&c.r)->crossings;
            long d = zt_first_diff(ref, img, n);
            if (d >= 0) {
                long px = d / (long)zs_format_bytes(sp.format);
                ZT_FAIL("scene %d (seed %llx): %s band %d%s differs from zline (whole frame) at "
                        "byte %ld = pixel (%ld,%ld): %02x vs %02x; format %d shading %d lights %d "
                        "fog %d",
                        k, (unsigned long long)SEED, mode ? "zline" : "span", band,
                        via ? " via zs_render_frame" : "", d, px % W, px / W, img[d], ref[d],
                        (int)sp.format, (int)sp.shading, sp.light_count, sp.fog.enabled);
            }
            g_bytes += n;
        }
        /* Warnock mode (area subdivision of each band), the third mode */
        for (int v = 0; v < 5; v++) {
            int band = v < 4 ? bands[v] : 8;
            memset(img, 0xA5, cap);
            ZT_ST(frame(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, img, band, v == 4, 0), ZS_OK);
            const zs_stats *st = zs_frame_stats(&c.r);
            g_windows += st->windows;
            g_pixel_decisions += st->pixel_decisions;
            ZT_CHECK(st->pixels_shaded == W * H, "scene %d: Warnock wrote %u pixels, not %d", k,
                     st->pixels_shaded, W * H);
            long d = zt_first_diff(ref, img, n);
            if (d >= 0) {
                long px = d / (long)zs_format_bytes(sp.format);
                ZT_FAIL("scene %d (seed %llx): warnock band %d%s differs from zline at byte %ld = "
                        "pixel (%ld,%ld): %02x vs %02x; format %d shading %d lights %d fog %d",
                        k, (unsigned long long)SEED, band, v == 4 ? " via zs_render_frame" : "",
                        d, px % W, px / W, img[d], ref[d], (int)sp.format, (int)sp.shading,
                        sp.light_count, sp.fog.enabled);
            }
            g_bytes += n;
            g_warnock += n;
        }
        /* skipping the first rows renders the rest identically */
        static const zs_visibility skip_modes[] = {ZS_MODE_SPAN, ZS_MODE_ZLINE, ZS_MODE_WARNOCK};
        for (int mi = 0; mi < 3; mi++) {
            zs_visibility mode = skip_modes[mi];
            int skip = 1 + (int)zt_below(&g, H - 1);
            memset(img, 0xA5, cap);
            ZT_ST(frame(&c, &cam, mode, &sp, &m, img, 0, 0, skip), ZS_OK);
            long d = zt_first_diff(ref + (size_t)skip * stride, img + (size_t)skip * stride,
                                   n - (size_t)skip * stride);
            ZT_CHECK(d < 0, "scene %d: %s after skipping %d rows differs at byte %ld", k,
                     mode == ZS_MODE_WARNOCK ? "warnock" : mode ? "zline" : "span", skip, d);
            for (size_t i = 0; i < (size_t)skip * stride; i++)
                ZT_CHECK(img[i] == 0xA5, "scene %d: skipped rows were written", k);
        }
        g_scenes++;
        g_tris += sc.nt;
    }
    free(ref);
    free(img);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* Depth ranges: layers far apart in depth are ordered by their ranges alone.
 * Three screen-covering quads at eye depths 8, 4 and 2 (submitted far to
 * near): every pixel shows the nearest, span mode evaluates no plane, and
 * the image equals the z-buffer mode's. */
static void test_depth_ranges(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 16, 16, 32);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    const double depth[3] = {8.0, 4.0, 2.0};
    for (int l = 0; l < 3; l++) {
        int v[4];
        v[0] = zt_scene_vertex_px(&sc, -10, -10, depth[l], 0);
        v[1] = zt_scene_vertex_px(&sc, W + 10, -10, depth[l], 0);
        v[2] = zt_scene_vertex_px(&sc, W + 10, H + 10, depth[l], 0);
        v[3] = zt_scene_vertex_px(&sc, -10, H + 10, depth[l], 0);
        zt_scene_tri_front(&sc, v[0], v[1], v[2], 0x102030u * (unsigned)(l + 1));
        zt_scene_tri_front(&sc, v[0], v[2], v[3], 0x302010u * (unsigned)(l + 1));
    }
    zs_mesh m = zt_scene_mesh(&sc, 1, 0);
    static uint8_t span[W * H * 2], zline[W * H * 2];
    ZT_ST(zt_frame(&c, &cam, ZS_MODE_ZLINE, NULL, &m, 1, NULL, zline, H), ZS_OK);
    ZT_ST(zt_frame(&c, &cam, ZS_MODE_SPAN, NULL, &m, 1, NULL, span, H), ZS_OK);
    const zs_stats *st = zs_frame_stats(&c.r);
    ZT_CHECK(st->tris_drawn == 6, "%u of 6 triangles drawn", st->tris_drawn);
    ZT_CHECK(st->depth_evals == 0, "span mode evaluated %u planes for disjoint layers",
             st->depth_evals);
    ZT_CHECK(zt_first_diff(span, zline, sizeof span) < 0, "span differs from zline");
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint16_t id = zt_id_at(span, W, x, y);
            ZT_CHECK(id == 5 || id == 6, "pixel (%d,%d) shows triangle %u, not the nearest "
                     "layer (5 or 6)", x, y, id);
        }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* ---- pixel packing ---- */

static void expect_bytes(zs_format f, zs_color col, uint16_t id, uint8_t out[3])
{
    unsigned r = (col >> 16) & 255, g = (col >> 8) & 255, b = col & 255;
    uint16_t v = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    memset(out, 0, 3);
    switch (f) {
    case ZS_FMT_RGB565_BE: out[0] = (uint8_t)(v >> 8); out[1] = (uint8_t)v; break;
    case ZS_FMT_RGB565: memcpy(out, &v, 2); break;
    case ZS_FMT_RGB666: out[0] = (uint8_t)(r & 0xFC); out[1] = (uint8_t)(g & 0xFC); out[2] = (uint8_t)(b & 0xFC); break;
    case ZS_FMT_GRAY8: out[0] = (uint8_t)((77 * r + 150 * g + 29 * b) / 256); break;
    case ZS_FMT_RGB888: out[0] = (uint8_t)r; out[1] = (uint8_t)g; out[2] = (uint8_t)b; break;
    case ZS_FMT_ID16: memcpy(out, &id, 2); break;
    default: break;
    }
}

static void test_packing(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 8, 16, 8);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 8 * H);
    static const zs_color cols[] = {0x123456, 0xFFFFFF, 0x000000, 0xF81F07, 0x80FF01,
                                    0x07E0F8, 0xABCDEF, 0x010203, 0xFEFDFC};
    static const zs_color bgs[] = {0x000000, 0xFFFFFF, 0x4080C0, 0x7F7F7F};
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xBEEF);
    uint8_t img[W * H * 3];
    for (size_t ci = 0; ci < sizeof cols / sizeof cols[0]; ci++) {
        zs_color col = cols[ci], bg = bgs[ci % 4];
        /* a big triangle on the depth-1 plane covering the middle of the screen */
        zt_scene_reset(&sc);
        int a = zt_scene_vertex_q(&sc, 16 * 5, 16 * 5, col);
        int b = zt_scene_vertex_q(&sc, 16 * (W - 5), 16 * 8, col);
        int d = zt_scene_vertex_q(&sc, 16 * 20, 16 * (H - 3), col);
        zt_scene_tri_front(&sc, a, b, d, col);
        for (int src = 0; src < 4; src++) {
            /* colour source: face colour, mesh colour, equal vertex colours (flat:
             * averaged; Gouraud: interpolated) */
            zs_mesh m = zt_scene_mesh(&sc, src == 0, src >= 2);
            m.color = src == 1 ? col : 0x0F0F0F;
            for (int f = 0; f < ZS_FMT_COUNT; f++)
                for (int mode = 0; mode < 2; mode++) {
                    zs_shade_params sp = zs_shade_default();
                    sp.format = (zs_format)f;
                    sp.background = bg;
                    sp.shading = src == 3 ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
                    memset(img, 0x77, sizeof img);
                    ZT_ST(zs_frame_begin(&c.r, &cam, (zs_visibility)mode), ZS_OK);
                    ZT_ST(zs_frame_shading(&c.r, &sp), ZS_OK);
                    ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
                    ZT_ST(zt_render_rows_all(&c.r, img, W, H, sp.format, 1 + (int)zt_below(&g, 9)),
                          ZS_OK);
                    unsigned bpp = zs_format_bytes(sp.format);
                    uint8_t in[3], out[3];
                    expect_bytes(sp.format, col, 1, in);
                    expect_bytes(sp.format, bg, 0, out);
                    /* pixel (20, 20) is inside, (W-2, H-2) and (0, 0) outside */
                    static const int probe[][3] = {{20, 20, 1}, {30, 15, 1}, {0, 0, 0},
                                                   {W - 2, H - 2, 0}, {W - 1, 0, 0}};
                    for (int p = 0; p < 5; p++) {
                        const uint8_t *px = img + ((size_t)probe[p][1] * W + (size_t)probe[p][0]) * bpp;
                        const uint8_t *want = probe[p][2] ? in : out;
                        ZT_CHECK(memcmp(px, want, bpp) == 0,
                                 "format %d, %s, colour %06x (source %d), background %06x: pixel "
                                 "(%d,%d) = %02x %02x %02x, expected %02x %02x %02x (%u bytes)",
                                 f, mode ? "zline" : "span", (unsigned)col, src, (unsigned)bg,
                                 probe[p][0], probe[p][1], px[0], bpp > 1 ? px[1] : 0,
                                 bpp > 2 ? px[2] : 0, want[0], bpp > 1 ? want[1] : 0,
                                 bpp > 2 ? want[2] : 0, bpp);
                        g_packed++;
                    }
                }
        }
    }
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_packing),
        cmocka_unit_test(test_span_equals_zline),
        cmocka_unit_test(test_depth_ranges),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_modes: seed %llx, %lu scenes (%lu triangles) %dx%d, %lu renders, %lu bytes "
           "compared span vs zline over 6 formats x flat/Gouraud x lights/fog x bands 1/3/8/%d, "
           "%lu span-mode crossings, %lu of %lu pixels covered in the ID16 scenes; %lu packed pixels "
           "checked; Warnock mode: %lu bytes equal to zline, %lu windows visited, %lu pixel "
           "decisions; %d failed\n",
           (unsigned long long)SEED, g_scenes, g_tris, W, H, g_renders, g_bytes, H, g_crossings,
           g_id_covered, g_id_px, g_packed, g_warnock, g_windows, g_pixel_decisions, rc);
    fflush(stdout);
    return rc;
}
