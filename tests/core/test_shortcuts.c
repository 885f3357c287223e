/*
 * test_shortcuts: regression tests for the span engine's shortcuts (issue
 * 11), each against oracles that do not take the shortcut:
 *
 *  1. box_inside (geometry.c): a mesh whose bounding box is inside near, far
 *     and the guard band projects its vertices without outcodes. Probe
 *     meshes put one vertex just inside or just outside the near plane, the
 *     far plane or one of the four guard planes (guard 4, 3 and 2: screens
 *     64x48, 900x12, 1024x12), with identity, slightly turned and randomly
 *     turned model matrices; the boundary is found by bisection on the
 *     outcode path itself (the same mesh plus one unused vertex behind the
 *     eye or beyond far, which puts its box outside), and the probe is placed
 *     at every step from 60 inside to 8 outside it, including the last
 *     position inside and the first outside (for the identity turn exactly
 *     w == near and w == far). Each mesh is rendered (a) as it is and (b)
 *     with the unused vertex: the ID16 and RGB565 images, the setup hook's
 *     records and the statistics must be identical (verts_stored one more
 *     for b), and the image must agree with the ray caster.
 *  2. The counting sort of new edges (raster.c count_sort, more than 24 and
 *     at most width edges starting on a row, with the z-buffer line as
 *     scratch): 640x36 frames where 25..300 triangles start on one row (fans
 *     and strips sharing edges, so edges fold; loose triangles; starts left
 *     of and right of the screen; rows entered from above): span == zline in
 *     every format, span equal to a ZS_CFG_NO_ZLINE renderer's span (which
 *     sorts by insertion), and the ray caster.
 *  3. Planes evaluated per row instead of stepped (depth zrow + zdy * dy,
 *     Gouraud crow + cdy * dy): 56x560 frames of triangles spanning the whole
 *     height with steep depth gradients and pairs whose depth order flips
 *     half way down, Gouraud colours, and needles (steep planes by
 *     activate.c's rule, counted from the records); bands 1, 3, 8 and all
 *     rows: span == zline in ID16 and RGB888, the ray caster, and every
 *     Gouraud pixel within 0.5 + 1/32 of a double barycentric reference at
 *     RGB888 (so within 1 LSB; flat ones exact).
 *  4. Depth-range decisions and the top pick when the top leaves through an
 *     edge it shares with the entering triangle (span.c range_top,
 *     always_nearer, the deferred pick): grids of quads split into two
 *     triangles, 2..4 layers at depths far apart, close, one position unit
 *     apart or interpenetrating, exact coplanar duplicates submitted with
 *     rotated vertex order: ray caster (exact ties to the earlier triangle),
 *     span == zline in ID16, RGB565 and Gouraud RGB888.
 *
 * The ray caster comparisons leave out near ties (ZT_TIE_TOL) like the other
 * suites; their number is printed. Every count in the summary line comes from
 * the test's own reading of the records and images.
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
                        g_raycast_bad += zt_vs_raycast(fa, pw);
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
    ZT_CHECK(g_raycast_bad == 0, "%lu pixels disagree with the ray caster", g_raycast_bad);
}

int main(void)
{
    (void)first_row_of; (void)ctx_init_flags; /*TMP*/
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_inside),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);

    fflush(stderr);
    printf("test_shortcuts: seed %llx; box_inside: %lu probe scenes (guard 4/3/2; near, far and 4 "
           "guard planes; identity, slight, any and margin turns; %lu redrawn), %lu probe meshes "
           "rendered (%lu need no clipping, %lu do; %lu with the box estimated inside), last "
           "position inside exactly on near %lu and on far %lu times, %lu margin slides drawn; "
           "%lu renders; ray caster: %lu of %lu covered pixels excluded as near ties, %lu "
           "disagreeing; %d failed\n",
           (unsigned long long)SEED, g_bx_scenes, g_bx_redrawn, g_bx_probes, g_bx_inside,
           g_bx_outside, g_bx_fast, g_bx_exact_near, g_bx_exact_far, g_bx_slides, g_renders,
           zt_tot.excluded, zt_tot.px, g_raycast_bad, rc);
    fflush(stdout);
    return rc;
}
