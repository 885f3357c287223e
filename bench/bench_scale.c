/* SPDX-License-Identifier: MIT */
/*
 * The scaling benchmark: how the cost of a frame grows with the triangle
 * count and the screen size (make bench; bench/run_scale.sh drives it).
 *
 *   bench_scale stats [--quick] [--case NAME] [--frames N]
 *       for every case: finds the pool capacities, renders the frames in
 *       both modes with the setup hook and prints per case and mode one line
 *       ST NAME MODE w=.. h=.. tris=.. frames=.. caps=T,V,E rows=.. submitted=..
 *          drawn=.. edge_events=.. pixels=.. ... (sums over the frames)
 *       checking that span and z-line images are identical, that nothing is
 *       dropped and that the hook's count of edge sides per row agrees with
 *       the core's max_active_edges; exits 1 if a check fails.
 *   bench_scale run NAME span|zline --caps T,V,E [--frames N]
 *       renders only (no hook): the program to run under callgrind with
 *       --toggle-collect of zs_frame_begin, zs_draw and zs_render_rows.
 *   bench_scale report --stats FILE --cg FILE [--fw FILE]...
 *       the Markdown section "How cost grows": the runs, the fitted cost
 *       model, and frames-per-second estimates from the firmware bench's
 *       instruction counts (its R lines, bench/run_bench.sh).
 *   bench_scale list [--quick]   the case names
 *
 * Edge events are counted here, on the host, from the stored triangle
 * records (zs_set_setup_hook: snapped 28.4 vertices; the core has no such
 * counter). An edge crosses the rows whose pixel-centre line y + 0.5 lies in
 * [y_top, y_bottom) of its endpoints, clipped to the screen; a record has two
 * sides on each row it covers (its long edge, and one of the two short ones):
 *   edge sides  = sum over records of 2 * (rows covered on screen)
 *   edge events = sum over distinct edges of the rows each crosses
 *               = edge sides - the rows of every edge that two records share
 * (an edge shared by two records, same two snapped endpoints, is one event:
 * the span walk meets it once). The per-row sums of the sides give the most
 * sides on one row, which must equal the core's zs_stats.max_active_edges:
 * an independent check of the row ranges.
 *
 * Uses only the public API (include/zspan/zspan.h) and the bench scenes
 * (bench_scenes.h). The spheres are generated with floating point here; the
 * core sees only their int16 positions.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_scenes.h"
#include "scale_fit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FRAMES BENCH_FRAMES
#define DEFAULT_FRAMES 10
#define PI 3.14159265358979323846

/* ------------------------------------------------------------------ */
/* Cases                                                                */
/* ------------------------------------------------------------------ */

typedef struct scale_case {
    const char *name;
    int stacks, slices;      /* UV sphere; 0 stacks: bench scene `scene` */
    int scene;
    uint16_t w, h;
    int tx_milli, tz_milli;  /* sphere centre (x, 0, z), thousandths of a unit */
    int quick;               /* in the short run of make test */
} scale_case;

/* Triangles of a UV sphere: two per quad, one per quad at the poles. */
#define SPHERE_TRIS(stacks, slices) (2 * (slices) * ((stacks) - 1))

static const scale_case cases[] = {
    /* the triangle series at 240x240 */
    {"sphere80", 5, 10, 0, 240, 240, 0, -3000, 1},
    {"sphere300", 11, 15, 0, 240, 240, 0, -3000, 1},
    {"sphere1000", 21, 25, 0, 240, 240, 0, -3000, 0},
    {"sphere4000", 41, 50, 0, 240, 240, 0, -3000, 0},
    {"sphere16000", 81, 100, 0, 240, 240, 0, -3000, 0},
    /* the screen series */
    {"sphere1000-120x120", 21, 25, 0, 120, 120, 0, -3000, 0},
    {"sphere1000-480x320", 21, 25, 0, 480, 320, 0, -3000, 0},
    {"sphere300-120x120", 11, 15, 0, 120, 120, 0, -3000, 1},
    {"sphere300-480x320", 11, 15, 0, 480, 320, 0, -3000, 1},
    /* other mixes of the terms: far (many empty triangles), half off the
     * right edge (rejected ones), near (large triangles, long edges) */
    {"sphere80-edge", 5, 10, 0, 240, 240, 1700, -3000, 1},
    {"sphere300-far", 11, 15, 0, 240, 240, 0, -12000, 1},
    {"sphere1000-edge", 21, 25, 0, 240, 240, 1700, -3000, 0},
    {"sphere1000-near", 21, 25, 0, 240, 240, 0, -1600, 0},
    {"sphere16000-far", 81, 100, 0, 240, 240, 0, -12000, 0},
    /* the bench scenes at the three sizes */
    {"sphere285-120x120", 0, 0, 0, 120, 120, 0, 0, 0},
    {"sphere285", 0, 0, 0, 240, 240, 0, 0, 0},
    {"sphere285-480x320", 0, 0, 0, 480, 320, 0, 0, 0},
    {"cubes-120x120", 0, 0, 1, 120, 120, 0, 0, 0},
    {"cubes", 0, 0, 1, 240, 240, 0, 0, 0},
    {"cubes-480x320", 0, 0, 1, 480, 320, 0, 0, 0},
    {"wuson-120x120", 0, 0, 2, 120, 120, 0, 0, 0},
    {"wuson", 0, 0, 2, 240, 240, 0, 0, 0},
    {"wuson-480x320", 0, 0, 2, 480, 320, 0, 0, 0},
    {"cluster-120x120", 0, 0, 3, 120, 120, 0, 0, 0},
    {"cluster", 0, 0, 3, 240, 240, 0, 0, 0},
    {"cluster-480x320", 0, 0, 3, 480, 320, 0, 0, 0},
};
#define CASE_COUNT ((int)(sizeof cases / sizeof cases[0]))

static const scale_case *case_find(const char *name)
{
    int i;
    for (i = 0; i < CASE_COUNT; i++)
        if (!strcmp(cases[i].name, name))
            return &cases[i];
    return NULL;
}

/* ------------------------------------------------------------------ */
/* UV spheres                                                           */
/* ------------------------------------------------------------------ */

typedef struct sphere {
    int16_t *pos;
    uint16_t *idx;
    zs_color *colors;
    zs_mesh mesh;
} sphere;

#define SPHERE_UNIT 16384 /* int16 per model unit: scale 65536 / 16384 = 4 */

static void sphere_free(sphere *s)
{
    free(s->pos);
    free(s->idx);
    free(s->colors);
    memset(s, 0, sizeof *s);
}

/* A face colour from its index (an integer hash), never the black background. */
static zs_color face_color(uint32_t i)
{
    uint32_t h = i * 2654435761u;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return (h & 0xFFFFFFu) | 0x202020u;
}

/* Unit-radius sphere: poles on y, `stacks` bands, `slices` around;
 * counter-clockwise seen from outside. Returns 0, -1 when out of memory. */
static int sphere_make(sphere *s, int stacks, int slices)
{
    int nv = slices * (stacks - 1) + 2, nt = SPHERE_TRIS(stacks, slices), i, j, t = 0;
    double (*v)[3];
    memset(s, 0, sizeof *s);
    s->pos = malloc(sizeof *s->pos * 3u * (size_t)nv);
    s->idx = malloc(sizeof *s->idx * 3u * (size_t)nt);
    s->colors = malloc(sizeof *s->colors * (size_t)nt);
    v = malloc(sizeof *v * (size_t)nv);
    if (!s->pos || !s->idx || !s->colors || !v) {
        free(v);
        sphere_free(s);
        return -1;
    }
    /* vertex 0 the top pole, then the rings, the last the bottom pole */
    v[0][0] = 0, v[0][1] = 1, v[0][2] = 0;
    for (i = 1; i < stacks; i++)
        for (j = 0; j < slices; j++) {
            double th = PI * i / stacks, ph = 2 * PI * j / slices;
            double *p = v[1 + (i - 1) * slices + j];
            p[0] = sin(th) * cos(ph), p[1] = cos(th), p[2] = sin(th) * sin(ph);
        }
    v[nv - 1][0] = 0, v[nv - 1][1] = -1, v[nv - 1][2] = 0;
    for (i = 0; i < nv; i++)
        for (j = 0; j < 3; j++)
            s->pos[3 * i + j] = (int16_t)lround(v[i][j] * SPHERE_UNIT);
#define RING(i, j) (1 + ((i) - 1) * slices + ((j) % slices))
    for (i = 0; i < stacks; i++)
        for (j = 0; j < slices; j++) {
            int tri[2][3], n = 0, k;
            if (i == 0) {
                tri[n][0] = 0, tri[n][1] = RING(1, j), tri[n][2] = RING(1, j + 1), n++;
            } else if (i == stacks - 1) {
                tri[n][0] = nv - 1, tri[n][1] = RING(i, j), tri[n][2] = RING(i, j + 1), n++;
            } else {
                tri[n][0] = RING(i, j), tri[n][1] = RING(i + 1, j), tri[n][2] = RING(i + 1, j + 1), n++;
                tri[n][0] = RING(i, j), tri[n][1] = RING(i + 1, j + 1), tri[n][2] = RING(i, j + 1), n++;
            }
            for (k = 0; k < n; k++) {
                /* outward normal: (b - a) x (c - a) . a > 0, else swap */
                const double *a = v[tri[k][0]], *b = v[tri[k][1]], *c = v[tri[k][2]];
                double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
                double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                double nx = e1[1] * e2[2] - e1[2] * e2[1], ny = e1[2] * e2[0] - e1[0] * e2[2],
                       nz = e1[0] * e2[1] - e1[1] * e2[0];
                double cx = a[0] + b[0] + c[0], cy = a[1] + b[1] + c[1], cz = a[2] + b[2] + c[2];
                int swap = nx * cx + ny * cy + nz * cz < 0;
                s->idx[3 * t] = (uint16_t)tri[k][0];
                s->idx[3 * t + 1] = (uint16_t)tri[k][swap ? 2 : 1];
                s->idx[3 * t + 2] = (uint16_t)tri[k][swap ? 1 : 2];
                s->colors[t] = face_color((uint32_t)t);
                t++;
            }
        }
#undef RING
    free(v);
    s->mesh.positions = s->pos;
    s->mesh.indices = s->idx;
    s->mesh.face_colors = s->colors;
    s->mesh.scale = ZS_FX_ONE / SPHERE_UNIT;
    s->mesh.vertex_count = (uint16_t)nv;
    s->mesh.triangle_count = (uint16_t)nt;
    s->mesh.color = ZS_RGB(255, 255, 255);
    return 0;
}

/* ------------------------------------------------------------------ */
/* Rendering                                                            */
/* ------------------------------------------------------------------ */

typedef struct scene_src {
    const scale_case *c;
    sphere sph;          /* when c->stacks */
    const zs_mesh *mesh;
} scene_src;

static int scene_open(scene_src *s, const scale_case *c)
{
    memset(s, 0, sizeof *s);
    s->c = c;
    if (!c->stacks) {
        s->mesh = bench_scenes[c->scene].mesh;
        return 0;
    }
    if (sphere_make(&s->sph, c->stacks, c->slices) != 0)
        return -1;
    s->mesh = &s->sph.mesh;
    return 0;
}

static void scene_close(scene_src *s)
{
    sphere_free(&s->sph);
}

/* Model-view of frame f: the bench scenes' own; the spheres turn about a
 * tilted axis so that no two frames see the same arrangement of bands. */
static zs_mat34 scene_model_view(const scene_src *s, int f)
{
    zs_mat34 t, rx, ry, rxy;
    if (!s->c->stacks)
        return bench_model_view(&bench_scenes[s->c->scene], f);
    t = zs_mat34_translate(ZS_FX_RATIO(s->c->tx_milli, 1000), 0,
                           ZS_FX_RATIO(s->c->tz_milli, 1000));
    rx = zs_mat34_rotate_x(ZS_FX(15 + 11 * f));
    ry = zs_mat34_rotate_y(ZS_FX(30 + 7 * f));
    rxy = zs_mat34_mul(&rx, &ry);
    return zs_mat34_mul(&t, &rxy);
}

/* What the setup hook sees during one frame. */
typedef struct edge_key {
    int32_t x0, y0, x1, y1;   /* endpoints, upper one first (28.4) */
    int used, shared;
} edge_key;

typedef struct edge_count {
    int32_t *sides;     /* per row: +2 where a record starts, -2 past its end */
    int h;
    uint64_t events;    /* edge sides x rows (see the file's comment) */
    uint64_t shared;    /* rows of edges met a second time (by another record) */
    uint32_t records;   /* records seen */
    edge_key *table;    /* open addressing, size a power of two */
    uint32_t mask;
} edge_count;

static int32_t first_row(int32_t y) /* first row whose centre is at or below y (28.4) */
{
    return (int32_t)floor((y + 7) / 16.0);
}

/* Rows [y0, y1) whose centres lie in [ya, yb), clipped to the screen. */
static int32_t rows_between(int32_t ya, int32_t yb, int h)
{
    int32_t y0 = first_row(ya), y1 = first_row(yb);
    if (y0 < 0)
        y0 = 0;
    if (y1 > h)
        y1 = h;
    return y1 > y0 ? y1 - y0 : 0;
}

/* Edge a -> b of a record: the second record with the same two endpoints
 * (the neighbour across a shared edge) adds its rows to `shared`. */
static void edge_meet(edge_count *ec, int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    int32_t rows;
    uint32_t hsh, i;
    if (ay > by || (ay == by && ax > bx)) {
        int32_t t = ax;
        ax = bx, bx = t;
        t = ay, ay = by, by = t;
    }
    rows = rows_between(ay, by, ec->h);
    if (!rows)
        return; /* horizontal, or off the screen: never an event */
    hsh = ((uint32_t)ax * 73856093u) ^ ((uint32_t)ay * 19349663u) ^ ((uint32_t)bx * 83492791u) ^
          ((uint32_t)by * 2654435761u);
    for (i = hsh & ec->mask;; i = (i + 1) & ec->mask) {
        edge_key *k = &ec->table[i];
        if (!k->used) {
            k->used = 1;
            k->x0 = ax, k->y0 = ay, k->x1 = bx, k->y1 = by;
            return;
        }
        if (k->x0 == ax && k->y0 == ay && k->x1 == bx && k->y1 == by) {
            if (!k->shared) {
                k->shared = 1;
                ec->shared += (uint64_t)rows;
            }
            return;
        }
    }
}

static void count_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    edge_count *ec = user;
    int32_t lo = xy[1], hi = xy[1], y0, y1;
    (void)tag;
    (void)z;
    if (xy[3] < lo) lo = xy[3];
    if (xy[5] < lo) lo = xy[5];
    if (xy[3] > hi) hi = xy[3];
    if (xy[5] > hi) hi = xy[5];
    y0 = first_row(lo);
    y1 = first_row(hi);
    if (y0 < 0)
        y0 = 0;
    if (y1 > ec->h)
        y1 = ec->h;
    ec->records++;
    if (y1 <= y0)
        return;
    ec->events += 2u * (uint64_t)(y1 - y0);
    ec->sides[y0] += 2;
    ec->sides[y1] -= 2;
    edge_meet(ec, xy[0], xy[1], xy[2], xy[3]);
    edge_meet(ec, xy[2], xy[3], xy[4], xy[5]);
    edge_meet(ec, xy[4], xy[5], xy[0], xy[1]);
}

typedef struct frame_sums {
    uint64_t rows, submitted, culled, rejected, clipped, empty, stored, records, drawn;
    uint64_t edge_sides, edge_events, pixels, spans, depth_evals, crossings, dropped;
    uint32_t max_sides;            /* the most edge sides on a row, from the hook */
    uint32_t core_max_sides;       /* zs_stats.max_active_edges */
    int side_mismatch, record_mismatch;
} frame_sums;

typedef struct caps {
    uint16_t tris, verts, edges;
} caps;

static uint32_t fnv1a(uint32_t h, const uint8_t *p, size_t n)
{
    return bench_fnv1a(h, p, n);
}

/* Renders frames 0..frames-1 of s in one mode with capacities cp. With sums,
 * the hook counts edges and the statistics are added up; with sum_out, each
 * frame's checksum is stored. Returns 0, or -1 on an API error (printed). */
static int render_frames(const scene_src *s, const caps *cp, zs_visibility mode, int frames,
                         frame_sums *sums, uint32_t *sum_out)
{
    zs_config cfg = zs_config_default(s->c->w, s->c->h, cp->tris, cp->verts, cp->edges);
    size_t need, stride = (size_t)s->c->w * 2u;
    uint8_t *arena, *img;
    zs_renderer r;
    zs_camera cam;
    edge_count ec;
    zs_status st;
    int f, y, ret = -1;
    cfg.flags = ZS_CFG_FLAT_ONLY; /* flat unlit, as the bench scenes */
    need = zs_arena_bytes(&cfg);
    arena = malloc(need ? need : 1);
    img = malloc(stride * s->c->h);
    memset(&ec, 0, sizeof ec);
    ec.h = s->c->h;
    ec.sides = calloc((size_t)s->c->h + 1u, sizeof *ec.sides);
    for (ec.mask = 1; ec.mask < 12u * cp->tris; ec.mask *= 2)
        ; /* three edges a record, the table at most a quarter full */
    ec.table = sums ? malloc(sizeof *ec.table * ec.mask) : NULL;
    ec.mask--;
    if (!arena || !img || !ec.sides || (sums && !ec.table)) {
        fprintf(stderr, "bench_scale: out of memory\n");
        goto out;
    }
    if ((st = zs_init(&r, arena, need, &cfg)) != ZS_OK || (st = bench_camera(&cam)) != ZS_OK) {
        fprintf(stderr, "bench_scale: %s: %s\n", s->c->name, zs_strerror(st));
        goto out;
    }
    for (f = 0; f < frames; f++) {
        zs_mat34 mv = scene_model_view(s, f);
        const zs_stats *stt;
        if (sums) {
            memset(ec.sides, 0, sizeof *ec.sides * ((size_t)s->c->h + 1u));
            memset(ec.table, 0, sizeof *ec.table * (ec.mask + 1u));
            ec.events = 0;
            ec.shared = 0;
            ec.records = 0;
            zs_set_setup_hook(&r, count_hook, &ec);
        }
        st = zs_frame_begin(&r, &cam, mode);
        if (st == ZS_OK)
            st = zs_draw(&r, s->mesh, &mv);
        for (y = 0; st == ZS_OK && y < s->c->h; y++)
            st = zs_render_rows(&r, y, 1, img + (size_t)y * stride, stride);
        if (st != ZS_OK) {
            fprintf(stderr, "bench_scale: %s frame %d: %s\n", s->c->name, f, zs_strerror(st));
            goto out;
        }
        stt = zs_frame_stats(&r);
        if (!sums && stt->tris_dropped + stt->verts_dropped + stt->records_skipped) {
            /* a count of a frame that lost triangles would mislead */
            fprintf(stderr, "bench_scale: %s frame %d: pools too small for --caps (%lu "
                            "triangles, %lu vertices dropped, %lu records skipped)\n",
                    s->c->name, f, (unsigned long)stt->tris_dropped,
                    (unsigned long)stt->verts_dropped, (unsigned long)stt->records_skipped);
            goto out;
        }
        if (sum_out)
            sum_out[f] = fnv1a(BENCH_FNV_BASIS, img, stride * s->c->h);
        if (sums) {
            int32_t run = 0;
            uint32_t mx = 0;
            for (y = 0; y < s->c->h; y++) {
                run += ec.sides[y];
                if ((uint32_t)run > mx)
                    mx = (uint32_t)run;
            }
            sums->rows += stt->rows;
            sums->submitted += stt->tris_submitted;
            sums->culled += stt->tris_culled;
            sums->rejected += stt->tris_rejected;
            sums->clipped += stt->tris_clipped;
            sums->empty += stt->tris_empty;
            sums->stored += stt->tris_stored;
            sums->records += stt->records;
            sums->drawn += stt->tris_drawn;
            sums->edge_sides += ec.events;
            sums->edge_events += ec.events - ec.shared;
            sums->pixels += stt->pixels_shaded;
            sums->spans += stt->spans;
            sums->depth_evals += stt->depth_evals;
            sums->crossings += stt->crossings;
            sums->dropped += stt->tris_dropped + stt->verts_dropped + stt->records_skipped;
            if (mx > sums->max_sides)
                sums->max_sides = mx;
            if (stt->max_active_edges > sums->core_max_sides)
                sums->core_max_sides = stt->max_active_edges;
            if (mx != stt->max_active_edges)
                sums->side_mismatch++;
            if (ec.records != stt->records)
                sums->record_mismatch++;
            zs_set_setup_hook(&r, NULL, NULL);
        }
    }
    ret = 0;
out:
    free(arena);
    free(img);
    free(ec.sides);
    free(ec.table);
    return ret;
}

static uint16_t grow16(uint32_t v)
{
    uint32_t n = v + (v / 16u > 1u ? v / 16u : 1u);
    return (uint16_t)(n > 65535u ? 65535u : n);
}

/* The smallest pools (as bench_host's caps) with which no frame of either
 * mode drops anything: large pools would add their set-up to every frame. */
static int find_caps(const scene_src *s, int frames, caps *out)
{
    caps cp = {65535, 65535, ZS_MAX_ACTIVE_EDGES};
    uint32_t t = 1, v = 1, e = 2;
    int mi, i;
    for (mi = 0; mi < 2; mi++) {
        int f;
        for (f = 0; f < frames; f++) { /* per frame: the largest use */
            zs_config cfg = zs_config_default(s->c->w, s->c->h, cp.tris, cp.verts, cp.edges);
            zs_renderer r;
            size_t need;
            uint8_t *arena, *row;
            zs_camera cam;
            zs_mat34 mv = scene_model_view(s, f);
            const zs_stats *stt;
            int y;
            zs_status st;
            cfg.flags = ZS_CFG_FLAT_ONLY;
            need = zs_arena_bytes(&cfg);
            arena = malloc(need);
            row = malloc((size_t)s->c->w * 2u);
            if (!arena || !row) {
                free(arena);
                free(row);
                return -1;
            }
            st = zs_init(&r, arena, need, &cfg);
            if (st == ZS_OK)
                st = bench_camera(&cam);
            if (st == ZS_OK)
                st = zs_frame_begin(&r, &cam, mi ? ZS_MODE_ZLINE : ZS_MODE_SPAN);
            if (st == ZS_OK)
                st = zs_draw(&r, s->mesh, &mv);
            for (y = 0; st == ZS_OK && y < s->c->h; y++)
                st = zs_render_rows(&r, y, 1, row, (size_t)s->c->w * 2u);
            stt = zs_frame_stats(&r);
            if (st == ZS_OK && stt->tris_dropped + stt->verts_dropped + stt->records_skipped)
                st = ZS_ERR_STATE; /* even the largest pools overflowed */
            free(arena);
            free(row);
            if (st != ZS_OK) {
                fprintf(stderr, "bench_scale: %s: pool sizing failed (%s)\n", s->c->name,
                        zs_strerror(st));
                return -1;
            }
            if (stt->records > t)
                t = stt->records;
            if (stt->verts_stored > v)
                v = stt->verts_stored;
            if (stt->max_active_edges > e)
                e = stt->max_active_edges;
        }
    }
    cp.tris = (uint16_t)t;
    cp.verts = (uint16_t)v;
    cp.edges = (uint16_t)(e > ZS_MAX_ACTIVE_EDGES ? ZS_MAX_ACTIVE_EDGES : e);
    for (i = 0; i < 100; i++) { /* grow a pool that the statistics did not bound */
        int grew = 0;
        for (mi = 0; mi < 2; mi++) {
            frame_sums fs;
            memset(&fs, 0, sizeof fs);
            if (render_frames(s, &cp, mi ? ZS_MODE_ZLINE : ZS_MODE_SPAN, frames, &fs, NULL))
                return -1;
            if (fs.dropped) {
                cp.tris = grow16(cp.tris);
                cp.verts = grow16(cp.verts);
                cp.edges = grow16(cp.edges) > ZS_MAX_ACTIVE_EDGES ? ZS_MAX_ACTIVE_EDGES
                                                                  : grow16(cp.edges);
                grew = 1;
            }
        }
        if (!grew)
            break;
    }
    *out = cp;
    return 0;
}

/* ------------------------------------------------------------------ */
/* Commands                                                             */
/* ------------------------------------------------------------------ */

static int cmd_stats(const char *only, int quick, int frames)
{
    int i, failures = 0, mi, f;
    for (i = 0; i < CASE_COUNT; i++) {
        const scale_case *c = &cases[i];
        scene_src s;
        caps cp;
        uint32_t sum[2][MAX_FRAMES];
        frame_sums fs[2];
        int same = 1;
        if ((only && strcmp(only, c->name)) || (quick && !c->quick))
            continue;
        if (scene_open(&s, c) != 0) {
            fprintf(stderr, "bench_scale: out of memory\n");
            return 1;
        }
        if (find_caps(&s, frames, &cp) != 0) {
            scene_close(&s);
            return 1;
        }
        for (mi = 0; mi < 2; mi++) {
            memset(&fs[mi], 0, sizeof fs[mi]);
            if (render_frames(&s, &cp, mi ? ZS_MODE_ZLINE : ZS_MODE_SPAN, frames, &fs[mi],
                              sum[mi])) {
                scene_close(&s);
                return 1;
            }
        }
        for (f = 0; f < frames; f++)
            if (sum[0][f] != sum[1][f])
                same = 0;
        for (mi = 0; mi < 2; mi++) {
            const frame_sums *p = &fs[mi];
            printf("ST %s %s w=%u h=%u tris=%u frames=%d caps=%u,%u,%u rows=%llu "
                   "submitted=%llu culled=%llu rejected=%llu clipped=%llu empty=%llu "
                   "stored=%llu records=%llu drawn=%llu edge_sides=%llu edge_events=%llu pixels=%llu "
                   "spans=%llu depth_evals=%llu crossings=%llu dropped=%llu max_sides=%u "
                   "core_max_sides=%u span_eq_zline=%s sum0=%08lx\n",
                   c->name, mi ? "zline" : "span", c->w, c->h, s.mesh->triangle_count, frames,
                   cp.tris, cp.verts, cp.edges, (unsigned long long)p->rows,
                   (unsigned long long)p->submitted, (unsigned long long)p->culled,
                   (unsigned long long)p->rejected, (unsigned long long)p->clipped,
                   (unsigned long long)p->empty, (unsigned long long)p->stored,
                   (unsigned long long)p->records, (unsigned long long)p->drawn,
                   (unsigned long long)p->edge_sides, (unsigned long long)p->edge_events,
                   (unsigned long long)p->pixels,
                   (unsigned long long)p->spans, (unsigned long long)p->depth_evals,
                   (unsigned long long)p->crossings, (unsigned long long)p->dropped,
                   p->max_sides, p->core_max_sides, same ? "yes" : "NO",
                   (unsigned long)sum[mi][0]);
            if (p->dropped) {
                fprintf(stderr, "bench_scale: %s %s: %llu triangles dropped\n", c->name,
                        mi ? "zline" : "span", (unsigned long long)p->dropped);
                failures++;
            }
            if (p->side_mismatch || p->record_mismatch) {
                fprintf(stderr,
                        "bench_scale: %s %s: the hook's count disagrees with the core's "
                        "statistics in %d frames (most sides on a row %u, core %u; records "
                        "in %d frames)\n",
                        c->name, mi ? "zline" : "span", p->side_mismatch, p->max_sides,
                        p->core_max_sides, p->record_mismatch);
                failures++;
            }
        }
        if (!same) {
            fprintf(stderr, "bench_scale: %s: span and z-line images differ\n", c->name);
            failures++;
        }
        fflush(stdout);
        scene_close(&s);
    }
    return failures ? 1 : 0;
}

static int cmd_run(const char *name, const char *mode, const char *caps_arg, int frames)
{
    const scale_case *c = case_find(name);
    unsigned t, v, e;
    scene_src s;
    caps cp;
    int ret;
    if (!c) {
        fprintf(stderr, "bench_scale: no case '%s' (bench_scale list)\n", name);
        return 2;
    }
    if (strcmp(mode, "span") && strcmp(mode, "zline")) {
        fprintf(stderr, "bench_scale: mode must be span or zline, not '%s'\n", mode);
        return 2;
    }
    if (!caps_arg || sscanf(caps_arg, "%u,%u,%u", &t, &v, &e) != 3 || !t || !v || e < 2 ||
        t > 65535 || v > 65535 || e > ZS_MAX_ACTIVE_EDGES) {
        fprintf(stderr, "bench_scale: --caps T,V,E needed (from the stats line)\n");
        return 2;
    }
    cp.tris = (uint16_t)t, cp.verts = (uint16_t)v, cp.edges = (uint16_t)e;
    if (scene_open(&s, c) != 0) {
        fprintf(stderr, "bench_scale: out of memory\n");
        return 1;
    }
    ret = render_frames(&s, &cp, strcmp(mode, "span") ? ZS_MODE_ZLINE : ZS_MODE_SPAN, frames,
                        NULL, NULL);
    scene_close(&s);
    return ret ? 1 : 0;
}

/* ------------------------------------------------------------------ */
/* The report                                                           */
/* ------------------------------------------------------------------ */

#define MAX_RUNS 128
#define MAX_FW 64
#define TERMS 5     /* the cost model: rows, submitted, drawn, edge events, pixels */
#define TERMS_EXT 6 /* the same plus depth evaluations */
#define M4_HZ 168e6
#define M0_HZ 133e6

typedef struct run_line {
    char name[64], mode[8];
    unsigned w, h, tris, frames;
    double rows, submitted, drawn, edge_events, pixels, depth_evals;
    double instr; /* per frame, from the CG line; 0 if none */
    int eq;
} run_line;

typedef struct fw_scene {
    char board[24], scene[32], mode[8];
    double sum;
    int n;
} fw_scene;

typedef struct report {
    run_line runs[MAX_RUNS];
    int n_runs;
    fw_scene fw[MAX_FW];
    int n_fw;
} report;

static const char *const modes[2] = {"span", "zline"};
static const char *const term_name[TERMS_EXT] = {
    "row", "submitted triangle", "drawn triangle", "edge event", "pixel", "depth evaluation"};

/* The value of key=... on a line, or NULL. */
static const char *kv(const char *line, const char *key)
{
    size_t n = strlen(key);
    const char *p = line;
    while ((p = strstr(p, key)) != NULL) {
        if ((p == line || p[-1] == ' ') && p[n] == '=')
            return p + n + 1;
        p += n;
    }
    return NULL;
}

static double kvd(const char *line, const char *key)
{
    const char *v = kv(line, key);
    return v ? strtod(v, NULL) : -1.0;
}

/* The terms of one run, per frame. */
static void terms_of(const run_line *r, double *x)
{
    double f = r->frames;
    x[0] = r->rows / f;
    x[1] = r->submitted / f;
    x[2] = r->drawn / f;
    x[3] = r->edge_events / f;
    x[4] = r->pixels / f;
    x[5] = r->depth_evals / f;
}

static void fmt_count(char *buf, size_t n, double v)
{
    if (v >= 1e6)
        snprintf(buf, n, "%.3f M", v / 1e6);
    else if (v >= 1e4)
        snprintf(buf, n, "%.1f k", v / 1e3);
    else
        snprintf(buf, n, "%.0f", v);
}

static int load_stats(report *rp, const char *path)
{
    char line[1024];
    FILE *fp = fopen(path, "r");
    if (!fp) {
        perror(path);
        return -1;
    }
    while (fgets(line, sizeof line, fp) && rp->n_runs < MAX_RUNS) {
        run_line *r = &rp->runs[rp->n_runs];
        const char *eq;
        memset(r, 0, sizeof *r);
        if (sscanf(line, "ST %63s %7s", r->name, r->mode) != 2)
            continue;
        r->w = (unsigned)kvd(line, "w"), r->h = (unsigned)kvd(line, "h");
        r->tris = (unsigned)kvd(line, "tris"), r->frames = (unsigned)kvd(line, "frames");
        r->rows = kvd(line, "rows"), r->submitted = kvd(line, "submitted");
        r->drawn = kvd(line, "drawn"), r->edge_events = kvd(line, "edge_events");
        r->pixels = kvd(line, "pixels"), r->depth_evals = kvd(line, "depth_evals");
        eq = kv(line, "span_eq_zline");
        r->eq = eq && !strncmp(eq, "yes", 3);
        if (r->frames >= 1 && r->rows >= 0 && r->submitted >= 0 && r->drawn >= 0 &&
            r->edge_events >= 0 && r->pixels >= 0 && r->depth_evals >= 0)
            rp->n_runs++;
    }
    fclose(fp);
    return 0;
}

static run_line *find_run(report *rp, const char *name, const char *mode)
{
    int i;
    for (i = 0; i < rp->n_runs; i++)
        if (!strcmp(rp->runs[i].name, name) && !strcmp(rp->runs[i].mode, mode))
            return &rp->runs[i];
    return NULL;
}

static int load_cg(report *rp, const char *path)
{
    char line[256], name[64], mode[8];
    double total;
    FILE *fp = fopen(path, "r");
    if (!fp) {
        perror(path);
        return -1;
    }
    while (fgets(line, sizeof line, fp)) {
        run_line *r;
        if (sscanf(line, "CG %63s %7s %lf", name, mode, &total) == 3 &&
            (r = find_run(rp, name, mode)) != NULL && total > 0)
            r->instr = total / r->frames;
    }
    fclose(fp);
    return 0;
}

/* R lines of the firmware bench: R BOARD SCENE MODE FRAME ... instr=N. A
 * file that is missing gives no figures (that machine did not run). */
static void load_fw(report *rp, const char *path)
{
    char line[1024], board[24], scene[32], mode[8];
    int frame, i;
    FILE *fp = fopen(path, "r");
    if (!fp)
        return;
    while (fgets(line, sizeof line, fp)) {
        double ins = kvd(line, "instr");
        fw_scene *w;
        if (sscanf(line, "R %23s %31s %7s %d", board, scene, mode, &frame) != 4 || ins <= 0)
            continue;
        for (i = 0; i < rp->n_fw; i++)
            if (!strcmp(rp->fw[i].board, board) && !strcmp(rp->fw[i].scene, scene) &&
                !strcmp(rp->fw[i].mode, mode))
                break;
        if (i == rp->n_fw) {
            if (rp->n_fw == MAX_FW)
                continue;
            w = &rp->fw[rp->n_fw++];
            memset(w, 0, sizeof *w);
            snprintf(w->board, sizeof w->board, "%s", board);
            snprintf(w->scene, sizeof w->scene, "%s", scene);
            snprintf(w->mode, sizeof w->mode, "%s", mode);
        }
        rp->fw[i].sum += ins;
        rp->fw[i].n++;
    }
    fclose(fp);
}

/* Mean instructions per frame of a scene on a board, 0 if not measured. */
static double fw_mean(const report *rp, const char *board, const char *scene, const char *mode)
{
    int i;
    for (i = 0; i < rp->n_fw; i++)
        if (!strcmp(rp->fw[i].board, board) && !strcmp(rp->fw[i].scene, scene) &&
            !strcmp(rp->fw[i].mode, mode) && rp->fw[i].n)
            return rp->fw[i].sum / rp->fw[i].n;
    return 0.0;
}

/* Cortex-M0 code: the microbit's figure, else the same code on mps2-an386. */
static double m0_mean(const report *rp, const char *scene, const char *mode)
{
    double v = fw_mean(rp, "microbit", scene, mode);
    return v > 0 ? v : fw_mean(rp, "m0code-an386", scene, mode);
}

static scale_fit_status fit_mode(report *rp, int mi, int n_terms, scale_fit *fit)
{
    static double x[MAX_RUNS * TERMS_EXT], y[MAX_RUNS];
    int i, m = 0;
    for (i = 0; i < rp->n_runs; i++) {
        double t[TERMS_EXT];
        if (strcmp(rp->runs[i].mode, modes[mi]) || rp->runs[i].instr <= 0)
            continue;
        terms_of(&rp->runs[i], t);
        memcpy(x + m * n_terms, t, sizeof *t * (size_t)n_terms);
        y[m++] = rp->runs[i].instr;
    }
    return scale_fit_solve(x, y, m, n_terms, fit);
}

static void print_error(char *buf, size_t n, const scale_fit *fit, scale_fit_status st,
                        const run_line *r)
{
    double t[TERMS_EXT];
    snprintf(buf, n, "-");
    if (st != SCALE_FIT_OK || !r || r->instr <= 0)
        return;
    terms_of(r, t);
    snprintf(buf, n, "%+.1f%%", 100.0 * (scale_fit_eval(fit, t) - r->instr) / r->instr);
}

/* Ratios of Cortex-M instructions to host instructions over the bench scenes
 * measured both ways (240x240, the mode given): mean, min, max. Returns the
 * number of scenes. */
static int cm_ratio(report *rp, const char *board_m0_or_m4, const char *mode, double *mean,
                    double *lo, double *hi)
{
    static const char *const scenes[] = {"sphere285", "cubes", "wuson", "cluster"};
    int i, n = 0;
    *mean = 0, *lo = 1e300, *hi = 0;
    for (i = 0; i < (int)(sizeof scenes / sizeof scenes[0]); i++) {
        const run_line *h = find_run(rp, scenes[i], mode);
        double c = strcmp(board_m0_or_m4, "m0") ? fw_mean(rp, "mps2-an386", scenes[i], mode)
                                                 : m0_mean(rp, scenes[i], mode);
        double q;
        if (!h || h->instr <= 0 || c <= 0)
            continue;
        q = c / h->instr;
        *mean += q;
        if (q < *lo)
            *lo = q;
        if (q > *hi)
            *hi = q;
        n++;
    }
    if (n)
        *mean /= n;
    return n;
}

static int cmd_report(const char *stats_path, const char *cg_path, const char **fw_paths,
                      int n_fw)
{
    static report rp;
    scale_fit fit[2][2];          /* [model: 5 terms, 6 terms][mode] */
    scale_fit_status fst[2][2];
    int i, j, mi, k, ret = 0, n_r4[2], n_r0[2];
    double r4[2], r4lo[2], r4hi[2], r0[2], r0lo[2], r0hi[2];
    memset(&rp, 0, sizeof rp);
    if (load_stats(&rp, stats_path) || load_cg(&rp, cg_path))
        return 1;
    for (j = 0; j < n_fw; j++)
        load_fw(&rp, fw_paths[j]);
    for (k = 0; k < 2; k++)
        for (mi = 0; mi < 2; mi++) {
            fst[k][mi] = fit_mode(&rp, mi, k ? TERMS_EXT : TERMS, &fit[k][mi]);
            if (fst[k][mi] != SCALE_FIT_OK) {
                fprintf(stderr, "bench_scale: %s fit with %d terms: %s (%d runs, condition "
                                "%.3g)\n",
                        modes[mi], k ? TERMS_EXT : TERMS, scale_fit_strerror(fst[k][mi]),
                        fit[k][mi].n_runs, fit[k][mi].cond);
                ret = 1;
            }
        }

    printf("## How cost grows\n\n");
    printf("Generated by `bench/bench_scale.c` (`bench/run_scale.sh`, part of `make bench`): "
           "host x86-64\n");
    printf("instructions per frame under callgrind, counting only `zs_frame_begin` + "
           "`zs_draw` +\n");
    printf("`zs_render_rows` (mean of %u frames), RGB565, flat unlit, one colour per "
           "triangle, back faces\n",
           rp.n_runs ? rp.runs[0].frames : 0u);
    printf("culled, pools sized to the largest use. `sphereN`: a generated UV sphere of "
           "radius 1 with N\n");
    printf("triangles at T(0,0,-3) Rx(15+11f) Ry(30+7f); `-edge`: centred at x = 1.7, half "
           "off the right\n");
    printf("edge; `-far`: at z = -12; `-near`: at z = -1.6. The bench scenes turn as in the "
           "first table.\n");
    printf("Sizes other than 240x240 are in the name. Counts per frame: rows, submitted and "
           "drawn\n");
    printf("triangles, depth evaluations (`zs_stats`) and edge events. **Edge events** are "
           "counted on the\n");
    printf("host from the stored triangle records (`zs_set_setup_hook`; the core has no such "
           "counter): the\n");
    printf("sum over distinct edges of the pixel-centre rows each crosses on screen, an edge "
           "that two\n");
    printf("records share (same snapped endpoints) counted once; that is 2 sides x the rows "
           "of every\n");
    printf("record, minus the rows of the shared edges. The per-row count of sides has the "
           "core's\n");
    printf("`max_active_edges` as its maximum in every frame (checked). \"span = zline\": "
           "the two modes'\n");
    printf("images are identical in every frame.\n\n");

    printf("| case | size | tris | drawn | edge events | depth evals (span) | span instr | "
           "span fit err | zline instr | zline fit err | span = zline |\n");
    printf("| ---- | ---- | ---: | ----: | ----------: | -----------------: | ---------: | "
           "-----------: | ----------: | ------------: | ------------ |\n");
    for (i = 0; i < rp.n_runs; i++) {
        const run_line *r = &rp.runs[i], *z;
        char a[32], b[32] = "-", e1[32], e2[32], ee[32], de[32];
        if (strcmp(r->mode, "span"))
            continue;
        z = find_run(&rp, r->name, "zline");
        fmt_count(a, sizeof a, r->instr);
        fmt_count(ee, sizeof ee, r->edge_events / r->frames);
        fmt_count(de, sizeof de, r->depth_evals / r->frames);
        print_error(e1, sizeof e1, &fit[0][0], fst[0][0], r);
        print_error(e2, sizeof e2, &fit[0][1], fst[0][1], z);
        if (z && z->instr > 0)
            fmt_count(b, sizeof b, z->instr);
        printf("| %s | %ux%u | %u | %.0f | %s | %s | %s | %s | %s | %s | %s |\n", r->name, r->w,
               r->h, r->tris, r->drawn / r->frames, ee, de, a, e1, b, e2,
               r->eq ? "yes" : "**NO**");
    }

    printf("\nFitted cost model: instructions per frame = sum of coefficient x count, by "
           "weighted least\n");
    printf("squares (each run's error relative to its own count, so small and large runs "
           "weigh alike;\n");
    printf("Householder QR); R^2 on the instruction counts; the condition number of the "
           "scaled design\n");
    printf("says how well the runs tell the terms apart (1 = perfectly). The first two "
           "columns are the\n");
    printf("five-term model; z-line mode also tests depth at every covered pixel, which no "
           "term counts,\n");
    printf("so the last two add the core's depth evaluations (z-line: one per covered "
           "pixel; span: one\n");
    printf("per visibility decision) as a sixth term.\n\n");
    printf("| instructions per | span | zline | span, 6 terms | zline, 6 terms |\n");
    printf("| ---------------- | ---: | ----: | ------------: | -------------: |\n");
    for (j = 0; j < TERMS_EXT; j++) {
        printf("| %s |", term_name[j]);
        for (k = 0; k < 2; k++)
            for (mi = 0; mi < 2; mi++)
                if (fst[k][mi] == SCALE_FIT_OK && j < fit[k][mi].n_terms)
                    printf(" %.2f |", fit[k][mi].coef[j]);
                else
                    printf(" - |");
        printf("\n");
    }
    printf("| R^2 |");
    for (k = 0; k < 2; k++)
        for (mi = 0; mi < 2; mi++)
            printf(fst[k][mi] == SCALE_FIT_OK ? " %.4f |" : " - |", fit[k][mi].r2);
    printf("\n| largest error |");
    for (k = 0; k < 2; k++)
        for (mi = 0; mi < 2; mi++)
            printf(fst[k][mi] == SCALE_FIT_OK ? " %.1f%% |" : " - |",
                   100.0 * fit[k][mi].max_rel_err);
    printf("\n| runs, condition number |");
    for (k = 0; k < 2; k++)
        for (mi = 0; mi < 2; mi++)
            printf(" %d, %.1f |", fit[k][mi].n_runs, fit[k][mi].cond);
    printf("\n");
    for (k = 0; k < 2; k++)
        for (mi = 0; mi < 2; mi++)
            if (fst[k][mi] != SCALE_FIT_OK)
                printf("\n%s fit (%d terms) failed: %s.\n", modes[mi], k ? TERMS_EXT : TERMS,
                       scale_fit_strerror(fst[k][mi]));

    printf("\n### Frames per second: estimates from instruction counts\n\n");
    printf("**Estimates, not measurements**: instructions per frame / clock, assuming about "
           "one\n");
    printf("instruction per cycle, no flash wait states and no bus or display time, at "
           "168 MHz for a\n");
    printf("Cortex-M4 (STM32F4 class) and 133 MHz for a Cortex-M0+ (RP2040 class) running "
           "the Cortex-M0\n");
    printf("code. Real boards are slower: wait states, multi-cycle loads and branches, and "
           "the SPI\n");
    printf("transfer unless DMA overlaps it. Bench scenes: the Cortex-M4 and Cortex-M0 "
           "counts of the\n");
    printf("first table (QEMU, mean of its frames).\n\n");
    printf("| scene | mode | Cortex-M4 instr | M4 @ 168 MHz, fps (est.) | Cortex-M0 instr | "
           "M0+ @ 133 MHz, fps (est.) |\n");
    printf("| ----- | ---- | --------------: | -----------------------: | --------------: | "
           "------------------------: |\n");
    {
        int shown = 0;
        for (i = 0; i < rp.n_fw; i++) {
            const fw_scene *w = &rp.fw[i];
            char a[32], b[32] = "-", fa[32], fb[32] = "-";
            double m4, m0;
            if (strcmp(w->board, "mps2-an386"))
                continue;
            m4 = w->sum / w->n;
            m0 = m0_mean(&rp, w->scene, w->mode);
            fmt_count(a, sizeof a, m4);
            snprintf(fa, sizeof fa, "%.0f", M4_HZ / m4);
            if (m0 > 0) {
                fmt_count(b, sizeof b, m0);
                snprintf(fb, sizeof fb, "%.0f", M0_HZ / m0);
            }
            printf("| %s | %s | %s | %s | %s | %s |\n", w->scene, w->mode, a, fa, b, fb);
            shown++;
        }
        if (!shown)
            printf("| (no Cortex-M figures: they come from `make bench`) | | | | | |\n");
    }

    /* the spheres: host counts scaled by the bench scenes' Cortex-M / host ratio */
    for (mi = 0; mi < 2; mi++) {
        n_r4[mi] = cm_ratio(&rp, "m4", modes[mi], &r4[mi], &r4lo[mi], &r4hi[mi]);
        n_r0[mi] = cm_ratio(&rp, "m0", modes[mi], &r0[mi], &r0lo[mi], &r0hi[mi]);
    }
    if (n_r4[0] && n_r4[1] && n_r0[0] && n_r0[1]) {
        printf("\nThe spheres and sizes, estimated twice over: host instructions x the mean "
               "ratio of Cortex-M\n");
        printf("to host instructions over the bench scenes at 240x240 (M4/host: span %.2f "
               "(%.2f-%.2f), zline\n",
               r4[0], r4lo[0], r4hi[0]);
        printf("%.2f (%.2f-%.2f); M0/host: span %.2f (%.2f-%.2f), zline %.2f (%.2f-%.2f); "
               "range over the\n",
               r4[1], r4lo[1], r4hi[1], r0[0], r0lo[0], r0hi[0], r0[1], r0lo[1], r0hi[1]);
        printf("scenes in brackets), then / clock as above.\n\n");
        printf("| case | size | tris | M4 fps span (est.) | M4 fps zline (est.) | M0+ fps span "
               "(est.) | M0+ fps zline (est.) |\n");
        printf("| ---- | ---- | ---: | -----------------: | ------------------: | "
               "------------------: | -------------------: |\n");
        for (i = 0; i < rp.n_runs; i++) {
            const run_line *r = &rp.runs[i], *z;
            if (strcmp(r->mode, "span") || strncmp(r->name, "sphere", 6) ||
                !strcmp(r->name, "sphere285") || strstr(r->name, "sphere285-") ||
                r->instr <= 0)
                continue;
            z = find_run(&rp, r->name, "zline");
            if (!z || z->instr <= 0)
                continue;
            printf("| %s | %ux%u | %u | %.0f | %.0f | %.0f | %.0f |\n", r->name, r->w, r->h,
                   r->tris, M4_HZ / (r->instr * r4[0]), M4_HZ / (z->instr * r4[1]),
                   M0_HZ / (r->instr * r0[0]), M0_HZ / (z->instr * r0[1]));
        }
    }
    return ret;
}

/* ------------------------------------------------------------------ */

static void usage(void)
{
    fprintf(stderr,
            "usage: bench_scale stats [--quick] [--case NAME] [--frames N]\n"
            "       bench_scale run NAME span|zline --caps T,V,E [--frames N]\n"
            "       bench_scale report --stats FILE --cg FILE [--fw FILE]...\n"
            "       bench_scale list [--quick]\n");
}

static int parse_frames(const char *s)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*end || v < 1 || v > MAX_FRAMES) {
        fprintf(stderr, "bench_scale: --frames takes 1..%d, not '%s'\n", MAX_FRAMES, s);
        return -1;
    }
    return (int)v;
}

int main(int argc, char **argv)
{
    int i, quick = 0, frames = DEFAULT_FRAMES;
    const char *only = NULL, *caps_arg = NULL, *stats = NULL, *cg = NULL;
    const char *fw[8];
    int n_fw = 0, first_opt = 2;
    if (argc < 2) {
        usage();
        return 2;
    }
    if (!strcmp(argv[1], "run"))
        first_opt = 4;
    if (argc < first_opt) {
        usage();
        return 2;
    }
    for (i = first_opt; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--case") && i + 1 < argc)
            only = argv[++i];
        else if (!strcmp(argv[i], "--frames") && i + 1 < argc) {
            if ((frames = parse_frames(argv[++i])) < 0)
                return 2;
        } else if (!strcmp(argv[i], "--caps") && i + 1 < argc)
            caps_arg = argv[++i];
        else if (!strcmp(argv[i], "--stats") && i + 1 < argc)
            stats = argv[++i];
        else if (!strcmp(argv[i], "--cg") && i + 1 < argc)
            cg = argv[++i];
        else if (!strcmp(argv[i], "--fw") && i + 1 < argc && n_fw < 8)
            fw[n_fw++] = argv[++i];
        else {
            fprintf(stderr, "bench_scale: unknown argument '%s'\n", argv[i]);
            usage();
            return 2;
        }
    }
    if (!strcmp(argv[1], "list")) {
        for (i = 0; i < CASE_COUNT; i++)
            if (!quick || cases[i].quick)
                printf("%s\n", cases[i].name);
        return 0;
    }
    if (!strcmp(argv[1], "stats")) {
        if (only && !case_find(only)) {
            fprintf(stderr, "bench_scale: no case '%s' (bench_scale list)\n", only);
            return 2;
        }
        return cmd_stats(only, quick, frames);
    }
    if (!strcmp(argv[1], "run"))
        return cmd_run(argv[2], argv[3], caps_arg, frames);
    if (!strcmp(argv[1], "report")) {
        if (!stats || !cg) {
            usage();
            return 2;
        }
        return cmd_report(stats, cg, fw, n_fw);
    }
    usage();
    return 2;
}
