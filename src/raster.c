/* SPDX-License-Identifier: MIT */
/* The row loop: activate the row's triangles, sort their new edges as a
 * batch, fold edges that two triangles share into one record, merge the batch
 * into the x-sorted active edge list, resolve the row, then step the edges,
 * retire finished ones and restore the order. */
#include "zs_internal.h"

/* Setup pushes records on the front of their row's list; turning each list
 * once puts them back in submission order, so when the active pools fill
 * up, the triangles submitted last are the ones dropped. */
static void reverse_buckets(zs_renderer *r)
{
    uint16_t *bucket = r->priv.buckets;
    zs_tri *tris = r->priv.tris;
    int y;
    for (y = 0; y < (int)r->cfg.height; y++) {
        uint16_t prev = ZS_NONE, t = bucket[y];
        while (t != ZS_NONE) {
            uint16_t next = tris[t].next;
            tris[t].next = prev;
            prev = t;
            t = next;
        }
        bucket[y] = prev;
    }
}

/* Empties the twin table (zs_internal.h): after each batch is merged, so
 * twins are only found among edges made for the same row. */
static void clear_twins(zs_renderer *r)
{
    const uint32_t n = zs_twin_slots(r->priv.twin_shift); /* 0 or a multiple of 16 */
#ifdef ZS_WORD_STORES
    if (n)
        zs_store_blocks((zs_word_alias *)(void *)r->priv.sort_keys, n / 4u, ZS_TWIN_EMPTY);
#else
    uint32_t i;
    for (i = 0; i < n; i++)
        r->priv.sort_keys[i] = ZS_TWIN_EMPTY;
#endif
}

/* merge_columns' lists, after the twin table */
static uint16_t *column_heads(const zs_renderer *r)
{
    return (uint16_t *)(void *)r->priv.sort_keys + 3u * zs_twin_slots(r->priv.twin_shift);
}

void zs_raster_begin(zs_renderer *r)
{
    uint16_t *efree = r->priv.edge_free;
    uint16_t *afree = r->priv.active_free;
    /* two edge sides per triangle: e / 2 triangles can never need more than
     * e edges, even while shared edges split at their continuations */
    uint16_t e = r->cfg.max_active_edges, a = (uint16_t)(e / 2u), i;
    /* free stacks, popped from the end: lowest indices first */
    for (i = 0; i < e; i++)
        efree[i] = (uint16_t)(e - 1u - i);
    for (i = 0; i < a; i++)
        afree[i] = (uint16_t)(a - 1u - i);
    r->priv.n_edge_free = e;
    r->priv.n_active_free = a;
    r->priv.n_ael = 0;
    r->priv.n_sorted = 0;
    r->priv.steep = 0;
    r->priv.background = zs_background_word(r); /* packed once a frame */
    r->priv.row_fn = ZS_HAS_ZLINE && r->priv.mode == ZS_MODE_ZLINE         ? zs_zline_row
                     : ZS_HAS_PRIORITY && r->priv.mode == ZS_MODE_PRIORITY ? zs_priority_row
                                                                           : zs_span_row;
    r->priv.twin_shift = (uint8_t)(r->priv.sort_keys ? zs_twin_shift(r->cfg.width) : 0u);
    if (r->priv.sort_keys) { /* merge_columns' lists and the twin table: all empty */
        uint16_t *head = column_heads(r);
        for (i = 0; i <= r->cfg.width; i++)
            head[i] = ZS_NONE;
        clear_twins(r);
    }
    reverse_buckets(r);
}

/* Two new edges on the same line over the same rows, one ending a triangle
 * and the other starting one: keep one record for both. Every pool edge is
 * owned by at least one triangle side, so the pool never holds more edges
 * than twice the active triangles. */
static ZS_INLINE_ALWAYS int fold_edge(zs_renderer *r, zs_edge *keep, uint16_t keep_i, zs_edge *dup)
{
    zs_active *act = r->priv.active;
    if (keep->frac != dup->frac || keep->run != dup->run || keep->dy != dup->dy)
        return 0;
    if ((keep->lead != ZS_NONE && dup->lead != ZS_NONE) ||
        (keep->trail != ZS_NONE && dup->trail != ZS_NONE))
        return 0; /* same side twice (coplanar duplicates): keep both */
    if (dup->lead != ZS_NONE)
        keep->lead = dup->lead;
    if (dup->trail != ZS_NONE) {
        keep->trail = dup->trail;
        act[dup->trail].right = keep_i;
    }
    return 1;
}

/* Sorts edge indices by column: insertion (merge_columns' fallback without
 * the scratch, ZS_CFG_NO_ZLINE). */
static void sort_batch(zs_renderer *r, uint16_t *a, int n)
{
    const zs_edge *edges = r->priv.edges;
    int i, j;
    for (i = 1; i < n; i++) {
        uint16_t e = a[i];
        int32_t x = edges[e].x;
        for (j = i; j > 0 && edges[a[j - 1]].x > x; j--)
            a[j] = a[j - 1];
        a[j] = e;
    }
}

/* Folds, sorts and merges the unsorted tail ael[sorted, n) in one pass over
 * it and one over the columns it reaches, in the edge scratch (sort_keys, 8
 * bytes a column): head[c], c in [0, width], lists the tail's edges at column
 * c clamped to the screen, linked through their pad fields (every head is
 * ZS_NONE between rows); cols[] holds the columns with a list. No per-row
 * sort: the lists are the columns' order, and a shared edge meets its twin in
 * its column's list. Returns the list's new length. */
static int merge_columns(zs_renderer *r, int sorted, int n)
{
    uint16_t *const ael = r->priv.ael;
    zs_edge *const edges = r->priv.edges;
    uint16_t *const head = column_heads(r);
    const int32_t w = (int32_t)r->cfg.width;
    uint16_t *const cols = head + w + 1;
    int32_t lo = w, hi = 0;
    int i, k, g, ng = 0, nb = 0;
    for (i = sorted; i < n; i++) {
        const uint16_t ei = ael[i];
        zs_edge *const e = &edges[ei];
        const int32_t x = e->x;
        const int32_t c = zs_clampi(x, 0, w);
        uint16_t h = head[c];
        if (h == ZS_NONE) {
            cols[ng++] = (uint16_t)c;
        } else if (c == x) {
            /* twins start at the same column; off the screen they are
             * left apart (a column's list there may be long, and the walk
             * treats them all as at its edge) */
            for (; h != ZS_NONE; h = edges[h].pad)
                if (edges[h].x == x && fold_edge(r, &edges[h], h, e)) {
                    r->priv.edge_free[r->priv.n_edge_free++] = ei;
                    goto folded;
                }
            h = head[c];
        }
        e->pad = h;
        head[c] = ei;
        nb++;
    folded:;
    }
    /* columns from the right: a few sorted by insertion, many walked (the
     * range only looked at where it could be short enough: ng > 4) */
    if (ng > 4)
        for (g = 0; g < ng; g++) {
            lo = cols[g] < lo ? cols[g] : lo;
            hi = cols[g] > hi ? cols[g] : hi;
        }
    if (ng > 4 && (uint32_t)ng * (uint32_t)ng > 4u * (uint32_t)(hi - lo + 1)) {
        ng = 0;
        for (k = hi; k >= lo; k--)
            if (head[k] != ZS_NONE)
                cols[ng++] = (uint16_t)k;
    } else {
        for (g = 1; g < ng; g++) {
            uint16_t c = cols[g];
            for (k = g; k > 0 && cols[k - 1] < c; k--)
                cols[k] = cols[k - 1];
            cols[k] = c;
        }
    }
    /* merge from the back: each new edge after the old ones right of it
     * (the list has room; the tail is read from the lists only) */
    {
        /* the leftmost old edge stops every scan that starts at or right of
         * it: no bound test in the moving loop (unless all have moved: a
         * list off the screen is in no order of x) */
        const int32_t x0 = sorted > 0 ? edges[ael[0]].x : INT32_MAX;
#if defined(__OPTIMIZE_SIZE__)
        /* indices: fewer registers live in the loops (M0) */
        i = sorted - 1;
        k = sorted + nb - 1;
#else
        /* one past the next old edge to move and the next slot to fill: a
         * move is a load, a compare and a store */
        uint16_t *src = ael + sorted, *dst = ael + sorted + nb;
#endif
        for (g = 0; g < ng; g++) {
            const uint16_t c = cols[g];
            uint16_t b = head[c];
            head[c] = ZS_NONE;
            for (; b != ZS_NONE; b = edges[b].pad) {
                const int32_t bx = edges[b].x;
#if defined(__OPTIMIZE_SIZE__)
                if (bx >= x0 && i >= 0) {
                    while (edges[ael[i]].x > bx)
                        ael[k--] = ael[i--];
                } else {
                    for (; i >= 0; i--)
                        ael[k--] = ael[i];
                }
                ael[k--] = b;
#else
                if (bx >= x0 && src > ael) {
                    uint16_t v;
                    while (edges[v = src[-1]].x > bx) {
                        *--dst = v;
                        src--;
                    }
                } else {
                    while (src > ael)
                        *--dst = *--src;
                }
                *--dst = b;
#endif
            }
        }
    }
    return sorted + nb;
}

/* Activates the triangles first met on row y; sorts, folds and merges the
 * unsorted tail (those edges plus continuations made by the last step). */
static void add_new_edges(zs_renderer *r, int32_t y)
{
    uint16_t *ael = r->priv.ael;
    zs_edge *edges = r->priv.edges;
    uint16_t *bucket = r->priv.buckets;
    const zs_tri *tris = r->priv.tris;
    uint16_t *efree = r->priv.edge_free;
    int sorted = r->priv.n_sorted, n, i, j, k, w;
    uint16_t ti;
    for (ti = bucket[y]; ti != ZS_NONE; ti = tris[ti].next)
        zs_activate(r, ti, y);
    n = r->priv.n_ael;
    if (n == sorted)
        return;
    if (r->priv.sort_keys) {
        clear_twins(r);
        n = merge_columns(r, sorted, n);
        r->priv.n_ael = (uint16_t)n;
        r->priv.n_sorted = (uint16_t)n;
        return;
    }
    /* without the scratch (ZS_CFG_NO_ZLINE): sort by insertion, fold, merge */
    sort_batch(r, ael + sorted, n - sorted);
    /* fold shared edges: they start at the same column */
    w = sorted;
    for (i = sorted; i < n; i++) {
        zs_edge *e = &edges[ael[i]];
        int folded = 0;
        for (j = w - 1; j >= sorted && edges[ael[j]].x == e->x; j--) {
            if (fold_edge(r, &edges[ael[j]], ael[j], e)) {
                efree[r->priv.n_edge_free++] = ael[i];
                folded = 1;
                break;
            }
        }
        if (!folded)
            ael[w++] = ael[i];
    }
    n = w;
    /* merge from the back: both runs are sorted, the list has room; the free
     * stack's unused top (as many slots as edges in use) holds the batch */
    if (sorted > 0) {
        uint16_t *batch = efree + r->priv.n_edge_free;
        int nb = n - sorted;
        for (i = 0; i < nb; i++)
            batch[i] = ael[sorted + i];
        i = sorted - 1;
        k = n - 1;
        for (j = nb - 1; j >= 0; j--) { /* each new edge after the old ones right of it */
            uint16_t b = batch[j];
            int32_t bx = edges[b].x;
            while (i >= 0 && edges[ael[i]].x > bx)
                ael[k--] = ael[i--];
            ael[k--] = b;
        }
    }
    r->priv.n_ael = (uint16_t)n;
    r->priv.n_sorted = (uint16_t)n;
}

/* Row `next` of the steep planes: each anchored at its left edge's column.
 * A pass of its own, run only in frames with needles, so the edge stepping
 * loop stays as lean as without them. */
static void anchor_steep(zs_renderer *r, int32_t next)
{
    const uint16_t *ael = r->priv.ael;
    const zs_edge *edges = r->priv.edges;
    zs_active *act = r->priv.active;
    int i;
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        if (e->lead != ZS_NONE && (act[e->lead].flags & ZS_ACT_STEEP))
            zs_anchor_depth(r, &act[e->lead], &r->priv.aplane[e->lead],
                            zs_clampi(e->x, 0, r->cfg.width), next);
    }
}

/* An edge ends above row `next`: each of its triangles either ends too (freed
 * with its left edge onto afree[*n_afree]) or goes on with its lower short
 * edge (queued in cont). Returns the new length of cont. */
static inline int retire_edge(zs_active *act, const zs_edge *e, int32_t next, uint16_t *cont,
                              int n_cont, uint16_t *afree, unsigned *n_afree)
{
    if (e->lead != ZS_NONE) {
        if (next >= act[e->lead].y_end)
            afree[(*n_afree)++] = e->lead;
        else
            cont[n_cont++] = e->lead;
    }
    if (e->trail != ZS_NONE && next < act[e->trail].y_end)
        cont[n_cont++] = e->trail;
    return n_cont;
}

/* Reads e's x and remainders (neighbours: on Thumb-2 one paired load,
 * which compilers do not form here by themselves) and writes them back. */
#if defined(__GNUC__) && defined(__thumb2__)
#define ZS_LOAD_X(e, x, f)                                                               \
    __asm__("ldrd %0, %1, [%2]" : "=r"(x), "=r"(f) : "r"(e), "m"((e)->x), "m"((e)->frac))
#define ZS_STORE_X(e, x, f)                                                              \
    __asm__("strd %2, %3, [%4]" : "=m"((e)->x), "=m"((e)->frac) : "r"(x), "r"(f), "r"(e))
#else
#define ZS_LOAD_X(e, x, f) ((x) = (e)->x, (f) = (e)->frac)
#define ZS_STORE_X(e, x, f) ((e)->x = (x), (e)->frac = (f))
#endif

/* e one row down (its run loaded); returns its new x. The remainder is the
 * high half of frac, the step's remainder the low half: one subtraction
 * with a shift takes one from the other, its borrow carries the column. */
static ZS_INLINE_ALWAYS int32_t step_one(zs_edge *e, uint32_t run)
{
    int32_t x;
    uint32_t f;
    ZS_LOAD_X(e, x, f);
    x += zs_run_step(run);
#if defined(__GNUC__) && defined(__thumb2__)
    {
        uint32_t t;
        __asm__("subs %[f], %[f], %[f], lsl #16\n\t"
                "bcs 1f\n\t"
                "ldrh %[t], %[dy]\n\t"
                "add %[f], %[f], %[t], lsl #16\n\t"
                "add %[x], %[x], #1\n"
                "1:"
                : [f] "+r"(f), [x] "+r"(x), [t] "=&r"(t)
                : [dy] "m"(e->dy)
                : "cc");
    }
#elif defined(__GNUC__) && defined(__thumb__) && !defined(__clang__)
    {
        uint32_t t;
        /* (GCC hands Thumb-1 inline assembly the divided syntax) */
        __asm__(".syntax unified\n\t"
                "lsls %[t], %[f], #16\n\t"
                "subs %[f], %[f], %[t]\n\t"
                "bcs 1f\n\t"
                "ldrh %[t], %[dy]\n\t"
                "lsls %[t], %[t], #16\n\t"
                "adds %[f], %[f], %[t]\n\t"
                "adds %[x], %[x], #1\n"
                "1:\n\t"
                ".syntax divided"
                : [f] "+l"(f), [x] "+l"(x), [t] "=&l"(t)
                : [dy] "m"(e->dy)
                : "cc");
    }
#else
    if (f < f << 16) { /* err < rstep: borrow, the column carries */
        f += ((uint32_t)e->dy << 16) - (f << 16);
        x++;
    } else {
        f -= f << 16;
    }
#endif
    ZS_STORE_X(e, x, f);
    return x;
}

/* Puts edge ei, now at x, at *at or, where it passed edges before it (rare),
 * back among them: ael[0, at - ael) is sorted. */
#if defined(__OPTIMIZE_SIZE__)
#define ZS_PLACE_INLINE ZS_NOINLINE /* one copy, off the loops' registers */
#else
#define ZS_PLACE_INLINE ZS_INLINE_ALWAYS
#endif
static ZS_PLACE_INLINE void place(uint16_t *const ael, const zs_edge *edges, uint16_t *at,
                                  uint16_t ei, int32_t x)
{
    for (; at > ael && edges[at[-1]].x > x; at--)
        at[0] = at[-1];
    *at = ei;
}

#if defined(__OPTIMIZE_SIZE__)
#define ZS_LATE_INC 1 /* step_edges' second loop: p moves at its end */
#else
#define ZS_LATE_INC 0
#endif

/* Steps every edge to row y + 1, retires finished ones and keeps the list
 * sorted (an edge that passed its left neighbour is moved back: rare).
 * Planes are not stepped: each is evaluated for the row it is needed on.
 * The last edge's run reads "ends" while the loops run, so they stop there
 * with no test for the list's end; it is put back and the last edge done
 * after them. */
static void step_edges(zs_renderer *r, int32_t y)
{
    uint16_t *const ael = r->priv.ael;
    zs_edge *const edges = r->priv.edges;
    /* continuations wait in the in-polygon set's array (unused between
     * rows): at most one per active triangle */
    uint16_t *const cont = r->priv.in_set;
    const int n = r->priv.n_ael;
    const int32_t next = y + 1;
    const uint32_t next_hi = (uint32_t)next << 16;
    int i, kept = 0, n_cont = 0;
    if (n > 0) {
        uint16_t *p = ael, *const last = ael + n - 1;
        zs_edge *const le = &edges[*last];
        const uint32_t last_run = le->run;
        int32_t prev_x = INT32_MIN;
        le->run = 0; /* ends by any row */
        /* up to the first edge that retires, every edge keeps its place or
         * moves back among those before it: the list is rewritten only
         * there. One word holds the end row and the step, one both
         * remainders, next to x (a paired load and store where the core
         * has them). */
        for (;; p++) {
            zs_edge *const e = &edges[*p];
            const uint32_t run = e->run;
            int32_t x;
            if (zs_run_ends(run, next_hi))
                break;
            x = step_one(e, run);
            if (x >= prev_x)
                prev_x = x;
            else
                place(ael, edges, p, *p, x);
        }
        le->run = last_run;
        if (p == last && !zs_run_ends(last_run, next_hi)) {
            const int32_t x = step_one(le, last_run);
            if (x < prev_x)
                place(ael, edges, p, *p, x);
            kept = n;
        } else {
            /* the free stacks' tops in locals (on M0 each priv field costs
             * a literal load), written back before anything else takes
             * from them */
            zs_active *const act = r->priv.active;
            uint16_t *const efree = r->priv.edge_free, *const afree = r->priv.active_free;
            unsigned n_efree = r->priv.n_edge_free, n_afree = r->priv.n_active_free;
            uint16_t *out = p;
            int32_t x;
            le->run = 0;
            /* speed builds move p past each edge as they read it (GCC then
             * rotates the loop: M4 cubes -3.5k instructions a frame), so the
             * edge read was the last one when p > last; at -Os p moves at
             * the loop's end (ZS_LATE_INC: the post-increment costs M0 up to
             * 6k) */
            for (;; p += ZS_LATE_INC) {
                const uint16_t ei = ZS_LATE_INC ? *p : *p++;
                zs_edge *const e = &edges[ei];
                const uint32_t run = e->run;
                if (zs_run_ends(run, next_hi)) {
                    if (ZS_LATE_INC ? p == last : p > last) {
                        le->run = last_run;
                        if (!zs_run_ends(last_run, next_hi))
                            break; /* stepped below */
                    }
                    /* the one place that retires (a single copy at -Os) */
                    n_cont = retire_edge(act, e, next, cont, n_cont, afree, &n_afree);
                    efree[n_efree++] = ei;
                    if (ZS_LATE_INC ? p == last : p > last)
                        goto retired;
                    continue;
                }
                /* locals: a store through e could otherwise force reloads */
                x = step_one(e, run);
                if (x >= prev_x) {
                    prev_x = x;
                    *out++ = ei;
                } else {
                    place(ael, edges, out++, ei, x);
                }
            }
            x = step_one(le, last_run);
            if (x >= prev_x)
                *out++ = *last;
            else
                place(ael, edges, out++, *last, x);
        retired:
            kept = (int)(out - ael);
            r->priv.n_edge_free = (uint16_t)n_efree;
            r->priv.n_active_free = (uint16_t)n_afree;
        }
    }
    r->priv.n_ael = (uint16_t)kept;
    r->priv.n_sorted = (uint16_t)kept;
    if (r->priv.steep)
        anchor_steep(r, next);
    /* lower short edges join the next row's batch (edges were freed first,
     * so the pool has room) */
    for (i = 0; i < n_cont; i++)
        zs_continue_edge(r, cont[i], next);
}

void zs_raster_row(zs_renderer *r, int y, uint8_t *row)
{
    uint32_t sides;
    add_new_edges(r, y);
    /* capacity demand in edge sides, two per active triangle (a shared edge
     * record serves two sides, but each triangle needs its pair) */
    sides = 2u * (uint32_t)(r->cfg.max_active_edges / 2u - r->priv.n_active_free);
    if (sides > r->stats.max_active_edges)
        r->stats.max_active_edges = sides;
    if (row) {
        r->priv.row_fn(r, y, row); /* the mode's walk, chosen once a frame */
    }
    step_edges(r, y);
}
