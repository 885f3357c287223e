/* SPDX-License-Identifier: MIT */
/* Shared cmocka scaffolding of the core suites: see zt_test.h. */
#include "zt_test.h"

#include <stdlib.h>
#include <string.h>

#define ZT_CANARY 0xC3
#define ZT_GUARD 48
#define ZT_PAD 5

unsigned long zt_checks;
zt_totals zt_tot;

static const int16_t zt_pair_pos[] = {-200, -150, -400, 220, -120, -300, 0,  200,  -500,
                                      -180, 100,  -250, 200, 160,  -520, 30, -200, -350};
static const uint16_t zt_pair_idx[] = {0, 1, 2, 3, 5, 4};
static const zs_color zt_pair_fcol[] = {ZS_RGB(200, 40, 40), ZS_RGB(40, 200, 90)};

zs_mesh zt_mesh_pair(void)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = zt_pair_pos;
    m.indices = zt_pair_idx;
    m.face_colors = zt_pair_fcol;
    m.scale = ZS_FX(1) / 128;
    m.vertex_count = 6;
    m.triangle_count = 2;
    m.color = ZS_RGB(255, 255, 255);
    return m;
}

int zt_sink(void *user, int y0, int rows, const void *buf, size_t stride)
{
    (void)user;
    (void)y0;
    (void)rows;
    (void)buf;
    (void)stride;
    return 0;
}

zs_status zt_render_guarded(zs_renderer *r, int w, int h, unsigned bpp, int band, uint8_t *img)
{
    size_t rowb = (size_t)w * bpp, stride = rowb + ZT_PAD;
    size_t total = ZT_GUARD + stride * (size_t)band + ZT_GUARD;
    uint8_t *buf = malloc(total);
    zs_status st = ZS_OK;
    ZT_CHECK(buf != NULL, "out of memory");
    for (int y0 = 0; y0 < h;) {
        int n = band < h - y0 ? band : h - y0;
        memset(buf, ZT_CANARY, total);
        st = zs_render_rows(r, y0, n, buf + ZT_GUARD, stride);
        if (st != ZS_OK)
            break;
        for (size_t i = 0; i < ZT_GUARD; i++) {
            ZT_CHECK(buf[i] == ZT_CANARY, "rows %d+%d: guard byte %zu before the band written",
                     y0, n, i);
            ZT_CHECK(buf[total - 1 - i] == ZT_CANARY,
                     "rows %d+%d: guard byte %zu after the band written", y0, n, i);
        }
        for (int y = 0; y < n; y++) {
            const uint8_t *row = buf + ZT_GUARD + (size_t)y * stride;
            for (size_t k = rowb; k < stride; k++)
                ZT_CHECK(row[k] == ZT_CANARY, "row %d: padding byte %zu written", y0 + y, k);
            memcpy(img + (size_t)(y0 + y) * rowb, row, rowb);
        }
        y0 += n;
    }
    free(buf);
    return st;
}

void zt_check_accounting(const zs_stats *s, const zs_config *cfg)
{
    zt_checks++;
    ZT_CHECK(s->tris_submitted ==
                 s->tris_culled + s->tris_rejected + s->tris_empty + s->tris_dropped + s->tris_stored,
             "accounting: submitted %u != culled %u + rejected %u + empty %u + dropped %u + "
             "stored %u",
             s->tris_submitted, s->tris_culled, s->tris_rejected, s->tris_empty, s->tris_dropped,
             s->tris_stored);
    ZT_CHECK(s->records_dropped >= s->tris_dropped, "records_dropped %u < tris_dropped %u",
             s->records_dropped, s->tris_dropped);
    if (!cfg)
        return;
    ZT_CHECK(s->records_dropped == 0 || s->records == cfg->max_triangles || s->verts_dropped > 0,
             "records_dropped %u with a triangle pool not full (%u of %u) and no vertex drop",
             s->records_dropped, s->records, cfg->max_triangles);
    ZT_CHECK(s->records >= s->tris_stored, "records %u < tris_stored %u", s->records,
             s->tris_stored);
    ZT_CHECK(s->records <= cfg->max_triangles, "records %u above max_triangles %u", s->records,
             cfg->max_triangles);
    ZT_CHECK(s->verts_stored <= cfg->max_vertices, "verts_stored %u above max_vertices %u",
             s->verts_stored, cfg->max_vertices);
    ZT_CHECK(s->tris_drawn <= s->records, "tris_drawn %u > records %u", s->tris_drawn, s->records);
    ZT_CHECK(s->max_active_edges <= cfg->max_active_edges, "max_active_edges %u above %u",
             s->max_active_edges, cfg->max_active_edges);
}

zt_gframe *zt_gframe_new(int w, int h)
{
    zt_gframe *f = calloc(1, sizeof *f);
    ZT_CHECK(f != NULL, "out of memory");
    f->w = w;
    f->h = h;
    f->img = calloc((size_t)w * (size_t)h, 2);
    ZT_CHECK(f->img != NULL, "out of memory");
    return f;
}

void zt_gframe_free(zt_gframe *f)
{
    zt_recs_free(&f->recs);
    free(f->img);
    free(f);
}

int zt_gframe_empty(const zt_gframe *f)
{
    for (int y = 0; y < f->h; y++)
        for (int x = 0; x < f->w; x++)
            if (zt_id_at(f->img, f->w, x, y))
                return 0;
    return 1;
}

void zt_guarded_frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                      const zs_mesh *meshes, int nm, const zs_mat34 *model, zt_gframe *f,
                      int band)
{
    int w = f->w, h = f->h;
    ZT_CHECK(w == c->cfg.width && h == c->cfg.height, "frame %dx%d for a %ux%u renderer", w, h,
             c->cfg.width, c->cfg.height);
    zt_recs_clear(&f->recs);
    zs_set_setup_hook(&c->r, zt_recs_hook, &f->recs);
    ZT_ST(zs_frame_begin(&c->r, cam, mode), ZS_OK);
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_ID16;
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    f->draw_st = ZS_OK;
    for (int i = 0; i < nm; i++) {
        zs_status s = zs_draw(&c->r, &meshes[i], model);
        if (s != ZS_OK && f->draw_st == ZS_OK)
            f->draw_st = s;
    }
    ZT_ST(zt_render_guarded(&c->r, w, h, 2, band, f->img), ZS_OK);
    zs_set_setup_hook(&c->r, NULL, NULL);
    f->st = *zs_frame_stats(&c->r);
    zt_tot.frames++;
    const zs_stats *s = &f->st;
    zt_check_accounting(s, &c->cfg);
    ZT_CHECK(s->records == f->recs.n, "stats.records %u != %zu hook calls", s->records, f->recs.n);
    ZT_CHECK(s->rows == (uint32_t)h, "rows %u of %d", s->rows, h);
    if (mode == ZS_MODE_SPAN)
        ZT_CHECK(s->pixels_shaded == (uint32_t)(w * h), "span pixels_shaded %u of %d",
                 s->pixels_shaded, w * h);
    /* a shown tag is covered by one of its records */
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint16_t id = zt_id_at(f->img, w, x, y);
            if (!id)
                continue;
            int ok = 0;
            for (size_t i = 0; i < f->recs.n && !ok; i++)
                ok = f->recs.v[i].tag == id && zt_covers(f->recs.v[i].xy, x, y);
            ZT_CHECK(ok, "pixel (%d,%d) shows tag %u, which no record of that tag covers", x, y, id);
        }
    zt_tot.clipped += s->tris_clipped;
    zt_tot.rejected += s->tris_rejected;
    zt_tot.culled += s->tris_culled;
    zt_tot.dropped += s->tris_dropped;
    zt_tot.vdropped += s->verts_dropped;
    zt_tot.edropped += s->records_skipped;
    zt_tot.saturated += s->saturated;
}

unsigned long zt_vs_raycast(const zt_gframe *f, const char *what)
{
    int w = f->w, h = f->h;
    zt_cast cast;
    zt_cast_alloc(&cast, w, h);
    zt_raycast(&f->recs, &cast);
    unsigned long bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int p = y * w + x;
            uint16_t id = zt_id_at(f->img, w, x, y), want = cast.owner[p];
            if (want)
                zt_tot.px++;
            int tie = want && cast.z2[p] - cast.z1[p] < ZT_TIE_TOL;
            if (tie)
                zt_tot.excluded++;
            if (id == want || tie)
                continue;
            if (bad++ < 3) {
                print_error("%s: pixel (%d,%d) ID16 %u, ray caster %u (z %.9f, runner-up %.9f)\n",
                            what, x, y, id, want, cast.z1[p], cast.z2[p]);
                for (size_t i = 0; i < f->recs.n; i++) {
                    const zt_rec *t = &f->recs.v[i];
                    if ((t->tag == id || t->tag == want) && zt_covers(t->xy, x, y))
                        print_error("  record tag %u xy %d %d %d %d %d %d z %u %u %u -> %.9f\n",
                                    t->tag, t->xy[0], t->xy[1], t->xy[2], t->xy[3], t->xy[4],
                                    t->xy[5], t->z[0], t->z[1], t->z[2], zt_depth_at(t, x, y));
                }
            }
        }
    zt_cast_free(&cast);
    return bad;
}
