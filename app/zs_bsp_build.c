/* SPDX-License-Identifier: MIT */
/* The host's BSP compiler (see zs_bsp_build.h). */
#include "zs_bsp_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_OUT 65535u
#define TOL_UNITS 1.0 /* a vertex this close to a plane (position units) is in it */

typedef struct plane {
    int64_t n[3], d;
    double tol; /* TOL_UNITS in the plane's own units (|n| times it) */
} plane;

typedef struct wtri {
    uint32_t v[3];
    uint32_t src;
    uint32_t sliver; /* a gap filler: never cut again (see classify) */
} wtri;

typedef struct tlist {
    wtri *t;
    size_t n, cap;
} tlist;

/* Vertex storage while building: int16 positions and double attributes. */
typedef struct builder {
    const zs_bspb_mesh *in;
    int weight, cands;
    int16_t *pos;
    double *col;   /* 3 per vertex, 0..255 (vertex colours) */
    double *nrm;   /* 3 per vertex (vertex normals) */
    double *uv;    /* 2 per vertex (texture coordinates) */
    uint8_t *split;
    size_t nv, capv;
    plane *src_plane; /* per input triangle */
    zs_bsp_node *nodes;
    size_t nn, capn;
    tlist out;        /* output triangles in node order */
    size_t splits, slivers;
    int depth;
    double max_snap;
    const char *err;
    /* cut cache of the node being split: edge -> vertex */
    uint64_t *ckey;
    uint32_t *cval;
    size_t ccap;
} builder;

static void *grow(void *p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return p;
    size_t c = *cap ? *cap : 16;
    while (c < need)
        c *= 2;
    void *q = realloc(p, c * elem);
    if (!q)
        abort();
    *cap = c;
    return q;
}

static void push(tlist *l, wtri t)
{
    l->t = grow(l->t, &l->cap, l->n + 1, sizeof *l->t);
    l->t[l->n++] = t;
}

static int64_t gcd64(int64_t a, int64_t b)
{
    if (a < 0)
        a = -a;
    if (b < 0)
        b = -b;
    while (b) {
        int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

static void vsub(const int16_t *a, const int16_t *b, int64_t out[3])
{
    for (unsigned k = 0; k < 3; k++)
        out[k] = (int64_t)a[k] - b[k];
}

static void cross(const int64_t a[3], const int64_t b[3], int64_t o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* The plane of triangle (a, b, c): exact when its reduced normal fits, else
 * the normal rounded to below ZS_BSP_MAX_NORMAL (a then exactly in it).
 * 0 for a zero-area triangle. */
static int make_plane(const int16_t *a, const int16_t *b, const int16_t *c, plane *p)
{
    int64_t u[3], v[3], n[3], g, m;
    vsub(b, a, u);
    vsub(c, a, v);
    cross(u, v, n);
    g = gcd64(gcd64(n[0], n[1]), n[2]);
    if (g == 0)
        return 0;
    for (unsigned k = 0; k < 3; k++)
        n[k] /= g;
    m = 0;
    for (unsigned k = 0; k < 3; k++)
        m = llabs(n[k]) > m ? llabs(n[k]) : m;
    while (m >= ZS_BSP_MAX_NORMAL) {
        for (unsigned k = 0; k < 3; k++)
            n[k] = n[k] >= 0 ? (n[k] + 1) / 2 : -((-n[k] + 1) / 2);
        m = (m + 1) / 2;
    }
    if (n[0] == 0 && n[1] == 0 && n[2] == 0)
        return 0;
    for (unsigned k = 0; k < 3; k++)
        p->n[k] = n[k];
    p->d = -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]);
    p->tol = TOL_UNITS * sqrt((double)n[0] * (double)n[0] + (double)n[1] * (double)n[1] +
                              (double)n[2] * (double)n[2]);
    return 1;
}

static int64_t dist(const plane *p, const int16_t *v)
{
    return p->n[0] * v[0] + p->n[1] * v[1] + p->n[2] * v[2] + p->d;
}

/* -1 behind, 0 in, 1 in front */
static int side_of(const plane *p, const int16_t *v)
{
    double d = (double)dist(p, v);
    return d > p->tol ? 1 : d < -p->tol ? -1 : 0;
}

static uint32_t add_vertex(builder *b)
{
    size_t cap = b->capv;
    if (b->nv >= MAX_OUT) {
        b->err = "more than 65535 vertices after splitting";
        return 0;
    }
    b->pos = grow(b->pos, &cap, b->nv + 1, 3 * sizeof *b->pos);
    cap = b->capv;
    b->col = grow(b->col, &cap, b->nv + 1, 3 * sizeof *b->col);
    cap = b->capv;
    b->nrm = grow(b->nrm, &cap, b->nv + 1, 3 * sizeof *b->nrm);
    cap = b->capv;
    b->uv = grow(b->uv, &cap, b->nv + 1, 2 * sizeof *b->uv);
    cap = b->capv;
    b->split = grow(b->split, &cap, b->nv + 1, 1);
    b->capv = cap;
    return (uint32_t)b->nv++;
}

/* The vertex where edge p-q crosses plane pl (p and q on opposite sides),
 * shared by every triangle of this node that has the edge. */
static uint32_t cut(builder *b, const plane *pl, uint32_t p, uint32_t q)
{
    uint64_t key = p < q ? ((uint64_t)p << 32 | q) : ((uint64_t)q << 32 | p);
    size_t h = (size_t)((key * 0x9E3779B97F4A7C15ull) >> 40) & (b->ccap - 1);
    while (b->ckey[h] != UINT64_MAX) {
        if (b->ckey[h] == key)
            return b->cval[h];
        h = (h + 1) & (b->ccap - 1);
    }
    uint32_t lo = p < q ? p : q, hi = p < q ? q : p; /* the same point either way */
    double dl = (double)dist(pl, &b->pos[3 * lo]), dh = (double)dist(pl, &b->pos[3 * hi]);
    double t = dl / (dl - dh), snap = 0;
    uint32_t x = add_vertex(b);
    if (b->err)
        return 0;
    for (unsigned k = 0; k < 3; k++) {
        double e = b->pos[3 * lo + k] + t * (b->pos[3 * hi + k] - b->pos[3 * lo + k]);
        double r = floor(e + 0.5);
        b->pos[3 * x + k] = (int16_t)r;
        snap += (r - e) * (r - e);
        b->col[3 * x + k] = b->col[3 * lo + k] + t * (b->col[3 * hi + k] - b->col[3 * lo + k]);
        b->nrm[3 * x + k] = b->nrm[3 * lo + k] + t * (b->nrm[3 * hi + k] - b->nrm[3 * lo + k]);
    }
    for (unsigned k = 0; k < 2; k++) /* at the exact crossing, like colours */
        b->uv[2 * x + k] = b->uv[2 * lo + k] + t * (b->uv[2 * hi + k] - b->uv[2 * lo + k]);
    snap = sqrt(snap);
    if (snap > b->max_snap)
        b->max_snap = snap;
    b->split[x] = 1;
    b->ckey[h] = key;
    b->cval[h] = x;
    return x;
}

/* Triangulates polygon v[0..n) (3 or 4 vertices, the source's winding) into
 * l as a fan. A piece that rounding turned over is kept (the renderer culls
 * it): the fan's windings then still add up to one over the polygon, so the
 * pieces that face the eye cover it with no gap. Only collapsed pieces are
 * left out. */
/* Do two of the three vertices sit at one position? (Then the triangle
 * covers nothing wherever it is seen from; three distinct points in a line
 * may still cover a pixel once the screen positions are rounded.) */
static int collapsed(const builder *b, uint32_t a, uint32_t c1, uint32_t c2)
{
    return !memcmp(&b->pos[3 * a], &b->pos[3 * c1], 3 * sizeof *b->pos) ||
           !memcmp(&b->pos[3 * a], &b->pos[3 * c2], 3 * sizeof *b->pos) ||
           !memcmp(&b->pos[3 * c1], &b->pos[3 * c2], 3 * sizeof *b->pos);
}

static void emit_poly(builder *b, const uint32_t *v, int n, uint32_t src, tlist *l)
{
    for (int k = 1; k + 1 < n; k++)
        if (!collapsed(b, v[0], v[k], v[k + 1]))
            push(l, (wtri){{v[0], v[k], v[k + 1]}, src, 0});
}

/* Cuts t by pl into front and back pieces (and slivers, to front). */
static void split_tri(builder *b, const plane *pl, const wtri *t, const int cls[3], tlist *front,
                      tlist *back)
{
    uint32_t f[4], bk[4];
    int nf = 0, nb = 0;
    b->splits++;
    for (unsigned k = 0; k < 3; k++) {
        uint32_t p = t->v[k], q = t->v[(k + 1) % 3];
        int cp = cls[k], cq = cls[(k + 1) % 3];
        if (cp >= 0)
            f[nf++] = p;
        if (cp <= 0)
            bk[nb++] = p;
        if (cp * cq < 0) {
            uint32_t x = cut(b, pl, p, q);
            if (b->err)
                return;
            f[nf++] = x;
            bk[nb++] = x;
            /* the sliver p, q, x between the edge and the rounded vertex:
             * it faces the eye where rounding moved x into the triangle and
             * fills the gap there; turned over (culled) where x moved out.
             * Always kept: on screen the 28.4 rounding decides again, and
             * the windings add up either way */
            if (!collapsed(b, p, q, x)) {
                push(front, (wtri){{p, q, x}, t->src, 1});
                b->slivers++;
            }
        }
    }
    emit_poly(b, f, nf, t->src, front);
    emit_poly(b, bk, nb, t->src, back);
}

static void classify(const builder *b, const plane *pl, const wtri *t, int cls[3], int *nf,
                     int *nb)
{
    *nf = *nb = 0;
    for (unsigned k = 0; k < 3; k++) {
        cls[k] = side_of(pl, &b->pos[3 * t->v[k]]);
        *nf += cls[k] > 0;
        *nb += cls[k] < 0;
    }
}

/* The candidate with the lowest split_weight * splits + |front - back|. */
static size_t choose(const builder *b, const tlist *l)
{
    size_t best = 0, step = l->n > (size_t)b->cands ? l->n / (size_t)b->cands : 1;
    double best_score = -1;
    for (size_t c = 0; c < l->n; c += step) {
        const plane *pl = &b->src_plane[l->t[c].src];
        long fr = 0, bk = 0, sp = 0;
        for (size_t i = 0; i < l->n; i++) {
            int cls[3], nf, nb;
            classify(b, pl, &l->t[i], cls, &nf, &nb);
            if (nf && nb)
                sp++;
            else if (nf)
                fr++;
            else if (nb)
                bk++;
        }
        double score = (double)b->weight * (double)sp + fabs((double)(fr - bk));
        if (best_score < 0 || score < best_score) {
            best_score = score;
            best = c;
        }
    }
    return best;
}

static uint16_t build(builder *b, tlist *l, int depth)
{
    if (l->n == 0 || b->err)
        return ZS_BSP_NONE;
    if (b->nn >= MAX_OUT - 1) {
        b->err = "more than 65534 nodes";
        return ZS_BSP_NONE;
    }
    if (depth > b->depth)
        b->depth = depth;
    size_t ci = choose(b, l);
    plane pl = b->src_plane[l->t[ci].src];
    size_t node = b->nn;
    b->nodes = grow(b->nodes, &b->capn, b->nn + 1, sizeof *b->nodes);
    b->nn++;
    tlist front = {0}, back = {0}, on_f = {0}, on_b = {0};
    /* the cut cache: room for every edge of the list */
    size_t need = 1;
    while (need < 8 * l->n)
        need *= 2;
    if (need > b->ccap) {
        free(b->ckey);
        free(b->cval);
        b->ckey = malloc(need * sizeof *b->ckey);
        b->cval = malloc(need * sizeof *b->cval);
        if (!b->ckey || !b->cval)
            abort();
        b->ccap = need;
    }
    memset(b->ckey, 0xFF, b->ccap * sizeof *b->ckey);
    for (size_t i = 0; i < l->n && !b->err; i++) {
        const wtri *t = &l->t[i];
        int cls[3], nf, nb;
        classify(b, &pl, t, cls, &nf, &nb);
        const int64_t *sn = b->src_plane[t->src].n;
        double dot = (double)sn[0] * (double)pl.n[0] + (double)sn[1] * (double)pl.n[1] +
                     (double)sn[2] * (double)pl.n[2];
        double cosang = dot / (b->src_plane[t->src].tol * pl.tol) * TOL_UNITS * TOL_UNITS;
        if (i == ci || (!nf && !nb && fabs(cosang) > 0.999)) {
            /* in the plane (the splitter always): drawn with the node, its
             * facing from its source's normal */
            push(dot > 0 ? &on_f : &on_b, *t);
        } else if (!nf && !nb) {
            /* within the tolerance but across the plane (a sliver along an
             * edge of it): to the side its vertices lean to */
            int64_t sum = 0;
            for (unsigned k = 0; k < 3; k++)
                sum += dist(&pl, &b->pos[3 * t->v[k]]);
            push(sum >= 0 ? &front : &back, *t);
        } else if (nf && nb && t->sliver) {
            /* a sliver runs along a whole edge and would be cut by every
             * plane crossing it, making slivers of its own: it goes whole to
             * the side of most of its vertices (it is at most a rounding
             * wide, inside the bound) */
            push(nf >= nb ? &front : &back, *t);
        } else if (nf && nb) {
            split_tri(b, &pl, t, cls, &front, &back);
        } else {
            push(nf ? &front : &back, *t);
        }
    }
    free(l->t);
    l->t = 0;
    l->n = l->cap = 0;
    if (b->out.n + on_f.n + on_b.n > MAX_OUT && !b->err)
        b->err = "more than 65535 triangles after splitting";
    zs_bsp_node nd;
    memset(&nd, 0, sizeof nd);
    nd.n[0] = (int32_t)pl.n[0];
    nd.n[1] = (int32_t)pl.n[1];
    nd.n[2] = (int32_t)pl.n[2];
    nd.d = pl.d;
    nd.first = (uint16_t)b->out.n;
    nd.n_front = (uint16_t)on_f.n;
    nd.n_back = (uint16_t)on_b.n;
    for (size_t i = 0; i < on_f.n && !b->err; i++)
        push(&b->out, on_f.t[i]);
    for (size_t i = 0; i < on_b.n && !b->err; i++)
        push(&b->out, on_b.t[i]);
    free(on_f.t);
    free(on_b.t);
    nd.front = build(b, &front, depth + 1);
    nd.back = build(b, &back, depth + 1);
    free(front.t);
    free(back.t);
    b->nodes[node] = nd;
    return (uint16_t)node;
}

/* The most entries the core's walk can leave pending below node i (the
 * measure zs_bsp_check bounds by ZS_BSP_MAX_STACK). */
static int walk_stack(const zs_bsp_node *nodes, uint16_t i, int c)
{
    const zs_bsp_node *nd = &nodes[i];
    int m = c, k;
    if (nd->front != ZS_BSP_NONE) {
        k = walk_stack(nodes, nd->front,
                       c + (nd->back != ZS_BSP_NONE) + (nd->n_front + nd->n_back > 0));
        m = k > m ? k : m;
    }
    if (nd->back != ZS_BSP_NONE) {
        k = walk_stack(nodes, nd->back, c + (nd->front != ZS_BSP_NONE) + (nd->n_back > 0));
        m = k > m ? k : m;
    }
    return m;
}

void zs_bspb_free(zs_bspb_result *r)
{
    free(r->mesh.pos);
    free(r->mesh.idx);
    free(r->mesh.fcol);
    free(r->mesh.fnrm);
    free(r->mesh.vcol);
    free(r->mesh.vnrm);
    free(r->mesh.uv);
    free(r->source);
    free(r->is_split);
    free(r->nodes);
    memset(r, 0, sizeof *r);
}

static int16_t q14(double x)
{
    double v = floor(x * 16384.0 + 0.5);
    return (int16_t)(v > 16384 ? 16384 : v < -16384 ? -16384 : v);
}

/* One build with the given splitter score; *too_deep set when it failed for
 * the walk's stack alone. */
static const char *build_once(const zs_bspb_mesh *in, int weight, int cands, zs_bspb_result *out,
                              int *too_deep)
{
    builder b;
    tlist all = {0};
    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    *too_deep = 0;
    if (in->nv > MAX_OUT || in->nt > MAX_OUT)
        return "more than 65535 vertices or triangles";
    b.in = in;
    b.weight = weight;
    b.cands = cands;
    for (size_t i = 0; i < in->nv; i++) {
        uint32_t v = add_vertex(&b);
        for (unsigned k = 0; k < 3; k++) {
            b.pos[3 * v + k] = in->pos[3 * i + k];
            b.col[3 * v + k] = in->vcol ? (double)((in->vcol[i] >> (16 - 8 * k)) & 255u) : 0;
            b.nrm[3 * v + k] = in->vnrm ? in->vnrm[3 * i + k] / 16384.0 : 0;
        }
        for (unsigned k = 0; k < 2; k++)
            b.uv[2 * v + k] = in->uv ? (double)in->uv[2 * i + k] : 0;
        b.split[v] = 0;
    }
    b.src_plane = calloc(in->nt ? in->nt : 1, sizeof *b.src_plane);
    if (!b.src_plane)
        abort();
    for (size_t i = 0; i < in->nt; i++) {
        const uint16_t *t = &in->idx[3 * i];
        if (t[0] >= in->nv || t[1] >= in->nv || t[2] >= in->nv) {
            b.err = "a triangle index is out of range";
            break;
        }
        if (!make_plane(&in->pos[3 * t[0]], &in->pos[3 * t[1]], &in->pos[3 * t[2]],
                        &b.src_plane[i])) {
            out->dropped++;
            continue;
        }
        push(&all, (wtri){{t[0], t[1], t[2]}, (uint32_t)i, 0});
    }
    if (!b.err && all.n == 0)
        b.err = "no triangle with an area";
    if (!b.err)
        build(&b, &all, 1);
    if (!b.err) {
        out->stack = walk_stack(b.nodes, 0, 0);
        if (out->stack > ZS_BSP_MAX_STACK) {
            static char msg[96];
            snprintf(msg, sizeof msg, "the walk of the tree would need %d entries, more than "
                     "ZS_BSP_MAX_STACK", out->stack);
            b.err = msg;
            *too_deep = 1;
        }
    }
    free(all.t);
    free(b.ckey);
    free(b.cval);
    free(b.src_plane);
    if (!b.err) {
        zs_bspb_mesh *m = &out->mesh;
        m->nv = b.nv;
        m->nt = b.out.n;
        m->pos = b.pos;
        b.pos = 0;
        out->is_split = b.split;
        b.split = 0;
        m->idx = malloc(3 * m->nt * sizeof *m->idx + 1);
        out->source = malloc(m->nt * sizeof *out->source + 1);
        if (!m->idx || !out->source)
            abort();
        for (size_t i = 0; i < m->nt; i++) {
            for (unsigned k = 0; k < 3; k++)
                m->idx[3 * i + k] = (uint16_t)b.out.t[i].v[k];
            out->source[i] = b.out.t[i].src;
        }
        if (in->fcol || in->fnrm) {
            if (in->fcol && !(m->fcol = malloc(m->nt * sizeof *m->fcol + 1)))
                abort();
            if (in->fnrm && !(m->fnrm = malloc(3 * m->nt * sizeof *m->fnrm + 1)))
                abort();
            for (size_t i = 0; i < m->nt; i++) {
                if (m->fcol)
                    m->fcol[i] = in->fcol[out->source[i]];
                for (unsigned k = 0; m->fnrm && k < 3; k++)
                    m->fnrm[3 * i + k] = in->fnrm[3 * out->source[i] + k];
            }
        }
        if (in->vcol) {
            if (!(m->vcol = malloc(m->nv * sizeof *m->vcol + 1)))
                abort();
            for (size_t i = 0; i < m->nv; i++) {
                uint32_t c = 0;
                for (unsigned k = 0; k < 3; k++) {
                    double v = floor(b.col[3 * i + k] + 0.5);
                    c |= (uint32_t)(v < 0 ? 0 : v > 255 ? 255 : v) << (16 - 8 * k);
                }
                m->vcol[i] = c;
            }
        }
        if (in->vnrm) {
            if (!(m->vnrm = malloc(3 * m->nv * sizeof *m->vnrm + 1)))
                abort();
            for (size_t i = 0; i < m->nv; i++) {
                double *n = &b.nrm[3 * i], len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                for (unsigned k = 0; k < 3; k++)
                    m->vnrm[3 * i + k] = q14(len > 0 ? n[k] / len : 0);
            }
        }
        if (in->uv) {
            if (!(m->uv = malloc(2 * m->nv * sizeof *m->uv + 1)))
                abort();
            for (size_t i = 0; i < 2 * m->nv; i++) {
                double v = floor(b.uv[i] + 0.5);
                m->uv[i] = (int16_t)(v < -32768 ? -32768 : v > 32767 ? 32767 : v);
            }
        }
        out->nodes = b.nodes;
        b.nodes = 0;
        out->node_count = b.nn;
        out->splits = b.splits;
        out->slivers = b.slivers;
        out->depth = b.depth;
        out->max_snap = b.max_snap;
    }
    free(b.pos);
    free(b.col);
    free(b.nrm);
    free(b.uv);
    free(b.split);
    free(b.nodes);
    free(b.out.t);
    if (b.err) {
        zs_bspb_free(out);
        return b.err;
    }
    return NULL;
}

const char *zs_bspb_build(const zs_bspb_mesh *in, const zs_bspb_params *p, zs_bspb_result *out)
{
    int weight = p && p->split_weight > 0 ? p->split_weight : 8;
    int cands = p && p->candidates > 0 ? p->candidates : 24, too_deep;
    for (;;) {
        const char *err = build_once(in, weight, cands, out, &too_deep);
        /* a tree too deep to walk: with the default score, weigh balance
         * more (halving the split weight) until it fits or the weight is 1 */
        if (!err)
            out->split_weight = weight;
        if (!err || !too_deep || (p && p->split_weight > 0) || weight == 1)
            return err;
        weight /= 2;
    }
}
