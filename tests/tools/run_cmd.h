/* SPDX-License-Identifier: MIT */
/*
 * Runs a program through the shell for the command-line suites (test_sim,
 * test_meshc, test_meshc_tex, ...): exit status and joined output kept.
 */
#ifndef ZSPAN_TESTS_RUN_CMD_H
#define ZSPAN_TESTS_RUN_CMD_H

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>

#ifndef SIM
#define SIM "build/zspan-sim"
#endif
#ifndef MESHC
#define MESHC "build/zspan-meshc"
#endif
#ifndef ASSIMP_MODELS
#define ASSIMP_MODELS "/usr/share/assimp/models"
#endif
#ifndef TOOLS_DATA
#define TOOLS_DATA "tests/tools/data"
#endif

typedef struct run_result {
    int exited;   /* 1 if it exited normally (not by a signal) */
    int status;   /* its exit status, or -1 */
    char out[16384]; /* stdout and stderr */
} run_result;

/* Runs the shell command (a printf format) under `timeout 120` with stderr
 * joined to stdout. A hang shows as status 124. */
static void run(run_result *res, const char *fmt, ...)
{
    char text[12288], cmd[16384];
    va_list ap;
    FILE *p;
    size_t n = 0, i, k;
    int st;

    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    /* timeout 120 sh -c 'TEXT' 2>&1, with the quotes of TEXT escaped */
    k = (size_t)snprintf(cmd, sizeof cmd, "timeout 120 sh -c '");
    for (i = 0; text[i] != 0 && k + 8 < sizeof cmd; i++) {
        if (text[i] == '\'') {
            memcpy(cmd + k, "'\\''", 4);
            k += 4;
        } else {
            cmd[k++] = text[i];
        }
    }
    cmd[k] = 0;
    strncat(cmd, "' 2>&1", sizeof cmd - strlen(cmd) - 1);
    p = popen(cmd, "r");
    res->exited = 0;
    res->status = -1;
    res->out[0] = 0;
    if (p == NULL)
        return;
    while (n + 1 < sizeof res->out) {
        size_t got = fread(res->out + n, 1, sizeof res->out - 1 - n, p);
        if (got == 0)
            break;
        n += got;
    }
    res->out[n] = 0;
    while (fgetc(p) != EOF) {
    }
    st = pclose(p);
    /* timeout's own status carries the program's: 128 + signal if it died. */
    res->exited = WIFEXITED(st) && WEXITSTATUS(st) < 128;
    res->status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

#endif
