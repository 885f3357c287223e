/* SPDX-License-Identifier: MIT */
/* Geometry stage of zs_draw: transform vertices to clip space, light them,
 * trivially accept or reject triangles by outcodes, clip the rest, and hand
 * every screen triangle to setup. */
#include "zs_internal.h"
#include "zs_mono.h" /* zs_lines_draw */

#define WHITE 0xFFFFFFu
#define REJECT_MASK                                                                       \
    (ZS_OUT_NEAR | ZS_OUT_FAR | ZS_OUT_LEFT | ZS_OUT_RIGHT | ZS_OUT_BOTTOM | ZS_OUT_TOP)

/* Eye coordinates beyond this (2^30 units) are far outside the documented
 * limits; they are clamped so that the clip transform cannot overflow. */
#define EYE_LIMIT ((int64_t)1 << 46)

/* Lives in zs_draw's frame, under every call of the geometry stage: kept
 * small (no copy of the model matrix, no unused translation column). */
typedef struct draw_ctx {
    zs_renderer *r;
    const zs_mesh *mesh;
    const zs_mat34 *model; /* model -> world, for normals (the caller's) */
    uint8_t fast;          /* the folded rows below fit 32 bits */
    uint8_t lit;           /* lighting changes colours */
    uint8_t vertex_light;  /* lighting per vertex (Gouraud with vertex normals) */
    uint8_t vertex_color;  /* Gouraud with per-vertex colours */
    uint8_t tex_slot;      /* the mesh's texture slot (texture.c), 0 = none */
    uint32_t tri_flags;
    int32_t clip[3][3];    /* int16 position -> xc, yc, w, Q32 (scale and projection folded in) */
    int64_t clip_t[3];     /* the translations, Q16 */
    int64_t mv_t[3];       /* model -> eye translation, Q16, unsaturated */
    int32_t mv[3][3];      /* model -> eye, the 3x3 part */
} draw_ctx;

static ZS_NOINLINE int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* Folds scale and projection into the model-view rows where the products
 * fit 32 bits (always, for real scenes: a unit sphere in int16 has a scale
 * near 2^-15); else the general path runs. */
static ZS_NOINLINE void prepare_clip_rows(draw_ctx *c)
{
    const zs_renderer *r = c->r;
    /* w = -z_eye: the third row's factor -1.0 negates exactly */
    const int32_t proj[3] = {r->priv.proj_sx, r->priv.proj_sy, -65536};
    int k, j;
    c->fast = abs64(c->mesh->scale) < ((int64_t)1 << 30);
    for (k = 0; k < 3 && c->fast; k++) {
        for (j = 0; j < 3; j++) {
            int64_t m = zs_asr64((int64_t)c->mv[k][j] * proj[k] + 32768, 16);
            if (abs64(m) >= ((int64_t)1 << 31) || abs64(m * c->mesh->scale) >= INT32_MAX) {
                c->fast = 0;
                break;
            }
            c->clip[k][j] = (int32_t)(m * c->mesh->scale);
        }
        c->clip_t[k] = zs_mul_q16_wide(c->mv_t[k], proj[k]);
    }
}

static int32_t sat_count(zs_renderer *r, int64_t v)
{
    return zs_sat32(v, &r->stats.saturated);
}

/* Model -> eye: the view times the model matrix. The 3x3 part saturates
 * (counted) only for scales beyond Q16.16; the translation is kept in 64
 * bits, as world and eye positions within the limits may lie more than
 * 32768 units apart. */
static ZS_NOINLINE void model_view(draw_ctx *c)
{
    const zs_mat34 *v = &c->r->cam.view, *m = c->model;
    int k, j;
    for (k = 0; k < 3; k++) {
        for (j = 0; j < 4; j++) { /* column j of the model */
            int32_t col[3];
            int64_t s;
            col[0] = m->m[0][j];
            col[1] = m->m[1][j];
            col[2] = m->m[2][j];
            s = zs_dot3_q16(v->m[k], col);
            if (j < 3)
                c->mv[k][j] = sat_count(c->r, s);
            else
                c->mv_t[k] = s + v->m[k][3];
        }
    }
}

/* Model-space vertex i to clip space (Q16.16, not saturated: clip
 * coordinates may pass 2^31 where a narrow field of view or a far vertex
 * magnifies eye coordinates; outcodes and the clipper take them whole). */
/* The fast path's clip coordinates of an int16 position (also the bounding
 * box's corners, so both round alike): 32x16-bit products in 64 bits. */
static inline void fast_clip(const draw_ctx *c, int32_t px, int32_t py, int32_t pz,
                             int64_t *xc, int64_t *yc, int64_t *w)
{
#if ZS_SMALL_
    /* the same sums as a loop over the rows */
    const int32_t p[3] = {px, py, pz};
    int64_t *out[3];
    int k, j;
    out[0] = xc;
    out[1] = yc;
    out[2] = w;
    for (k = 0; k < 3; k++) {
        int64_t s = 32768;
        for (j = 0; j < 3; j++)
            s += zs_mul_32x16(c->clip[k][j], p[j]);
        *out[k] = zs_asr64(s, 16) + c->clip_t[k];
    }
#else
    const int32_t *m0 = c->clip[0], *m1 = c->clip[1], *m2 = c->clip[2];
    int64_t sx = zs_mul_32x16(m0[0], px) + zs_mul_32x16(m0[1], py) + zs_mul_32x16(m0[2], pz) + 32768;
    int64_t sy = zs_mul_32x16(m1[0], px) + zs_mul_32x16(m1[1], py) + zs_mul_32x16(m1[2], pz) + 32768;
    int64_t sw = zs_mul_32x16(m2[0], px) + zs_mul_32x16(m2[1], py) + zs_mul_32x16(m2[2], pz) + 32768;
    *xc = zs_asr64(sx, 16) + c->clip_t[0];
    *yc = zs_asr64(sy, 16) + c->clip_t[1];
    *w = zs_asr64(sw, 16) + c->clip_t[2];
#endif
}

static void to_clip(const draw_ctx *c, uint32_t i, int64_t *xc, int64_t *yc, int64_t *w)
{
    if (c->fast) {
        const int16_t *pos = c->mesh->positions + 3u * i;
        fast_clip(c, pos[0], pos[1], pos[2], xc, yc, w);
    } else { /* general path: model coordinates saturate (counted) */
        zs_renderer *r = c->r;
        const int16_t *pos = c->mesh->positions + 3u * i;
        int32_t p[3];
        int64_t e[3];
        int k;
        for (k = 0; k < 3; k++)
            p[k] = sat_count(r, (int64_t)pos[k] * c->mesh->scale);
        for (k = 0; k < 3; k++) {
            /* within the limits |e| < 2^34; beyond them clamp (counted) so
             * that the products below stay defined */
            e[k] = zs_dot3_q16(c->mv[k], p) + c->mv_t[k];
            if (e[k] > EYE_LIMIT || e[k] < -EYE_LIMIT) {
                r->stats.saturated++;
                e[k] = e[k] > 0 ? EYE_LIMIT : -EYE_LIMIT;
            }
        }
        *xc = zs_mul_q16_wide(e[0], r->priv.proj_sx);
        *yc = zs_mul_q16_wide(e[1], r->priv.proj_sy);
        *w = -e[2];
    }
}

/* Light intensity (Q16.16) for a model-space normal direction n (the
 * caller's scratch: changed). */
static zs_fixed light_intensity(const draw_ctx *c, int64_t n[3])
{
    const zs_renderer *r = c->r;
    int32_t nm[3], unit[3];
    int64_t total = r->shade.ambient;
    int k;
    zs_shrink3(n, (int64_t)1 << 24);
    nm[0] = (int32_t)n[0];
    nm[1] = (int32_t)n[1];
    nm[2] = (int32_t)n[2];
    for (k = 0; k < 3; k++) /* the model's 3x3 takes normals to world space */
        n[k] = zs_dot3_q16(c->model->m[k], nm);
    if (zs_normalize3(n, unit)) {
        for (k = 0; k < r->shade.light_count; k++) {
            int32_t l[3];
            int64_t d;
            l[0] = r->priv.light_dir[k].x;
            l[1] = r->priv.light_dir[k].y;
            l[2] = r->priv.light_dir[k].z;
            d = zs_dot3_q16(unit, l);
            if (d > 0)
                total += zs_asr64(d * r->shade.lights[k].intensity, 16);
        }
    }
    if (total > ((int64_t)16 << 16))
        total = (int64_t)16 << 16;
    return (zs_fixed)total;
}

static uint32_t fog_byte(const zs_renderer *r, int64_t w)
{
    const zs_fog *f = &r->shade.fog;
    int64_t t;
    if (!f->enabled || w <= f->start)
        return 0;
    if (w >= f->end)
        return 255;
    t = (w - f->start) * 255 / ((int64_t)f->end - f->start);
    return (uint32_t)t;
}

/* Per-vertex shade word: RGB (colour or light multiplier) and fog. */
static uint32_t vertex_shade(const draw_ctx *c, uint32_t i, int64_t w)
{
    uint32_t rgb = c->vertex_color ? (c->mesh->vertex_colors[i] & WHITE) : WHITE;
    if (c->vertex_light) {
        const int16_t *nv = c->mesh->vertex_normals + 3u * i;
        int64_t n[3];
        n[0] = nv[0];
        n[1] = nv[1];
        n[2] = nv[2];
        rgb = zs_light_color(rgb, light_intensity(c, n));
    }
    return rgb | (fog_byte(c->r, w) << 24);
}

static uint32_t average3(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s < 24; s += 8) {
        uint32_t sum = ((a >> s) & 255u) + ((b >> s) & 255u) + ((c >> s) & 255u);
        out |= ((sum + 1u) / 3u) << s;
    }
    return out;
}

/* Face colour with flags, lit per face when lighting is not per vertex. */
static uint32_t face_color(const draw_ctx *c, uint32_t t)
{
    const zs_mesh *m = c->mesh;
    const uint16_t *idx = m->indices + 3u * t;
    uint32_t col;
    if (ZS_HAS_GOURAUD && c->vertex_color)
        col = WHITE;
    else if (m->face_colors)
        col = m->face_colors[t] & WHITE;
    else if (m->vertex_colors)
        col = average3(m->vertex_colors[idx[0]], m->vertex_colors[idx[1]],
                       m->vertex_colors[idx[2]]);
    else
        col = m->color & WHITE;
    if (ZS_HAS_LIGHTING && c->lit && !(ZS_HAS_GOURAUD && c->vertex_light)) {
        int64_t n[3];
        if (m->face_normals) {
            const int16_t *fn = m->face_normals + 3u * t;
            n[0] = fn[0];
            n[1] = fn[1];
            n[2] = fn[2];
        } else {
            const int16_t *p0 = m->positions + 3u * idx[0];
            const int16_t *p1 = m->positions + 3u * idx[1];
            const int16_t *p2 = m->positions + 3u * idx[2];
            int32_t a[3], b[3]; /* int16 differences */
            int k;
            for (k = 0; k < 3; k++) {
                a[k] = p1[k] - p0[k];
                b[k] = p2[k] - p0[k];
            }
            zs_cross3(a, b, n);
            if (m->scale < 0) /* a mirrored mesh turns its normals */
                for (k = 0; k < 3; k++)
                    n[k] = -n[k];
        }
        col = zs_light_color(col, light_intensity(c, n));
    }
    return col | (c->tri_flags << 24);
}

/* Is every position in the box lx..hx, ly..hy, lz..hz inside near, far and
 * the guard band? Decided from its 8 corners (fast path only): w is a
 * rounded affine function of the position, so it lies within the corners'
 * range; xc - guard * w may exceed the corners' values by the roundings of
 * xc and w (under 1 + guard units), hence the margin. */
#define INSIDE_MARGIN (2 * ZS_GUARD_MAX)
static int corners_inside(const draw_ctx *c, int32_t lx, int32_t ly, int32_t lz, int32_t hx,
                          int32_t hy, int32_t hz)
{
    const zs_renderer *r = c->r;
    int k;
    for (k = 0; k < 8; k++) {
        int64_t xc, yc, w, gw;
        fast_clip(c, (k & 1) ? hx : lx, (k & 2) ? hy : ly, (k & 4) ? hz : lz, &xc, &yc, &w);
        if (w < r->cam.near_z || w > r->cam.far_z)
            return 0;
        gw = r->priv.guard * w - INSIDE_MARGIN;
        if (xc < -gw || xc > gw || yc < -gw || yc > gw)
            return 0;
    }
    return 1;
}

/* Is every one of the first n vertices inside? (Their bounding box's.) */
static ZS_NOINLINE int box_inside(const draw_ctx *c, uint32_t n)
{
    const int16_t *p = c->mesh->positions, *end = p + 3u * n;
    int32_t lx, ly, lz, hx, hy, hz; /* scalars: the scan stays in registers */
    if (!c->fast || n == 0)
        return 0;
    lx = hx = p[0];
    ly = hy = p[1];
    lz = hz = p[2];
    for (p += 3; p < end; p += 3) {
        int32_t x = p[0], y = p[1], z = p[2];
        lx = x < lx ? x : lx;
        hx = x > hx ? x : hx;
        ly = y < ly ? y : ly;
        hy = y > hy ? y : hy;
        lz = z < lz ? z : lz;
        hz = z > hz ? z : hz;
    }
    return corners_inside(c, lx, ly, lz, hx, hy, hz);
}

/* The clip rows of a fast draw for project_all, with the translations and
 * rounding folded into one constant per row (Cortex-M4 and the like: each
 * row is a 64-bit multiply-accumulate chain); 0 where a clip coordinate
 * might not fit 32 bits. */
#ifndef ZS_SPLIT_MUL
typedef struct inside_rows {
    int64_t k[3]; /* 2^16 clip_t + 2^15 */
} inside_rows;

static int inside_rows_init(const draw_ctx *c, inside_rows *ir)
{
    int k;
    for (k = 0; k < 3; k++) {
        /* |clip coordinate| <= sum |m| 2^15 / 2^16 + |t| + 1: below 2^31 for
         * every int16 position, so it is taken as 32 bits */
        const int32_t *m = c->clip[k];
        if (abs64(m[0]) + abs64(m[1]) + abs64(m[2]) + 2 * abs64(c->clip_t[k]) >=
            ((int64_t)1 << 32) - 4)
            return 0;
        ir->k[k] = c->clip_t[k] * 65536 + 32768;
    }
    return 1;
}
#else
/* Cortex-M0: each coefficient m split as hi * 2^14 + lo, lo in [0, 2^14),
 * so that a row's three products of each part sum in 32 bits (where the
 * hi parts are small, as for every real mesh), no 64-bit product; the clip
 * coordinates then fit 32 bits. */
typedef struct inside_rows {
    int32_t hi[3][3], lo[3][3], t[3];
} inside_rows;

static int inside_rows_init(const draw_ctx *c, inside_rows *ir)
{
    int k, j;
    for (k = 0; k < 3; k++) {
        int32_t sum = 0;
        if (abs64(c->clip_t[k]) >= ((int64_t)1 << 30))
            return 0;
        ir->t[k] = (int32_t)c->clip_t[k];
        for (j = 0; j < 3; j++) {
            int32_t m = c->clip[k][j];
            ir->hi[k][j] = zs_asr32(m, 14);
            ir->lo[k][j] = (int32_t)((uint32_t)m & 0x3FFFu);
            sum += ir->hi[k][j] < 0 ? -ir->hi[k][j] : ir->hi[k][j];
        }
        if (sum >= ((int32_t)1 << 15)) /* |sum of hi * p| < 2^30 */
            return 0;
    }
    return 1;
}

/* floor((m . p + 2^15) / 2^16) + t for row k: the hi sum is a * 4 + b, and
 * hi * 2^14 = a * 2^16 + b * 2^14, so the rest fits 32 bits. */
static ZS_INLINE_ALWAYS int32_t inside_row(const inside_rows *ir, int k, int32_t px, int32_t py,
                                           int32_t pz)
{
    int32_t sh = ir->hi[k][0] * px + ir->hi[k][1] * py + ir->hi[k][2] * pz;
    int32_t sl = ir->lo[k][0] * px + ir->lo[k][1] * py + ir->lo[k][2] * pz; /* < 1.5 * 2^30 */
    return zs_asr32(sh, 2) + zs_asr32((sh & 3) * 16384 + sl + 32768, 16) + ir->t[k];
}
#endif

/* The first n vertices of a fast draw (far below 2^29) into the pool at v:
 * clip coordinates (fast_clip's) and, for those inside near, far and the
 * guard band (zs_outcode's test), the projection, in one pass; the rest are
 * marked unprojected. Returns whether all are inside (what
 * box_inside tells from the bounding box, here from each vertex: the same
 * vertices are projected either way, and an inside draw's triangles go the
 * same way as the per-triangle loop's). */
static ZS_INLINE_ALWAYS int project_run(const draw_ctx *c, const inside_rows *ir,
                                         const zs_proj *p, zs_vert *v, uint32_t n, int checked)
{
    const zs_renderer *r = c->r;
    const int16_t *pos = c->mesh->positions, *end = pos + 3u * n;
    const uint32_t near_z = (uint32_t)r->cam.near_z;
    const uint32_t depth = (uint32_t)r->cam.far_z - near_z;
    const uint32_t guard = (uint32_t)r->priv.guard;
    unsigned outside = 0;
#ifndef ZS_SPLIT_MUL
    const int32_t *m0 = c->clip[0], *m1 = c->clip[1], *m2 = c->clip[2];
#endif
    for (; pos != end; pos += 3, v++) {
        int32_t px = pos[0], py = pos[1], pz = pos[2], xc, yc, w;
        uint32_t gw;
#ifndef ZS_SPLIT_MUL
        xc = (int32_t)zs_asr64(ir->k[0] + (int64_t)m0[0] * px + (int64_t)m0[1] * py +
                                   (int64_t)m0[2] * pz, 16);
        yc = (int32_t)zs_asr64(ir->k[1] + (int64_t)m1[0] * px + (int64_t)m1[1] * py +
                                   (int64_t)m1[2] * pz, 16);
        w = (int32_t)zs_asr64(ir->k[2] + (int64_t)m2[0] * px + (int64_t)m2[1] * py +
                                  (int64_t)m2[2] * pz, 16);
#else
        xc = inside_row(ir, 0, px, py, pz);
        yc = inside_row(ir, 1, px, py, pz);
        w = inside_row(ir, 2, px, py, pz);
#endif
        /* near <= w <= far < 2^29, |xc|, |yc| <= guard * w < 2^31, by
         * differences mod 2^32 (known for every int16 position where not
         * checked) */
        if (checked) {
            if ((uint32_t)w - near_z > depth)
                goto out;
            gw = guard * (uint32_t)w;
            if ((uint32_t)xc + gw > 2u * gw || (uint32_t)yc + gw > 2u * gw)
                goto out;
            ZS_PROJECT_FAST(p, xc, yc, w, v, 1);
        } else {
            ZS_PROJECT_NARROW(p, xc, yc, w, v);
        }
        continue;
    out:
        v->z = ZS_VERT_UNPROJECTED;
        outside = 1;
    }
    return !outside;
}

/* project_run, without a test per vertex where the whole int16 cube of
 * positions is inside near, far and the guard band (box_inside's test of
 * its corners: a mesh small on the screen), depth_scale is below 2^32 (near
 * below 3/4 of far) and near below 2^30 (zs_project_body's narrow case). */
#if defined(__GNUC__) && defined(__thumb2__) && defined(__ARM_FEATURE_SIMD32) &&            \
    defined(__ARM_FEATURE_IDIV) && !defined(ZS_SPLIT_MUL) && defined(__BYTE_ORDER__) &&     \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ /* (x, y stored as the halves of one word) */
#define PROJECT_ASM 1
/* project_run's unchecked loop on Cortex-M4, the same arithmetic step for
 * step (fast_clip's rows, zs_recip61_fast, zs_project_body's narrow case),
 * with its constants in one block taken by load-multiples: the compiler's
 * copy spills a dozen values a vertex. Order: each row's 64-bit constant
 * and coefficients (w, xc, yc), near_z * 4, ds_lo, xk, hw, yk, nhh, end. */
static void project_narrow_asm(const int32_t blk[24], const int16_t *pos, zs_vert *v)
{
    register const int32_t *r0 __asm__("r0") = blk;
    register const int16_t *r1 __asm__("r1") = pos;
    register zs_vert *r2 __asm__("r2") = v;
    __asm__ volatile(
        ".syntax unified\n"
        "1:  ldrsh r4, [r1, #2]\n"
        "    ldrsh r5, [r1, #4]\n"
        "    ldrsh r3, [r1], #6\n"
        /* w = (kw + m2 . p) >> 16, xc and yc likewise */
        "    ldmia r0!, {r6, r8, r9, r10, r11}\n"
        "    smlal r6, r8, r9, r3\n"
        "    smlal r6, r8, r10, r4\n"
        "    smlal r6, r8, r11, r5\n"
        "    lsrs r6, r6, #16\n"
        "    orr lr, r6, r8, lsl #16\n"
        "    ldmia r0!, {r6, r8, r9, r10, r11}\n"
        "    smlal r6, r8, r9, r3\n"
        "    smlal r6, r8, r10, r4\n"
        "    smlal r6, r8, r11, r5\n"
        "    lsrs r6, r6, #16\n"
        "    orr r12, r6, r8, lsl #16\n"
        "    ldmia r0!, {r6, r8, r9, r10, r11}\n"
        "    smlal r6, r8, r9, r3\n"
        "    smlal r6, r8, r10, r4\n"
        "    smlal r6, r8, r11, r5\n"
        "    lsrs r6, r6, #16\n"
        "    orr r3, r6, r8, lsl #16\n"
        /* r4 = clz(w) = s + 1, d = w << s in r5, inv in r6 (zs_recip61_fast) */
        "    clz r4, lr\n"
        "    subs r5, r4, #1\n"
        "    lsl r5, lr, r5\n"
        "    add r6, r5, #0x4000\n"
        "    lsrs r6, r6, #15\n"
        "    mov r8, #-1\n"
        "    udiv r6, r8, r6\n"
        "    lsls r6, r6, #14\n"
        "    umull r8, r9, r5, r6\n"
        "    negs r8, r8\n"
        "    mov r10, #0x20000000\n"
        "    sbc r9, r10, r9\n"
        "    lsrs r8, r8, #16\n"
        "    orr r8, r8, r9, lsl #16\n"
        "    smull r9, r10, r6, r8\n"
        "    smull r9, r11, r10, r8\n"
        "    asrs r10, r10, #5\n"
        "    add r10, r10, r11, asr #18\n"
        "    subs r10, r10, #1\n"
        "    add r6, r6, r10, asr #8\n"
        "    mul r8, r5, r6\n"
        "    negs r8, r8\n"
        "    cmp r8, r5\n"
        "    it cs\n"
        "    addcs r6, r6, #1\n"
        /* shifts 33 - s (r5) and s - 1 (r4); nx in r12, ny in r3 */
        "    rsb r5, r4, #34\n"
        "    subs r4, r4, #2\n"
        "    umull r8, r9, r12, r6\n"
        "    asr r10, r12, #31\n"
        "    mla r9, r10, r6, r9\n"
        "    lsr r8, r8, r5\n"
        "    lsl r9, r9, r4\n"
        "    orr r12, r8, r9\n"
        "    umull r8, r9, r3, r6\n"
        "    asr r10, r3, #31\n"
        "    mla r9, r10, r6, r9\n"
        "    lsr r8, r8, r5\n"
        "    lsl r9, r9, r4\n"
        "    orr r3, r8, r9\n"
        /* q = near / w (Q30), the depth in lr */
        "    ldmia r0!, {r10, r11}\n"
        "    umull r8, r9, r10, r6\n"
        "    lsr r8, r8, r5\n"
        "    lsl r9, r9, r4\n"
        "    orr r8, r8, r9\n"
        "    rsb r8, r8, #0x40000000\n"
        "    umull r8, r9, r8, r11\n"
        "    lsrs r8, r8, #30\n"
        "    orr lr, r8, r9, lsl #2\n"
        "    cmp lr, #0x40000000\n"
        "    it hi\n"
        "    movhi lr, #0x40000000\n"
        /* x and y, the record */
        "    ldmia r0!, {r8, r9, r10}\n"
        "    smlal r8, r9, r12, r10\n"
        "    lsrs r8, r8, #28\n"
        "    orr r12, r8, r9, lsl #4\n"
        "    ldmia r0!, {r8, r9, r10, r11}\n"
        "    smlal r8, r9, r3, r10\n"
        "    lsrs r8, r8, #28\n"
        "    orr r3, r8, r9, lsl #4\n"
        "    pkhbt r12, r12, r3, lsl #16\n"
        "    strd r12, lr, [r2], #8\n"
        "    subs r0, r0, #96\n"
        "    cmp r1, r11\n"
        "    bne 1b\n"
        : "+r"(r0), "+r"(r1), "+r"(r2)
        :
        : "r3", "r4", "r5", "r6", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
}

static void narrow_block(const draw_ctx *c, const inside_rows *ir, const zs_proj *p,
                         const int16_t *end, int32_t blk[24])
{
    static const uint8_t row[3] = {2, 0, 1}; /* w, xc, yc */
    int k, j;
    for (k = 0; k < 3; k++) {
        uint64_t kk = (uint64_t)ir->k[row[k]];
        blk[5 * k] = zs_s32((uint32_t)(kk & 0xFFFFFFFFu));
        blk[5 * k + 1] = zs_s32((uint32_t)(kk >> 32));
        for (j = 0; j < 3; j++)
            blk[5 * k + 2 + j] = c->clip[row[k]][j];
    }
    blk[15] = zs_s32(p->near_z << 2);
    blk[16] = zs_s32(p->ds_lo);
    blk[17] = zs_s32((uint32_t)((uint64_t)p->xk & 0xFFFFFFFFu));
    blk[18] = zs_s32((uint32_t)((uint64_t)p->xk >> 32));
    blk[19] = p->hw;
    blk[20] = zs_s32((uint32_t)((uint64_t)p->yk & 0xFFFFFFFFu));
    blk[21] = zs_s32((uint32_t)((uint64_t)p->yk >> 32));
    blk[22] = p->nhh;
    blk[23] = zs_s32((uint32_t)(uintptr_t)end);
}
#endif

static ZS_NOINLINE int project_all(const draw_ctx *c, const inside_rows *ir, const zs_proj *p,
                                   zs_vert *v, uint32_t n)
{
    if (p->ds_hi == 0 && p->near_z < ((uint32_t)1 << 30) &&
        corners_inside(c, -32768, -32768, -32768, 32767, 32767, 32767)) {
#ifdef PROJECT_ASM
        int32_t blk[24];
        if (n == 0)
            return 1;
        narrow_block(c, ir, p, c->mesh->positions + 3u * n, blk);
        project_narrow_asm(blk, c->mesh->positions, v);
        return 1;
#else
        return project_run(c, ir, p, v, n, 0);
#endif
    }
    return project_run(c, ir, p, v, n, 1);
}

/* Vertices base .. base + n - 1 of the pool from the mesh's first n. Out of
 * line (called once a draw), so its locals stay off zs_draw's frame, which
 * lies under the clipper's. Returns whether all are inside near, far and the
 * guard band (then each triangle needs no clip test). */
static ZS_NOINLINE int transform_vertices(const draw_ctx *c, uint16_t base, uint32_t n)
{
    zs_renderer *r = c->r;
    zs_vert *v = &r->priv.verts[base];
    uint32_t i;
    zs_proj p;
    inside_rows ir;
    unsigned test;
    /* zs_project_fast suits every vertex within near, far and the guard
     * band when far is below 2^29 (not in a small build: the loop below
     * projects the same vertices alike) */
    if (!ZS_SMALL_ && c->fast && zs_proj_init(r, &p) && r->cam.far_z < ((int32_t)1 << 29) &&
        inside_rows_init(c, &ir)) {
        int all = project_all(c, &ir, &p, v, n);
        if (r->priv.vshade || !all) /* shade words, outcodes: a second pass */
            for (i = 0; i < n; i++) {
                int64_t xc, yc, w;
                if (!r->priv.vshade && !(v[i].z & ZS_VERT_UNPROJECTED))
                    continue;
                to_clip(c, i, &xc, &yc, &w);
                if (r->priv.vshade)
                    r->priv.vshade[base + i] = vertex_shade(c, i, w);
                if (v[i].z & ZS_VERT_UNPROJECTED) /* for clip_and_setup */
                    v[i].x = (int16_t)zs_outcode(r, xc, yc, w);
            }
        return all;
    }
    /* a mesh wholly inside needs no outcode per vertex (a small build takes
     * them all: the same vertices are inside) */
    test = !ZS_SMALL_ && box_inside(c, n) ? 0u : (ZS_OUT_NEAR | ZS_OUT_FAR | ZS_OUT_GUARD);
    for (i = 0; i < n; i++, v++) {
        int64_t xc, yc, w;
        unsigned oc = 0;
        to_clip(c, i, &xc, &yc, &w);
        if (ZS_HAS_PLANES_ && r->priv.vshade)
            r->priv.vshade[base + i] = vertex_shade(c, i, w);
        if (test)
            oc = zs_outcode(r, xc, yc, w);
        if (oc & test) {
            v->z = ZS_VERT_UNPROJECTED;
            v->x = (int16_t)oc; /* for clip_and_setup */
        } else /* near <= w <= far: 32 bits */
            zs_project(r, xc, yc, (int32_t)w, &v->x, &v->y, &v->z);
    }
    return test == 0;
}


/* Outcome priority when pieces of one clipped triangle end differently. */
static int merge_outcome(int have, int piece)
{
    /* stored > dropped > empty > culled > rejected */
    static const uint8_t rank[5] = {4, 1, 2, 0, 3};
    return rank[piece] > rank[have] ? piece : have;
}

static void count_outcome(zs_stats *s, int outcome)
{
    /* tests, not a switch: the common outcome first, no case table (a helper
     * call on Cortex-M0 at -Os) */
    if (outcome == ZS_SETUP_STORED)
        s->tris_stored++;
    else if (outcome == ZS_SETUP_CULLED)
        s->tris_culled++;
    else if (outcome == ZS_SETUP_EMPTY)
        s->tris_empty++;
    else if (outcome == ZS_SETUP_DROPPED)
        s->tris_dropped++;
    else
        s->tris_rejected++;
}

/* The tag of triangle t of a draw that starts at frame count tag0: 1..65535
 * (the count wraps like the 32-bit counter it replaces). */
static uint16_t tag_of(uint32_t tag0, uint32_t t)
{
    return (uint16_t)((tag0 + t) % 65535u + 1u);
}

/* The same without a division per triangle (a helper call on Cortex-M0):
 * base = tag0 % 65535, valid while t < 65535 (a uint16 count) and tag0 + t
 * does not wrap. */
static uint16_t tag_from_base(uint32_t base, uint32_t t)
{
    uint32_t v = base + t;
    if (v >= 65535u)
        v -= 65535u;
    return (uint16_t)(v + 1u);
}

/* zs_draw's tag of triangle t: one copy out of line in a small build. */
#if ZS_SMALL_
static ZS_NOINLINE uint16_t draw_tag(int fast, uint32_t base, uint32_t tag0, uint32_t t)
{
    return fast ? tag_from_base(base, t) : tag_of(tag0, t);
}
#define DRAW_TAG(t) draw_tag(tag_fast, tag_base, tag0, t)
#else
#define DRAW_TAG(t) (tag_fast ? tag_from_base(tag_base, t) : tag_of(tag0, t))
#endif

/* Is a before b in lexicographic order of (w, yc, xc)? */
static ZS_NOINLINE int svert_before(const zs_svert *a, const zs_svert *b)
{
    if (a->w != b->w)
        return a->w < b->w;
    if (a->yc != b->yc)
        return a->yc < b->yc;
    return a->xc < b->xc;
}

static int first_vertex(const zs_svert in[3])
{
    int k = svert_before(&in[1], &in[0]) ? 1 : 0;
    return svert_before(&in[2], &in[k]) ? 2 : k;
}

/* Triangle t with a vertex outside near/far/guard: reject or clip it. It
 * reads its indices itself, so the caller's stay in registers. */
static ZS_COLD int clip_and_setup(draw_ctx *c, uint16_t base, uint32_t t, uint16_t tag)
{
    zs_renderer *r = c->r;
    zs_vert *pool = r->priv.verts;
    zs_svert v[9]; /* the triangle, clipped in place (clip.c allows it) */
    unsigned and_codes = 0xFFu;
    int n, k, outcome = ZS_SETUP_REJECTED;
    uint32_t color;
    const uint16_t *idx = c->mesh->indices + 3u * t;
    /* the unprojected vertices' outcodes were kept in their x: where they
     * share no reject bit neither do all three, else the projected ones'
     * outcodes decide (the usual rejects need no clip coordinates at all) */
    for (k = 0; k < 3; k++) {
        const zs_vert *pv = &pool[base + idx[k]];
        if (pv->z & ZS_VERT_UNPROJECTED)
            and_codes &= (unsigned)pv->x;
    }
    if (and_codes & REJECT_MASK) {
        for (k = 0; k < 3; k++) {
            const zs_vert *pv = &pool[base + idx[k]];
            if (!(pv->z & ZS_VERT_UNPROJECTED)) {
                to_clip(c, idx[k], &v[k].xc, &v[k].yc, &v[k].w);
                and_codes &= zs_outcode(r, v[k].xc, v[k].yc, v[k].w);
            }
        }
        if (and_codes & REJECT_MASK)
            return ZS_SETUP_REJECTED;
    }
    for (k = 0; k < 3; k++) {
        const zs_vert *pv = &pool[base + idx[k]];
        to_clip(c, idx[k], &v[k].xc, &v[k].yc, &v[k].w);
        v[k].shade = ZS_HAS_PLANES_ && r->priv.vshade ? r->priv.vshade[base + idx[k]] : 0;
        v[k].pool = (pv->z & ZS_VERT_UNPROJECTED) ? (uint16_t)ZS_NONE : (uint16_t)(base + idx[k]);
        v[k].uv[0] = ZS_HAS_TEXTURE && c->tex_slot ? c->mesh->uvs[2u * idx[k]] : 0;
        v[k].uv[1] = ZS_HAS_TEXTURE && c->tex_slot ? c->mesh->uvs[2u * idx[k] + 1u] : 0;
    }
    r->stats.tris_clipped++;
    /* start from a canonical vertex: the same triangle with its vertices
     * rotated is then cut into the same pieces (equal planes, so exact ties
     * still go to the earlier triangle) */
    for (k = first_vertex(v); k > 0; k--) { /* rotate left k times */
        v[3] = v[0];
        v[0] = v[1];
        v[1] = v[2];
        v[2] = v[3];
    }
    n = zs_clip_polygon(r, v, 3, v);
    if (n < 3)
        return ZS_SETUP_REJECTED;
    color = face_color(c, t);
    for (k = 0; k < n; k++)
        if (v[k].pool == ZS_NONE) {
            v[k].pool = zs_project_vertex(r, v[k].xc, v[k].yc, (int32_t)v[k].w, v[k].shade);
            /* texture.c's record */
            if (ZS_HAS_TEXTURE && r->priv.tex_verts && v[k].pool != ZS_NONE) {
                zs_tex_vert *tv = &r->priv.tex_verts[v[k].pool];
                tv->u = v[k].uv[0];
                tv->v = v[k].uv[1];
                tv->slot = c->tex_slot;
            }
        }
    for (k = 1; k + 1 < n; k++) {
        int piece;
        if (v[0].pool == ZS_NONE || v[k].pool == ZS_NONE || v[k + 1].pool == ZS_NONE) {
            piece = ZS_SETUP_DROPPED;
            r->stats.records_dropped++;
        } else
            piece = zs_setup_triangle(r, v[0].pool, v[k].pool, v[k + 1].pool,
                                      zs_area2(&pool[v[0].pool], &pool[v[k].pool],
                                               &pool[v[k + 1].pool]),
                                      color, tag);
        outcome = merge_outcome(outcome, piece);
    }
    return outcome;
}

/* The triangles of a draw whose vertices all fit the pool and are all
 * projected (the mesh is inside): no per-triangle index or clip test, counts
 * kept in locals. */
static ZS_NOINLINE void setup_inside(draw_ctx *c, uint16_t base, uint32_t tag_base)
{
    zs_renderer *r = c->r;
    const zs_mesh *m = c->mesh;
    const zs_vert *pool = r->priv.verts + base;
    const uint16_t *idx = m->indices;
    uint32_t t, n = m->triangle_count, culled = 0;
    /* face colours from a table or one colour, not lit per face (face_color's
     * first and last cases): setup.c's loop, each colour a load */
    if (!(c->lit && !c->vertex_light) && (c->vertex_color || m->face_colors || !m->vertex_colors)) {
        uint32_t flags = c->tri_flags << 24;
        if (c->vertex_color)
            zs_setup_run(r, idx, n, base, 0, WHITE | flags, tag_base);
        else
            zs_setup_run(r, idx, n, base, m->face_colors, (m->color & WHITE) | flags, tag_base);
        return;
    }
    for (t = 0; t < n; t++, idx += 3) {
        uint32_t i0 = idx[0], i1 = idx[1], i2 = idx[2];
        int64_t area2 = zs_area2_inline(&pool[i0], &pool[i1], &pool[i2]);
        if (area2 >= 0) { /* culled before lighting the face */
            culled++;
            continue;
        }
        count_outcome(&r->stats, zs_setup_triangle(r, (uint16_t)(base + i0),
                                                   (uint16_t)(base + i1),
                                                   (uint16_t)(base + i2), area2,
                                                   face_color(c, t),
                                                   tag_from_base(tag_base, t)));
    }
    r->stats.tris_culled += culled;
}

/* Hidden lines: the eye-space normals of a draw's records (lines.c). */
#ifdef ZS_NO_MONO
#define LINES_NORMALS(c, first, tag_base) ((void)0)
#else
#define LINES_NORMALS(c, first, tag_base)                                                   \
    do {                                                                                   \
        if ((c)->r->priv.line_keep)                                                        \
            zs_lines_draw((c)->r, (c)->mesh, (const int32_t(*)[3])(c)->mv, first, tag_base); \
    } while (0)
#endif

/* Are all indices below vcount (>= 1)? (vcount - 1 - index) wraps past 2^31
 * exactly when an index is too large: one subtraction and one OR each, no
 * branch per index. */
static ZS_NOINLINE int indices_valid(const uint16_t *idx, uint32_t tris, uint32_t vcount)
{
    const uint16_t *end = idx + 3u * tris;
    const uint32_t last = vcount - 1u;
    uint32_t bad = 0, acc = 0;
#if defined(__ARM_FEATURE_SIMD32) && defined(ZS_WORD_STORES)
    /* Cortex-M4: two indices a word, both against last at once (usub16 sets
     * a lane's GE flag where index <= last, sel keeps bad's lane there and
     * takes all ones elsewhere), four words a load-multiple */
    if (((uintptr_t)idx & 2u) && idx != end)
        bad |= last - *idx++; /* to a word boundary */
    if (end - idx >= 2) {
        const zs_word_alias *w = (const zs_word_alias *)(const void *)idx;
        const zs_word_alias *wend = w + (end - idx) / 2;
        const uint32_t lim = last * 0x10001u, ones = 0xFFFFFFFFu; /* last <= 65534 */
        while ((wend - w) & 3) { /* then blocks of four words */
            uint32_t t;
            __asm__(".syntax unified\n"
                    "    usub16 %1, %2, %3\n"
                    "    sel %0, %0, %4\n"
                    : "+r"(acc), "=&r"(t)
                    : "r"(lim), "r"(*w++), "r"(ones)
                    : "cc");
        }
        if (w != wend) {
            uint32_t t;
            __asm__(".syntax unified\n"
                    "1:  ldmia %[w]!, {r4, r5, r6, r8}\n"
                    "    usub16 %[t], %[lim], r4\n"
                    "    sel %[acc], %[acc], %[ones]\n"
                    "    usub16 %[t], %[lim], r5\n"
                    "    sel %[acc], %[acc], %[ones]\n"
                    "    usub16 %[t], %[lim], r6\n"
                    "    sel %[acc], %[acc], %[ones]\n"
                    "    usub16 %[t], %[lim], r8\n"
                    "    sel %[acc], %[acc], %[ones]\n"
                    "    cmp %[w], %[end]\n"
                    "    bne 1b\n"
                    : [w] "+r"(w), [acc] "+r"(acc), [t] "=&r"(t)
                    : [end] "r"(wend), [lim] "r"(lim), [ones] "r"(ones)
                    : "r4", "r5", "r6", "r8", "cc", "memory");
        }
        idx = (const uint16_t *)(const void *)wend;
    }
    for (; idx != end; idx++)
        bad |= last - *idx;
#else
    if (idx != end)
        do /* tested at the bottom: one branch a triangle */
            bad |= (last - idx[0]) | (last - idx[1]) | (last - idx[2]);
        while ((idx += 3) != end);
#endif
    return (bad >> 31) == 0 && acc == 0;
}

zs_status zs_draw(zs_renderer *r, const zs_mesh *m, const zs_mat34 *model)
{
    draw_ctx c;
    zs_vert *pool;
    uint32_t t, t_end, vfit, room, tag0, tag_base;
    int tag_fast, inside;
    uint16_t base, first;
    if (!r || !m)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    if (!m->positions || !m->indices || m->scale == 0 || m->vertex_count == 0)
        return ZS_ERR_MESH;
    if (!indices_valid(m->indices, m->triangle_count, m->vertex_count))
        return ZS_ERR_INDEX;
    c.tex_slot = 0;
    if (m->uvs || m->texture) { /* texture.c checks it and takes a slot */
        zs_status st = ZS_HAS_TEXTURE ? zs_tex_draw(r, m, &c.tex_slot) : ZS_ERR_MODE;
        if (st != ZS_OK)
            return st;
    }
    c.r = r;
    c.mesh = m;
    c.model = model ? model : &zs_identity34;
    first = r->priv.n_tris;
    if (ZS_HAS_MONO && r->priv.draw_starts && first < r->cfg.max_triangles) /* hidden lines */
        r->priv.draw_starts[first >> 3] |= (uint8_t)(1u << (first & 7u));
    model_view(&c);
    prepare_clip_rows(&c);
    c.lit = (uint8_t)(r->shade.light_count > 0 || r->shade.ambient != ZS_FX_ONE);
    /* (without ZS_HAS_GOURAUD shading is flat and fog off: zs_frame_shading) */
    c.vertex_light = (uint8_t)(ZS_HAS_GOURAUD && r->shade.shading == ZS_SHADE_GOURAUD && c.lit &&
                               m->vertex_normals != 0);
    c.vertex_color =
        (uint8_t)(ZS_HAS_GOURAUD && r->shade.shading == ZS_SHADE_GOURAUD && m->vertex_colors != 0);
    c.tri_flags = ((c.vertex_light || c.vertex_color) ? ZS_TRI_MODULATE : 0u) |
                  /* texture.c fogs */
                  ((ZS_HAS_GOURAUD && r->shade.fog.enabled && !c.tex_slot) ? ZS_TRI_FOG : 0u) |
                  (c.tex_slot ? ZS_TRI_TEXTURED : 0u);

    /* vertices: transform all that fit the pool (capacity policy: the last
     * vertices are dropped, and so are the triangles that use them) */
    pool = r->priv.verts;
    base = r->priv.n_verts;
    room = (uint32_t)r->cfg.max_vertices - base;
    vfit = m->vertex_count < room ? m->vertex_count : room;
    r->stats.verts_dropped += m->vertex_count - vfit;
    inside = transform_vertices(&c, base, vfit);
    if (ZS_HAS_TEXTURE && r->priv.tex_verts)
        zs_tex_vertices(r, m, base, vfit, c.tex_slot);
    r->priv.n_verts = (uint16_t)(base + vfit);
    r->stats.verts_stored = r->priv.n_verts;

    /* triangle t takes tag number tag0 + t (wrapping like the counter), so
     * only the triangles that reach setup compute their tag */
    tag0 = r->priv.tag_counter;
    tag_base = tag0 % 65535u;
    tag_fast = tag0 <= UINT32_MAX - m->triangle_count; /* and t < 65535: uint16 count */
    r->priv.tag_counter += m->triangle_count;
    /* (a small build takes the loop below: the same outcomes and counts) */
    if (!ZS_SMALL_ && inside && vfit == m->vertex_count && tag_fast && !r->priv.ranges) {
        r->stats.tris_submitted += m->triangle_count;
        setup_inside(&c, base, tag_base);
        LINES_NORMALS(&c, first, tag_base);
        return ZS_OK;
    }
    t = 0;
    t_end = r->priv.ranges ? 0u : m->triangle_count; /* zs_draw_bsp: ranges in order */
    while (t < t_end || (ZS_HAS_PRIORITY && r->priv.ranges && zs_next_range(r, &t, &t_end)))
    for (; t < t_end; t++) {
        const uint16_t *idx = m->indices + 3u * t;
        uint32_t i0 = idx[0], i1 = idx[1], i2 = idx[2];
        const zs_vert *v0, *v1, *v2;
        int outcome;
        r->stats.tris_submitted++;
        if (i0 >= vfit || i1 >= vfit || i2 >= vfit) {
            r->stats.tris_dropped++;
            r->stats.records_dropped++;
            continue;
        }
        v0 = &pool[base + i0];
        v1 = &pool[base + i1];
        v2 = &pool[base + i2];
        if ((v0->z | v1->z | v2->z) & ZS_VERT_UNPROJECTED) {
            outcome = clip_and_setup(&c, base, t, DRAW_TAG(t));
        } else {
            /* (a small build calls setup.c's copy) */
            int64_t area2 = ZS_SMALL_ ? zs_area2(v0, v1, v2) : zs_area2_inline(v0, v1, v2);
            if (area2 >= 0) /* culled before lighting the face */
                outcome = ZS_SETUP_CULLED;
            else
                outcome = zs_setup_triangle(r, (uint16_t)(base + i0), (uint16_t)(base + i1),
                                            (uint16_t)(base + i2), area2, face_color(&c, t),
                                            DRAW_TAG(t));
        }
        count_outcome(&r->stats, outcome);
    }
    LINES_NORMALS(&c, first, tag_base);
    return ZS_OK;
}
