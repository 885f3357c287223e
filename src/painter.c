/* SPDX-License-Identifier: MIT */
/* Painter's output (zspan/priority.h): the stored records painted back to
 * front into a whole frame buffer, and the order and records handed out.
 *
 * A record is painted over exactly the centres the span walk gives it: on
 * each row the columns [left, right) of its two edge chains, the walk's
 * exact columns (centre.c's rule, stepped here without a division per row),
 * clamped to the screen. Its
 * planes are the ones zs_activate makes, in the active pool's slot 0 (idle
 * outside zs_render_rows), so flat pixels, Gouraud colours and textures are
 * the walk's. In ZS_MODE_PRIORITY the walk shows at each centre the lowest
 * covering record; painting from the highest down leaves the same one on
 * top, so the two images are equal byte for byte. */
#include "zs_centre.h"
#include "zspan/priority.h"

/* An edge's column ceil(x(Y) - 0.5) stepped down the rows without a
 * division: at row Y the exact value is (q * den - r) / den with 0 <= r <
 * den, and each row adds 16 * dx = s * den + t (0 <= t < den) to the
 * numerator. The start is the one 64-bit division zs_rec_left_col makes. */
typedef struct col_step {
    int32_t q, r, s, t, den;
} col_step;

/* Edge a -> b (b below a) at the centre row Y (1/16 px). */
static void step_init(col_step *c, const zs_vert *a, const zs_vert *b, int32_t Y)
{
    int32_t dx = b->x - a->x, dy = b->y - a->y; /* dy > 0 where the edge is used */
    int64_t num = ((int64_t)a->x - 8) * dy + ((int64_t)Y - a->y) * dx;
    int64_t q;
    c->den = 16 * dy;
    q = num / c->den;
    if (q * c->den < num)
        q++;
    c->q = (int32_t)q;
    c->r = (int32_t)(q * c->den - num);
    c->s = (16 * dx) / c->den; /* toward zero, then floored */
    if (c->s * c->den > 16 * dx)
        c->s--;
    c->t = 16 * dx - c->s * c->den;
}

static void step_row(col_step *c)
{
    c->q += c->s;
    c->r -= c->t;
    if (c->r < 0) {
        c->q++;
        c->r += c->den;
    }
}

zs_status zs_paint_frame(zs_renderer *r, void *buf, size_t stride)
{
    int32_t width;
    uint8_t *const img = (uint8_t *)buf;
    zs_active *a;
    zs_active_plane plane; /* made by zs_rec_planes, never read: no depth here */
    zs_active_color *ac;
    size_t need;
    uint32_t background, writes;
    int32_t y, height;
    uint16_t k;
    if (!r || !buf)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    if (r->priv.mode != ZS_MODE_PRIORITY || r->priv.aa_mode)
        return ZS_ERR_MODE;
    if (r->priv.rows_kind == ZS_ROWS_MONO)
        return ZS_ERR_FORMAT; /* 1-bit and GRAY4 rows are dithered, not painted */
    width = (int32_t)r->cfg.width;
    height = (int32_t)r->cfg.height;
    need = (size_t)width * r->priv.bpp;
    if (stride < need || stride > (SIZE_MAX - need) / (size_t)height)
        return ZS_ERR_BUFFER;
    a = r->priv.active;
    ac = r->priv.acolor; /* NULL for a flat-only renderer */
    background = zs_background_word(r);
    for (y = 0; y < height; y++)
        zs_fill_flat(img + (size_t)y * stride, 0, width, r->priv.bpp, background);
    writes = (uint32_t)width * (uint32_t)height;
    r->stats.spans += (uint32_t)height;
    for (k = r->priv.n_tris; k-- > 0;) {
        zs_rec_view v;
        int32_t end, painted = 0;
        zs_rec_view_make(r, k, &v);
        end = v.row_end < height ? v.row_end : height;
        if (v.row0 >= end)
            continue;
        /* the planes refer to the row the walk activates the record on */
        zs_rec_planes(r, k, &v, v.row0, &a[0], &plane, ac ? &ac[0] : 0, 1);
        {
            /* the long edge and the short chain, the short one switching to
             * s1 -> s2 at the first centre row at or below s1 */
            const zs_vert *s0 = v.s[0], *s1 = v.s[1], *s2 = v.s[2];
            int32_t Y = 16 * v.row0 + 8;
            col_step lng, sht;
            int upper = Y < s1->y;
            step_init(&lng, s0, s2, Y);
            if (upper)
                step_init(&sht, s0, s1, Y);
            else
                step_init(&sht, s1, s2, Y);
            for (y = v.row0; y < end; y++, Y += 16) {
                int32_t x0, x1;
                uint8_t *row = img + (size_t)y * stride;
                if (y > v.row0) {
                    step_row(&lng);
                    if (upper && Y >= s1->y) {
                        upper = 0;
                        step_init(&sht, s1, s2, Y);
                    } else {
                        step_row(&sht);
                    }
                }
                x0 = zs_clampi(v.long_left ? lng.q : sht.q, 0, width);
                x1 = zs_clampi(v.long_left ? sht.q : lng.q, 0, width);
                if (x0 >= x1)
                    continue; /* an inverted span is never entered by the walk either */
                if (a[0].flags & ZS_ACT_GOURAUD)
                    zs_fill_gouraud(r, &ac[0], y - a[0].y0, row, x0, x1);
                else
                    zs_fill_flat(row, x0, x1, r->priv.bpp, a[0].pixel);
                writes += (uint32_t)(x1 - x0);
                r->stats.spans++;
                painted = 1;
            }
        }
        r->stats.tris_drawn += (uint32_t)painted;
    }
    r->stats.pixels_shaded += writes;
    r->stats.rows += (uint32_t)height;
    r->priv.next_row = height;
    r->priv.state = ZS_STATE_DONE;
    return ZS_OK;
}

zs_status zs_priority_order(const zs_renderer *r, uint16_t *records, uint32_t capacity,
                            uint32_t *count)
{
    uint32_t n, k;
    if (!r || !count)
        return ZS_ERR_NULL;
    if (r->priv.state < ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    n = r->priv.n_tris;
    *count = n;
    if (n > capacity)
        return ZS_ERR_CAPACITY;
    if (n > 0 && !records)
        return ZS_ERR_NULL;
    for (k = 0; k < n; k++)
        records[k] = (uint16_t)(n - 1u - k);
    return ZS_OK;
}

zs_status zs_record_get(const zs_renderer *r, uint32_t record, zs_record_tri *out)
{
    const zs_tri *t;
    int k;
    if (!r || !out)
        return ZS_ERR_NULL;
    if (r->priv.state < ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    if (record >= r->priv.n_tris)
        return ZS_ERR_ARGUMENT;
    t = &r->priv.tris[record];
    for (k = 0; k < 3; k++) {
        const zs_vert *v = &r->priv.verts[t->v[k]];
        out->x[k] = v->x;
        out->y[k] = v->y;
        out->z[k] = v->z;
        if (r->shade.format == ZS_FMT_ID16)
            out->rgb[k] = t->color & 0xFFFFu; /* setup keeps the tag there */
        else if ((t->color >> 24) == 0 || !r->priv.vshade)
            out->rgb[k] = t->color & 0xFFFFFFu;
        else
            out->rgb[k] = zs_vertex_rgb(r, t, r->priv.vshade[t->v[k]]);
    }
    return ZS_OK;
}
