/* SPDX-License-Identifier: MIT */
/* BSP order: check a compiled tree, find the eye in the mesh's position
 * units, and walk the tree near side first, handing zs_draw one node's
 * triangle range at a time (zs_next_range), so the records are stored in
 * visibility order for ZS_MODE_PRIORITY. */
#include "zs_internal.h"
#include "zspan/priority.h"

/* Stack entries: node index << 2 | what to do with it. */
enum { VISIT = 0, RANGE_FRONT = 1, RANGE_BACK = 2, RANGE_BOTH = 3 };
#define STACK_MAX (ZS_BSP_MAX_STACK + 3)
/* |eye coordinate| kept below this (Q16 position units) so a plane test fits
 * 64 bits: 3 * 2^24 * 2^36 + 2^58 < 2^63. */
#define EYE_MAX ((int64_t)1 << 36)
/* |model 3x3 entry| below this (scales below 256) keeps A^T rel in 64 bits */
#define MODEL_MAX ((int32_t)1 << 24)

typedef struct bsp_walk {
    const zs_bsp *bsp;
    int64_t eye[3];  /* Q16 position units, shifted right by shift */
    unsigned shift;
    int sp;
    uint32_t stack[STACK_MAX];
} bsp_walk;

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

zs_status zs_bsp_check(const zs_bsp *bsp)
{
    /* preorder walk, front first: the nodes must come as 0, 1, 2, ... so a
     * cycle or a node reached twice shows as an index out of turn; each
     * entry carries the walk's worst pending count on the way down */
    uint16_t stack[ZS_BSP_MAX_STACK + 1];
    uint8_t cost[ZS_BSP_MAX_STACK + 1];
    uint32_t next = 0, ntri;
    int sp = 0;
    if (!bsp || !bsp->nodes || !bsp->mesh)
        return ZS_ERR_NULL;
    if (bsp->node_count == 0)
        return ZS_ERR_BSP;
    ntri = bsp->mesh->triangle_count;
    stack[sp] = 0;
    cost[sp++] = 0;
    while (sp > 0) {
        uint16_t i = stack[--sp];
        unsigned c = cost[sp], cf, cb;
        const zs_bsp_node *nd;
        int k;
        if (i != next || i >= bsp->node_count)
            return ZS_ERR_BSP;
        next++;
        nd = &bsp->nodes[i];
        if ((uint32_t)nd->first + nd->n_front + nd->n_back > ntri)
            return ZS_ERR_BSP;
        for (k = 0; k < 3; k++)
            if (nd->n[k] >= ZS_BSP_MAX_NORMAL || nd->n[k] <= -ZS_BSP_MAX_NORMAL)
                return ZS_ERR_BSP;
        if (abs64(nd->d) >= ZS_BSP_MAX_D)
            return ZS_ERR_BSP;
        if (nd->front != ZS_BSP_NONE && nd->front != i + 1u)
            return ZS_ERR_BSP;
        /* what stays pending while the walk is below each child */
        cf = c + (nd->back != ZS_BSP_NONE) + (nd->n_front + nd->n_back > 0);
        cb = c + (nd->front != ZS_BSP_NONE) + (nd->n_back > 0);
        if (nd->back != ZS_BSP_NONE) { /* its turn comes after the front subtree */
            if (nd->back <= i || cb > ZS_BSP_MAX_STACK || sp >= ZS_BSP_MAX_STACK)
                return ZS_ERR_BSP;
            stack[sp] = nd->back;
            cost[sp++] = (uint8_t)cb;
        }
        if (nd->front != ZS_BSP_NONE) {
            if (cf > ZS_BSP_MAX_STACK || sp >= ZS_BSP_MAX_STACK)
                return ZS_ERR_BSP;
            stack[sp] = nd->front;
            cost[sp++] = (uint8_t)cf;
        }
    }
    return next == bsp->node_count ? ZS_OK : ZS_ERR_BSP; /* every node once */
}

/* a / c * 65536 rounded toward zero, |a| < 2^62, c != 0; the quotient's
 * whole part is clamped to 2^40 (an eye that far is far enough). */
static int64_t div_q16(int64_t a, int64_t c)
{
    int neg = (a < 0) != (c < 0);
    uint64_t ua = (uint64_t)abs64(a), uc = (uint64_t)abs64(c);
    uint64_t q = ua / uc, rem = ua % uc, v;
    if (q > ((uint64_t)1 << 40))
        q = (uint64_t)1 << 40;
    /* rem < uc < 2^48 after the checks in eye_position */
    v = (q << 16) + (rem << 16) / uc;
    return neg ? -(int64_t)v : (int64_t)v;
}

/* The eye in the mesh's position units (Q16), or ZS_ERR_ARGUMENT for a model
 * matrix that is not a rotation times a uniform scale. */
static zs_status eye_position(const zs_renderer *r, const zs_mat34 *model, const zs_mesh *mesh,
                              int64_t eye[3])
{
    const zs_mat34 *v = &r->cam.view;
    int64_t world[3], rel[3], s2 = 0;
    int j, k;
    /* world eye = -R^T t for the view's rotation R and translation t */
    for (j = 0; j < 3; j++) {
        int64_t s = 0;
        for (k = 0; k < 3; k++)
            s += (int64_t)v->m[k][j] * v->m[k][3];
        world[j] = -zs_asr64(s + 32768, 16);
    }
    /* the model's columns: orthogonal, of one length s (s2 = s^2, Q32) */
    for (k = 0; k < 3; k++) {
        if (model->m[k][0] >= MODEL_MAX || model->m[k][0] <= -MODEL_MAX ||
            model->m[k][1] >= MODEL_MAX || model->m[k][1] <= -MODEL_MAX ||
            model->m[k][2] >= MODEL_MAX || model->m[k][2] <= -MODEL_MAX)
            return ZS_ERR_ARGUMENT;
        s2 += (int64_t)model->m[k][0] * model->m[k][0];
    }
    if (s2 < 65536)
        return ZS_ERR_ARGUMENT;
    for (j = 0; j < 3; j++) {
        int i;
        for (i = j; i < 3; i++) {
            int64_t d = 0;
            for (k = 0; k < 3; k++)
                d += (int64_t)model->m[k][i] * model->m[k][j];
            if (abs64(i == j ? d - s2 : d) > s2 / 256)
                return ZS_ERR_ARGUMENT;
        }
    }
    for (k = 0; k < 3; k++)
        rel[k] = world[k] - model->m[k][3];
    for (j = 0; j < 3; j++) {
        /* (A^T rel / s^2) in model units, then / scale in position units */
        int64_t num = 0, em;
        for (k = 0; k < 3; k++)
            num += (int64_t)model->m[k][j] * rel[k];
        em = zs_muldiv64(num, 65536, s2, 0);
        eye[j] = div_q16(em, mesh->scale);
    }
    return ZS_OK;
}

/* Which side of node nd the eye is on: > 0 front, < 0 back, 0 in the plane. */
static int eye_side(const bsp_walk *w, const zs_bsp_node *nd)
{
    int64_t s = (int64_t)nd->n[0] * w->eye[0] + (int64_t)nd->n[1] * w->eye[1] +
                (int64_t)nd->n[2] * w->eye[2] + zs_asr64(nd->d * 65536, w->shift);
    return (s > 0) - (s < 0);
}

int zs_next_range(zs_renderer *r, uint32_t *t, uint32_t *end)
{
    bsp_walk *w = (bsp_walk *)r->priv.ranges;
    const zs_bsp_node *nodes = w->bsp->nodes;
    while (w->sp > 0) {
        uint32_t e = w->stack[--w->sp], kind = e & 3u;
        uint16_t i = (uint16_t)(e >> 2);
        const zs_bsp_node *nd = &nodes[i];
        if (kind == VISIT) {
            int side = eye_side(w, nd);
            uint16_t near_child = side >= 0 ? nd->front : nd->back;
            uint16_t far_child = side >= 0 ? nd->back : nd->front;
            unsigned kind_now = side > 0 ? RANGE_FRONT : side < 0 ? RANGE_BACK : RANGE_BOTH;
            uint32_t own = kind_now == RANGE_FRONT  ? nd->n_front
                           : kind_now == RANGE_BACK ? nd->n_back
                                                    : (uint32_t)nd->n_front + nd->n_back;
            r->stats.bsp_nodes++;
            if (kind_now == RANGE_FRONT)
                r->stats.bsp_pruned += nd->n_back;
            else if (kind_now == RANGE_BACK)
                r->stats.bsp_pruned += nd->n_front;
            /* zs_bsp_check bounded what stays pending: an empty range is not pushed */
            if (far_child != ZS_BSP_NONE)
                w->stack[w->sp++] = (uint32_t)far_child << 2;
            if (own > 0)
                w->stack[w->sp++] = ((uint32_t)i << 2) | kind_now;
            if (near_child != ZS_BSP_NONE)
                w->stack[w->sp++] = (uint32_t)near_child << 2;
            continue;
        }
        /* the node's own triangles: those facing away are never looked at */
        if (kind == RANGE_FRONT) {
            *t = nd->first;
            *end = (uint32_t)nd->first + nd->n_front;
        } else if (kind == RANGE_BACK) {
            *t = (uint32_t)nd->first + nd->n_front;
            *end = *t + nd->n_back;
        } else {
            *t = nd->first;
            *end = (uint32_t)nd->first + nd->n_front + nd->n_back;
        }
        if (*t < *end)
            return 1;
    }
    return 0;
}

zs_status zs_draw_bsp(zs_renderer *r, const zs_bsp *bsp, const zs_mat34 *model)
{
    bsp_walk w;
    zs_status st;
    int64_t m = 0;
    int k;
    if (!r || !bsp)
        return ZS_ERR_NULL;
    if (!ZS_HAS_PRIORITY)
        return ZS_ERR_MODE; /* ZS_NO_PRIORITY: zs_draw walks no ranges */
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    st = zs_bsp_check(bsp);
    if (st != ZS_OK)
        return st;
    if (bsp->mesh->scale == 0)
        return ZS_ERR_MESH;
    st = eye_position(r, model ? model : &zs_identity34, bsp->mesh, w.eye);
    if (st != ZS_OK)
        return st;
    /* shrink a far eye (the planes' d with it) so the tests fit 64 bits */
    w.shift = 0;
    for (k = 0; k < 3; k++)
        m = abs64(w.eye[k]) > m ? abs64(w.eye[k]) : m;
    while (m >= EYE_MAX) {
        m >>= 1;
        w.shift++;
    }
    for (k = 0; k < 3; k++)
        w.eye[k] = zs_asr64(w.eye[k], w.shift);
    w.bsp = bsp;
    w.sp = 0;
    w.stack[w.sp++] = 0; /* visit the root */
    r->priv.ranges = &w;
    st = zs_draw(r, bsp->mesh, model);
    r->priv.ranges = 0;
    return st;
}
