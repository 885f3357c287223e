/* SPDX-License-Identifier: MIT */
/*
 * Firmware test: frame 0 of the sphere285 benchmark scene, both visibility
 * modes, the three 1-bit outputs (ordered dither, error diffusion, hidden
 * lines) and GRAY4 rounded and dithered (bench_mono_frame), the textured
 * scene (bench_tex_frame) and its geometry in Warnock mode and through the
 * A-buffer (edges, transparency; bench_extra_frame), on the Cortex-M4 (QEMU
 * mps2-an386) and Cortex-M0 (QEMU microbit, 16 KB RAM) images; the frame
 * checksums must equal the host's, and the host's Warnock frame its span
 * frame. Also checks
 * the SysTick calibration under -icount shift=0 and that no pool overflowed.
 * Takes well under a second per machine.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#ifndef BENCH_HOST
#define BENCH_HOST "build/bench/bench_host"
#endif
#ifndef FW_M4
#define FW_M4 "build/fw/bench-mps2-an386.elf"
#endif
#ifndef FW_M0
#define FW_M0 "build/fw/bench-microbit.elf"
#endif
#ifndef FW_QEMU
#define FW_QEMU "qemu-system-arm"
#endif
#ifndef FW_QEMU_FLAGS
#define FW_QEMU_FLAGS "-nographic -monitor none -serial none -icount shift=0 " \
                      "-semihosting-config enable=on,target=native"
#endif

typedef struct output {
    char text[16384];
    int status;
} output;

static void run(output *o, const char *cmd)
{
    FILE *p = popen(cmd, "r");
    size_t n = 0;
    int st;
    assert_non_null(p);
    for (;;) {
        size_t got = fread(o->text + n, 1, sizeof o->text - 1 - n, p);
        if (got == 0)
            break;
        n += got;
        if (n + 1 >= sizeof o->text)
            break;
    }
    o->text[n] = 0;
    while (fgetc(p) != EOF) {
    }
    st = pclose(p);
    o->status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Finds "R <board> <scene> <mode> 0 ... sum=XXXXXXXX" and returns the sum
 * (scene: sphere285, or textured from outputs[TEX_FIRST] on). */
static int find_sum(const char *text, const char *board, const char *scene, const char *mode,
                    unsigned long *sum, unsigned long *instr, unsigned long *dropped)
{
    char prefix[96];
    const char *p;
    snprintf(prefix, sizeof prefix, "R %s %s %s 0 ", board,
             scene, mode);
    p = strstr(text, prefix);
    if (!p)
        return 0;
    *instr = 0;
    *dropped = 0;
    {
        const char *s = strstr(p, "sum=");
        const char *i = strstr(p, "instr=");
        const char *d = strstr(p, "dropped=");
        const char *eol = strchr(p, '\n');
        if (!s || (eol && s > eol))
            return 0;
        *sum = strtoul(s + 4, NULL, 16);
        if (i && (!eol || i < eol))
            *instr = strtoul(i + 6, NULL, 10);
        if (d && (!eol || d < eol))
            *dropped = strtoul(d + 8, NULL, 10);
    }
    return 1;
}

/* span, zline, the 1-bit and GRAY4 outputs of bench_mono_frame, the
 * textured frames of bench_tex_frame, the Warnock and A-buffer frames of
 * bench_extra_frame (the textured scene's geometry) */
#define N_OUTPUTS 16
static const char *const outputs[N_OUTPUTS] = {
    "span", "zline", "mono-bayer", "mono-diffuse", "mono-lines", "gray4", "gray4-dither",
    "tex-plain", "tex-nearest", "tex-nearest-zline", "tex-subdiv", "tex-bilinear", "tex-lit-fog",
    "warnock", "aa-edges", "aa-transparent"};
#define TEX_FIRST 7    /* outputs[TEX_FIRST] is "tex-plain" */
#define EXTRA_FIRST 13 /* outputs[EXTRA_FIRST] is "warnock" */
#define SCENE_OF(m) ((m) < TEX_FIRST ? "sphere285" : "textured")
static unsigned long host_sum[N_OUTPUTS];

static int host_setup(void **state)
{
    static output o;
    unsigned long instr, dropped;
    (void)state;
    run(&o, BENCH_HOST " run --scene sphere285 --frames 1 --mono 2>&1");
    if (o.status != 0) {
        fprintf(stderr, "bench_host failed (%d):\n%s\n", o.status, o.text);
        return -1;
    }
    {
        int m;
        for (m = 0; m < N_OUTPUTS; m++)
            if (!find_sum(o.text, "host", SCENE_OF(m), outputs[m], &host_sum[m], &instr,
                          &dropped)) {
                fprintf(stderr, "no host %s checksum in:\n%s\n", outputs[m], o.text);
                return -1;
            }
    }
    /* the textured frame is the same in both modes, and textured at all */
    if (host_sum[TEX_FIRST + 1] != host_sum[TEX_FIRST + 2] ||
        host_sum[TEX_FIRST] == host_sum[TEX_FIRST + 1]) {
        fprintf(stderr, "host textured checksums: plain %08lx nearest %08lx zline %08lx\n",
                host_sum[TEX_FIRST], host_sum[TEX_FIRST + 1], host_sum[TEX_FIRST + 2]);
        return -1;
    }
    /* Warnock mode: the span image byte for byte; anti-aliasing changes it */
    if (host_sum[EXTRA_FIRST] != host_sum[TEX_FIRST] ||
        host_sum[EXTRA_FIRST + 1] == host_sum[TEX_FIRST] ||
        host_sum[EXTRA_FIRST + 2] == host_sum[EXTRA_FIRST + 1]) {
        fprintf(stderr, "host checksums: tex-plain %08lx warnock %08lx aa-edges %08lx "
                        "aa-transparent %08lx\n",
                host_sum[TEX_FIRST], host_sum[EXTRA_FIRST], host_sum[EXTRA_FIRST + 1],
                host_sum[EXTRA_FIRST + 2]);
        return -1;
    }
    return 0;
}

static void check_machine(const char *machine, const char *elf, const char *board,
                          unsigned nominal_ipt_milli)
{
    static output o;
    char cmd[1024];
    const char *info;
    int m;
    snprintf(cmd, sizeof cmd,
             "timeout 60 " FW_QEMU " -M %s " FW_QEMU_FLAGS ",arg=bench,arg=quick -kernel %s 2>&1",
             machine, elf);
    run(&o, cmd);
    print_message("%s", o.text);
    if (o.status != 0)
        fail_msg("%s: exit status %d", machine, o.status);
    info = strstr(o.text, "ipt_milli=");
    assert_non_null(info);
    {
        unsigned long ipt = strtoul(info + 10, NULL, 10);
        /* -icount shift=0: 1 instruction per ns; SysTick counts the CPU clock */
        assert_true(ipt + 10 >= nominal_ipt_milli && ipt <= nominal_ipt_milli + 10);
    }
    for (m = 0; m < N_OUTPUTS; m++) {
        unsigned long sum, instr, dropped;
        if (!find_sum(o.text, board, SCENE_OF(m), outputs[m], &sum, &instr, &dropped))
            fail_msg("%s: no %s result", machine, outputs[m]);
        if (sum != host_sum[m])
            fail_msg("%s %s: checksum %08lx, host %08lx", machine, outputs[m], sum, host_sum[m]);
        assert_int_equal(dropped, 0);
        assert_true(instr > 1000);
    }
}

static void test_cortex_m4_mps2_an386(void **state)
{
    (void)state;
    check_machine("mps2-an386", FW_M4, "mps2-an386", 40000);
}

static void test_cortex_m0_microbit(void **state)
{
    (void)state;
    check_machine("microbit", FW_M0, "microbit", 62500);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cortex_m4_mps2_an386),
        cmocka_unit_test(test_cortex_m0_microbit),
    };
    return cmocka_run_group_tests_name("firmware", tests, host_setup, NULL);
}
