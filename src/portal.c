/* SPDX-License-Identifier: MIT */
/* Portals: check a level, find the eye's cell, walk the portals from it with
 * a shrinking screen window and submit the cells that survive
 * (include/zspan/portal.h). Draws through the public zs_draw only. */
#include "zspan/portal.h"

#include "zs_internal.h"

/* A clip window in whole pixels, [x0, x1) x [y0, y1), within the screen. */
typedef struct zs_window {
    int16_t x0, y0, x1, y1;
} zs_window;

/* One cell on the walk's path: the next portal to try and the window it
 * was entered through. */
typedef struct zs_walk_entry {
    uint16_t cell, next_portal, end_portal;
    zs_window win;
} zs_walk_entry;

static uint32_t pvs_row_bytes(const zs_level *lv)
{
    return ((uint32_t)lv->cell_count + 7u) / 8u;
}

static int bit_get(const uint8_t *row, uint32_t i)
{
    return (row[i >> 3] >> (i & 7u)) & 1;
}

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

static int coord_ok(int32_t v)
{
    return v >= -ZS_LEVEL_MAX_COORD && v <= ZS_LEVEL_MAX_COORD;
}

/* Twice the signed area of (a, b, c) in plan units: > 0 counter-clockwise. */
static int64_t cross_plan(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy)
{
    return (int64_t)(bx - ax) * (cy - ay) - (int64_t)(by - ay) * (cx - ax);
}

static zs_status check_cell(const zs_level *lv, uint32_t ci)
{
    const zs_level_cell *c = &lv->cells[ci];
    const int16_t *v;
    uint32_t n = c->vertex_count, i;
    int64_t area = 0;
    if (n < 3 || (uint32_t)c->first_vertex + n > lv->vertex_count)
        return ZS_ERR_LEVEL;
    if ((uint32_t)c->first_portal + c->portal_count > lv->portal_count)
        return ZS_ERR_LEVEL;
    if (!coord_ok(c->floor) || !coord_ok(c->ceiling) || c->floor >= c->ceiling)
        return ZS_ERR_LEVEL;
    v = lv->vertices + 2u * c->first_vertex;
    for (i = 0; i < n; i++) {
        const int16_t *p = v + 2u * i, *q = v + 2u * ((i + 1u) % n), *s = v + 2u * ((i + 2u) % n);
        if (!coord_ok(p[0]) || !coord_ok(p[1]))
            return ZS_ERR_LEVEL;
        /* convex: no corner turns clockwise (collinear points are fine) */
        if (cross_plan(p[0], p[1], q[0], q[1], s[0], s[1]) < 0)
            return ZS_ERR_LEVEL;
        area += cross_plan(v[0], v[1], p[0], p[1], q[0], q[1]);
    }
    if (area <= 0)
        return ZS_ERR_LEVEL;
    /* the walk relies on every neighbour being in the PVS */
    for (i = 0; i < c->portal_count; i++) {
        const zs_level_portal *p = &lv->portals[c->first_portal + i];
        if (p->to >= lv->cell_count || p->to == ci || p->bottom >= p->top)
            return ZS_ERR_LEVEL;
        if (!coord_ok(p->ax) || !coord_ok(p->ay) || !coord_ok(p->bx) || !coord_ok(p->by) ||
            !coord_ok(p->bottom) || !coord_ok(p->top))
            return ZS_ERR_LEVEL;
        if (!bit_get(lv->pvs + ci * pvs_row_bytes(lv), p->to))
            return ZS_ERR_LEVEL;
    }
    return ZS_OK;
}

zs_status zs_level_check(const zs_level *lv)
{
    uint32_t rb, i, j;
    if (!lv)
        return ZS_ERR_NULL;
    if (lv->cell_count == 0 || lv->cell_count > ZS_LEVEL_MAX_CELLS || lv->vertex_count < 3)
        return ZS_ERR_LEVEL;
    if (!lv->vertices || !lv->cells || !lv->pvs || !lv->meshes ||
        (lv->portal_count && !lv->portals))
        return ZS_ERR_LEVEL;
    /* every world coordinate within +-32767 units: |coord| * unit < 2^31 */
    if (lv->unit <= 0 || (int64_t)lv->unit * ZS_LEVEL_MAX_COORD >= ((int64_t)1 << 31))
        return ZS_ERR_LEVEL;
    rb = pvs_row_bytes(lv);
    for (i = 0; i < lv->cell_count; i++) {
        const uint8_t *row = lv->pvs + i * rb;
        zs_status st;
        if (!bit_get(row, i))
            return ZS_ERR_LEVEL;
        for (j = lv->cell_count; j < rb * 8u; j++)
            if (bit_get(row, j))
                return ZS_ERR_LEVEL;
        st = check_cell(lv, i);
        if (st != ZS_OK)
            return st;
        if (lv->meshes[i].scale != lv->unit)
            return ZS_ERR_LEVEL;
    }
    return ZS_OK;
}

/* The eye's plan position stays in world Q16.16: plan x = world x,
 * plan y = -world z. A plan point p (level units) is at p * unit. Signs of
 * cross products are computed with the unit divided out:
 * (b - a) x (e - a * unit), all in 64 bits (|e| < 2^31, |a * unit| < 2^31). */
static int64_t cross_eye(const zs_level *lv, int32_t ax, int32_t ay, int32_t bx, int32_t by,
                         int64_t ex, int64_t ey)
{
    int64_t dx = ex - (int64_t)ax * lv->unit, dy = ey - (int64_t)ay * lv->unit;
    return (int64_t)(bx - ax) * dy - (int64_t)(by - ay) * dx;
}

static int cell_holds(const zs_level *lv, uint32_t ci, zs_vec3 eye)
{
    const zs_level_cell *c = &lv->cells[ci];
    const int16_t *v = lv->vertices + 2u * c->first_vertex;
    uint32_t n = c->vertex_count, i;
    int64_t ex = eye.x, ey = -(int64_t)eye.z;
    if ((int64_t)eye.y < (int64_t)c->floor * lv->unit ||
        (int64_t)eye.y > (int64_t)c->ceiling * lv->unit)
        return 0;
    for (i = 0; i < n; i++) {
        const int16_t *p = v + 2u * i, *q = v + 2u * ((i + 1u) % n);
        if (cross_eye(lv, p[0], p[1], q[0], q[1], ex, ey) < 0)
            return 0;
    }
    return 1;
}

int32_t zs_level_find_cell(const zs_level *lv, zs_vec3 eye)
{
    uint32_t i;
    if (!lv || !lv->cells || !lv->vertices)
        return -1;
    for (i = 0; i < lv->cell_count; i++)
        if (cell_holds(lv, i, eye))
            return (int32_t)i;
    return -1;
}

/* Eye coordinates of a world point (Q16.16 in 64 bits). */
static void to_eye(const zs_camera *cam, const int64_t p[3], int64_t e[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        int64_t s = cam->view.m[k][3];
        int j;
        /* |m|, |p| <= 2^31: each product fits, their sum only after the shift */
        for (j = 0; j < 3; j++)
            s += zs_asr64((int64_t)cam->view.m[k][j] * p[j] + ((int64_t)1 << 15), 16);
        e[k] = s;
    }
}

/* cot(fov / 2) in Q16.16, as zs_frame_begin computes it. */
static int64_t frame_cot(const zs_renderer *r)
{
    int32_t s = zs_sin_q30(r->cam.fov_deg / 2);
    int32_t c = zs_sin_q30(r->cam.fov_deg / 2 + ZS_FX(90));
    return s > 0 ? ((int64_t)c * 65536) / s : INT32_MAX;
}

#define ZS_PROJ_LIMIT ((int64_t)1 << 30) /* 2^14 pixels in Q16 */

static int64_t clamp_proj(int64_t v)
{
    return v > ZS_PROJ_LIMIT ? ZS_PROJ_LIMIT : v < -ZS_PROJ_LIMIT ? -ZS_PROJ_LIMIT : v;
}

/* Screen position (Q16.16 pixels) of eye coordinates e with depth d >= near.
 * x = W/2 + e_x cot H / (2 d), y = H/2 - e_y cot H / (2 d) (the core's
 * projection, proj_sx = cot H / W). Each coordinate is clamped: the clamp is
 * far outside any screen, so a window built from it stays conservative. */
static void project_eye(const zs_renderer *r, int64_t cot, const int64_t e[3], int64_t d,
                        int64_t xy[2])
{
    int k;
    for (k = 0; k < 2; k++) {
        int64_t c = e[k], t;
        /* t = c * cot / d in Q16, with |c| and cot below 2^31 so the product fits */
        if (abs64(c) >= ((int64_t)1 << 31) || cot >= ((int64_t)1 << 31))
            t = c < 0 ? -ZS_PROJ_LIMIT : ZS_PROJ_LIMIT;
        else
            t = clamp_proj((c * cot) / d);
        t = (t * r->cfg.height) / 2;
        xy[k] = k == 0 ? (int64_t)r->cfg.width * 32768 + t : (int64_t)r->cfg.height * 32768 - t;
        xy[k] = clamp_proj(xy[k]);
    }
}

zs_status zs_project_point(const zs_renderer *r, zs_vec3 world, zs_fixed xy[2], zs_fixed *depth)
{
    int64_t p[3], e[3], s[2];
    if (!r || !xy || !depth)
        return ZS_ERR_NULL;
    if (r->priv.state < ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    p[0] = world.x;
    p[1] = world.y;
    p[2] = world.z;
    to_eye(&r->cam, p, e);
    *depth = zs_sat32(-e[2], 0);
    if (-e[2] < r->cam.near_z)
        return ZS_ERR_ARGUMENT;
    project_eye(r, frame_cot(r), e, -e[2], s);
    xy[0] = (zs_fixed)s[0];
    xy[1] = (zs_fixed)s[1];
    return ZS_OK;
}

/* The window through portal p given the window w it is seen through: the
 * bounding box of its projected corners plus a margin, met with w. Returns 0
 * if they do not meet. A corner nearer than the near plane leaves w as it is
 * (the portal is too close to bound on screen; keeping w is conservative). */
static int portal_window(const zs_renderer *r, const zs_level *lv, int64_t cot,
                         const zs_level_portal *p, const zs_window *w, zs_window *out)
{
    int64_t lo[2] = {INT64_MAX, INT64_MAX}, hi[2] = {INT64_MIN, INT64_MIN};
    int k;
    for (k = 0; k < 4; k++) {
        int64_t wp[3], e[3], s[2];
        int32_t px = (k & 1) ? p->bx : p->ax, py = (k & 1) ? p->by : p->ay;
        int32_t h = (k & 2) ? p->top : p->bottom;
        int j;
        wp[0] = (int64_t)px * lv->unit;
        wp[1] = (int64_t)h * lv->unit;
        wp[2] = -(int64_t)py * lv->unit;
        to_eye(&r->cam, wp, e);
        if (-e[2] < r->cam.near_z) {
            *out = *w;
            return 1;
        }
        project_eye(r, cot, e, -e[2], s);
        for (j = 0; j < 2; j++) {
            if (s[j] < lo[j])
                lo[j] = s[j];
            if (s[j] > hi[j])
                hi[j] = s[j];
        }
    }
    {
        /* |lo|, |hi| <= 2^14 pixels (clamped), so all of this fits */
        int32_t x0 = (int32_t)zs_asr64(lo[0], 16) - ZS_LEVEL_MARGIN_PX;
        int32_t y0 = (int32_t)zs_asr64(lo[1], 16) - ZS_LEVEL_MARGIN_PX;
        int32_t x1 = (int32_t)zs_asr64(hi[0], 16) + 1 + ZS_LEVEL_MARGIN_PX;
        int32_t y1 = (int32_t)zs_asr64(hi[1], 16) + 1 + ZS_LEVEL_MARGIN_PX;
        out->x0 = (int16_t)(x0 > w->x0 ? x0 : w->x0);
        out->y0 = (int16_t)(y0 > w->y0 ? y0 : w->y0);
        out->x1 = (int16_t)(x1 < w->x1 ? x1 : w->x1);
        out->y1 = (int16_t)(y1 < w->y1 ? y1 : w->y1);
    }
    return out->x0 < out->x1 && out->y0 < out->y1;
}

/* Depth-first over portal chains from the eye cell, inside its PVS, never
 * entering a cell already on the chain (a sightline crosses a convex cell
 * once). Marks the cells reached in vis. Returns 0 when it ran out of
 * budget or depth. */
static int walk(const zs_renderer *r, const zs_level *lv, uint32_t eye_cell, zs_vec3 eye,
                const uint8_t *pvs, uint8_t *vis, zs_level_stats *st)
{
    zs_walk_entry stack[ZS_LEVEL_MAX_DEPTH];
    uint32_t depth = 1;
    int64_t cot = frame_cot(r), ex = eye.x, ey = -(int64_t)eye.z;
    const zs_level_cell *c = &lv->cells[eye_cell];
    stack[0].cell = (uint16_t)eye_cell;
    stack[0].next_portal = c->first_portal;
    stack[0].end_portal = (uint16_t)(c->first_portal + c->portal_count);
    stack[0].win.x0 = 0;
    stack[0].win.y0 = 0;
    stack[0].win.x1 = (int16_t)r->cfg.width;
    stack[0].win.y1 = (int16_t)r->cfg.height;
    st->cells_visited = 1;
    while (depth > 0) {
        zs_walk_entry *top = &stack[depth - 1];
        const zs_level_portal *p;
        zs_window nw;
        uint32_t k, to;
        int on_path = 0;
        if (top->next_portal >= top->end_portal) {
            depth--;
            continue;
        }
        if (st->portals_tested >= ZS_LEVEL_WALK_BUDGET)
            return 0;
        st->portals_tested++;
        p = &lv->portals[top->next_portal++];
        to = p->to;
        if (!bit_get(pvs, to))
            continue;
        for (k = 0; k < depth; k++)
            on_path |= stack[k].cell == to;
        if (on_path)
            continue;
        /* a sightline leaves through the portal only if the eye is on the
         * cell's side of its line (on the line counts: conservative) */
        if (cross_eye(lv, p->ax, p->ay, p->bx, p->by, ex, ey) < 0)
            continue;
        if (!portal_window(r, lv, cot, p, &top->win, &nw))
            continue;
        if (depth == ZS_LEVEL_MAX_DEPTH)
            return 0;
        vis[to >> 3] = (uint8_t)(vis[to >> 3] | (1u << (to & 7u)));
        st->cells_visited++;
        c = &lv->cells[to];
        stack[depth].cell = (uint16_t)to;
        stack[depth].next_portal = c->first_portal;
        stack[depth].end_portal = (uint16_t)(c->first_portal + c->portal_count);
        stack[depth].win = nw;
        depth++;
    }
    return 1;
}

zs_status zs_level_draw(zs_renderer *r, const zs_level *lv, zs_vec3 eye, zs_level_cull cull,
                        zs_level_stats *stats)
{
    uint8_t vis[ZS_LEVEL_MAX_CELLS / 8];
    zs_level_stats local;
    zs_level_stats *st = stats ? stats : &local;
    zs_status res = ZS_OK;
    uint32_t rb, i;
    int32_t ec;
    if (!r || !lv)
        return ZS_ERR_NULL;
    if (cull != ZS_LEVEL_CULL_NONE && cull != ZS_LEVEL_CULL_PVS && cull != ZS_LEVEL_CULL_PORTALS)
        return ZS_ERR_ARGUMENT;
    res = zs_level_check(lv);
    if (res != ZS_OK)
        return res;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    memset(st, 0, sizeof *st);
    rb = pvs_row_bytes(lv);
    ec = zs_level_find_cell(lv, eye);
    st->eye_cell = ec;
    if (ec < 0 || cull == ZS_LEVEL_CULL_NONE) {
        memset(vis, 0xFF, rb);
    } else {
        const uint8_t *pvs = lv->pvs + (uint32_t)ec * rb;
        for (i = 0; i < lv->cell_count; i++)
            st->pvs_cells += (uint32_t)bit_get(pvs, i);
        if (cull == ZS_LEVEL_CULL_PVS) {
            memcpy(vis, pvs, rb);
        } else {
            memset(vis, 0, rb);
            vis[(uint32_t)ec >> 3] = (uint8_t)(1u << ((uint32_t)ec & 7u));
            if (!walk(r, lv, (uint32_t)ec, eye, pvs, vis, st)) {
                st->fallback = 1;
                memcpy(vis, pvs, rb);
            }
        }
    }
    /* in cell order, so that kept triangles keep their relative order */
    for (i = 0; i < lv->cell_count; i++) {
        const zs_mesh *m = &lv->meshes[i];
        if (!bit_get(vis, i)) {
            st->tris_culled += m->triangle_count;
            continue;
        }
        st->cells_drawn++;
        st->tris_submitted += m->triangle_count;
        if (res == ZS_OK) {
            res = zs_draw(r, m, NULL);
        }
    }
    return res;
}
