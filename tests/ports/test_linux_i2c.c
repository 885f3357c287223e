/* SPDX-License-Identifier: MIT */
/*
 * The Linux I2C port (ports/linux/i2c_bus.c) through the real i2c-dev
 * interface: open(), ioctl(I2C_SLAVE) and ioctl(I2C_RDWR) on /dev/i2c-1 as
 * a Raspberry Pi program makes them, with umockdev's preload library routing
 * the node to an ioctl handler here that acts like the kernel's i2c-dev: it
 * resolves the messages and their buffers and puts each write transaction on
 * the emulated SSD1306's I2C interface (host_sim/emu/emu_mono.c), which
 * decodes the control bytes; a transaction to an address nobody answers
 * fails with ENXIO, as a NACK does.
 *
 *  - a frame of the demo scene: the emulated glass equals the core's 1-bit
 *    image; wire time per frame printed for 400 kHz and 1 MHz;
 *  - a missing bus, a device that does not answer (at open and in the
 *    middle of a run) and a permission problem each give their message.
 *
 * The program re-runs itself under umockdev-wrapper; without umockdev every
 * test is skipped with the reason.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <linux/i2c-dev.h>
#include <linux/i2c.h>
#include <umockdev.h>

#include <cmocka.h>

#include "demo_scene.h"
#include "emu_mono.h"
#include "zs_linux_i2c.h"
#include "zspan/panel.h"

typedef struct hw {
    emu_mono emu;
    int answer;                 /* the device acknowledges its address */
    uint64_t transactions, bytes, nacks;
} hw;

static hw H_;
static UMockdevTestbed *tb;
static int have_umockdev;
static char skip_reason[200];

static gboolean on_i2c(UMockdevIoctlBase *base, UMockdevIoctlClient *c, gpointer user)
{
    hw *h = user;
    gulong req = umockdev_ioctl_client_get_request(c);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(c);
    (void)base;
    if (req == I2C_SLAVE || req == I2C_SLAVE_FORCE) {
        unsigned long a = 0;
        memcpy(&a, arg->data, (size_t)arg->data_len < sizeof a ? (size_t)arg->data_len : sizeof a);
        umockdev_ioctl_client_complete(c, a > 0x7F ? -1 : 0, a > 0x7F ? EINVAL : 0);
        return TRUE;
    }
    if (req == I2C_RDWR) {
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct i2c_rdwr_ioctl_data), NULL);
        struct i2c_rdwr_ioctl_data *x = (struct i2c_rdwr_ioctl_data *)d->data;
        uint32_t n = x->nmsgs, i;
        if (n == 0 || n > I2C_RDWR_IOCTL_MAX_MSGS) {
            umockdev_ioctl_client_complete(c, -1, EINVAL);
            return TRUE;
        }
        g_autoptr(UMockdevIoctlData) m = umockdev_ioctl_data_resolve(
            d, offsetof(struct i2c_rdwr_ioctl_data, msgs), n * sizeof(struct i2c_msg), NULL);
        struct i2c_msg *msg = (struct i2c_msg *)m->data;
        for (i = 0; i < n; i++) {
            g_autoptr(UMockdevIoctlData) b = NULL;
            if (msg[i].flags & I2C_M_RD) {
                umockdev_ioctl_client_complete(c, -1, EOPNOTSUPP); /* write-only controller */
                return TRUE;
            }
            b = umockdev_ioctl_data_resolve(m, i * sizeof(struct i2c_msg) + offsetof(struct i2c_msg, buf),
                                            msg[i].len, NULL);
            if (!h->answer || emu_mono_i2c_write(&h->emu, (uint8_t)msg[i].addr, b->data,
                                                 msg[i].len) != 0) {
                h->nacks++;
                umockdev_ioctl_client_complete(c, -1, ENXIO); /* no ACK */
                return TRUE;
            }
            h->transactions++;
            h->bytes += msg[i].len;
        }
        umockdev_ioctl_client_complete(c, (glong)n, 0);
        return TRUE;
    }
    umockdev_ioctl_client_complete(c, -1, ENOTTY);
    return TRUE;
}

static int setup_testbed(void)
{
    GError *err = NULL;
    UMockdevIoctlBase *bus;
    tb = umockdev_testbed_new();
    if (!umockdev_testbed_add_from_string(tb,
                                          "P: /devices/platform/soc/fe804000.i2c/i2c-1/i2c-dev/i2c-1\n"
                                          "N: i2c-1\n"
                                          "E: DEVNAME=/dev/i2c-1\n"
                                          "E: SUBSYSTEM=i2c-dev\n"
                                          "E: MAJOR=89\n"
                                          "E: MINOR=1\n"
                                          "A: dev=89:1\n",
                                          &err)) {
        snprintf(skip_reason, sizeof skip_reason, "umockdev add_from_string: %s",
                 err ? err->message : "failed");
        return -1;
    }
    bus = umockdev_ioctl_base_new();
    g_signal_connect(bus, "handle-ioctl", G_CALLBACK(on_i2c), &H_);
    if (!umockdev_testbed_attach_ioctl(tb, "/dev/i2c-1", bus, &err)) {
        snprintf(skip_reason, sizeof skip_reason, "umockdev attach_ioctl: %s",
                 err ? err->message : "failed");
        return -1;
    }
    return 0;
}

static void need_umockdev(void)
{
    if (!have_umockdev) {
        printf("SKIPPED: %s\n", skip_reason);
        skip();
    }
}

static void hw_reset(hw *h)
{
    if (h->emu.m != NULL)
        emu_mono_free(&h->emu);
    memset(h, 0, sizeof *h);
    assert_int_equal(emu_mono_init(&h->emu, emu_mono_model_find("ssd1306-128x64")), 0);
    h->answer = 1;
}

static void test_frame(void **state)
{
    (void)state;
    need_umockdev();
    hw_reset(&H_);
    zs_i2c_port port;
    char err[256];
    assert_int_equal(zs_i2c_open(&port, "/dev/i2c-1", 0x3C, err, sizeof err), 0);
    zs_panel lcd;
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_ssd1306_128x64, &port.bus, ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_OK);
    static demo_scene scene;
    demo_scene_init(&scene);
    zs_config cfg = zs_config_default(128, 64, DEMO_TRIANGLES * 2, DEMO_VERTICES * 2, 1024);
    cfg.flags = ZS_CFG_MONO;
    size_t n = zs_arena_bytes(&cfg);
    uint8_t *arena = malloc(n), ref[1024], buf[256];
    zs_renderer r;
    assert_int_equal(zs_init(&r, arena, n, &cfg), ZS_OK);
    assert_int_equal(demo_frame(&r, &scene, 0, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_MONO_PAGE),
                     ZS_OK);
    assert_int_equal(zs_render_rows(&r, 0, 64, ref, 128), ZS_OK);
    assert_int_equal(demo_frame(&r, &scene, 0, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_MONO_PAGE),
                     ZS_OK);
    uint64_t b0 = port.bytes;
    uint32_t m0 = port.messages;
    assert_int_equal(zs_panel_stream(&lcd, &r, buf, NULL, sizeof buf, 16, NULL, NULL), ZS_PANEL_OK);
    uint64_t bytes = port.bytes - b0;
    uint32_t msgs = port.messages - m0;
    uint8_t got[128 * 64];
    unsigned bad = 0, lit = 0;
    emu_mono_view(&H_.emu, 0, got);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 128; x++) {
            int want = (ref[(y / 8) * 128 + x] >> (y % 8)) & 1;
            bad += want != got[y * 128 + x];
            lit += (unsigned)want;
        }
    if (H_.emu.errors)
        print_message("    emulator: %s\n", H_.emu.first_error);
    assert_int_equal(H_.emu.errors, 0);
    assert_int_equal(bad, 0);
    assert_true(lit > 200 && lit < 128 * 64 - 200);
    /* the window (6 command messages of 2 bytes) and 8 pages of 1 + 128 bytes */
    assert_int_equal(msgs, 6 + 8);
    assert_int_equal(bytes, 6 * 2 + 8 * 129);
    print_message("    i2c-dev: %u messages, %llu bytes a frame: %.2f ms at 400 kHz, %.2f ms at "
                  "1 MHz (9 clocks a byte with the address, 2 for start/stop)\n",
                  msgs, (unsigned long long)bytes, zs_i2c_wire_us(bytes, msgs, 400e3) / 1e3,
                  zs_i2c_wire_us(bytes, msgs, 1e6) / 1e3);
    zs_i2c_close(&port);
    free(arena);
}

static void test_missing_bus(void **state)
{
    (void)state;
    need_umockdev();
    zs_i2c_port port;
    char err[256];
    assert_int_equal(zs_i2c_open(&port, "/dev/i2c-7", 0x3C, err, sizeof err), -1);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "no I2C bus /dev/i2c-7"));
    assert_non_null(strstr(err, "modprobe i2c-dev"));
}

static void test_nack(void **state)
{
    (void)state;
    need_umockdev();
    hw_reset(&H_);
    zs_i2c_port port;
    char err[256];
    /* nobody at 0x3D */
    assert_int_equal(zs_i2c_open(&port, "/dev/i2c-1", 0x3D, err, sizeof err), -1);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "no device answers at 0x3D on /dev/i2c-1 (NACK)"));
    assert_true(H_.nacks > 0);
    /* the device goes away in the middle of a run */
    assert_int_equal(zs_i2c_open(&port, "/dev/i2c-1", 0x3C, err, sizeof err), 0);
    H_.answer = 0;
    zs_panel lcd;
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_ssd1306_128x64, &port.bus, ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_ERR_IO);
    assert_non_null(strstr(zs_i2c_error(&port), "NACK"));
    print_message("    %s\n", zs_i2c_error(&port));
    zs_i2c_close(&port);
}

static void test_permission(void **state)
{
    (void)state;
    need_umockdev();
    int fd[2];
    char msg[256] = {0}, node[512];
    /* not root: take the permission away from the node itself */
    snprintf(node, sizeof node, "%s/dev/i2c-1", umockdev_testbed_get_root_dir(tb));
    if (geteuid() != 0)
        assert_int_equal(chmod(node, 0), 0);
    /* The unprivileged run is the program itself, started by fork + exec:
     * this process has umockdev's threads, and a forked copy that went on
     * running library code could wait for ever on a lock one of them held. */
    char prog[512];
    snprintf(prog, sizeof prog, "%s/build/zspan-i2c", ZT_TOP_DIR);
    assert_int_equal(pipe(fd), 0);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        close(fd[0]);
        if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0))
            _exit(5);
        if (dup2(fd[1], 2) < 0)
            _exit(6);
        execl(prog, "zspan-i2c", "--bus", "/dev/i2c-1", "--frames", "1", (char *)NULL);
        _exit(7);
    }
    close(fd[1]);
    ssize_t n = 0, got;
    while (n < (ssize_t)sizeof msg - 1 && (got = read(fd[0], msg + n, sizeof msg - 1 - (size_t)n)) > 0)
        n += got;
    int status;
    waitpid(pid, &status, 0);
    close(fd[0]);
    if (geteuid() != 0)
        chmod(node, 0644);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 3); /* the open failed */
    assert_true(n > 0);
    print_message("    as an unprivileged user: %s", msg);
    assert_non_null(strstr(msg, "permission denied on /dev/i2c-1"));
    assert_non_null(strstr(msg, "i2c group"));
}

/* The program itself (build/zspan-i2c) on the emulated bus: the same
 * i2c-dev node, from another process. */
static void test_program(void **state)
{
    (void)state;
    need_umockdev();
    hw_reset(&H_);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s/build/zspan-i2c --bus /dev/i2c-1 --frames 3 --lines", ZT_TOP_DIR);
    FILE *f = popen(cmd, "r");
    char line[512] = {0};
    assert_non_null(f);
    while (fgets(line, sizeof line, f) != NULL)
        print_message("    %s", line);
    int rc = pclose(f);
    assert_true(WIFEXITED(rc) && WEXITSTATUS(rc) == 0);
    assert_non_null(strstr(line, "3 frames"));
    assert_int_equal(H_.emu.errors, 0);
    assert_true(H_.emu.display_on);
    assert_true(H_.emu.data_bytes >= 3 * 1024);
    /* no device: exit status 3 and the reason */
    snprintf(cmd, sizeof cmd, "%s/build/zspan-i2c --bus /dev/i2c-1 --addr 0x3D 2>&1", ZT_TOP_DIR);
    f = popen(cmd, "r");
    assert_non_null(f);
    line[0] = 0;
    if (fgets(line, sizeof line, f) == NULL) line[0] = 0;
    rc = pclose(f);
    assert_true(WIFEXITED(rc) && WEXITSTATUS(rc) == 3);
    assert_non_null(strstr(line, "NACK"));
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_frame),
        cmocka_unit_test(test_missing_bus),
        cmocka_unit_test(test_nack),
        cmocka_unit_test(test_permission),
        cmocka_unit_test(test_program),
    };
    (void)argc;
    if (getenv("ZS_UMOCKDEV_CHILD") == NULL) {
        setenv("ZS_UMOCKDEV_CHILD", "1", 1);
        execvp("umockdev-wrapper", (char *[]){"umockdev-wrapper", argv[0], NULL});
        snprintf(skip_reason, sizeof skip_reason,
                 "umockdev-wrapper not found (Debian: umockdev): the i2c-dev emulation needs it");
    } else if (getenv("LD_PRELOAD") == NULL || strstr(getenv("LD_PRELOAD"), "umockdev") == NULL) {
        snprintf(skip_reason, sizeof skip_reason, "umockdev's preload library is not active");
    } else if (setup_testbed() == 0) {
        have_umockdev = 1;
    }
    return cmocka_run_group_tests_name("linux port: i2c-dev under umockdev", tests, NULL, NULL);
}
