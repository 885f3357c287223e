/* SPDX-License-Identifier: MIT */
/* The renderer context: configuration, arena layout, frame life cycle and
 * the band API. */
#include "zs_centre.h"
#include "zs_mono.h"

zs_config zs_config_default(uint16_t width, uint16_t height, uint16_t max_triangles,
                            uint16_t max_vertices, uint16_t max_active_edges)
{
    zs_config c;
    c.width = width;
    c.height = height;
    c.max_triangles = max_triangles;
    c.max_vertices = max_vertices;
    c.max_active_edges = max_active_edges;
    c.flags = 0;
    return c;
}

static zs_status check_config(const zs_config *c)
{
    if (!c)
        return ZS_ERR_NULL;
    if (c->width == 0 || c->height == 0 || c->width > ZS_MAX_DIM || c->height > ZS_MAX_DIM)
        return ZS_ERR_SIZE;
    if (c->max_triangles == 0 || c->max_vertices == 0 || c->max_active_edges < 2 ||
        c->max_active_edges > ZS_MAX_ACTIVE_EDGES)
        return ZS_ERR_CAPACITY;
    if (!ZS_CFG_FLAGS_OK(c->flags))
        return ZS_ERR_ARGUMENT;
    return ZS_OK;
}

#if SIZE_MAX < 0xFFFFFFFFu
/* ZS_ARENA_BYTES_CFG in 32 bits: with a 16-bit size_t (AVR) the figure of a
 * large configuration would wrap to a small one. */
static uint32_t arena_bytes32(const zs_config *c)
{
    return ZS_ARENA_BYTES_T_(uint32_t, c->width, c->height, c->max_triangles, c->max_vertices,
                             c->max_active_edges, c->flags);
}
#endif

size_t zs_arena_bytes(const zs_config *cfg)
{
    if (check_config(cfg) != ZS_OK)
        return 0;
#if SIZE_MAX < 0xFFFFFFFFu
    if (arena_bytes32(cfg) > SIZE_MAX)
        return 0; /* more than the address space: reported as a capacity error */
#endif
    /* flags & ZS_CFG_BUILT: the same (checked above), and the left-out terms fold away */
    return ZS_ARENA_BYTES_CFG(cfg->width, cfg->height, cfg->max_triangles, cfg->max_vertices,
                              cfg->max_active_edges, cfg->flags & ZS_CFG_BUILT);
}

/* Built with -DZS_NO_MONO the 1-bit stages (mono.c, lines.c) are never
 * called, so a firmware link leaves them out (about 2.6 KB on Cortex-M0);
 * the 1-bit formats are then unknown (ZS_ERR_FORMAT). */
#ifdef ZS_NO_MONO
#define MONO_BUILT(f) ((void)(f), 0)
#else
#define MONO_BUILT(f) (zs_format_is_mono(f) || (f) == ZS_FMT_GRAY4)
#endif

/* Takes n bytes (rounded up to 8) from the cursor. */
static void *carve(uint8_t **cursor, size_t n)
{
    void *p = *cursor;
    *cursor += ZS_ROUND8_(n);
    return p;
}

/* The default shading (zs_shade_default) and its pixel size. */
static ZS_NOINLINE void reset_shading(zs_renderer *r)
{
    r->shade = zs_shade_default();
    r->priv.bpp = (uint8_t)zs_format_bytes(r->shade.format);
    r->priv.out_format = (uint8_t)r->shade.format;
    r->priv.rows_kind =
        ZS_HAS_WARNOCK && r->priv.mode == ZS_MODE_WARNOCK ? ZS_ROWS_AREA : ZS_ROWS_BYTES;
}

zs_status zs_init(zs_renderer *r, void *arena, size_t arena_size, const zs_config *cfg)
{
    zs_status st;
    uint8_t *cur;
    size_t need, e, a;
    int flat = (cfg && (cfg->flags & ZS_CFG_FLAT_ONLY)) != 0;
    unsigned dim;
    if (!r || !arena || !cfg)
        return ZS_ERR_NULL;
    st = check_config(cfg);
    if (st != ZS_OK)
        return st;
    need = zs_arena_bytes(cfg);
    if (need == 0)
        return ZS_ERR_CAPACITY; /* the arena would not fit the address space */
    if (arena_size < need)
        return ZS_ERR_ARENA_SMALL;
    memset(r, 0, sizeof *r);
    r->cfg = *cfg;
    e = cfg->max_active_edges;
    a = e / 2u;
    cur = arena;
    cur += (ZS_ARENA_ALIGN - ((uintptr_t)cur & (ZS_ARENA_ALIGN - 1u))) & (ZS_ARENA_ALIGN - 1u);
    r->priv.verts = carve(&cur, (size_t)cfg->max_vertices * sizeof(zs_vert));
    /* textured triangles are set up through the per-vertex shade path */
    r->priv.vshade = flat && !(cfg->flags & ZS_CFG_TEXTURE) ? 0 : carve(&cur, (size_t)cfg->max_vertices * 4u);
    r->priv.tris = carve(&cur, (size_t)cfg->max_triangles * sizeof(zs_tri));
    r->priv.buckets = carve(&cur, (size_t)cfg->height * 2u);
    r->priv.edges = carve(&cur, e * sizeof(zs_edge));
    r->priv.ael = carve(&cur, e * 2u);
    r->priv.edge_free = carve(&cur, e * 2u);
    r->priv.active = carve(&cur, a * sizeof(zs_active));
    r->priv.aplane =
        (cfg->flags & ZS_CFG_PRIORITY_ONLY) ? 0 : carve(&cur, a * sizeof(zs_active_plane));
    /* textured fills are reached through the colour planes' fill */
    r->priv.acolor = flat && !(cfg->flags & ZS_CFG_TEXTURE) ? 0 : carve(&cur, a * sizeof(zs_active_color));
    r->priv.in_set = carve(&cur, a * 2u);
    r->priv.active_free = carve(&cur, a * 2u);
    if (!(cfg->flags & ZS_CFG_NO_ZLINE)) {
        /* span mode sorts edges here: 2 keys a pixel (zline mode keeps
         * owners only, not depths) */
        r->priv.sort_keys = carve(&cur, (size_t)cfg->width * 8u);
        /* one owner a column and two slots past the last: a sentinel and the
         * other half of the word holding it (zline.c reads owners in pairs) */
        r->priv.zline_owner = carve(&cur, (size_t)cfg->width * 2u + 4u);
    }
    if (ZS_HAS_MONO && (cfg->flags & ZS_CFG_MONO)) {
        r->priv.mono_grey = carve(&cur, cfg->width);
        r->priv.mono_err = carve(&cur, (size_t)cfg->width * 2u);
    }
    if (ZS_HAS_MONO && (cfg->flags & ZS_CFG_LINES)) {
        if (!r->priv.mono_grey)
            r->priv.mono_grey = carve(&cur, cfg->width);
        r->priv.line_ids[0] = carve(&cur, (size_t)cfg->width * 2u);
        r->priv.line_ids[1] = carve(&cur, (size_t)cfg->width * 2u);
        /* the diffusion line is idle in a hidden-line frame */
        r->priv.line_pending =
            r->priv.mono_err ? (uint8_t *)r->priv.mono_err : carve(&cur, cfg->width);
        r->priv.tri_normal = carve(&cur, (size_t)cfg->max_triangles * ZS_TRI_NORMAL_BYTES);
        r->priv.draw_starts = carve(&cur, ((size_t)cfg->max_triangles + 7u) / 8u);
        r->priv.line_next_rec = carve(&cur, (size_t)cfg->max_triangles * 6u);
        r->priv.line_vert_head = carve(&cur, (size_t)cfg->max_vertices * 2u);
    }
    if (ZS_HAS_PRIORITY && (cfg->flags & ZS_CFG_PRIORITY)) {
        r->priv.sort_list = carve(&cur, (size_t)cfg->max_triangles * 2u);
        r->priv.sort_aux = carve(&cur, (size_t)cfg->max_triangles * 2u);
    }
    if (ZS_HAS_TEXTURE && (cfg->flags & ZS_CFG_TEXTURE)) {
        r->priv.tex_verts = carve(&cur, (size_t)cfg->max_vertices * sizeof(zs_tex_vert));
        r->priv.atex = carve(&cur, a * sizeof(zs_active_tex));
        memset(r->priv.atex, 0, a * sizeof(zs_active_tex)); /* serial 0: made in no frame */
        r->priv.textures = carve(&cur, ZS_MAX_FRAME_TEXTURES * sizeof(void *));
    }
    if (ZS_HAS_ABUFFER && (cfg->flags & ZS_CFG_ABUFFER))
        r->priv.aa = zs_abuffer_carve(r, &cur);
    /* the widest guard band whose projected 28.4 coordinates fit int16 */
    dim = cfg->width > cfg->height ? cfg->width : cfg->height;
    r->priv.guard = (int32_t)(32767u / (8u * dim)) - 1;
    if (r->priv.guard > ZS_GUARD_MAX)
        r->priv.guard = ZS_GUARD_MAX;
    reset_shading(r);
    r->priv.state = ZS_STATE_READY;
    return ZS_OK;
}

zs_shade_params zs_shade_default(void)
{
    zs_shade_params p;
    memset(&p, 0, sizeof p);
    p.shading = ZS_SHADE_FLAT;
    p.format = ZS_FMT_RGB565_BE;
    p.background = 0;
    p.ambient = ZS_FX_ONE;
    return p;
}

zs_status zs_frame_begin(zs_renderer *r, const zs_camera *cam, zs_visibility mode)
{
    int32_t s, c;
    int64_t cot;
    if (!r || !cam)
        return ZS_ERR_NULL;
    if (r->priv.state == ZS_STATE_NONE)
        return ZS_ERR_STATE;
    if (mode != ZS_MODE_SPAN && mode != ZS_MODE_ZLINE && mode != ZS_MODE_WARNOCK &&
        mode != ZS_MODE_PRIORITY)
        return ZS_ERR_MODE;
    if (mode == ZS_MODE_ZLINE && (!ZS_HAS_ZLINE || (r->cfg.flags & ZS_CFG_NO_ZLINE)))
        return ZS_ERR_MODE;
    if ((mode == ZS_MODE_WARNOCK && !ZS_HAS_WARNOCK) ||
        (mode == ZS_MODE_PRIORITY && !ZS_HAS_PRIORITY))
        return ZS_ERR_MODE; /* left out of this build (ZS_NO_WARNOCK, ZS_NO_PRIORITY) */
    if (mode != ZS_MODE_PRIORITY && (r->cfg.flags & ZS_CFG_PRIORITY_ONLY))
        return ZS_ERR_MODE; /* no depth planes */
    if (cam->has_view != 1 || cam->has_projection != 1)
        return ZS_ERR_CAMERA;
    if (cam->fov_deg <= 0 || cam->fov_deg >= ZS_FX(180))
        return ZS_ERR_FOV;
    if (cam->near_z <= 0 || cam->far_z <= cam->near_z)
        return ZS_ERR_DEPTH_RANGE;
    s = zs_sin_q30(cam->fov_deg / 2);
    c = zs_sin_q30(cam->fov_deg / 2 + ZS_FX(90));
    if (s <= 0)
        return ZS_ERR_FOV;
    cot = ((int64_t)c * 65536) / s;
    if (cot > INT32_MAX / 2 || (cot * r->cfg.height) / r->cfg.width > INT32_MAX / 2)
        return ZS_ERR_FOV;
    r->cam = *cam;
    r->priv.mode = (uint8_t)mode;
    r->priv.proj_sy = (zs_fixed)cot;
    r->priv.proj_sx = (zs_fixed)((cot * r->cfg.height) / r->cfg.width);
    {
        int64_t f = cam->far_z, n = cam->near_z;
        r->priv.depth_scale = f < 8 * (f - n) ? (f * ((int64_t)1 << 30)) / (f - n) : 0;
    }
    memset(&r->stats, 0, sizeof r->stats);
    r->priv.n_textures = 0;
    r->priv.tex_serial++;
    reset_shading(r);
    r->priv.n_verts = 0;
    r->priv.n_tris = 0;
    r->priv.tag_counter = 0;
    r->priv.next_row = 0;
    r->priv.tall_rows = 0xFFFFu; /* counted when Warnock mode or zs_pick needs it */
    r->priv.line_next = 0;
    r->priv.line_keep = 0;
    if (ZS_HAS_ABUFFER)
        zs_abuffer_frame(r);
    memset(r->priv.buckets, 0xFF, (size_t)r->cfg.height * 2u);
    if (ZS_HAS_MONO && r->priv.draw_starts)
        memset(r->priv.draw_starts, 0, ((size_t)r->cfg.max_triangles + 7u) / 8u);
    r->priv.state = ZS_STATE_OPEN;
    return ZS_OK;
}

zs_status zs_frame_shading(zs_renderer *r, const zs_shade_params *p)
{
    zs_vec3 dirs[ZS_MAX_LIGHTS];
    int i;
    if (!r || !p)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN || r->priv.tag_counter != 0)
        return ZS_ERR_STATE;
    if (p->shading != ZS_SHADE_FLAT && p->shading != ZS_SHADE_GOURAUD)
        return ZS_ERR_MODE;
    if ((!ZS_HAS_GOURAUD || (r->cfg.flags & ZS_CFG_FLAT_ONLY)) &&
        (p->shading != ZS_SHADE_FLAT || p->fog.enabled))
        return ZS_ERR_MODE;
    if ((unsigned)p->format >= (unsigned)ZS_FMT_COUNT && !MONO_BUILT(p->format))
        return ZS_ERR_FORMAT;
    if (!ZS_HAS_FORMATS && (unsigned)p->format < (unsigned)ZS_FMT_COUNT &&
        p->format != ZS_FMT_RGB565_BE && p->format != ZS_FMT_RGB565)
        return ZS_ERR_FORMAT; /* ZS_RGB565_ONLY */
    if (zs_format_is_mono(p->format)) {
        if (p->mono & ~(unsigned)(ZS_MONO_DIFFUSE | ZS_MONO_LINES | ZS_MONO_INVERT) ||
            p->crease_deg >= 180)
            return ZS_ERR_ARGUMENT;
        if ((p->mono & ZS_MONO_LINES) ? !(r->cfg.flags & ZS_CFG_LINES)
                                      : !(r->cfg.flags & ZS_CFG_MONO))
            return ZS_ERR_MODE;
    }
    if (p->format == ZS_FMT_GRAY4) { /* gray4.c: the grey scratch line of ZS_CFG_MONO */
        if (p->mono & ~(unsigned)(ZS_GRAY4_DITHER | ZS_MONO_INVERT))
            return ZS_ERR_ARGUMENT;
        if (!(r->cfg.flags & ZS_CFG_MONO))
            return ZS_ERR_MODE;
    }
    if (p->light_count > ZS_MAX_LIGHTS || p->ambient < 0 ||
        (p->fog.enabled && p->fog.end <= p->fog.start) || p->background > 0xFFFFFFu ||
        p->fog.color > 0xFFFFFFu)
        return ZS_ERR_ARGUMENT;
    if (!ZS_HAS_LIGHTING && (p->light_count != 0 || p->ambient != ZS_FX_ONE))
        return ZS_ERR_MODE; /* ZS_NO_LIGHTING */
    for (i = 0; ZS_HAS_LIGHTING && i < p->light_count; i++) {
        int64_t d[3];
        int32_t u[3];
        if (p->lights[i].intensity < 0)
            return ZS_ERR_ARGUMENT;
        d[0] = p->lights[i].direction.x;
        d[1] = p->lights[i].direction.y;
        d[2] = p->lights[i].direction.z;
        if (!zs_normalize3(d, u))
            return ZS_ERR_ARGUMENT;
        dirs[i] = zs_vec3_make(u[0], u[1], u[2]);
    }
    /* a refused call changes nothing: commit only now */
    for (i = 0; ZS_HAS_LIGHTING && i < p->light_count; i++)
        r->priv.light_dir[i] = dirs[i];
    r->shade = *p;
    r->priv.out_format = (uint8_t)p->format;
    r->priv.line_keep = (uint8_t)(zs_format_is_mono(p->format) && (p->mono & ZS_MONO_LINES));
    if (zs_format_is_mono(p->format)) /* the stages render a scratch line */
        r->shade.format = (p->mono & ZS_MONO_LINES) ? ZS_FMT_ID16 : ZS_FMT_GRAY8;
    else if (p->format == ZS_FMT_GRAY4)
        r->shade.format = ZS_FMT_GRAY8;
    r->priv.bpp = (uint8_t)zs_format_bytes(r->shade.format);
    r->priv.rows_kind = (zs_format_is_mono(p->format) || p->format == ZS_FMT_GRAY4)
                            ? ZS_ROWS_MONO /* a scratch line, then packed */
                        : ZS_HAS_WARNOCK && r->priv.mode == ZS_MODE_WARNOCK ? ZS_ROWS_AREA
                                                          : ZS_ROWS_BYTES;
    return ZS_OK;
}

#ifndef ZS_NO_MONO
/* One row of visibility: the row machinery, or area subdivision. */
void zs_visible_row(zs_renderer *r, int y, uint8_t *row)
{
    if (ZS_HAS_WARNOCK && r->priv.mode == ZS_MODE_WARNOCK)
        zs_warnock_rows(r, y, 1, row, 0);
    else
        zs_raster_row(r, y, row);
}
#endif

/* One row of a 1-bit (or GRAY4) frame: the scratch line, then dithered and packed. */
static void mono_row(zs_renderer *r, int y, uint8_t *out)
{
#ifdef ZS_NO_MONO
    (void)r;
    (void)y;
    (void)out;
#else
    uint8_t *grey = r->priv.mono_grey;
    if (r->priv.out_format == ZS_FMT_GRAY4) {
        zs_visible_row(r, y, grey);
        if (ZS_HAS_ABUFFER && r->priv.aa_mode)
            zs_abuffer_row(r, y, grey);
        zs_gray4_row(r, y, grey, out);
        return;
    }
    if (r->shade.mono & ZS_MONO_LINES) {
        zs_lines_row(r, y, grey); /* renders the rows it needs */
    } else {
        zs_visible_row(r, y, grey);
        if (ZS_HAS_ABUFFER && r->priv.aa_mode) /* span mode only */
            zs_abuffer_row(r, y, grey);
    }
    zs_mono_row(r, y, grey, out);
#endif
}

zs_status zs_render_rows(zs_renderer *r, int y0, int rows, void *buf, size_t stride)
{
    int y, kind;
    size_t need, units;
    if (!r || !buf)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_OPEN && r->priv.state != ZS_STATE_RENDERING)
        return ZS_ERR_STATE;
    if (rows < 1 || y0 < r->priv.next_row || y0 >= (int)r->cfg.height ||
        rows > (int)r->cfg.height - y0)
        return ZS_ERR_ROW;
    /* byte formats first: the common call costs no more than before */
    kind = r->priv.rows_kind; /* per frame: byte rows, 1-bit rows, or Warnock */
    if (!ZS_HAS_MONO || kind != ZS_ROWS_MONO) {
        need = (size_t)r->cfg.width * r->priv.bpp;
        units = (size_t)rows;
    } else {
        need = zs_format_stride((zs_format)r->priv.out_format, r->cfg.width);
        /* rows of the buffer: pages for the page layout */
        units = r->priv.out_format == ZS_FMT_MONO_PAGE
                    ? (size_t)((y0 + rows - 1) / 8 - y0 / 8 + 1)
                    : (size_t)rows;
    }
    if (stride < need ||
        (units > 1 && /* no division for one row (a helper call on Cortex-M0) */
         stride > (SIZE_MAX - need) / units))
        return ZS_ERR_BUFFER; /* too small, or rows * stride past the address space */
    if (r->priv.state == ZS_STATE_OPEN) {
        zs_raster_begin(r);
#ifndef ZS_NO_MONO
        if (kind == ZS_ROWS_MONO) {
            zs_mono_begin(r);
            if (r->shade.mono & ZS_MONO_LINES)
                zs_lines_begin(r);
        }
#endif
        if (ZS_HAS_ABUFFER && r->priv.aa_mode)
            zs_abuffer_begin(r);
        r->priv.state = ZS_STATE_RENDERING;
    }
    for (y = r->priv.next_row; y < y0; y++) {
        if (ZS_HAS_MONO && y < r->priv.line_next) /* hidden lines render a row ahead */
            continue;
        /* Warnock mode keeps no state between rows */
        if (!ZS_HAS_WARNOCK || r->priv.mode != ZS_MODE_WARNOCK)
            zs_raster_row(r, y, 0);
    }
    if (kind == ZS_ROWS_BYTES) {
        for (y = y0; y < y0 + rows; y++)
            zs_raster_row(r, y, (uint8_t *)buf + (size_t)(y - y0) * stride);
    } else if (ZS_HAS_WARNOCK && kind == ZS_ROWS_AREA) { /* the band as one rectangle */
        zs_warnock_rows(r, y0, rows, (uint8_t *)buf, stride);
    } else if (ZS_HAS_MONO) {
        for (y = y0; y < y0 + rows; y++) {
            if (r->priv.out_format == ZS_FMT_MONO_PAGE) /* a page holds 8 rows */
                mono_row(r, y, (uint8_t *)buf + (size_t)(y / 8 - y0 / 8) * stride);
            else
                mono_row(r, y, (uint8_t *)buf + (size_t)(y - y0) * stride);
        }
    }
    /* the A-buffer rewrites the rows' edge pixels */
    if (ZS_HAS_ABUFFER && r->priv.aa_mode && kind != ZS_ROWS_MONO)
        zs_abuffer_rows(r, y0, rows, (uint8_t *)buf, stride);
    r->priv.next_row = y0 + rows;
    r->stats.rows += (uint32_t)rows;
    if (r->priv.next_row >= (int)r->cfg.height)
        r->priv.state = ZS_STATE_DONE;
    return ZS_OK;
}

zs_status zs_render_frame(zs_renderer *r, void *buf, size_t stride, int band_rows,
                          zs_band_fn fn, void *user)
{
    if (!r || !buf || !fn)
        return ZS_ERR_NULL;
    if (band_rows < 1 || (r->priv.out_format == ZS_FMT_MONO_PAGE && band_rows % 8 != 0))
        return ZS_ERR_ROW;
    if (r->priv.state != ZS_STATE_OPEN && r->priv.state != ZS_STATE_RENDERING)
        return ZS_ERR_STATE;
    while (r->priv.next_row < (int)r->cfg.height) {
        int y0 = r->priv.next_row;
        int n = (int)r->cfg.height - y0;
        zs_status st;
        if (n > band_rows)
            n = band_rows;
        st = zs_render_rows(r, y0, n, buf, stride);
        if (st != ZS_OK)
            return st;
        if (fn(user, y0, n, buf, stride) != 0)
            break;
    }
    return ZS_OK;
}

zs_format zs_frame_format(const zs_renderer *r)
{
    return r ? (zs_format)r->priv.out_format : ZS_FMT_RGB565_BE;
}

const zs_stats *zs_frame_stats(const zs_renderer *r)
{
    return r ? &r->stats : 0;
}

void zs_set_setup_hook(zs_renderer *r, zs_setup_hook_fn fn, void *user)
{
    if (!r)
        return;
    r->priv.setup_hook = fn;
    r->priv.setup_hook_user = user;
}
