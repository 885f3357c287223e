/* SPDX-License-Identifier: MIT */
/* Whole frames of random scenes on the host, on Cortex-M4 (core -O2, with
 * its assembly projection and cull loops) and on Cortex-M0 code (core -Os,
 * split 32-bit products, the Newton reciprocal, bisection for crossings),
 * the last two under QEMU mps2-an386: each prints one line per scene with
 * the FNV-1a hashes of its span and z-buffer frames and the statistics that
 * must not depend on the target, and make check-frames-xtarget compares the
 * three lists byte for byte. The bench scenes do this for four meshes; this
 * covers what they do not: any screen size, interpenetrating soups, folded
 * two-sided grids of shared edges, triangles through the near plane and far
 * off the screen, face and vertex colours, lights and fog, ID16 and RGB888,
 * bands.
 * Every platform also checks span == zline itself (an "E" line and exit 1
 * otherwise). The generator uses 32-bit integers only, so the scenes are the
 * same everywhere. */
#include "zspan/zspan.h"
#include <string.h>
#include "check_rng.h"
#ifdef __arm__
#include "port.h"
#define OUT sh_printf
#else
#include <stdio.h>
#define OUT printf
#endif

#define SCENES 600
#define MAXW 160
#define MAXH 120
#define MAXT 600
#define MAXV 640
#define MAXE 360
#define MESH_V 96
#define MESH_T 200
#define MESHES 4

static uint8_t arena[ZS_ARENA_BYTES(MAXW, MAXH, MAXT, MAXV, MAXE)];
static uint8_t frame_span[MAXW * MAXH * 3], frame_zline[MAXW * MAXH * 3];
static int16_t pos[MESHES][3 * MESH_V];
static uint16_t idx[MESHES][3 * MESH_T];
static zs_color fcol[MESHES][MESH_T], vcol[MESHES][MESH_V];
static zs_mesh meshes[MESHES];
static zs_mat34 models[MESHES];
/* Mesh k: a soup of random triangles (penetrating, any winding), a grid of
 * quads sharing edges with random heights (folds, hand-overs), or a few
 * large triangles (through the near plane, off the screen). */
static void make_mesh(int k)
{
    zs_mesh *m = &meshes[k];
    int kind = (int)(next() % 3u), i, vc, tc;
    int32_t spread = 32767 >> range(0, 4);
    memset(m, 0, sizeof *m);
    if (kind == 1) { /* grid n x n quads */
        int n = range(2, 7), x, y;
        vc = (n + 1) * (n + 1);
        for (y = 0; y <= n; y++)
            for (x = 0; x <= n; x++) {
                int16_t *p = &pos[k][3 * (y * (n + 1) + x)];
                p[0] = (int16_t)(-spread + (2 * spread / n) * x);
                p[1] = (int16_t)(-spread + (2 * spread / n) * y);
                p[2] = (int16_t)range(-spread / 8, spread / 8);
            }
        tc = 0;
        for (y = 0; y < n; y++)
            for (x = 0; x < n; x++) {
                uint16_t a = (uint16_t)(y * (n + 1) + x), b = (uint16_t)(a + 1),
                         c = (uint16_t)(a + n + 1), d = (uint16_t)(c + 1);
                uint16_t *t = &idx[k][3 * tc];
                if (next() & 1) {
                    t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
                } else {
                    t[0] = a, t[1] = b, t[2] = c, t[3] = b, t[4] = d, t[5] = c;
                }
                /* and the other side (seen from either way) */
                for (i = 0; i < 6; i += 3) {
                    t[6 + i] = t[i];
                    t[7 + i] = t[i + 2];
                    t[8 + i] = t[i + 1];
                }
                tc += 4;
            }
    } else {
        vc = kind == 0 ? range(3, MESH_V) : range(3, 9);
        tc = kind == 0 ? range(1, MESH_T) : range(1, 6);
        for (i = 0; i < 3 * vc; i++)
            pos[k][i] = (int16_t)range(-spread - 1, spread);
        for (i = 0; i < 3 * tc; i++)
            idx[k][i] = (uint16_t)(next() % (uint32_t)vc);
    }
    for (i = 0; i < tc; i++)
        fcol[k][i] = next();
    for (i = 0; i < vc; i++)
        vcol[k][i] = next();
    m->positions = pos[k];
    m->indices = idx[k];
    m->vertex_count = (uint16_t)vc;
    m->triangle_count = (uint16_t)tc;
    m->scale = kind == 2 ? ZS_FX(1) >> range(8, 12) : ZS_FX(1) >> range(13, 15);
    m->color = next();
    switch (next() % 3u) {
    case 0: m->face_colors = fcol[k]; break;
    case 1: m->vertex_colors = vcol[k]; break;
    default: break;
    }
    {
        zs_mat34 a = zs_mat34_rotate_y(range(0, ZS_FX(360)));
        zs_mat34 b = zs_mat34_rotate_x(range(0, ZS_FX(360)));
        zs_mat34 ab = zs_mat34_mul(&a, &b);
        zs_fixed t[3];
        for (i = 0; i < 3; i++) /* one call a statement: argument order is unspecified */
            t[i] = range(-ZS_FX(2), ZS_FX(2));
        a = zs_mat34_translate(t[0], t[1], t[2]);
        models[k] = zs_mat34_mul(&a, &ab);
    }
}

/* Renders the frame into buf in bands of band rows; its hash. */
static zs_status render(zs_renderer *r, const zs_camera *cam, zs_visibility mode,
                        const zs_shade_params *sp, int nm, uint8_t *buf, int band,
                        uint32_t *hash)
{
    const int w = r->cfg.width, h = r->cfg.height;
    const size_t stride = (size_t)w * zs_format_bytes(sp->format);
    zs_status st = zs_frame_begin(r, cam, mode);
    int k, y;
    if (st == ZS_OK)
        st = zs_frame_shading(r, sp);
    for (k = 0; k < nm && st == ZS_OK; k++)
        st = zs_draw(r, &meshes[k], &models[k]);
    for (y = 0; y < h && st == ZS_OK; y += band)
        st = zs_render_rows(r, y, y + band <= h ? band : h - y, buf + (size_t)y * stride, stride);
    *hash = fnv_bytes(0x811C9DC5u, buf, stride * (size_t)h);
    return st;
}

int main(void)
{
    static zs_renderer r;
    static const uint16_t sizes[5][2] = {{64, 48}, {96, 72}, {160, 120}, {33, 17}, {120, 90}};
    unsigned s, mismatches = 0, pixels = 0;
    unsigned long records = 0, clipped = 0, crossings = 0, evals = 0;
    check_seed(0x5EED1234u);
    for (s = 0; s < SCENES; s++) {
        const uint16_t *wh = sizes[next() % 5u];
        zs_config cfg = zs_config_default(wh[0], wh[1], MAXT, MAXV, MAXE);
        zs_camera cam;
        zs_shade_params sp = zs_shade_default();
        zs_fixed v[6];
        uint32_t hs, hz, hstat = 0x811C9DC5u;
        zs_status a, b;
        int k, nm = range(1, MESHES), band = range(1, 16);
        if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK) {
            OUT("E zs_init failed\n");
            return 1;
        }
        /* the eye 2.5..8 units from the middle, either side, looking at it */
        for (k = 0; k < 6; k++)
            v[k] = k == 2 ? range(ZS_FX(5) / 2, ZS_FX(8)) : range(-ZS_FX(k < 3 ? 3 : 1), ZS_FX(k < 3 ? 3 : 1));
        if (next() & 1)
            v[2] = -v[2];
        memset(&cam, 0, sizeof cam);
        zs_camera_look_at(&cam, zs_vec3_make(v[0], v[1], v[2]), zs_vec3_make(v[3], v[4], v[5]),
                          zs_vec3_make(0, ZS_FX(1), 0));
        v[0] = range(ZS_FX(30), ZS_FX(100));
        v[1] = range(ZS_FX(1) / 64, ZS_FX(1));
        v[2] = range(ZS_FX(8), ZS_FX(200));
        zs_camera_perspective(&cam, v[0], v[1], v[2]);
        for (k = 0; k < nm; k++)
            make_mesh(k);
        switch (next() % 5u) {
        case 0: sp.format = ZS_FMT_RGB565; break;
        case 1: sp.format = ZS_FMT_ID16; break;
        case 2: /* Gouraud, lit */
            sp.format = ZS_FMT_RGB888;
            sp.shading = ZS_SHADE_GOURAUD;
            sp.ambient = range(0, ZS_FX(1));
            sp.light_count = 1;
            v[0] = range(-ZS_FX(1), ZS_FX(1));
            v[1] = range(-ZS_FX(1), ZS_FX(1));
            sp.lights[0].direction = zs_vec3_make(v[0], v[1], ZS_FX(1));
            sp.lights[0].intensity = range(ZS_FX(1) / 4, ZS_FX(1));
            break;
        case 3: /* flat, lit by two lights */
            sp.format = ZS_FMT_RGB565;
            sp.ambient = range(0, ZS_FX(1) / 2);
            sp.light_count = 2;
            for (k = 0; k < 2; k++) {
                v[0] = range(-ZS_FX(1), ZS_FX(1));
                v[1] = range(-ZS_FX(1), ZS_FX(1));
                sp.lights[k].direction = zs_vec3_make(v[0], ZS_FX(1), v[1]);
                sp.lights[k].intensity = range(ZS_FX(1) / 4, ZS_FX(1));
            }
            break;
        default: /* Gouraud with fog */
            sp.format = ZS_FMT_RGB888;
            sp.shading = ZS_SHADE_GOURAUD;
            sp.fog.enabled = 1;
            sp.fog.color = next();
            sp.fog.start = range(0, ZS_FX(4));
            sp.fog.end = range(ZS_FX(1), ZS_FX(20));
            sp.fog.end += sp.fog.start;
            break;
        }
        sp.background = next();
        a = render(&r, &cam, ZS_MODE_SPAN, &sp, nm, frame_span, band, &hs);
        hstat = fnv_word(hstat, r.stats.tris_culled);
        hstat = fnv_word(hstat, r.stats.tris_rejected);
        hstat = fnv_word(hstat, r.stats.tris_clipped);
        hstat = fnv_word(hstat, r.stats.tris_empty);
        hstat = fnv_word(hstat, r.stats.tris_stored);
        hstat = fnv_word(hstat, r.stats.records);
        hstat = fnv_word(hstat, r.stats.tris_drawn);
        hstat = fnv_word(hstat, r.stats.spans);
        hstat = fnv_word(hstat, r.stats.depth_evals);
        hstat = fnv_word(hstat, r.stats.crossings);
        records += r.stats.records;
        clipped += r.stats.tris_clipped;
        crossings += r.stats.crossings;
        evals += r.stats.depth_evals;
        b = render(&r, &cam, ZS_MODE_ZLINE, &sp, nm, frame_zline, range(1, 16), &hz);
        if (a != ZS_OK || b != ZS_OK) {
            OUT("E scene %u: %s / %s\n", s, zs_strerror(a), zs_strerror(b));
            return 1;
        }
        if (hs != hz)
            mismatches++;
        pixels += (unsigned)(cfg.width * cfg.height);
        OUT("F %u %ux%u fmt %u draws %d records %lu drawn %lu %08lx %08lx %08lx\n", s,
            (unsigned)cfg.width, (unsigned)cfg.height, (unsigned)sp.format, nm,
            (unsigned long)r.stats.records, (unsigned long)r.stats.tris_drawn,
            (unsigned long)hs, (unsigned long)hz, (unsigned long)hstat);
    }
    if (mismatches) {
        OUT("E %u scenes whose span and zline frames differ\n", mismatches);
        return 1;
    }
    OUT("N %u scenes, %u pixels each mode, %lu records (%lu clipped), %lu depth evaluations, "
        "%lu crossings; span == zline in all\n",
        SCENES, pixels, records, clipped, evals, crossings);
    return 0;
}
