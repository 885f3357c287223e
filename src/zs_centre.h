/* SPDX-License-Identifier: MIT */
/* Stored records evaluated at pixel centres without the row machinery
 * (centre.c), for Warnock mode (warnock.c) and picking (pick.c). */
#ifndef ZSPAN_CENTRE_H
#define ZSPAN_CENTRE_H

#include "zs_internal.h"

/* A record seen through its canonical vertices (sorted by y, then x). */
typedef struct zs_rec_view {
    const zs_vert *s[3];
    int long_left;         /* the long edge s0 -> s2 is the left one */
    int32_t row0, row_end; /* rows [row0, row_end) it crosses (row0 >= 0) */
} zs_rec_view;

void zs_rec_view_make(const zs_renderer *r, uint16_t ti, zs_rec_view *v);
/* The row a record is activated on (its bucket): its first row, clamped. */
int32_t zs_rec_first_row(const zs_renderer *r, uint16_t ti);
/* Is the point (X, Y) (1/16 px, a pixel centre) covered, by the rule of the
 * edge walk (top-left: left edges and the top row inclusive)? */
int zs_rec_covers(const zs_rec_view *v, int32_t X, int32_t Y);
/* Does a non-horizontal edge of the record leave all four corners of the
 * centres [x0, x1) x [y0, y1) outside (then none of them is covered)? */
int zs_rec_separated(const zs_rec_view *v, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
/* First covered column on row y and first column past the covered ones, as
 * the edge walk steps them (unclamped); row y within [row0, row_end). */
int32_t zs_rec_left_col(const zs_rec_view *v, int32_t y);
int32_t zs_rec_right_col(const zs_rec_view *v, int32_t y);
/* Fills a with the depth plane (and steep flag) zs_activate gives the
 * record on row y; with shade also the colour planes (ac, NULL for a flat-
 * only renderer) and flat pixel. */
void zs_rec_planes(const zs_renderer *r, uint16_t ti, const zs_rec_view *v, int32_t y,
                   zs_active *a, zs_active_plane *p, zs_active_color *ac, int shade);
/* Depth (Q40) the renderer evaluates at covered centre (x, y): a steep plane
 * is anchored at its row's first covered column first, as the walk does. */
int64_t zs_rec_depth(const zs_renderer *r, const zs_rec_view *v, const zs_active *a,
                     zs_active_plane *p, int32_t x, int32_t y);
/* Counts the tallest record (rows) into r->priv.tall_rows once a frame. */
void zs_rec_count_tall(zs_renderer *r);

/* warnock.c: rows [y0, y0 + rows) of the frame into buf (row k at buf + k *
 * stride) by area subdivision. */
void zs_warnock_rows(zs_renderer *r, int32_t y0, int32_t rows, uint8_t *buf, size_t stride);

#endif
