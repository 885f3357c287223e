/* SPDX-License-Identifier: MIT */
/* Span visibility for one row: walk the x-sorted active edge list, keep the
 * set of triangles the walk is inside and the nearest of them (the top).
 *
 * Decisions are exact at pixel centres: at every column the top is the
 * minimum of (depth, record index) over the set, the same rule the z-buffer
 * mode applies per pixel, so the two modes give identical images.
 *
 * Work stays small because a decision is only made when something changes:
 *  - a triangle entering is compared with the top once, at its first column;
 *  - when the top leaves, the nearest of the rest is picked, once all the
 *    events at that column are in (where a mesh's triangles share an edge,
 *    one leaves and the next enters at the same column);
 *  - two depth planes differ linearly along a row, so for each other member
 *    the first column where it would overtake the top (a penetration) is
 *    computed once, and only when it lies before either of the two ends
 *    (one multiplication; a division only for a real crossing). The nearest
 *    such column splits the span. */
#include "zs_internal.h"

#define NO_CROSS INT32_MAX

/* The walk's hot state lives in locals of zs_span_row (registers: with
 * -fno-strict-aliasing, state behind a pointer would be reloaded after every
 * store to a record). The out-of-line helpers below get what they need as
 * arguments and pass the nearest crossing back through r->priv.min_cross. */

/* The depth plane of a (same index in the parallel array). */
static inline zs_active_plane *plane_of(const zs_renderer *r, const zs_active *a)
{
    return &r->priv.aplane[a - r->priv.active];
}

/* Depth of a (plane p) at column x of row y, the plane made first if lazy. */
static ZS_INLINE_ALWAYS int64_t depth_at(zs_renderer *r, zs_active *a, const zs_active_plane *p,
                                         int32_t x, int32_t y)
{
    if (a->flags & ZS_ACT_LAZY)
        zs_make_plane(r, a, y);
    return zs_row_depth(p, a, y) + zs_mul64_small(a->zdx, x);
}

/* Does (za, a) win over (zb, b)? Nearer first, then the earlier record. */
static int nearer(int64_t za, const zs_active *a, int64_t zb, const zs_active *b)
{
    return za < zb || (za == zb && a->tri < b->tri);
}

/* Is a nearer than b at every centre both cover? (Their depth ranges say
 * so without evaluating either plane.) */
static int always_nearer(const zs_active *a, const zs_active *b)
{
    return a->zhi <= b->zlo;
}

/* Clamped column where a ends on this row (its right edge). */
static int32_t right_column(const zs_renderer *r, const zs_active *a)
{
    return zs_clampi(r->priv.edges[a->right].x, 0, (int32_t)r->cfg.width);
}

/* First column after x where j overtakes top, or NO_CROSS when that does not
 * happen before one of the two triangles ends on this row. zj, zt: depths
 * at x, where top wins. */
static int32_t overtake(const zs_renderer *r, const zs_active *j, const zs_active *top,
                        int32_t x, int64_t zj, int64_t zt)
{
    int64_t slope = top->zdx - j->zdx, gap = zj - zt, reach, k;
    int32_t lim, lj;
    int j_wins_tie = j->tri < top->tri;
    if (slope <= 0)
        return NO_CROSS; /* j never gets nearer along this row */
    lim = right_column(r, top);
    lj = right_column(r, j);
    if (lj < lim)
        lim = lj;
    if (lim - x <= 1)
        return NO_CROSS;
    /* how much the gap closes by the last shared column (|slope| <= 2^49) */
    reach = zs_mul64_small(slope, lim - x - 1);
    if (reach < gap || (reach == gap && !j_wins_tie))
        return NO_CROSS;
#ifdef ZS_SPLIT_MUL
    /* the first k in [1, lim - x - 1] where slope * k reaches the gap (passes
     * it when the tie goes to top), by bisection: no 64-bit division helper */
    {
        int32_t lo = 1, hi = lim - x - 1;
        while (lo < hi) {
            int32_t mid = lo + (hi - lo) / 2;
            int64_t c = zs_mul64_small(slope, mid);
            if (c > gap || (c == gap && j_wins_tie))
                hi = mid;
            else
                lo = mid + 1;
        }
        k = lo;
    }
#else
    k = j_wins_tie ? (gap + slope - 1) / slope : gap / slope + 1;
#endif
    return x + (int32_t)k;
}

/* The top by depth ranges alone, or NULL: the member whose range ends first
 * wins outright if it ends before every other range starts (typical where
 * surfaces are apart in depth); then no plane is evaluated and nothing can
 * overtake it. *others_lo: the smallest zlo of the other members; *min_hi:
 * the smallest zhi (a member whose zlo is not below it cannot be nearest).
 * Every member's crossing is reset on the way. */
static zs_active *range_top(zs_active *act, const uint16_t *set, int ns, uint16_t *others_lo,
                            uint16_t *min_hi)
{
    zs_active *near = 0;
    const zs_active *lo1_of = 0;
    uint16_t lo1 = 0xFFFFu, lo2 = 0xFFFFu; /* the two smallest zlo */
    int k;
    for (k = 0; k < ns; k++) {
        zs_active *a = &act[set[k]];
        a->cross = NO_CROSS; /* the top's is never read; the others' are set
                                again unless this pick needs no depth */
        if (!near || a->zhi < near->zhi)
            near = a;
        if (a->zlo < lo1) {
            lo2 = lo1;
            lo1 = a->zlo;
            lo1_of = a;
        } else if (a->zlo < lo2) {
            lo2 = a->zlo;
        }
    }
    *others_lo = near == lo1_of ? lo2 : lo1;
    *min_hi = near ? near->zhi : 0xFFFFu;
    return near && near->zhi <= *others_lo ? near : 0;
}

/* What the out-of-line helpers need besides the walk's locals. */
typedef struct walk_ctx {
    zs_renderer *r;
    uint8_t *row;
    int32_t y;
} walk_ctx;

/* Picks the top among the ns members at column x; sets each member's
 * crossing with it and the nearest of them in r->priv.min_cross, and the
 * smallest zlo of the other members in r->priv.others_lo. */
static ZS_NOINLINE zs_active *retop(const walk_ctx *w, int ns, int32_t x)
{
    zs_renderer *r = w->r;
    zs_active *act = r->priv.active;
    zs_active_plane *pl = r->priv.aplane;
    const uint16_t *set = r->priv.in_set;
    uint16_t others_lo, min_hi;
    zs_active *best = range_top(act, set, ns, &others_lo, &min_hi);
    int32_t min_cross = NO_CROSS, y = w->y;
    int64_t bz = 0;
    uint32_t evals = 0;
    int k;
    if (best) { /* nearer than every other member wherever they meet */
        r->priv.others_lo = others_lo;
        r->priv.min_cross = NO_CROSS;
        return best;
    }
    /* the nearest at x: only a member whose range starts below min_hi can
     * be it (the member whose range ends there is nearer than the rest) */
    for (k = 0; k < ns; k++) {
        zs_active *a = &act[set[k]];
        zs_active_plane *p = &pl[set[k]];
        int64_t z;
        if (a->zlo >= min_hi)
            continue;
        z = depth_at(r, a, p, x, y);
        p->zcur = z;
        evals++;
        if (!best || nearer(z, a, bz, best)) {
            best = a;
            bz = z;
        }
    }
    /* each other member's crossing with it: none for those behind it
     * wherever they meet, which need no depth at all */
    others_lo = 0xFFFFu;
    for (k = 0; k < ns; k++) {
        zs_active *a = &act[set[k]];
        if (a == best)
            continue;
        if (a->zlo < others_lo)
            others_lo = a->zlo;
        if (always_nearer(best, a)) {
            a->cross = NO_CROSS;
        } else {
            zs_active_plane *p = &pl[set[k]];
            if (a->zlo >= min_hi) {
                p->zcur = depth_at(r, a, p, x, y);
                evals++;
            }
            a->cross = overtake(r, a, best, x, p->zcur, bz);
        }
        if (a->cross < min_cross)
            min_cross = a->cross;
    }
    r->stats.depth_evals += evals;
    r->priv.min_cross = min_cross;
    r->priv.others_lo = others_lo;
    return best;
}

/* Writes [x0, x1) of a (NULL: the background). */
static ZS_NOINLINE void put_span(const walk_ctx *w, const zs_active *a, int32_t x0, int32_t x1)
{
    zs_renderer *r = w->r;
    if (!a)
        zs_fill_flat(w->row, x0, x1, r->priv.bpp, r->priv.background);
    else if (ZS_HAS_PLANES_ && (a->flags & ZS_ACT_GOURAUD))
        zs_fill_gouraud(r, &r->priv.acolor[a - r->priv.active], w->y - a->y0, w->row, x0, x1);
    else
        zs_fill_flat(w->row, x0, x1, r->priv.bpp, a->pixel);
    r->stats.spans++;
}

/* put_span, with the common case in line: a flat surface in a 2-byte
 * format is one fill of a packed pair, no call. */
static ZS_INLINE_ALWAYS void write_span(const walk_ctx *w, const zs_active *a, int32_t x0,
                                        int32_t x1, const int flat2)
{
#if defined(__OPTIMIZE_SIZE__) /* one copy: smaller, and no slower there */
    (void)flat2;
    put_span(w, a, x0, x1);
#else
    if (flat2 || (w->r->priv.bpp == 2 && !(a && (a->flags & ZS_ACT_GOURAUD)))) {
        /* a constant bpp: zs_fill_flat folds to the 2-byte fill */
        zs_fill_flat(w->row, x0, x1, 2u, a ? a->pixel : w->r->priv.background);
        w->r->stats.spans++;
    } else {
        put_span(w, a, x0, x1);
    }
#endif
}

/* A member other than the top left: the nearest crossing of the rest. */
static ZS_NOINLINE int32_t next_cross(const zs_renderer *r, int ns, const zs_active *top)
{
    const zs_active *act = r->priv.active;
    const uint16_t *set = r->priv.in_set;
    int32_t m = NO_CROSS;
    int k;
    for (k = 0; k < ns; k++) {
        const zs_active *a = &act[set[k]];
        if (a != top && a->cross < m)
            m = a->cross;
    }
    return m;
}

/* An entering triangle a at column x against the top (both in the set):
 * its crossing with the top, or 1 when it may be the new top (pick again). */
static ZS_NOINLINE int enter_vs_top(const walk_ctx *w, zs_active *a, zs_active *top,
                                    int32_t x)
{
    int64_t za = depth_at(w->r, a, plane_of(w->r, a), x, w->y);
    int64_t zt = depth_at(w->r, top, plane_of(w->r, top), x, w->y);
    w->r->stats.depth_evals += 2;
    if (nearer(za, a, zt, top))
        return 1;
    a->cross = overtake(w->r, a, top, x, za, zt);
    return 0;
}

/* An edge's lead or trail as a signed value: ZS_NONE (all ones) reads as -1
 * through int16_t (exact-width, two's complement; it may alias uint16_t),
 * and indices stay below 2^15: one signed load and a sign test. */
static inline int32_t edge_side(const uint16_t *f)
{
    return *(const int16_t *)(const void *)f;
}

/* An entering member b against a top that stays in the set: behind it
 * wherever both are (no crossing either), a new top (every member's crossing
 * changes: pick again, unless b is nearer than every member wherever they
 * meet while no crossing is pending: then b is the top outright and every
 * crossing stays none), or behind it with a crossing to keep. */
#define b_vs_top(b)                                                                        \
    do {                                                                                   \
        if (always_nearer(top, (b))) {                                                     \
            if ((b)->zlo < others_lo)                                                      \
                others_lo = (b)->zlo;                                                      \
        } else if (always_nearer((b), top)) {                                              \
            if (min_cross == NO_CROSS && (b)->zhi <= others_lo) {                          \
                if (top->zlo < others_lo)                                                  \
                    others_lo = top->zlo;                                                  \
                top = (b);                                                                 \
            } else {                                                                       \
                top = 0;                                                                   \
            }                                                                              \
        } else if (enter_vs_top(&w, (b), top, cur)) {                                      \
            top = 0;                                                                       \
        } else {                                                                           \
            if ((b)->cross < min_cross)                                                    \
                min_cross = (b)->cross;                                                    \
            if ((b)->zlo < others_lo)                                                      \
                others_lo = (b)->zlo;                                                      \
        }                                                                                  \
    } while (0)

/* All events at a column are applied before its span: moves the walk to
 * column xv, writing or extending the span before it and splitting it where
 * a member overtakes the top. An edge left of the screen acts at column 0,
 * one right of it at the width. (A macro: it updates the walk's locals.) */
#define ADVANCE_TO(xv)                                                                     \
    do {                                                                                   \
        int32_t x = (xv);                                                                  \
        if (x > cur) {                                                                     \
            if (x > width)                                                                 \
                x = width;                                                                 \
            if (top ? min_cross < x : ns > 0) {                                            \
                /* a pick is due, or a member overtakes the top before x */                \
                if (!top) {                                                                \
                    top = retop(&w, ns, cur);                                              \
                    min_cross = r->priv.min_cross;                                         \
                    others_lo = r->priv.others_lo;                                         \
                }                                                                          \
                for (;;) {                                                                 \
                    if (top != pend_top) { /* spans of one surface merge */                \
                        if (cur > pend_x0)                                                 \
                            write_span(&w, pend_top, pend_x0, cur, flat2);                        \
                        pend_top = top;                                                    \
                        pend_x0 = cur;                                                     \
                    }                                                                      \
                    if (min_cross >= x)                                                    \
                        break;                                                             \
                    cur = min_cross; /* split */                                           \
                    r->stats.crossings++;                                                  \
                    top = retop(&w, ns, cur);                                              \
                    min_cross = r->priv.min_cross;                                         \
                    others_lo = r->priv.others_lo;                                         \
                }                                                                          \
            } else if (top != pend_top) { /* spans of one surface merge */                 \
                if (cur > pend_x0)                                                         \
                    write_span(&w, pend_top, pend_x0, cur, flat2);                                \
                pend_top = top;                                                            \
                pend_x0 = cur;                                                             \
            }                                                                              \
            cur = x;                                                                       \
        }                                                                                  \
    } while (0)

/* The walk of one row; flat2: every span is a flat fill of a 2-byte format
 * (a constant, so that copy has no per-span test). */
static ZS_INLINE_ALWAYS void span_row(zs_renderer *r, int y, uint8_t *row, const int flat2)
{
    zs_active *const act = r->priv.active;
    const zs_edge *const edges = r->priv.edges;
    const uint16_t *p = r->priv.ael;
    const uint16_t *const end = p + r->priv.n_ael;
    uint16_t *const set = r->priv.in_set;
    const int32_t width = (int32_t)r->cfg.width;
    /* the nearest member; NULL while the set has members means "pick again
     * once this column's events are in" */
    zs_active *top = 0;
    const zs_active *pend_top = 0; /* span started at pend_x0, not yet written */
    int32_t pend_x0 = 0, cur = 0;
    int32_t min_cross = NO_CROSS;  /* first column where a member overtakes the top */
    uint16_t others_lo = 0xFFFFu;  /* at most the smallest zlo of the other members */
    int ns = 0;                    /* members of the in-polygon set */
    int odd = 0;                   /* triangles whose counter is 255: right edge met
                                      first (a span inverted by rounding) */
    walk_ctx w;
    w.r = r;
    w.row = row;
    w.y = y;
single:
    /* A single-layer stretch: the set holds at most the top, no crossing is
     * pending and every other counter is 0 (a convex mesh's rows are this
     * whole: one triangle hands over to the next at each edge). The same
     * spans as the general walk below, with none of its bookkeeping; it
     * takes over at the first event that would make a second member or
     * meets a triangle that is not in the set. */
    while (p != end) {
        const zs_edge *const e = &edges[*p];
        const int32_t t = edge_side(&e->trail), l = edge_side(&e->lead);
        int32_t x = e->x;
        zs_active *after = top;
        if (t >= 0) {
            if (&act[t] != top)
                break;
            after = 0;
        }
        if (l >= 0) {
            if (after)
                break;
            after = &act[l];
        }
        p++;
        if (x > cur) {
            if (x > width)
                x = width;
            if (top != pend_top) { /* spans of one surface merge */
                if (cur > pend_x0)
                    write_span(&w, pend_top, pend_x0, cur, flat2);
                pend_top = top;
                pend_x0 = cur;
            }
            cur = x;
        }
        top = after;
    }
    /* the general walk's state for what the stretch leaves (the top's
     * counter reads 0 in the stretch, 1 here) */
    ns = 0;
    if (top) {
        top->inside = 1u;
        top->set_pos = 0;
        top->cross = NO_CROSS;
        set[0] = (uint16_t)(top - act);
        ns = 1;
    }
    min_cross = NO_CROSS;
    others_lo = 0xFFFFu;
    while (p != end) {
        const zs_edge *const e = &edges[*p++];
        int32_t t, l; /* the edge's triangles, < 0 for none */
        int handover; /* the top left at this edge with no crossing pending */
        zs_active *entering;
        ADVANCE_TO(e->x);
        /* in/out counters: a span inverted by rounding is never entered
         * (they count modulo 256: entering is 0 -> 1, leaving 1 -> 0) */
        handover = 0;
        t = edge_side(&e->trail);
        l = edge_side(&e->lead);
        if (t >= 0) {
            zs_active *a = &act[t];
            uint8_t was = a->inside;
            a->inside = (uint8_t)(was - 1u);
            if (was == 1u) { /* leaves the set */
                uint16_t pos = a->set_pos;
                if (l >= 0 && act[l].inside == 0u) {
                    /* a shared edge: the entering neighbour takes the slot */
                    zs_active *b = &act[l];
                    b->inside = 1u;
                    b->set_pos = pos;
                    set[pos] = (uint16_t)l;
                    b->cross = NO_CROSS;
                    if (ns == 1) { /* the only member */
                        top = b;
                        min_cross = NO_CROSS;
                        others_lo = 0xFFFFu;
                    } else if (a == top) {
                        top = 0;
                        if (min_cross == NO_CROSS && b->zhi <= others_lo)
                            top = b; /* nearer than every other member */
                    } else if (top) {
                        if (a->cross == min_cross && min_cross != NO_CROSS)
                            min_cross = next_cross(r, ns, top);
#if defined(__OPTIMIZE_SIZE__) /* one copy of b_vs_top: smaller and faster there */
                        entering = b;
                        goto vs_top; /* (ns >= 2: the check after it fails too) */
#else
                        b_vs_top(b);
#endif
                    }
                    continue;
                }
                {
                    uint16_t last = set[--ns];
                    set[pos] = last;
                    act[last].set_pos = pos;
                }
                if (a == top) {
                    /* nothing overtakes it: every member's crossing is none */
                    handover = min_cross == NO_CROSS;
                    top = 0;
                } else if (top && a->cross == min_cross && min_cross != NO_CROSS)
                    min_cross = next_cross(r, ns, top);
            } else {
                odd++;
            }
        }
        if (l >= 0) {
            zs_active *a = &act[l];
            uint8_t was = a->inside;
            a->inside = (uint8_t)(was + 1u);
            if (was == 0u) { /* enters the set */
                a->set_pos = (uint16_t)ns;
                set[ns++] = (uint16_t)l;
                a->cross = NO_CROSS;
                if (!top) {
                    if (ns == 1) { /* the only member */
                        top = a;
                        min_cross = NO_CROSS;
                        others_lo = 0xFFFFu;
                    } else if (handover && a->zhi <= others_lo) {
                        /* the top left through the edge a enters by, and a is
                         * nearer than every other member wherever they meet */
                        top = a;
                    } /* else the pick after this column's events includes it */
                } else {
                    entering = a;
#if defined(__OPTIMIZE_SIZE__)
                vs_top:
#endif
                    b_vs_top(entering);
                }
            } else {
                odd--;
            }
        }
        if (ns <= 1 && odd == 0) {
            /* one member or none, every other counter 0: a single-layer
             * stretch again (its top's counter reads 0 there) */
            if (ns) {
                top = &act[set[0]];
                top->inside = 0u;
            }
            goto single;
        }
    }
    ADVANCE_TO(width); /* the rest of the row */
    if (width > pend_x0)
        write_span(&w, pend_top, pend_x0, width, flat2);
    r->stats.pixels_shaded += (uint32_t)width;
}

void zs_span_row(zs_renderer *r, int y, uint8_t *row)
{
#if defined(__OPTIMIZE_SIZE__) /* one copy */
    span_row(r, y, row, 0);
#else
    /* without colour planes no triangle is Gouraud-shaded */
    if (r->priv.bpp == 2 && !r->priv.acolor)
        span_row(r, y, row, 1);
    else
        span_row(r, y, row, 0);
#endif
}
