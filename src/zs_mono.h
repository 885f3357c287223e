/* SPDX-License-Identifier: MIT */
/* Internal: the 1-bit output and hidden-line stages (mono.c, lines.c),
 * driven by renderer.c. */
#ifndef ZSPAN_MONO_H
#define ZSPAN_MONO_H

#include "zs_internal.h"

/* mono.c: the 8x8 Bayer index matrix (values 0..63). */
extern const uint8_t zs_bayer8[8][8];
/* mono.c: clears the diffusion error (first row of a frame). */
void zs_mono_begin(zs_renderer *r);
/* Dithers row y (g: GRAY8, or 0/1 line flags with ZS_MONO_LINES; g is
 * overwritten) and packs it into out: the row's page for ZS_FMT_MONO_PAGE
 * (only bit y % 8 of each byte changes), the row for ZS_FMT_MONO_MSB. */
void zs_mono_row(zs_renderer *r, int y, uint8_t *g, uint8_t *out);

/* lines.c: the eye-space unit normals of the records a draw made (from
 * index first on; tag_base = the draw's first tag number % 65535), from the
 * mesh's own positions and mv, the model -> eye 3x3 (Q16). */
void zs_lines_draw(zs_renderer *r, const zs_mesh *m, const int32_t mv[3][3], uint16_t first,
                   uint32_t tag_base);
/* lines.c: draw numbers and the records around each vertex (first row of
 * a frame). */
void zs_lines_begin(zs_renderer *r);
/* Edge flags (0/1) of row y. It renders row y + 1 (and row y itself when
 * it was not rendered ahead), so each boundary's line can go on the pixel
 * nearer to it, above or below. */
void zs_lines_row(zs_renderer *r, int y, uint8_t *flags);
/* renderer.c: one row of visibility into row (the row machinery, or Warnock). */
void zs_visible_row(zs_renderer *r, int y, uint8_t *row);

/* gray4.c: row y (g: GRAY8, overwritten or not) packed into out as
 * ZS_FMT_GRAY4, rounded or dithered (ZS_GRAY4_DITHER), inverted if asked. */
void zs_gray4_row(const zs_renderer *r, int y, const uint8_t *g, uint8_t *out);

#endif
