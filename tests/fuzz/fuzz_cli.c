/* SPDX-License-Identifier: MIT */
/*
 * fuzz_cli: the option parser of every program over argv vectors
 * (libFuzzer): zspan-sim demo, render and panel, zspan-meshc, zspan-linux,
 * zspan-mcp2210, and the --seq file-name patterns.
 *
 * Input: byte 0 picks the parser; the rest, split at NUL bytes, are the
 * arguments (at most FUZZ_CLI_MAX_ARGS; tests/fuzz/cli.dict holds the
 * option names). The parsers run exactly as in the programs (their
 * messages go to the closed stdout/stderr: -close_fd_mask=3).
 *
 * Invariants:
 *  - no memory error, leak or undefined behaviour (ASan, UBSan, LSan);
 *  - the result is one the program documents: go on (0), or the usage
 *    status (2), never anything else;
 *  - what a parser accepts is what the rest of the program relies on: the
 *    camera options of render are taken by the core (zs_camera_perspective,
 *    zs_camera_look_at return ZS_OK), sizes and bands are in range, the
 *    panel exists, a mesh name is a usable C identifier, a --seq pattern
 *    accepted makes file names with the frame number in them.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "sim.h"
#include "zs_app.h"
#include "zs_opts.h"

#define FUZZ_CLI_MAX_ARGS 24

int fuzz_meshc_parse(int argc, char **argv);
int fuzz_linux_parse(int argc, char **argv);
int fuzz_mcp2210_parse(int argc, char **argv);

static void check_demo(int argc, char **argv)
{
    sim_demo_opts o;
    int rc = sim_demo_parse(argc, argv, &o);
    FZ_CHECK(rc == 0 || rc == SIM_EXIT_USAGE, "demo parse %d", rc);
    if (rc != 0 || o.done)
        return;
    FZ_CHECK(o.width >= 1 && o.width <= ZS_MAX_DIM && o.height >= 1 && o.height <= ZS_MAX_DIM,
             "size %dx%d", o.width, o.height);
    FZ_CHECK(o.band >= 1 && o.band <= ZS_MAX_DIM && o.frame >= 0, "band %ld frame %ld", o.band,
             o.frame);
}

static void check_render(int argc, char **argv)
{
    sim_render_opts o;
    zs_camera cam;
    int rc = sim_render_parse(argc, argv, &o);
    FZ_CHECK(rc == 0 || rc == SIM_EXIT_USAGE, "render parse %d", rc);
    if (rc == 0 && !o.done) {
        FZ_CHECK(o.nfiles >= 1, "no files");
        FZ_CHECK(o.fov > 0.0 && o.fov < 180.0 && o.q_near > 0 && o.q_far > o.q_near,
                 "fov %g near %d far %d", o.fov, (int)o.q_near, (int)o.q_far);
        FZ_CHECK(zs_camera_perspective(&cam, o.q_fov, o.q_near, o.q_far) == ZS_OK,
                 "projection refused after the parser took it");
        FZ_CHECK(zs_camera_look_at(&cam, o.q_eye, o.q_target, o.q_up) == ZS_OK,
                 "view refused after the parser took it");
        FZ_CHECK(o.width >= 1 && o.width <= ZS_MAX_DIM && o.height >= 1 &&
                     o.height <= ZS_MAX_DIM && o.band >= 1,
                 "size %dx%d band %ld", o.width, o.height, o.band);
        FZ_CHECK(o.up_axis >= 0 && o.up_axis <= 6, "up axis %d", o.up_axis);
    }
    sim_render_opts_free(&o);
}

/* An accepted pattern makes a name with the number where the conversion was. */
static void check_seq(const char *pattern)
{
    char buf[512], num[32];
    if (zs_opt_seq_pattern("fuzz", "--seq", pattern) != 0)
        return;
    if (zs_opt_seq_path(buf, sizeof buf, pattern, 4711) != 0)
        return; /* too long for buf */
    snprintf(num, sizeof num, "4711");
    FZ_CHECK(strstr(buf, num) != NULL, "'%s' -> '%s' lacks the number", pattern, buf);
    FZ_CHECK(strlen(buf) < sizeof buf, "overlong");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"demo", "render", "panel", "zspan-meshc",
                                        "zspan-linux", "zspan-mcp2210", "--seq"};
    char *copy, *argv[FUZZ_CLI_MAX_ARGS + 2];
    int argc = 1, which, rc;
    size_t k, start;

    if (size < 1)
        return 0;
    which = data[0] % 7;
    copy = malloc(size);
    if (copy == NULL)
        return 0;
    memcpy(copy, data + 1, size - 1);
    copy[size - 1] = '\0';
    argv[0] = (char *)names[which];
    for (k = 0, start = 0; k < size && argc <= FUZZ_CLI_MAX_ARGS; k++)
        if (copy[k] == '\0') {
            argv[argc++] = copy + start;
            start = k + 1;
            if (k == size - 1)
                break;
        }
    argv[argc] = NULL;
    switch (which) {
    case 0: check_demo(argc, argv); break;
    case 1: check_render(argc, argv); break;
    case 2:
        rc = sim_panel_parse_check(argc, argv);
        FZ_CHECK(rc == 0 || rc == SIM_EXIT_USAGE, "panel parse %d", rc);
        break;
    case 3:
        rc = fuzz_meshc_parse(argc, argv);
        FZ_CHECK(rc == 0 || rc == 2, "meshc parse %d", rc);
        break;
    case 4:
        rc = fuzz_linux_parse(argc, argv);
        FZ_CHECK(rc == 0 || rc == 2, "linux parse %d", rc);
        break;
    case 5:
        rc = fuzz_mcp2210_parse(argc, argv);
        FZ_CHECK(rc == 0 || rc == 2, "mcp2210 parse %d", rc);
        break;
    default:
        check_seq(argc > 1 ? argv[1] : "");
        break;
    }
    free(copy);
    return 0;
}
