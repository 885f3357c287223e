/* SPDX-License-Identifier: MIT */
/* Texture mapping: per-vertex texture coordinates, perspective-correct
 * planes per active triangle and the textured span fill.
 *
 * Perspective: q = 1/w, s q and t q are affine in screen space, so each is
 * a plane like depth and colour; the texel coordinate at a pixel centre is
 * s = (s q) / q. 1/w comes from the window depth the vertex already has
 * (z = A (1 - near / w), so 1/w is proportional to A - z): no extra state
 * per vertex but the coordinates.
 *
 * Every pixel's value is a function of its column and row alone (planes are
 * evaluated, never stepped from where a span happens to start), so the span
 * and z-buffer modes, which cut a row into spans differently, write the same
 * bytes.
 *  - Exact, nearest: the texel index floor(S / (256 Q)) is followed along
 *    the span as an integer quotient with its remainder (as an edge's
 *    column is): adds and compares per pixel, no product, no division; one
 *    division per span to start it. Exact, so the same wherever it starts.
 *  - Exact, bilinear: one quotient per coordinate per pixel.
 *  - Subdivided (ZS_TEX_SUBDIV): the quotient at every column that is a
 *    multiple of 16, affine in between (as Quake does, but at fixed columns,
 *    so both modes agree).
 * Quotients are formed with 32-bit steps (zs_udiv64_32): no 64-bit division
 * helper. */
#include "zs_internal.h"

#define WHITE 0xFFFFFFu
#define PLANE_FRAC 16       /* fraction bits of the planes */
#define Q_TOP ((int64_t)1 << 22) /* vertex 1/w normalised below this */
#define SUBDIV_LOG2 4       /* ZS_TEX_SUBDIV: exact every 16 columns */
#define DDA_STEPS 4         /* quotient steps per pixel before dividing again */

zs_status zs_texture_check(const zs_texture *t)
{
    if (!t)
        return ZS_ERR_NULL;
    if (!t->texels || t->width == 0 || t->height == 0 || t->width > ZS_TEX_MAX_DIM ||
        t->height > ZS_TEX_MAX_DIM || (t->width & (t->width - 1u)) ||
        (t->height & (t->height - 1u)))
        return ZS_ERR_TEXTURE;
    if (t->format == ZS_TEX_PAL8) {
        if (!t->palette)
            return ZS_ERR_TEXTURE;
    } else if (t->format != ZS_TEX_RGB565) {
        return ZS_ERR_TEXTURE;
    }
    if (t->flags & ~(unsigned)(ZS_TEX_BILINEAR | ZS_TEX_CLAMP | ZS_TEX_SUBDIV))
        return ZS_ERR_TEXTURE;
    return ZS_OK;
}

zs_status zs_tex_draw(zs_renderer *r, const zs_mesh *m, uint8_t *slot)
{
    unsigned k;
    *slot = 0;
    if (!m->uvs && !m->texture)
        return ZS_OK;
    if (!r->priv.textures)
        return ZS_ERR_MODE; /* the config left ZS_CFG_TEXTURE out */
    if (!m->uvs || !m->texture || zs_texture_check(m->texture) != ZS_OK)
        return ZS_ERR_TEXTURE;
    for (k = 0; k < r->priv.n_textures; k++)
        if (r->priv.textures[k] == m->texture)
            break;
    if (k == r->priv.n_textures) {
        if (k >= ZS_MAX_FRAME_TEXTURES)
            return ZS_ERR_CAPACITY;
        if (k == 0) { /* the frame's first texture: A = far / (far - near), Q30 */
            int64_t f = r->cam.far_z, n = r->cam.near_z;
            r->priv.tex_depth_a = (f * ((int64_t)1 << 30)) / (f - n);
        }
        r->priv.textures[k] = m->texture;
        r->priv.n_textures = (uint8_t)(k + 1u);
    }
    *slot = (uint8_t)(k + 1u);
    return ZS_OK;
}

void zs_tex_vertices(zs_renderer *r, const zs_mesh *m, uint16_t base, uint32_t n, uint8_t slot)
{
    zs_tex_vert *tv = &r->priv.tex_verts[base];
    uint32_t i;
    for (i = 0; i < n; i++, tv++) {
        tv->u = slot ? m->uvs[2u * i] : 0;
        tv->v = slot ? m->uvs[2u * i + 1u] : 0;
        tv->slot = slot;
        tv->pad = 0;
    }
}

/* ---- wrapping 64-bit arithmetic (planes are exact modulo 2^64: the value
 * at a covered centre fits, whatever the products on the way) ---- */

/* a * b mod 2^64 from 32-bit products (no helper call on Cortex-M0). */
static uint64_t wmul(uint64_t a, int32_t b)
{
    uint32_t al = (uint32_t)(a & 0xFFFFFFFFu), ah = (uint32_t)(a >> 32);
    uint32_t bl = (uint32_t)b, bh = b < 0 ? 0xFFFFFFFFu : 0u;
    return zs_umul32(al, bl) + ((uint64_t)(al * bh + ah * bl) << 32);
}

/* The two's complement value of v (no implementation-defined conversion). */
static int64_t to_signed(uint64_t v)
{
    return (v >> 63) ? -(int64_t)(~v) - 1 : (int64_t)v;
}

/* A plane's value at column x of row y0 + dy. */
static uint64_t plane_at(const uint64_t p[3], int32_t x, int32_t dy)
{
    return p[0] + wmul(p[2], dy) + wmul(p[1], x);
}

static unsigned clz32(uint32_t v) /* v != 0 */
{
#if defined(__GNUC__) && __SIZEOF_INT__ == 4
    return (unsigned)__builtin_clz(v);
#elif defined(__GNUC__) && __SIZEOF_LONG__ == 4
    return (unsigned)__builtin_clzl(v);
#else
    unsigned n = 0;
    while (!(v & 0x80000000u)) {
        v <<= 1;
        n++;
    }
    return n;
#endif
}

#define QUOT_MAX ((int32_t)1 << 30)

/* floor(s / d) for d > 0 (as signed values), to within 2 and clamped to
 * +-QUOT_MAX: d is cut to 32 significant bits, then one 64/32 division in
 * 32-bit steps. */
static int32_t quot(uint64_t s, uint64_t d)
{
    int neg = (s >> 63) != 0;
    uint64_t a = neg ? (uint64_t)0 - s : s;
    uint32_t dv, nh, nl, q;
    unsigned k;
    if (d >> 32) {
        k = 32u - clz32((uint32_t)(d >> 32));
        d >>= k;
        a >>= k;
    }
    dv = (uint32_t)d;
    k = clz32(dv);
    if (k > 0) {
        if (a >> (64u - k))
            return neg ? -QUOT_MAX : QUOT_MAX;
        a <<= k;
        dv <<= k;
    }
    nh = (uint32_t)(a >> 32);
    nl = (uint32_t)(a & 0xFFFFFFFFu);
    if (nh >= dv)
        return neg ? -QUOT_MAX : QUOT_MAX;
    q = zs_udiv64_32(nh, nl, dv);
    if (q > (uint32_t)QUOT_MAX)
        q = (uint32_t)QUOT_MAX;
    return neg ? -(int32_t)q - 1 : (int32_t)q;
}

/* floor(s / d) exactly (d > 0), unless it lies beyond +-QUOT_MAX or the
 * estimate's correction needs more than a few steps (planes clamped for a
 * needle): the estimate is corrected by the remainder. */
static int32_t quot_exact(uint64_t s, uint64_t d)
{
    int32_t n = quot(s, d);
    uint64_t e = s - wmul(d, n);
    int k;
    for (k = 0; k < DDA_STEPS && to_signed(e) < 0; k++) {
        n--;
        e += d;
    }
    for (; k < DDA_STEPS && e >= d; k++) { /* e >= 0 here unless the steps ran out */
        n++;
        e -= d;
    }
    return n;
}

/* ---- set-up ---- */

/* The plane through the values p[k] at the vertices v[k]: its value at the
 * centre of column 0 of row y0, per column and per row, in 2^-PLANE_FRAC.
 * Gradients come per 1/16 pixel, so the offsets of the centres from vertex
 * 0 multiply them exactly. */
static ZS_NOINLINE void make_plane(uint64_t out[3], const int64_t p[3], const zs_vert *v[3],
                       const zs_recip *area2, int32_t y0)
{
    int32_t dx1 = (int32_t)v[1]->x - v[0]->x, dy1 = (int32_t)v[1]->y - v[0]->y;
    int32_t dx2 = (int32_t)v[2]->x - v[0]->x, dy2 = (int32_t)v[2]->y - v[0]->y;
    int64_t d1 = p[1] - p[0], d2 = p[2] - p[0]; /* |d| < 2^45, |dx|, |dy| < 2^16 */
    int64_t gx = zs_recip_muldiv(area2, d1 * dy2 - d2 * dy1, PLANE_FRAC, (int64_t)1 << 58);
    int64_t gy = zs_recip_muldiv(area2, d2 * dx1 - d1 * dx2, PLANE_FRAC, (int64_t)1 << 58);
    uint64_t ugx = (uint64_t)gx, ugy = (uint64_t)gy; /* two's complement, wrapping */
    out[0] = ((uint64_t)p[0] << PLANE_FRAC) + wmul(ugx, (int32_t)8 - v[0]->x) +
             wmul(ugy, 16 * y0 + 8 - (int32_t)v[0]->y);
    out[1] = ugx << 4;
    out[2] = ugy << 4;
}

/* Fog plane (Q8.16, wrapping), as the colour planes are made. */
static ZS_NOINLINE void fog_plane(uint32_t out[3], const uint32_t f[3], const zs_vert *v[3],
                      const zs_recip *area2, int32_t y0)
{
    int64_t dx1 = (int64_t)v[1]->x - v[0]->x, dy1 = (int64_t)v[1]->y - v[0]->y;
    int64_t dx2 = (int64_t)v[2]->x - v[0]->x, dy2 = (int64_t)v[2]->y - v[0]->y;
    int64_t c0 = (int64_t)f[0] * 65536, d1 = (int64_t)f[1] * 65536 - c0;
    int64_t d2 = (int64_t)f[2] * 65536 - c0;
    int32_t gx = (int32_t)zs_recip_muldiv(area2, d1 * dy2 - d2 * dy1, 4, (int64_t)1 << 28);
    int32_t gy = (int32_t)zs_recip_muldiv(area2, d2 * dx1 - d1 * dx2, 4, (int64_t)1 << 28);
    int64_t co = c0 + 32768 +
                 zs_asr64((int64_t)gx * ((int32_t)8 - v[0]->x) + (int64_t)gy * (16 * (int64_t)y0 + 8 - v[0]->y),
                          4);
    out[0] = (uint32_t)co;
    out[1] = (uint32_t)gx;
    out[2] = (uint32_t)gy;
}

static int32_t floor_div256(int32_t v)
{
    return zs_asr32(v, 8);
}

/* The 1/w, s/w and t/w planes (out of line: a frame of its own, off the
 * activation's deepest path). */
static ZS_NOINLINE void texture_planes(const zs_renderer *r, zs_active_tex *at, const zs_tri *t,
                                       const zs_vert *v[3], const zs_recip *area2, int32_t y)
{
    const zs_tex_vert *tv = r->priv.tex_verts;
    const zs_texture *tex = r->priv.textures[at->slot - 1u];
    int64_t q[3], p[3], qmax, A = r->priv.tex_depth_a;
    int32_t s[3], tt[3], smin, tmin;
    int k;
    /* 1/w at the vertices, scaled so that the largest is in [2^21, 2^22) */
    qmax = 1;
    for (k = 0; k < 3; k++) {
        q[k] = A - (int64_t)v[k]->z;
        if (q[k] < 1)
            q[k] = 1;
        if (q[k] > qmax)
            qmax = q[k];
    }
    {
        uint64_t m = (uint64_t)qmax;
        int bits = (m >> 32) ? 64 - (int)clz32((uint32_t)(m >> 32)) : 32 - (int)clz32((uint32_t)m);
        int sh = bits - 22; /* qmax >> sh in [2^21, 2^22) */
        for (k = 0; k < 3; k++) {
            if (sh > 0)
                q[k] = (q[k] + ((int64_t)1 << (sh - 1))) >> sh;
            else
                q[k] <<= -sh;
            if (q[k] < 1)
                q[k] = 1;
        }
        qmax = sh > 0 ? (qmax + ((int64_t)1 << (sh - 1))) >> sh : qmax << -sh;
    }
    /* texel coordinates in 1/256 texel, less whole texels (s_base) */
    for (k = 0; k < 3; k++) {
        const zs_tex_vert *w = &tv[t->v[k]];
        s[k] = zs_asr32((int32_t)w->u * (int32_t)tex->width, 4);
        tt[k] = zs_asr32((int32_t)w->v * (int32_t)tex->height, 4);
    }
    smin = s[0] < s[1] ? s[0] : s[1];
    smin = smin < s[2] ? smin : s[2];
    tmin = tt[0] < tt[1] ? tt[0] : tt[1];
    tmin = tmin < tt[2] ? tmin : tt[2];
    at->s_base = floor_div256(smin);
    at->t_base = floor_div256(tmin);
    at->s_max = at->t_max = 0;
    at->q_min_hi = (int32_t)qmax;
    for (k = 0; k < 3; k++) {
        s[k] -= 256 * at->s_base; /* [0, 2^22) */
        tt[k] -= 256 * at->t_base;
        if (s[k] > at->s_max)
            at->s_max = s[k];
        if (tt[k] > at->t_max)
            at->t_max = tt[k];
        if (q[k] < at->q_min_hi)
            at->q_min_hi = (int32_t)q[k];
    }
    if (!(tex->flags & ZS_TEX_CLAMP)) { /* repeat: only the base modulo the size */
        at->s_base &= (int32_t)tex->width - 1;
        at->t_base &= (int32_t)tex->height - 1;
    }
    make_plane(at->q, q, v, area2, y);
    for (k = 0; k < 3; k++)
        p[k] = (int64_t)s[k] * q[k];
    make_plane(at->s, p, v, area2, y);
    for (k = 0; k < 3; k++)
        p[k] = (int64_t)tt[k] * q[k];
    make_plane(at->t, p, v, area2, y);
}

/* The texture and fog planes of active triangle ai (its record textured),
 * made on its first span. */
static ZS_NOINLINE void tex_setup(const zs_renderer *r, zs_active_tex *at, uint16_t ai)
{
    const zs_active *a = &r->priv.active[ai];
    const zs_tri *t = &r->priv.tris[a->tri];
    const zs_vert *pool = r->priv.verts, *v[3];
    int32_t y = a->y0;
    zs_recip area2;
    int k;
    /* the vertices in submission order (per-vertex data follows t->v), as
     * zs_shade_setup has them; the area is negative then */
    v[0] = &pool[t->v[0]];
    v[1] = &pool[t->v[1]];
    v[2] = &pool[t->v[2]];
    zs_recip_init(&area2, zs_area2(v[0], v[1], v[2]));
    at->tri = a->tri;
    at->serial = r->priv.tex_serial;
    at->y0 = (int16_t)y;
    at->slot = r->priv.tex_verts[t->v[0]].slot;
    at->flags = 0;
    texture_planes(r, at, t, v, &area2, y);
    if (r->shade.fog.enabled) { /* fog is this stage's: geometry left it out */
        uint32_t f[3];
        for (k = 0; k < 3; k++)
            f[k] = r->priv.vshade[t->v[k]] >> 24;
        if (f[0] | f[1] | f[2]) {
            at->flags |= ZS_ATEX_FOG;
            fog_plane(at->f, f, v, &area2, y);
        }
    }
}

/* ---- the fill ---- */

/* The RGB565 colour of texel (i, j), both already in range. */
static uint32_t texel(const zs_texture *tex, uint32_t i, uint32_t j)
{
    uint32_t n = j * tex->width + i;
    if (tex->format == ZS_TEX_PAL8)
        return tex->palette[((const uint8_t *)tex->texels)[n]];
    return ((const uint16_t *)tex->texels)[n];
}

/* A texel index (texels from the base) into the texture. */
static uint32_t wrap_index(int32_t n, int32_t base, uint32_t size, int clamp)
{
    int32_t i = n + base;
    if (clamp)
        return (uint32_t)zs_clampi(i, 0, (int32_t)size - 1);
    return (uint32_t)i & (size - 1u);
}

static uint32_t expand565(uint32_t c)
{
    uint32_t r = (c >> 11) & 31u, g = (c >> 5) & 63u, b = c & 31u;
    return (((r << 3) | (r >> 2)) << 16) | (((g << 2) | (g >> 4)) << 8) | ((b << 3) | (b >> 2));
}

/* round(a * b / 255) for a, b <= 255, without a division. */
static uint32_t mul255(uint32_t a, uint32_t b)
{
    uint32_t x = a * b + 128u;
    return (x + (x >> 8)) >> 8;
}

static uint32_t chan(uint32_t acc) /* a Q8.16 plane value to 0..255 */
{
    if (acc & 0x80000000u)
        return 0;
    acc >>= 16;
    return acc > 255u ? 255u : acc;
}

/* What the fill needs besides the planes. */
typedef struct tex_span {
    const zs_texture *tex;
    const zs_active_tex *at;
    int clamp;
    /* light and fog planes, evaluated at the current column */
    uint32_t cr, cg, cb, dr, dg, db, f, df;
    uint32_t light; /* RGB888, where the planes are constant along the span */
    int light_planes, fog;
    uint32_t fog_rgb;
    uint8_t *p;
    unsigned bpp;
    zs_format fmt;
    int direct; /* unlit, unfogged RGB565 output: texels stored as they are */
} tex_span;

/* Modulates, fogs, packs and stores one texel colour; steps the colour
 * planes. */
static void put_pixel(tex_span *ts, uint32_t c565_or_rgb, int is_rgb)
{
    uint8_t *p = ts->p;
    uint32_t rgb, R, G, B;
    if (ts->direct) {
        uint32_t c = c565_or_rgb;
        if (ts->fmt == ZS_FMT_RGB565_BE) {
            p[0] = (uint8_t)(c >> 8);
            p[1] = (uint8_t)c;
        } else {
            zs_store_rgb565(p, (c >> 8) & 0xF8u, (c >> 3) & 0xFCu, (c << 3) & 0xF8u);
        }
        ts->p += 2;
        return;
    }
    rgb = is_rgb ? c565_or_rgb : expand565(c565_or_rgb);
    R = (rgb >> 16) & 255u;
    G = (rgb >> 8) & 255u;
    B = rgb & 255u;
    if (ts->light_planes) {
        R = mul255(R, chan(ts->cr));
        G = mul255(G, chan(ts->cg));
        B = mul255(B, chan(ts->cb));
        ts->cr += ts->dr;
        ts->cg += ts->dg;
        ts->cb += ts->db;
    } else if (ts->light != WHITE) {
        R = mul255(R, (ts->light >> 16) & 255u);
        G = mul255(G, (ts->light >> 8) & 255u);
        B = mul255(B, ts->light & 255u);
    }
    if (ts->fog) {
        uint32_t f = chan(ts->f);
        R = mul255(R, 255u - f) + mul255((ts->fog_rgb >> 16) & 255u, f);
        G = mul255(G, 255u - f) + mul255((ts->fog_rgb >> 8) & 255u, f);
        B = mul255(B, 255u - f) + mul255(ts->fog_rgb & 255u, f);
        R = R > 255u ? 255u : R;
        G = G > 255u ? 255u : G;
        B = B > 255u ? 255u : B;
        ts->f += ts->df;
    }
    if (ts->fmt == ZS_FMT_RGB565_BE)
        zs_store_rgb565_be(p, R, G, B);
    else if (ts->fmt == ZS_FMT_RGB565)
        zs_store_rgb565(p, R, G, B);
    else if (ts->fmt == ZS_FMT_GRAY8)
        zs_store_gray8(p, R, G, B);
    else if (ts->fmt == ZS_FMT_RGB666)
        zs_store_rgb666(p, R, G, B);
    else
        zs_store_rgb888(p, R, G, B);
    ts->p += ts->bpp;
}

/* The nearest texel at texel coordinates (s, t) in 1/256 texel from the
 * base, as RGB565. */
static uint32_t sample_nearest(const tex_span *ts, int32_t s, int32_t t)
{
    return texel(ts->tex, wrap_index(zs_asr32(s, 8), ts->at->s_base, ts->tex->width, ts->clamp),
                 wrap_index(zs_asr32(t, 8), ts->at->t_base, ts->tex->height, ts->clamp));
}

/* Bilinear: the four texels around (s, t) (1/256 texel; texel centres at
 * +128), weighted in 1/256; RGB888. */
static uint32_t sample_bilinear(const tex_span *ts, int32_t s, int32_t t)
{
    const zs_texture *tex = ts->tex;
    int32_t s0 = s - 128, t0 = t - 128;
    int32_t i = zs_asr32(s0, 8), j = zs_asr32(t0, 8);
    uint32_t fx = (uint32_t)s0 & 255u, fy = (uint32_t)t0 & 255u;
    uint32_t i0 = wrap_index(i, ts->at->s_base, tex->width, ts->clamp);
    uint32_t i1 = wrap_index(i + 1, ts->at->s_base, tex->width, ts->clamp);
    uint32_t j0 = wrap_index(j, ts->at->t_base, tex->height, ts->clamp);
    uint32_t j1 = wrap_index(j + 1, ts->at->t_base, tex->height, ts->clamp);
    uint32_t c00 = expand565(texel(tex, i0, j0)), c10 = expand565(texel(tex, i1, j0));
    uint32_t c01 = expand565(texel(tex, i0, j1)), c11 = expand565(texel(tex, i1, j1));
    uint32_t w00 = (256u - fx) * (256u - fy), w10 = fx * (256u - fy);
    uint32_t w01 = (256u - fx) * fy, w11 = fx * fy;
    uint32_t out = 0;
    int sh;
    for (sh = 0; sh < 24; sh += 8) {
        uint32_t v = ((c00 >> sh) & 255u) * w00 + ((c10 >> sh) & 255u) * w10 +
                     ((c01 >> sh) & 255u) * w01 + ((c11 >> sh) & 255u) * w11;
        out |= ((v + 32768u) >> 16) << sh;
    }
    return out;
}

/* The exact texel index along a span: n = floor(S / D) with E = S - n D in
 * [0, D) and G = dS - n dD, all modulo 2^64 (so S = E + n D is never lost). */
typedef struct dda {
    int32_t n;
    uint64_t e, g;
} dda;

static void dda_start(dda *c, uint64_t s, uint64_t ds, uint64_t d, uint64_t dd)
{
    c->n = to_signed(d) > 0 ? quot(s, d) : 0; /* d <= 0: off the triangle */
    c->e = s - wmul(d, c->n);
    c->g = ds - wmul(dd, c->n);
}

/* Brings the remainder back into [0, d) (d > 0): a few steps, else a
 * division from the S it stands for. */
static void dda_fix(dda *c, uint64_t d, uint64_t dd)
{
    int k;
    for (k = 0; k < DDA_STEPS && to_signed(c->e) < 0; k++) {
        c->n--;
        c->e += d;
        c->g += dd;
    }
    for (; k < DDA_STEPS && to_signed(c->e) >= to_signed(d); k++) {
        c->n++;
        c->e -= d;
        c->g -= dd;
    }
    if (to_signed(c->e) < 0 || to_signed(c->e) >= to_signed(d)) {
        uint64_t s = c->e + wmul(d, c->n);
        int32_t n = quot(s, d);
        c->e = s - wmul(d, n);
        c->g += wmul(dd, c->n - n);
        c->n = n;
        for (k = 0; k < DDA_STEPS && to_signed(c->e) < 0; k++) {
            c->n--;
            c->e += d;
            c->g += dd;
        }
        for (; k < DDA_STEPS && to_signed(c->e) >= to_signed(d); k++) {
            c->n++;
            c->e -= d;
            c->g -= dd;
        }
    }
}

static int32_t clamp_coord(int32_t v, int32_t max)
{
    return zs_clampi(v, 0, max);
}

/* The texel row and column of indices (ns, nt): clamped to the triangle's
 * range, repeated. */
static const uint16_t *direct_row(const zs_texture *tex, const zs_active_tex *at, int32_t nt)
{
    uint32_t j = (uint32_t)(clamp_coord(nt, at->t_max >> 8) + at->t_base) & (tex->height - 1u);
    return (const uint16_t *)tex->texels + j * tex->width;
}

static uint32_t direct_col(const zs_texture *tex, const zs_active_tex *at, int32_t ns)
{
    return (uint32_t)(clamp_coord(ns, at->s_max >> 8) + at->s_base) & (tex->width - 1u);
}

/* The common case of the exact nearest loop below (unlit, unfogged RGB565
 * texels repeated into RGB565 rows) where 1/w stays positive along the span
 * (both ends are, and it is affine): the same arithmetic with its state in
 * locals. The indices change only where a remainder leaves [0, d), so the
 * texel row and column are found there and a pixel is a fetch and a store.
 * n > 0 pixels from p; 0 if 1/w is not positive at both ends (the caller
 * takes the general loop). */
static int nearest_direct(const zs_texture *tex, const zs_active_tex *at, uint8_t *p, int be,
                          int n, dda *cs, dda *ct, uint64_t d, uint64_t dd)
{
    uint64_t es, gs, et, gt;
    const uint16_t *row;
    uint32_t i;
    if (!(to_signed(d) > 0 && to_signed(d + wmul(dd, n - 1)) > 0))
        return 0;
    if (cs->e >= d)
        dda_fix(cs, d, dd);
    if (ct->e >= d)
        dda_fix(ct, d, dd);
    es = cs->e;
    gs = cs->g;
    et = ct->e;
    gt = ct->g;
    i = direct_col(tex, at, cs->n);
    row = direct_row(tex, at, ct->n);
    for (;;) {
        uint32_t c = row[i];
        if (be) {
            p[0] = (uint8_t)(c >> 8);
            p[1] = (uint8_t)c;
        } else {
            union {
                uint16_t v;
                uint8_t b[2];
            } u; /* the host's byte order */
            u.v = (uint16_t)c;
            p[0] = u.b[0];
            p[1] = u.b[1];
        }
        if (--n == 0)
            return 1;
        p += 2;
        es += gs;
        et += gt;
        d += dd;
        if (es >= d) { /* unsigned: below zero or at least d */
            cs->e = es;
            cs->g = gs;
            dda_fix(cs, d, dd);
            es = cs->e;
            gs = cs->g;
            i = direct_col(tex, at, cs->n);
        }
        if (et >= d) {
            ct->e = et;
            ct->g = gt;
            dda_fix(ct, d, dd);
            et = ct->e;
            gt = ct->g;
            row = direct_row(tex, at, ct->n);
        }
    }
}

/* 1/w at column x (plane units), no less than the triangle's least; *low
 * set where it was less (off the triangle, toward its horizon). */
static uint64_t q_at(const zs_active_tex *at, int32_t x, int32_t dy, int *low)
{
    uint64_t q = plane_at(at->q, x, dy);
    int64_t qmin = (int64_t)at->q_min_hi << PLANE_FRAC;
    *low = to_signed(q) < qmin;
    return *low ? (uint64_t)qmin : q;
}

/* Texel coordinates (1/256 texel from the base) at column x, exact and
 * clamped to the triangle's range. */
static void coords_at(const zs_active_tex *at, int32_t x, int32_t dy, int32_t *s, int32_t *t)
{
    int low;
    uint64_t q = q_at(at, x, dy, &low);
    *s = clamp_coord(quot_exact(plane_at(at->s, x, dy), q), at->s_max);
    *t = clamp_coord(quot_exact(plane_at(at->t, x, dy), q), at->t_max);
}

/* The same at a subdivision column, not clamped (the column may lie off
 * the triangle; the affine steps between two of them are clamped per
 * pixel); *q: 1/w there (plane units >> 16), 0 where it is below the
 * triangle's least (toward the horizon of its plane). */
static void subdiv_at(const zs_active_tex *at, int32_t x, int32_t dy, int32_t *s, int32_t *t,
                      int32_t *qh)
{
    int low;
    uint64_t q = q_at(at, x, dy, &low);
    *s = zs_clampi(quot_exact(plane_at(at->s, x, dy), q), -((int32_t)1 << 24), (int32_t)1 << 24);
    *t = zs_clampi(quot_exact(plane_at(at->t, x, dy), q), -((int32_t)1 << 24), (int32_t)1 << 24);
    *qh = low ? 0 : (int32_t)(q >> PLANE_FRAC); /* <= 2^23 */
}

/* May the segment between two subdivision columns be affine? Between
 * exact values at its ends, the perspective parameter strays from the
 * affine one by at most |qb - qa| / (4 min(qa, qb)) of the way ((sqrt(r) -
 * 1) / (sqrt(r) + 1) <= (r - 1) / 4 for the ratio r >= 1 of the two), so
 * the coordinate by at most |ds| |qb - qa| / (4 min): affine where that is
 * within SUBDIV_ERROR (1/256 texel), else exact per pixel. */
#define SUBDIV_ERROR 64 /* a quarter of a texel */
static int affine_ok(int32_t ds, int32_t dt, int32_t qa, int32_t qb)
{
    int32_t d = ds < 0 ? -ds : ds, e = dt < 0 ? -dt : dt, dq = qb - qa;
    if (qa == 0 || qb == 0)
        return 0;
    if (e > d)
        d = e;
    return zs_smul32(d, dq < 0 ? -dq : dq) <=
           zs_smul32(4 * SUBDIV_ERROR, qa < qb ? qa : qb);
}

void zs_fill_textured(const zs_renderer *r, uint16_t ai, int32_t y, uint8_t *row, int x0,
                      int x1)
{
    zs_active_tex *at = &r->priv.atex[ai];
    const zs_active *act = &r->priv.active[ai];
    const zs_active_color *ac = &r->priv.acolor[ai];
    tex_span ts;
    int32_t dy, x, cdy = y - act->y0;
    int bilinear;
    if (at->tri != act->tri || at->serial != r->priv.tex_serial || at->y0 != act->y0)
        tex_setup(r, at, ai);
    dy = y - at->y0;
    ts.at = at;
    ts.tex = r->priv.textures[at->slot - 1u];
    ts.clamp = (ts.tex->flags & ZS_TEX_CLAMP) != 0;
    ts.bpp = r->priv.bpp;
    ts.fmt = r->shade.format;
    ts.p = row + (size_t)x0 * ts.bpp;
    ts.fog = (at->flags & ZS_ATEX_FOG) != 0;
    ts.fog_rgb = r->shade.fog.color;
    /* the light's planes as zs_fill_gouraud steps them (wrapping products) */
    ts.cr = ac->crow[0] + (uint32_t)ac->cdy[0] * (uint32_t)cdy + (uint32_t)ac->cdx[0] * (uint32_t)x0;
    ts.cg = ac->crow[1] + (uint32_t)ac->cdy[1] * (uint32_t)cdy + (uint32_t)ac->cdx[1] * (uint32_t)x0;
    ts.cb = ac->crow[2] + (uint32_t)ac->cdy[2] * (uint32_t)cdy + (uint32_t)ac->cdx[2] * (uint32_t)x0;
    ts.dr = (uint32_t)ac->cdx[0];
    ts.dg = (uint32_t)ac->cdx[1];
    ts.db = (uint32_t)ac->cdx[2];
    /* constant along the span: the light of its first pixel, not stepped */
    ts.light_planes = (ts.dr | ts.dg | ts.db) != 0;
    ts.light = (chan(ts.cr) << 16) | (chan(ts.cg) << 8) | chan(ts.cb);
    bilinear = (ts.tex->flags & ZS_TEX_BILINEAR) != 0;
    ts.direct = !bilinear && !ts.light_planes && !ts.fog && ts.light == WHITE &&
                (ts.fmt == ZS_FMT_RGB565_BE || ts.fmt == ZS_FMT_RGB565);
    ts.f = ts.df = 0;
    if (ts.fog) {
        ts.f = at->f[0] + (uint32_t)at->f[2] * (uint32_t)dy + (uint32_t)at->f[1] * (uint32_t)x0;
        ts.df = at->f[1];
    }
    if (ts.tex->flags & ZS_TEX_SUBDIV) {
        /* exact at multiples of 16, affine between */
        int32_t xa = x0 & ~((1 << SUBDIV_LOG2) - 1);
        int32_t sa, ta, sb, tb, qa, qb;
        subdiv_at(at, xa, dy, &sa, &ta, &qa);
        for (x = x0; x < x1;) {
            int32_t xb = xa + (1 << SUBDIV_LOG2), end = xb < x1 ? xb : x1;
            int32_t ss, st, j = x - xa;
            int affine;
            subdiv_at(at, xb, dy, &sb, &tb, &qb);
            affine = affine_ok(sb - sa, tb - ta, qa, qb);
            ss = sa * (1 << SUBDIV_LOG2) + (sb - sa) * j;
            st = ta * (1 << SUBDIV_LOG2) + (tb - ta) * j;
            for (; x < end; x++) {
                int32_t s, t;
                if (affine) {
                    s = clamp_coord(zs_asr32(ss, SUBDIV_LOG2), at->s_max);
                    t = clamp_coord(zs_asr32(st, SUBDIV_LOG2), at->t_max);
                } else { /* strong perspective or the horizon near: exact */
                    coords_at(at, x, dy, &s, &t);
                }
                if (bilinear)
                    put_pixel(&ts, sample_bilinear(&ts, s, t), 1);
                else
                    put_pixel(&ts, sample_nearest(&ts, s, t), 0);
                ss += sb - sa;
                st += tb - ta;
            }
            xa = xb;
            sa = sb;
            ta = tb;
            qa = qb;
        }
    } else if (bilinear) {
        for (x = x0; x < x1; x++) {
            int32_t s, t;
            coords_at(at, x, dy, &s, &t);
            put_pixel(&ts, sample_bilinear(&ts, s, t), 1);
        }
    } else {
        /* the texel index itself: floor(S / (256 Q)) */
        uint64_t d = plane_at(at->q, x0, dy) << 8, dd = at->q[1] << 8;
        uint64_t s0 = plane_at(at->s, x0, dy), t0 = plane_at(at->t, x0, dy);
        int32_t nmax_s = at->s_max >> 8, nmax_t = at->t_max >> 8;
        dda cs, ct;
        dda_start(&cs, s0, at->s[1], d, dd);
        dda_start(&ct, t0, at->t[1], d, dd);
        if (ts.direct && ts.tex->format == ZS_TEX_RGB565 && !ts.clamp && x1 > x0 &&
            nearest_direct(ts.tex, at, ts.p, ts.fmt == ZS_FMT_RGB565_BE, x1 - x0, &cs, &ct, d, dd))
            return;
        for (x = x0; x < x1; x++) {
            int32_t ns = 0, nt = 0;
            if (to_signed(d) > 0) {
                if (cs.e >= d) /* unsigned: below zero or at least d */
                    dda_fix(&cs, d, dd);
                if (ct.e >= d)
                    dda_fix(&ct, d, dd);
                ns = cs.n;
                nt = ct.n;
            }
            put_pixel(&ts,
                      texel(ts.tex, wrap_index(clamp_coord(ns, nmax_s), at->s_base, ts.tex->width, ts.clamp),
                            wrap_index(clamp_coord(nt, nmax_t), at->t_base, ts.tex->height, ts.clamp)),
                      0);
            cs.e += cs.g;
            ct.e += ct.g;
            d += dd;
        }
    }
}
