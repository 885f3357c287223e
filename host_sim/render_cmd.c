/* SPDX-License-Identifier: MIT */
/* zspan-sim render: meshes from files (assimp) -> PNG through the core. */
#include "sim.h"
#include "zs_hlines.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "png_out.h"
#include "raycast.h"
#include "regions.h"
#include "zs_arena.h"
#include "zs_teximg.h"
#include "zs_bsp_build.h"
#include "zs_model.h"
#include "zspan/priority.h"
#include "zs_opts.h"

static int vec_to_fixed(const char *what, const double v[3], zs_vec3 *out);

static void opts_default(sim_render_opts *o)
{
    memset(o, 0, sizeof *o);
    o->width = 240;
    o->height = 240;
    o->fov = 60.0;
    o->near_z = 0.1;
    o->far_z = 100.0;
    o->eye[2] = 3.0;
    o->up[1] = 1.0;
    o->mode = ZS_MODE_SPAN;
    o->shade = SHADE_FLAT;
    o->out = SIM_RENDER_OUT;
    o->up_axis = ZS_UP_AUTO;
    o->background = 0;
    o->band = 1;
    o->grid = 8;
    o->tex_size = 256;
}

static int parse_fog(const char *s, sim_render_opts *o)
{
    char buf[128];
    char *c1, *c2;

    if (strlen(s) >= sizeof buf)
        goto bad;
    strcpy(buf, s);
    c1 = strchr(buf, ',');
    if (c1 == NULL)
        goto bad;
    c2 = strchr(c1 + 1, ',');
    if (c2 == NULL)
        goto bad;
    *c1 = '\0';
    *c2 = '\0';
    if (zs_opt_double(SIM_PROG, "--fog", buf, &o->fog_start) != 0 ||
        zs_opt_double(SIM_PROG, "--fog", c1 + 1, &o->fog_end) != 0 ||
        zs_opt_color(SIM_PROG, "--fog", c2 + 1, &o->fog_color) != 0)
        return -1;
    o->fog = 1;
    return 0;
bad:
    fprintf(stderr, "zspan-sim: --fog: expected start,end,RRGGBB, got '%s'\n", s);
    return -1;
}

/* --opacity A1[,A2...]: 0..255 each, at most 16. */
static int parse_opacity(const char *s, sim_render_opts *o)
{
    const char *p = s;
    o->n_opacity = 0;
    for (;;) {
        char *end;
        long v;
        errno = 0;
        v = strtol(p, &end, 10);
        if (end == p || errno != 0 || v < 0 || v > 255 || o->n_opacity >= 16 ||
            (*end != ',' && *end != '\0'))
            break;
        o->opacity[o->n_opacity++] = (uint8_t)v;
        if (*end == '\0')
            return 0;
        p = end + 1;
    }
    fprintf(stderr, "zspan-sim: --opacity: expected up to 16 values 0..255 separated by commas, "
                    "got '%s'\n", s);
    return -1;
}

static int count_commas(const char *s)
{
    int n = 0;

    for (; *s != '\0'; s++)
        n += *s == ',';
    return n;
}

/* Returns 0, or SIM_EXIT_USAGE after printing a message, or SIM_EXIT_OK with
 * o->done set after --help or --version. */
static int parse_args(int argc, char **argv, sim_render_opts *o)
{
    int i, only_files = 0;

    o->files = malloc((size_t)(argc + 1) * sizeof *o->files);
    if (o->files == NULL) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        return SIM_EXIT_FAIL;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = NULL;
        int m;

        if (only_files || a[0] != '-' || a[1] == '\0') {
            o->files[o->nfiles++] = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            only_files = 1;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            sim_print_render_usage(stdout);
            o->done = 1;
            return SIM_EXIT_OK;
        }
        if (zs_opt_version(a, SIM_PROG)) {
            o->done = 1;
            return SIM_EXIT_OK;
        }
        if (strcmp(a, "--flip-winding") == 0) {
            o->flip_winding = 1;
            continue;
        }
        if (strcmp(a, "--two-sided") == 0) {
            o->two_sided = 1;
            continue;
        }
        if (strcmp(a, "--fit") == 0) {
            o->fit = 1;
            continue;
        }
        if (strcmp(a, "--smooth") == 0) {
            o->smooth = 1;
            continue;
        }
        if (strcmp(a, "--aa") == 0) {
            o->aa = 1;
            continue;
        }
        if (strcmp(a, "--painter") == 0) {
            o->painter = 1;
            continue;
        }
        if (strcmp(a, "--unlit") == 0) {
            o->unlit = 1;
            continue;
        }
        if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            o->quiet = 1;
            continue;
        }
        if (strcmp(a, "--textures") == 0) {
            o->textures = 1;
            continue;
        }
#define OPT(name) ((m = zs_opt_value(argc, argv, &i, name, &v, SIM_PROG)) != 0)
        if (OPT("--texture-size")) {
            if (m < 0 || zs_opt_long(SIM_PROG, "--texture-size", v, 1, ZS_TEX_MAX_DIM,
                                     &o->tex_size) != 0)
                return SIM_EXIT_USAGE;
            if (o->tex_size & (o->tex_size - 1)) {
                fprintf(stderr, "zspan-sim: --texture-size must be a power of two, got %ld\n",
                        o->tex_size);
                return SIM_EXIT_USAGE;
            }
        } else if (OPT("--texture-filter")) {
            static const char *const filters[] = {"nearest", "bilinear"};
            if (m < 0 || zs_opt_choice(SIM_PROG, "--texture-filter", v, filters, 2,
                                       &o->tex_bilinear) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--size")) {
            if (m < 0 || zs_opt_size(SIM_PROG, "--size", v, &o->width, &o->height) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--fov")) {
            if (m < 0 || zs_opt_double(SIM_PROG, "--fov", v, &o->fov) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--near")) {
            if (m < 0 || zs_opt_double(SIM_PROG, "--near", v, &o->near_z) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--far")) {
            if (m < 0 || zs_opt_double(SIM_PROG, "--far", v, &o->far_z) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--eye")) {
            if (m < 0 || zs_opt_doubles(SIM_PROG, "--eye", v, o->eye, 3) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--target")) {
            if (m < 0 || zs_opt_doubles(SIM_PROG, "--target", v, o->target, 3) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--up-axis")) {
            if (m < 0 || zs_opt_up_axis(SIM_PROG, "--up-axis", v, &o->up_axis) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--up")) {
            /* An axis name is the file's up axis; three numbers the camera's up. */
            if (m < 0)
                return SIM_EXIT_USAGE;
            if (strchr(v, ',') == NULL) {
                if (zs_opt_up_axis(SIM_PROG, "--up (an axis, or x,y,z for the camera)", v,
                                   &o->up_axis) != 0)
                    return SIM_EXIT_USAGE;
                if (o->up_axis == 0) {
                    fprintf(stderr, "zspan-sim: --up auto: say --up-axis auto\n");
                    return SIM_EXIT_USAGE;
                }
            } else if (zs_opt_doubles(SIM_PROG, "--up", v, o->up, 3) != 0) {
                return SIM_EXIT_USAGE;
            }
        } else if (OPT("--rotate")) {
            if (m < 0 || zs_opt_doubles(SIM_PROG, "--rotate", v, o->rot, 3) != 0)
                return SIM_EXIT_USAGE;
            o->has_rot = 1;
        } else if (OPT("--mode")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->raycast = strcmp(v, "raycast") == 0;
            if (o->raycast)
                o->mode = ZS_MODE_SPAN; /* the core makes the records */
            else if (!strcmp(v, "priority"))
                o->mode = ZS_MODE_PRIORITY;
            else if (zs_opt_mode(SIM_PROG, v, &o->mode) != 0) {
                fprintf(stderr, "zspan-sim: --mode: or raycast, priority (render only)\n");
                return SIM_EXIT_USAGE;
            }
        } else if (OPT("--grid")) {
            if (m < 0 || zs_opt_long(SIM_PROG, "--grid", v, 0, ZS_MAX_DIM, &o->grid) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--svg")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->svg = v;
        } else if (OPT("--order")) {
            static const char *const orders[] = {"bsp", "nns", "sort"};
            int k;
            if (m < 0 || zs_opt_choice(SIM_PROG, "--order", v, orders, 3, &k) != 0)
                return SIM_EXIT_USAGE;
            o->order = SIM_ORDER_BSP + k;
        } else if (OPT("--cells")) {
            static const char *const kinds[] = {"kd", "grid"};
            int k;
            if (m < 0 || zs_opt_choice(SIM_PROG, "--cells", v, kinds, 2, &k) != 0)
                return SIM_EXIT_USAGE;
            o->cells = 1 + k; /* ZS_CELLS_KD = 0, ZS_CELLS_GRID = 1 */
        } else if (OPT("--shade")) {
            static const char *const shades[] = {"flat", "gouraud", "ids"};
            if (m < 0 || zs_opt_choice(SIM_PROG, "--shade", v, shades, 3, &o->shade) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--out")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->out = v;
            o->out_set = 1;
        } else if (OPT("--dump-tris")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->dump = v;
        } else if (OPT("--svg-lines")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->svg_lines = v;
        } else if (OPT("--background")) {
            if (m < 0 || zs_opt_color(SIM_PROG, "--background", v, &o->background) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--light")) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->light[3] = 0.7;
            if (zs_opt_doubles(SIM_PROG, "--light", v, o->light, count_commas(v) == 3 ? 4 : 3) != 0)
                return SIM_EXIT_USAGE;
            o->has_light = 1;
        } else if (OPT("--ambient")) {
            if (m < 0 || zs_opt_double(SIM_PROG, "--ambient", v, &o->ambient) != 0)
                return SIM_EXIT_USAGE;
            o->has_ambient = 1;
        } else if (OPT("--fog")) {
            if (m < 0 || parse_fog(v, o) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--opacity")) {
            if (m < 0 || parse_opacity(v, o) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--band")) {
            if (m < 0 || zs_opt_long(SIM_PROG, "--band", v, 1, ZS_MAX_DIM, &o->band) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--max-tris")) {
            if (m < 0 ||
                zs_opt_long(SIM_PROG, "--max-tris", v, 1, ZS_MAX_TRIANGLES, &o->max_tris) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--max-verts")) {
            if (m < 0 ||
                zs_opt_long(SIM_PROG, "--max-verts", v, 1, ZS_MAX_VERTICES, &o->max_verts) != 0)
                return SIM_EXIT_USAGE;
        } else if (OPT("--max-edges")) {
            if (m < 0 ||
                zs_opt_long(SIM_PROG, "--max-edges", v, 2, ZS_MAX_ACTIVE_EDGES, &o->max_edges) != 0)
                return SIM_EXIT_USAGE;
        } else {
            fprintf(stderr, "zspan-sim: render: unknown option '%s' (see zspan-sim render --help)\n",
                    a);
            return SIM_EXIT_USAGE;
        }
#undef OPT
    }
    if (o->nfiles == 0) {
        fprintf(stderr, "zspan-sim: render: no mesh file given (see zspan-sim render --help)\n");
        return SIM_EXIT_USAGE;
    }
    return 0;
}

/* The narrowest field of view (Q16.16 degrees) the core's projection takes. */
static zs_fixed narrowest_fov(void)
{
    zs_fixed lo = 0, hi = ZS_FX(1); /* refused at lo, taken at hi */
    zs_camera cam;

    memset(&cam, 0, sizeof cam);
    while (hi - lo > 1) {
        zs_fixed mid = lo + (hi - lo) / 2;
        if (zs_camera_perspective(&cam, mid, ZS_FX(1), ZS_FX(2)) == ZS_OK)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* The camera and projection options, checked against what the core takes,
 * each message naming the option. Returns 0 or SIM_EXIT_USAGE. */
static int check_camera(sim_render_opts *o)
{
    zs_camera cam;
    zs_fixed fov_min;
    zs_status st;

    if (vec_to_fixed("--eye", o->eye, &o->q_eye) != 0 ||
        vec_to_fixed("--target", o->target, &o->q_target) != 0 ||
        vec_to_fixed("--up", o->up, &o->q_up) != 0)
        return SIM_EXIT_USAGE;
    if (!(o->fov > 0.0 && o->fov < 180.0)) {
        fprintf(stderr, "zspan-sim: --fov: %g is outside 0 .. 180 degrees (both excluded)\n",
                o->fov);
        return SIM_EXIT_USAGE;
    }
    fov_min = narrowest_fov();
    if (zs_opt_fixed(SIM_PROG, "--fov", o->fov, &o->q_fov) != 0 || o->q_fov < fov_min) {
        fprintf(stderr, "zspan-sim: --fov: %g degrees is too narrow (the narrowest is %.5f)\n",
                o->fov, (double)fov_min / 65536.0);
        return SIM_EXIT_USAGE;
    }
    if (zs_opt_fixed(SIM_PROG, "--near", o->near_z, &o->q_near) != 0 ||
        zs_opt_fixed(SIM_PROG, "--far", o->far_z, &o->q_far) != 0)
        return SIM_EXIT_USAGE;
    if (o->q_near <= 0) {
        fprintf(stderr, "zspan-sim: --near: %g must be above 0 (at least 1/65536)\n", o->near_z);
        return SIM_EXIT_USAGE;
    }
    if (o->q_far <= o->q_near) {
        fprintf(stderr, "zspan-sim: --far: %g must be beyond --near %g\n", o->far_z, o->near_z);
        return SIM_EXIT_USAGE;
    }
    st = zs_camera_perspective(&cam, o->q_fov, o->q_near, o->q_far);
    if (st != ZS_OK) {
        fprintf(stderr, "zspan-sim: --fov %g --near %g --far %g: %s\n", o->fov, o->near_z,
                o->far_z, zs_strerror(st));
        return SIM_EXIT_USAGE;
    }
    if (o->q_eye.x == o->q_target.x && o->q_eye.y == o->q_target.y &&
        o->q_eye.z == o->q_target.z) {
        fprintf(stderr, "zspan-sim: --eye and --target are the same point\n");
        return SIM_EXIT_USAGE;
    }
    st = zs_camera_look_at(&cam, o->q_eye, o->q_target, o->q_up);
    if (st != ZS_OK) {
        fprintf(stderr, "zspan-sim: --up %g,%g,%g is zero or parallel to the view direction "
                        "(--target minus --eye)\n",
                o->up[0], o->up[1], o->up[2]);
        return SIM_EXIT_USAGE;
    }
    return 0;
}

int sim_render_parse(int argc, char **argv, sim_render_opts *o)
{
    int rc;

    opts_default(o);
    rc = parse_args(argc, argv, o);
    if (rc != 0 || o->done)
        return rc;
    rc = check_camera(o);
    if (rc == 0 && o->has_rot) {
        zs_fixed ax, ay, az;
        if (zs_opt_fixed(SIM_PROG, "--rotate", o->rot[0], &ax) != 0 ||
            zs_opt_fixed(SIM_PROG, "--rotate", o->rot[1], &ay) != 0 ||
            zs_opt_fixed(SIM_PROG, "--rotate", o->rot[2], &az) != 0)
            rc = SIM_EXIT_USAGE;
    }
    if (rc == 0 && o->has_ambient && zs_opt_fixed(SIM_PROG, "--ambient", o->ambient, &o->q_ambient) != 0)
        rc = SIM_EXIT_USAGE;
    if (rc == 0 && o->fog) {
        zs_fixed a, b;
        if (zs_opt_fixed(SIM_PROG, "--fog", o->fog_start, &a) != 0 ||
            zs_opt_fixed(SIM_PROG, "--fog", o->fog_end, &b) != 0)
            rc = SIM_EXIT_USAGE;
    }
    if (rc == 0 && o->has_light) {
        zs_fixed in;
        if (zs_opt_fixed(SIM_PROG, "--light", o->light[3], &in) != 0)
            rc = SIM_EXIT_USAGE;
        else if (o->light[0] == 0.0 && o->light[1] == 0.0 && o->light[2] == 0.0) {
            fprintf(stderr, "zspan-sim: --light: the direction 0,0,0 points nowhere\n");
            rc = SIM_EXIT_USAGE;
        }
    }
    if (rc == 0 && sim_check_output(o->out, "--out") != 0)
        rc = SIM_EXIT_USAGE;
    if (rc == 0 && o->dump != NULL && sim_check_output(o->dump, "--dump-tris") != 0)
        rc = SIM_EXIT_USAGE;
    if (rc == 0 && o->svg != NULL && sim_check_output(o->svg, "--svg") != 0)
        rc = SIM_EXIT_USAGE;
    return rc;
}

void sim_render_opts_free(sim_render_opts *o)
{
    free(o->files);
    o->files = NULL;
}

/* A pleasant, deterministic colour for triangle number n (0-based). */
static zs_color palette_color(uint32_t n)
{
    static const zs_color base[12] = {
        ZS_RGB(230, 80, 70),  ZS_RGB(240, 160, 50), ZS_RGB(230, 220, 70),
        ZS_RGB(120, 200, 80), ZS_RGB(60, 180, 150), ZS_RGB(70, 170, 230),
        ZS_RGB(90, 110, 230), ZS_RGB(160, 90, 220), ZS_RGB(220, 90, 180),
        ZS_RGB(200, 200, 200), ZS_RGB(150, 120, 90), ZS_RGB(110, 150, 110),
    };
    uint32_t h = n * 2654435761u;
    zs_color c = base[(h >> 16) % 12u];
    int shift = (int)((h >> 8) & 31u) - 16; /* +-16 per channel for variety */
    uint32_t r = (c >> 16) & 255u, g = (c >> 8) & 255u, b = c & 255u;
    int rr = (int)r + shift, gg = (int)g + shift, bb = (int)b + shift;

    rr = rr < 0 ? 0 : rr > 255 ? 255 : rr;
    gg = gg < 0 ? 0 : gg > 255 ? 255 : gg;
    bb = bb < 0 ? 0 : bb > 255 ? 255 : bb;
    return ZS_RGB(rr, gg, bb);
}

/* The meshes' quantised vertices (as the core draws them) in eye space, their
 * visible feature edges (app/zs_hlines.c) as an SVG. */
static int write_svg_lines(const sim_render_opts *o, const zs_model *scene, const zs_mat34 *model,
                           const zs_camera *cam)
{
    size_t nv = 0, nt = 0, i, k, v0 = 0, t0 = 0;
    double *pos;
    uint32_t *idx;
    int *group, rc = -1;
    zs_hl_view view;
    zs_hl_result res;
    for (i = 0; i < scene->count; i++) {
        nv += scene->chunks[i].mesh.vertex_count;
        nt += scene->chunks[i].mesh.triangle_count;
    }
    pos = malloc((nv + 1) * 3 * sizeof *pos);
    idx = malloc((nt + 1) * 3 * sizeof *idx);
    group = malloc((nt + 1) * sizeof *group);
    if (!pos || !idx || !group)
        goto out;
    for (i = 0; i < scene->count; i++) {
        const zs_mesh *m = &scene->chunks[i].mesh;
        for (k = 0; k < m->vertex_count; k++) {
            double p[3], w[3];
            int a, b;
            for (a = 0; a < 3; a++)
                p[a] = m->positions[3 * k + a] * (m->scale / 65536.0);
            for (a = 0; a < 3; a++) {
                w[a] = p[a];
                if (model)
                    w[a] = (model->m[a][0] * p[0] + model->m[a][1] * p[1] + model->m[a][2] * p[2] +
                            model->m[a][3]) / 65536.0;
            }
            for (a = 0; a < 3; a++) {
                double e = cam->view.m[a][3] / 65536.0;
                for (b = 0; b < 3; b++)
                    e += cam->view.m[a][b] / 65536.0 * w[b];
                pos[3 * (v0 + k) + (size_t)a] = e;
            }
        }
        for (k = 0; k < m->triangle_count; k++) {
            for (int c = 0; c < 3; c++)
                idx[3 * (t0 + k) + (size_t)c] = (uint32_t)(v0 + m->indices[3 * k + c]);
            group[t0 + k] = (int)i;
        }
        v0 += m->vertex_count;
        t0 += m->triangle_count;
    }
    view.width = o->width;
    view.height = o->height;
    view.fov_deg = o->fov;
    view.near_z = o->near_z;
    view.crease_deg = 30.0;
    if (zs_hl_compute(&view, pos, nv, idx, group, nt, &res) != 0) {
        fprintf(stderr, "zspan-sim: out of memory (--svg-lines)\n");
        goto out;
    }
    if (sim_make_parent_dirs(o->svg_lines) != 0 || zs_hl_write_svg(o->svg_lines, &view, &res) != 0)
        fprintf(stderr, "zspan-sim: cannot write %s\n", o->svg_lines);
    else
        rc = 0;
    if (rc == 0 && !o->quiet)
        printf("svg-lines: %lu feature edges, %lu visible segments -> %s\n",
               (unsigned long)res.feature_edges, (unsigned long)res.n, o->svg_lines);
    zs_hl_free(&res);
out:
    free(pos);
    free(idx);
    free(group);
    return rc;
}

static void dump_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3])
{
    FILE *f = user;
    int k;

    fprintf(f, "%u", (unsigned)tag);
    for (k = 0; k < 3; k++)
        fprintf(f, " %.4f %.4f %.17g", (double)xy[2 * k] / 16.0, (double)xy[2 * k + 1] / 16.0,
                (double)z[k] / 1073741824.0);
    fputc('\n', f);
}

static void normalize3(double v[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);

    if (len > 0.0) {
        v[0] /= len;
        v[1] /= len;
        v[2] /= len;
    }
}

/* Default light: from over the viewer's left shoulder. */
static void default_light(const sim_render_opts *o, double out[3])
{
    double f[3], u[3], r[3], d;
    int a;

    for (a = 0; a < 3; a++) {
        f[a] = o->eye[a] - o->target[a];
        u[a] = o->up[a];
    }
    normalize3(f);
    d = u[0] * f[0] + u[1] * f[1] + u[2] * f[2];
    for (a = 0; a < 3; a++)
        u[a] -= d * f[a];
    normalize3(u);
    r[0] = u[1] * f[2] - u[2] * f[1];
    r[1] = u[2] * f[0] - u[0] * f[2];
    r[2] = u[0] * f[1] - u[1] * f[0];
    for (a = 0; a < 3; a++)
        out[a] = f[a] + 0.7 * u[a] - 0.5 * r[a];
    normalize3(out);
}

static int vec_to_fixed(const char *what, const double v[3], zs_vec3 *out)
{
    zs_fixed x, y, z;

    if (zs_opt_fixed(SIM_PROG, what, v[0], &x) != 0 ||
        zs_opt_fixed(SIM_PROG, what, v[1], &y) != 0 ||
        zs_opt_fixed(SIM_PROG, what, v[2], &z) != 0)
        return -1;
    *out = zs_vec3_make(x, y, z);
    return 0;
}

/* --order bsp: compiles the meshes into one BSP tree (app/zs_bsp_build.c),
 * all chunks merged so that their triangles are ordered among each other;
 * *extra: the triangles the splits add. Returns 0, or -1 after a message. */
/* --textures: a material's diffuse texture (zs_model_opts.load_texture). */
static int sim_load_texture(void *user, const struct aiScene *ai, unsigned material,
                            const char *path, zs_texture *out)
{
    const sim_render_opts *o = user;
    char ref[256], msg[768];
    int rc = zs_timg_material_texture(ai, material, path, (unsigned)o->tex_size, 1,
                                      ZS_TEX_RGB565, o->tex_bilinear ? ZS_TEX_BILINEAR : 0u, out,
                                      ref, sizeof ref, msg, sizeof msg);
    if (rc == ZS_TIMG_NONE)
        return 0;
    if (rc != ZS_TIMG_OK) {
        fprintf(stderr, "zspan-sim: %s: texture %s: %s\n", path, ref,
                rc == ZS_TIMG_ERR_MEMORY ? "out of memory" : msg);
        return -1;
    }
    return 1;
}

static int build_tree(const zs_model *scene, zs_bspb_result *tree, zs_mesh *mesh,
                      unsigned long *extra, const sim_render_opts *o)
{
    size_t i, nv = 0, nt = 0, v0 = 0, t0 = 0;
    int fcol = 1, vnrm = 1, vcol = 1, uv = 1;
    zs_fixed scale = 0;
    zs_bspb_mesh in;
    const char *err;
    for (i = 0; i < scene->count; i++) {
        const zs_mesh *m = &scene->chunks[i].mesh;
        nv += m->vertex_count;
        nt += m->triangle_count;
        fcol &= m->face_colors != NULL;
        vnrm &= m->vertex_normals != NULL;
        vcol &= m->vertex_colors != NULL;
        uv &= m->uvs != NULL && m->texture == scene->chunks[0].mesh.texture; /* one texture */
        if (m->scale > scale)
            scale = m->scale; /* the chunks are put on the coarsest grid */
    }
    if (nv > 65535 || nt > 65535 || scene->count == 0) {
        fprintf(stderr, "zspan-sim: --order bsp: at most 65535 vertices and triangles in all\n");
        return -1;
    }
    memset(&in, 0, sizeof in);
    in.pos = malloc(3 * nv * sizeof *in.pos + 1);
    in.idx = malloc(3 * nt * sizeof *in.idx + 1);
    in.fcol = fcol ? malloc(nt * sizeof *in.fcol + 1) : NULL;
    in.vnrm = vnrm ? malloc(3 * nv * sizeof *in.vnrm + 1) : NULL;
    in.vcol = vcol ? malloc(nv * sizeof *in.vcol + 1) : NULL;
    in.uv = uv ? malloc(2 * nv * sizeof *in.uv + 1) : NULL;
    if (!in.pos || !in.idx || (fcol && !in.fcol) || (vnrm && !in.vnrm) || (vcol && !in.vcol) ||
        (uv && !in.uv)) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        return -1;
    }
    for (i = 0; i < scene->count; i++) {
        const zs_mesh *m = &scene->chunks[i].mesh;
        size_t k;
        for (k = 0; k < 3u * m->vertex_count; k++)
            in.pos[3 * v0 + k] =
                (int16_t)lround((double)m->positions[k] * (double)m->scale / (double)scale);
        if (vnrm)
            memcpy(in.vnrm + 3 * v0, m->vertex_normals, 3u * m->vertex_count * sizeof *in.vnrm);
        if (vcol)
            memcpy(in.vcol + v0, m->vertex_colors, m->vertex_count * sizeof *in.vcol);
        if (uv)
            memcpy(in.uv + 2 * v0, m->uvs, 2u * m->vertex_count * sizeof *in.uv);
        if (fcol)
            memcpy(in.fcol + t0, m->face_colors, m->triangle_count * sizeof *in.fcol);
        for (k = 0; k < 3u * m->triangle_count; k++)
            in.idx[3 * t0 + k] = (uint16_t)(m->indices[k] + v0);
        v0 += m->vertex_count;
        t0 += m->triangle_count;
    }
    in.nv = nv;
    in.nt = nt;
    err = zs_bspb_build(&in, NULL, tree);
    free(in.pos);
    free(in.idx);
    free(in.fcol);
    free(in.vnrm);
    free(in.vcol);
    free(in.uv);
    if (err) {
        fprintf(stderr, "zspan-sim: --order bsp: %s\n", err);
        return -1;
    }
    *mesh = scene->chunks[0].mesh;
    mesh->scale = scale;
    mesh->positions = tree->mesh.pos;
    mesh->indices = tree->mesh.idx;
    mesh->face_colors = tree->mesh.fcol;
    mesh->face_normals = tree->mesh.fnrm;
    mesh->vertex_colors = tree->mesh.vcol;
    mesh->vertex_normals = tree->mesh.vnrm;
    mesh->uvs = tree->mesh.uv;
    mesh->texture = tree->mesh.uv ? scene->chunks[0].mesh.texture : NULL;
    mesh->vertex_count = (uint16_t)tree->mesh.nv;
    mesh->triangle_count = (uint16_t)tree->mesh.nt;
    *extra = tree->mesh.nt > nt ? tree->mesh.nt - nt : 0;
    if (!o->quiet)
        printf("render: BSP: %zu nodes, %zu -> %zu triangles (%zu splits, %zu slivers), walk "
               "stack %d\n",
               tree->node_count, nt, tree->mesh.nt, tree->splits, tree->slivers, tree->stack);
    return 0;
}

static int core_error(const char *call, zs_status st)
{
    fprintf(stderr, "zspan-sim: %s: %s (status %d)\n", call, zs_strerror(st), (int)st);
    return SIM_EXIT_FAIL;
}

/* --mode raycast: the frame's records ray-cast on the host (the core's own
 * frame, in ID16, is the comparison); writes the PNG: the tags with --shade
 * ids, else each triangle in its palette colour, unlit. Returns 0 or -1. */
static int raycast_output(const sim_render_opts *o, const sim_rc_set *recs, const uint8_t *ids,
                          size_t stride)
{
    sim_rc_image im;
    unsigned long covered = 0, differ = 0, near = 0;
    uint8_t *out;
    size_t ostride;
    int x, y, rc = -1;
    if (sim_raycast(recs, o->width, o->height, (int)o->grid, &im) != 0) {
        fprintf(stderr, "zspan-sim: out of memory (--mode raycast)\n");
        return -1;
    }
    for (y = 0; y < o->height; y++)
        for (x = 0; x < o->width; x++) {
            uint16_t want, got = im.tag[(size_t)y * (size_t)o->width + (size_t)x];
            double zs;
            memcpy(&want, ids + (size_t)y * stride + 2 * (size_t)x, 2);
            covered += want != 0 || got != 0;
            if (want == got)
                continue;
            differ++;
            /* a near tie: the span image's triangle is there, within 2^-20
             * of the nearest depth the ray found */
            if (want != 0 && got != 0 && sim_rc_depth_of(recs, want, x, y, &zs) &&
                zs - im.z1[(size_t)y * (size_t)o->width + (size_t)x] < 1.0 / 1048576.0)
                near++;
        }
    ostride = (size_t)o->width * (o->shade == SHADE_IDS ? 2u : 3u);
    out = malloc((size_t)o->height * ostride);
    if (out == NULL) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        goto done;
    }
    for (y = 0; y < o->height; y++)
        for (x = 0; x < o->width; x++) {
            uint16_t t = im.tag[(size_t)y * (size_t)o->width + (size_t)x];
            uint8_t *p = out + (size_t)y * ostride;
            if (o->shade == SHADE_IDS) {
                memcpy(p + 2 * (size_t)x, &t, 2);
            } else {
                zs_color c = t ? palette_color((uint32_t)t - 1u) : o->background;
                p[3 * x] = (uint8_t)(c >> 16);
                p[3 * x + 1] = (uint8_t)(c >> 8);
                p[3 * x + 2] = (uint8_t)c;
            }
        }
    if (!o->out_set && sim_make_parent_dirs(o->out) != 0)
        goto done;
    if ((o->shade == SHADE_IDS ? png_write_gray16(o->out, o->width, o->height, out, ostride)
                               : png_write_rgb8(o->out, o->width, o->height, out, ostride)) != 0)
        goto done;
    if (!o->quiet)
        printf("raycast: %lu records, grid %ldx%ld px, %lu ray-record tests; %lu of %lu covered "
               "pixels differ from span mode, %lu of them near ties (depths within 2^-20), %lu "
               "other -> %s\n",
               (unsigned long)recs->n, o->grid, o->grid, im.tests, differ, covered, near,
               differ - near, o->out);
    rc = 0;
done:
    free(out);
    sim_rc_image_free(&im);
    return rc;
}

/* --svg: the visible regions of the frame's records, coloured as the image
 * shows them (the colour of the first pixel of each tag; a tag no pixel
 * shows gets its palette colour). The tags come from a second frame of the
 * same draws in ID16. Returns 0 or -1. */
static int svg_output(const sim_render_opts *o, zs_renderer *r, const zs_camera *cam,
                      const zs_shade_params *sp, const zs_model *scene, const zs_mat34 *model,
                      const sim_rc_set *recs, const uint8_t *img, size_t stride)
{
    size_t np = (size_t)o->width * (size_t)o->height, i, ids_stride = (size_t)o->width * 2;
    uint8_t *ids = malloc(np * 2);
    uint32_t *tag_rgb = malloc(65536 * sizeof *tag_rgb), *rgb = malloc((recs->n + 1) * sizeof *rgb);
    uint8_t *seen = calloc(65536, 1);
    zs_shade_params idp = *sp;
    sim_vr_result res;
    int rc = -1, x, y;
    zs_status st;
    memset(&res, 0, sizeof res);
    if (!ids || !tag_rgb || !rgb || !seen) {
        fprintf(stderr, "zspan-sim: out of memory (--svg)\n");
        goto out;
    }
    idp.format = ZS_FMT_ID16;
    idp.shading = ZS_SHADE_FLAT;
    st = zs_frame_begin(r, cam, o->mode);
    if (st == ZS_OK)
        st = zs_frame_shading(r, &idp);
    for (i = 0; st == ZS_OK && i < scene->count; i++)
        st = zs_draw(r, &scene->chunks[i].mesh, model);
    if (st == ZS_OK)
        st = sim_render_image(r, ids, ids_stride, o->height, (int)o->band);
    if (st != ZS_OK) {
        core_error("--svg frame", st);
        goto out;
    }
    for (y = 0; y < o->height; y++)
        for (x = 0; x < o->width; x++) {
            uint16_t t;
            memcpy(&t, ids + (size_t)y * ids_stride + 2 * (size_t)x, 2);
            if (t == 0 || seen[t])
                continue;
            seen[t] = 1;
            if (sp->format == ZS_FMT_RGB888) {
                const uint8_t *p = img + (size_t)y * stride + 3 * (size_t)x;
                tag_rgb[t] = ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
            } else {
                tag_rgb[t] = palette_color((uint32_t)t - 1u);
            }
        }
    for (i = 0; i < recs->n; i++) {
        uint16_t t = recs->v[i].tag;
        rgb[i] = seen[t] ? tag_rgb[t] : palette_color((uint32_t)t - 1u);
    }
    rc = sim_vr_compute(recs, o->width, o->height, &res);
    if (rc != 0) {
        fprintf(stderr, "zspan-sim: %s (--svg)\n",
                rc == -2 ? "a visible region was cut into pieces of too many corners"
                         : "out of memory");
        rc = -1;
        goto out;
    }
    rc = -1;
    if (sim_make_parent_dirs(o->svg) != 0 ||
        sim_vr_write_svg(o->svg, &res, recs, rgb, o->background, o->width, o->height) != 0) {
        fprintf(stderr, "zspan-sim: cannot write %s\n", o->svg);
        goto out;
    }
    if (!o->quiet) {
        size_t regions = 0, pieces = 0;
        for (i = 0; i < res.n; i++) {
            regions += res.r[i].n > 0;
            pieces += res.r[i].n;
        }
        printf("svg: %lu records, %lu visible regions (%lu convex pieces, %lu clip polygons), "
               "visible area %.4f px^2 -> %s\n",
               (unsigned long)recs->n, (unsigned long)regions, (unsigned long)pieces, res.clips,
               res.area, o->svg);
    }
    rc = 0;
out:
    sim_vr_free(&res);
    free(ids);
    free(tag_rgb);
    free(rgb);
    free(seen);
    return rc;
}

int sim_cmd_render(int argc, char **argv)
{
    sim_render_opts o;
    zs_model scene;
    zs_renderer r;
    zs_camera cam;
    zs_config cfg;
    zs_shade_params sp;
    zs_mat34 model, *model_ptr = NULL;
    zs_vec3 eye, target, up;
    zs_fixed fov, near_z, far_z;
    zs_status st;
    void *arena = NULL;
    uint8_t *img = NULL;
    FILE *dump = NULL;
    sim_rc_set recs;
    size_t arena_size, stride, i;
    unsigned bpp;
    int rc = SIM_EXIT_FAIL, f;
    zs_bspb_result bsp;          /* --order bsp: the tree of all chunks */
    zs_mesh bsp_mesh;
    unsigned long bsp_tris = 0;
    size_t n_cells = 0;            /* --cells: the scene's cells */

    memset(&scene, 0, sizeof scene);
    memset(&recs, 0, sizeof recs);
    memset(&bsp, 0, sizeof bsp);
    f = sim_render_parse(argc, argv, &o);
    if (f != 0 || o.done) {
        sim_render_opts_free(&o);
        return f;
    }
    eye = o.q_eye;
    target = o.q_target;
    up = o.q_up;
    fov = o.q_fov;
    near_z = o.q_near;
    far_z = o.q_far;

    for (f = 0; f < o.nfiles; f++) {
        zs_model_opts lo = zs_model_opts_default();
        lo.want_normals = o.shade == SHADE_GOURAUD ? (o.smooth ? 2 : 1) : 0;
        lo.flip_winding = o.flip_winding;
        lo.up = o.up_axis;
        lo.quiet = o.quiet;
        if (o.textures) {
            lo.load_texture = sim_load_texture;
            lo.texture_user = &o;
        }
        if (zs_model_load_opts(&scene, o.files[f], &lo) != 0)
            goto done;
        if (scene.total_tris * (o.two_sided ? 2u : 1u) > ZS_MAX_TRIANGLES) {
            fprintf(stderr,
                    "zspan-sim: %s: too many triangles (%lu so far%s); a frame takes at most "
                    "%u (and the tags of --shade ids are 16-bit). Decimate it with the "
                    "converter, which writes a file zspan-sim reads:\n"
                    "  zspan-meshc --max-triangles %u --format zsm -o out/model %s\n"
                    "  zspan-sim render out/model.zsm ...\n",
                    o.files[f], (unsigned long)scene.total_tris,
                    o.two_sided ? ", twice with --two-sided" : "", (unsigned)ZS_MAX_TRIANGLES,
                    o.two_sided ? 30000u : 60000u, o.files[f]);
            goto done;
        }
    }

    if (o.fit) {
        double lo[3], hi[3], c[3], radius;
        if (zs_model_bounds(&scene, lo, hi)) {
            for (f = 0; f < 3; f++)
                c[f] = 0.5 * (lo[f] + hi[f]);
            radius = zs_model_radius(&scene, c);
            zs_model_transform(&scene, c, radius > 0.0 ? 1.0 / radius : 1.0);
        }
    }
    if (zs_model_quantize(&scene) != 0)
        goto done;

    /* Colours: vertex colours, else the material's diffuse colour, else (flat)
     * a palette colour per triangle or (gouraud) a light grey. */
    for (i = 0; i < scene.count; i++) {
        zs_model_chunk *c = &scene.chunks[i];
        if (o.shade == SHADE_FLAT && c->vcol == NULL && !c->has_material_color &&
            c->tcount > 0) {
            uint32_t t;
            c->fcol = malloc((size_t)c->tcount * sizeof *c->fcol);
            if (c->fcol == NULL) {
                fprintf(stderr, "zspan-sim: out of memory\n");
                goto done;
            }
            for (t = 0; t < c->tcount; t++)
                c->fcol[t] = palette_color(c->first_tri + t);
            c->mesh.face_colors = c->fcol;
        }
    }

    if (o.two_sided && zs_model_add_back_faces(&scene) != 0) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        goto done;
    }

    if (o.has_rot) {
        zs_fixed ax, ay, az;
        zs_mat34 rx, ry, rz, m;
        if (zs_opt_fixed(SIM_PROG, "--rotate", o.rot[0], &ax) != 0 ||
            zs_opt_fixed(SIM_PROG, "--rotate", o.rot[1], &ay) != 0 ||
            zs_opt_fixed(SIM_PROG, "--rotate", o.rot[2], &az) != 0) {
            rc = SIM_EXIT_USAGE;
            goto done;
        }
        /* Rx first, then Ry, then Rz: M = Rz * Ry * Rx. */
        rx = zs_mat34_rotate_x(ax);
        ry = zs_mat34_rotate_y(ay);
        rz = zs_mat34_rotate_z(az);
        m = zs_mat34_mul(&ry, &rx);
        model = zs_mat34_mul(&rz, &m);
        model_ptr = &model;
    }

    if ((o.order != SIM_ORDER_SUBMIT || o.painter) && o.mode != ZS_MODE_PRIORITY) {
        fprintf(stderr, "zspan-sim: --order and --painter need --mode priority\n");
        rc = SIM_EXIT_USAGE;
        goto done;
    }
    if (o.cells && (o.order == SIM_ORDER_BSP || o.n_opacity)) {
        fprintf(stderr, "zspan-sim: --cells: not with --order bsp (one tree) or --opacity\n");
        rc = SIM_EXIT_USAGE;
        goto done;
    }
    if (o.order == SIM_ORDER_BSP && build_tree(&scene, &bsp, &bsp_mesh, &bsp_tris, &o) != 0)
        goto done;

    /* Arena from the scene: clipping can split a triangle into a few. */
    cfg = zs_app_config(o.width, o.height,
                        o.max_tris ? (unsigned long)o.max_tris
                                   : (scene.total_tris + bsp_tris) * 3ul + 64u,
                        (unsigned long)o.max_verts, (unsigned long)o.max_edges);
    if (o.order == SIM_ORDER_NNS || o.order == SIM_ORDER_SORT)
        cfg.flags |= ZS_CFG_PRIORITY;
    if (o.aa || o.n_opacity)
        cfg.flags |= ZS_CFG_ABUFFER;
    if (scene.ntex) {
        if (cfg.flags & ZS_CFG_ABUFFER) {
            fprintf(stderr, "zspan-sim: --aa and --opacity do not go with textures (the core's "
                            "A-buffer is untextured): leave out --textures, or convert the "
                            "model with zspan-meshc --texture none\n");
            rc = SIM_EXIT_USAGE;
            goto done;
        }
        cfg.flags |= ZS_CFG_TEXTURE;
    }
    arena = zs_app_renderer(&r, &cfg, &arena_size, SIM_PROG);
    if (arena == NULL)
        goto done;
    /* Checked by sim_render_parse: these cannot fail here. */
    st = zs_camera_look_at(&cam, eye, target, up);
    if (st == ZS_OK)
        st = zs_camera_perspective(&cam, fov, near_z, far_z);
    if (st != ZS_OK) {
        rc = core_error("the camera", st);
        goto done;
    }
    st = zs_frame_begin(&r, &cam, o.mode);
    if (st != ZS_OK) {
        rc = core_error("zs_frame_begin", st);
        goto done;
    }

    sp = zs_shade_default();
    sp.background = o.background;
    if (o.shade == SHADE_IDS) {
        sp.shading = ZS_SHADE_FLAT;
        sp.format = ZS_FMT_ID16;
    } else {
        sp.shading = o.shade == SHADE_GOURAUD ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
        sp.format = ZS_FMT_RGB888;
        if (o.unlit) {
            sp.ambient = ZS_FX_ONE;
            sp.light_count = 0;
        } else {
            double ld[3];
            double ambient = o.has_ambient ? o.ambient : 0.3;
            double intensity = o.has_light ? o.light[3] : 0.7;
            zs_vec3 lv;
            if (o.has_light) {
                ld[0] = o.light[0];
                ld[1] = o.light[1];
                ld[2] = o.light[2];
                normalize3(ld);
            } else {
                default_light(&o, ld);
            }
            if (vec_to_fixed("--light", ld, &lv) != 0 ||
                zs_opt_fixed(SIM_PROG, "--ambient", ambient, &sp.ambient) != 0 ||
                zs_opt_fixed(SIM_PROG, "--light", intensity, &sp.lights[0].intensity) != 0) {
                rc = SIM_EXIT_USAGE;
                goto done;
            }
            sp.light_count = 1;
            sp.lights[0].direction = lv;
        }
        if (o.fog) {
            sp.fog.enabled = 1;
            sp.fog.color = o.fog_color;
            if (zs_opt_fixed(SIM_PROG, "--fog", o.fog_start, &sp.fog.start) != 0 ||
                zs_opt_fixed(SIM_PROG, "--fog", o.fog_end, &sp.fog.end) != 0) {
                rc = SIM_EXIT_USAGE;
                goto done;
            }
        }
    }
    if (o.raycast) { /* the core's frame in tags: what the rays must agree with */
        sp.format = ZS_FMT_ID16;
        sp.shading = ZS_SHADE_FLAT;
    }
    st = zs_frame_shading(&r, &sp);
    if (st != ZS_OK) {
        rc = core_error("zs_frame_shading", st);
        goto done;
    }
    if (o.aa || o.n_opacity) {
        st = zs_frame_antialias(&r, o.n_opacity ? ZS_AA_TRANSPARENT : ZS_AA_EDGES);
        if (st != ZS_OK) {
            rc = core_error("zs_frame_antialias (--aa, --opacity)", st);
            goto done;
        }
    }

    if (o.dump != NULL) {
        dump = fopen(o.dump, "w");
        if (dump == NULL) {
            fprintf(stderr, "zspan-sim: cannot write %s: %s\n", o.dump, strerror(errno));
            goto done;
        }
        zs_set_setup_hook(&r, dump_hook, dump);
    }
    if (o.raycast || o.svg != NULL) { /* the records, for the host's own visibility */
        recs.dump = dump;
        zs_set_setup_hook(&r, sim_rc_hook, &recs);
    }
    for (i = 0; i < scene.count; i++) {
        if (o.n_opacity) {
            st = zs_draw_opacity(&r, o.opacity[i < (size_t)o.n_opacity ? i : (size_t)o.n_opacity - 1]);
            if (st != ZS_OK) {
                rc = core_error("zs_draw_opacity", st);
                goto done;
            }
        }
        if (o.cells) {
            st = sim_draw_cells(&r, &scene, model_ptr, o.cells - 1, &n_cells);
            i = scene.count; /* the cells hold every chunk */
        } else if (o.order == SIM_ORDER_BSP) {
            zs_bsp tree = {bsp.nodes, &bsp_mesh, (uint16_t)bsp.node_count};
            st = zs_draw_bsp(&r, &tree, model_ptr);
            i = scene.count; /* one tree holds them all */
        } else {
            st = zs_draw(&r, &scene.chunks[i].mesh, model_ptr);
        }
        if (st != ZS_OK) {
            rc = core_error(o.cells ? "zs_draw_cells"
                            : o.order == SIM_ORDER_BSP ? "zs_draw_bsp"
                                                       : "zs_draw",
                            st);
            goto done;
        }
    }
    if (o.order == SIM_ORDER_NNS || o.order == SIM_ORDER_SORT) {
        st = zs_depth_sort(&r, o.order == SIM_ORDER_NNS ? ZS_SORT_NNS : ZS_SORT_DEPTH, 0);
        if (st != ZS_OK) {
            rc = core_error("zs_depth_sort", st);
            goto done;
        }
    }
    zs_set_setup_hook(&r, NULL, NULL);
    if (recs.failed) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        goto done;
    }
    if (o.svg_lines != NULL && write_svg_lines(&o, &scene, model_ptr, &cam) != 0)
        goto done;

    bpp = zs_format_bytes(sp.format);
    stride = (size_t)o.width * bpp;
    img = calloc((size_t)o.height, stride);
    if (img == NULL) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        goto done;
    }
    st = o.painter ? zs_paint_frame(&r, img, stride)
                   : sim_render_image(&r, img, stride, o.height, (int)o.band);
    if (st != ZS_OK) {
        rc = core_error(o.painter ? "zs_paint_frame" : "zs_render_frame", st);
        goto done;
    }
    if (dump != NULL) {
        int bad = ferror(dump);
        if (fclose(dump) != 0 || bad) {
            dump = NULL;
            fprintf(stderr, "zspan-sim: error writing %s\n", o.dump);
            goto done;
        }
        dump = NULL;
    }

    if (o.svg != NULL &&
        svg_output(&o, &r, &cam, &sp, &scene, model_ptr, &recs, img, stride) != 0)
        goto done;
    if (o.raycast) {
        if (raycast_output(&o, &recs, img, stride) != 0)
            goto done;
    } else if (!o.out_set && sim_make_parent_dirs(o.out) != 0) {
        goto done; /* only the default's out/ is created */
    } else if (o.shade == SHADE_IDS) {
        if (png_write_gray16(o.out, o.width, o.height, img, stride) != 0)
            goto done;
    } else if (png_write_rgb8(o.out, o.width, o.height, img, stride) != 0) {
        goto done;
    }

    {
        const zs_stats *s = zs_frame_stats(&r);
        if (!o.quiet) {
            printf("render: %d files, %lu triangles -> %s (%dx%d, %s, %s, checksum %08lx)\n",
                   o.nfiles, (unsigned long)scene.total_tris, o.out, o.width, o.height,
                   sim_mode_name(o.mode),
                   o.shade == SHADE_IDS ? "ids" : o.shade == SHADE_GOURAUD ? "gouraud" : "flat",
                   (unsigned long)sim_fnv1a(img, stride * (size_t)o.height));
            sim_print_stats(stdout, s);
            if (o.cells)
                printf("  cells: %lu chunks in %lu cells (%s)\n", (unsigned long)scene.count,
                       (unsigned long)n_cells, o.cells == 1 ? "k-d tree" : "uniform grid");
            if (o.painter)
                printf("  painter: %lu pixel writes, %.2f per pixel (the background's "
                       "included), %lu records painted\n",
                       (unsigned long)s->pixels_shaded,
                       (double)s->pixels_shaded / ((double)o.width * o.height),
                       (unsigned long)s->tris_drawn);
            if (o.aa || o.n_opacity)
                printf("  a-buffer: %lu pixels resolved from %lu fragments (at most %lu), %lu "
                       "left aliased (pool full), %lu triangles left out\n",
                       (unsigned long)s->aa_pixels, (unsigned long)s->aa_fragments,
                       (unsigned long)s->aa_max_fragments, (unsigned long)s->aa_overflow,
                       (unsigned long)s->aa_skipped);
        }
        if (s->records_dropped || s->verts_dropped || s->records_skipped)
            fprintf(stderr,
                    "zspan-sim: warning: pools full: %lu triangles (%lu records) and %lu "
                    "vertices dropped, %lu triangles not activated (edge pool)\n",
                    (unsigned long)s->tris_dropped, (unsigned long)s->records_dropped,
                    (unsigned long)s->verts_dropped, (unsigned long)s->records_skipped);
    }
    rc = SIM_EXIT_OK;
done:
    zs_bspb_free(&bsp);
    if (dump != NULL)
        fclose(dump);
    free(img);
    free(arena);
    sim_rc_free(&recs);
    zs_model_free(&scene);
    sim_render_opts_free(&o);
    return rc;
}
