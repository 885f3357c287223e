/* SPDX-License-Identifier: MIT */
/*
 * test_shortcuts: regression tests for the span engine's shortcuts (issue
 * 11), each against oracles that do not take the shortcut. Every frame that
 * goes through zt_guarded_frame also has its guard bytes, statistics
 * accounting and ID16 coverage checked.
 *
 *  1. box_inside (geometry.c): a mesh whose bounding box is inside near, far
 *     and the guard band projects its vertices without outcodes. A probe
 *     vertex sits just inside or just outside the near plane, the far plane
 *     or one of the four guard planes, on screens with guard 4, 3 and 2
 *     (64x48, 900x12, 1024x12), under identity, slightly turned, randomly
 *     turned and "margin" model matrices. The boundary is found by bisection
 *     on the outcode path itself (the mesh plus one unused vertex behind the
 *     eye or beyond far, so its box is outside); the probe is placed from 60
 *     steps inside to 8 outside, including the last position inside and the
 *     first outside (identity turn: the last inside is exactly w == near or
 *     w == far). Each mesh is drawn (a) as it is and (b) with the unused
 *     vertex: ID16 and RGB565 images, the setup hook's records and every
 *     statistic must be identical (verts_stored one more for b), and the
 *     image must agree with the ray caster and the zline mode.
 *     The margin turn tilts the mesh so that the guard function xc - guard w
 *     grows by only 0.1..1.5 Q16 units per position unit along one model
 *     axis while xc and w each change by many; a row of companion vertices
 *     along that axis then slides outward a unit at a time, where the
 *     roundings of xc and w can put a vertex outside while the box's corners
 *     are inside: what INSIDE_MARGIN is for (records and statistics of a and
 *     b compared at every slide).
 *  2. The counting sort of new edges (raster.c count_sort: 25..width new
 *     edges on a row, the z-buffer line as scratch): 640x36 frames where
 *     25..300 triangles start on one row (fans and strips of quads sharing
 *     edges, so edges fold; loose penetrating triangles; first columns far
 *     left and right of the screen and at columns -1, 0, width - 1, width;
 *     rows entered from above): span == zline in every format, span equal to
 *     a ZS_CFG_NO_ZLINE renderer's (which sorts by insertion), ray caster.
 *     The batch size is counted from the records.
 *  3. Planes evaluated for the row instead of stepped (depth zrow + zdy dy,
 *     Gouraud crow + cdy dy): 56x560 frames of triangles spanning the whole
 *     height with depths far apart at their ends, pairs whose depth order
 *     flips half way down, Gouraud vertex colours, and needles (a fraction of
 *     a pixel wide, their third vertex much deeper; counted steep by
 *     activate.c's rule from the records); bands 1, 3, 8 and all rows:
 *     span == zline in ID16 and RGB888, the ray caster, and every Gouraud
 *     pixel within 0.5 + 1/32 of a double barycentric colour at RGB888 (the
 *     renderer rounds its Q8.16 planes to nearest: within 1 LSB), flat ones
 *     exact, background exact.
 *  4. Depth-range decisions and the top pick when the top leaves through an
 *     edge it shares with the entering triangle (span.c range_top,
 *     always_nearer, the deferred pick): grids of quads split into two
 *     triangles along random diagonals, 2..4 layers at depths far apart,
 *     close, 0..2 position units apart, interpenetrating or folded, exact
 *     coplanar duplicates of a layer submitted later with rotated vertex
 *     order (same or copied vertices), and wedges whose depth sweeps through
 *     the layers (an entering triangle nearer than the top by range but not
 *     nearer than a member that comes in front after the top has left; the
 *     new top outright only where its range is nearer than every member's):
 *     ray caster (exact ties to the earlier
 *     triangle), span == zline in ID16, RGB565 flat and RGB888 Gouraud.
 *     The z-buffer mode's shortcuts (zline.c: owner runs decided whole by
 *     the depth ranges, spans that overlap no other written directly) are
 *     checked against the ray caster on the same frames, and Warnock's
 *     image (which takes neither) must equal both modes'.
 *
 *  5. Single-layer stretches (span.c: the walk without the in-polygon set
 *     while at most one triangle is inside, handing over to the general walk
 *     at an overlap or at a rounding inversion, and back when one member or
 *     none is left): one grid layer (random diagonals, so most edges are
 *     shared hand-overs), slivers a fraction of a pixel wide at every angle
 *     (many rows see their right edge before their left: the counter that
 *     goes to 255), a few loose triangles in front of, behind and through
 *     the layer (stretches end and start again on the same row), on
 *     renderers with and without colour planes (ZS_CFG_FLAT_ONLY, whose
 *     RGB565 frames take the walk's flat 2-byte copy): the ray caster in
 *     ID16, span == zline in ID16, RGB565 and RGB888 (Gouraud where planes
 *     exist), and the colour-plane renderer's image == the flat one's.
 *
 * Near ties (ZT_TIE_TOL) are left out of the ray-caster comparisons as in
 * the other suites; their number is printed and must stay under 1%.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEED 0x5C0A7C0700000011ull

/* ---------------- shared helpers ---------------- */

static unsigned long g_raycast_bad, g_renders;

static void ctx_init_flags(zt_ctx *c, int w, int h, int tris, int verts, int edges,
                           uint16_t flags)
{
    memset(c, 0, sizeof *c);
    c->cfg = zs_config_default((uint16_t)w, (uint16_t)h, (uint16_t)tris, (uint16_t)verts,
                               (uint16_t)edges);
    c->cfg.flags = flags;
    c->arena_size = zs_arena_bytes(&c->cfg);
    ZT_CHECK(c->arena_size > 0, "zs_arena_bytes == 0 for %dx%d flags %u", w, h, flags);
    c->arena = malloc(c->arena_size);
    ZT_CHECK(c->arena != NULL, "out of memory");
    ZT_ST(zs_init(&c->r, c->arena, c->arena_size, &c->cfg), ZS_OK);
}

/* One frame of nm meshes (all with model, which may be NULL) in shading sp,
 * rendered with zs_render_rows in bands of band rows into img; records into
 * recs when it is not NULL; the statistics into st when it is not NULL. */
static void render(zt_ctx *c, const zs_camera *cam, zs_visibility mode, const zs_shade_params *sp,
                   const zs_mesh *m, int nm, const zs_mat34 *model, zt_recs *recs, uint8_t *img,
                   int band, zs_stats *st)
{
    if (recs) {
        zt_recs_clear(recs);
        zs_set_setup_hook(&c->r, zt_recs_hook, recs);
    } else {
        zs_set_setup_hook(&c->r, NULL, NULL);
    }
    ZT_ST(zs_frame_begin(&c->r, cam, mode), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, sp), ZS_OK);
    for (int i = 0; i < nm; i++)
        ZT_ST(zs_draw(&c->r, &m[i], model), ZS_OK);
    ZT_ST(zt_render_rows_all(&c->r, img, c->cfg.width, c->cfg.height, sp->format, band), ZS_OK);
    zs_set_setup_hook(&c->r, NULL, NULL);
    if (st)
        *st = *zs_frame_stats(&c->r);
    g_renders++;
}

static zs_shade_params shade(zs_format f, zs_shading s, zs_color bg)
{
    zs_shade_params sp = zs_shade_default();
    sp.format = f;
    sp.shading = s;
    sp.background = bg;
    return sp;
}

/* Fails with the first differing pixel of two images. */
static void same_image(const uint8_t *a, const uint8_t *b, int w, int h, zs_format f,
                       const char *what)
{
    size_t bpp = zs_format_bytes(f);
    long d = zt_first_diff(a, b, (size_t)w * (size_t)h * bpp);
    if (d >= 0) {
        long px = d / (long)bpp;
        ZT_FAIL("%s: format %d differs at pixel (%ld,%ld): byte %02x vs %02x", what, (int)f,
                px % w, px / w, a[d], b[d]);
    }
}

static int first_row_of(int32_t y) /* first pixel row at or below 28.4 y, like the core's rule */
{
    return (int)floor((y + 7) / 16.0);
}

static zs_color rand_color(zt_rng *g) { return (zs_color)(zt_u32(g) & 0xFFFFFFu); }

/* ================= 1. box_inside ================= */

#define BX_MAXV 16
#define BX_REPS_MARGIN 10 /* scenes per screen and guard plane with the margin turn */
#define BX_MAXT 16

typedef struct bmesh {
    int16_t pos[3 * BX_MAXV];
    uint16_t idx[3 * BX_MAXT];
    zs_color vcol[BX_MAXV], fcol[BX_MAXT];
    int nv, nt;
} bmesh;

static zs_mesh bmesh_view(const bmesh *b, zs_fixed scale)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = b->pos;
    m.indices = b->idx;
    m.face_colors = b->fcol;
    m.vertex_colors = b->vcol;
    m.scale = scale;
    m.vertex_count = (uint16_t)b->nv;
    m.triangle_count = (uint16_t)b->nt;
    return m;
}

/* A probe scene: eye-space points (world == eye: identity view), the model
 * matrix (rotation then translation by (0, 0, -d0)), and what moves. */
typedef struct bscene {
    int w, h, guard;
    zs_fixed near_q, far_q;
    double near_d, far_d;
    int plane;          /* 0 near, 1 far, 2 right, 3 left, 4 top, 5 bottom */
    int turn;           /* 0 identity, 1 slight, 2 random */
    int extra_kind;     /* 0 behind the eye, 1 beyond far */
    double rot[3][3];   /* the model matrix's 3x3 as the renderer has it */
    zs_mat34 model;
    int32_t d0;         /* Q16 */
    int32_t scale;      /* Q16, the mesh's */
    int ncore;
    double core_m[6][3];  /* model coordinates (position units, unrounded) */
    double pin_m[3], pout_m[3];
    double extra_m[3];
    int steps;            /* probe positions 0 (inside) .. steps (outside) */
    int shift[3];         /* added to the probe (and companions): the margin sweep */
    int sweep_axis, sweep_dir;
    int ncomp;
    int comp[8][3];       /* companion offsets from the probe, position units */
    int tri[BX_MAXT][3];  /* indices: core 0..ncore-1, probe ncore, companions after */
    int ntri;
    zs_color vcol[BX_MAXV], fcol[BX_MAXT];
} bscene;

static int guard_of(int w, int h)
{
    /* documented in zs_internal.h: min(4, 32767 / (8 * max(w, h)) - 1) */
    int dim = w > h ? w : h;
    int g = 32767 / (8 * dim) - 1;
    return g > 4 ? 4 : g;
}

/* eye point -> model coordinates in position units (unrounded) */
static void eye_to_model(const bscene *s, const double e[3], double out[3])
{
    double t[3] = {e[0], e[1], e[2] + s->d0 / 65536.0};
    for (int j = 0; j < 3; j++)
        out[j] = (s->rot[0][j] * t[0] + s->rot[1][j] * t[1] + s->rot[2][j] * t[2]) * 65536.0 /
                 s->scale;
}

static void model_to_eye(const bscene *s, const double p[3], double out[3])
{
    for (int k = 0; k < 3; k++) {
        out[k] = 0;
        for (int j = 0; j < 3; j++)
            out[k] += s->rot[k][j] * p[j] * s->scale / 65536.0;
    }
    out[2] -= s->d0 / 65536.0;
}

static int16_t q16s(double v)
{
    double r = floor(v + 0.5);
    if (r > 32767) r = 32767;
    if (r < -32768) r = -32768;
    return (int16_t)r;
}

static void probe_pos(const bscene *s, int t, int16_t out[3])
{
    for (int j = 0; j < 3; j++)
        out[j] = q16s(s->pin_m[j] + (s->pout_m[j] - s->pin_m[j]) * t / s->steps);
}

/* The mesh with the probe at step t; with_extra appends the unused vertex. */
static void bscene_mesh(const bscene *s, int t, int with_extra, bmesh *b)
{
    int n = 0;
    for (int i = 0; i < s->ncore; i++, n++)
        for (int j = 0; j < 3; j++)
            b->pos[3 * n + j] = q16s(s->core_m[i][j]);
    int16_t p[3];
    probe_pos(s, t, p);
    for (int j = 0; j < 3; j++)
        p[j] = q16s((double)p[j] + s->shift[j]);
    memcpy(&b->pos[3 * n], p, sizeof p);
    n++;
    for (int c = 0; c < s->ncomp; c++, n++)
        for (int j = 0; j < 3; j++)
            b->pos[3 * n + j] = q16s((double)p[j] + s->comp[c][j]);
    if (with_extra) {
        for (int j = 0; j < 3; j++)
            b->pos[3 * n + j] = q16s(s->extra_m[j]);
        n++;
    }
    b->nv = n;
    for (int i = 0; i < n; i++)
        b->vcol[i] = s->vcol[i];
    b->nt = s->ntri;
    for (int k = 0; k < s->ntri; k++) {
        for (int j = 0; j < 3; j++)
            b->idx[3 * k + j] = (uint16_t)s->tri[k][j];
        b->fcol[k] = s->fcol[k];
    }
}

/* Orders triangle (a, b, c) front-facing for the eye at the origin, from the
 * eye positions of the mesh at step t. */
static void add_tri_front(bscene *s, const bmesh *b, int a, int bb, int c)
{
    double e[3][3];
    int id[3] = {a, bb, c};
    for (int k = 0; k < 3; k++) {
        double p[3] = {b->pos[3 * id[k]], b->pos[3 * id[k] + 1], b->pos[3 * id[k] + 2]};
        model_to_eye(s, p, e[k]);
    }
    double u[3], v[3], nrm[3];
    for (int j = 0; j < 3; j++) {
        u[j] = e[1][j] - e[0][j];
        v[j] = e[2][j] - e[0][j];
    }
    nrm[0] = u[1] * v[2] - u[2] * v[1];
    nrm[1] = u[2] * v[0] - u[0] * v[2];
    nrm[2] = u[0] * v[1] - u[1] * v[0];
    double dot = -(nrm[0] * e[0][0] + nrm[1] * e[0][1] + nrm[2] * e[0][2]);
    int k = s->ntri++;
    s->tri[k][0] = a;
    s->tri[k][1] = dot >= 0 ? bb : c;
    s->tri[k][2] = dot >= 0 ? c : bb;
}

/* Gradient (model coordinates, up to a positive factor) of the probed
 * plane's function, which grows outward: near - w, w - far, +-xc - guard w,
 * +-yc - guard w. */
static void plane_gradient(const bscene *s, double aspect, double gl[3])
{
    for (int j = 0; j < 3; j++) {
        double gx = s->rot[0][j] / aspect, gy = s->rot[1][j], gz = s->rot[2][j];
        int p = s->plane;
        gl[j] = p == 0 ? gz : p == 1 ? -gz : p == 2 ? gx + s->guard * gz
                : p == 3 ? -gx + s->guard * gz : p == 4 ? gy + s->guard * gz
                                                        : -gy + s->guard * gz;
    }
}

static void set_rot(bscene *s, const zs_mat34 *rot)
{
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++)
            s->rot[k][j] = rot->m[k][j] / 65536.0;
}

/* The finest mesh scale (Q16) that keeps the n eye points within 30000
 * position units. */
static int32_t fit_scale(bscene *s, const double (*pts)[3], int n)
{
    double ext = 0, m[3];
    s->scale = 1; /* eye_to_model then gives 1/65536 world units */
    for (int i = 0; i < n; i++) {
        eye_to_model(s, pts[i], m);
        for (int j = 0; j < 3; j++)
            ext = fabs(m[j]) > ext ? fabs(m[j]) : ext;
    }
    int32_t sc = (int32_t)ceil(ext / 30000.0);
    return sc < 1 ? 1 : sc;
}

static void bscene_make(zt_rng *g, bscene *s, int screen, int plane, int turn)
{
    static const int sizes[3][2] = {{64, 48}, {900, 12}, {1024, 12}};
    memset(s, 0, sizeof *s);
    s->w = sizes[screen][0];
    s->h = sizes[screen][1];
    s->guard = guard_of(s->w, s->h);
    s->plane = plane;
    s->turn = turn;
    static const double nears[3] = {0.1, 0.25, 0.5};
    s->near_q = (zs_fixed)floor(nears[zt_below(g, 3)] * 65536 + 0.5);
    s->near_d = s->near_q / 65536.0;
    double aspect = (double)s->w / s->h, N = s->near_d;
    /* probe depth for guard planes; the margin turn tilts w along the box by
     * up to (guard - 1) / guard of it, so it is kept well beyond near and far */
    double D = N * (turn == 3 ? zt_uniform(g, 6, 10) : zt_uniform(g, 1.1, 2.0));
    double F = plane == 1 ? N * zt_uniform(g, 3, 8)
                          : D * (turn == 3 ? zt_uniform(g, 6, 10) : zt_uniform(g, 3, 6));
    s->far_q = (zs_fixed)floor(F * 65536 + 0.5);
    s->far_d = s->far_q / 65536.0;
    F = s->far_d;
    /* core depths and probe endpoints in eye space */
    double clo, chi, pin[3], pout[3];
    double u = zt_uniform(g, -1, 1), v = zt_uniform(g, -1, 1);
    if (plane == 0) {
        clo = 1.2 * N;
        chi = 2.5 * N;
        double x = 0.5 * u * N * aspect, y = 0.5 * v * N;
        double p0[3] = {x, y, -1.03 * N}, p1[3] = {x, y, -0.97 * N};
        memcpy(pin, p0, sizeof p0);
        memcpy(pout, p1, sizeof p1);
    } else if (plane == 1) {
        clo = 0.5 * F;
        chi = 0.9 * F;
        double x = 0.5 * u * F * aspect, y = 0.5 * v * F;
        double p0[3] = {x, y, -0.97 * F}, p1[3] = {x, y, -1.03 * F};
        memcpy(pin, p0, sizeof p0);
        memcpy(pout, p1, sizeof p1);
    } else {
        clo = 1.05 * D;
        chi = 1.6 * D;
        /* the guard plane: |xc| = guard w with xc = x / aspect (fov 90),
         * |yc| = guard w with yc = y */
        int ax = plane <= 3 ? 0 : 1;
        double sign = (plane == 2 || plane == 4) ? 1 : -1;
        double lim = s->guard * D * (ax == 0 ? aspect : 1.0);
        double other = 0.5 * u * D * (ax == 0 ? 1.0 : aspect);
        pin[ax] = sign * 0.97 * lim;
        pout[ax] = sign * 1.03 * lim;
        pin[1 - ax] = pout[1 - ax] = other;
        pin[2] = pout[2] = -D;
    }
    /* core vertices: on screen, within 0.6 of the frustum at their depth */
    s->ncore = 3 + (int)zt_below(g, 3);
    double core_e[6][3];
    for (int i = 0; i < s->ncore; i++) {
        double d = zt_uniform(g, clo, chi);
        double spread = turn == 2 ? 0.6 : 0.3;
        core_e[i][0] = zt_uniform(g, -spread, spread) * d * aspect;
        core_e[i][1] = zt_uniform(g, -spread, spread) * d;
        core_e[i][2] = -d;
        if (turn == 3) {
            /* compact, by the screen's edge on the probe's side, so the
             * turn's tilt of w over the box stays small */
            d = zt_uniform(g, D, 1.1 * D);
            int ax = plane <= 3 ? 0 : 1;
            double sign = (plane == 2 || plane == 4) ? 1 : -1;
            core_e[i][ax] = sign * zt_uniform(g, 0.6, 0.95) * d * (ax == 0 ? aspect : 1.0);
            core_e[i][1 - ax] = zt_uniform(g, -0.3, 0.3) * d * (ax == 1 ? aspect : 1.0);
            core_e[i][2] = -d;
        }
    }
    s->extra_kind = (int)zt_below(g, 2);
    double extra_e[3] = {0, 0, s->extra_kind == 0 ? 0.5 * N : -1.6 * F};
    /* translation near the middle of the depths */
    double dmid = 0.5 * (clo + (plane == 1 ? 1.03 * F : chi));
    s->d0 = (int32_t)floor(dmid * 65536 + 0.5);
    double pts[9][3];
    int np = 0;
    for (int i = 0; i < s->ncore; i++, np++)
        memcpy(pts[np], core_e[i], sizeof pts[np]);
    memcpy(pts[np++], pin, sizeof pts[0]);
    memcpy(pts[np++], pout, sizeof pts[0]);
    memcpy(pts[np++], extra_e, sizeof pts[0]);
    /* model rotation: identity; a slight turn (a few degrees); any; or
     * (turn 3, guard planes) a turn about one axis that leaves the probed
     * guard function xc - guard w growing by only 0.1 to 1.5 Q16 units per
     * position unit along another axis, though xc and w each change by many:
     * where the box's corner and a vertex differ only along that axis, their
     * roundings can put the vertex outside and the corner inside by up to
     * 1 + guard units, which INSIDE_MARGIN covers */
    zs_mat34 rot = zs_mat34_identity();
    set_rot(s, &rot);
    if (turn == 1 || turn == 2) {
        double lim = turn == 1 ? 3.0 : 180.0;
        zs_mat34 rx = zs_mat34_rotate_x((zs_fixed)(zt_uniform(g, -lim, lim) * 65536));
        zs_mat34 ry = zs_mat34_rotate_y((zs_fixed)(zt_uniform(g, -lim, lim) * 65536));
        zs_mat34 rz = zs_mat34_rotate_z((zs_fixed)(zt_uniform(g, -lim, lim) * 65536));
        zs_mat34 t1 = zs_mat34_mul(&ry, &rx);
        rot = zs_mat34_mul(&rz, &t1);
    } else if (turn == 3) {
        /* about y for the x guard planes, about x for the y ones, to the
         * angle where the function's gradient along model x (resp. y) is
         * the target: bracketed by a scan, then bisected */
        int32_t sc = fit_scale(s, (const double (*)[3])pts, np);
        /* growing outward (the probe's side), so the core stays behind */
        double target = zt_uniform(g, 0.1, 1.5) * ((plane == 2 || plane == 4) ? 1 : -1) / sc;
        int k = plane <= 3 ? 0 : 1;
        double prev = 0, lo = 0, hi = 0, gl[3];
        int found = 0;
        for (double deg = -80; deg <= 80 && !found; deg += 0.25) {
            zs_mat34 r1 = k == 0 ? zs_mat34_rotate_y((zs_fixed)(deg * 65536))
                                 : zs_mat34_rotate_x((zs_fixed)(deg * 65536));
            set_rot(s, &r1);
            plane_gradient(s, aspect, gl);
            double f = gl[k] - target;
            if (deg > -80 && (f > 0) != (prev > 0)) {
                lo = deg - 0.25;
                hi = deg;
                found = 1;
            }
            prev = f;
        }
        ZT_CHECK(found, "no turn gives the gradient %g", target);
        for (int it = 0; it < 40; it++) {
            double mid = 0.5 * (lo + hi);
            zs_mat34 r1 = k == 0 ? zs_mat34_rotate_y((zs_fixed)(mid * 65536))
                                 : zs_mat34_rotate_x((zs_fixed)(mid * 65536));
            zs_mat34 r0 = k == 0 ? zs_mat34_rotate_y((zs_fixed)(lo * 65536))
                                 : zs_mat34_rotate_x((zs_fixed)(lo * 65536));
            set_rot(s, &r0);
            plane_gradient(s, aspect, gl);
            double flo = gl[k] - target;
            set_rot(s, &r1);
            plane_gradient(s, aspect, gl);
            if ((gl[k] - target > 0) == (flo > 0))
                lo = mid;
            else
                hi = mid;
        }
        rot = k == 0 ? zs_mat34_rotate_y((zs_fixed)(lo * 65536))
                     : zs_mat34_rotate_x((zs_fixed)(lo * 65536));
    }
    set_rot(s, &rot);
    s->scale = fit_scale(s, (const double (*)[3])pts, np);
    /* identity turn: w = d0 - scale * pz exactly (no rounding anywhere), so
     * d0 is moved to put near (or far) on a representable w */
    if (turn == 0 && plane <= 1) {
        int32_t target = plane == 0 ? s->near_q : s->far_q;
        int32_t rem = ((s->d0 - target) % s->scale + s->scale) % s->scale;
        s->d0 -= rem;
    }
    zs_mat34 tr = zs_mat34_translate(0, 0, -s->d0);
    s->model = zs_mat34_mul(&tr, &rot);
    for (int i = 0; i < s->ncore; i++)
        eye_to_model(s, core_e[i], s->core_m[i]);
    eye_to_model(s, pin, s->pin_m);
    eye_to_model(s, pout, s->pout_m);
    eye_to_model(s, extra_e, s->extra_m);
    double gl[3];
    plane_gradient(s, aspect, gl);
    if (turn != 2) {
        /* keep the core behind the probe in every model coordinate along
         * which the probed plane's function grows (outward), so the box's
         * outermost corner is the probe's, give or take the companions */
        for (int i = 0; i < s->ncore; i++)
            for (int j = 0; j < 3; j++) {
                if (fabs(gl[j]) < 1e-9) continue;
                double ref = gl[j] > 0 ? fmin(s->pin_m[j], s->pout_m[j])
                                       : fmax(s->pin_m[j], s->pout_m[j]);
                if ((s->core_m[i][j] - ref) * gl[j] > 0)
                    s->core_m[i][j] = 2 * ref - s->core_m[i][j];
            }
    }
    double span = 0;
    for (int j = 0; j < 3; j++)
        span = fabs(s->pout_m[j] - s->pin_m[j]) > span ? fabs(s->pout_m[j] - s->pin_m[j]) : span;
    s->steps = (int)ceil(span);
    if (s->steps < 2) s->steps = 2;
    s->ncomp = (int)zt_below(g, 3);
    if (turn == 3) {
        /* companions outward of the probe along the axis of small gradient */
        int k = plane <= 3 ? 0 : 1;
        /* a row of them along that axis, out to 1..4 units on either side:
         * the probe and most companions are then inside the box along it,
         * not at a corner, and each rounds its own way */
        int nout = 1 + (int)zt_below(g, 4), nin = 1 + (int)zt_below(g, 4);
        s->sweep_axis = k;
        s->sweep_dir = gl[k] > 0 ? 1 : -1;
        s->ncomp = 0;
        for (int m = -nin; m <= nout; m++) {
            if (m == 0) continue;
            memset(s->comp[s->ncomp], 0, sizeof s->comp[0]);
            s->comp[s->ncomp++][k] = gl[k] > 0 ? m : -m;
        }
    }
    for (int c = 0; c < s->ncomp && turn != 3; c++) {
        do {
            for (int j = 0; j < 3; j++)
                s->comp[c][j] = (int)zt_range(g, -2, 2);
            /* identity turn, near or far: companions no nearer the plane
             * than the probe, which alone decides the boundary */
            if (turn == 0 && plane == 0 && s->comp[c][2] > 0) s->comp[c][2] = -s->comp[c][2];
            if (turn == 0 && plane == 1 && s->comp[c][2] < 0) s->comp[c][2] = -s->comp[c][2];
        } while (!s->comp[c][0] && !s->comp[c][1] && !s->comp[c][2]);
    }
    for (int i = 0; i < BX_MAXV; i++)
        s->vcol[i] = rand_color(g);
    /* triangles, oriented from the mesh at the middle step */
    bmesh b;
    s->ntri = 0;
    bscene_mesh(s, s->steps / 2, 0, &b);
    int pr = s->ncore;
    add_tri_front(s, &b, 0, 1, 2);
    for (int i = 0; i + 1 < s->ncore; i++)
        add_tri_front(s, &b, i, i + 1, pr);
    add_tri_front(s, &b, s->ncore - 1, 0, pr);
    for (int c = 0; c < s->ncomp; c++)
        add_tri_front(s, &b, pr, pr + 1 + c, (int)zt_below(g, (uint32_t)s->ncore));
    for (int k = 0; k < s->ntri; k++)
        s->fcol[k] = rand_color(g);
}

/* The outcode path's verdict: does the probe mesh need clipping at step t?
 * (With the unused vertex outside, box_inside cannot pass.) */
static int needs_clip(zt_ctx *c, const zs_camera *cam, const bscene *s, int t)
{
    bmesh b;
    bscene_mesh(s, t, 1, &b);
    zs_mesh m = bmesh_view(&b, s->scale);
    zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
    zs_set_setup_hook(&c->r, NULL, NULL);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw(&c->r, &m, &s->model), ZS_OK);
    return zs_frame_stats(&c->r)->tris_clipped > 0;
}

/* Draws mesh m (no rows rendered) with the hook into recs; statistics into st. */
static void draw_only(zt_ctx *c, const zs_camera *cam, const zs_mesh *m, const zs_mat34 *model,
                      zt_recs *recs, zs_stats *st)
{
    zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
    zt_recs_clear(recs);
    zs_set_setup_hook(&c->r, zt_recs_hook, recs);
    ZT_ST(zs_frame_begin(&c->r, cam, ZS_MODE_SPAN), ZS_OK);
    ZT_ST(zs_frame_shading(&c->r, &sp), ZS_OK);
    ZT_ST(zs_draw(&c->r, m, model), ZS_OK);
    zs_set_setup_hook(&c->r, NULL, NULL);
    *st = *zs_frame_stats(&c->r);
}

/* Estimated in double (independent of the core's arithmetic): is the box of
 * mesh b inside near, far and the guard band by more than 2^-10 units? */
static int box_inside_estimate(const bscene *s, const bmesh *b)
{
    double lo[3], hi[3];
    for (int j = 0; j < 3; j++) {
        lo[j] = hi[j] = b->pos[j];
        for (int i = 1; i < b->nv; i++) {
            double v = b->pos[3 * i + j];
            lo[j] = v < lo[j] ? v : lo[j];
            hi[j] = v > hi[j] ? v : hi[j];
        }
    }
    /* 16 Q16 units plus the estimate's own error (proj_sx in Q16) */
    const double aspect = (double)s->w / s->h;
    for (int k = 0; k < 8; k++) {
        double p[3] = {(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]};
        double e[3];
        model_to_eye(s, p, e);
        double w = -e[2], xc = e[0] / aspect, yc = e[1];
        double eps = 16.0 / 65536 + 4e-5 * (fabs(xc) + fabs(yc) + w);
        if (w < s->near_d + eps || w > s->far_d - eps) return 0;
        if (fabs(xc) > s->guard * w - eps || fabs(yc) > s->guard * w - eps) return 0;
    }
    return 1;
}

static void same_stats(const zs_stats *a, const zs_stats *b, const char *what)
{
#define SAME(f) ZT_CHECK(a->f == b->f, "%s: stats." #f " %u without the unused vertex, %u with it", \
                         what, a->f, b->f)
    SAME(tris_submitted);
    SAME(tris_culled);
    SAME(tris_rejected);
    SAME(tris_clipped);
    SAME(tris_empty);
    SAME(tris_dropped);
    SAME(tris_stored);
    SAME(records);
    SAME(tris_drawn);
    SAME(verts_dropped);
    SAME(records_skipped);
    SAME(saturated);
    SAME(rows);
    SAME(spans);
    SAME(max_active_edges);
    SAME(depth_evals);
    SAME(crossings);
    SAME(pixels_shaded);
#undef SAME
    ZT_CHECK(b->verts_stored == a->verts_stored + 1, "%s: verts_stored %u and %u (with the unused "
             "vertex)", what, a->verts_stored, b->verts_stored);
}

static void same_recs(const zt_recs *a, const zt_recs *b, const char *what)
{
    ZT_CHECK(a->n == b->n, "%s: %zu records without the unused vertex, %zu with it", what, a->n,
             b->n);
    for (size_t i = 0; i < a->n; i++)
        ZT_CHECK(a->v[i].tag == b->v[i].tag && !memcmp(a->v[i].xy, b->v[i].xy, sizeof a->v[i].xy) &&
                     !memcmp(a->v[i].z, b->v[i].z, sizeof a->v[i].z),
                 "%s: record %zu differs with the unused vertex (tag %u vs %u)", what, i,
                 a->v[i].tag, b->v[i].tag);
}

static unsigned long g_bx_scenes, g_bx_probes, g_bx_inside, g_bx_outside, g_bx_fast,
    g_bx_exact_near, g_bx_exact_far, g_bx_redrawn, g_bx_slides;

static void test_box_inside(void **state)
{
    (void)state;
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xB0C5);
    static const int ks[] = {-60, -24, -12, -9, -8, -7, -6, -5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 8};
    const int nks = (int)(sizeof ks / sizeof ks[0]);
    zt_recs ra = {0}, rb = {0};
    for (int screen = 0; screen < 3; screen++) {
        int w = screen == 0 ? 64 : screen == 1 ? 900 : 1024, h = screen == 0 ? 48 : 12;
        zt_ctx c;
        zt_ctx_init(&c, w, h, 64, 64, 64);
        zt_gframe *fa = zt_gframe_new(w, h), *fb = zt_gframe_new(w, h);
        size_t n565 = (size_t)w * h * 2;
        uint8_t *ia = malloc(n565), *ib = malloc(n565);
        for (int rep = 0; rep < BX_REPS_MARGIN; rep++)
            for (int plane = 0; plane < 6; plane++)
                for (int turn = 0; turn < 4; turn++) {
                    if (turn == 3 && plane < 2) continue; /* near and far need no margin */
                    if (turn < 3 && rep >= 2) continue;
                    bscene s;
                    zs_camera cam;
                    char what[160];
                    int tries = 0;
                    /* a scene whose ends are inside and outside by the outcode
                     * path (a turned core may itself reach outside: drawn again) */
                    for (;;) {
                        bscene_make(&g, &s, screen, plane, turn);
                        ZT_CHECK(s.guard >= 2 && s.guard <= 4, "guard %d", s.guard);
                        zs_mat34 id = zs_mat34_identity();
                        ZT_ST(zs_camera_set_view(&cam, &id), ZS_OK);
                        ZT_ST(zs_camera_perspective(&cam, ZS_FX(90), s.near_q, s.far_q), ZS_OK);
                        snprintf(what, sizeof what,
                                 "box scene %dx%d plane %d turn %d rep %d try %d (seed %llx)", w, h,
                                 plane, turn, rep, tries, (unsigned long long)SEED);
                        if (!needs_clip(&c, &cam, &s, 0) && needs_clip(&c, &cam, &s, s.steps))
                            break;
                        g_bx_redrawn++;
                        ZT_CHECK(++tries < 50, "%s: no usable probe scene in 50 tries", what);
                    }
                    /* the first step that needs clipping, by bisection */
                    int lo = 0, hi = s.steps;
                    while (hi - lo > 1) {
                        int mid = (lo + hi) / 2;
                        if (needs_clip(&c, &cam, &s, mid))
                            hi = mid;
                        else
                            lo = mid;
                    }
                    if (turn == 0 && plane <= 1) {
                        /* w = d0 - scale * pz exactly: the last inside is on the plane */
                        int16_t p[3];
                        probe_pos(&s, lo, p);
                        int64_t wq = (int64_t)s.d0 - (int64_t)s.scale * p[2];
                        int64_t want = plane == 0 ? s.near_q : s.far_q;
                        ZT_CHECK(wq == want, "%s: last position inside has w %lld (Q16), the plane "
                                 "is at %lld", what, (long long)wq, (long long)want);
                        if (plane == 0) g_bx_exact_near++;
                        else g_bx_exact_far++;
                    }
                    g_bx_scenes++;
                    /* turn 3: every step from 6 inside to 6 outside the boundary */
                    int nprobe = turn == 3 ? 13 : nks + 2;
                    for (int ki = 0; ki < nprobe; ki++) {
                        int t = turn == 3 ? hi - 6 + ki : ki < nks ? hi + ks[ki] : ki == nks ? 0 : s.steps;
                        if (t < 0 || t > s.steps) continue;
                        bmesh a, b;
                        bscene_mesh(&s, t, 0, &a);
                        bscene_mesh(&s, t, 1, &b);
                        zs_mesh ma = bmesh_view(&a, s.scale), mb = bmesh_view(&b, s.scale);
                        char pw[200];
                        snprintf(pw, sizeof pw, "%s step %d (boundary %d)", what, t, hi);
                        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &ma, 1, &s.model, fa, 1 + ki % 5);
                        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &mb, 1, &s.model, fb, 1 + ki % 5);
                        ZT_ST(fa->draw_st, ZS_OK);
                        ZT_ST(fb->draw_st, ZS_OK);
                        same_image(fa->img, fb->img, w, h, ZS_FMT_ID16, pw);
                        same_recs(&fa->recs, &fb->recs, pw);
                        same_stats(&fa->st, &fb->st, pw);
                        bad += zt_vs_raycast(fa, pw);
                        /* colours: flat face colours or Gouraud vertex colours */
                        zs_shade_params sp = shade(ZS_FMT_RGB565, ki % 2 ? ZS_SHADE_GOURAUD
                                                                         : ZS_SHADE_FLAT, 0x102030);
                        zs_stats sa, sb;
                        render(&c, &cam, ZS_MODE_SPAN, &sp, &ma, 1, &s.model, &ra, ia, h, &sa);
                        render(&c, &cam, ZS_MODE_SPAN, &sp, &mb, 1, &s.model, &rb, ib, h, &sb);
                        same_image(ia, ib, w, h, ZS_FMT_RGB565, pw);
                        same_recs(&ra, &rb, pw);
                        same_stats(&sa, &sb, pw);
                        render(&c, &cam, ZS_MODE_ZLINE, &sp, &ma, 1, &s.model, NULL, ib, h, NULL);
                        same_image(ia, ib, w, h, ZS_FMT_RGB565, pw);
                        g_bx_probes++;
                        if (fa->st.tris_clipped) g_bx_outside++;
                        else g_bx_inside++;
                        g_bx_fast += box_inside_estimate(&s, &a);
                    }
                    if (turn == 3) {
                        /* from the last step inside, the probe and its row of
                         * companions slide outward along the axis of small
                         * gradient, a unit at a time (each rounding afresh),
                         * until 12 slides in a row needed clipping: every
                         * draw as it is and with the unused vertex must store
                         * the same records and count the same */
                        int run = 0;
                        for (int u = 0; u < 400 && run < 12; u++) {
                            s.shift[s.sweep_axis] = u * s.sweep_dir;
                            bmesh a, b;
                            bscene_mesh(&s, hi - 1, 0, &a);
                            bscene_mesh(&s, hi - 1, 1, &b);
                            zs_mesh ma = bmesh_view(&a, s.scale), mb = bmesh_view(&b, s.scale);
                            zs_stats sa, sb;
                            char pw[200];
                            snprintf(pw, sizeof pw, "%s step %d slid %d", what, hi - 1, u);
                            draw_only(&c, &cam, &ma, &s.model, &ra, &sa);
                            draw_only(&c, &cam, &mb, &s.model, &rb, &sb);
                            same_recs(&ra, &rb, pw);
                            same_stats(&sa, &sb, pw);
                            run = sa.tris_clipped ? run + 1 : 0;
                            g_bx_slides++;
                        }
                        s.shift[s.sweep_axis] = 0;
                    }
                }
        free(ia);
        free(ib);
        zt_gframe_free(fa);
        zt_gframe_free(fb);
        zt_ctx_free(&c);
    }
    zt_recs_free(&ra);
    zt_recs_free(&rb);
    ZT_CHECK(g_bx_fast > 0, "no probe mesh had its box inside: the fast path was not exercised");
    g_raycast_bad += bad;
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster", bad);
}

/* ================= 2. counting sort of new edges ================= */

#define CS_W 640
#define CS_H 36
#define CS_SCENES 40

static unsigned long g_cs_scenes, g_cs_tris, g_cs_bytes, g_cs_rows_counted, g_cs_max_batch,
    g_cs_left, g_cs_right;

/* A vertex on the batch row yr (first covered row yr: y within 0.35 px of
 * its centre). */
static double on_row(zt_rng *g, int yr) { return yr + zt_uniform(g, -0.35, 0.35); }

/* Triangles whose top vertex lies on row yr, appended to sc until it holds
 * at least `target` more: fans (shared edges from the apex), strips of quads
 * (every inner edge shared), loose triangles with their own depth per vertex;
 * tops from 150 px left of the screen to 150 px right of it. */
static void cs_batch(zt_rng *g, zt_scene *sc, int target, int yr)
{
    size_t start = sc->nt;
    while ((int)(sc->nt - start) < target) {
        int kind = (int)zt_below(g, 4);
        double d = zt_uniform(g, 1.0, 3.6);
        double ax = zt_uniform(g, -150, CS_W + 150);
        if (kind == 3) { /* by a screen edge: first columns 0, -1, width - 1, width */
            kind = (int)zt_below(g, 3);
            ax = zt_below(g, 2) ? zt_uniform(g, -1.5, 1.5) : CS_W + zt_uniform(g, -1.5, 1.5);
        }
        if (kind == 0) { /* fan */
            int m = 3 + (int)zt_below(g, 6), apex, rim[9];
            double R = zt_uniform(g, 10, 150), Ry = zt_uniform(g, 4, 30), ay = on_row(g, yr);
            apex = zt_scene_vertex_px(sc, ax, ay, d, rand_color(g));
            for (int i = 0; i < m; i++) {
                double th = 3.141592653589793 * (0.1 + 0.8 * (i + zt_uniform(g, 0.1, 0.9)) / m);
                rim[i] = zt_scene_vertex_px(sc, ax + R * cos(th), ay + 1.5 + Ry * sin(th),
                                            d * (1 + zt_uniform(g, -0.25, 0.25)), rand_color(g));
            }
            for (int i = 0; i + 1 < m; i++)
                zt_scene_tri_front(sc, apex, rim[i], rim[i + 1], rand_color(g));
        } else if (kind == 1) { /* strip of quads, each split in two */
            int n = 2 + (int)zt_below(g, 10), A[13], B[13];
            double dx = zt_uniform(g, 4, 30), tx = zt_uniform(g, -0.3, 0.3),
                   ty = zt_uniform(g, -0.3, 0.3), drop = zt_uniform(g, 4, 30);
            for (int i = 0; i <= n; i++) {
                double x = ax + i * dx + zt_uniform(g, -0.3, 0.3) * dx;
                double yb = yr + drop + zt_uniform(g, -2, 2);
                A[i] = zt_scene_vertex_px(sc, x, on_row(g, yr), d * (1 + tx * i / n), rand_color(g));
                B[i] = zt_scene_vertex_px(sc, x + zt_uniform(g, -4, 4), yb,
                                          d * (1 + tx * i / n + ty), rand_color(g));
            }
            for (int i = 0; i < n; i++) {
                zt_scene_tri_front(sc, A[i], A[i + 1], B[i], rand_color(g));
                zt_scene_tri_front(sc, A[i + 1], B[i + 1], B[i], rand_color(g));
            }
        } else { /* loose, penetrating */
            int v0 = zt_scene_vertex_px(sc, ax, on_row(g, yr), d * exp(zt_uniform(g, -0.4, 0.4)),
                                        rand_color(g));
            int v1 = zt_scene_vertex_px(sc, ax + zt_uniform(g, -80, 80), yr + zt_uniform(g, 1, 30),
                                        d * exp(zt_uniform(g, -0.4, 0.4)), rand_color(g));
            int v2 = zt_scene_vertex_px(sc, ax + zt_uniform(g, -80, 80), yr + zt_uniform(g, 1, 30),
                                        d * exp(zt_uniform(g, -0.4, 0.4)), rand_color(g));
            zt_scene_tri_front(sc, v0, v1, v2, rand_color(g));
        }
    }
}

static void test_count_sort(void **state)
{
    (void)state;
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0xC5);
    zt_ctx c, cn;
    ctx_init_flags(&c, CS_W, CS_H, 1400, 4000, 2400, 0);
    ctx_init_flags(&cn, CS_W, CS_H, 1400, 4000, 2400, ZS_CFG_NO_ZLINE);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, CS_W, CS_H, 256);
    zt_gframe *f = zt_gframe_new(CS_W, CS_H);
    size_t cap = (size_t)CS_W * CS_H * 3;
    uint8_t *ref = malloc(cap), *img = malloc(cap);
    static const int targets[] = {25, 40, 70, 120, 200, 300};
    static const int bands[] = {1, 3, 8, CS_H};
    for (int k = 0; k < CS_SCENES; k++) {
        zt_scene_reset(&sc);
        int target = targets[k % 6] + (int)zt_below(&g, 10);
        if (target > 290) target = 290;
        int yr = k % 4 == 0 ? 0 : (int)zt_range(&g, 1, CS_H - 6);
        cs_batch(&g, &sc, target, yr);
        /* some fall off the screen or are culled: top up until at least 13
         * records (26 new edges) start on the row */
        for (int more = 0;; more++) {
            zs_mesh m0 = zt_scene_mesh(&sc, 1, 0);
            zt_recs rs = {0};
            zs_stats st;
            draw_only(&c, &cam, &m0, NULL, &rs, &st);
            int on_row = 0;
            for (size_t i = 0; i < rs.n; i++) {
                const int32_t *xy = rs.v[i].xy;
                int32_t ymin = xy[1] < xy[3] ? xy[1] : xy[3];
                ymin = ymin < xy[5] ? ymin : xy[5];
                int row = first_row_of(ymin);
                on_row += (row < 0 ? 0 : row) == yr;
            }
            zt_recs_free(&rs);
            ZT_CHECK(more < 30, "scene %d: cannot get 13 records onto row %d", k, yr);
            if (on_row >= 13) break;
            cs_batch(&g, &sc, 8, yr);
        }
        if (yr == 0) /* rows entered from above join row 0's batch */
            for (int i = 0; i < 6; i++) {
                int v0 = zt_scene_vertex_px(&sc, zt_uniform(&g, -100, CS_W + 100), -zt_uniform(&g, 2, 20),
                                            2.0, rand_color(&g));
                int v1 = zt_scene_vertex_px(&sc, zt_uniform(&g, -100, CS_W + 100), zt_uniform(&g, 5, 30),
                                            2.5, rand_color(&g));
                int v2 = zt_scene_vertex_px(&sc, zt_uniform(&g, -100, CS_W + 100), zt_uniform(&g, 5, 30),
                                            1.5, rand_color(&g));
                zt_scene_tri_front(&sc, v0, v1, v2, rand_color(&g));
            }
        /* and some triangles elsewhere, so the batch merges into a list */
        zt_scene_random(&g, &sc, 12, ZT_SC_PLAIN | ZT_SC_SHARED | ZT_SC_FLAT, 0.5);
        zs_mesh m = zt_scene_mesh(&sc, 1, 1);
        char what[120];
        snprintf(what, sizeof what, "count-sort scene %d (row %d, %zu triangles, seed %llx)", k, yr,
                 sc.nt, (unsigned long long)SEED);
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, bands[k % 4]);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(f->st.tris_dropped == 0 && f->st.records_skipped == 0 && f->st.verts_dropped == 0,
                 "%s: pools too small for the test", what);
        bad += zt_vs_raycast(f, what);
        /* the batch on row yr, from the records: two new edges each */
        int per_row[CS_H];
        memset(per_row, 0, sizeof per_row);
        for (size_t i = 0; i < f->recs.n; i++) {
            const int32_t *xy = f->recs.v[i].xy;
            int32_t ymin = xy[1] < xy[3] ? xy[1] : xy[3];
            ymin = ymin < xy[5] ? ymin : xy[5];
            int row = first_row_of(ymin);
            if (row < 0) row = 0;
            if (row < CS_H) per_row[row]++;
            if (row == yr) {
                int32_t xmin = xy[0] < xy[2] ? xy[0] : xy[2], xmax = xy[0] > xy[2] ? xy[0] : xy[2];
                xmin = xmin < xy[4] ? xmin : xy[4];
                xmax = xmax > xy[4] ? xmax : xy[4];
                g_cs_left += xmin < 0;
                g_cs_right += xmax > 16 * CS_W;
            }
        }
        int batch = 2 * per_row[yr];
        ZT_CHECK(batch > 24 && batch <= CS_W, "%s: %d new edges on row %d, not in the counting "
                 "sort's range 25..%d", what, batch, yr, CS_W);
        g_cs_rows_counted++;
        if ((unsigned long)batch > g_cs_max_batch) g_cs_max_batch = (unsigned long)batch;
        /* every format: span (with and without the z-buffer line's scratch)
         * against zline */
        zs_shading shading = k % 2 ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
        zs_color bg = rand_color(&g);
        for (int fi = 0; fi < ZS_FMT_COUNT; fi++) {
            zs_shade_params sp = shade((zs_format)fi, shading, bg);
            size_t n = (size_t)CS_W * CS_H * zs_format_bytes(sp.format);
            memset(ref, 0x5A, cap);
            render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, ref, CS_H, NULL);
            char w2[200];
            memset(img, 0xA5, cap);
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, bands[(k + fi) % 4], NULL);
            snprintf(w2, sizeof w2, "%s: span vs zline", what);
            same_image(ref, img, CS_W, CS_H, sp.format, w2);
            memset(img, 0xA5, cap);
            render(&cn, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, bands[(k + fi + 1) % 4], NULL);
            snprintf(w2, sizeof w2, "%s: span without the z-buffer line (insertion sort) vs zline",
                     what);
            same_image(ref, img, CS_W, CS_H, sp.format, w2);
            memset(img, 0xA5, cap);
            render(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, 1, NULL, NULL, img, bands[(k + fi + 2) % 4],
                   NULL);
            snprintf(w2, sizeof w2, "%s: Warnock vs zline", what);
            same_image(ref, img, CS_W, CS_H, sp.format, w2);
            g_cs_bytes += 2 * n;
        }
        g_cs_scenes++;
        g_cs_tris += sc.nt;
    }
    ZT_CHECK(g_cs_left > 0 && g_cs_right > 0, "no batch triangle reaches off the left (%lu) or "
             "right (%lu) of the screen", g_cs_left, g_cs_right);
    free(ref);
    free(img);
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    zt_ctx_free(&cn);
    g_raycast_bad += bad;
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster", bad);
}

/* ================= 3. planes evaluated per row ================= */

#define PL_W 56
#define PL_H 560
#define PL_SCENES 24

static unsigned long g_pl_scenes, g_pl_tris, g_pl_needles, g_pl_steep, g_pl_gouraud_px,
    g_pl_flat_px, g_pl_off_half, g_pl_flips;
static double g_pl_maxdev;

/* Window depth per pixel of a record's plane along x and y (double). */
static void rec_gradients(const zt_rec *t, double *zdx, double *zdy)
{
    double x0 = t->xy[0] / 16.0, y0 = t->xy[1] / 16.0, x1 = t->xy[2] / 16.0, y1 = t->xy[3] / 16.0,
           x2 = t->xy[4] / 16.0, y2 = t->xy[5] / 16.0;
    double z0 = t->z[0] / 1073741824.0, z1 = t->z[1] / 1073741824.0, z2 = t->z[2] / 1073741824.0;
    double a = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    *zdx = ((z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0)) / a;
    *zdy = ((z2 - z0) * (x1 - x0) - (z1 - z0) * (x2 - x0)) / a;
}

static void test_planes_per_row(void **state)
{
    (void)state;
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x9A);
    zt_ctx c;
    ctx_init_flags(&c, PL_W, PL_H, 64, 200, 64, 0);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, PL_W, PL_H, 4096);
    zt_gframe *f = zt_gframe_new(PL_W, PL_H);
    size_t n3 = (size_t)PL_W * PL_H * 3;
    uint8_t *ref = malloc(n3), *img = malloc(n3), *rgb = malloc(n3);
    static const int bands[] = {1, 3, 8, PL_H};
    for (int k = 0; k < PL_SCENES; k++) {
        zt_scene_reset(&sc);
        int ntall = 2 + (int)zt_below(&g, 4), npair = 1 + (int)zt_below(&g, 2),
            nneedle = 2 + (int)zt_below(&g, 4);
        int needle_first = -1;
        for (int i = 0; i < ntall; i++) { /* top to bottom, depths apart */
            int v0 = zt_scene_vertex_px(&sc, zt_uniform(&g, -5, PL_W + 5), zt_uniform(&g, -8, 3),
                                        zt_uniform(&g, 1.2, 6), rand_color(&g));
            int v1 = zt_scene_vertex_px(&sc, zt_uniform(&g, -5, PL_W + 5),
                                        zt_uniform(&g, PL_H - 3, PL_H + 8), zt_uniform(&g, 1.2, 6),
                                        rand_color(&g));
            int v2 = zt_scene_vertex_px(&sc, zt_uniform(&g, -10, PL_W + 10),
                                        zt_uniform(&g, 0.2 * PL_H, 0.8 * PL_H),
                                        zt_uniform(&g, 1.2, 6), rand_color(&g));
            zt_scene_tri_front(&sc, v0, v1, v2, rand_color(&g));
        }
        for (int i = 0; i < npair; i++) { /* near at the top and far at the bottom, and back */
            double xa = zt_uniform(&g, -10, 10), xb = PL_W + zt_uniform(&g, -10, 10);
            int a0 = zt_scene_vertex_px(&sc, xa, -4, 1.5, rand_color(&g));
            int a1 = zt_scene_vertex_px(&sc, xb, -5, 1.6, rand_color(&g));
            int a2 = zt_scene_vertex_px(&sc, zt_uniform(&g, 0, PL_W), PL_H + 4, 5.0, rand_color(&g));
            zt_scene_tri_front(&sc, a0, a1, a2, rand_color(&g));
            int b0 = zt_scene_vertex_px(&sc, xa + zt_uniform(&g, -5, 5), PL_H + 4, 1.5, rand_color(&g));
            int b1 = zt_scene_vertex_px(&sc, xb + zt_uniform(&g, -5, 5), PL_H + 5, 1.6, rand_color(&g));
            int b2 = zt_scene_vertex_px(&sc, zt_uniform(&g, 0, PL_W), -4, 5.0, rand_color(&g));
            zt_scene_tri_front(&sc, b0, b1, b2, rand_color(&g));
        }
        needle_first = (int)sc.nt;
        for (int i = 0; i < nneedle; i++) {
            /* long and thin (a fraction of a pixel), its third vertex much
             * deeper than the long edge: huge, nearly cancelling gradients */
            double x0 = zt_uniform(&g, 5, PL_W - 5), y0 = zt_uniform(&g, -6, 2);
            double x1 = x0 + zt_uniform(&g, -50, 50), y1 = zt_uniform(&g, PL_H - 2, PL_H + 6);
            double fr = zt_uniform(&g, 0.2, 0.8), off = zt_uniform(&g, 0.1, 0.4);
            if (zt_below(&g, 2)) off = -off;
            zs_color col = rand_color(&g);
            double d0 = zt_uniform(&g, 0.7, 1.5), d1 = zt_uniform(&g, 0.7, 1.5);
            int v0 = zt_scene_vertex_px(&sc, x0, y0, d0, col);
            int v1 = zt_scene_vertex_px(&sc, x1, y1, d1, col);
            int v2 = zt_scene_vertex_px(&sc, x0 + fr * (x1 - x0) + off, y0 + fr * (y1 - y0),
                                        zt_uniform(&g, 4, 6), col);
            zt_scene_tri_front(&sc, v0, v1, v2, col);
        }
        zs_mesh m = zt_scene_mesh(&sc, 1, 1);
        char what[120];
        snprintf(what, sizeof what, "tall scene %d (seed %llx)", k, (unsigned long long)SEED);
        /* ID16: the ray caster on band 1, every band against zline */
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, 1);
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(f->st.tris_clipped == 0 && f->st.tris_dropped == 0 && f->st.records_skipped == 0,
                 "%s: clipped %u dropped %u skipped %u (the colour check needs whole triangles)",
                 what, f->st.tris_clipped, f->st.tris_dropped, f->st.records_skipped);
        bad += zt_vs_raycast(f, what);
        for (size_t i = 0; i < f->recs.n; i++) {
            const zt_rec *t = &f->recs.v[i];
            if ((int)t->tag - 1 < needle_first) continue;
            g_pl_needles++;
            /* steep by activate.c's rule: |zdx| (x extent + 1 px) + |zdy|
             * (y extent + 1 px) >= 2^46 in Q40, i.e. 64 in window depth */
            double zdx, zdy;
            rec_gradients(t, &zdx, &zdy);
            int32_t xmin = t->xy[0], xmax = t->xy[0];
            for (int v = 1; v < 3; v++) {
                xmin = t->xy[2 * v] < xmin ? t->xy[2 * v] : xmin;
                xmax = t->xy[2 * v] > xmax ? t->xy[2 * v] : xmax;
            }
            double h2 = 0;
            for (int v = 0; v < 3; v++)
                for (int u = 0; u < 3; u++)
                    h2 = fabs((double)t->xy[2 * v + 1] - t->xy[2 * u + 1]) > h2
                             ? fabs((double)t->xy[2 * v + 1] - t->xy[2 * u + 1]) : h2;
            g_pl_steep += fabs(zdx) * ((xmax - xmin) / 16.0 + 1) + fabs(zdy) * (h2 / 16.0 + 1) >= 64.0;
        }
        /* the pairs flip order down the screen: count rows where the top
         * row's owner and the bottom row's differ in the middle column */
        g_pl_flips += zt_id_at(f->img, PL_W, PL_W / 2, 2) != zt_id_at(f->img, PL_W, PL_W / 2, PL_H - 3);
        memcpy(ref, f->img, (size_t)PL_W * PL_H * 2);
        for (int b = 1; b < 4; b++) {
            zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, bands[b], NULL);
            same_image(ref, img, PL_W, PL_H, ZS_FMT_ID16, what);
        }
        {
            zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
            render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, img, PL_H, NULL);
            same_image(ref, img, PL_W, PL_H, ZS_FMT_ID16, what);
            for (int b = 0; b < 4; b++) { /* Warnock: steep planes anchored as the walk does */
                render(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, 1, NULL, NULL, img, bands[b], NULL);
                same_image(ref, img, PL_W, PL_H, ZS_FMT_ID16, what);
            }
        }
        /* RGB888 Gouraud: every band against zline, then the colours */
        zs_color bg = rand_color(&g);
        zs_shade_params sp = shade(ZS_FMT_RGB888, ZS_SHADE_GOURAUD, bg);
        render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, rgb, PL_H, NULL);
        for (int b = 0; b < 4; b++) {
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, bands[b], NULL);
            same_image(rgb, img, PL_W, PL_H, ZS_FMT_RGB888, what);
            render(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, 1, NULL, NULL, img, bands[b], NULL);
            same_image(rgb, img, PL_W, PL_H, ZS_FMT_RGB888, what);
        }
        for (int y = 0; y < PL_H; y++)
            for (int x = 0; x < PL_W; x++) {
                uint16_t id = zt_id_at(ref, PL_W, x, y);
                const uint8_t *px = rgb + 3 * ((size_t)y * PL_W + (size_t)x);
                if (!id) {
                    ZT_CHECK(px[0] == (bg >> 16 & 255) && px[1] == (bg >> 8 & 255) &&
                                 px[2] == (bg & 255),
                             "%s: background pixel (%d,%d) is %02x%02x%02x", what, x, y, px[0],
                             px[1], px[2]);
                    continue;
                }
                const zt_rec *t = NULL;
                for (size_t i = 0; i < f->recs.n && !t; i++)
                    if (f->recs.v[i].tag == id) t = &f->recs.v[i];
                ZT_CHECK(t != NULL, "%s: no record of tag %u", what, id);
                const uint16_t *ix = &sc.idx[3 * (size_t)(id - 1)];
                zs_color vc[3] = {sc.vcol[ix[0]], sc.vcol[ix[1]], sc.vcol[ix[2]]};
                if (vc[0] == vc[1] && vc[1] == vc[2]) {
                    ZT_CHECK(px[0] == (vc[0] >> 16 & 255) && px[1] == (vc[0] >> 8 & 255) &&
                                 px[2] == (vc[0] & 255),
                             "%s: flat triangle %u at (%d,%d) is %02x%02x%02x, not %06x", what, id, x,
                             y, px[0], px[1], px[2], (unsigned)vc[0]);
                    g_pl_flat_px++;
                    continue;
                }
                /* barycentric weights of the snapped vertices at the centre */
                double X0 = t->xy[0], Y0 = t->xy[1], X1 = t->xy[2], Y1 = t->xy[3], X2 = t->xy[4],
                       Y2 = t->xy[5], cx = 16.0 * x + 8, cy = 16.0 * y + 8;
                double a = (X1 - X0) * (Y2 - Y0) - (X2 - X0) * (Y1 - Y0);
                double l1 = ((cx - X0) * (Y2 - Y0) - (X2 - X0) * (cy - Y0)) / a;
                double l2 = ((X1 - X0) * (cy - Y0) - (cx - X0) * (Y1 - Y0)) / a;
                for (int ch = 0; ch < 3; ch++) {
                    int sh = 16 - 8 * ch;
                    double c0 = vc[0] >> sh & 255, c1 = vc[1] >> sh & 255, c2 = vc[2] >> sh & 255;
                    double want = c0 + l1 * (c1 - c0) + l2 * (c2 - c0);
                    want = want < 0 ? 0 : want > 255 ? 255 : want;
                    double dev = fabs(px[ch] - want);
                    if (dev > g_pl_maxdev) g_pl_maxdev = dev;
                    g_pl_off_half += dev > 0.5;
                    ZT_CHECK(dev <= 0.5 + 1.0 / 32,
                             "%s: Gouraud pixel (%d,%d) of triangle %u channel %d is %u, the "
                             "barycentric colour %.4f", what, x, y, id, ch, px[ch], want);
                }
                g_pl_gouraud_px++;
            }
        g_pl_scenes++;
        g_pl_tris += sc.nt;
    }
    ZT_CHECK(g_pl_steep > 0, "no needle is steep by activate.c's rule: ZS_ACT_STEEP not exercised");
    ZT_CHECK(g_pl_flips > 0, "no scene flips depth order down the screen");
    free(ref);
    free(img);
    free(rgb);
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    g_raycast_bad += bad;
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster", bad);
}

/* ================= 4. depth ranges and shared-edge hand-over ================= */

#define LG_W 96
#define LG_H 72
#define LG_SCENES 160

static unsigned long g_lg_scenes, g_lg_tris, g_lg_dups, g_lg_dup_px, g_lg_bytes, g_lg_wedges;

/* A grid of nx x ny quads, each split along a random diagonal, over the
 * pixel rectangle (x0, y0) + (i cw, j ch), depth d (1 + tx u + ty v) plus
 * bump * d of noise per vertex (then the quads fold along their diagonals).
 * Returns the index of its first triangle. */
static int lg_grid(zt_rng *g, zt_scene *sc, double x0, double y0, double cw, double ch, int nx,
                   int ny, double d, double tx, double ty, double bump)
{
    int first = (int)sc->nt, base = (int)sc->nv;
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++) {
            double u = (double)i / nx - 0.5, v = (double)j / ny - 0.5;
            zt_scene_vertex_px(sc, x0 + i * cw, y0 + j * ch,
                               d * (1 + tx * u + ty * v + bump * zt_uniform(g, -1, 1)), rand_color(g));
        }
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int a = base + j * (nx + 1) + i, b = a + 1, cc = a + nx + 1, dd = cc + 1;
            if (zt_below(g, 2)) {
                zt_scene_tri_front(sc, a, b, dd, rand_color(g));
                zt_scene_tri_front(sc, a, dd, cc, rand_color(g));
            } else {
                zt_scene_tri_front(sc, a, b, cc, rand_color(g));
                zt_scene_tri_front(sc, b, dd, cc, rand_color(g));
            }
        }
    return first;
}

static void test_layers(void **state)
{
    (void)state;
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x1A);
    zt_ctx c;
    ctx_init_flags(&c, LG_W, LG_H, 1200, 2400, 1200, 0);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, LG_W, LG_H, 512);
    zt_gframe *f = zt_gframe_new(LG_W, LG_H);
    size_t cap = (size_t)LG_W * LG_H * 3;
    uint8_t *ref = malloc(cap), *img = malloc(cap);
    zt_cast cast;
    zt_cast_alloc(&cast, LG_W, LG_H);
    for (int k = 0; k < LG_SCENES; k++) {
        zt_scene_reset(&sc);
        int nl = 2 + (int)zt_below(&g, 3);
        double d = zt_uniform(&g, 1.5, 4), unit = 1.0 / 512;
        int firsts[4], counts[4];
        for (int l = 0; l < nl; l++) {
            int kind = (int)zt_below(&g, 5);
            int nx = 2 + (int)zt_below(&g, 5), ny = 2 + (int)zt_below(&g, 4);
            double x0 = zt_uniform(&g, -30, LG_W * 0.5), y0 = zt_uniform(&g, -25, LG_H * 0.5);
            double cw = zt_uniform(&g, 6, 30), ch = zt_uniform(&g, 6, 25);
            double tx = 0, ty = 0, bump = 0;
            if (kind == 0) d *= zt_uniform(&g, 1.5, 2.5);        /* far apart */
            else if (kind == 1) d *= zt_uniform(&g, 1.001, 1.02); /* close */
            else if (kind == 2) d += unit * (double)zt_below(&g, 3); /* 0..2 position units */
            else if (kind == 3) {                                 /* through the others */
                tx = zt_uniform(&g, -0.6, 0.6);
                ty = zt_uniform(&g, -0.6, 0.6);
            } else {
                bump = zt_uniform(&g, 0.005, 0.05);                /* folded quads */
            }
            if (l > 0 && zt_below(&g, 4) == 0) { /* the same rectangle as the last layer */
                x0 = zt_uniform(&g, -10, 10);
                y0 = zt_uniform(&g, -10, 10);
            }
            firsts[l] = lg_grid(&g, &sc, x0, y0, cw, ch, nx, ny, d, tx, ty, bump);
            counts[l] = (int)sc.nt - firsts[l];
        }
        /* wedges: large triangles whose depth sweeps through the layers
         * within a few pixels (behind a top where a nearer triangle enters,
         * in front of it soon after that top has left) */
        int nwedge = (int)zt_below(&g, 4);
        for (int i = 0; i < nwedge; i++) {
            int v[3];
            for (int q = 0; q < 3; q++)
                v[q] = zt_scene_vertex_px(&sc, zt_uniform(&g, -10, LG_W + 10),
                                          zt_uniform(&g, -10, LG_H + 10),
                                          d * zt_uniform(&g, 0.6, 1.6), rand_color(&g));
            zt_scene_tri_front(&sc, v[0], v[1], v[2], rand_color(&g));
            g_lg_wedges++;
        }
        /* exact coplanar duplicates of a layer, later in the submission,
         * each triangle's vertices rotated (same indices, or copied vertices) */
        int ndup = (int)zt_below(&g, 3);
        for (int i = 0; i < ndup; i++) {
            int l = (int)zt_below(&g, (uint32_t)nl), copy = (int)zt_below(&g, 2);
            for (int t = firsts[l]; t < firsts[l] + counts[l]; t++) {
                int id[3] = {sc.idx[3 * t], sc.idx[3 * t + 1], sc.idx[3 * t + 2]};
                if (copy)
                    for (int v = 0; v < 3; v++) {
                        int n = zt_scene_vertex_world(&sc, 0, 0, 0, rand_color(&g));
                        memcpy(&sc.pos[3 * n], &sc.pos[3 * id[v]], 3 * sizeof sc.pos[0]);
                        id[v] = n;
                    }
                int r = (int)zt_below(&g, 3);
                zt_scene_tri(&sc, id[r], id[(r + 1) % 3], id[(r + 2) % 3], rand_color(&g));
            }
            g_lg_dups++;
        }
        zs_mesh m = zt_scene_mesh(&sc, 1, 1);
        char what[120];
        snprintf(what, sizeof what, "layer scene %d (%d layers, %d duplicated, seed %llx)", k, nl,
                 ndup, (unsigned long long)SEED);
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, 1 + (int)zt_below(&g, 9));
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(f->st.tris_dropped == 0 && f->st.records_skipped == 0, "%s: pools too small", what);
        bad += zt_vs_raycast(f, what);
        /* the z-buffer mode decides runs by the same depth ranges and writes
         * spans that overlap nothing directly: against the ray caster too */
        zt_guarded_frame(&c, &cam, ZS_MODE_ZLINE, &m, 1, NULL, f, 1 + (int)zt_below(&g, 9));
        ZT_ST(f->draw_st, ZS_OK);
        bad += zt_vs_raycast(f, what);
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, 1 + (int)zt_below(&g, 9));
        zt_raycast(&f->recs, &cast);
        for (int i = 0; i < LG_W * LG_H; i++) g_lg_dup_px += cast.exact[i];
        memcpy(ref, f->img, (size_t)LG_W * LG_H * 2);
        zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
        render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, img, LG_H, NULL);
        same_image(ref, img, LG_W, LG_H, ZS_FMT_ID16, what);
        static const zs_format fmts[2] = {ZS_FMT_RGB565, ZS_FMT_RGB888};
        for (int fi = 0; fi < 2; fi++) {
            sp = shade(fmts[fi], fi ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT, rand_color(&g));
            render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, ref, LG_H, NULL);
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9), NULL);
            same_image(ref, img, LG_W, LG_H, sp.format, what);
            render(&c, &cam, ZS_MODE_WARNOCK, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9),
                   NULL);
            same_image(ref, img, LG_W, LG_H, sp.format, what);
            g_lg_bytes += (size_t)LG_W * LG_H * zs_format_bytes(sp.format);
        }
        g_lg_scenes++;
        g_lg_tris += sc.nt;
    }
    zt_cast_free(&cast);
    free(ref);
    free(img);
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    ZT_CHECK(g_lg_dup_px > 0, "no pixel is an exact duplicate tie");
    ZT_CHECK(zt_tot.excluded * 100 <= zt_tot.px, "%lu of %lu covered pixels excluded as near ties "
             "(limit 1%%)", zt_tot.excluded, zt_tot.px);
    g_raycast_bad += bad;
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster", bad);
}

/* ================= 5. single-layer stretches ================= */

#define SL_W 112
#define SL_H 80
#define SL_SCENES 200

static unsigned long g_sl_scenes, g_sl_tris, g_sl_slivers, g_sl_loose, g_sl_bytes;

/* A triangle a fraction of a pixel wide: from (x, y) length len at angle
 * ang, its third vertex off the middle by width pixels, at depth d. */
static void sl_sliver(zt_rng *g, zt_scene *sc, double d)
{
    double x = zt_uniform(g, -8, SL_W + 8), y = zt_uniform(g, -8, SL_H + 8);
    double ang = zt_uniform(g, 0, 6.283185307179586), len = zt_uniform(g, 4, 60);
    double wid = zt_uniform(g, 0.02, 0.7), dx = cos(ang), dy = sin(ang);
    double d2 = d * zt_uniform(g, 0.98, 1.02);
    int a = zt_scene_vertex_px(sc, x, y, d, rand_color(g));
    int b = zt_scene_vertex_px(sc, x + len * dx, y + len * dy, d2, rand_color(g));
    int c = zt_scene_vertex_px(sc, x + 0.5 * len * dx - wid * dy, y + 0.5 * len * dy + wid * dx,
                               0.5 * (d + d2), rand_color(g));
    zt_scene_tri_front(sc, a, b, c, rand_color(g));
}

static void test_single_layer(void **state)
{
    (void)state;
    unsigned long bad = 0;
    zt_rng g;
    zt_rng_seed(&g, SEED ^ 0x5E);
    zt_ctx c, cf;
    ctx_init_flags(&c, SL_W, SL_H, 1500, 3000, 1500, 0);
    ctx_init_flags(&cf, SL_W, SL_H, 1500, 3000, 1500, ZS_CFG_FLAT_ONLY);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(60));
    zt_scene sc;
    zt_scene_init(&sc, SL_W, SL_H, 512);
    zt_gframe *f = zt_gframe_new(SL_W, SL_H);
    size_t cap = (size_t)SL_W * SL_H * 3;
    uint8_t *ref = malloc(cap), *img = malloc(cap);
    ZT_CHECK(ref && img, "out of memory");
    for (int k = 0; k < SL_SCENES; k++) {
        zt_scene_reset(&sc);
        double d = zt_uniform(&g, 1.5, 4);
        int nx = 2 + (int)zt_below(&g, 9), ny = 2 + (int)zt_below(&g, 7);
        double cw = zt_uniform(&g, 4, 2.0 * SL_W / nx), ch = zt_uniform(&g, 4, 2.0 * SL_H / ny);
        double tilt = zt_below(&g, 2) ? zt_uniform(&g, -0.5, 0.5) : 0;
        lg_grid(&g, &sc, zt_uniform(&g, -SL_W * 0.6, SL_W * 0.4), zt_uniform(&g, -SL_H * 0.6, SL_H * 0.4),
                cw, ch, nx, ny, d, tilt, -tilt, 0);
        /* slivers in the layer's depth range (in front, behind or level) */
        int ns = (int)zt_below(&g, 24);
        for (int i = 0; i < ns; i++)
            sl_sliver(&g, &sc, d * zt_uniform(&g, 0.7, 1.3));
        g_sl_slivers += (unsigned long)ns;
        /* loose triangles: a second layer here and there, or none */
        int nl = (int)zt_below(&g, 4);
        for (int i = 0; i < nl; i++) {
            double x = zt_uniform(&g, -10, SL_W), y = zt_uniform(&g, -10, SL_H);
            double dl = d * zt_uniform(&g, 0.6, 1.4), sz = zt_uniform(&g, 3, 30);
            int a = zt_scene_vertex_px(&sc, x, y, dl, rand_color(&g));
            int b = zt_scene_vertex_px(&sc, x + sz, y + zt_uniform(&g, -sz, sz),
                                       dl * zt_uniform(&g, 0.8, 1.25), rand_color(&g));
            int cc = zt_scene_vertex_px(&sc, x + zt_uniform(&g, -sz, sz), y + sz,
                                        dl * zt_uniform(&g, 0.8, 1.25), rand_color(&g));
            zt_scene_tri_front(&sc, a, b, cc, rand_color(&g));
        }
        g_sl_loose += (unsigned long)nl;
        zs_mesh m = zt_scene_mesh(&sc, 1, 1);
        char what[120];
        snprintf(what, sizeof what, "single-layer scene %d (%d slivers, %d loose, seed %llx)", k, ns,
                 nl, (unsigned long long)SEED);
        zt_guarded_frame(&c, &cam, ZS_MODE_SPAN, &m, 1, NULL, f, 1 + (int)zt_below(&g, 9));
        ZT_ST(f->draw_st, ZS_OK);
        ZT_CHECK(f->st.tris_dropped == 0 && f->st.records_skipped == 0, "%s: pools too small", what);
        bad += zt_vs_raycast(f, what);
        memcpy(ref, f->img, (size_t)SL_W * SL_H * 2);
        zs_shade_params sp = shade(ZS_FMT_ID16, ZS_SHADE_FLAT, 0);
        render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, img, SL_H, NULL);
        same_image(ref, img, SL_W, SL_H, ZS_FMT_ID16, what);
        render(&cf, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9), NULL);
        same_image(ref, img, SL_W, SL_H, ZS_FMT_ID16, what);
        static const zs_format fmts[2] = {ZS_FMT_RGB565, ZS_FMT_RGB888};
        for (int fi = 0; fi < 2; fi++) {
            zs_color bg = rand_color(&g);
            /* flat: both renderers, span against zline */
            sp = shade(fmts[fi], ZS_SHADE_FLAT, bg);
            render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, ref, SL_H, NULL);
            render(&cf, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9),
                   NULL);
            same_image(ref, img, SL_W, SL_H, sp.format, what);
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9),
                   NULL);
            same_image(ref, img, SL_W, SL_H, sp.format, what);
            /* Gouraud where colour planes exist */
            sp = shade(fmts[fi], ZS_SHADE_GOURAUD, bg);
            render(&c, &cam, ZS_MODE_ZLINE, &sp, &m, 1, NULL, NULL, ref, SL_H, NULL);
            render(&c, &cam, ZS_MODE_SPAN, &sp, &m, 1, NULL, NULL, img, 1 + (int)zt_below(&g, 9),
                   NULL);
            same_image(ref, img, SL_W, SL_H, sp.format, what);
            g_sl_bytes += 3u * (size_t)SL_W * SL_H * zs_format_bytes(sp.format);
        }
        g_sl_scenes++;
        g_sl_tris += sc.nt;
    }
    free(ref);
    free(img);
    zt_gframe_free(f);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
    zt_ctx_free(&cf);
    g_raycast_bad += bad;
    ZT_CHECK(bad == 0, "%lu pixels disagree with the ray caster", bad);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_inside),
        cmocka_unit_test(test_count_sort),
        cmocka_unit_test(test_planes_per_row),
        cmocka_unit_test(test_layers),
        cmocka_unit_test(test_single_layer),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);

    fflush(stderr);
    printf("test_shortcuts: seed %llx; box_inside: %lu probe scenes (guard 4/3/2; near, far and 4 "
           "guard planes; identity, slight, any and margin turns; %lu redrawn), %lu probe meshes "
           "rendered (%lu need no clipping, %lu do; %lu with the box estimated inside), last "
           "position inside exactly on near %lu and on far %lu times, %lu margin slides drawn; "
           "count sort: %lu scenes %dx%d (%lu triangles), batches of 26..%lu new edges on one "
           "row, %lu batch triangles reaching off the left and %lu off the right, %lu bytes "
           "compared (6 formats, span and span without the z-buffer line vs zline); planes: %lu "
           "scenes %dx%d (%lu triangles, %lu needles, %lu of them steep), %lu whose middle column "
           "shows another triangle at the bottom than at the top, %lu Gouraud pixels (max deviation %.3f, %lu channels beyond 0.5) "
           "and %lu flat pixels against the barycentric reference; layers: %lu scenes (%lu "
           "triangles, %lu duplicated layers, %lu wedges, %lu exact-duplicate tie pixels), %lu bytes "
           "compared; single layer: %lu scenes %dx%d (%lu triangles, %lu slivers, %lu loose), %lu "
           "bytes compared; %lu renders; ray caster: %lu of %lu covered pixels excluded as near ties, "
           "%lu disagreeing; %d failed\n",
           (unsigned long long)SEED, g_bx_scenes, g_bx_redrawn, g_bx_probes, g_bx_inside,
           g_bx_outside, g_bx_fast, g_bx_exact_near, g_bx_exact_far, g_bx_slides, g_cs_scenes,
           CS_W, CS_H, g_cs_tris, g_cs_max_batch, g_cs_left, g_cs_right, g_cs_bytes, g_pl_scenes,
           PL_W, PL_H, g_pl_tris, g_pl_needles, g_pl_steep, g_pl_flips, g_pl_gouraud_px,
           g_pl_maxdev, g_pl_off_half, g_pl_flat_px, g_lg_scenes, g_lg_tris, g_lg_dups,
           g_lg_wedges, g_lg_dup_px, g_lg_bytes, g_sl_scenes, SL_W, SL_H, g_sl_tris, g_sl_slivers, g_sl_loose,
           g_sl_bytes, g_renders, zt_tot.excluded, zt_tot.px, g_raycast_bad, rc);
    fflush(stdout);
    return rc;
}
