/* SPDX-License-Identifier: MIT */
/*
 * test_exact: exactness at the documented limits.
 *
 * 1. Clip-space range (test_clip_range_*): fields of view from 5 to 170
 *    degrees, world coordinates up to +-32767 units, far planes up to 32000,
 *    eyes up to 20000 units from the origin, geometry reaching far outside the
 *    view. Each ID16 image is compared at every pixel centre with an
 *    independent double-precision pipeline over the unsnapped mesh
 *    (transform, near/far clipping, projection, culling, nearest surface by
 *    ray-plane intersection). Left out: centres within EDGE_EPS of a projected
 *    edge (1/16-px snapping moves edges by up to 0.044 px) and surfaces whose
 *    depths at the centre are closer than snapping can move them. The snapped
 *    records must also match the ray caster, and no frame may count a
 *    saturation.
 * 2. Needles (test_needles_*): triangles 1e-4 .. 1e-1 px thick and up to the
 *    screen wide, placed exactly in 28.4 at integer eye depths, so their two
 *    depth gradients are huge and nearly cancel, some with an edge through
 *    pixel centres, over a tilted backdrop they pierce: ID16 against the ray
 *    caster in both modes; the needles must show.
 * 3. Vertex order (test_rotations_*): random triangles (clipped ones too),
 *    each followed by copies in its other two rotations, with shared and with
 *    copied vertices: the ray caster gives every pixel of a copy to the first
 *    and allows no exception.
 */
#include "zt_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEED 0xE8AC7000000000C9ull
#define TOL (1.0 / 1048576.0) /* near ties for the ray caster: 2^-20 */
#define EDGE_EPS 0.125        /* px: snapping and rounding margin at edges */

/* ------------------------------------------------------------------ */
/* Shared: ID16 image against the ray caster over the hooked records.  */
/* ------------------------------------------------------------------ */

typedef struct cast_result {
    unsigned long px, bad, ties;
} cast_result;

static cast_result vs_raycast(const zt_recs *recs, const uint8_t *img, int w, int h,
                              const char *what)
{
    cast_result res = {0, 0, 0};
    zt_cast cast;
    zt_cast_alloc(&cast, w, h);
    zt_raycast(recs, &cast);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int p = y * w + x;
            uint16_t id = zt_id_at(img, w, x, y), want = cast.owner[p];
            if (want) res.px++;
            int tie = want && cast.z2[p] - cast.z1[p] < TOL;
            res.ties += (unsigned long)tie;
            if (id == want || tie) continue;
            if (res.bad++ < 3)
                print_error("%s: pixel (%d,%d) ID16 %u, ray caster %u (z %.12f, runner-up %.12f)\n",
                            what, x, y, id, want, cast.z1[p], cast.z2[p]);
        }
    zt_cast_free(&cast);
    return res;
}

/* One frame: hook, begin, ID16, one draw, all rows in bands of 3. */
static zs_status render_ids(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                            const zs_mesh *mesh, const zs_mat34 *model, zt_recs *recs,
                            uint8_t *img)
{
    zs_shade_params sp = zs_shade_default();
    zs_status st;
    zt_recs_clear(recs);
    zs_set_setup_hook(&c->r, zt_recs_hook, recs);
    if ((st = zs_frame_begin(&c->r, cam, mode)) != ZS_OK) return st;
    sp.format = ZS_FMT_ID16;
    if ((st = zs_frame_shading(&c->r, &sp)) != ZS_OK) return st;
    if ((st = zs_draw(&c->r, mesh, model)) != ZS_OK) return st;
    return zt_render_rows_all(&c->r, img, c->cfg.width, c->cfg.height, ZS_FMT_ID16, 3);
}

/* ------------------------------------------------------------------ */
/* 1. A double-precision pipeline over the unsnapped mesh.             */
/* ------------------------------------------------------------------ */

typedef struct dvec {
    double x, y, z;
} dvec;

static double fx(zs_fixed v)
{
    return v / 65536.0;
}

static dvec mat_apply(const zs_mat34 *m, dvec p)
{
    dvec o;
    o.x = fx(m->m[0][0]) * p.x + fx(m->m[0][1]) * p.y + fx(m->m[0][2]) * p.z + fx(m->m[0][3]);
    o.y = fx(m->m[1][0]) * p.x + fx(m->m[1][1]) * p.y + fx(m->m[1][2]) * p.z + fx(m->m[1][3]);
    o.z = fx(m->m[2][0]) * p.x + fx(m->m[2][1]) * p.y + fx(m->m[2][2]) * p.z + fx(m->m[2][3]);
    return o;
}

typedef struct ref_poly {
    int n;              /* 0: clipped away */
    double sx[5], sy[5]; /* screen, pixels, y down */
    double len[5];      /* edge i -> i+1 lengths */
    double sign;        /* orientation of the projected polygon */
    int front;
    dvec e0, nrm;       /* eye-space plane of the triangle */
} ref_poly;

typedef struct ref_cam {
    int w, h;
    double sx, sy, near_d, far_d;
} ref_cam;

/* Eye-space triangle -> near/far clipped, projected polygon. */
static void ref_polygon(const ref_cam *rc, const dvec e[3], ref_poly *out)
{
    dvec a[6], b[6];
    int n = 3, m;
    for (int i = 0; i < 3; i++) a[i] = e[i];
    /* w = -z; clip w >= near, then w <= far */
    for (int plane = 0; plane < 2; plane++) {
        m = 0;
        for (int i = 0; i < n; i++) {
            const dvec *p = &a[i], *q = &a[(i + 1) % n];
            double dp = plane == 0 ? -p->z - rc->near_d : rc->far_d + p->z;
            double dq = plane == 0 ? -q->z - rc->near_d : rc->far_d + q->z;
            if (dp >= 0) b[m++] = *p;
            if ((dp >= 0) != (dq >= 0)) {
                double t = dp / (dp - dq);
                dvec v = {p->x + (q->x - p->x) * t, p->y + (q->y - p->y) * t,
                          p->z + (q->z - p->z) * t};
                v.z = plane == 0 ? -rc->near_d : -rc->far_d;
                b[m++] = v;
            }
        }
        n = m;
        memcpy(a, b, sizeof(dvec) * (size_t)n);
        if (n < 3) {
            out->n = 0;
            return;
        }
    }
    out->n = n;
    double area = 0;
    for (int i = 0; i < n; i++) {
        double wv = -a[i].z;
        out->sx[i] = rc->w / 2.0 * (1.0 + rc->sx * a[i].x / wv);
        out->sy[i] = rc->h / 2.0 * (1.0 - rc->sy * a[i].y / wv);
    }
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        area += out->sx[i] * out->sy[j] - out->sx[j] * out->sy[i];
        out->len[i] = hypot(out->sx[j] - out->sx[i], out->sy[j] - out->sy[i]);
    }
    out->sign = area < 0 ? -1.0 : 1.0;
    out->front = area < 0; /* counter-clockwise seen by the camera: negative with y down */
    out->e0 = e[0];
    dvec u = {e[1].x - e[0].x, e[1].y - e[0].y, e[1].z - e[0].z};
    dvec v = {e[2].x - e[0].x, e[2].y - e[0].y, e[2].z - e[0].z};
    out->nrm.x = u.y * v.z - u.z * v.y;
    out->nrm.y = u.z * v.x - u.x * v.z;
    out->nrm.z = u.x * v.y - u.y * v.x;
}

/* 1 inside (by more than EDGE_EPS), 0 outside (by more), -1 too close. */
static int ref_inside(const ref_poly *p, double x, double y)
{
    int close = 0;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        if (p->len[i] == 0) continue;
        double c = (p->sx[j] - p->sx[i]) * (y - p->sy[i]) - (p->sy[j] - p->sy[i]) * (x - p->sx[i]);
        double d = p->sign * c / p->len[i]; /* > 0 inside */
        if (d < -EDGE_EPS) return 0;
        if (d <= EDGE_EPS) close = 1;
    }
    return close ? -1 : 1;
}

/* Window depth where the ray through screen point (x, y) meets the plane. */
static double ref_depth(const ref_cam *rc, const ref_poly *p, double x, double y)
{
    dvec dir = {(2.0 * x / rc->w - 1.0) / rc->sx, (1.0 - 2.0 * y / rc->h) / rc->sy, -1.0};
    double den = p->nrm.x * dir.x + p->nrm.y * dir.y + p->nrm.z * dir.z;
    double num = p->nrm.x * p->e0.x + p->nrm.y * p->e0.y + p->nrm.z * p->e0.z;
    if (den == 0) return 2.0;
    double t = num / den; /* eye distance along -z */
    return rc->far_d * (t - rc->near_d) / ((rc->far_d - rc->near_d) * t);
}

typedef struct clip_totals {
    unsigned long scenes, tris, px_checked, px_covered, px_left_out, bad, cast_bad, cast_ties,
        cast_px, saturated, clipped, fov_min10, fov_max10;
} clip_totals;

static clip_totals g_clip[2];

/* Mesh of ntri triangles in world units (scale 1.0) for the given view. */
typedef struct world_mesh {
    int16_t pos[3 * 3 * 64];
    uint16_t idx[3 * 64];
    int nv, nt;
} world_mesh;

static int16_t clamp16(double v)
{
    return (int16_t)(v > 32767 ? 32767 : (v < -32767 ? -32767 : lrint(v)));
}

static int wm_vertex(world_mesh *m, dvec p)
{
    m->pos[3 * m->nv] = clamp16(p.x);
    m->pos[3 * m->nv + 1] = clamp16(p.y);
    m->pos[3 * m->nv + 2] = clamp16(p.z);
    return m->nv++;
}

static void wm_tri(world_mesh *m, int a, int b, int c)
{
    m->idx[3 * m->nt] = (uint16_t)a;
    m->idx[3 * m->nt + 1] = (uint16_t)b;
    m->idx[3 * m->nt + 2] = (uint16_t)c;
    m->nt++;
}

/* World point at eye distance d along a direction inside the view cone
 * (spread 1: to the screen edges), from the eye basis. */
static dvec view_point(const dvec *eye, const dvec basis[3], double tx, double ty, double d)
{
    dvec p;
    p.x = eye->x + d * (basis[0].x * tx + basis[1].x * ty - basis[2].x);
    p.y = eye->y + d * (basis[0].y * tx + basis[1].y * ty - basis[2].y);
    p.z = eye->z + d * (basis[0].z * tx + basis[1].z * ty - basis[2].z);
    return p;
}

static void run_clip_range(zs_visibility mode)
{
    const int W = 80, H = 60, NSCENES = 240;
    zt_rng g;
    zt_rng_seed(&g, SEED + 1);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 600, 900, 400);
    zt_recs recs = {0};
    static uint8_t img[80 * 60 * 2];
    static world_mesh wm;
    ref_poly *polys = calloc(64, sizeof *polys);
    clip_totals *tot = &g_clip[mode];
    tot->fov_min10 = 1800;
    for (int n = 0; n < NSCENES; n++) {
        /* field of view: a sweep over 5..170 degrees, then random */
        double fov = n < 34 ? 5.0 + 5.0 * n : zt_uniform(&g, 5.0, 170.0);
        double near_d = pow(10.0, zt_uniform(&g, -1.5, 1.5));
        double far_d = (n % 2) ? 32000.0 : near_d * pow(10.0, zt_uniform(&g, 1.0, 4.0));
        if (far_d > 32000.0) far_d = 32000.0;
        int kind = n % 3;
        dvec eye = {0, 0, 0}, target = {0, 0, -1};
        if (kind == 1) { /* high above a ground plane at y = 0 */
            eye.x = zt_uniform(&g, -20000, 20000);
            eye.z = zt_uniform(&g, -20000, 20000);
            eye.y = pow(10.0, zt_uniform(&g, 0.0, 4.3));
            target.x = eye.x + zt_uniform(&g, -30000, 30000);
            target.z = eye.z + zt_uniform(&g, -30000, 30000);
            target.y = 0;
        } else if (kind == 2) { /* anywhere within 20000 units of the origin */
            eye.x = zt_uniform(&g, -11500, 11500);
            eye.y = zt_uniform(&g, -11500, 11500);
            eye.z = zt_uniform(&g, -11500, 11500);
            target.x = eye.x + zt_uniform(&g, -1, 1);
            target.y = eye.y + zt_uniform(&g, -1, 1);
            target.z = eye.z + zt_uniform(&g, -1, 1);
        }
        zs_camera cam;
        zs_status st = zs_camera_look_at(
            &cam, zs_vec3_make((zs_fixed)lrint(eye.x * 65536), (zs_fixed)lrint(eye.y * 65536),
                               (zs_fixed)lrint(eye.z * 65536)),
            zs_vec3_make((zs_fixed)lrint(target.x * 65536), (zs_fixed)lrint(target.y * 65536),
                         (zs_fixed)lrint(target.z * 65536)),
            zs_vec3_make(0, ZS_FX(1), 0));
        if (st != ZS_OK) { /* looking straight down the up vector: try again */
            n--;
            continue;
        }
        ZT_ST(zs_camera_perspective(&cam, (zs_fixed)lrint(fov * 65536),
                                    (zs_fixed)lrint(near_d * 65536),
                                    (zs_fixed)lrint(far_d * 65536)),
              ZS_OK);
        /* the camera as stored (Q16.16) is the input of both pipelines */
        dvec basis[3]; /* side, up, back: the rows of the view's 3x3 */
        for (int k = 0; k < 3; k++) {
            dvec *b = &basis[k];
            b->x = fx(cam.view.m[k][0]);
            b->y = fx(cam.view.m[k][1]);
            b->z = fx(cam.view.m[k][2]);
        }
        ref_cam rc;
        rc.w = W;
        rc.h = H;
        rc.near_d = fx(cam.near_z);
        rc.far_d = fx(cam.far_z);
        rc.sy = 1.0 / tan(fx(cam.fov_deg) * 3.14159265358979323846 / 360.0);
        rc.sx = rc.sy * H / W;
        double tanx = 1.0 / rc.sx, tany = 1.0 / rc.sy;

        /* the mesh: each triangle has a vertex in view; the others anywhere */
        memset(&wm, 0, sizeof wm);
        if (kind == 1) { /* the ground, +-32767 */
            dvec q[4] = {{-32767, 0, -32767}, {-32767, 0, 32767}, {32767, 0, 32767},
                         {32767, 0, -32767}};
            int v[4];
            for (int k = 0; k < 4; k++) v[k] = wm_vertex(&wm, q[k]);
            wm_tri(&wm, v[0], v[1], v[2]);
            wm_tri(&wm, v[0], v[2], v[3]);
        }
        int ntri = (int)zt_range(&g, 6, 16);
        for (int t = 0; t < ntri; t++) {
            double d = rc.near_d * pow(rc.far_d / rc.near_d, zt_unit(&g)) * 0.999;
            dvec p0 = view_point(&eye, basis, tanx * zt_uniform(&g, -1, 1),
                                 tany * zt_uniform(&g, -1, 1), d);
            dvec p[3];
            p[0] = p0;
            for (int k = 1; k < 3; k++) {
                int how = (int)zt_below(&g, 3);
                if (how == 0) { /* far outside the view, same depth band */
                    p[k] = view_point(&eye, basis, tanx * zt_uniform(&g, -400, 400),
                                      tany * zt_uniform(&g, -400, 400), d * zt_uniform(&g, 0.5, 2));
                } else if (how == 1) { /* anywhere in the world */
                    p[k].x = zt_uniform(&g, -32767, 32767);
                    p[k].y = zt_uniform(&g, -32767, 32767);
                    p[k].z = zt_uniform(&g, -32767, 32767);
                } else { /* near the first, a few screens across */
                    p[k] = view_point(&eye, basis, tanx * zt_uniform(&g, -3, 3),
                                      tany * zt_uniform(&g, -3, 3), d * zt_uniform(&g, 0.7, 1.4));
                }
            }
            int v0 = wm_vertex(&wm, p[0]), v1 = wm_vertex(&wm, p[1]), v2 = wm_vertex(&wm, p[2]);
            if (zt_below(&g, 2)) wm_tri(&wm, v0, v1, v2);
            else wm_tri(&wm, v0, v2, v1);
        }
        if (n == 0) { /* the case: z = -50 reaching x = 4000, 10 degrees */
            wm.nv = wm.nt = 0;
            dvec a = {-20, -10, -50}, b = {4000, -10, -50}, cc = {-20, 10, -50};
            int i0 = wm_vertex(&wm, a), i1 = wm_vertex(&wm, b), i2 = wm_vertex(&wm, cc);
            wm_tri(&wm, i0, i1, i2);
        }
        zs_mesh mesh;
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = wm.pos;
        mesh.indices = wm.idx;
        mesh.scale = ZS_FX(1);
        mesh.vertex_count = (uint16_t)wm.nv;
        mesh.triangle_count = (uint16_t)wm.nt;
        /* a model matrix in a third of the scenes (world = R p + t) */
        zs_mat34 model = zs_mat34_identity(), *mp = NULL;
        if (n % 5 == 4) {
            zs_mat34 rot = zs_mat34_rotate_y((zs_fixed)zt_range(&g, 0, 360 * 65536));
            model = zs_mat34_translate((zs_fixed)zt_range(&g, -1000, 1000) * 65536,
                                       (zs_fixed)zt_range(&g, -1000, 1000) * 65536,
                                       (zs_fixed)zt_range(&g, -1000, 1000) * 65536);
            model = zs_mat34_mul(&model, &rot);
            mp = &model;
        }

        st = render_ids(&c, &cam, mode, &mesh, mp, &recs, img);
        ZT_CHECK(st == ZS_OK, "scene %d: %s", n, zs_strerror(st));
        const zs_stats *stats = zs_frame_stats(&c.r);
        ZT_CHECK(stats->tris_dropped == 0 && stats->records_skipped == 0 &&
                     stats->verts_dropped == 0,
                 "scene %d: pools too small for the test", n);
        tot->saturated += stats->saturated;
        tot->clipped += stats->tris_clipped;
        tot->scenes++;
        tot->tris += (unsigned long)wm.nt;
        if (fov * 10 < tot->fov_min10) tot->fov_min10 = (unsigned long)(fov * 10);
        if (fov * 10 > tot->fov_max10) tot->fov_max10 = (unsigned long)(fov * 10);

        /* the reference */
        for (int t = 0; t < wm.nt; t++) {
            dvec e[3];
            for (int k = 0; k < 3; k++) {
                const int16_t *q = &wm.pos[3 * wm.idx[3 * t + k]];
                dvec pm = {q[0], q[1], q[2]};
                dvec pw = mp ? mat_apply(mp, pm) : pm;
                e[k] = mat_apply(&cam.view, pw);
            }
            ref_polygon(&rc, e, &polys[t]);
        }
        unsigned long bad_here = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double cx = x + 0.5, cy = y + 0.5;
                int best = -1, amb = 0;
                double z1 = 3.0, z2 = 3.0, g1 = 0, g2 = 0;
                for (int t = 0; t < wm.nt && !amb; t++) {
                    const ref_poly *p = &polys[t];
                    if (p->n == 0) continue;
                    int in = ref_inside(p, cx, cy);
                    if (in < 0) amb = 1;
                    if (in <= 0 || !p->front) continue;
                    double z = ref_depth(&rc, p, cx, cy);
                    /* how far 1/16 px of snapping can move this depth */
                    double gz = fabs(ref_depth(&rc, p, cx + 0.0625, cy) - z) +
                                fabs(ref_depth(&rc, p, cx, cy + 0.0625) - z);
                    if (z < z1) {
                        z2 = z1;
                        g2 = g1;
                        z1 = z;
                        g1 = gz;
                        best = t;
                    } else if (z < z2) {
                        z2 = z;
                        g2 = gz;
                    }
                }
                if (amb || (best >= 0 && z2 - z1 < TOL + 4 * (g1 + g2))) {
                    tot->px_left_out++;
                    continue;
                }
                uint16_t want = (uint16_t)(best + 1), got = zt_id_at(img, W, x, y);
                tot->px_checked++;
                if (best >= 0) tot->px_covered++;
                if (got != want && bad_here++ < 3)
                    print_error("clip range (%s) scene %d, fov %.2f, near %.4g, far %.4g: pixel "
                                "(%d,%d) ID16 %u, double pipeline %u\n",
                                mode ? "zline" : "span", n, fov, rc.near_d, rc.far_d, x, y, got,
                                want);
            }
        tot->bad += bad_here;
        cast_result cr = vs_raycast(&recs, img, W, H, "clip range vs ray caster");
        tot->cast_bad += cr.bad;
        tot->cast_ties += cr.ties;
        tot->cast_px += cr.px;
    }
    ZT_CHECK(tot->bad == 0, "%lu pixels differ from the double pipeline", tot->bad);
    ZT_CHECK(tot->cast_bad == 0, "%lu pixels differ from the ray caster", tot->cast_bad);
    ZT_CHECK(tot->saturated == 0, "%lu saturations within the documented limits",
             tot->saturated);
    /* the test must look at something */
    ZT_CHECK(tot->px_covered > tot->px_checked / 4, "only %lu of %lu checked pixels covered",
             tot->px_covered, tot->px_checked);
    free(polys);
    zt_recs_free(&recs);
    zt_ctx_free(&c);
}

static void test_clip_range_span(void **state)
{
    (void)state;
    run_clip_range(ZS_MODE_SPAN);
}

static void test_clip_range_zline(void **state)
{
    (void)state;
    run_clip_range(ZS_MODE_ZLINE);
}

/* ------------------------------------------------------------------ */
/* 2. Needles.                                                         */
/* ------------------------------------------------------------------ */

/* 64 x 64 with 512 position units per world unit (scale exactly 128 in
 * Q16.16): a vertex at integer eye depth d projects exactly to any 28.4
 * position q when its position is (q - 512) * d. */
#define NW 64
#define NUNIT 512

static int needle_vertex(zt_scene *s, int32_t qx, int32_t qy, int d)
{
    return zt_scene_vertex_world(s, (qx - 8.0 * NW) * d / NUNIT, (8.0 * NW - qy) * d / NUNIT,
                                 -(double)d, 0);
}

/* x, y with a * x + b * y == gcd(a, b) (>= 0). */
static int64_t ext_gcd(int64_t a, int64_t b, int64_t *x, int64_t *y)
{
    if (b == 0) {
        *x = a < 0 ? -1 : 1;
        *y = 0;
        return a < 0 ? -a : a;
    }
    int64_t x1, y1, gg = ext_gcd(b, a % b, &x1, &y1);
    *x = y1;
    *y = x1 - (a / b) * y1;
    return gg;
}

typedef struct needle_totals {
    unsigned long scenes, needles, in_range, on_centre, visible_px, needle_px, cast_px, ties, bad,
        exact_place;
    double thin, thick;
} needle_totals;

static needle_totals g_needle[2];

static void run_needles(zs_visibility mode)
{
    const int NSCENES = 300, NPER = 12;
    zt_rng g;
    zt_rng_seed(&g, SEED + 2);
    zt_ctx c;
    zt_ctx_init(&c, NW, NW, 200, 300, 200);
    zs_camera cam;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, NW, NW, NUNIT);
    zt_recs recs = {0};
    static uint8_t img[NW * NW * 2];
    needle_totals *tot = &g_needle[mode];
    tot->thin = 1.0;
    for (int n = 0; n < NSCENES; n++) {
        zt_scene_reset(&sc);
        /* the backdrop: a tilted quad over the whole screen, depths 2..12 */
        int b[4];
        for (int k = 0; k < 4; k++)
            b[k] = zt_scene_vertex_px(&sc, (k == 1 || k == 2) ? 3.0 * NW : -2.0 * NW,
                                      k < 2 ? -2.0 * NW : 3.0 * NW, zt_uniform(&g, 2, 12), 0);
        zt_scene_tri_front(&sc, b[0], b[1], b[2], 0);
        zt_scene_tri_front(&sc, b[0], b[2], b[3], 0);
        int32_t want_xy[NPER][6];
        for (int k = 0; k < NPER; k++) {
            int32_t ax, ay, bx, by;
            int64_t dx, dy;
            do {
                ax = (int32_t)zt_range(&g, -128, 16 * NW + 128);
                ay = (int32_t)zt_range(&g, -128, 16 * NW + 128);
                double len = zt_uniform(&g, 4, 16.0 * NW), ang = zt_uniform(&g, 0, 6.283185307);
                bx = ax + (int32_t)lrint(len * cos(ang));
                by = ay + (int32_t)lrint(len * sin(ang));
                if (k % 2 == 0) {
                    /* the long edge through the centre P of a pixel on the
                     * screen, away from both ends: B = A + m (P - A) */
                    int32_t px = 16 * (int32_t)zt_range(&g, 0, NW - 1) + 8;
                    int32_t py = 16 * (int32_t)zt_range(&g, 0, NW - 1) + 8;
                    int32_t m = (int32_t)zt_range(&g, 2, 4);
                    ax = px + (int32_t)lrint((ax - px) / (double)m);
                    ay = py + (int32_t)lrint((ay - py) / (double)m);
                    bx = ax + m * (px - ax);
                    by = ay + m * (py - ay);
                }
                dx = bx - ax;
                dy = by - ay;
            } while (dx == 0 && dy == 0);
            /* third vertex: cross(B - A, C - A) == kk exactly, C between */
            double len_q = sqrt((double)(dx * dx + dy * dy));
            double h = pow(10.0, zt_uniform(&g, -4.0, -1.0)); /* thickness, px */
            int64_t u, v, gg = ext_gcd(dx, -dy, &u, &v);      /* dx u - dy v == gg */
            int64_t kk = (int64_t)llround(h * 16.0 * len_q / (double)gg) * gg;
            if (kk == 0) kk = gg;
            int64_t cy0 = u * (kk / gg), cx0 = v * (kk / gg);
            double frac = zt_uniform(&g, 0.1, 0.9);
            double steps = (frac * len_q * len_q - (double)(cx0 * dx + cy0 * dy)) /
                           (len_q * len_q / (double)gg);
            int64_t m = (int64_t)llround(steps);
            int32_t cx = (int32_t)(ax + cx0 + m * (dx / gg)), cy = (int32_t)(ay + cy0 + m * (dy / gg));
            int va = needle_vertex(&sc, ax, ay, (int)zt_range(&g, 1, 16));
            int vb = needle_vertex(&sc, bx, by, (int)zt_range(&g, 1, 16));
            int vc = needle_vertex(&sc, cx, cy, (int)zt_range(&g, 1, 16));
            /* front-facing: negative area with y down */
            int64_t cr = dx * (int64_t)(cy - ay) - dy * (int64_t)(cx - ax);
            if (cr < 0) {
                zt_scene_tri(&sc, va, vb, vc, 0);
                int32_t xy[6] = {ax, ay, bx, by, cx, cy};
                memcpy(want_xy[k], xy, sizeof xy);
            } else {
                zt_scene_tri(&sc, va, vc, vb, 0);
                int32_t xy[6] = {ax, ay, cx, cy, bx, by};
                memcpy(want_xy[k], xy, sizeof xy);
            }
        }
        zs_mesh mesh = zt_scene_mesh(&sc, 1, 0);
        zs_status st = render_ids(&c, &cam, mode, &mesh, NULL, &recs, img);
        ZT_CHECK(st == ZS_OK, "needle scene %d: %s", n, zs_strerror(st));
        ZT_CHECK(zs_frame_stats(&c.r)->saturated == 0, "needle scene %d saturated", n);
        tot->scenes++;
        /* the needles as stored: thickness from the snapped records */
        for (size_t i = 0; i < recs.n; i++) {
            const zt_rec *t = &recs.v[i];
            if (t->tag <= 2) continue; /* the backdrop */
            tot->needles++;
            if (memcmp(t->xy, want_xy[t->tag - 3], sizeof t->xy) == 0) tot->exact_place++;
            double lmax = 0;
            for (int e = 0; e < 3; e++) {
                double ex = t->xy[(2 * e + 2) % 6] - t->xy[2 * e];
                double ey = t->xy[(2 * e + 3) % 6] - t->xy[2 * e + 1];
                if (hypot(ex, ey) > lmax) lmax = hypot(ex, ey);
            }
            double thick = fabs((double)zt_area2(t->xy)) / (16.0 * lmax);
            if (thick >= 1e-4 && thick <= 1e-1) tot->in_range++;
            if (thick < tot->thin) tot->thin = thick;
            if (thick > tot->thick) tot->thick = thick;
            for (int py = 0; py < NW; py++)
                for (int px = 0; px < NW; px++)
                    if (zt_covers(t->xy, px, py)) {
                        tot->needle_px++;
                        if (zt_id_at(img, NW, px, py) == t->tag) tot->visible_px++;
                        for (int e = 0; e < 3; e++)
                            if (t->xy[2 * e] == 16 * px + 8 && t->xy[2 * e + 1] == 16 * py + 8)
                                tot->on_centre++;
                    }
        }
        char what[64];
        snprintf(what, sizeof what, "needles (%s) scene %d", mode ? "zline" : "span", n);
        cast_result cr = vs_raycast(&recs, img, NW, NW, what);
        tot->bad += cr.bad;
        tot->ties += cr.ties;
        tot->cast_px += cr.px;
    }
    ZT_CHECK(tot->bad == 0, "%lu needle-scene pixels differ from the ray caster", tot->bad);
    /* a few vertices may fall outside int16 positions and be clamped */
    ZT_CHECK(tot->exact_place * 50 >= tot->needles * 49, "%lu of %lu needles not placed exactly",
             tot->needles - tot->exact_place, tot->needles);
    ZT_CHECK(tot->in_range * 10 >= tot->needles * 9, "only %lu of %lu needles 1e-4..1e-1 px thick",
             tot->in_range, tot->needles);
    ZT_CHECK(tot->visible_px > 300, "needles visible at only %lu pixels", tot->visible_px);
    zt_recs_free(&recs);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_needles_span(void **state)
{
    (void)state;
    run_needles(ZS_MODE_SPAN);
}

static void test_needles_zline(void **state)
{
    (void)state;
    run_needles(ZS_MODE_ZLINE);
}

/* ------------------------------------------------------------------ */
/* 3. The same triangle in all three rotations.                        */
/* ------------------------------------------------------------------ */

typedef struct rot_totals {
    unsigned long scenes, groups, copy_px, cast_px, ties, bad, clipped;
} rot_totals;

static rot_totals g_rot[2];

static void run_rotations(zs_visibility mode)
{
    const int W = 96, H = 80, NSCENES = 200;
    zt_rng g;
    zt_rng_seed(&g, SEED + 3);
    zt_ctx c;
    zt_ctx_init(&c, W, H, 800, 2400, 800);
    zs_camera cam;
    const double near_d = 0.5;
    zt_camera_std(&cam, ZS_FX(1) / 2, ZS_FX(100));
    zt_scene sc;
    zt_scene_init(&sc, W, H, 128);
    zt_recs recs = {0};
    static uint8_t img[96 * 80 * 2];
    rot_totals *tot = &g_rot[mode];
    for (int n = 0; n < NSCENES; n++) {
        zt_scene_reset(&sc);
        zt_scene_random(&g, &sc, (int)zt_range(&g, 8, 24),
                        ZT_SC_PLAIN | ZT_SC_FLAT | ZT_SC_NEAR | ZT_SC_BIG | ZT_SC_SHARED, near_d);
        size_t base = sc.nt;
        for (size_t t = 0; t < base; t++) {
            int a = sc.idx[3 * t], b = sc.idx[3 * t + 1], cc = sc.idx[3 * t + 2];
            zs_color col = (zs_color)(zt_u32(&g) & 0xFFFFFFu);
            if (zt_below(&g, 2)) { /* shared vertices */
                zt_scene_tri(&sc, b, cc, a, col);
                zt_scene_tri(&sc, cc, a, b, col);
            } else { /* copied vertices, rotated */
                int id[3] = {b, cc, a}, nv[3];
                for (int k = 0; k < 3; k++) {
                    int v = (int)sc.nv;
                    zt_scene_vertex_world(&sc, 0, 0, 0, 0);
                    memcpy(&sc.pos[3 * v], &sc.pos[3 * id[k]], 3 * sizeof *sc.pos);
                    nv[k] = v;
                }
                zt_scene_tri(&sc, nv[0], nv[1], nv[2], col);
                zt_scene_tri(&sc, nv[1], nv[2], nv[0], col);
            }
            tot->groups++;
        }
        zs_mesh mesh = zt_scene_mesh(&sc, 1, 0);
        zs_status st = render_ids(&c, &cam, mode, &mesh, NULL, &recs, img);
        ZT_CHECK(st == ZS_OK, "rotation scene %d: %s", n, zs_strerror(st));
        const zs_stats *stats = zs_frame_stats(&c.r);
        ZT_CHECK(stats->tris_dropped == 0 && stats->records_skipped == 0,
                 "rotation scene %d: pools too small", n);
        tot->clipped += stats->tris_clipped;
        tot->scenes++;
        /* no pixel may show a later copy of a triangle */
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint16_t id = zt_id_at(img, W, x, y);
                if (id > base) tot->copy_px++;
            }
        char what[64];
        snprintf(what, sizeof what, "rotations (%s) scene %d", mode ? "zline" : "span", n);
        cast_result cr = vs_raycast(&recs, img, W, H, what);
        tot->bad += cr.bad;
        tot->ties += cr.ties;
        tot->cast_px += cr.px;
    }
    ZT_CHECK(tot->copy_px == 0, "%lu pixels show a later copy of a triangle", tot->copy_px);
    ZT_CHECK(tot->bad == 0, "%lu pixels differ from the ray caster", tot->bad);
    zt_recs_free(&recs);
    zt_scene_free(&sc);
    zt_ctx_free(&c);
}

static void test_rotations_span(void **state)
{
    (void)state;
    run_rotations(ZS_MODE_SPAN);
}

static void test_rotations_zline(void **state)
{
    (void)state;
    run_rotations(ZS_MODE_ZLINE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clip_range_span), cmocka_unit_test(test_clip_range_zline),
        cmocka_unit_test(test_needles_span),    cmocka_unit_test(test_needles_zline),
        cmocka_unit_test(test_rotations_span),  cmocka_unit_test(test_rotations_zline),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    for (int m = 0; m < 2; m++) {
        const clip_totals *t = &g_clip[m];
        printf("test_exact clip range (%s): %lu scenes, %lu triangles (%lu clipped), fov "
               "%.1f..%.1f deg; %lu pixels checked against the double pipeline (%lu covered, "
               "%lu left out near edges or depth ties): %lu differ; ray caster: %lu of %lu "
               "differ (%lu near ties); saturations %lu\n",
               m ? "zline" : "span", t->scenes, t->tris, t->clipped, t->fov_min10 / 10.0,
               t->fov_max10 / 10.0, t->px_checked, t->px_covered, t->px_left_out, t->bad,
               t->cast_bad, t->cast_px, t->cast_ties, t->saturated);
    }
    for (int m = 0; m < 2; m++) {
        const needle_totals *t = &g_needle[m];
        printf("test_exact needles (%s): %lu scenes, %lu needles (%lu placed exactly, %lu "
               "1e-4..1e-1 px thick, thinnest %.2g, thickest %.2g px), %lu covered centres "
               "(%lu on a vertex), %lu visible; ray caster: %lu of %lu differ (%lu near ties)\n",
               m ? "zline" : "span", t->scenes, t->needles, t->exact_place, t->in_range, t->thin,
               t->thick, t->needle_px, t->on_centre, t->visible_px, t->bad, t->cast_px, t->ties);
    }
    for (int m = 0; m < 2; m++) {
        const rot_totals *t = &g_rot[m];
        printf("test_exact rotations (%s): %lu scenes, %lu triangles each drawn in 3 rotations "
               "(%lu clipped), pixels showing a later copy: %lu; ray caster: %lu of %lu differ "
               "(%lu near ties)\n",
               m ? "zline" : "span", t->scenes, t->groups, t->clipped, t->copy_px, t->bad,
               t->cast_px, t->ties);
    }
    printf("test_exact: %d failed\n", rc);
    fflush(stdout);
    return rc;
}
