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

#define NORMAL_VALID 1

static int any_positive(const int64_t q[3])
{
    int64_t m = q[0];
    if (q[1] > m)
        m = q[1];
    if (q[2] > m)
        m = q[2];
    return m > 0 ? 1 : 0;
}

/* Unit normal (Q14, toward the eye) of record t in n[0..2], n[3] = valid. */
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
    n[0] = n[1] = n[2] = n[3] = 0;
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
    n[3] = NORMAL_VALID;
}

void zs_lines_begin(zs_renderer *r)
{
    int64_t A, K;
    unsigned kshift = 0;
    uint16_t i;
    int deg = r->shade.crease_deg ? r->shade.crease_deg : 30;
    r->priv.crease_cos = zs_fx_cos_deg(ZS_FX(deg)) * 4096; /* Q16 -> Q28 */
    r->priv.line_prev_row = 0;
    if (r->priv.depth_scale != 0) {
        A = r->priv.depth_scale;
    } else {
        int64_t f = r->cam.far_z, nz = r->cam.near_z;
        A = (f * ((int64_t)1 << 30)) / (f - nz);
    }
    K = ((int64_t)r->cfg.height * r->priv.proj_sy) >> 13; /* 8 H cot, 1/16 px */
    if (K < 1)
        K = 1;
    while (K >= ((int64_t)1 << 16)) {
        K >>= 1;
        kshift++;
    }
    for (i = 0; i < r->priv.n_tris; i++)
        record_normal(r, &r->priv.tris[i], A, K, kshift, &r->priv.tri_normal[4u * i]);
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

/* Do the visible triangles tagged a and b (a != b, both non-zero) meet
 * smoothly? Any record of each tag (a clipped triangle has several) may do. */
static ZS_NOINLINE int smooth_pair(const zs_renderer *r, uint16_t a, uint16_t b)
{
    const zs_tri *t = r->priv.tris;
    const int16_t *nrm = r->priv.tri_normal;
    uint16_t n = r->priv.n_tris, i, j;
    for (i = first_record(r, a); i < n && t[i].color == a; i++) {
        for (j = first_record(r, b); j < n && t[j].color == b; j++) {
            const int16_t *p = &nrm[4u * i], *q = &nrm[4u * j];
            int32_t dot;
            if (p[3] != NORMAL_VALID || q[3] != NORMAL_VALID || !share_vertex(&t[i], &t[j]))
                continue;
            dot = p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
            if (dot >= r->priv.crease_cos)
                return 1;
        }
    }
    return 0;
}

typedef struct pair_cache {
    uint16_t a, b;
    uint8_t edge;
} pair_cache;

static int is_edge(const zs_renderer *r, pair_cache *c, uint16_t a, uint16_t b)
{
    if (a == b)
        return 0;
    if (a == 0 || b == 0)
        return 1;
    if ((c->a != a || c->b != b) && (c->a != b || c->b != a)) {
        c->a = a;
        c->b = b;
        c->edge = (uint8_t)!smooth_pair(r, a, b);
    }
    return c->edge;
}

void zs_lines_row(zs_renderer *r, uint8_t *flags)
{
    const uint16_t *cur = r->priv.line_ids[0], *above = r->priv.line_ids[1];
    int w = r->cfg.width, x, has_above = r->priv.line_prev_row;
    pair_cache left = {0, 0, 0}, up = {0, 0, 0};
    uint16_t *swap;
    for (x = 0; x < w; x++) {
        int e = x > 0 && is_edge(r, &left, cur[x - 1], cur[x]);
        if (!e && has_above)
            e = is_edge(r, &up, above[x], cur[x]);
        flags[x] = (uint8_t)e;
    }
    swap = r->priv.line_ids[0];
    r->priv.line_ids[0] = r->priv.line_ids[1];
    r->priv.line_ids[1] = swap;
    r->priv.line_prev_row = 1;
}
