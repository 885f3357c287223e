/* SPDX-License-Identifier: MIT */
/*
 * test_abuffer: the A-buffer (ZS_CFG_ABUFFER, zs_frame_antialias) against an
 * independent supersampled reference.
 *
 * The reference takes the hook's snapped records and, at each of the 4x4
 * sub-samples of every pixel ((16x + 2 + 4i, 16y + 2 + 4j) in 1/16 px),
 * finds the nearest record covering it by half-space edge functions with the
 * top-left rule and barycentric depth in double; exact duplicates go to the
 * one submitted first. The pixel is the box-filtered mean of its samples'
 * colours (flat face colours, or the vertex colours interpolated in double
 * at each sample). The renderer must agree within 1 LSB per channel on at
 * least 99.5% of the pixels and within 8 everywhere, on random scenes with
 * penetrations, slivers, shared edges, duplicates, near-plane clipping and
 * large planes. Samples whose nearest and runner-up differ in depth by less
 * than 2^-20 may go either way: their pixels are left out (and counted;
 * under 0.5%).
 *
 * Also: transparency (ZS_AA_TRANSPARENT) against a ray caster that blends
 * every hit in depth order, per sample and at pixel centres; a
 * jittered one-colour mesh tiling the screen renders as one flat colour
 * (no seams); AA off renders byte for byte as a renderer without the
 * A-buffer, in both modes; the z-buffer mode refuses AA; every byte format
 * and the 1-bit formats; pool accounting.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 48
#define NSCENES 160
#define TOL (1.0 / 1048576.0)
#define SEED 0xAB0FFE7000000017ull

/* What the scene tests start from: the random stream of seed, a renderer
 * with the suite's pools and flags, the standard camera and an empty scene
 * of unit_div position units per world unit. */
static void scene_setup(zt_rng *g, uint64_t seed, zt_ctx *c, uint16_t flags, zs_camera *cam,
                        zt_scene *sc, int unit_div)
{
    zt_rng_seed(g, seed);
    zt_ctx_init_flags(c, W, H, 800, 2400, 600, flags);
    zt_camera_std(cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene_init(sc, W, H, unit_div);
}

/* ---------------- the reference ---------------- */

/* Is the point (X, Y) (1/16 px) inside by the top-left rule? */
static int covers_pt(const int32_t xy[6], int64_t X, int64_t Y)
{
    int64_t area = zt_area2(xy);
    if (area == 0) return 0;
    int64_t s = area > 0 ? 1 : -1;
    for (int k = 0; k < 3; k++) {
        int64_t ax = xy[2 * k], ay = xy[2 * k + 1];
        int64_t bx = xy[(2 * k + 2) % 6], by = xy[(2 * k + 3) % 6];
        int64_t dx = bx - ax, dy = by - ay;
        int64_t e = (dx * (Y - ay) - dy * (X - ax)) * s;
        if (e < 0) return 0;
        if (e == 0) {
            int64_t nx = -dy * s, ny = dx * s;
            if (!(nx > 0 || (nx == 0 && ny > 0))) return 0;
        }
    }
    return 1;
}

/* Barycentric weights of the record's vertices at (X, Y). */
static void bary(const int32_t xy[6], double X, double Y, double l[3])
{
    double x0 = xy[0], y0 = xy[1], x1 = xy[2], y1 = xy[3], x2 = xy[4], y2 = xy[5];
    double a = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    l[1] = ((X - x0) * (y2 - y0) - (x2 - x0) * (Y - y0)) / a;
    l[2] = ((x1 - x0) * (Y - y0) - (X - x0) * (y1 - y0)) / a;
    l[0] = 1.0 - l[1] - l[2];
}

/* Depth at (X, Y), from the vertices in a canonical order (by y, then x) so
 * that copies of a triangle in any vertex order tie exactly (the earlier
 * record wins, as in the renderer). */
static double depth_pt(const zt_rec *t, double X, double Y)
{
    int o[3] = {0, 1, 2};
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++) {
            int pa = o[a], pb = o[b];
            if (t->xy[2 * pb + 1] < t->xy[2 * pa + 1] ||
                (t->xy[2 * pb + 1] == t->xy[2 * pa + 1] && t->xy[2 * pb] < t->xy[2 * pa])) {
                o[a] = pb;
                o[b] = pa;
            }
        }
    int32_t xy[6];
    double l[3];
    for (int k = 0; k < 3; k++) {
        xy[2 * k] = t->xy[2 * o[k]];
        xy[2 * k + 1] = t->xy[2 * o[k] + 1];
    }
    bary(xy, X, Y, l);
    return (l[0] * t->z[o[0]] + l[1] * t->z[o[1]] + l[2] * t->z[o[2]]) / 1073741824.0;
}

/* Colour of record i at (X, Y): per record three vertex colours (equal for
 * flat), interpolated. */
typedef struct ref_colors {
    double c[3][3]; /* vertex k, channel */
    double alpha;   /* 0..1 */
} ref_colors;

static void color_pt(const zt_rec *t, const ref_colors *rc, double X, double Y, double out[3])
{
    double l[3];
    bary(t->xy, X, Y, l);
    for (int k = 0; k < 3; k++) {
        double v = l[0] * rc->c[0][k] + l[1] * rc->c[1][k] + l[2] * rc->c[2][k];
        out[k] = v < 0 ? 0 : v > 255 ? 255 : v;
    }
}

typedef struct hit {
    double z;
    size_t rec;
} hit;

static int hit_cmp(const void *a, const void *b)
{
    const hit *p = a, *q = b;
    if (p->z != q->z) return p->z < q->z ? -1 : 1;
    return p->rec < q->rec ? -1 : p->rec > q->rec;
}

/* Colour at point (X, Y): nearest opaque hit, then the transparent ones in
 * front of it blended far to near. *tie: a near tie decided the point. */
static uint64_t shade_pt(const zt_recs *rs, const ref_colors *rc, double X, double Y, int64_t iX,
                         int64_t iY, const double bg[3], double out[3], int *tie)
{
    hit hits[256];
    int n = 0;
    for (size_t i = 0; i < rs->n && n < 256; i++) {
        if (rc[i].alpha <= 0.0 || !covers_pt(rs->v[i].xy, iX, iY)) continue;
        hits[n].z = depth_pt(&rs->v[i], X, Y);
        hits[n].rec = i;
        n++;
    }
    qsort(hits, (size_t)n, sizeof *hits, hit_cmp);
    int op = -1;
    for (int k = 0; k < n; k++)
        if (rc[hits[k].rec].alpha >= 1.0) {
            op = k;
            break;
        }
    /* near ties among the hits that matter (up to the opaque one and the next) */
    int last = op < 0 ? n - 1 : (op + 1 < n ? op + 1 : op);
    for (int k = 0; k < last; k++)
        if (hits[k + 1].z - hits[k].z < TOL &&
            !zt_same_vertex_set(&rs->v[hits[k].rec], &rs->v[hits[k + 1].rec]))
            *tie = 1;
    double c[3] = {bg[0], bg[1], bg[2]};
    if (op >= 0) color_pt(&rs->v[hits[op].rec], &rc[hits[op].rec], X, Y, c);
    for (int k = (op >= 0 ? op : n) - 1; k >= 0; k--) {
        double t[3], a = rc[hits[k].rec].alpha;
        color_pt(&rs->v[hits[k].rec], &rc[hits[k].rec], X, Y, t);
        for (int ch = 0; ch < 3; ch++) c[ch] += (t[ch] - c[ch]) * a;
    }
    for (int ch = 0; ch < 3; ch++) out[ch] = c[ch];
    /* which surfaces made the colour, as a signature */
    uint64_t sig = 1469598103934665603ull;
    for (int k = 0; k <= (op >= 0 ? op : n - 1); k++) sig = (sig ^ hits[k].rec) * 1099511628211ull;
    return sig;
}

/* Box-filtered 4x4 mean at pixel (x, y); centre: the colour at the centre. */
static void ref_pixel(const zt_recs *rs, const ref_colors *rc, int x, int y, const double bg[3],
                      double mean[3], double centre[3], int *tie, int *uniform)
{
    mean[0] = mean[1] = mean[2] = 0;
    int dummy = 0;
    uint64_t sig0 = shade_pt(rs, rc, 16.0 * x + 8, 16.0 * y + 8, 16 * x + 8, 16 * y + 8, bg,
                             centre, &dummy);
    *uniform = 1;
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            int64_t X = 16 * x + 2 + 4 * i, Y = 16 * y + 2 + 4 * j;
            double c[3];
            if (shade_pt(rs, rc, (double)X, (double)Y, X, Y, bg, c, tie) != sig0) *uniform = 0;
            for (int k = 0; k < 3; k++) mean[k] += c[k] / 16.0;
        }
}

/* ---------------- scenes ---------------- */

typedef struct aa_stats {
    unsigned long px, within1, excluded, max_err, resolved, frags, scenes;
    unsigned long uni_px, uni_bad, uni_max, max_frags, skipped;
} aa_stats;

/* Renders the scene with AA (mode), compares with the reference. alpha:
 * per draw opacity (one draw per part of the scene when given). */
static void check_scene(zt_ctx *c, const zs_camera *cam, zt_scene *sc, int gouraud,
                        zs_aa_mode aa, int nparts, const uint8_t *alpha, int scene, aa_stats *as)
{
    static uint8_t img[W * H * 3];
    zt_recs recs = {0};
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_RGB888;
    sp.shading = gouraud ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
    sp.background = ZS_RGB(20, 40, 60);
    zs_set_setup_hook(&c->r, zt_recs_hook, &recs);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_frame_antialias(&c->r, aa), ZS_OK);
    /* the scene in nparts draws of consecutive triangles; record tags map to
     * scene triangles one to one (no clipping in Gouraud scenes) */
    size_t per = (sc->nt + (size_t)nparts - 1) / (size_t)nparts;
    for (int p = 0; p < nparts; p++) {
        zs_mesh m = zt_scene_mesh(sc, 1, gouraud);
        size_t t0 = (size_t)p * per, t1 = t0 + per > sc->nt ? sc->nt : t0 + per;
        if (t0 >= t1) break;
        m.indices = sc->idx + 3 * t0;
        m.face_colors = sc->fcol + t0;
        m.triangle_count = (uint16_t)(t1 - t0);
        if (alpha) ZT_ST(zs_draw_opacity(&c->r, alpha[p]), ZS_OK);
        ZT_ST(zs_draw(&c->r, &m, NULL), ZS_OK);
    }
    memset(img, 0xAB, sizeof img);
    ZT_ST(zt_render_rows_all(&c->r, img, W, H, ZS_FMT_RGB888, 1 + scene % 7), ZS_OK);
    const zs_stats *st = zs_frame_stats(&c->r);
    if (st->aa_max_fragments > as->max_frags) as->max_frags = st->aa_max_fragments;
    if (gouraud && st->tris_clipped) { /* clipped pieces: vertex colours unknown here */
        as->skipped++;
        zt_recs_free(&recs);
        zs_set_setup_hook(&c->r, NULL, NULL);
        return;
    }
    ZT_CHECK(st->aa_skipped == 0 && st->tris_dropped == 0 &&
                 st->records_skipped == 0,
             "scene %d: pools too small for the test (%u %u %u %u)", scene, st->aa_overflow,
             st->aa_skipped, st->tris_dropped, st->records_skipped);
    ZT_CHECK(st->records == recs.n, "scene %d: records %u, hook %zu", scene, st->records, recs.n);
    as->resolved += st->aa_pixels;
    as->frags += st->aa_fragments;
    as->scenes++;
    /* colours per record: the tag is the scene triangle + 1 (one frame) */
    ref_colors *rc = calloc(recs.n ? recs.n : 1, sizeof *rc);
    for (size_t i = 0; i < recs.n; i++) {
        size_t t = (size_t)recs.v[i].tag - 1;
        int part = (int)(t / per);
        rc[i].alpha = alpha ? alpha[part] / 255.0 : 1.0;
        for (int k = 0; k < 3; k++) {
            zs_color col = sc->fcol[t];
            if (gouraud) {
                /* the record's vertex k is the scene vertex at that position */
                col = sc->vcol[sc->idx[3 * t + (size_t)k]];
            }
            rc[i].c[k][0] = (col >> 16) & 255;
            rc[i].c[k][1] = (col >> 8) & 255;
            rc[i].c[k][2] = col & 255;
        }
    }
    double bg[3] = {20, 40, 60};
    int bad_shown = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double mean[3], centre[3];
            int tie = 0, uniform = 1;
            ref_pixel(&recs, rc, x, y, bg, mean, centre, &tie, &uniform);
            as->px++;
            if (tie) {
                as->excluded++;
                continue;
            }
            double e = 0, ec = 0;
            for (int k = 0; k < 3; k++) {
                double d = fabs((double)img[3 * (y * W + x) + k] - mean[k]);
                double dc = fabs((double)img[3 * (y * W + x) + k] - centre[k]);
                e = d > e ? d : e;
                ec = dc > ec ? dc : ec;
            }
            if (e <= 1.0) as->within1++;
            unsigned long ei = (unsigned long)ceil(e - 1e-9);
            if (ei > as->max_err) as->max_err = ei;
            if (uniform) { /* every sample sees the same: the ray cast at the centre */
                as->uni_px++;
                unsigned long ci = (unsigned long)ceil(ec - 1e-9);
                if (ci > as->uni_max) as->uni_max = ci;
                if (ec > 1.0) as->uni_bad++;
            }
            if (e > 8.0 && bad_shown++ < 3)
                print_error("scene %d pixel (%d,%d): got %u %u %u, reference %.2f %.2f %.2f "
                            "(centre %.1f %.1f %.1f)\n",
                            scene, x, y, img[3 * (y * W + x)], img[3 * (y * W + x) + 1],
                            img[3 * (y * W + x) + 2], mean[0], mean[1], mean[2], centre[0],
                            centre[1], centre[2]);
            if (e > 8.0 && bad_shown <= 3 && getenv("AA_DEBUG"))
                for (size_t i = 0; i < recs.n; i++) {
                    int cnt = 0;
                    for (int j = 0; j < 16; j++)
                        cnt += covers_pt(recs.v[i].xy, 16 * x + 2 + 4 * (j & 3), 16 * y + 2 + 4 * (j >> 2));
                    if (!cnt && !zt_covers(recs.v[i].xy, x, y)) continue;
                    print_error("  rec %zu tag %u samples %d centre %d z %.9f xy %d %d %d %d %d %d col %06x\n", i,
                                recs.v[i].tag, cnt, zt_covers(recs.v[i].xy, x, y),
                                depth_pt(&recs.v[i], 16.0 * x + 8, 16.0 * y + 8), recs.v[i].xy[0],
                                recs.v[i].xy[1], recs.v[i].xy[2], recs.v[i].xy[3], recs.v[i].xy[4],
                                recs.v[i].xy[5], sc->fcol[recs.v[i].tag - 1]);
                    print_error("     alpha %.3f\n", rc[i].alpha);
                }
        }
    free(rc);
    zt_recs_free(&recs);
    zs_set_setup_hook(&c->r, NULL, NULL);
}

static void report(const char *what, const aa_stats *as)
{
    printf("test_abuffer: %s: %lu scenes, %lu pixels, %.3f%% within 1 LSB, max error %lu LSB, "
           "%lu near-tie pixels left out (%.3f%%), %lu resolved (%.1f fragments each); "
           "uniform pixels vs centre ray cast: %lu, %lu beyond 1 LSB, max %lu; most fragments "
           "in a row %lu; %lu clipped scenes skipped\n",
           what, as->scenes, as->px,
           100.0 * (double)as->within1 / (double)(as->px - as->excluded), as->max_err,
           as->excluded, 100.0 * (double)as->excluded / (double)as->px, as->resolved,
           as->resolved ? (double)as->frags / (double)as->resolved : 0.0, as->uni_px,
           as->uni_bad, as->uni_max, as->max_frags, as->skipped);
}

static void assert_quality(const char *what, const aa_stats *as)
{
    report(what, as);
    ZT_CHECK((double)as->within1 >= 0.995 * (double)(as->px - as->excluded),
             "%s: %lu of %lu pixels within 1 LSB", what, as->within1, as->px - as->excluded);
    ZT_CHECK(as->max_err <= 8, "%s: max error %lu LSB", what, as->max_err);
    ZT_CHECK((double)as->excluded <= 0.005 * (double)as->px, "%s: %lu near-tie pixels", what,
             as->excluded);
    ZT_CHECK(as->uni_bad == 0, "%s: %lu uniform pixels differ from the centre ray cast", what,
             as->uni_bad);
}

static void test_random_flat(void **state)
{
    (void)state;
    zt_rng g;
    zt_ctx c;
    zs_camera cam;
    zt_scene sc;
    scene_setup(&g, SEED, &c, ZS_CFG_ABUFFER, &cam, &sc, 128);
    aa_stats as;
    memset(&as, 0, sizeof as);
    for (int n = 0; n < NSCENES; n++) {
        zt_scene_reset(&sc);
        unsigned flags = ZT_SC_ALL;
        if (n % 4 == 1) flags = ZT_SC_PLAIN; /* penetrations */
        if (n % 4 == 2) flags = ZT_SC_FLAT | ZT_SC_SHARED | ZT_SC_DUP;
        if (n % 4 == 3) flags = ZT_SC_LAYERS | ZT_SC_PLAIN;
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 32), flags, 0.5);
        check_scene(&c, &cam, &sc, 0, ZS_AA_EDGES, 1, NULL, n, &as);
    }
    assert_quality("flat, edges", &as);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_random_gouraud(void **state)
{
    (void)state;
    zt_rng g;
    zt_ctx c;
    zs_camera cam;
    zt_scene sc;
    scene_setup(&g, SEED + 1, &c, ZS_CFG_ABUFFER, &cam, &sc, 128);
    aa_stats as;
    memset(&as, 0, sizeof as);
    for (int n = 0; n < NSCENES / 2; n++) {
        zt_scene_reset(&sc);
        /* no near-plane clipping and no BIG planes (clipped at the guard band):
         * records are the scene's triangles with their vertex order */
        unsigned flags = ZT_SC_PLAIN | ZT_SC_SHARED | ZT_SC_FLAT | ZT_SC_LAYERS;
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 40), flags, 0.5);
        check_scene(&c, &cam, &sc, 1, ZS_AA_EDGES, 1, NULL, n, &as);
    }
    assert_quality("gouraud, edges", &as);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* Transparency: the scene in 2..4 draws with random opacities (some opaque,
 * some invisible); per sample the transparent hits in front of the nearest
 * opaque one are blended far to near. Flat and Gouraud. */
static void test_random_transparent(void **state)
{
    (void)state;
    zt_rng g;
    zt_ctx c;
    zs_camera cam;
    zt_scene sc;
    scene_setup(&g, SEED + 4, &c, ZS_CFG_ABUFFER, &cam, &sc, 128);
    aa_stats as[2];
    memset(as, 0, sizeof as);
    for (int n = 0; n < NSCENES / 2; n++) {
        int gouraud = n & 1;
        zt_scene_reset(&sc);
        unsigned flags = gouraud ? ZT_SC_PLAIN | ZT_SC_SHARED | ZT_SC_FLAT | ZT_SC_LAYERS
                                 : ZT_SC_ALL;
        zt_scene_random(&g, &sc, (int)zt_range(&g, 8, 24), flags, 0.5);
        uint8_t alpha[4];
        int parts = 2 + (int)zt_below(&g, 3);
        for (int p = 0; p < parts; p++) {
            unsigned k = zt_below(&g, 6);
            alpha[p] = (uint8_t)(k == 0 ? 255 : k == 1 ? 0 : 30 + zt_below(&g, 200));
        }
        check_scene(&c, &cam, &sc, gouraud, ZS_AA_TRANSPARENT, parts, alpha, n, &as[gouraud]);
    }
    assert_quality("flat, transparent", &as[0]);
    assert_quality("gouraud, transparent", &as[1]);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

/* A jittered grid of one colour over the whole screen (and beyond): every
 * pixel is that colour exactly; no seam where triangles meet. */
static void test_tiling_no_seams(void **state)
{
    (void)state;
    zt_rng g;
    zt_ctx c;
    zs_camera cam;
    zt_scene sc;
    scene_setup(&g, SEED + 2, &c, ZS_CFG_ABUFFER, &cam, &sc, 8 * H);
    static uint8_t img[W * H * 3];
    unsigned long bad = 0, resolved = 0, meshes = 0;
    const zs_color col = ZS_RGB(200, 120, 40);
    for (int n = 0; n < 60; n++) {
        zt_scene_reset(&sc);
        int nx = (int)zt_range(&g, 2, 14), ny = (int)zt_range(&g, 2, 12);
        int32_t X0 = -40, Y0 = -40, X1 = 16 * W + 40, Y1 = 16 * H + 40;
        double cw = (double)(X1 - X0) / nx, ch = (double)(Y1 - Y0) / ny;
        int *vi = malloc(sizeof(int) * (size_t)((nx + 1) * (ny + 1)));
        for (int j = 0; j <= ny; j++)
            for (int i = 0; i <= nx; i++) {
                double x = X0 + i * cw, y = Y0 + j * ch;
                if (i > 0 && i < nx) x += zt_uniform(&g, -0.3, 0.3) * cw;
                if (j > 0 && j < ny) y += zt_uniform(&g, -0.3, 0.3) * ch;
                int32_t qx = (int32_t)floor(x), qy = (int32_t)floor(y);
                if (zt_below(&g, 4) == 0) qx = (qx & ~15) + 2 + 4 * (int32_t)zt_below(&g, 4);
                if (zt_below(&g, 4) == 0) qy = (qy & ~15) + 2 + 4 * (int32_t)zt_below(&g, 4);
                vi[j * (nx + 1) + i] = zt_scene_vertex_q(&sc, qx, qy, col);
            }
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                int a = vi[j * (nx + 1) + i], b = vi[j * (nx + 1) + i + 1];
                int d = vi[(j + 1) * (nx + 1) + i], e = vi[(j + 1) * (nx + 1) + i + 1];
                if (zt_below(&g, 2)) {
                    zt_scene_tri_front(&sc, a, b, e, col);
                    zt_scene_tri_front(&sc, a, e, d, col);
                } else {
                    zt_scene_tri_front(&sc, a, b, d, col);
                    zt_scene_tri_front(&sc, b, e, d, col);
                }
            }
        free(vi);
        zs_shade_params sp = zs_shade_default();
        sp.format = ZS_FMT_RGB888;
        zs_mesh m = zt_scene_mesh(&sc, 1, 0);
        ZT_ST(zs_frame_begin(&c.r, &cam, ZS_MODE_SPAN), ZS_OK);
        ZT_ST(zs_frame_shading(&c.r, &sp), ZS_OK);
        ZT_ST(zs_frame_antialias(&c.r, ZS_AA_EDGES), ZS_OK);
        ZT_ST(zs_draw(&c.r, &m, NULL), ZS_OK);
        ZT_ST(zt_render_rows_all(&c.r, img, W, H, ZS_FMT_RGB888, 1 + n % 5), ZS_OK);
        resolved += zs_frame_stats(&c.r)->aa_pixels;
        meshes++;
        for (int p = 0; p < W * H; p++)
            if (img[3 * p] != 200 || img[3 * p + 1] != 120 || img[3 * p + 2] != 40) {
                if (bad++ < 3)
                    print_error("mesh %d pixel (%d,%d): %u %u %u\n", n, p % W, p / W, img[3 * p],
                                img[3 * p + 1], img[3 * p + 2]);
            }
    }
    printf("test_abuffer: tiling: %lu meshes, %lu edge pixels resolved, %lu off the flat colour\n",
           meshes, resolved, bad);
    ZT_CHECK(bad == 0, "%lu pixels show a seam", bad);
    ZT_CHECK(resolved > 0, "no pixel was resolved: the test did not test");
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static zs_status frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode, zs_format fmt,
                       int aa, const zs_mesh *m, uint8_t *img, size_t stride, int band)
{
    zs_shade_params sp = zs_shade_default();
    sp.format = fmt;
    sp.shading = ZS_SHADE_GOURAUD;
    sp.background = ZS_RGB(9, 80, 200);
    zs_status st = zs_frame_begin(&c->r, cam, mode);
    if (st) return st;
    if ((st = zs_frame_shading(&c->r, &sp))) return st;
    if (aa >= 0 && (st = zs_frame_antialias(&c->r, (zs_aa_mode)aa))) return st;
    if ((st = zs_draw(&c->r, m, NULL))) return st;
    for (int y = 0; y < H; y += band) {
        int rows = band < H - y ? band : H - y;
        int unit = fmt == ZS_FMT_MONO_PAGE ? y / 8 : y;
        if ((st = zs_render_rows(&c->r, y, rows, img + (size_t)unit * stride, stride))) return st;
    }
    return ZS_OK;
}

static void pack(zs_format fmt, const uint8_t *rgb, uint8_t *out)
{
    unsigned r = rgb[0], g = rgb[1], b = rgb[2], v = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    if (fmt == ZS_FMT_RGB565_BE) {
        out[0] = (uint8_t)(v >> 8);
        out[1] = (uint8_t)v;
    } else if (fmt == ZS_FMT_RGB565) {
        uint16_t h = (uint16_t)v;
        memcpy(out, &h, 2);
    } else if (fmt == ZS_FMT_RGB666) {
        out[0] = (uint8_t)(r & 0xFC);
        out[1] = (uint8_t)(g & 0xFC);
        out[2] = (uint8_t)(b & 0xFC);
    } else { /* GRAY8 */
        out[0] = (uint8_t)((77 * r + 150 * g + 29 * b) >> 8);
    }
}

static int bayer(int x, int y)
{
    int v = 0;
    for (int b = 0; b < 3; b++) {
        int xb = (x >> b) & 1, yb = (y >> b) & 1;
        v |= ((xb ^ yb) << (2 * (2 - b) + 1)) | (yb << (2 * (2 - b)));
    }
    return v;
}

/* AA off: byte for byte the renderer without the A-buffer (both modes,
 * every byte format); AA on in every byte format: the RGB888 A-buffer
 * frame packed (the RGB888 frame itself is checked by the oracle above);
 * 1-bit output: the GRAY8 A-buffer frame dithered (ordered dithering by its
 * threshold rule); ID16: each tag is 0 or one covering a sub-sample. */
static void test_formats_and_off(void **state)
{
    (void)state;
    zt_rng g;
    zt_rng_seed(&g, SEED + 3);
    zt_ctx plain, aa;
    zt_ctx_init(&plain, W, H, 800, 2400, 600);
    zt_ctx_init_flags(&aa, W, H, 800, 2400, 600, ZS_CFG_ABUFFER | ZS_CFG_MONO);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    static uint8_t a[W * H * 3], b[W * H * 3], ref[W * H * 3];
    const zs_format fmts[] = {ZS_FMT_RGB565_BE, ZS_FMT_RGB565, ZS_FMT_RGB666, ZS_FMT_GRAY8,
                              ZS_FMT_RGB888, ZS_FMT_ID16};
    unsigned long checked = 0;
    for (int n = 0; n < 24; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 10, 30), ZT_SC_ALL, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, n & 1, 1);
        int band = 1 + n % 4;
        for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
            size_t bpp = zs_format_bytes(fmts[f]), stride = W * bpp;
            for (int mode = 0; mode < 2; mode++) {
                memset(a, 0x5A, sizeof a);
                memset(b, 0xA5, sizeof b);
                ZT_ST(frame(&plain, &cam, (zs_visibility)mode, fmts[f], -1, &m, a, stride, band),
                      ZS_OK);
                ZT_ST(frame(&aa, &cam, (zs_visibility)mode, fmts[f], ZS_AA_OFF, &m, b, stride,
                            band), ZS_OK);
                ZT_CHECK(memcmp(a, b, (size_t)H * stride) == 0,
                         "scene %d format %d mode %d: AA off differs from no A-buffer", n,
                         (int)fmts[f], mode);
                ZT_CHECK(zs_frame_stats(&aa.r)->aa_pixels == 0, "AA off resolved pixels");
            }
        }
        /* AA on */
        ZT_ST(frame(&aa, &cam, ZS_MODE_SPAN, ZS_FMT_RGB888, ZS_AA_EDGES, &m, ref, 3 * W, band),
              ZS_OK);
        ZT_CHECK(zs_frame_stats(&aa.r)->aa_pixels > 0, "scene %d: nothing resolved", n);
        for (size_t f = 0; f < 4; f++) {
            size_t bpp = zs_format_bytes(fmts[f]);
            ZT_ST(frame(&aa, &cam, ZS_MODE_SPAN, fmts[f], ZS_AA_EDGES, &m, a, W * bpp, band),
                  ZS_OK);
            for (int p = 0; p < W * H; p++) {
                uint8_t want[3];
                pack(fmts[f], ref + 3 * p, want);
                ZT_CHECK(memcmp(a + bpp * (size_t)p, want, bpp) == 0,
                         "scene %d format %d pixel %d: not the RGB888 frame packed", n,
                         (int)fmts[f], p);
                checked++;
            }
        }
        /* rows skipped over (partial updates): the rest as in the whole frame */
        {
            zs_shade_params sp = zs_shade_default();
            sp.format = ZS_FMT_RGB888;
            sp.shading = ZS_SHADE_GOURAUD;
            sp.background = ZS_RGB(9, 80, 200);
            int y0 = 1 + n % 17;
            ZT_ST(zs_frame_begin(&aa.r, &cam, ZS_MODE_SPAN), ZS_OK);
            ZT_ST(zs_frame_shading(&aa.r, &sp), ZS_OK);
            ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_EDGES), ZS_OK);
            ZT_ST(zs_draw(&aa.r, &m, NULL), ZS_OK);
            ZT_ST(zs_render_rows(&aa.r, y0, H - y0, a, 3 * W), ZS_OK);
            ZT_CHECK(memcmp(a, ref + (size_t)y0 * 3 * W, (size_t)(H - y0) * 3 * W) == 0,
                     "scene %d: rows from %d differ from the whole frame's", n, y0);
        }
        /* 1-bit: ordered dithering of the GRAY8 A-buffer frame */
        ZT_ST(frame(&aa, &cam, ZS_MODE_SPAN, ZS_FMT_GRAY8, ZS_AA_EDGES, &m, a, W, band), ZS_OK);
        ZT_ST(frame(&aa, &cam, ZS_MODE_SPAN, ZS_FMT_MONO_MSB, ZS_AA_EDGES, &m, b, W / 8, band),
              ZS_OK);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want = 128 * a[y * W + x] > 255 * (2 * bayer(x & 7, y & 7) + 1);
                int got = (b[y * (W / 8) + x / 8] >> (7 - x % 8)) & 1;
                ZT_CHECK(want == got, "scene %d 1-bit pixel (%d,%d): %d, want %d", n, x, y, got,
                         want);
            }
        /* ID16 */
        zt_recs recs = {0};
        zs_set_setup_hook(&aa.r, zt_recs_hook, &recs);
        ZT_ST(frame(&aa, &cam, ZS_MODE_SPAN, ZS_FMT_ID16, ZS_AA_EDGES, &m, a, 2 * W, band), ZS_OK);
        zs_set_setup_hook(&aa.r, NULL, NULL);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint16_t id = zt_id_at(a, W, x, y);
                int ok = id == 0;
                for (size_t i = 0; i < recs.n && !ok; i++)
                    if (recs.v[i].tag == id)
                        for (int j = 0; j < 16 && !ok; j++)
                            ok = covers_pt(recs.v[i].xy, 16 * x + 2 + 4 * (j & 3),
                                           16 * y + 2 + 4 * (j >> 2));
                ZT_CHECK(ok, "scene %d ID16 pixel (%d,%d): tag %u covers none of its samples", n,
                         x, y, id);
            }
        zt_recs_free(&recs);
    }
    printf("test_abuffer: formats: 24 scenes, AA off == no A-buffer in 6 formats x 2 modes, "
           "%lu packed pixels equal, 1-bit and ID16 checked\n", checked);
    zt_scene_free(&sc);
    zt_ctx_free(&plain);
    zt_ctx_free(&aa);
}

/* Refusals: the z-buffer mode, a config without the A-buffer, unknown modes,
 * calls out of order; opacity needs the transparent mode. */
static void test_api(void **state)
{
    (void)state;
    zt_ctx plain, aa;
    zt_ctx_init(&plain, 16, 16, 10, 30, 10);
    zt_ctx_init_flags(&aa, 16, 16, 40, 120, 10, ZS_CFG_ABUFFER);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    ZT_ST(zs_frame_antialias(NULL, ZS_AA_EDGES), ZS_ERR_NULL);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_EDGES), ZS_ERR_STATE); /* no frame yet */
    ZT_ST(zs_frame_begin(&plain.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_antialias(&plain.r, ZS_AA_EDGES), ZS_ERR_MODE);
    ZT_ST(zs_frame_antialias(&plain.r, ZS_AA_OFF), ZS_OK);
    ZT_ST(zs_draw_opacity(&plain.r, 100), ZS_ERR_MODE);
    ZT_ST(zs_frame_begin(&aa.r, &cam, ZS_MODE_ZLINE), ZS_OK);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_EDGES), ZS_ERR_MODE);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_TRANSPARENT), ZS_ERR_MODE);
    ZT_ST(zs_frame_begin(&aa.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_antialias(&aa.r, (zs_aa_mode)3), ZS_ERR_ARGUMENT);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_EDGES), ZS_OK);
    ZT_ST(zs_draw_opacity(&aa.r, 100), ZS_ERR_MODE);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_TRANSPARENT), ZS_OK);
    for (unsigned i = 0; i < ZS_ABUFFER_OPACITY_RUNS; i++) {
        /* a change with nothing drawn since replaces the last one */
        ZT_ST(zs_draw_opacity(&aa.r, (uint8_t)(i & 1 ? 255 : 100)), ZS_OK);
    }
    ZT_ST(zs_draw_opacity(NULL, 1), ZS_ERR_NULL);
    zt_scene sc;
    zt_scene_init(&sc, 16, 16, 128);
    zt_scene_tri_front(&sc, zt_scene_vertex_px(&sc, 2, 2, 2, 0xFFFFFF),
                       zt_scene_vertex_px(&sc, 14, 3, 2, 0xFFFFFF),
                       zt_scene_vertex_px(&sc, 7, 14, 2, 0xFFFFFF), 0xFFFFFF);
    zs_mesh m = zt_scene_mesh(&sc, 0, 0);
    for (unsigned i = 0; i < ZS_ABUFFER_OPACITY_RUNS; i++) {
        ZT_ST(zs_draw_opacity(&aa.r, (uint8_t)(i & 1 ? 255 : 100)), ZS_OK);
        ZT_ST(zs_draw(&aa.r, &m, NULL), ZS_OK);
    }
    ZT_CHECK(zs_frame_stats(&aa.r)->records == ZS_ABUFFER_OPACITY_RUNS, "records %u",
             zs_frame_stats(&aa.r)->records);
    ZT_ST(zs_draw_opacity(&aa.r, 7), ZS_ERR_CAPACITY);
    ZT_ST(zs_frame_antialias(&aa.r, ZS_AA_EDGES), ZS_ERR_STATE); /* after a draw */
    uint8_t line[16 * 2];
    ZT_ST(zs_render_rows(&aa.r, 0, 1, line, sizeof line), ZS_OK);
    ZT_ST(zs_draw_opacity(&aa.r, 7), ZS_ERR_STATE);
    /* frame_begin resets the mode */
    ZT_ST(zs_frame_begin(&aa.r, &cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_draw_opacity(&aa.r, 7), ZS_ERR_MODE);
    zt_scene_free(&sc);
    zt_ctx_free(&plain);
    zt_ctx_free(&aa);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_flat),
        cmocka_unit_test(test_random_gouraud),
        cmocka_unit_test(test_random_transparent),
        cmocka_unit_test(test_tiling_no_seams),
        cmocka_unit_test(test_formats_and_off),
        cmocka_unit_test(test_api),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
