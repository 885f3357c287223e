/* SPDX-License-Identifier: MIT */
/* cmocka glue for the zspan core suites. */
#ifndef ZT_TEST_H
#define ZT_TEST_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "zt.h"

/* Fail the current test with a printf-style message. */
#define ZT_FAIL(...)                                                            \
    do {                                                                        \
        print_error("%s:%d: ", __FILE__, __LINE__);                             \
        print_error(__VA_ARGS__);                                               \
        print_error("\n");                                                      \
        fail();                                                                 \
    } while (0)

/* Check a condition; on failure print the message and fail. */
#define ZT_CHECK(cond, ...)                                                     \
    do {                                                                        \
        if (!(cond)) {                                                          \
            print_error("%s:%d: check failed: %s\n  ", __FILE__, __LINE__, #cond); \
            print_error(__VA_ARGS__);                                           \
            print_error("\n");                                                  \
            fail();                                                             \
        }                                                                       \
    } while (0)

/* Check a status code. */
#define ZT_ST(expr, want)                                                       \
    do {                                                                        \
        zs_status zt_st_ = (expr);                                              \
        if (zt_st_ != (want)) {                                                 \
            print_error("%s:%d: %s returned %d (%s), expected %d (%s)\n",       \
                        __FILE__, __LINE__, #expr, (int)zt_st_,                 \
                        zs_strerror(zt_st_), (int)(want), zs_strerror(want));   \
            fail();                                                             \
        }                                                                       \
    } while (0)

/* ---------------- shared scaffolding of the bad-input suites ---------------- */

/* Status and invariant checks done by ZT_STN and the zt_check_* helpers
 * (the suites print it in their summary line). */
extern unsigned long zt_checks;

/* ZT_ST that also counts the check in zt_checks. */
#define ZT_STN(expr, want)                                                      \
    do {                                                                        \
        zt_checks++;                                                            \
        ZT_ST(expr, want);                                                      \
    } while (0)

/* Two overlapping, penetrating triangles (face colours, scale 1/128) in front
 * of the standard camera (zt_camera_std): the small scene of the API and
 * bad-input suites. */
zs_mesh zt_mesh_pair(void);

/* A zs_render_frame callback that accepts every band. */
int zt_sink(void *user, int y0, int rows, const void *buf, size_t stride);

/* Renders rows 0..h-1 of the open frame in bands of band rows, each band into
 * a fresh buffer filled with a canary, with guard bytes before and after it
 * and padding after each row (stride = w * bpp + padding); fails the test if
 * a guard or padding byte was written; copies the rows into img (w * bpp
 * bytes per row, tight). Returns the first non-OK status of zs_render_rows. */
zs_status zt_render_guarded(zs_renderer *r, int w, int h, unsigned bpp, int band, uint8_t *img);

/* Fails the test unless the frame statistics add up as the header documents:
 *   tris_submitted == culled + rejected + empty + dropped + stored,
 * and, if cfg is not NULL, the peaks stay within its capacities
 * (records <= max_triangles, verts_stored <= max_vertices, max_active_edges
 * <= max_active_edges, tris_stored <= records, tris_drawn <= records). */
void zt_check_accounting(const zs_stats *s, const zs_config *cfg);

/* One guarded ID16 frame (zt_guarded_frame) and what it left. */
typedef struct zt_gframe {
    int w, h;
    zs_status draw_st;    /* first non-OK status of the draws */
    zs_stats st;          /* statistics after the last row */
    zt_recs recs;         /* every setup-hook call of the frame */
    uint8_t *img;         /* w * h ID16 pixels, tight */
} zt_gframe;

zt_gframe *zt_gframe_new(int w, int h);
void zt_gframe_free(zt_gframe *f);
/* 1 if every pixel of the frame is background (ID16 0). */
int zt_gframe_empty(const zt_gframe *f);

/* Totals over every zt_guarded_frame / zt_vs_raycast of the program. */
typedef struct zt_totals {
    unsigned long frames, clipped, rejected, culled, dropped, vdropped, edropped, saturated;
    unsigned long px, excluded;   /* ray-cast pixels compared, near ties left out */
} zt_totals;
extern zt_totals zt_tot;

/* Renders meshes (each with model, which may be NULL) in ID16 flat shading
 * on the renderer of c with the setup hook collecting into f->recs, in bands
 * of band rows through zt_render_guarded. Fails the test if rendering is
 * refused, a guard byte is written, the statistics do not add up
 * (zt_check_accounting with c's config), stats.records differs from the
 * number of hook calls, not every row was rendered, a span frame did not
 * shade every pixel, or a pixel shows a tag that no record of that tag
 * covers (reference rasterizer). The frame's size is c's. */
void zt_guarded_frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                      const zs_mesh *meshes, int nm, const zs_mat34 *model, zt_gframe *f,
                      int band);

/* Depth difference below which the ray caster's nearest and runner-up
 * surfaces count as a tie (either may show). */
#define ZT_TIE_TOL (1.0 / 1048576.0)

/* Compares the ID16 image of f with the ray caster over f's records; returns
 * the number of pixels that differ beyond near ties, printing the first
 * three with what (a description of the frame). */
unsigned long zt_vs_raycast(const zt_gframe *f, const char *what);

#endif
