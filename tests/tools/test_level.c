/* SPDX-License-Identifier: MIT */
/*
 * Tests of portal levels: the level format (tools/level), the PVS
 * precomputation and the core's portal walk (src/portal.c).
 *
 *  - Format: bad level files (no header, unknown keywords, bad numbers,
 *    unclosed cells, portals between unknown cells, out-of-range indices,
 *    non-convex cells, portals off the cells' edges, overlapping cells, ...)
 *    are refused with a message naming the line or the cell; a good file
 *    survives write -> parse unchanged.
 *  - The stabbing linear program against an independent oracle: a sweep of
 *    line directions with, per direction, the interval of feasible offsets
 *    (doubles); wherever the sweep finds a strictly feasible line the exact
 *    test must say yes, and where the exact test says no the sweep must find
 *    nothing.
 *  - Conservative PVS: on 22 random levels (mazes and buildings), from 100
 *    eye positions per cell and 360 rays each (traced cell to cell on the
 *    plan, in doubles, independent of the PVS code), every cell a ray reaches
 *    is in the eye cell's PVS. Tightness (PVS size over the sampled-visible
 *    set) is printed: mean and worst.
 *  - Frames: on the same levels, from random eyes in every cell looking in
 *    random directions, drawing with PVS + portal culling and with the PVS
 *    alone gives the same bytes as drawing every cell, in span and zline
 *    modes; no frame shows the background (the levels are closed, so a
 *    crack or a wrongly wound face would); the statistics add up.
 *    LEVEL_TEST_FULL=1 (make check-portals-full) renders from 100 eyes per
 *    cell instead of 3.
 *  - Mesh import (groups cell_NAME and portal_A_B): two rooms and a door from
 *    an OBJ give the expected cells, opening and walls; unknown cells, other
 *    group names and a door off the rooms' outlines are refused by name.
 *  - The emitted C (the bench level, converted at build time by zspan-level c)
 *    equals the level built in memory from the same file, array by array.
 *  - A walk that runs out of its budget falls back to the whole PVS.
 *  - The core refuses malformed level data (every check of zs_level_check)
 *    with ZS_ERR_LEVEL and submits nothing; zs_project_point agrees with the
 *    vertices the renderer itself projects (setup hook).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_level.h"
#include "level.h"
#include "level_import.h"

#define N_LEVELS 22
#define PI_D 3.14159265358979323846
#define EYES_PER_CELL 100
#define RAYS_PER_EYE 360

/* ---------------- helpers ---------------- */

static uint32_t g_rng = 12345u;
static uint32_t rnd(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 17;
    g_rng ^= g_rng << 5;
    return g_rng;
}
static double rndf(void)
{
    return (rnd() >> 8) / 16777216.0;
}

static void make_level(int i, lv_level *lv)
{
    lv_generate(lv, i % 2 ? LV_BUILDING : LV_MAZE, 4 + i % 3, 3 + (i / 3) % 3, 1000u + (uint32_t)i);
}

static int pvs_has(const uint8_t *pvs, int ncells, int from, int to)
{
    int rb = (ncells + 7) / 8;
    return (pvs[from * rb + to / 8] >> (to % 8)) & 1;
}

/* Distance from p to segment a-b. */
static double seg_dist(const double *p, const int *a, const int *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], t;
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/* A random point of cell c at least margin from its sides (plan units): walls,
 * and portals, whose steps and lintels are faces too. */
static int sample_eye(const lv_level *lv, int c, double margin, double p[2])
{
    const lv_cell *cell = &lv->cells[c];
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    int k, tries;
    for (k = 0; k < cell->nv; k++) {
        const int *q = lv->xy[cell->v[k]];
        lo[0] = fmin(lo[0], q[0]);
        lo[1] = fmin(lo[1], q[1]);
        hi[0] = fmax(hi[0], q[0]);
        hi[1] = fmax(hi[1], q[1]);
    }
    for (tries = 0; tries < 10000; tries++) {
        int ok = 1;
        p[0] = lo[0] + rndf() * (hi[0] - lo[0]);
        p[1] = lo[1] + rndf() * (hi[1] - lo[1]);
        for (k = 0; k < cell->nv && ok; k++) {
            const int *a = lv->xy[cell->v[k]], *b = lv->xy[cell->v[(k + 1) % cell->nv]];
            double cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            if (cr <= 0)
                ok = 0;
            else if (seg_dist(p, a, b) < margin)
                ok = 0;
        }
        if (ok)
            return 1;
    }
    return 0;
}

/* Traces a plan ray from p in cell c; marks every cell it enters. */
static void trace(const lv_level *lv, int c, const double p0[2], double ang, uint8_t *seen)
{
    double p[2] = {p0[0], p0[1]}, d[2] = {cos(ang), sin(ang)};
    int steps;
    seen[c] = 1;
    for (steps = 0; steps < 4 * lv->ncells; steps++) {
        const lv_cell *cell = &lv->cells[c];
        double best = 1e300;
        int k, be = -1;
        for (k = 0; k < cell->nv; k++) {
            const int *a = lv->xy[cell->v[k]], *b = lv->xy[cell->v[(k + 1) % cell->nv]];
            double nx = b[1] - a[1], ny = -(b[0] - a[0]); /* outward */
            double nd = nx * d[0] + ny * d[1], t;
            if (nd <= 0)
                continue;
            t = (nx * (a[0] - p[0]) + ny * (a[1] - p[1])) / nd;
            if (t < best) {
                best = t;
                be = k;
            }
        }
        if (be < 0)
            return;
        p[0] += best * d[0];
        p[1] += best * d[1];
        /* collinear edges (a door in a wall) tie in t: take the one whose
         * segment holds the exit point */
        for (k = 0; k < cell->nv; k++) {
            const int *a = lv->xy[cell->v[k]], *b = lv->xy[cell->v[(k + 1) % cell->nv]];
            double ex = b[0] - a[0], ey = b[1] - a[1];
            double cr = ex * (p[1] - a[1]) - ey * (p[0] - a[0]);
            double s = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey);
            if (fabs(cr) < 1e-7 * (ex * ex + ey * ey) && s >= 0 && s <= 1 &&
                (b[1] - a[1]) * d[0] - (b[0] - a[0]) * d[1] > 0) {
                be = k;
                break;
            }
        }
        if (cell->edge_kind[be] < 0)
            return;
        {
            const lv_portal *pt = &lv->portals[cell->edge_kind[be]];
            c = pt->a == c ? pt->b : pt->a;
        }
        seen[c] = 1;
    }
}

/* ---------------- format ---------------- */

static const char k_good[] = "zspan-level 1\n"
                             "# two rooms and a door\n"
                             "unit 4\n"
                             "vertex 0 0\nvertex 10 0\nvertex 10 4\nvertex 10 6\nvertex 10 10\n"
                             "vertex 0 10\nvertex 20 0\nvertex 20 10\n"
                             "cell 0 12 0 1 2 3 4 5\n"
                             "cell 1 10 1 6 7 4 3 2\n"
                             "wall 0 1\nwall 3 4\nwall 4 5\nwall 5 0\nwall 1 2\n"
                             "wall 1 6\nwall 6 7\nwall 7 4\n"
                             "portal 0 1 2 3\n";

typedef struct bad_case {
    const char *text;
    const char *message; /* a part of the expected message */
} bad_case;

static void test_bad_files(void **state)
{
    static const bad_case cases[] = {
        {"", "empty file"},
        {"zspan-level 2\n", "not a level file"},
        {"zspan-level 1\nroom 1 2\n", "t:2: unknown keyword \"room\""},
        {"zspan-level 1\nvertex 1 x\n", "t:2: \"x\" is not an integer"},
        {"zspan-level 1\nvertex 1 99999\n", "is not an integer in [-16384, 16384]"},
        {"zspan-level 1\nunit 3\n", "unit needs one power of two"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 7\n",
         "t:5: cell 0: vertex 7 out of range"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 4 4 0 1 2\n",
         "floor 4 is not below ceiling 4"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 2\nwall 0 1\nwall 1 2\n",
         "cell 0 is not closed: its edge from vertex 2 to vertex 0 is neither a wall nor a portal"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 2 1\nwall 0 1\nwall 1 2\n"
         "wall 2 0\n",
         "cell 0 is not convex and counter-clockwise"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 2\nportal 0 3 0 1\n",
         "t:6: portal between unknown cells 0 and 3"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 2\nwall 0 9\n",
         "t:6: wall: vertex out of range"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\nvertex 1 1\ncell 0 4 0 1 2\n"
         "cell 0 4 1 3 2\nwall 0 1\nwall 2 0\nwall 1 3\nwall 3 2\nportal 0 1 0 1\n",
         "t:12: portal 0-1 is not an edge of cell 1"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\nvertex 1 1\ncell 0 4 0 1 2\n"
         "cell 5 9 1 3 2\nwall 0 1\nwall 2 0\nwall 1 3\nwall 3 2\nportal 0 1 1 2\n",
         "has no opening"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 2\nwall 0 1\nwall 1 2\n"
         "wall 2 0\nwall 0 1\n",
         "t:9: wall 0-1 is given twice"},
        {"zspan-level 1\nvertex 0 0\nvertex 4 0\nvertex 0 4\nvertex 1 1\nvertex 5 1\nvertex 1 5\n"
         "cell 0 4 0 1 2\ncell 0 4 3 4 5\nwall 0 1\nwall 1 2\nwall 2 0\nwall 3 4\nwall 4 5\n"
         "wall 5 3\n",
         "cells 0 and 1 overlap"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\nvertex 5 5\ncell 0 4 0 1 2\n"
         "wall 0 1\nwall 1 2\nwall 2 0\nwall 0 3\n",
         "t:10: wall 0-3 is not an edge of any cell"},
        {"zspan-level 1\nvertex 0 0\nvertex 1 0\nvertex 0 1\ncell 0 4 0 1 2\nportal 0 0 0 1\n",
         "portal from cell 0 to itself"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lv_level lv;
        char err[512] = "";
        int rc = lv_parse(cases[i].text, "t", &lv, err, sizeof err);
        if (rc == 0 || !strstr(err, cases[i].message))
            print_error("case %zu: rc %d, message \"%s\", expected \"%s\"\n", i, rc, err,
                        cases[i].message);
        assert_int_equal(rc, -1);
        assert_non_null(strstr(err, cases[i].message));
    }
}

static void test_good_file_round_trip(void **state)
{
    lv_level a, b;
    char err[512];
    char *buf = NULL;
    size_t len = 0;
    FILE *f;
    int i, k;
    (void)state;
    assert_int_equal(lv_parse(k_good, "good", &a, err, sizeof err), 0);
    assert_int_equal(a.ncells, 2);
    assert_int_equal(a.nportals, 1);
    assert_int_equal(a.unit, 4);
    f = open_memstream(&buf, &len);
    assert_int_equal(lv_write(f, &a), 0);
    fclose(f);
    assert_int_equal(lv_parse(buf, "again", &b, err, sizeof err), 0);
    assert_int_equal(a.nverts, b.nverts);
    assert_int_equal(a.nwalls, b.nwalls);
    for (i = 0; i < a.nverts; i++)
        assert_memory_equal(a.xy[i], b.xy[i], sizeof a.xy[i]);
    for (i = 0; i < a.ncells; i++) {
        assert_int_equal(a.cells[i].nv, b.cells[i].nv);
        assert_int_equal(a.cells[i].floor, b.cells[i].floor);
        assert_int_equal(a.cells[i].ceiling, b.cells[i].ceiling);
        for (k = 0; k < a.cells[i].nv; k++)
            assert_int_equal(a.cells[i].v[k], b.cells[i].v[k]);
    }
    /* the two rooms see each other and the built level passes the core's check */
    {
        uint8_t *pvs = lv_compute_pvs(&a, NULL);
        lv_built built;
        assert_true(pvs_has(pvs, 2, 0, 1) && pvs_has(pvs, 2, 1, 0));
        assert_int_equal(lv_build(&a, pvs, &built, err, sizeof err), 0);
        assert_int_equal(zs_level_check(&built.level), ZS_OK);
        assert_int_equal(built.level.portal_count, 2);
        lv_built_free(&built);
    }
    lv_free(&a);
    lv_free(&b);
    free(buf);
}

/* ---------------- the stabbing LP ---------------- */

/* Best slack of any line over a sweep of directions: for direction angle
 * th, normal n = (-sin, cos); left points need n.p + c >= 0, right ones
 * n.p + c <= 0, so c in [max(-n.l), min(-n.r)]. */
static double sweep_slack(const int (*l)[2], const int (*r)[2], int n)
{
    double best = -1e300;
    int s, i;
    for (s = 0; s < 7200; s++) {
        double th = s * (2 * PI_D / 7200), nx = -sin(th), ny = cos(th), lo = -1e300, hi = 1e300;
        for (i = 0; i < n; i++) {
            lo = fmax(lo, -(nx * l[i][0] + ny * l[i][1]));
            hi = fmin(hi, -(nx * r[i][0] + ny * r[i][1]));
        }
        best = fmax(best, hi - lo);
    }
    return best;
}

static void test_stabbing_lp(void **state)
{
    int trial, yes = 0, no = 0;
    (void)state;
    g_rng = 777u;
    /* hand cases: a straight corridor of doors, then one shifted out of line */
    {
        int l[3][2] = {{0, 2}, {10, 2}, {20, 2}}, r[3][2] = {{0, 0}, {10, 0}, {20, 0}};
        assert_true(lv_stabbable((const int(*)[2])l, 3, (const int(*)[2])r, 3));
        l[1][1] = 12;
        r[1][1] = 10;
        assert_false(lv_stabbable((const int(*)[2])l, 3, (const int(*)[2])r, 3));
        /* grazing: only the line y = 2 through both corners */
        l[1][1] = 4;
        r[1][1] = 2;
        assert_true(lv_stabbable((const int(*)[2])l, 3, (const int(*)[2])r, 3));
    }
    for (trial = 0; trial < 3000; trial++) {
        int n = 2 + (int)(rnd() % 3), i, exact;
        int l[4][2], r[4][2];
        double slack;
        for (i = 0; i < n; i++) {
            /* portals along +x roughly, each a vertical-ish segment */
            int x = i * 10 + (int)(rnd() % 5), y = (int)(rnd() % 12) - 6, h = 1 + (int)(rnd() % 6);
            r[i][0] = x;
            r[i][1] = y;
            l[i][0] = x + (int)(rnd() % 3) - 1;
            l[i][1] = y + h;
        }
        exact = lv_stabbable((const int(*)[2])l, n, (const int(*)[2])r, n);
        slack = sweep_slack((const int(*)[2])l, (const int(*)[2])r, n);
        if (slack > 1e-2)
            assert_true(exact);
        if (!exact)
            assert_true(slack < 1e-9);
        if (exact)
            yes++;
        else
            no++;
    }
    /* both answers occur */
    assert_true(yes > 300 && no > 300);
}

/* ---------------- conservative and tight PVS ---------------- */

static void test_pvs_conservative(void **state)
{
    int li;
    double sum_ratio = 0, worst = 0;
    long n_ratio = 0, rays = 0;
    unsigned long long sequences = 0;
    (void)state;
    g_rng = 4242u;
    for (li = 0; li < N_LEVELS; li++) {
        lv_level lv;
        uint8_t *pvs, *seen, *vis_any;
        int c, e, k, missing = 0;
        lv_pvs_stats ps;
        make_level(li, &lv);
        pvs = lv_compute_pvs(&lv, &ps);
        sequences += ps.sequences;
        seen = malloc((size_t)lv.ncells);
        vis_any = malloc((size_t)lv.ncells);
        for (c = 0; c < lv.ncells; c++) {
            int npvs = 0, nvis = 0;
            memset(vis_any, 0, (size_t)lv.ncells);
            for (e = 0; e < EYES_PER_CELL; e++) {
                double p[2];
                assert_true(sample_eye(&lv, c, 0.01, p));
                memset(seen, 0, (size_t)lv.ncells);
                for (k = 0; k < RAYS_PER_EYE; k++)
                    trace(&lv, c, p, (k + rndf()) * (2 * PI_D / RAYS_PER_EYE), seen);
                rays += RAYS_PER_EYE;
                for (k = 0; k < lv.ncells; k++)
                    if (seen[k]) {
                        vis_any[k] = 1;
                        if (!pvs_has(pvs, lv.ncells, c, k)) {
                            if (missing++ < 5)
                                print_error("level %d: a ray from cell %d reaches cell %d, not "
                                            "in the PVS\n",
                                            li, c, k);
                        }
                    }
            }
            for (k = 0; k < lv.ncells; k++) {
                npvs += pvs_has(pvs, lv.ncells, c, k);
                nvis += vis_any[k];
            }
            sum_ratio += (double)npvs / nvis;
            worst = fmax(worst, (double)npvs / nvis);
            n_ratio++;
        }
        assert_int_equal(missing, 0);
        free(seen);
        free(vis_any);
        free(pvs);
        lv_free(&lv);
    }
    printf("pvs: %d levels, %ld cells, %ld rays: nothing missing; PVS / sampled-visible: mean "
           "%.3f, worst %.3f; %llu portal sequences tested\n",
           N_LEVELS, n_ratio, rays, sum_ratio / (double)n_ratio, worst, sequences);
}

/* ---------------- frames ---------------- */

/* Two views: a small screen at 70 degrees, and a larger one at 110 degrees
 * looking up and down steeply (eyes farther from the faces there, as the
 * near plane's corners reach farther). */
typedef struct frame_cfg {
    int w, h, fov, eyes, eyes_full;
    double pitch, margin;
} frame_cfg;

static const frame_cfg k_frames[2] = {{120, 90, 70, 3, 100, 1.0, 0.5},
                                      {320, 240, 110, 1, 10, 2.6, 0.8}};
#define FMAX (320 * 240)
#define BACKGROUND ZS_RGB(255, 0, 255)

static zs_fixed fxd(double v)
{
    return (zs_fixed)lround(v * 65536.0);
}

static void frame(zs_renderer *r, const zs_level *lv, const zs_camera *cam, zs_vec3 eye,
                  zs_visibility mode, zs_level_cull cull, uint8_t *img, zs_level_stats *ls)
{
    int y, fw = r->cfg.width, fh = r->cfg.height;
    zs_shade_params sp = zs_shade_default();
    sp.format = ZS_FMT_RGB888;
    sp.background = BACKGROUND;
    sp.light_count = 1;
    sp.lights[0].direction = zs_vec3_make(ZS_FX(1), ZS_FX(3), ZS_FX(2));
    sp.lights[0].intensity = ZS_FX_ONE / 2;
    sp.ambient = ZS_FX_ONE / 2;
    assert_int_equal(zs_frame_begin(r, cam, mode), ZS_OK);
    assert_int_equal(zs_frame_shading(r, &sp), ZS_OK);
    assert_int_equal(zs_level_draw(r, lv, eye, cull, ls), ZS_OK);
    for (y = 0; y < fh; y++)
        assert_int_equal(zs_render_rows(r, y, 1, img + (size_t)y * (size_t)fw * 3, (size_t)fw * 3),
                         ZS_OK);
}

static void frames_equal(const frame_cfg *fc)
{
    int li, eyes = getenv("LEVEL_TEST_FULL") ? fc->eyes_full : fc->eyes;
    long frames = 0, culled = 0, total = 0, narrowed = 0;
    const int FW = fc->w, FH = fc->h;
    size_t bytes = (size_t)FW * FH * 3;
    static uint8_t img[FMAX * 3], ref[FMAX * 3];
    for (li = 0; li < N_LEVELS; li++) {
        lv_level lv;
        lv_built b;
        char err[256];
        zs_renderer r;
        zs_config cfg;
        void *arena;
        int c, e;
        make_level(li, &lv);
        assert_int_equal(lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err), 0);
        cfg = zs_config_default((uint16_t)FW, (uint16_t)FH, (uint16_t)(b.total_tris * 3), (uint16_t)(b.total_tris * 4),
                                2048);
        arena = malloc(zs_arena_bytes(&cfg));
        assert_int_equal(zs_init(&r, arena, zs_arena_bytes(&cfg), &cfg), ZS_OK);
        for (c = 0; c < lv.ncells; c++)
            for (e = 0; e < eyes; e++) {
                double p[2], yaw = rndf() * 2 * PI_D, pitch = (rndf() - 0.5) * fc->pitch, u = 0.25;
                double h = lv.cells[c].floor + fc->margin +
                           rndf() * (lv.cells[c].ceiling - lv.cells[c].floor - 2 * fc->margin);
                zs_camera cam;
                zs_vec3 eye, tgt;
                zs_level_stats ls, lp, la;
                int m, i;
                assert_true(sample_eye(&lv, c, fc->margin, p));
                eye = zs_vec3_make(fxd(p[0] * u), fxd(h * u), fxd(-p[1] * u));
                tgt = zs_vec3_make(fxd(p[0] * u + cos(yaw) * cos(pitch)), fxd(h * u + sin(pitch)),
                                   fxd(-p[1] * u - sin(yaw) * cos(pitch)));
                assert_int_equal(zs_camera_look_at(&cam, eye, tgt, zs_vec3_make(0, ZS_FX_ONE, 0)),
                                 ZS_OK);
                assert_int_equal(zs_camera_perspective(&cam, ZS_FX(fc->fov), ZS_FX_ONE / 20, ZS_FX(200)),
                                 ZS_OK);
                for (m = 0; m < 2; m++) {
                    zs_visibility mode = m ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
                    frame(&r, &b.level, &cam, eye, mode, ZS_LEVEL_CULL_NONE, ref, &la);
                    for (i = 0; i < FW * FH; i++)
                        if (ref[3 * i] == 255 && ref[3 * i + 1] == 0 && ref[3 * i + 2] == 255) {
                            print_error("level %d cell %d: background at pixel (%d, %d), eye "
                                        "%.9g %.9g %.9g target %.9g %.9g %.9g\n",
                                        li, c, i % FW, i / FW, eye.x / 65536.0, eye.y / 65536.0,
                                        eye.z / 65536.0, tgt.x / 65536.0, tgt.y / 65536.0,
                                        tgt.z / 65536.0);
                            fail();
                        }
                    frame(&r, &b.level, &cam, eye, mode, ZS_LEVEL_CULL_PORTALS, img, &ls);
                    if (memcmp(img, ref, bytes)) {
                        print_error("level %d cell %d eye %d %s: portal culling changes the "
                                    "frame\n",
                                    li, c, e, m ? "zline" : "span");
                        fail();
                    }
                    frame(&r, &b.level, &cam, eye, mode, ZS_LEVEL_CULL_PVS, img, &lp);
                    assert_memory_equal(img, ref, bytes);
                    /* statistics */
                    assert_int_equal(ls.eye_cell, c);
                    assert_int_equal(la.cells_drawn, lv.ncells);
                    assert_int_equal(la.tris_submitted, b.total_tris);
                    assert_int_equal(ls.tris_submitted + ls.tris_culled, b.total_tris);
                    assert_int_equal(lp.cells_drawn, lp.pvs_cells);
                    assert_true(ls.cells_drawn <= ls.pvs_cells);
                    assert_true(ls.cells_visited >= ls.cells_drawn);
                    assert_int_equal(ls.fallback, 0);
                    assert_int_equal(zs_frame_stats(&r)->tris_submitted, lp.tris_submitted);
                    frames++;
                    culled += ls.tris_culled;
                    total += b.total_tris;
                    narrowed += ls.cells_drawn < ls.pvs_cells;
                }
            }
        free(arena);
        lv_built_free(&b);
        lv_free(&lv);
    }
    printf("frames %dx%d, fov %d: %ld pairs equal (span and zline, portals and PVS against every "
           "cell); %.1f%% of triangles culled; the walk drew fewer cells than the PVS in %ld\n",
           FW, FH, fc->fov, frames, 100.0 * (double)culled / (double)total, narrowed);
    /* the culling is real: most triangles are never submitted */
    assert_true(culled * 2 > total);
    assert_true(narrowed > 0);
}

static void test_frames_equal(void **state)
{
    (void)state;
    g_rng = 99u;
    frames_equal(&k_frames[0]);
    frames_equal(&k_frames[1]);
}

/* ---------------- mesh import ---------------- */

/* Room A: plan [0,2.5]^2, heights 0..3; room B: [2.5,5]x[0,2.5], heights
 * 0..2.5; a door in their shared side x = DOOR_X, plan y 1..1.5. The third
 * group's name is GROUP. */
static void write_rooms(const char *file, const char *door_x, const char *group)
{
    FILE *f = fopen(file, "w");
    assert_non_null(f);
    fprintf(f, "v 0 0 0\nv 2.5 0 0\nv 2.5 0 -2.5\nv 0 0 -2.5\nv 0 3 0\nv 2.5 3 -2.5\n"
               "v 5 0 0\nv 5 0 -2.5\nv 5 2.5 0\n"
               "g cell_A\nf 1 2 3\nf 1 3 4\nf 5 2 6\n"
               "g cell_B\nf 2 7 8\nf 2 8 3\nf 9 2 8\n"
               "g %s\nv %s 0 -1.0\nv %s 0 -1.5\nv %s 2.5 -1.5\nv %s 2.5 -1.0\nf 10 11 12 13\n",
            group, door_x, door_x, door_x, door_x);
    fclose(f);
}

static void test_import_mesh(void **state)
{
    char dir[] = "/tmp/zspan-level-XXXXXX", file[64], err[600];
    lv_level lv;
    int k, a = -1, b = -1;
    (void)state;
    assert_non_null(mkdtemp(dir));
    snprintf(file, sizeof file, "%s/rooms.obj", dir);
    write_rooms(file, "2.5", "portal_A_B");
    k = lv_import_mesh(file, 16, &lv, err, sizeof err);
    if (k != 0)
        print_error("%s\n", err);
    assert_int_equal(k, 0);
    assert_int_equal(lv.ncells, 2);
    assert_int_equal(lv.nportals, 1);
    assert_int_equal(lv.unit, 16);
    assert_int_equal(lv.cells[0].floor, 0);
    assert_int_equal(lv.cells[0].ceiling, 48);
    assert_int_equal(lv.cells[1].ceiling, 40);
    /* A: its four corners and the door's two ends on its right side */
    assert_int_equal(lv.cells[0].nv, 6);
    assert_int_equal(lv.cells[1].nv, 6);
    for (k = 0; k < lv.nverts; k++) {
        if (lv.xy[k][0] == 40 && lv.xy[k][1] == 16)
            a = k;
        if (lv.xy[k][0] == 40 && lv.xy[k][1] == 24)
            b = k;
    }
    assert_true(a >= 0 && b >= 0);
    assert_true((lv.portals[0].va == a && lv.portals[0].vb == b) ||
                (lv.portals[0].va == b && lv.portals[0].vb == a));
    /* 6 + 6 sides, 2 of them the opening: the other 10 are walls, the two
     * pieces of the shared side beside the door once each */
    assert_int_equal(lv.nwalls, 8);
    {
        uint8_t *pvs = lv_compute_pvs(&lv, NULL);
        assert_true(pvs_has(pvs, 2, 0, 1) && pvs_has(pvs, 2, 1, 0));
        free(pvs);
    }
    lv_free(&lv);
    /* refusals */
    write_rooms(file, "2.5", "portal_A_C");
    assert_int_equal(lv_import_mesh(file, 16, &lv, err, sizeof err), -1);
    assert_non_null(strstr(err, "portal_A_C: a portal between unknown cells (no cell_C)"));
    write_rooms(file, "2.5", "door");
    assert_int_equal(lv_import_mesh(file, 16, &lv, err, sizeof err), -1);
    assert_non_null(strstr(err, "group \"door\" is neither cell_NAME nor portal_A_B"));
    write_rooms(file, "2.4", "portal_A_B");
    assert_int_equal(lv_import_mesh(file, 16, &lv, err, sizeof err), -1);
    assert_non_null(strstr(err, "is not on the outline of cell_"));
    assert_int_equal(lv_import_mesh(file, 3, &lv, err, sizeof err), -1);
    assert_non_null(strstr(err, "unit must be a power of two"));
    remove(file);
    assert_int_equal(lv_import_mesh(file, 16, &lv, err, sizeof err), -1);
    assert_non_null(strstr(err, file));
    rmdir(dir);
}

/* ---------------- the emitted C, the walk's fallback ---------------- */

static void test_emitted_c(void **state)
{
    lv_level lv;
    lv_built b;
    char err[512];
    const zs_level *e = &bench_level;
    int c, rb;
    (void)state;
    assert_int_equal(lv_load(LEVEL_FILE, &lv, err, sizeof err), 0);
    assert_int_equal(lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err), 0);
    assert_int_equal(e->cell_count, b.level.cell_count);
    assert_int_equal(e->portal_count, b.level.portal_count);
    assert_int_equal(e->vertex_count, b.level.vertex_count);
    assert_int_equal(e->unit, b.level.unit);
    rb = (e->cell_count + 7) / 8;
    assert_memory_equal(e->vertices, b.level.vertices, sizeof(int16_t) * 2 * e->vertex_count);
    assert_memory_equal(e->cells, b.level.cells, sizeof(zs_level_cell) * e->cell_count);
    assert_memory_equal(e->portals, b.level.portals, sizeof(zs_level_portal) * e->portal_count);
    assert_memory_equal(e->pvs, b.level.pvs, (size_t)rb * e->cell_count);
    for (c = 0; c < e->cell_count; c++) {
        const zs_mesh *x = &e->meshes[c], *y = &b.level.meshes[c];
        assert_int_equal(x->vertex_count, y->vertex_count);
        assert_int_equal(x->triangle_count, y->triangle_count);
        assert_int_equal(x->scale, y->scale);
        assert_memory_equal(x->positions, y->positions, sizeof(int16_t) * 3 * x->vertex_count);
        assert_memory_equal(x->indices, y->indices, sizeof(uint16_t) * 3 * x->triangle_count);
        assert_memory_equal(x->face_colors, y->face_colors, sizeof(zs_color) * x->triangle_count);
    }
    assert_int_equal(zs_level_check(e), ZS_OK);
    assert_int_equal(bench_level_TRIANGLES, b.total_tris);
    lv_built_free(&b);
    lv_free(&lv);
}

static void test_walk_fallback(void **state)
{
    /* two rooms joined by 1000 copies of their portal each way: the walk
     * tries every chain A -> B -> A (refused: A is on the path) and runs
     * out of its budget, then draws the PVS */
    lv_level lv;
    lv_built b;
    char err[512];
    zs_level l;
    zs_level_cell cells[2];
    static zs_level_portal many[2000];
    zs_renderer r;
    zs_config cfg = zs_config_default(64, 48, 200, 200, 128);
    void *arena = malloc(zs_arena_bytes(&cfg));
    zs_camera cam;
    zs_level_stats ls;
    zs_vec3 eye = zs_vec3_make(ZS_FX(1), ZS_FX(1), -ZS_FX(1));
    int k;
    (void)state;
    assert_int_equal(lv_parse(k_good, "good", &lv, err, sizeof err), 0);
    assert_int_equal(lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err), 0);
    l = b.level;
    memcpy(cells, b.cells, sizeof cells);
    for (k = 0; k < 2000; k++)
        many[k] = b.portals[k < 1000 ? cells[0].first_portal : cells[1].first_portal];
    cells[0].first_portal = 0;
    cells[0].portal_count = 1000;
    cells[1].first_portal = 1000;
    cells[1].portal_count = 1000;
    l.cells = cells;
    l.portals = many;
    l.portal_count = 2000;
    assert_int_equal(zs_level_check(&l), ZS_OK);
    assert_int_equal(zs_init(&r, arena, zs_arena_bytes(&cfg), &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, eye, zs_vec3_make(ZS_FX(3), ZS_FX(1), -ZS_FX(1)),
                                       zs_vec3_make(0, ZS_FX_ONE, 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_ONE / 20, ZS_FX(100)), ZS_OK);
    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_level_draw(&r, &l, eye, ZS_LEVEL_CULL_PORTALS, &ls), ZS_OK);
    assert_int_equal(ls.eye_cell, 0);
    assert_int_equal(ls.fallback, 1);
    assert_int_equal(ls.portals_tested, ZS_LEVEL_WALK_BUDGET);
    assert_int_equal(ls.cells_drawn, 2);
    assert_int_equal(ls.tris_culled, 0);
    /* one copy of each: no fallback, the same cells */
    cells[0].portal_count = 1;
    cells[1].portal_count = 1;
    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_level_draw(&r, &l, eye, ZS_LEVEL_CULL_PORTALS, &ls), ZS_OK);
    assert_int_equal(ls.fallback, 0);
    assert_int_equal(ls.cells_drawn, 2);
    assert_int_equal(ls.portals_tested, 2);
    free(arena);
    lv_built_free(&b);
    lv_free(&lv);
}

/* ---------------- the core's checks ---------------- */

static void test_core_refuses_malformed(void **state)
{
    lv_level lv;
    lv_built b;
    char err[256];
    zs_level l;
    zs_level_cell *cells;
    zs_level_portal *portals;
    uint8_t *pvs;
    int16_t *verts;
    zs_mesh *meshes;
    size_t nc, np, nv, rb;
    int k;
    zs_renderer r;
    zs_config cfg = zs_config_default(64, 48, 4000, 6000, 512);
    void *arena = malloc(zs_arena_bytes(&cfg));
    zs_camera cam;
    (void)state;
    make_level(1, &lv);
    assert_int_equal(lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err), 0);
    nc = b.level.cell_count;
    np = b.level.portal_count;
    nv = b.level.vertex_count;
    rb = (nc + 7) / 8;
    cells = malloc(nc * sizeof *cells);
    portals = malloc(np * sizeof *portals);
    pvs = malloc(nc * rb);
    verts = malloc(nv * 2 * sizeof *verts);
    meshes = malloc(nc * sizeof *meshes);
    assert_int_equal(zs_init(&r, arena, zs_arena_bytes(&cfg), &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(ZS_FX(2), ZS_FX(1), -ZS_FX(2)),
                                       zs_vec3_make(ZS_FX(3), ZS_FX(1), -ZS_FX(3)),
                                       zs_vec3_make(0, ZS_FX_ONE, 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_ONE / 20, ZS_FX(100)), ZS_OK);
    for (k = 0; k < 24; k++) {
        zs_status want = ZS_ERR_LEVEL, got;
        memcpy(cells, b.cells, nc * sizeof *cells);
        memcpy(portals, b.portals, np * sizeof *portals);
        memcpy(pvs, b.pvs, nc * rb);
        memcpy(verts, b.vertices, nv * 2 * sizeof *verts);
        memcpy(meshes, b.meshes, nc * sizeof *meshes);
        l = b.level;
        l.cells = cells;
        l.portals = portals;
        l.pvs = pvs;
        l.vertices = verts;
        l.meshes = meshes;
        switch (k) {
        case 0: want = ZS_OK; break;                                   /* the copy is fine */
        case 1: pvs[rb * 3] &= (uint8_t)~(1u << 3); break;              /* cell 3 misses itself */
        case 2: pvs[rb - 1] |= 0x80; break;                            /* a bit past the cells */
        case 3: portals[0].to = (uint16_t)nc; break;                   /* unknown cell */
        case 4: portals[cells[2].first_portal].to = 2; break;          /* a portal to itself */
        case 5: { int to = portals[0].to; pvs[to / 8] &= (uint8_t)~(1u << (to % 8)); } break;
        case 6: cells[nc - 1].portal_count = (uint16_t)(np + 1); break; /* past the portals */
        case 7: cells[nc - 1].vertex_count = (uint16_t)(nv + 1); break; /* past the vertices */
        case 8: cells[0].vertex_count = 2; break;                      /* not a polygon */
        case 9: {                                                      /* clockwise */
            int16_t *v = verts + 2 * cells[0].first_vertex, t0 = v[2], t1 = v[3];
            v[2] = v[2 * (cells[0].vertex_count - 1)];
            v[3] = v[2 * (cells[0].vertex_count - 1) + 1];
            v[2 * (cells[0].vertex_count - 1)] = t0;
            v[2 * (cells[0].vertex_count - 1) + 1] = t1;
        } break;
        case 10: cells[1].floor = cells[1].ceiling; break;
        case 11: portals[1].top = portals[1].bottom; break;
        case 12: l.unit = 0; break;
        case 13: l.unit = ZS_FX(200); break;                           /* past +-32767 units */
        case 14: meshes[0].scale = l.unit * 2; break;
        case 15: l.pvs = NULL; break;
        case 16: l.cells = NULL; break;
        case 17: l.meshes = NULL; break;
        case 18: l.cell_count = 0; break;
        case 19: l.cell_count = ZS_LEVEL_MAX_CELLS + 1; break;
        case 20: verts[0] = ZS_LEVEL_MAX_COORD + 1; break;
        case 21: portals[2].ax = -ZS_LEVEL_MAX_COORD - 1; break;
        case 22: l.vertices = NULL; break;
        case 23: l.portals = NULL; break;
        }
        got = zs_level_check(&l);
        if (got != want)
            print_error("case %d: zs_level_check gives %d, expected %d\n", k, got, want);
        assert_int_equal(got, want);
        assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
        got = zs_level_draw(&r, &l, zs_vec3_make(ZS_FX(2), ZS_FX(1), -ZS_FX(2)),
                            ZS_LEVEL_CULL_PORTALS, NULL);
        assert_int_equal(got, want);
        if (want != ZS_OK)
            assert_int_equal(zs_frame_stats(&r)->tris_submitted, 0);
    }
    assert_int_equal(zs_level_check(NULL), ZS_ERR_NULL);
    assert_string_equal(zs_strerror(ZS_ERR_LEVEL),
                        "malformed level or PVS data (zspan/portal.h): a count, index, cell "
                        "polygon, portal or PVS row that zs_level_check refuses");
    /* call order and arguments */
    {
        zs_renderer fresh;
        zs_fixed xy[2], depth;
        memset(&fresh, 0, sizeof fresh);
        assert_int_equal(zs_level_draw(NULL, &b.level, zs_vec3_make(0, 0, 0), 0, NULL),
                         ZS_ERR_NULL);
        assert_int_equal(zs_level_draw(&r, &b.level, zs_vec3_make(0, 0, 0), (zs_level_cull)3,
                                       NULL),
                         ZS_ERR_ARGUMENT);
        assert_int_equal(zs_project_point(&fresh, zs_vec3_make(0, 0, 0), xy, &depth),
                         ZS_ERR_STATE);
        assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
        {
            uint8_t line[64 * 2];
            assert_int_equal(zs_render_rows(&r, 0, 1, line, sizeof line), ZS_OK);
        }
        assert_int_equal(zs_level_draw(&r, &b.level, zs_vec3_make(0, 0, 0), ZS_LEVEL_CULL_NONE,
                                       NULL),
                         ZS_ERR_STATE);
        /* behind the eye */
        assert_int_equal(zs_project_point(&r, zs_vec3_make(0, ZS_FX(1), 0), xy, &depth),
                         ZS_ERR_ARGUMENT);
    }
    free(cells);
    free(portals);
    free(pvs);
    free(verts);
    free(meshes);
    free(arena);
    lv_built_free(&b);
    lv_free(&lv);
}

/* zs_project_point against the renderer's own projection of a vertex. */
typedef struct hook_rec {
    int n;
    int32_t xy[6];
} hook_rec;

static void hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    hook_rec *h = user;
    (void)tag;
    (void)z;
    if (h->n++ == 0)
        memcpy(h->xy, xy, sizeof h->xy);
}

static void test_project_point(void **state)
{
    zs_config cfg = zs_config_default(200, 150, 16, 16, 16);
    void *arena = malloc(zs_arena_bytes(&cfg));
    zs_renderer r;
    int t, checked = 0;
    (void)state;
    g_rng = 31337u;
    assert_int_equal(zs_init(&r, arena, zs_arena_bytes(&cfg), &cfg), ZS_OK);
    for (t = 0; t < 500; t++) {
        zs_camera cam;
        zs_vec3 eye = zs_vec3_make(fxd(rndf() * 20 - 10), fxd(rndf() * 4), fxd(rndf() * 20 - 10));
        zs_vec3 tgt = zs_vec3_make(eye.x + fxd(rndf() * 2 - 1), eye.y + fxd(rndf() - 0.5),
                                   eye.z + fxd(rndf() * 2 - 1));
        int16_t pos[9];
        static const uint16_t idx[3] = {0, 1, 2};
        zs_mesh m;
        hook_rec h;
        zs_fixed xy[2], depth;
        int k;
        if (zs_camera_look_at(&cam, eye, tgt, zs_vec3_make(0, ZS_FX_ONE, 0)) != ZS_OK)
            continue;
        assert_int_equal(zs_camera_perspective(&cam, ZS_FX(20 + (int)(rnd() % 120)),
                                               ZS_FX_ONE / 10, ZS_FX(100)),
                         ZS_OK);
        /* a point in front of the eye, on integer coordinates, and a tiny
         * triangle from it in both windings (one of them is a front face) */
        for (k = 0; k < 3; k++) {
            int32_t c = (k == 0 ? tgt.x : k == 1 ? tgt.y : tgt.z) +
                        (k == 0 ? tgt.x - eye.x : k == 1 ? tgt.y - eye.y : tgt.z - eye.z) * 3;
            pos[k] = (int16_t)(c >> 16);
        }
        memcpy(pos + 3, pos, 3 * sizeof *pos);
        memcpy(pos + 6, pos, 3 * sizeof *pos);
        pos[3] += 1;
        pos[7] += 1;
        memset(&m, 0, sizeof m);
        m.positions = pos;
        m.indices = idx;
        m.scale = ZS_FX_ONE;
        m.vertex_count = 3;
        m.triangle_count = 1;
        h.n = 0;
        assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
        zs_set_setup_hook(&r, hook, &h);
        assert_int_equal(zs_draw(&r, &m, NULL), ZS_OK);
        if (h.n == 0) {
            pos[3] -= 2;
            assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
            assert_int_equal(zs_draw(&r, &m, NULL), ZS_OK);
        }
        zs_set_setup_hook(&r, NULL, NULL);
        if (h.n == 0 || zs_frame_stats(&r)->tris_clipped)
            continue;
        if (zs_project_point(&r, zs_vec3_make(ZS_FX(pos[0]), ZS_FX(pos[1]), ZS_FX(pos[2])), xy,
                             &depth) != ZS_OK)
            continue;
        /* the record's vertex 0 is one of the three; the first vertex is
         * found among them within 1/16 pixel */
        {
            int best = 1 << 30;
            for (k = 0; k < 3; k++) {
                int dx = abs(h.xy[2 * k] * 4096 - xy[0]), dy = abs(h.xy[2 * k + 1] * 4096 - xy[1]);
                int d = dx > dy ? dx : dy;
                best = d < best ? d : best;
            }
            if (best > 65536 / 16 + 64)
                print_error("trial %d: zs_project_point (%f, %f) far from the renderer's\n", t,
                            xy[0] / 65536.0, xy[1] / 65536.0);
            assert_true(best <= 65536 / 16 + 64);
        }
        checked++;
    }
    assert_true(checked > 200);
    free(arena);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_files),
        cmocka_unit_test(test_good_file_round_trip),
        cmocka_unit_test(test_stabbing_lp),
        cmocka_unit_test(test_pvs_conservative),
        cmocka_unit_test(test_frames_equal),
        cmocka_unit_test(test_import_mesh),
        cmocka_unit_test(test_emitted_c),
        cmocka_unit_test(test_walk_fallback),
        cmocka_unit_test(test_core_refuses_malformed),
        cmocka_unit_test(test_project_point),
    };
    return cmocka_run_group_tests_name("level", tests, NULL, NULL);
}
