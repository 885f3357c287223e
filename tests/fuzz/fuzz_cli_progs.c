/* SPDX-License-Identifier: MIT */
/*
 * The programs whose option parsers live next to their main (zspan-meshc,
 * zspan-linux, zspan-mcp2210), compiled into fuzz_cli with main renamed:
 * each fuzz_*_parse runs the program's own parsing on argv and returns what
 * the program would do next: 0 (go on, or --help/--version answered) or its
 * usage exit status. One translation unit per program (PROG_MESHC, ...).
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdio.h>

#include "fuzz_util.h"

#if defined(PROG_MESHC)
/* The converter exits from its parser: every exit is a longjmp here. */
static jmp_buf g_jmp;
static int g_code;
__attribute__((noreturn)) void fuzz_cli_exit(int code);
void fuzz_cli_exit(int code)
{
    g_code = code;
    longjmp(g_jmp, 1);
}
#define exit fuzz_cli_exit
#define main meshc_main
#include "../../tools/zspan-meshc.c"
#undef exit
#undef main

int fuzz_meshc_parse(int argc, char **argv);
int fuzz_meshc_parse(int argc, char **argv)
{
    static options o; /* static: survives the longjmp */
    memset(&o, 0, sizeof o);
    if (setjmp(g_jmp) != 0) {
        FZ_CHECK(g_code == 0 || g_code == EXIT_USAGE, "zspan-meshc parse exit %d", g_code);
        return g_code;
    }
    parse_args(argc, argv, &o);
    /* Accepted: what the rest of the converter relies on. */
    FZ_CHECK(o.input != NULL, "no input accepted");
    FZ_CHECK(o.fit_radius > 0 && o.scale > 0, "fit %g scale %g", o.fit_radius, o.scale);
    FZ_CHECK(o.max_tris <= MAX_OUT && o.max_verts <= MAX_OUT, "limits %lu %lu", o.max_tris,
             o.max_verts);
    FZ_CHECK(o.quant_scale >= 0 && o.mem_limit_mb >= -1, "quant %ld mem %ld", o.quant_scale,
             o.mem_limit_mb);
    FZ_CHECK(o.name == NULL || ident_problem(o.name) == NULL, "name '%s' accepted", o.name);
    FZ_CHECK(o.base_color <= 0xFFFFFFu, "colour %lx", (unsigned long)o.base_color);
    return 0;
}

#elif defined(PROG_LINUX)
#define main linux_main
#include "../../ports/linux/zspan-linux.c"
#undef main

int fuzz_linux_parse(int argc, char **argv);
int fuzz_linux_parse(int argc, char **argv)
{
    zs_app_opts o;
    zs_linux_cfg c = zs_linux_cfg_default();
    zs_app_cli cli = {NULL, usage, port_option, NULL, NULL};
    int rc;

    cli.prog = prog;
    cli.cfg = &c;
    rc = zs_app_parse(&o, argc, argv, &cli);
    if (rc != ZS_APP_PARSED)
        return rc;
    FZ_CHECK(zs_panel_find(o.panel) != NULL, "panel '%s' accepted", o.panel);
    FZ_CHECK(o.rotation >= 0 && o.rotation <= 3 && o.band >= 1, "rotation %ld band %ld",
             o.rotation, o.band);
    zs_app_free(&o);
    return 0;
}

#elif defined(PROG_MCP2210)
#define main mcp2210_main
#include "../../ports/mcp2210/zspan-mcp2210.c"
#undef main

int fuzz_mcp2210_parse(int argc, char **argv);
int fuzz_mcp2210_parse(int argc, char **argv)
{
    zs_app_opts o;
    mcp_args args;
    zs_app_cli cli = {NULL, usage, port_option, NULL, NULL};
    int rc;

    args.c = zs_mcp2210_cfg_default();
    args.path = NULL;
    cli.prog = prog;
    cli.cfg = &args;
    rc = zs_app_parse(&o, argc, argv, &cli);
    if (rc != ZS_APP_PARSED)
        return rc;
    FZ_CHECK(zs_panel_find(o.panel) != NULL, "panel '%s' accepted", o.panel);
    FZ_CHECK(args.c.cs_pin <= 8 && args.c.dc_pin <= 8, "pins %d %d", (int)args.c.cs_pin,
             (int)args.c.dc_pin);
    zs_app_free(&o);
    return 0;
}

#elif defined(PROG_SIM)
/* zspan-sim's main is libFuzzer's to have. */
#define main sim_main
#include "../../host_sim/sim_main.c"
#undef main
#else
#error "define PROG_MESHC, PROG_LINUX, PROG_MCP2210 or PROG_SIM"
#endif
