/* SPDX-License-Identifier: MIT */
/* Hidden-line drawing from the visibility the span walk computes: each row
 * is rendered as triangle ids, and a pixel is on an edge where its id differs
 * from the pixel on its left or above, unless the two triangles are smooth
 * neighbours (they share a vertex of the frame's pool and their normals are
 * within the crease angle). So silhouettes (against the background or a
 * farther surface), creases and boundaries between draw calls (which never
 * share pool vertices) are drawn, one pixel wide, on the pixel right of or
 * below the change. Only what is visible has ids, so hidden edges are never
 * drawn.
 *
 * Normals come from the pool's screen vertices: with X = x - 8W, Y = 8H - y
 * (1/16 px from the centre) and K = 8H cot(fov/2), the eye-space point of a
 * vertex is w (X, Y, -K) / K, and 1/w is proportional to q = A - z (window
 * depth z = A (1 - near/w)). The normal (P1 - P0) x (P2 - P0), divided by
 * the positive w0 w1 w2, is sum over cyclic (i, j, k) of q_k (D_i x D_j),
 * D = (X, Y, -K): integers only, no division. */
#include "zs_mono.h"


static int any_positive(const int64_t q[3])
{
    int64_t m = q[0];
    if (q[1] > m)
        m = q[1];
    if (q[2] > m)
        m = q[2];
    return m > 0 ? 1 : 0;
}

/* Unit normal (Q14, toward the eye) of record t in n[0..2] (all 0 when the
 * triangle is degenerate); n[3] is left to the caller. */
static ZS_COLD void record_normal(const zs_renderer *r, const zs_tri *t, int64_t A, int64_t K,
                                  unsigned kshift, int16_t n[4])
{
    const zs_vert *pool = r->priv.verts;
    int64_t X[3], Y[3], q[3], s[3], v[3], d0[3];
    int32_t u[3];
    int k;
    for (k = 0; k < 3; k++) {
        const zs_vert *p = &pool[t->v[k]];
        X[k] = (int64_t)p->x - 8 * (int64_t)r->cfg.width;
        Y[k] = 8 * (int64_t)r->cfg.height - p->y;
        q[k] = A - (int64_t)p->z;
        if (q[k] < 0)
            q[k] = 0;
    }
    n[0] = n[1] = n[2] = 0;
    if (!any_positive(q))
        return;
    /* q < 2^25, |X|, |Y| < 2^17: every sum below fits 63 bits */
    while (q[0] >= ((int64_t)1 << 25) || q[1] >= ((int64_t)1 << 25) ||
           q[2] >= ((int64_t)1 << 25))
        for (k = 0; k < 3; k++)
            q[k] >>= 1;
    s[0] = s[1] = s[2] = 0;
    for (k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3; /* (i, j, k) cyclic */
        s[0] += q[k] * (Y[j] - Y[i]);
        s[1] += q[k] * (X[i] - X[j]);
        s[2] += q[k] * (X[i] * Y[j] - X[j] * Y[i]);
    }
    /* (K s0, K s1, s2) with K reduced by 2^kshift: divide s2 alike */
    v[0] = K * s[0];
    v[1] = K * s[1];
    v[2] = zs_asr64(s[2], kshift);
    if (!zs_normalize3(v, u))
        return;
    /* toward the eye: the normal and the eye-to-vertex direction disagree */
    d0[0] = X[0];
    d0[1] = Y[0];
    d0[2] = -(K << kshift);
    zs_shrink3(d0, (int64_t)1 << 24);
    if (d0[0] * u[0] + d0[1] * u[1] + d0[2] * u[2] > 0)
        for (k = 0; k < 3; k++)
            u[k] = -u[k];
    for (k = 0; k < 3; k++)
        n[k] = (int16_t)zs_asr32(u[k], 2);
}

void zs_lines_begin(zs_renderer *r)
{
    int64_t A, K;
    unsigned kshift = 0;
    uint16_t i, draw = 0;
    int deg = r->shade.crease_deg ? r->shade.crease_deg : 30;
    r->priv.crease_cos = zs_fx_cos_deg(ZS_FX(deg)) * 4096; /* Q16 -> Q28 */
    r->priv.line_prev_row = 0;
    if (r->priv.depth_scale != 0) {
        A = r->priv.depth_scale;
    } else {
        int64_t f = r->cam.far_z, nz = r->cam.near_z;
        A = (f * ((int64_t)1 << 30)) / (f - nz);
    }
    r->priv.line_depth_a = A;
    K = ((int64_t)r->cfg.height * r->priv.proj_sy) >> 13; /* 8 H cot, 1/16 px */
    if (K < 1)
        K = 1;
    while (K >= ((int64_t)1 << 16)) {
        K >>= 1;
        kshift++;
    }
    for (i = 0; i < r->priv.n_tris; i++) {
        int16_t *n = &r->priv.tri_normal[4u * i];
        if (r->priv.draw_starts[i >> 3] & (1u << (i & 7u)))
            draw++;
        record_normal(r, &r->priv.tris[i], A, K, kshift, n);
        n[3] = (int16_t)(draw & 0x7FFFu); /* draw number (wrapping) */
    }
}

/* First record with tag >= tag: records are in submission order, and so are
 * their tags (ID16 keeps the tag in the colour word) while a frame has fewer
 * than 65536 submitted triangles. */
static uint16_t first_record(const zs_renderer *r, uint16_t tag)
{
    const zs_tri *t = r->priv.tris;
    uint32_t lo = 0, hi = r->priv.n_tris;
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2u;
        if (t[mid].color < tag)
            lo = mid + 1u;
        else
            hi = mid;
    }
    return (uint16_t)lo;
}

static int share_vertex(const zs_tri *a, const zs_tri *b)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            if (a->v[i] == b->v[j])
                return 1;
    return 0;
}

/* Window depth (Q2.30) of record t's plane at (px, py) in 1/16 px. The
 * depth differences lose their 6 low bits so that every product fits 63
 * bits (|dx|, |dy| < 2^16); the plane is only compared within 1/64 here. */
static int64_t plane_depth(const zs_renderer *r, const zs_tri *t, int32_t px, int32_t py)
{
    const zs_vert *a = &r->priv.verts[t->v[0]], *b = &r->priv.verts[t->v[1]],
                  *c = &r->priv.verts[t->v[2]];
    int64_t dx1 = b->x - a->x, dy1 = b->y - a->y, dx2 = c->x - a->x, dy2 = c->y - a->y;
    int64_t dz1 = zs_asr64((int64_t)b->z - (int64_t)a->z, 6);
    int64_t dz2 = zs_asr64((int64_t)c->z - (int64_t)a->z, 6);
    int64_t den = dx1 * dy2 - dx2 * dy1;
    int64_t num = (dz1 * dy2 - dz2 * dy1) * (px - a->x) + (dz2 * dx1 - dz1 * dx2) * (py - a->y);
    if (den == 0)
        return a->z;
    return (int64_t)a->z + (num / den) * 64;
}

/* Do the two planes meet at (px, py)? Their depths agree to 1/64 of
 * A - z (proportional to 1/w: about 1.5% of the eye distance). */
static int meet_at(const zs_renderer *r, const zs_tri *a, const zs_tri *b, int32_t px,
                   int32_t py)
{
    int64_t za = plane_depth(r, a, px, py), zb = plane_depth(r, b, px, py);
    int64_t d = za > zb ? za - zb : zb - za;
    int64_t q = r->priv.line_depth_a - (za > zb ? za : zb);
    return d < ((int64_t)1 << 40) && q > 0 && d * 64 < q;
}

/* Planes of neighbouring pixels' triangles meet at one of the two pixel
 * centres (p, the pixel of a, and p + step, that of b): extrapolating a
 * nearly edge-on plane a pixel away misleads, so the pixel it covers is
 * where it is compared. */
static int depth_continuous(const zs_renderer *r, const zs_tri *a, const zs_tri *b, int32_t px,
                            int32_t py, int32_t sx, int32_t sy)
{
    return meet_at(r, a, b, px, py) || meet_at(r, a, b, px + sx, py + sy);
}

/* Do the visible triangles tagged a and b (a != b, both non-zero), at the
 * pixel centres (px, py) and (px + sx, py + sy) (1/16 px), meet smoothly?
 * Same draw, normals within the crease angle, and a shared pool vertex or
 * planes that meet there. Any record of each tag (a clipped triangle has
 * several) may do. */
static ZS_NOINLINE int smooth_pair(const zs_renderer *r, uint16_t a, uint16_t b, int32_t px,
                                   int32_t py, int32_t sx, int32_t sy)
{
    const zs_tri *t = r->priv.tris;
    const int16_t *nrm = r->priv.tri_normal;
    uint16_t n = r->priv.n_tris, i, j;
    for (i = first_record(r, a); i < n && t[i].color == a; i++) {
        for (j = first_record(r, b); j < n && t[j].color == b; j++) {
            const int16_t *p = &nrm[4u * i], *q = &nrm[4u * j];
            int32_t dot = p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
            if (p[3] != q[3] || dot < r->priv.crease_cos || (dot == 0 && p[0] == 0))
                continue;
            if (share_vertex(&t[i], &t[j]) ||
                depth_continuous(r, &t[i], &t[j], px, py, sx, sy))
                return 1;
        }
    }
    return 0;
}

/* Is the boundary between the pixel tagged a centred at (px, py) (1/16
 * px) and its neighbour at (px + sx, py + sy) tagged b an edge? */
static int is_edge(const zs_renderer *r, uint16_t a, uint16_t b, int32_t px, int32_t py,
                   int32_t sx, int32_t sy)
{
    if (a == b)
        return 0;
    if (a == 0 || b == 0)
        return 1;
    return !smooth_pair(r, a, b, px, py, sx, sy);
}

void zs_lines_row(zs_renderer *r, int y, uint8_t *flags)
{
    const uint16_t *cur = r->priv.line_ids[0], *above = r->priv.line_ids[1];
    int w = r->cfg.width, x, has_above = r->priv.line_prev_row;
    uint16_t *swap;
    for (x = 0; x < w; x++) {
        /* the neighbour's centre, in 1/16 px, and the step to this one */
        int e = x > 0 && is_edge(r, cur[x - 1], cur[x], 16 * x - 8, 16 * y + 8, 16, 0);
        if (!e && has_above)
            e = is_edge(r, above[x], cur[x], 16 * x + 8, 16 * y - 8, 0, 16);
        flags[x] = (uint8_t)e;
    }
    swap = r->priv.line_ids[0];
    r->priv.line_ids[0] = r->priv.line_ids[1];
    r->priv.line_ids[1] = swap;
    r->priv.line_prev_row = 1;
}
