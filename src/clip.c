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

/* Signed distance to plane p (inside when >= 0). */
static int64_t plane_dist(const zs_renderer *r, int p, const zs_svert *v)
{
    int64_t gw = r->priv.guard * v->w;
    switch (p) {
    case 0: return v->w - r->cam.near_z;
    case 1: return r->cam.far_z - v->w;
    case 2: return gw + v->xc;
    case 3: return gw - v->xc;
    case 4: return gw + v->yc;
    default: return gw - v->yc;
    }
}

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

/* in + (out - in) * din / (din - dout), rounded: exact whatever the range
 * of the clip coordinates (they are carried unsaturated). */
static int64_t lerp64(int64_t in, int64_t out, int64_t din, int64_t den)
{
    return in + zs_muldiv64(out - in, din, den, 1);
}

/* The point where edge in -> out crosses plane p. Always interpolated from
 * the inside vertex so that two triangles sharing the edge get the same point. */
static zs_svert intersect(const zs_renderer *r, int p, const zs_svert *in, const zs_svert *out,
                          int64_t din, int64_t dout)
{
    zs_svert v;
    int64_t den = din - dout; /* din >= 0 > dout */
    v.xc = lerp64(in->xc, out->xc, din, den);
    v.yc = lerp64(in->yc, out->yc, din, den);
    v.w = lerp64(in->w, out->w, din, den);
    v.shade = lerp_shade(in->shade, out->shade, zs_muldiv64((int64_t)1 << 28, din, den, 0));
    v.pool = ZS_NONE;
    /* put the new vertex exactly on the plane */
    switch (p) {
    case 0: v.w = r->cam.near_z; break;
    case 1: v.w = r->cam.far_z; break;
    case 2: v.xc = -r->priv.guard * v.w; break;
    case 3: v.xc = r->priv.guard * v.w; break;
    case 4: v.yc = -r->priv.guard * v.w; break;
    default: v.yc = r->priv.guard * v.w; break;
    }
    return v;
}

int zs_clip_polygon(const zs_renderer *r, const zs_svert *in, int n, zs_svert *out)
{
    /* planes alternate between buf and out (one scratch polygon on the
     * stack, not two: clip vertices are 32 bytes); the first plane that cuts
     * reads in and writes buf, so out may be in */
    zs_svert buf[9];
    const zs_svert *src = in;
    int p, i, cnt = n;
    for (p = 0; p < 6 && cnt >= 3; p++) {
        int64_t d[9];
        int any_out = 0;
        zs_svert *dst;
        int m = 0;
        for (i = 0; i < cnt; i++) {
            d[i] = plane_dist(r, p, &src[i]);
            if (d[i] < 0)
                any_out = 1;
        }
        if (!any_out)
            continue;
        dst = src == buf ? out : buf;
        for (i = 0; i < cnt; i++) {
            int j = (i + 1 == cnt) ? 0 : i + 1;
            int in_i = d[i] >= 0, in_j = d[j] >= 0;
            /* a polygon made slightly non-convex by rounding could be cut
             * twice by one plane: never write past the 9 slots */
            if (in_i && m < 9)
                dst[m++] = src[i];
            if (in_i != in_j && m < 9) {
                if (in_i)
                    dst[m++] = intersect(r, p, &src[i], &src[j], d[i], d[j]);
                else
                    dst[m++] = intersect(r, p, &src[j], &src[i], d[j], d[i]);
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
