/* SPDX-License-Identifier: MIT */
/* A-buffer resolve: anti-aliased edges and transparency on top of the span
 * walk. The walk writes every row as before; this pass then rewrites only the
 * pixels whose 4x4 sub-samples may disagree with the pixel centre: those an
 * edge crosses, those a penetration crosses, and (ZS_AA_TRANSPARENT) those a
 * transparent surface covers. Interior pixels keep the span result.
 *
 * It keeps its own set of open triangles, read from the frame's records: a
 * triangle's sub-samples reach into the pixel rows above and below the rows
 * of centres the walk draws it on, and tiny triangles that cover sub-samples
 * but no centre are stored for this pass only (zs_abuffer_store).
 *
 * Coverage is exact and uses the core's rule: a point (X, Y) (1/16 px) is
 * inside when ytop <= Y < ybot and xl(Y) <= X < xr(Y), edges stepped as
 * integers with remainders (no rounding), so shared edges neither crack nor
 * double up at sub-samples either. Points lie on the grid of even 1/16 px:
 * sub-sample (i, j) of pixel (c, y) at (16c + 2 + 4i, 16y + 2 + 4j), the
 * centre at (16c + 8, 16y + 8). Depth and colour are the planes the core
 * builds (same gradients), evaluated at the pixel centre and offset to the
 * samples. */
#include "zs_internal.h"

#define WHITE 0xFFFFFFu
#define MARK_NONE 0u
#define MARK_RESOLVE 1u
/* depth evaluation slack (Q40) when deciding where two planes may cross */
#define CROSS_SLACK ((int64_t)1 << 26)

/* An edge stepped down the even-1/16 grid rows: k = ceil(x(Y) / 2), err =
 * k * den - x(Y) * dy * 2 / 2 in [0, den). Two rows (4/16 px) per step pair. */
typedef struct zs_aa_edge {
    int32_t k, err, q, rr, den;
} zs_aa_edge;

typedef struct zs_aa_tri {
    zs_aa_edge left, right;
    int32_t ytop, ymid, ybot, ycur; /* 1/16 px; ycur: the row the edges are at */
    int64_t z0, zdx, zdy;           /* depth Q40 at the centre of (ox, oy), per pixel */
    int32_t c0[3], cdx[3], cdy[3];  /* colour Q8.16 at the same centre, per pixel */
    int16_t ox, oy;
    uint16_t rec;                   /* record index: the tie order */
    uint8_t long_left, lower;       /* the long edge is the left one; short edge is s1->s2 */
    uint8_t alpha, pad;
    int16_t sl[4], sr[4];           /* this row's sub-sample columns [sl, sr) per sub-row */
    int16_t lo, hi;                 /* pixel columns the triangle touches on this row */
    int16_t flo, fhi;               /* pixel columns it covers wholly (all 16 samples) */
    uint16_t v[3];                  /* its vertices (mesh neighbours share two) */
    int64_t zrow;                   /* this row: depth at the centre of column 0 */
    int64_t reach;                  /* how far depth strays from a centre's over the samples */
    uint16_t zlo, zhi;              /* vertex depth range, Q30 >> 15 (rounded outward) */
} zs_aa_tri;

/* A fragment: an open triangle's part of one pixel. */
typedef struct zs_aa_pix {
    const zs_aa_tri *t;
    int64_t z;         /* depth at the centre */
    int32_t c[3];      /* colour Q8.16 at the centre */
    uint16_t mask;     /* sub-sample (i, j) in bit 4j + i */
    uint16_t won;      /* the samples it shows */
} zs_aa_pix;

typedef struct zs_aa_state {
    zs_aa_tri *open;      /* open triangles, dense */
    zs_aa_pix *frags;     /* the pixel being resolved: ZS_ABUFFER_FRAGMENTS */
    uint16_t *across;     /* open slots whose columns reach the sweep's pixel */
    uint8_t *mark;        /* per column: MARK_* */
    uint16_t *bucket;     /* per row: first record whose sub-samples start there */
    uint16_t *link;       /* per record */
    uint8_t *alpha;       /* per record */
    uint32_t *runs;       /* opacity runs: first record << 8 | opacity */
    uint16_t *order;      /* open slots by first column (the crossing sweep) */
    uint16_t n_open, cap_open, n_runs;
    int16_t next_row;     /* the next row to resolve or step */
    uint8_t opacity;      /* for the draws that follow */
    uint8_t any_alpha;    /* a transparent record is open on this row */
} zs_aa_state;

typedef char zs_check_aa_tri[(sizeof(zs_aa_tri) <= ZS_ABUFFER_TRI_BYTES) ? 1 : -1];
typedef char zs_check_aa_state[(sizeof(zs_aa_state) <= ZS_ABUFFER_STATE_BYTES) ? 1 : -1];
typedef char zs_check_aa_frag[(sizeof(zs_aa_pix) <= ZS_ABUFFER_FRAGMENT_BYTES) ? 1 : -1];

/* Sub-sample offsets from the centre (1/16 px), per column i or row j. */
static int32_t sample_off(int i)
{
    return 4 * i - 6;
}

static int32_t ceil_div64(int64_t n, int32_t d) /* d > 0 */
{
    int64_t q = n / d;
    if (n - q * d > 0)
        q++;
    return (int32_t)q;
}

/* Edge a -> b (a above b) at grid row Y. */
static void edge_init(zs_aa_edge *e, const zs_vert *a, const zs_vert *b, int32_t Y)
{
    int32_t dx = b->x - a->x, dy = b->y - a->y, q;
    int64_t n = (int64_t)a->x * dy + (int64_t)(Y - a->y) * dx; /* x(Y) * dy */
    e->den = 2 * dy;
    e->k = ceil_div64(n, e->den);
    e->err = (int32_t)((int64_t)e->k * e->den - n);
    q = dx / dy;
    if (q * dy > dx)
        q--; /* floor */
    e->q = q;
    e->rr = 2 * (dx - q * dy);
}

static void edge_step(zs_aa_edge *e) /* two grid rows down (Y += 2) */
{
    e->k += e->q;
    e->err -= e->rr;
    if (e->err < 0) {
        e->err += e->den;
        e->k++;
    }
}

static void canonical(const zs_renderer *r, uint16_t rec, uint16_t idx[3])
{
    const zs_vert *p = r->priv.verts;
    const zs_tri *t = &r->priv.tris[rec];
    uint16_t tmp;
    idx[0] = t->v[0];
    idx[1] = t->v[1];
    idx[2] = t->v[2];
#define ZS_AFTER(u, v) (p[u].y > p[v].y || (p[u].y == p[v].y && p[u].x > p[v].x))
    if (ZS_AFTER(idx[0], idx[1])) { tmp = idx[0]; idx[0] = idx[1]; idx[1] = tmp; }
    if (ZS_AFTER(idx[1], idx[2])) { tmp = idx[1]; idx[1] = idx[2]; idx[2] = tmp; }
    if (ZS_AFTER(idx[0], idx[1])) { tmp = idx[0]; idx[0] = idx[1]; idx[1] = tmp; }
#undef ZS_AFTER
}

/* Colour of a record at one of its vertices (shade.c's rule). */
static uint32_t vertex_color(const zs_renderer *r, const zs_tri *t, uint16_t v)
{
    if ((t->color >> 24) == 0 || !r->priv.vshade)
        return t->color & WHITE;
    return zs_vertex_rgb(r, t, r->priv.vshade[v]);
}

/* Opens record rec at the first grid row Y of its first pixel row. */
static void open_tri(zs_renderer *r, zs_aa_state *s, uint16_t rec, int32_t Y)
{
    const zs_vert *p = r->priv.verts;
    const zs_tri *t = &r->priv.tris[rec];
    zs_aa_tri *a;
    uint16_t idx[3];
    const zs_vert *v0, *v1, *v2;
    int64_t det, dx1, dy1, dx2, dy2, offx, offy;
    zs_recip rc;
    uint32_t c[3], zmin, zmax;
    int k;
    if (s->n_open >= s->cap_open) {
        r->stats.aa_skipped++; /* capacity policy: left out of the resolve */
        return;
    }
    canonical(r, rec, idx);
    v0 = &p[idx[0]];
    v1 = &p[idx[1]];
    v2 = &p[idx[2]];
    det = zs_area2(v0, v1, v2);
    if (det == 0)
        return;
    s->order[s->n_open] = s->n_open; /* sorted into place on the row */
    a = &s->open[s->n_open++];
    a->rec = rec;
    a->v[0] = t->v[0];
    a->v[1] = t->v[1];
    a->v[2] = t->v[2];
    a->alpha = s->alpha[rec];
    a->long_left = det > 0;
    a->lower = 0;
    a->ytop = v0->y;
    a->ymid = v1->y;
    a->ybot = v2->y;
    a->ycur = Y;
    edge_init(a->long_left ? &a->left : &a->right, v0, v2, Y);
    if (v0->y == v1->y || (Y >= v1->y && v1->y < v2->y)) {
        /* flat top, or the middle vertex above this row: the lower short edge at once
         * (the upper one, extrapolated this far, could leave the int32 range) */
        edge_init(a->long_left ? &a->right : &a->left, v1, v2, Y);
        a->lower = 1;
    } else {
        edge_init(a->long_left ? &a->right : &a->left, v0, v1, Y);
    }
    zmin = v0->z < v1->z ? v0->z : v1->z;
    zmin = zmin < v2->z ? zmin : v2->z;
    zmax = v0->z > v1->z ? v0->z : v1->z;
    zmax = zmax > v2->z ? zmax : v2->z;
    a->zlo = (uint16_t)((zmin >> 15) > 0 ? (zmin >> 15) - 1u : 0u);
    a->zhi = (uint16_t)((zmax >> 15) + 2u);
    /* planes: the core's gradients (activate.c, shade.c) */
    dx1 = (int64_t)v1->x - v0->x;
    dy1 = (int64_t)v1->y - v0->y;
    dx2 = (int64_t)v2->x - v0->x;
    dy2 = (int64_t)v2->y - v0->y;
    zs_recip_init(&rc, det);
    {
        int32_t z1 = (int32_t)((int64_t)v1->z - v0->z), z2 = (int32_t)((int64_t)v2->z - v0->z);
        a->zdx = zs_recip_muldiv(&rc, zs_smul32(z1, (int32_t)dy2) - zs_smul32(z2, (int32_t)dy1),
                                 14, (int64_t)1 << 48);
        a->zdy = zs_recip_muldiv(&rc, zs_smul32(z2, (int32_t)dx1) - zs_smul32(z1, (int32_t)dx2),
                                 14, (int64_t)1 << 48);
    }
    a->ox = (int16_t)zs_asr32(v0->x, 4);
    a->oy = (int16_t)zs_asr32(v0->y, 4);
    offx = 16 * (int64_t)a->ox + 8 - v0->x;
    offy = 16 * (int64_t)a->oy + 8 - v0->y;
    a->z0 = (int64_t)v0->z * 1024 + zs_asr64(a->zdx * offx + a->zdy * offy, 4);
    if (r->shade.format == ZS_FMT_ID16) {
        for (k = 0; k < 3; k++) {
            a->c0[k] = 0;
            a->cdx[k] = a->cdy[k] = 0;
        }
        return;
    }
    for (k = 0; k < 3; k++)
        c[k] = vertex_color(r, t, idx[k]);
    for (k = 0; k < 3; k++) {
        int sh = 16 - 8 * k;
        int64_t f0 = (int64_t)((c[0] >> sh) & 255u) * 65536;
        int64_t d1 = (int64_t)((c[1] >> sh) & 255u) * 65536 - f0;
        int64_t d2 = (int64_t)((c[2] >> sh) & 255u) * 65536 - f0;
        a->cdx[k] = (int32_t)zs_recip_muldiv(&rc, d1 * dy2 - d2 * dy1, 4, (int64_t)1 << 28);
        a->cdy[k] = (int32_t)zs_recip_muldiv(&rc, d2 * dx1 - d1 * dx2, 4, (int64_t)1 << 28);
        a->c0[k] = (int32_t)(f0 + zs_asr64((int64_t)a->cdx[k] * offx + (int64_t)a->cdy[k] * offy, 4));
    }
}

/* Brings a's edges to grid row Y (>= ycur, same parity). */
static void advance(const zs_renderer *r, zs_aa_tri *a, int32_t Y)
{
    for (; a->ycur < Y; a->ycur += 2) {
        edge_step(&a->left);
        edge_step(&a->right);
    }
    if (!a->lower && Y >= a->ymid && a->ymid < a->ybot) {
        const zs_vert *p = r->priv.verts;
        uint16_t idx[3];
        canonical(r, a->rec, idx);
        edge_init(a->long_left ? &a->right : &a->left, &p[idx[1]], &p[idx[2]], Y);
        a->lower = 1;
    }
}

/* How far the depth strays from the pixel centre's over the sub-samples. */
static int64_t depth_reach(const zs_aa_tri *a)
{
    int64_t gx = a->zdx < 0 ? -a->zdx : a->zdx, gy = a->zdy < 0 ? -a->zdy : a->zdy;
    return zs_asr64(6 * (gx + gy), 4) + CROSS_SLACK;
}

static void mark_range(zs_aa_state *s, int32_t lo, int32_t hi)
{
    for (; lo < hi; lo++)
        s->mark[lo] = MARK_RESOLVE;
}

/* This row's coverage of a: sub-sample columns per sub-row, pixel columns
 * touched, and the pixels to resolve (touched but not wholly covered). */
static void row_coverage(const zs_renderer *r, zs_aa_state *s, zs_aa_tri *a, int32_t y)
{
    const int32_t w = (int32_t)r->cfg.width;
    int32_t lo = w, hi = 0, flo = 0, fhi = w, j, base = 16 * y;
    int full = 1;
    for (j = 0; j < 5; j++) {
        /* sub-rows 0, 1, the centre, sub-rows 2, 3 */
        int32_t Y = base + (j < 2 ? 2 + 4 * j : j == 2 ? 8 : 4 * j - 2);
        int32_t kl, kr;
        advance(r, a, Y);
        kl = a->left.k;
        kr = a->right.k;
        if (Y < a->ytop || Y >= a->ybot)
            kl = kr = 0;
        if (j == 2) { /* centres at k = 8c + 4 */
            int32_t cl = zs_clampi(zs_asr32(kl + 3, 3), 0, w);
            int32_t cr = zs_clampi(zs_asr32(kr + 3, 3), 0, w);
            if (cl < cr) {
                lo = cl < lo ? cl : lo;
                hi = cr > hi ? cr : hi;
            }
        } else { /* sub-samples at k = 2s + 1 */
            int jj = j < 2 ? j : j - 1;
            int32_t sl = zs_clampi(zs_asr32(kl, 1), 0, 4 * w);
            int32_t sr = zs_clampi(zs_asr32(kr, 1), 0, 4 * w);
            if (sl >= sr) {
                sl = sr = 0;
                full = 0;
            } else {
                int32_t pl = sl >> 2, pr = (sr + 3) >> 2;
                lo = pl < lo ? pl : lo;
                hi = pr > hi ? pr : hi;
                pl = (sl + 3) >> 2;
                pr = sr >> 2;
                flo = pl > flo ? pl : flo;
                fhi = pr < fhi ? pr : fhi;
            }
            a->sl[jj] = (int16_t)sl;
            a->sr[jj] = (int16_t)sr;
        }
    }
    a->lo = (int16_t)lo;
    a->hi = (int16_t)hi;
    if (!full || flo >= fhi)
        flo = fhi = 0;
    a->flo = (int16_t)flo;
    a->fhi = (int16_t)fhi;
    if (lo >= hi)
        return;
    a->zrow = a->z0 + zs_mul64_small(a->zdy, y - a->oy) - zs_mul64_small(a->zdx, a->ox);
    a->reach = depth_reach(a);
    if (!full || flo >= fhi || a->alpha != 255) {
        mark_range(s, lo, hi);
    } else {
        mark_range(s, lo, flo);
        mark_range(s, fhi, hi);
    }
}

/* Depth difference of a and b at the centre of column c of row y. */
static int64_t depth_at(const zs_aa_tri *a, int32_t c)
{
    return a->zrow + zs_mul64_small(a->zdx, c);
}

/* Two front faces of a mesh that share an edge lie on its two sides: they
 * meet only on it, and its pixels are marked already. */
static int share_edge(const zs_aa_tri *a, const zs_aa_tri *b)
{
    int n = 0, i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            n += a->v[i] == b->v[j];
    return n >= 2;
}

/* Marks the pixels of row y where the planes of a and b may cross, within
 * the columns both touch: where |difference at the centre| is within half
 * the pixel's extent of the difference plane (plus evaluation slack). */
static void mark_crossing(zs_aa_state *s, const zs_aa_tri *a, const zs_aa_tri *b, int32_t y)
{
    int32_t lo = a->lo > b->lo ? a->lo : b->lo, hi = a->hi < b->hi ? a->hi : b->hi;
    int64_t d0, d1, gx, gy, h, t0, t1;
    if (lo >= hi || a->zhi <= b->zlo || b->zhi <= a->zlo || share_edge(a, b))
        return;
    gx = a->zdx - b->zdx;
    gy = a->zdy - b->zdy;
    h = ((gx < 0 ? -gx : gx) >> 1) + ((gy < 0 ? -gy : gy) >> 1) + CROSS_SLACK;
    d0 = depth_at(a, lo) - depth_at(b, lo);
    (void)y;
    d1 = d0 + gx * (hi - 1 - lo);
    if ((d0 > h && d1 > h) || (d0 < -h && d1 < -h))
        return; /* one sign all along */
    if (gx == 0) {
        mark_range(s, lo, hi);
        return;
    }
    /* columns c with |d0 + gx (c - lo)| <= h */
    t0 = (-h - d0) / gx;
    t1 = (h - d0) / gx;
    if (t0 > t1) {
        int64_t t = t0;
        t0 = t1;
        t1 = t;
    }
    t0 -= 1;
    t1 += 1; /* the divisions truncate: widen by one */
    if (t0 < 0)
        t0 = 0;
    if (t1 > hi - 1 - lo)
        t1 = hi - 1 - lo;
    if (t0 <= t1)
        mark_range(s, lo + (int32_t)t0, lo + (int32_t)t1 + 1);
}

/* Pairs whose touched columns overlap, by a sweep over the open triangles
 * sorted by first column (insertion: the order changes little from row to row). */
static void mark_crossings(zs_aa_state *s, int32_t y)
{
    uint16_t *o = s->order;
    int n = s->n_open, i, j;
    for (i = 1; i < n; i++) { /* last row's order: little moves */
        uint16_t v = o[i];
        int16_t key = s->open[v].lo;
        for (j = i; j > 0 && s->open[o[j - 1]].lo > key; j--)
            o[j] = o[j - 1];
        o[j] = v;
    }
    for (i = 0; i < n; i++) {
        const zs_aa_tri *a = &s->open[o[i]];
        if (a->lo >= a->hi || a->alpha != 255)
            continue;
        for (j = i + 1; j < n; j++) {
            const zs_aa_tri *b = &s->open[o[j]];
            if (b->lo >= a->hi)
                break;
            if (b->lo < b->hi && b->alpha == 255)
                mark_crossing(s, a, b, y);
        }
    }
}

/* a's coverage mask of pixel c (this row). */
static uint16_t pixel_mask(const zs_aa_tri *a, int32_t c)
{
    uint32_t m = 0;
    int32_t x0 = 4 * c, x1 = x0 + 4;
    int j;
    for (j = 0; j < 4; j++) {
        int32_t l = a->sl[j] > x0 ? a->sl[j] : x0, h = a->sr[j] < x1 ? a->sr[j] : x1;
        if (l < h)
            m |= (((1u << (h - x0)) - 1u) & ~((1u << (l - x0)) - 1u)) << (4 * j);
    }
    return (uint16_t)m;
}

static int nearer_at(const zs_aa_pix *a, int64_t za, const zs_aa_pix *b, int64_t zb)
{
    return za < zb || (za == zb && a->t->rec < b->t->rec);
}

static int64_t sample_depth(const zs_aa_pix *f, int i, int j)
{
    return f->z + zs_asr64(zs_mul64_small(f->t->zdx, sample_off(i)) +
                               zs_mul64_small(f->t->zdy, sample_off(j)), 4);
}

static int32_t sample_channel(const zs_aa_pix *f, int k, int i, int j)
{
    return f->c[k] + (int32_t)zs_asr64((int64_t)f->t->cdx[k] * sample_off(i) +
                                           (int64_t)f->t->cdy[k] * sample_off(j), 4);
}

/* Per 4-bit sub-row mask: samples set, sum of their column offsets. */
static const uint8_t nibble_count[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
static const int8_t nibble_sx[16] = {0, -6, -2, -8, 2, -4, 0, -6, 6, 0, 4, -2, 8, 2, 6, 0};

/* Drops the fragments wholly behind depth zfull (an opaque full cover). */
static int drop_hidden(zs_aa_pix *px, int n, int64_t zfull)
{
    int i, k = 0;
    for (i = 0; i < n; i++)
        if (px[i].z - px[i].t->reach <= zfull)
            px[k++] = px[i];
    return k;
}

static uint32_t popcount16(uint32_t m)
{
    m = m - ((m >> 1) & 0x5555u);
    m = (m & 0x3333u) + ((m >> 2) & 0x3333u);
    m = (m + (m >> 4)) & 0x0F0Fu;
    return (m + (m >> 8)) & 0x1Fu;
}

static uint32_t to_channel(int64_t mean_q16)
{
    int64_t v = (mean_q16 + 32768) >> 16;
    return v < 0 ? 0u : v > 255 ? 255u : (uint32_t)v;
}

/* Blends the transparent fragments covering sample (i, j) in front of the
 * opaque surface there (depth zop, record op_rec) over colour col (Q8.16),
 * far to near. */
static void blend_sample(zs_aa_pix *px, int n, int i, int j, int64_t zop, uint32_t op_rec,
                         int32_t col[3])
{
    int idx[ZS_ABUFFER_FRAGMENTS], m = 0, a, b, k;
    int64_t zs[ZS_ABUFFER_FRAGMENTS];
    uint32_t bit = 1u << (4 * j + i);
    for (a = 0; a < n; a++) {
        int64_t z;
        if (px[a].t->alpha == 255 || px[a].t->alpha == 0 || !(px[a].mask & bit))
            continue;
        z = sample_depth(&px[a], i, j);
        if (z > zop || (z == zop && px[a].t->rec >= op_rec))
            continue; /* behind the opaque surface (an exact tie: the later record is) */
        /* sorted far to near; equal depths: the later record first (the
         * earlier one ends on top, as it would win the tie) */
        for (b = m; b > 0 && (zs[b - 1] < z || (zs[b - 1] == z && px[idx[b - 1]].t->rec < px[a].t->rec)); b--) {
            zs[b] = zs[b - 1];
            idx[b] = idx[b - 1];
        }
        zs[b] = z;
        idx[b] = a;
        m++;
    }
    for (b = 0; b < m; b++) {
        const zs_aa_pix *f = &px[idx[b]];
        int32_t al = f->t->alpha;
        for (k = 0; k < 3; k++) {
            int32_t t = sample_channel(f, k, i, j);
            col[k] += (int32_t)(((int64_t)(t - col[k]) * al) / 255);
        }
    }
}

/* Resolves pixel c of row y into the row from the open triangles in
 * across[0..na). An opaque triangle covering the whole pixel hides what lies
 * wholly behind its farthest point there: such fragments are not taken. */
static void resolve_pixel(zs_renderer *r, zs_aa_state *s, const uint16_t *across, int na,
                          int32_t c, int32_t y, uint8_t *row)
{
    zs_aa_pix *px = s->frags;
    int n = 0, i, j, k, conflict = 0, transparent = 0;
    uint16_t covered = 0;
    int64_t acc[3], zfull = INT64_MAX;
    uint32_t bg = r->shade.background, rgb;
    for (i = 0; i < na; i++) {
        const zs_aa_tri *t = &s->open[across[i]];
        uint16_t m;
        int64_t z;
        if (t->alpha == 0)
            continue;
        z = depth_at(t, c);
        if (t->alpha == 255 && c >= t->flo && c < t->fhi && z + t->reach < zfull)
            zfull = z + t->reach;
        if (z - t->reach > zfull)
            continue; /* wholly behind an opaque fragment */
        m = pixel_mask(t, c);
        if (!m)
            continue;
        if (n >= (int)ZS_ABUFFER_FRAGMENTS)
            n = drop_hidden(px, n, zfull);
        if (n >= (int)ZS_ABUFFER_FRAGMENTS) {
            r->stats.aa_overflow++;
            return; /* capacity policy: more surfaces than the pool, the pixel stays aliased */
        }
        px[n].t = t;
        px[n].z = z;
        px[n].mask = m;
        px[n].won = 0;
        n++;
    }
    n = drop_hidden(px, n, zfull);
    for (i = 1; i < n; i++) { /* by centre depth */
        zs_aa_pix p = px[i];
        for (j = i; j > 0 && nearer_at(&p, p.z, &px[j - 1], px[j - 1].z); j--)
            px[j] = px[j - 1];
        px[j] = p;
    }
    for (i = 0; i < n; i++) {
        const zs_aa_tri *t = px[i].t;
        if (t->alpha != 255)
            transparent = 1;
        for (k = 0; k < 3; k++) {
            int64_t v = (int64_t)t->c0[k] + (int64_t)t->cdx[k] * (c - t->ox) +
                        (int64_t)t->cdy[k] * (y - t->oy);
            px[i].c[k] = (int32_t)(v > ((int64_t)1 << 30) ? ((int64_t)1 << 30)
                                   : v < -((int64_t)1 << 30) ? -((int64_t)1 << 30) : v);
        }
    }
    if ((uint32_t)n > r->stats.aa_max_fragments)
        r->stats.aa_max_fragments = (uint32_t)n;
    r->stats.aa_pixels++;
    r->stats.aa_fragments += (uint32_t)n;
    /* do two fragments that share samples have overlapping depth ranges? */
    for (i = 0; i < n && !conflict; i++) {
        int64_t hi = px[i].z + px[i].t->reach;
        if (px[i].t->alpha != 255)
            continue;
        for (j = i + 1; j < n; j++) {
            int64_t lo = px[j].z - px[j].t->reach;
            if (px[j].t->alpha == 255 && (px[i].mask & px[j].mask) && lo <= hi) {
                conflict = 1;
                break;
            }
        }
    }
    acc[0] = acc[1] = acc[2] = 0;
    if (!conflict && !transparent) {
        /* front to back: each takes the samples nobody nearer has */
        for (i = 0; i < n; i++) {
            px[i].won = (uint16_t)(px[i].mask & ~covered);
            covered |= px[i].mask;
        }
    } else {
        for (j = 0; j < 4; j++)
            for (i = 0; i < 4; i++) {
                uint16_t bit = (uint16_t)(1u << (4 * j + i));
                int best = -1;
                int64_t zb = 0;
                for (k = 0; k < n; k++) {
                    int64_t z;
                    if (!(px[k].mask & bit) || px[k].t->alpha != 255)
                        continue;
                    z = sample_depth(&px[k], i, j);
                    if (best < 0 || nearer_at(&px[k], z, &px[best], zb)) {
                        best = k;
                        zb = z;
                    }
                }
                if (best >= 0) {
                    px[best].won |= bit;
                    covered |= bit;
                }
                if (transparent) {
                    int32_t col[3];
                    for (k = 0; k < 3; k++)
                        col[k] = best >= 0 ? sample_channel(&px[best], k, i, j)
                                           : (int32_t)(((bg >> (16 - 8 * k)) & 255u) << 16);
                    blend_sample(px, n, i, j, best >= 0 ? zb : INT64_MAX,
                                 best >= 0 ? px[best].t->rec : 0x10000u, col);
                    for (k = 0; k < 3; k++)
                        acc[k] += 16 * (int64_t)col[k];
                }
            }
    }
    if (r->shade.format == ZS_FMT_ID16) {
        /* the tag covering most sub-samples (the background's is 0) */
        uint16_t tag = 0;
        uint32_t most = 16u - popcount16(covered);
        union {
            uint16_t h;
            uint8_t b[2];
        } u;
        for (i = 0; i < n; i++) {
            uint32_t cnt = popcount16(px[i].won);
            if (cnt > most) {
                most = cnt;
                tag = (uint16_t)r->priv.tris[px[i].t->rec].color;
            }
        }
        u.h = tag;
        row[2 * c] = u.b[0];
        row[2 * c + 1] = u.b[1];
        return;
    }
    if (!transparent) {
        uint32_t nbg = 16u - popcount16(covered);
        for (k = 0; k < 3; k++)
            acc[k] = (int64_t)nbg * 16 * (int64_t)(((bg >> (16 - 8 * k)) & 255u) << 16);
        for (i = 0; i < n; i++) {
            uint32_t m = px[i].won, cnt = 0;
            int64_t sx = 0, sy = 0;
            if (!m)
                continue;
            for (j = 0; j < 4; j++) { /* per sub-row: count and column offsets */
                uint32_t q = (m >> (4 * j)) & 15u;
                cnt += nibble_count[q];
                sx += nibble_sx[q];
                sy += (int64_t)nibble_count[q] * sample_off(j);
            }
            for (k = 0; k < 3; k++)
                acc[k] += 16 * (int64_t)cnt * px[i].c[k] + (int64_t)px[i].t->cdx[k] * sx +
                          (int64_t)px[i].t->cdy[k] * sy;
        }
    }
    /* acc = 256 * the mean colour (Q8.16) */
    rgb = (to_channel(zs_asr64(acc[0], 8)) << 16) | (to_channel(zs_asr64(acc[1], 8)) << 8) |
          to_channel(zs_asr64(acc[2], 8));
    {
        uint8_t out[4];
        unsigned b, bpp = r->priv.bpp;
        zs_pack_pixel(r->shade.format, rgb, out);
        for (b = 0; b < bpp; b++)
            row[(size_t)c * bpp + b] = out[b];
    }
}

/* Sweeps the row's marked pixels left to right, keeping the open triangles
 * whose columns reach the current one (order: by first column). */
static void resolve_row(zs_renderer *r, zs_aa_state *s, int32_t y, uint8_t *row)
{
    const int32_t w = (int32_t)r->cfg.width;
    const uint16_t *o = s->order;
    uint16_t *across = s->across;
    int n = s->n_open, next = 0, na = 0, i, k;
    int32_t c;
    for (c = 0; c < w; c++) {
        if (s->mark[c] != MARK_RESOLVE)
            continue;
        for (; next < n && s->open[o[next]].lo <= c; next++)
            if (s->open[o[next]].hi > s->open[o[next]].lo)
                across[na++] = o[next];
        for (i = k = 0; i < na; i++)
            if (s->open[across[i]].hi > c)
                across[k++] = across[i];
        na = k;
        resolve_pixel(r, s, across, na, c, y, row);
    }
}

void zs_abuffer_begin(zs_renderer *r)
{
    zs_aa_state *s = r->priv.aa;
    const zs_vert *p = r->priv.verts;
    int32_t h = (int32_t)r->cfg.height;
    uint16_t i, run = 0;
    memset(s->bucket, 0xFF, (size_t)h * 2u);
    /* opacities from the runs */
    for (i = 0; i < r->priv.n_tris; i++) {
        while (run < s->n_runs && (s->runs[run] >> 8) <= i)
            run++;
        s->alpha[i] = run > 0 ? (uint8_t)(s->runs[run - 1] & 255u) : 255u;
    }
    /* buckets by the pixel row of the top vertex, in record order */
    for (i = r->priv.n_tris; i-- > 0;) {
        const zs_tri *t = &r->priv.tris[i];
        int32_t ymin = p[t->v[0]].y, row;
        if (p[t->v[1]].y < ymin)
            ymin = p[t->v[1]].y;
        if (p[t->v[2]].y < ymin)
            ymin = p[t->v[2]].y;
        row = ymin < 0 ? 0 : zs_asr32(ymin, 4);
        if (row >= h)
            continue;
        s->link[i] = s->bucket[row];
        s->bucket[row] = i;
    }
    /* transparent records leave the span walk: the resolve draws them */
    if (r->priv.aa_mode == ZS_AA_TRANSPARENT) {
        int32_t y;
        for (y = 0; y < h; y++) {
            uint16_t *at = &r->priv.buckets[y];
            while (*at != ZS_NONE) {
                if (s->alpha[*at] != 255)
                    *at = r->priv.tris[*at].next;
                else
                    at = &r->priv.tris[*at].next;
            }
        }
    }
    s->n_open = 0;
    s->next_row = 0;
}

static void one_row(zs_renderer *r, int y, uint8_t *row)
{
    zs_aa_state *s = r->priv.aa;
    const int32_t w = (int32_t)r->cfg.width;
    uint16_t ti, i;
    int32_t next_y = 16 * (y + 1) + 2;
    for (ti = s->bucket[y]; ti != ZS_NONE; ti = s->link[ti])
        open_tri(r, s, ti, 16 * y + 2);
    if (row) {
        memset(s->mark, MARK_NONE, (size_t)w);
        for (i = 0; i < s->n_open; i++)
            row_coverage(r, s, &s->open[i], y);
        mark_crossings(s, y);
        resolve_row(r, s, y, row);
    }
    /* retire what reaches no grid row of the next pixel row */
    for (i = 0; i < s->n_open;) {
        zs_aa_tri *a = &s->open[i];
        if (a->ybot <= next_y) {
            uint16_t last = --s->n_open, k, w = 0;
            *a = s->open[last];
            for (k = 0; k <= last; k++) { /* the sweep order: i gone, last now at i */
                uint16_t v = s->order[k];
                if (v != i)
                    s->order[w++] = v == last ? i : v;
            }
        } else {
            if (!row)
                advance(r, a, 16 * y + 14);
            i++;
        }
    }
}

void zs_abuffer_row(zs_renderer *r, int y, uint8_t *row)
{
    zs_aa_state *s = r->priv.aa;
    for (; s->next_row < y; s->next_row++)
        one_row(r, s->next_row, 0); /* rows the caller skipped */
    one_row(r, y, row);
    s->next_row = (int16_t)(y + 1);
}

void zs_abuffer_rows(zs_renderer *r, int y0, int rows, uint8_t *buf, size_t stride)
{
    int k;
    for (k = 0; k < rows; k++)
        zs_abuffer_row(r, y0 + k, buf + (size_t)k * stride);
}

/* Keeps a triangle that covers no pixel centre for the resolve alone: a
 * record outside every bucket of the span walk. */
int zs_abuffer_store(zs_renderer *r, uint16_t i0, uint16_t i1, uint16_t i2, uint32_t color,
                     uint16_t tag)
{
    const zs_vert *p = r->priv.verts;
    zs_tri *t;
    int32_t ymin = p[i0].y, ymax = p[i0].y, xmin = p[i0].x, xmax = p[i0].x;
    int k;
    const uint16_t v[3] = {i0, i1, i2};
    for (k = 1; k < 3; k++) {
        ymin = p[v[k]].y < ymin ? p[v[k]].y : ymin;
        ymax = p[v[k]].y > ymax ? p[v[k]].y : ymax;
        xmin = p[v[k]].x < xmin ? p[v[k]].x : xmin;
        xmax = p[v[k]].x > xmax ? p[v[k]].x : xmax;
    }
    /* any sub-sample row (Y = 2 mod 4) and column (X = 2 mod 4) in the box? */
    if (ymin + (int32_t)((uint32_t)(2 - ymin) & 3u) > ymax ||
        xmin + (int32_t)((uint32_t)(2 - xmin) & 3u) > xmax)
        return ZS_SETUP_EMPTY;
    if (r->priv.n_tris >= r->cfg.max_triangles) {
        r->stats.records_dropped++;
        return ZS_SETUP_DROPPED;
    }
    t = &r->priv.tris[r->priv.n_tris];
    t->v[0] = i0;
    t->v[1] = i1;
    t->v[2] = i2;
    t->color = r->shade.format == ZS_FMT_ID16 ? tag : color;
    t->next = ZS_NONE;
    r->priv.n_tris++;
    r->stats.records++;
    if (r->priv.setup_hook) {
        int32_t xy[6];
        uint32_t z[3];
        for (k = 0; k < 3; k++) {
            xy[2 * k] = p[v[k]].x;
            xy[2 * k + 1] = p[v[k]].y;
            z[k] = p[v[k]].z;
        }
        r->priv.setup_hook(r->priv.setup_hook_user, tag, xy, z);
    }
    return ZS_SETUP_STORED;
}

void *zs_abuffer_carve(zs_renderer *r, uint8_t **cursor)
{
    uint8_t *cur = *cursor;
    const zs_config *cfg = &r->cfg;
    size_t w = cfg->width, cap = ZS_ABUFFER_TRIS(cfg->max_active_edges);
    zs_aa_state *s;
    /* the state itself lives in the frame's (idle) spare: carve first */
    s = (zs_aa_state *)(void *)cur;
    cur += ZS_ROUND8_(ZS_ABUFFER_STATE_BYTES);
    s->frags = (zs_aa_pix *)(void *)cur;
    cur += ZS_ROUND8_(ZS_ABUFFER_FRAGMENTS * ZS_ABUFFER_FRAGMENT_BYTES);
    s->mark = cur;
    cur += ZS_ROUND8_(w);
    s->bucket = (uint16_t *)(void *)cur;
    cur += ZS_ROUND8_((size_t)cfg->height * 2u + 2u);
    s->link = (uint16_t *)(void *)cur;
    s->alpha = cur + (size_t)cfg->max_triangles * 2u;
    cur += ZS_ROUND8_((size_t)cfg->max_triangles * 3u);
    s->open = (zs_aa_tri *)(void *)cur;
    cur += ZS_ROUND8_(cap * ZS_ABUFFER_TRI_BYTES);
    s->order = (uint16_t *)(void *)cur;
    cur += ZS_ROUND8_(cap * 2u);
    s->across = (uint16_t *)(void *)cur;
    cur += ZS_ROUND8_(cap * 2u);
    s->runs = (uint32_t *)(void *)cur;
    cur += ZS_ROUND8_(ZS_ABUFFER_OPACITY_RUNS * 4u);
    *cursor = cur;
    s->cap_open = (uint16_t)cap;
    s->n_open = s->n_runs = 0;
    s->opacity = 255;
    return s;
}

void zs_abuffer_frame(zs_renderer *r)
{
    zs_aa_state *s = r->priv.aa;
    r->priv.aa_mode = ZS_AA_OFF;
    if (s) {
        s->n_runs = 0;
        s->opacity = 255;
    }
}

zs_status zs_frame_antialias(zs_renderer *r, zs_aa_mode mode)
{
    if (!r)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN || r->priv.tag_counter != 0)
        return ZS_ERR_STATE;
    if ((unsigned)mode > (unsigned)ZS_AA_TRANSPARENT)
        return ZS_ERR_ARGUMENT;
    if (mode != ZS_AA_OFF && (!r->priv.aa || r->priv.mode != ZS_MODE_SPAN ||
                              (zs_format_is_mono((zs_format)r->priv.out_format) &&
                               (r->shade.mono & ZS_MONO_LINES))))
        return ZS_ERR_MODE; /* the z-buffer mode and line drawings: aliased only */
    r->priv.aa_mode = (uint8_t)mode;
    return ZS_OK;
}

zs_status zs_draw_opacity(zs_renderer *r, uint8_t opacity)
{
    zs_aa_state *s;
    if (!r)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    if (r->priv.aa_mode != ZS_AA_TRANSPARENT)
        return ZS_ERR_MODE;
    s = r->priv.aa;
    if (opacity == s->opacity)
        return ZS_OK;
    if (s->n_runs > 0 && (s->runs[s->n_runs - 1] >> 8) == r->priv.n_tris) {
        s->n_runs--; /* nothing drawn since the last change: replace it */
    } else if (s->n_runs >= ZS_ABUFFER_OPACITY_RUNS) {
        return ZS_ERR_CAPACITY;
    }
    s->runs[s->n_runs++] = ((uint32_t)r->priv.n_tris << 8) | opacity;
    s->opacity = opacity;
    return ZS_OK;
}
