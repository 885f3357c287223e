/* SPDX-License-Identifier: MIT */
/* Homogeneous clipping: outcodes, and Sutherland-Hodgman against the near and
 * far planes and the guard band (x, y within +-guard * w). */
#include "zs_internal.h"

unsigned zs_outcode(const zs_renderer *r, int64_t xc, int64_t yc, int64_t w)
{
    unsigned oc = 0;
    int64_t gw = r->priv.guard * w;
    if (w < r->cam.near_z)
        oc |= ZS_OUT_NEAR;
    if (w > r->cam.far_z)
        oc |= ZS_OUT_FAR;
    if (xc < -gw || xc > gw || yc < -gw || yc > gw)
        oc |= ZS_OUT_GUARD;
    if (xc < -w)
        oc |= ZS_OUT_LEFT;
    if (xc > w)
        oc |= ZS_OUT_RIGHT;
    if (yc < -w)
        oc |= ZS_OUT_BOTTOM;
    if (yc > w)
        oc |= ZS_OUT_TOP;
    return oc;
}

/* Clip coordinate k: w (k = 0), xc, yc. Plane p bounds coordinate p / 2:
 * near and far bound w, the guard planes xc and yc. */
static int64_t *coord(zs_svert *v, int k)
{
    return k == 0 ? &v->w : (k == 1 ? &v->xc : &v->yc);
}

static int64_t coord_of(const zs_svert *v, int k)
{
    return k == 0 ? v->w : (k == 1 ? v->xc : v->yc);
}

/* The bound of plane p at w: plane p is coord = -bound, inside where
 * coord + bound >= 0, for even p (near, left, bottom), and coord = bound,
 * inside where bound - coord >= 0, for odd p (far, right, top). */
static ZS_NOINLINE int64_t plane_bound(const zs_renderer *r, int p, int64_t w)
{
    if (p == 0)
        return -(int64_t)r->cam.near_z;
    if (p == 1)
        return r->cam.far_z;
    return r->priv.guard * w;
}

/* Signed distance to plane p (inside when >= 0). */
static int64_t plane_dist(const zs_renderer *r, int p, const zs_svert *v)
{
    int64_t c = coord_of(v, p >> 1);
    return (p & 1 ? -c : c) + plane_bound(r, p, v->w);
}

#if ZS_HAS_PLANES_
static int32_t lerp32(int32_t a, int32_t b, int64_t t_q28)
{
    int64_t d = (int64_t)b - a;
    return (int32_t)(a + zs_asr64(d * t_q28 + ((int64_t)1 << 27), 28));
}

static uint32_t lerp_shade(uint32_t a, uint32_t b, int64_t t_q28)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s < 32; s += 8) {
        int32_t ca = (int32_t)((a >> s) & 255u), cb = (int32_t)((b >> s) & 255u);
        int32_t v = lerp32(ca, cb, t_q28);
        out |= (uint32_t)zs_clampi(v, 0, 255) << s;
    }
    return out;
}
#endif

/* v = the point where edge in -> out crosses plane p. Always interpolated
 * from the inside vertex so that two triangles sharing the edge get the
 * same point: in + (out - in) * din / (din - dout), rounded, exact whatever
 * the range of the clip coordinates (they are carried unsaturated). */
static void intersect(const zs_renderer *r, int p, const zs_svert *in, const zs_svert *out,
                      zs_svert *v)
{
    /* the distances again, rather than passed: a smaller frame for the
     * clipper, which calls this at its deepest */
    int64_t din = plane_dist(r, p, in), den = din - plane_dist(r, p, out), b; /* > 0 */
    int k;
    for (k = 0; k < 3; k++) {
        int64_t a = coord_of(in, k);
        *coord(v, k) = a + zs_muldiv64(coord_of(out, k) - a, din, den, 1);
    }
    /* put the new vertex exactly on the plane (the guard planes' bound
     * depends on its w, so that is set first) */
    b = plane_bound(r, p, v->w);
    *coord(v, p >> 1) = p & 1 ? b : -b;
#if ZS_HAS_PLANES_
    b = zs_muldiv64((int64_t)1 << 28, din, den, 0); /* the cut's parameter, Q28 */
    v->shade = lerp_shade(in->shade, out->shade, b);
    v->uv[0] = (int16_t)lerp32(in->uv[0], out->uv[0], b);
    v->uv[1] = (int16_t)lerp32(in->uv[1], out->uv[1], b);
#else /* no colour or texture planes: nothing reads shade words or uvs */
    v->shade = 0;
    v->uv[0] = v->uv[1] = 0;
#endif
    v->pool = ZS_NONE;
}

int zs_clip_polygon(const zs_renderer *r, const zs_svert *in, int n, zs_svert *out)
{
    /* planes alternate between buf and out (one scratch polygon on the
     * stack, not two: clip vertices are 32 bytes); the first plane that cuts
     * reads in and writes buf, so out may be in. Distances are recomputed
     * rather than kept, to keep this frame small. */
    zs_svert buf[9];
    const zs_svert *src = in;
    int p, i, cnt = n;
    for (p = 0; p < 6 && cnt >= 3; p++) {
        int any_out = 0;
        zs_svert *dst;
        int m = 0;
        int64_t di, dj;
        for (i = 0; i < cnt; i++)
            if (plane_dist(r, p, &src[i]) < 0)
                any_out = 1;
        if (!any_out)
            continue;
        dst = src == buf ? out : buf;
        dj = plane_dist(r, p, &src[0]);
        for (i = 0; i < cnt; i++) {
            int j = (i + 1 == cnt) ? 0 : i + 1;
            int in_i, in_j;
            di = dj;
            dj = plane_dist(r, p, &src[j]);
            in_i = di >= 0;
            in_j = dj >= 0;
            /* a polygon made slightly non-convex by rounding could be cut
             * twice by one plane: never write past the 9 slots */
            if (in_i && m < 9)
                dst[m++] = src[i];
            if (in_i != in_j && m < 9) {
                if (in_i)
                    intersect(r, p, &src[i], &src[j], &dst[m++]);
                else
                    intersect(r, p, &src[j], &src[i], &dst[m++]);
            }
        }
        src = dst;
        cnt = m;
    }
    if (cnt < 3)
        return 0;
    if (src != out)
        for (i = 0; i < cnt; i++)
            out[i] = src[i];
    return cnt;
}
