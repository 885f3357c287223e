/*
 * zspan-sim walk LEVEL: flies a scripted path through a portal level
 * (tools/level, zspan/portal.h) and writes one PNG per frame, with the
 * portal walk's statistics per frame. The path runs from cell 0 to the cell
 * farthest from it (in portal steps) through the midpoints of the portals
 * on the way, at a height every cell's opening allows (lv_flight).
 */
#include "level.h"
#include "png_out.h"
#include "sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct walk_opts {
    const char *level, *out;
    int frames, width, height;
    zs_visibility mode;
    zs_level_cull cull;
    int compare, quiet;
} walk_opts;

static int walk_usage(void)
{
    fprintf(stderr, "usage: " SIM_PROG " walk LEVEL [--out DIR] [--frames N] [--size WxH]\n"
                    "       [--mode span|zline] [--cull none|pvs|portals] [--no-compare] [--quiet]\n");
    return SIM_EXIT_USAGE;
}

static int parse_opts(int argc, char **argv, walk_opts *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->out = "out/walk";
    o->frames = 48;
    o->width = 240;
    o->height = 180;
    o->mode = ZS_MODE_SPAN;
    o->cull = ZS_LEVEL_CULL_PORTALS;
    o->compare = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--out") && v) {
            o->out = v;
            i++;
        } else if (!strcmp(a, "--frames") && v) {
            o->frames = atoi(v);
            i++;
            if (o->frames < 1 || o->frames > 100000)
                return -1;
        } else if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &o->width, &o->height) != 2 || o->width < 1 ||
                o->height < 1 || o->width > ZS_MAX_DIM || o->height > ZS_MAX_DIM)
                return -1;
            i++;
        } else if (!strcmp(a, "--mode") && v) {
            if (!strcmp(v, "span"))
                o->mode = ZS_MODE_SPAN;
            else if (!strcmp(v, "zline"))
                o->mode = ZS_MODE_ZLINE;
            else
                return -1;
            i++;
        } else if (!strcmp(a, "--cull") && v) {
            if (!strcmp(v, "none"))
                o->cull = ZS_LEVEL_CULL_NONE;
            else if (!strcmp(v, "pvs"))
                o->cull = ZS_LEVEL_CULL_PVS;
            else if (!strcmp(v, "portals"))
                o->cull = ZS_LEVEL_CULL_PORTALS;
            else
                return -1;
            i++;
        } else if (!strcmp(a, "--no-compare")) {
            o->compare = 0;
        } else if (!strcmp(a, "--quiet")) {
            o->quiet = 1;
        } else if (a[0] != '-' && !o->level) {
            o->level = a;
        } else {
            return -1;
        }
    }
    return o->level ? 0 : -1;
}

static zs_fixed fx(double v)
{
    return (zs_fixed)lround(v * 65536.0);
}

static int render(zs_renderer *r, const zs_level *lv, const zs_camera *cam, zs_vec3 eye,
                  const walk_opts *o, zs_level_cull cull, uint8_t *img, zs_level_stats *ls)
{
    zs_shade_params sp = zs_shade_default();
    zs_status st;
    sp.format = ZS_FMT_RGB888;
    sp.background = ZS_RGB(20, 20, 40);
    if ((st = zs_frame_begin(r, cam, o->mode)) != ZS_OK || (st = zs_frame_shading(r, &sp)) != ZS_OK ||
        (st = zs_level_draw(r, lv, eye, cull, ls)) != ZS_OK ||
        (st = sim_render_image(r, img, (size_t)o->width * 3, o->height, 1)) != ZS_OK) {
        fprintf(stderr, SIM_PROG " walk: %s\n", zs_strerror(st));
        return -1;
    }
    return 0;
}

static int run_walk(int argc, char **argv)
{
    walk_opts o;
    lv_level lv;
    lv_built b;
    char err[512];
    double (*pe)[3] = NULL, (*pt)[3] = NULL;
    int f, differ = 0, rc = SIM_EXIT_OK;
    uint8_t *arena, *img, *ref;
    zs_renderer r;
    zs_config cfg;
    unsigned long sum_sub = 0, sum_cull = 0;
    if (parse_opts(argc, argv, &o) != 0)
        return walk_usage();
    if (lv_load(o.level, &lv, err, sizeof err) != 0) {
        fprintf(stderr, SIM_PROG " walk: %s\n", err);
        return SIM_EXIT_FAIL;
    }
    if (lv_build(&lv, lv_compute_pvs(&lv, NULL), &b, err, sizeof err) != 0) {
        fprintf(stderr, SIM_PROG " walk: %s: %s\n", o.level, err);
        lv_free(&lv);
        return SIM_EXIT_FAIL;
    }
    lv_free(&lv);
    cfg = zs_config_default((uint16_t)o.width, (uint16_t)o.height,
                            (uint16_t)(b.total_tris * 2 > 65535 ? 65535 : b.total_tris * 2),
                            (uint16_t)(b.total_tris * 3 > 65535 ? 65535 : b.total_tris * 3), 1024);
    arena = malloc(zs_arena_bytes(&cfg));
    img = malloc((size_t)o.width * o.height * 3);
    ref = malloc((size_t)o.width * o.height * 3);
    if (zs_init(&r, arena, zs_arena_bytes(&cfg), &cfg) != ZS_OK) {
        fprintf(stderr, SIM_PROG " walk: cannot initialise the renderer\n");
        rc = SIM_EXIT_FAIL;
        goto done;
    }
    pe = malloc(sizeof *pe * (size_t)o.frames);
    pt = malloc(sizeof *pt * (size_t)o.frames);
    if (lv_flight(&b.level, o.frames, pe, pt) != 0) {
        fprintf(stderr, SIM_PROG " walk: no height is open in every cell: no path to fly\n");
        rc = SIM_EXIT_FAIL;
        goto done;
    }
    for (f = 0; f < o.frames && rc == SIM_EXIT_OK; f++) {
        zs_camera cam;
        zs_vec3 eye, tgt;
        zs_level_stats ls;
        char path[1024];
        if (getenv("ZS_WALK_TRACE"))
            printf("frame %d: eye %.17g %.17g %.17g target %.17g %.17g %.17g (world)\n", f,
                   pe[f][0], pe[f][1], pe[f][2], pt[f][0], pt[f][1], pt[f][2]);
        eye = zs_vec3_make(fx(pe[f][0]), fx(pe[f][1]), fx(pe[f][2]));
        tgt = zs_vec3_make(fx(pt[f][0]), fx(pt[f][1]), fx(pt[f][2]));
        if (zs_camera_look_at(&cam, eye, tgt, zs_vec3_make(0, ZS_FX_ONE, 0)) != ZS_OK ||
            zs_camera_perspective(&cam, ZS_FX(70), ZS_FX_ONE / 20, ZS_FX(200)) != ZS_OK) {
            fprintf(stderr, SIM_PROG " walk: bad camera at frame %d\n", f);
            rc = SIM_EXIT_FAIL;
            break;
        }
        if (render(&r, &b.level, &cam, eye, &o, o.cull, img, &ls) != 0) {
            rc = SIM_EXIT_FAIL;
            break;
        }
        sum_sub += ls.tris_submitted;
        sum_cull += ls.tris_culled;
        snprintf(path, sizeof path, "%s/frame%04d.png", o.out, f);
        if (sim_make_parent_dirs(path) != 0 ||
            png_write_rgb8(path, o.width, o.height, img, (size_t)o.width * 3) != 0) {
            rc = SIM_EXIT_FAIL;
            break;
        }
        if (o.compare) {
            zs_level_stats all;
            if (render(&r, &b.level, &cam, eye, &o, ZS_LEVEL_CULL_NONE, ref, &all) != 0) {
                rc = SIM_EXIT_FAIL;
                break;
            }
            if (memcmp(img, ref, (size_t)o.width * o.height * 3) != 0)
                differ++;
        }
        if (!o.quiet)
            printf("frame %d: cell %d pvs %u visited %u portals %u drawn %u tris %u culled %u%s%s\n",
                   f, (int)ls.eye_cell, (unsigned)ls.pvs_cells, (unsigned)ls.cells_visited,
                   (unsigned)ls.portals_tested, (unsigned)ls.cells_drawn,
                   (unsigned)ls.tris_submitted, (unsigned)ls.tris_culled,
                   ls.fallback ? " (fallback)" : "",
                   o.compare ? (memcmp(img, ref, (size_t)o.width * o.height * 3) ? " DIFFERS"
                                                                                  : " same")
                             : "");
    }
    if (rc == SIM_EXIT_OK && !o.quiet)
        printf("%d frames in %s/: %.1f%% of the triangles never transformed%s\n", o.frames, o.out,
               100.0 * (double)sum_cull / (double)(sum_cull + sum_sub ? sum_cull + sum_sub : 1),
               o.compare ? (differ ? "; SOME FRAMES DIFFER from drawing every cell"
                                   : "; every frame equals drawing every cell")
                         : "");
    if (rc == SIM_EXIT_OK && differ)
        rc = SIM_EXIT_FAIL;
done:
    free(pe);
    free(pt);
    free(arena);
    free(img);
    free(ref);
    lv_built_free(&b);
    return rc;
}

SIM_COMMAND(walk, "walk", run_walk,
            "  walk LEVEL [--out DIR] [--frames N] [--size WxH] [--mode span|zline]\n"
            "       [--cull none|pvs|portals] [--no-compare] [--quiet]\n"
            "                        fly through a portal level (zspan-level), PNG per frame\n")
