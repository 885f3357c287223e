/* SPDX-License-Identifier: MIT */
/*
 * zspan-sim: the host simulator of zspan.
 *
 *   zspan-sim demo [options]            the built-in scene -> out/demo.png
 *   zspan-sim render FILE... [options]  meshes (assimp) -> PNG
 *   zspan-sim --help
 */
#include "sim.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "demo_scene.h"
#include "png_out.h"
#include "zs_arena.h"
#include "zs_opts.h"

#define SIM_MAX_COMMANDS 16
static const sim_command *extra_commands[SIM_MAX_COMMANDS];
static int n_extra_commands;

void sim_register_command(const sim_command *cmd)
{
    if (cmd != NULL && n_extra_commands < SIM_MAX_COMMANDS)
        extra_commands[n_extra_commands++] = cmd;
}

void sim_print_demo_usage(FILE *f)
{
    fputs("usage: zspan-sim demo [options]\n"
          "Renders the built-in scene (a torus sunk into a checkered ground, cubes\n"
          "cutting into each other, a pyramid) and prints the frame statistics.\n"
          "  --out FILE.png        output (default out/demo.png; out/ is created, any\n"
          "                        other directory must exist)\n"
          "  --mode span|zline     visibility mode (default span)\n"
          "  --shade flat|gouraud  shading (default gouraud)\n"
          "  --size WxH            image size (default 240x240)\n"
          "  --frame N             camera orbit frame, 3 degrees each (default 0)\n"
          "  --aa                  anti-aliased edges: 4x4 sub-samples where edges and\n"
        "                        penetrations cross (the A-buffer; span mode only)\n"
        "  --opacity A1[,A2...]  opacity 0..255 of each mesh in file order (the last\n"
        "                        repeats); blended in depth order, with --aa's edges\n"
        "  --band N              rows per zs_render_frame band (default 1)\n"
          "  --no-compare          do not also render the other mode and compare\n"
          "  --help, --version\n",
          f);
}

void sim_print_render_usage(FILE *f)
{
    fputs(
        "usage: zspan-sim render FILE [FILE...] [options]\n"
        "Loads meshes with assimp (triangulated; points and lines skipped), or the\n"
        "binary meshes of zspan-meshc --format zsm, and renders them. Triangle tags\n"
        "are 1-based in load order across all files.\n"
        "  --size WxH            image size (default 240x240)\n"
        "  --fov DEG             vertical field of view (default 60)\n"
        "  --near N --far F      clip distances (default 0.1 and 100)\n"
        "  --eye x,y,z           camera position (default 0,0,3)\n"
        "  --target x,y,z        point looked at (default 0,0,0)\n"
        "  --up x,y,z            camera up direction (default 0,1,0)\n"
        "  --up AXIS, --up-axis AXIS\n"
        "                        the files' up axis (x, y, z, -x, -y, -z): the model is\n"
        "                        turned so that it points up (+y); default auto: the\n"
        "                        file's own up-axis metadata (FBX), else y\n"
        "  --flip-winding        the files' triangles are clockwise: reverse them\n"
        "  --two-sided           draw back faces too (a reversed copy of every\n"
        "                        triangle; its tags follow all the originals')\n"
        "  --textures            map the materials' diffuse textures (assimp files: PNG,\n"
        "                        JPEG or TGA, embedded or beside the model; .zsm files\n"
        "                        always show the texture the converter stored)\n"
        "  --texture-size N      their largest side, a power of two (default 256)\n"
        "  --texture-filter nearest|bilinear  (default nearest)\n"
        "  --fit                 centre the bounding box of all meshes on the origin and\n"
        "                        scale so the farthest vertex is at distance 1; without it\n"
        "                        mesh coordinates are world coordinates\n"
        "  --rotate ax,ay,az     model rotation in degrees, after --fit: about x first,\n"
        "                        then y, then z (M = Rz * Ry * Rx), about the origin\n"
        "  --mode span|zline|warnock|priority|raycast\n"
        "                        visibility mode (default span); raycast: a ray per pixel\n"
        "                        centre through the core's snapped triangles, on the host\n"
        "                        in double precision (prints how it agrees with span mode;\n"
        "                        the PNG: tags with --shade ids, else palette colours, unlit)\n"
        "  --grid N              raycast: uniform grid of N x N pixel cells (default 8;\n"
        "                        0: every ray tests every triangle)\n"
        "                        priority: the order decides, from --order\n"
        "  --order bsp|nns|sort  (priority) bsp: each mesh compiled into a BSP tree and\n"
        "                        walked from the eye; nns: depth sort with the\n"
        "                        Newell-Newell-Sancha tests; sort: depth sort alone\n"
        "                        (approximate); default: the files' own order\n"
        "  --painter             (priority) the records painted back to front into the\n"
        "                        whole image (zs_paint_frame) instead of rendered in\n"
        "                        bands; the same image, and the overdraw it costs\n"
        "  --cells kd|grid       the files' meshes (chunks) as objects of scene cells,\n"
        "                        a k-d tree (default) or a uniform grid: cells outside\n"
        "                        the view are never transformed (zs_draw_cells)\n"
        "  --shade flat|gouraud|ids\n"
        "                        flat/gouraud: 8-bit RGB PNG; ids: 16-bit grey PNG whose\n"
        "                        value is the tag of the visible triangle, 0 = background\n"
        "                        (default flat)\n"
        "  --smooth              (gouraud) recompute smooth vertex normals from the\n"
        "                        winding even when the file has its own (default: the\n"
        "                        file's normals, smooth ones only when it has none)\n"
        "  --out FILE.png        output (default out/render.png; out/ is created, any\n"
        "                        other directory must exist)\n"
        "  --svg-lines FILE      also the visible silhouettes, creases and boundaries (crease\n"
        "                        30 degrees) as SVG lines, computed exactly on the host\n"
        "  --svg FILE            also the visible region of every triangle (Weiler-Atherton,\n"
        "                        on the host) as filled SVG paths in the image's colours\n"
        "  --dump-tris FILE      one line per stored triangle record: tag, then x y z of\n"
        "                        each vertex (x, y in pixels, z window depth in [0, 1])\n"
        "  --background RRGGBB   background colour (default 000000)\n"
        "  --light x,y,z[,I]     direction toward the light, intensity I (default 0.7;\n"
        "                        default direction: over the viewer's left shoulder)\n"
        "  --ambient A           ambient term (default 0.3)\n"
        "  --unlit               colours as they are (ambient 1, no light)\n"
        "  --fog start,end,RRGGBB  distance fog\n"
        "  --aa                  anti-aliased edges: 4x4 sub-samples where edges and\n"
        "                        penetrations cross (the A-buffer; span mode only)\n"
        "  --opacity A1[,A2...]  opacity 0..255 of each mesh in file order (the last\n"
        "                        repeats); blended in depth order, with --aa's edges\n"
        "  --band N              rows per zs_render_frame band (default 1)\n"
        "  --max-tris N --max-verts N --max-edges N\n"
        "                        pool capacities (default: from the triangle count)\n"
        "  --quiet               print nothing on success (and no warnings)\n"
        "  --help, --version\n"
        "Colours: vertex colours, else the material's diffuse colour, else a palette\n"
        "colour per triangle (flat) or light grey (gouraud). Counter-clockwise faces\n"
        "are front faces. Numbers are decimal, converted to Q16.16 (rounded). An\n"
        "import running longer than 30 s ($ZSPAN_IMPORT_SECONDS) is stopped.\n"
        "A model of more than 65535 triangles: decimate it with zspan-meshc\n"
        "--max-triangles N --format zsm and render the .zsm file.\n",
        f);
}

void sim_print_usage(FILE *f)
{
    int i;

    fputs("usage: zspan-sim demo [options]\n"
          "       zspan-sim render FILE [FILE...] [options]\n"
          "       zspan-sim COMMAND [options]   (extension commands, listed at the end)\n"
          "       zspan-sim COMMAND --help      (the options of one command)\n"
          "       zspan-sim --help | --version\n"
          "Exit status: 0 ok, 1 failure (file, core, output), 2 bad command line.\n\n",
          f);
    sim_print_demo_usage(f);
    fputc('\n', f);
    sim_print_render_usage(f);
    for (i = 0; i < n_extra_commands; i++) {
        fprintf(f, "\n%s:\n", extra_commands[i]->name);
        if (extra_commands[i]->usage != NULL)
            fputs(extra_commands[i]->usage, f);
    }
}

static double now_ms(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1000.0 + (double)ts.tv_nsec / 1e6;
}

/* Renders demo frame `frame` into img (RGB888). Returns a status; *ms gets the
 * time from zs_frame_begin to the last row. */
static zs_status demo_render(zs_renderer *r, const demo_scene *s, uint32_t frame,
                             zs_visibility mode, zs_shading shading, uint8_t *img, size_t stride,
                             int height, int band, double *ms)
{
    double t0 = now_ms();
    zs_status st = demo_frame(r, s, frame, mode, shading, ZS_FMT_RGB888);

    if (st != ZS_OK)
        return st;
    st = sim_render_image(r, img, stride, height, band);
    *ms = now_ms() - t0;
    return st;
}

int sim_demo_parse(int argc, char **argv, sim_demo_opts *o)
{
    int i;

    memset(o, 0, sizeof *o);
    o->out = SIM_DEMO_OUT;
    o->mode = ZS_MODE_SPAN;
    o->shading = ZS_SHADE_GOURAUD;
    o->width = 240;
    o->height = 240;
    o->compare = 1;
    o->band = 1;
    for (i = 1; i < argc; i++) {
        const char *v = NULL;
        int m;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            sim_print_demo_usage(stdout);
            o->done = 1;
            return SIM_EXIT_OK;
        } else if (zs_opt_version(argv[i], SIM_PROG)) {
            o->done = 1;
            return SIM_EXIT_OK;
        } else if (strcmp(argv[i], "--no-compare") == 0) {
            o->compare = 0;
        } else if ((m = zs_opt_value(argc, argv, &i, "--out", &v, SIM_PROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->out = v;
            o->out_set = 1;
        } else if ((m = zs_opt_value(argc, argv, &i, "--mode", &v, SIM_PROG)) != 0) {
            if (m < 0 || zs_opt_mode(SIM_PROG, v, &o->mode) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--shade", &v, SIM_PROG)) != 0) {
            if (m < 0 || zs_opt_shade(SIM_PROG, v, &o->shading) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--size", &v, SIM_PROG)) != 0) {
            if (m < 0 || zs_opt_size(SIM_PROG, "--size", v, &o->width, &o->height) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--frame", &v, SIM_PROG)) != 0) {
            if (m < 0 || zs_opt_long(SIM_PROG, "--frame", v, 0, 1000000000L, &o->frame) != 0)
                return SIM_EXIT_USAGE;
        } else if ((m = zs_opt_value(argc, argv, &i, "--band", &v, SIM_PROG)) != 0) {
            if (m < 0 || zs_opt_long(SIM_PROG, "--band", v, 1, ZS_MAX_DIM, &o->band) != 0)
                return SIM_EXIT_USAGE;
        } else {
            fprintf(stderr, "zspan-sim: demo: unknown argument '%s' (see zspan-sim demo --help)\n",
                    argv[i]);
            return SIM_EXIT_USAGE;
        }
    }
    if (o->out_set && sim_check_output(o->out, "--out") != 0)
        return SIM_EXIT_USAGE;
    return 0;
}

int sim_cmd_demo(int argc, char **argv)
{
    static demo_scene scene;
    sim_demo_opts o;
    const char *out;
    zs_visibility mode;
    zs_shading shading;
    int width, height, compare, rc = SIM_EXIT_FAIL;
    long frame, band;
    zs_config cfg;
    zs_renderer r;
    zs_status st;
    zs_stats stats;
    void *arena = NULL;
    uint8_t *img = NULL, *other = NULL;
    size_t arena_size, stride;
    double ms = 0.0, ms_other = 0.0;

    rc = sim_demo_parse(argc, argv, &o);
    if (rc != 0 || o.done)
        return rc;
    rc = SIM_EXIT_FAIL;
    out = o.out;
    mode = o.mode;
    shading = o.shading;
    width = o.width;
    height = o.height;
    compare = o.compare;
    frame = o.frame;
    band = o.band;

    demo_scene_init(&scene);
    cfg = zs_app_config(width, height, 3ul * DEMO_TRIANGLES, 0, 0);
    arena = zs_app_renderer(&r, &cfg, &arena_size, SIM_PROG);
    stride = (size_t)width * 3u;
    img = calloc((size_t)height, stride);
    other = calloc((size_t)height, stride);
    if (arena == NULL)
        goto done;
    if (img == NULL || other == NULL) {
        fprintf(stderr, "zspan-sim: out of memory\n");
        goto done;
    }
    st = demo_render(&r, &scene, (uint32_t)frame, mode, shading, img, stride, height, (int)band,
                     &ms);
    if (st != ZS_OK) {
        fprintf(stderr, "zspan-sim: demo frame: %s\n", zs_strerror(st));
        goto done;
    }
    stats = *zs_frame_stats(&r);
    if ((!o.out_set && sim_make_parent_dirs(out) != 0) ||
        png_write_rgb8(out, width, height, img, stride) != 0)
        goto done;

    printf("demo: %dx%d, %s, %s, frame %ld -> %s\n", width, height, sim_mode_name(mode),
           shading == ZS_SHADE_GOURAUD ? "gouraud" : "flat", frame, out);
    printf("  scene: %d triangles, %d vertices in %d meshes; arena %lu bytes\n",
           (int)DEMO_TRIANGLES, (int)DEMO_VERTICES, 3 + DEMO_CUBES, (unsigned long)arena_size);
    sim_print_stats(stdout, &stats);
    printf("  frame checksum (FNV-1a of RGB888): %08lx; host time %.2f ms\n",
           (unsigned long)sim_fnv1a(img, stride * (size_t)height), ms);

    if (compare) {
        zs_visibility om = mode == ZS_MODE_SPAN ? ZS_MODE_ZLINE : ZS_MODE_SPAN;
        size_t n = stride * (size_t)height, k;
        unsigned long diff = 0;
        st = demo_render(&r, &scene, (uint32_t)frame, om, shading, other, stride, height,
                         (int)band, &ms_other);
        if (st != ZS_OK) {
            fprintf(stderr, "zspan-sim: demo frame (%s): %s\n", sim_mode_name(om),
                    zs_strerror(st));
            goto done;
        }
        for (k = 0; k < n; k += 3)
            diff += memcmp(img + k, other + k, 3) != 0;
        if (diff == 0)
            printf("  %s vs %s: identical images (%s %.2f ms)\n", sim_mode_name(mode),
                   sim_mode_name(om), sim_mode_name(om), ms_other);
        else
            printf("  %s vs %s: %lu of %lu pixels differ\n", sim_mode_name(mode),
                   sim_mode_name(om), diff, (unsigned long)(n / 3));
    }
    rc = SIM_EXIT_OK;
done:
    free(other);
    free(img);
    free(arena);
    return rc;
}

int main(int argc, char **argv)
{
    int i;

    if (argc < 2) {
        sim_print_usage(stderr);
        return SIM_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        sim_print_usage(stdout);
        return SIM_EXIT_OK;
    }
    if (zs_opt_version(argv[1], SIM_PROG))
        return SIM_EXIT_OK;
    if (strcmp(argv[1], "demo") == 0)
        return sim_cmd_demo(argc - 1, argv + 1);
    if (strcmp(argv[1], "render") == 0)
        return sim_cmd_render(argc - 1, argv + 1);
    for (i = 0; i < n_extra_commands; i++)
        if (strcmp(argv[1], extra_commands[i]->name) == 0)
            return extra_commands[i]->run(argc - 1, argv + 1);
    fprintf(stderr, "zspan-sim: unknown command '%s' (try zspan-sim --help)\n", argv[1]);
    return SIM_EXIT_USAGE;
}
