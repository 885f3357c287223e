/* SPDX-License-Identifier: MIT */
/*
 * zspan-mcp2210 through the real stack: hidapi (hidraw backend) -> the Linux
 * kernel's hidraw -> uhid -> the MCP2210 model (a userspace HID device) ->
 * host_sim's emulated ST7789. The kernel is Debian's, booted under
 * qemu-system-x86_64 with software emulation (tests/ports/vm/run_vm.sh); the
 * model dumps what the panel shows to a second serial port and the test
 * compares it with the frame rendered here.
 *
 * Skipped (with the reason) when qemu, a kernel image with uhid, busybox-static
 * or cpio is missing; `make deps` installs them.
 */
#define _GNU_SOURCE
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmocka.h>

#include "ports_common.h"

#define WORK "build/tests/ports/vm/run"
#define MODEL "build/tests/ports/vm/mcp2210-uhid"
#define CLIENT "build/tests/ports/vm/zspan-mcp2210"

typedef struct dump {
    char tag[32];
    unsigned w, h, model_errors, panel_errors;
    unsigned long long busy, poll_busy, reports, bytes;
    int gone;
    uint32_t *img; /* 6-bit channels */
} dump;

static struct {
    int ran, skipped, ok;
    char skip_reason[300];
    char *console;
    dump dumps[8];
    int ndumps;
} vm;

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    if (buf != NULL && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf != NULL) {
        buf[n] = '\0';
        if (len != NULL)
            *len = (size_t)n;
    }
    return buf;
}

static void parse_dumps(const char *buf, size_t len)
{
    size_t off = 0;
    while (off < len && vm.ndumps < 8) {
        const char *p = memmem(buf + off, len - off, "ZSMODEL ", 8), *nl;
        dump *d = &vm.dumps[vm.ndumps];
        size_t px, i;
        if (p == NULL)
            break;
        nl = memchr(p, '\n', len - (size_t)(p - buf));
        if (nl == NULL)
            break;
        memset(d, 0, sizeof *d);
        if (sscanf(p,
                   "ZSMODEL %31s %u %u model_errors=%u panel_errors=0x%X busy=%llu "
                   "poll_busy=%llu reports=%llu bytes=%llu transactions=%*u gone=%d",
                   d->tag, &d->w, &d->h, &d->model_errors, &d->panel_errors, &d->busy,
                   &d->poll_busy, &d->reports, &d->bytes, &d->gone) != 10)
            break;
        px = (size_t)d->w * d->h;
        if ((size_t)(nl + 1 - buf) + px * 3 > len)
            break;
        d->img = malloc(px * sizeof *d->img);
        if (d->img == NULL)
            break;
        for (i = 0; i < px; i++) {
            const uint8_t *c = (const uint8_t *)nl + 1 + 3 * i;
            d->img[i] = (uint32_t)c[0] << 12 | (uint32_t)c[1] << 6 | c[2];
        }
        off = (size_t)(nl + 1 - buf) + px * 3;
        vm.ndumps++;
    }
}

static const dump *find_dump(const char *tag)
{
    int i;
    for (i = 0; i < vm.ndumps; i++)
        if (strcmp(vm.dumps[i].tag, tag) == 0)
            return &vm.dumps[i];
    return NULL;
}

/* The console text of one phase: from the model's start line to the
 * client's exit line. */
static char *phase_text(const char *tag)
{
    char start[64], end[64];
    const char *a, *b;
    char *s;
    snprintf(start, sizeof start, "model[%s]: device started", tag);
    snprintf(end, sizeof end, "ZSVM phase %s client rc=", tag);
    a = strstr(vm.console, start);
    b = a != NULL ? strstr(a, end) : NULL;
    if (b == NULL)
        return NULL;
    b = strchr(b, '\n') != NULL ? strchr(b, '\n') : b + strlen(b);
    s = strndup(a, (size_t)(b - a));
    return s;
}

static int phase_rc(const char *tag)
{
    char key[64];
    const char *p;
    int rc = -1;
    snprintf(key, sizeof key, "ZSVM phase %s client rc=", tag);
    p = strstr(vm.console, key);
    if (p != NULL)
        sscanf(p + strlen(key), "%d", &rc);
    return rc;
}

static void save_png(const dump *d)
{
    char path[256];
    uint8_t *rgb = malloc((size_t)d->w * d->h * 3);
    size_t i;
    if (rgb == NULL)
        return;
    for (i = 0; i < (size_t)d->w * d->h; i++) {
        uint32_t v = d->img[i];
        rgb[3 * i] = (uint8_t)((v >> 12 & 63) << 2 | (v >> 16 & 3));
        rgb[3 * i + 1] = (uint8_t)((v >> 6 & 63) << 2 | (v >> 10 & 3));
        rgb[3 * i + 2] = (uint8_t)((v & 63) << 2 | (v >> 4 & 3));
    }
    snprintf(path, sizeof path, WORK "/panel_%s.png", d->tag);
    emu_png_write_rgb(path, rgb, d->w, d->h);
    free(rgb);
}

static int run_vm(void **state)
{
    int st, rc, i;
    size_t len = 0;
    char *bin;
    (void)state;
    if (vm.ran)
        return 0;
    vm.ran = 1;
    mkdir("build/tests/ports/vm", 0755);
    mkdir(WORK, 0755);
    st = system("bash tests/ports/vm/run_vm.sh " WORK " " MODEL " " CLIENT " > " WORK
                "/run_vm.log 2>&1");
    rc = WIFEXITED(st) ? WEXITSTATUS(st) : 1;
    {
        char *log = slurp(WORK "/run_vm.log", NULL);
        if (log != NULL) {
            printf("%s", log);
            if (rc == 77) {
                const char *s = strstr(log, "SKIPPED: ");
                snprintf(vm.skip_reason, sizeof vm.skip_reason, "%s",
                         s != NULL ? s + 9 : "a tool is missing");
            }
            free(log);
        }
    }
    if (rc == 77) {
        vm.skipped = 1;
        return 0;
    }
    vm.console = slurp(WORK "/console.log", NULL);
    if (vm.console == NULL)
        vm.console = strdup("");
    bin = slurp(WORK "/ttyS1.bin", &len);
    if (bin != NULL) {
        parse_dumps(bin, len);
        free(bin);
    }
    for (i = 0; i < vm.ndumps; i++)
        save_png(&vm.dumps[i]);
    vm.ok = rc == 0;
    if (!vm.ok)
        printf("    the VM run failed (exit %d); console:\n%s\n", rc, vm.console);
    return 0;
}

static void need_vm(void)
{
    if (vm.skipped) {
        printf("SKIPPED: MCP2210 VM test: %s", vm.skip_reason);
        skip();
    }
    assert_true(vm.ok);
}

static void expect_frame(const char *tag, uint32_t frame)
{
    const dump *d = find_dump(tag);
    uint32_t *want;
    assert_non_null(d);
    printf("    %s: %ux%u picture, model errors %u, panel errors 0x%X, %llu bytes, %llu "
           "reports\n",
           tag, d->w, d->h, d->model_errors, d->panel_errors, d->bytes, d->reports);
    assert_int_equal(d->model_errors, 0);
    assert_int_equal(d->panel_errors, 0);
    want = ports_demo_666(d->w, d->h, frame);
    assert_non_null(want);
    assert_int_equal(ports_image_diff(d->img, want, d->w, d->h, tag), 0);
    free(want);
}

/* Frame 0 in full, then frame 1 as a partial update: the picture that
 * arrives through hidapi -> hidraw -> uhid -> model equals frame 1. */
static void test_vm_frame(void **state)
{
    char *t;
    (void)state;
    need_vm();
    assert_int_equal(phase_rc("full"), 0);
    expect_frame("full", 1);
    t = phase_text("full");
    assert_non_null(t);
    printf("%s\n", t);
    assert_non_null(strstr(t, "frame 1: "));
    free(t);
}

/* Busy (0xF8) answers: every one resent, the picture is exact, and the
 * client counted exactly as many as the model sent. */
static void test_vm_busy(void **state)
{
    const dump *d;
    char *t, *p;
    unsigned long long client_busy = 0;
    (void)state;
    need_vm();
    assert_int_equal(phase_rc("busy"), 0);
    expect_frame("busy", 7);
    d = find_dump("busy");
    t = phase_text("busy");
    assert_non_null(t);
    p = strstr(t, "MCP2210: ");
    assert_non_null(p);
    p = strstr(p, "), ");
    assert_non_null(p);
    assert_int_equal(sscanf(p, "), %llu busy answers resent", &client_busy), 1);
    printf("    busy answers: model sent %llu + %llu, client resent %llu\n", d->busy,
           d->poll_busy, client_busy);
    assert_true(d->busy > 0);
    assert_true(d->poll_busy > 0);
    assert_int_equal(client_busy, d->busy + d->poll_busy);
    free(t);
}

/* The device vanishes mid-frame: the client stops with exit status 3 and
 * says the MCP2210 disconnected. */
static void test_vm_disconnect(void **state)
{
    const dump *d;
    char *t;
    (void)state;
    need_vm();
    d = find_dump("unplug");
    assert_non_null(d);
    assert_int_equal(d->gone, 1);
    assert_int_equal(d->model_errors, 0);
    assert_int_equal(phase_rc("unplug"), 3);
    t = phase_text("unplug");
    assert_non_null(t);
    assert_non_null(strstr(t, "MCP2210 disconnected"));
    if (strstr(t, "zspan-mcp2210: frame") != NULL)
        printf("    %s\n", strstr(t, "zspan-mcp2210: frame"));
    free(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vm_frame),
        cmocka_unit_test(test_vm_busy),
        cmocka_unit_test(test_vm_disconnect),
    };
    return cmocka_run_group_tests_name("mcp2210 through hidapi/hidraw/uhid in a VM", tests, run_vm,
                                       NULL);
}
