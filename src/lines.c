/* SPDX-License-Identifier: MIT */
/* Hidden-line drawing from the visibility the span walk computes: each row
 * is rendered as triangle ids, and where two neighbouring pixels (left and
 * right, above and below) differ, the stage asks whether a feature edge
 * lies between their centres: a silhouette (against the background or a
 * farther surface), a crease (dihedral angle above the crease angle), a
 * mesh boundary or a boundary between draw calls. Only what is visible has
 * ids, so hidden edges are never drawn.
 *
 * The question is answered by walking the mesh along the segment between
 * the two centres: from the first pixel's triangle across the edge it
 * leaves by to the triangle on the other side (records of a hidden-line
 * frame include the triangles too small to hold a pixel centre, kept out
 * of the rendering, and the records around each vertex are listed), until
 * the second pixel's triangle is reached. Every edge crossed is checked:
 * its dihedral angle, from exact eye-space normals of the mesh's own
 * positions. A crossed edge without a neighbour (a silhouette, whose
 * neighbour faces away, or a boundary) ends the walk; then the two sides
 * are one surface only where their planes meet there (meshes whose faces
 * do not share vertices). The line goes on the pixel whose centre is nearer
 * the boundary, one pixel wide. Rows are rendered one ahead of the output
 * so that the pixel above a boundary can get it. */
#include "zs_mono.h"


/* Records of a hidden-line frame are at most 65534, so 0xFFFF is none. */
#define NO_RECORD 0xFFFFu

void zs_lines_draw(zs_renderer *r, const zs_mesh *m, const int32_t mv[3][3], uint16_t first,
                   uint32_t tag_base)
{
    int64_t mm[3][3], cof[3][3], big = 0;
    const zs_tri *tri = r->priv.tris;
    uint16_t i;
    int k, j;
    /* (M a) x (M b) = cof(M) (a x b): the cofactor matrix turns model-space
     * normals into eye-space ones, for any scaling; entries kept small so
     * every product below fits 63 bits */
    for (k = 0; k < 3; k++)
        for (j = 0; j < 3; j++) {
            mm[k][j] = mv[k][j];
            if ((mm[k][j] < 0 ? -mm[k][j] : mm[k][j]) > big)
                big = mm[k][j] < 0 ? -mm[k][j] : mm[k][j];
        }
    for (; big >= ((int64_t)1 << 28); big >>= 1)
        for (k = 0; k < 3; k++)
            for (j = 0; j < 3; j++)
                mm[k][j] = zs_asr64(mm[k][j], 1);
    big = 0;
    for (k = 0; k < 3; k++)
        for (j = 0; j < 3; j++) {
            int k1 = (k + 1) % 3, k2 = (k + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[k][j] = mm[k1][j1] * mm[k2][j2] - mm[k1][j2] * mm[k2][j1];
            if ((cof[k][j] < 0 ? -cof[k][j] : cof[k][j]) > big)
                big = cof[k][j] < 0 ? -cof[k][j] : cof[k][j];
        }
    for (; big >= ((int64_t)1 << 24); big >>= 1)
        for (k = 0; k < 3; k++)
            for (j = 0; j < 3; j++)
                cof[k][j] = zs_asr64(cof[k][j], 1);
    for (i = first; i < r->priv.n_tris; i++) {
        int16_t *n = &r->priv.tri_normal[4u * i];
        /* the mesh triangle from the record's tag (ID16: the colour word) */
        uint32_t tag = tri[i].color - 1u;
        uint32_t t = tag >= tag_base ? tag - tag_base : tag + 65535u - tag_base;
        const int16_t *p0, *p1, *p2;
        int32_t e1[3], e2[3];
        int64_t nm[3], v[3];
        int32_t u[3];
        n[0] = n[1] = n[2] = 0;
        if (t >= m->triangle_count)
            continue;
        p0 = m->positions + 3u * m->indices[3u * t];
        p1 = m->positions + 3u * m->indices[3u * t + 1u];
        p2 = m->positions + 3u * m->indices[3u * t + 2u];
        for (k = 0; k < 3; k++) {
            e1[k] = p1[k] - p0[k];
            e2[k] = p2[k] - p0[k];
        }
        zs_cross3(e1, e2, nm);
        zs_shrink3(nm, (int64_t)1 << 24);
        for (k = 0; k < 3; k++)
            v[k] = cof[k][0] * nm[0] + cof[k][1] * nm[1] + cof[k][2] * nm[2];
        if (!zs_normalize3(v, u))
            continue;
        for (k = 0; k < 3; k++)
            n[k] = (int16_t)zs_asr32(u[k], 2);
    }
}

void zs_lines_begin(zs_renderer *r)
{
    int64_t A;
    uint16_t i, draw = 0, *head = r->priv.line_vert_head, *next = r->priv.line_next_rec;
    int deg = r->shade.crease_deg ? r->shade.crease_deg : 30, k;
    r->priv.crease_cos = zs_fx_cos_deg(ZS_FX(deg)) * 4096; /* Q16 -> Q28 */
    r->priv.line_next = 0;
    if (r->priv.depth_scale != 0) {
        A = r->priv.depth_scale;
    } else {
        int64_t f = r->cam.far_z, nz = r->cam.near_z;
        A = (f * ((int64_t)1 << 30)) / (f - nz);
    }
    r->priv.line_depth_a = A;
    for (i = 0; i < r->priv.n_verts; i++)
        head[i] = NO_RECORD;
    for (i = 0; i < r->priv.n_tris; i++) {
        const zs_tri *t = &r->priv.tris[i];
        if (r->priv.draw_starts[i >> 3] & (1u << (i & 7u)))
            draw++;
        r->priv.tri_normal[4u * i + 3u] = (int16_t)(draw & 0x7FFFu); /* draw number (wrapping) */
        for (k = 0; k < 3; k++) {
            next[3u * i + (unsigned)k] = head[t->v[k]];
            head[t->v[k]] = i;
        }
    }
}

/* The record across edge k (v[k] -> v[k + 1]) of record i: the one that
 * runs the edge the other way (a consistently wound mesh); NO_RECORD if
 * none (a silhouette, whose neighbour faced away, a boundary, or a mesh
 * whose faces do not share vertices). */
static uint16_t neighbour(const zs_renderer *r, uint16_t i, int k)
{
    const zs_tri *t = r->priv.tris;
    uint16_t u = t[i].v[k], w = t[i].v[k == 2 ? 0 : k + 1], j = r->priv.line_vert_head[w];
    while (j != NO_RECORD) {
        int c = t[j].v[0] == w ? 0 : t[j].v[1] == w ? 1 : 2;
        if (j != i && t[j].v[c == 2 ? 0 : c + 1] == u)
            return j;
        j = r->priv.line_next_rec[3u * j + (unsigned)c];
    }
    return NO_RECORD;
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

/* Positions along the step from one pixel centre to its neighbour's, in
 * 1/4096 of the step. */
#define STEP_ONE 4096

/* The pair of pixel centres a decision is about: c0 = (px, py) and
 * c1 = c0 + (sx, sy), in 1/16 px, one pixel apart. */
typedef struct step_pair {
    int32_t px, py, sx, sy;
} step_pair;

/* n / d in 1/4096 (0 <= n <= d, d > 0), in 32-bit division. */
static int32_t fraction(uint64_t n, uint64_t d)
{
    while (d >= ((uint64_t)1 << 19)) {
        n >>= 1;
        d >>= 1;
    }
    return d ? (int32_t)(((uint32_t)n << 12) / (uint32_t)d) : 0;
}

/* The part [lo, hi] (1/4096 of the step) of the segment c0 -> c1 that
 * record t covers; 0 if none. An edge function is linear along the step, so
 * each edge cuts the segment once at most. */
static int cover_span(const zs_renderer *r, const zs_tri *t, const step_pair *s, int32_t *lo,
                      int32_t *hi, int *klo, int *khi)
{
    const zs_vert *pool = r->priv.verts;
    int64_t area = zs_area2_inline(&pool[t->v[0]], &pool[t->v[1]], &pool[t->v[2]]);
    int32_t l = 0, h = STEP_ONE;
    int k, el = -1, eh = -1;
    if (area == 0)
        return 0;
    for (k = 0; k < 3; k++) {
        const zs_vert *a = &pool[t->v[k]], *b = &pool[t->v[k == 2 ? 0 : k + 1]];
        int64_t ex = (int64_t)b->x - a->x, ey = (int64_t)b->y - a->y;
        /* the edge function, positive inside, at c0 and its change to c1 */
        int64_t e0 = ex * ((int64_t)s->py - a->y) - ey * ((int64_t)s->px - a->x);
        int64_t de = ex * s->sy - ey * s->sx, e1;
        if (area < 0) {
            e0 = -e0;
            de = -de;
        }
        e1 = e0 + de;
        /* inside where >= 0 (closed: a centre on an edge is where the
         * segment crosses it, whichever side the fill rule gives it to) */
        if (e0 < 0 && e1 < 0)
            return 0;
        if (e0 >= 0 && e1 >= 0) {
            if (e1 == 0 && e0 > 0 && h == STEP_ONE) { /* leaves at c1 */
                eh = k;
            } else if (e0 == 0 && e1 > 0 && l == 0) { /* enters at c0 */
                el = k;
            }
            continue;
        }
        if (e0 >= 0) { /* e1 < 0: leaves at e0 / (e0 - e1) */
            int32_t c = fraction((uint64_t)e0, (uint64_t)(e0 - e1));
            if (c <= h) {
                h = c;
                eh = k;
            }
        } else { /* e1 >= 0: enters there */
            int32_t c = fraction((uint64_t)-e0, (uint64_t)(e1 - e0));
            if (c >= l) {
                l = c;
                el = k;
            }
        }
    }
    if (l > h)
        return 0;
    *lo = l;
    *hi = h;
    *klo = el;
    *khi = eh;
    return 1;
}

/* The part of the segment that the records tagged tag cover together (a
 * clipped triangle has several records, one convex polygon in all), and
 * the edges it begins and ends at: edge k of a record runs from v[k] to
 * v[k + 1]; -1 where the cover reaches an end of the segment. */
typedef struct cover {
    int32_t lo, hi;
    uint16_t rec_lo, rec_hi;
    int edge_lo, edge_hi;
} cover;

static int tag_cover(const zs_renderer *r, uint16_t first, uint16_t tag, const step_pair *s,
                     cover *c)
{
    const zs_tri *t = r->priv.tris;
    uint16_t n = r->priv.n_tris, i;
    int32_t a, b;
    int any = 0, ka, kb;
    c->lo = STEP_ONE + 1; /* below any cover's end */
    c->hi = -1;
    c->rec_lo = c->rec_hi = first;
    c->edge_lo = c->edge_hi = -1;
    for (i = first; i < n && t[i].color == tag; i++)
        if (cover_span(r, &t[i], s, &a, &b, &ka, &kb)) {
            any = 1;
            if (a < c->lo) {
                c->lo = a;
                c->rec_lo = i;
                c->edge_lo = ka;
            }
            if (b > c->hi) {
                c->hi = b;
                c->rec_hi = i;
                c->edge_hi = kb;
            }
        }
    return any;
}

/* Depth of record t's plane at m (1/4096 of the step): window depth is
 * affine on the screen, so the two centres' depths interpolate it. */
static int64_t depth_at(const zs_renderer *r, const zs_tri *t, const step_pair *s, int32_t m)
{
    int64_t z0 = plane_depth(r, t, s->px, s->py);
    int64_t z1 = plane_depth(r, t, s->px + s->sx, s->py + s->sy);
    return z0 + zs_asr64((z1 - z0) * m, 12);
}

/* Do records a and b meet at m? Their depths agree to 1/64 of A - z
 * (proportional to 1/w: about 1.5% of the eye distance). */
static int meet_at(const zs_renderer *r, const zs_tri *a, const zs_tri *b, const step_pair *s,
                   int32_t m)
{
    int64_t za = depth_at(r, a, s, m), zb = depth_at(r, b, s, m);
    int64_t d = za > zb ? za - zb : zb - za;
    int64_t q = r->priv.line_depth_a - (za > zb ? za : zb);
    return d < ((int64_t)1 << 40) && q > 0 && d * 64 < q;
}

static int32_t dot_q28(const int16_t *p, const int16_t *q)
{
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

/* Records i and j on one surface, smooth where they meet at m: of one
 * draw, normals within the crease angle, planes that meet there. For the
 * end of a walk that found no neighbour. */
static int meet_smoothly(const zs_renderer *r, uint16_t i, uint16_t j, const step_pair *s,
                         int32_t m)
{
    const int16_t *p = &r->priv.tri_normal[4u * i], *q = &r->priv.tri_normal[4u * j];
    return p[3] == q[3] && dot_q28(p, q) >= r->priv.crease_cos &&
           meet_at(r, &r->priv.tris[i], &r->priv.tris[j], s, m);
}

/* The walk's steps at most: a pixel's width holds a few triangles. */
#define WALK_STEPS 16

static int has_vertex(const zs_tri *t, uint16_t v)
{
    return t->v[0] == v || t->v[1] == v || t->v[2] == v;
}

/* The end of edge k of record t that lies on the segment, or -1. */
static int vertex_on(const zs_renderer *r, const zs_tri *t, int k, const step_pair *s)
{
    int e;
    for (e = 0; e < 2; e++) {
        uint16_t v = t->v[(k + e) % 3];
        const zs_vert *p = &r->priv.verts[v];
        if (s->sy == 0 ? p->y == s->py && p->x >= s->px && p->x <= s->px + s->sx
                       : p->x == s->px && p->y >= s->py && p->y <= s->py + s->sy)
            return v;
    }
    return -1;
}

/* Around vertex v (on the segment) from record i to a record tagged b,
 * one way round (dir 0: across the edge that starts at v; 1: that ends
 * there): smooth if every edge crossed is. An open fan (a silhouette or
 * boundary through v) is not. */
static int smooth_fan(const zs_renderer *r, uint16_t i, uint16_t v, uint16_t b, int dir)
{
    const zs_tri *t = r->priv.tris;
    const int16_t *nrm = r->priv.tri_normal;
    int steps;
    for (steps = 0; steps < WALK_STEPS; steps++) {
        int c = t[i].v[0] == v ? 0 : t[i].v[1] == v ? 1 : 2;
        uint16_t j = neighbour(r, i, dir ? (c + 2) % 3 : c);
        if (j == NO_RECORD || dot_q28(&nrm[4u * i], &nrm[4u * j]) < r->priv.crease_cos)
            return 0;
        if (t[j].color == b)
            return 1;
        i = j;
    }
    return 0;
}


/* Is the way from a (at c0, cover ca) to b (at c1, cover cb) smooth? The
 * walk leaves a's record by the edge its cover ends at, and crosses
 * edge after edge: no edge is drawn if it reaches a record tagged b having
 * crossed only smooth edges. A crease ends it (edge), and so does reaching
 * c1 on a record not tagged b (b hides it: b's silhouette or boundary).
 * Without a neighbour, or when the step would not advance (a vertex on the
 * segment), the last record and b are compared directly. */
static int smooth_walk(const zs_renderer *r, uint16_t b, const cover *ca, uint16_t fb,
                       const cover *cb, const step_pair *s)
{
    const zs_tri *t = r->priv.tris;
    const int16_t *nrm = r->priv.tri_normal;
    uint16_t n = r->priv.n_tris, i = ca->rec_hi, j;
    int32_t pos = ca->hi, lo, hi;
    int k = ca->edge_hi, steps, kl, kh;
    for (steps = 0; steps < WALK_STEPS; steps++) {
        if (k < 0) /* this record reaches c1, where b is in front */
            return 0;
        j = neighbour(r, i, k);
        if (j == NO_RECORD)
            break;
        if (dot_q28(&nrm[4u * i], &nrm[4u * j]) < r->priv.crease_cos)
            return 0; /* a crease */
        if (t[j].color == b)
            return 1;
        if (!cover_span(r, &t[j], s, &lo, &hi, &kl, &kh) || hi <= pos) {
            /* no way on across j: the segment meets a vertex of edge k */
            int v = vertex_on(r, &t[i], k, s);
            if (v >= 0 && has_vertex(&t[fb], (uint16_t)v))
                return smooth_fan(r, i, (uint16_t)v, b, 0) && smooth_fan(r, i, (uint16_t)v, b, 1);
            break;
        }
        i = j;
        pos = hi;
        k = kh;
    }
    for (j = fb; j < n && t[j].color == b; j++)
        if (meet_smoothly(r, i, j, s, (pos + cb->lo) / 2))
            return 1;
    return 0;
}

/* Is there an edge between the pixel centres c0 (tag a) and c1 (tag b),
 * and on which of the two pixels does it go? 0: none; 1: c0's pixel; 2:
 * c1's. The line goes on the pixel whose centre is nearer the boundary, so
 * it is never more than half a pixel off along the step (the boundary is
 * where a's cover ends or b's begins, whichever is in front). */
static int pair_edge(const zs_renderer *r, uint16_t a, uint16_t b, const step_pair *s)
{
    uint16_t fa = 0, fb = 0;
    cover ca, cb;
    int32_t ta, tb, cut;
    int walk = 0;
    if (a == b)
        return 0;
    ca.hi = 0;
    cb.lo = STEP_ONE;
    if (a) {
        fa = first_record(r, a);
        walk = tag_cover(r, fa, a, s, &ca);
        if (!walk)
            ca.hi = 0;
    }
    if (b) {
        fb = first_record(r, b);
        if (!tag_cover(r, fb, b, s, &cb))
            cb.lo = STEP_ONE;
    }
    ta = ca.hi; /* where a's cover ends */
    tb = cb.lo; /* where b's begins */
    if (walk && b && smooth_walk(r, b, &ca, fb, &cb, s))
        return 0;
    if (!a)
        cut = tb;
    else if (!b)
        cut = ta;
    else if (ta >= STEP_ONE) /* a reaches c1, b is in front there */
        cut = tb;
    else if (tb <= 0) /* b reaches c0 */
        cut = ta;
    else if (ta <= tb) /* a gap between, covered by what no centre sees */
        cut = (ta + tb) / 2;
    else /* both cover the middle: the nearer one's end */
        cut = depth_at(r, &r->priv.tris[fa], s, (ta + tb) / 2) <=
                      depth_at(r, &r->priv.tris[fb], s, (ta + tb) / 2)
                  ? ta
                  : tb;
    return cut < STEP_ONE / 2 ? 1 : 2;
}

/* Flags of row y: what the row above left for it (line_pending), the
 * edges between its pixels, and those between it and the row below, which
 * is rendered now (so the line can go on either side of a boundary); the
 * flags the row below gets are left in line_pending. */
void zs_lines_row(zs_renderer *r, int y, uint8_t *flags)
{
    uint16_t *cur = r->priv.line_ids[0], *below = r->priv.line_ids[1];
    uint8_t *pending = r->priv.line_pending;
    int w = r->cfg.width, x;
    step_pair s;
    if (r->priv.line_next <= y) { /* not rendered ahead: no row above */
        zs_visible_row(r, y, (uint8_t *)cur);
        memset(pending, 0, (size_t)w);
    }
    memcpy(flags, pending, (size_t)w);
    memset(pending, 0, (size_t)w);
    s.py = 16 * y + 8;
    s.sx = 16;
    s.sy = 0;
    for (x = 1; x < w; x++)
        if (cur[x - 1] != cur[x]) {
            int e;
            s.px = 16 * x - 8;
            e = pair_edge(r, cur[x - 1], cur[x], &s);
            if (e)
                flags[x - 2 + e] = 1;
        }
    if (y + 1 >= (int)r->cfg.height) {
        r->priv.line_next = y + 1;
        return;
    }
    zs_visible_row(r, y + 1, (uint8_t *)below);
    s.sx = 0;
    s.sy = 16;
    for (x = 0; x < w; x++)
        if (cur[x] != below[x]) {
            int e;
            s.px = 16 * x + 8;
            e = pair_edge(r, cur[x], below[x], &s);
            if (e == 1)
                flags[x] = 1;
            else if (e == 2)
                pending[x] = 1;
        }
    r->priv.line_ids[0] = below;
    r->priv.line_ids[1] = cur;
    r->priv.line_next = y + 2;
}
