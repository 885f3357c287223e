/* SPDX-License-Identifier: MIT */
/*
 * Stellaris OLED firmware (issue 20): a spinning scene rendered in bands
 * straight to the board's display, no framebuffer.
 *
 *   build/fw/oled-lm3s6965.elf  LM3S6965 + SSD0323 over SSI0: the "big"
 *                               scene of oled_scene.h, GRAY4, bands of 8 rows
 *   build/fw/oled-lm3s811.elf   LM3S811 (8 KB SRAM) + SSD0303 over I2C: the
 *                               "small" scene, 1-bit pages, one page a band
 *
 * Command line (qemu -semihosting-config arg=...): "frames=N" renders N
 * frames (default 3), "halt" waits for ever after the last one (the harness
 * then takes the screen), "addr=N" talks to I2C address N (decimal; the
 * harness's NACK test points it at one with no device). Output through
 * semihosting, one line each:
 *
 *   F BOARD FRAME instr=N stream=XXXXXXXX bytes=N dropped=N
 *   M BOARD static_ram=N arena=N stack_used=N stack_size=N
 *   E BOARD what: panel status / port error      (then exit 2)
 *   DONE BOARD
 *
 * stream is FNV-1a 32 of everything the port put on the wire since the
 * panel was set up (lm3s_port.h): the host's emulated bus computes the same.
 * instr: guest instructions of the frame (SysTick ticks x the calibrated
 * instructions per tick; exact under qemu -icount shift=0).
 */
#include <string.h>

#include "lm3s_port.h"
#include "oled_scene.h"
#include "port.h"
#include "zspan/panel.h"

#ifdef OLED_LM3S811
#include "zspan/zspan.h"
#define FB_W OLED_SMALL_W
#define BAND_BYTES (FB_W * 1u)  /* one page of 8 rows */
#define BAND_ROWS 8
#define PANEL_DESC zs_panel_ssd0303_96x16
#define PANEL_FORMAT ZS_FMT_MONO_PAGE
#define ARENA_BYTES ZS_ARENA_BYTES_CFG(OLED_SMALL_W, OLED_SMALL_H, OLED_SMALL_TRIS, \
                                       OLED_SMALL_VERTS, OLED_SMALL_EDGES, OLED_SMALL_FLAGS)
#define XTAL_CODE 0xBu /* 6 MHz crystal */
#else
#include "demo_scene.h"
#define FB_W OLED_BIG_W
#define BAND_ROWS 8
#define BAND_BYTES (FB_W / 2u * BAND_ROWS)
#define PANEL_DESC zs_panel_ssd0323_128x64
#define PANEL_FORMAT ZS_FMT_GRAY4
#define ARENA_BYTES ZS_ARENA_BYTES_CFG(OLED_BIG_W, OLED_BIG_H, OLED_BIG_TRIS, OLED_BIG_VERTS, \
                                       OLED_BIG_EDGES, OLED_BIG_FLAGS)
#define XTAL_CODE 0xEu /* 8 MHz crystal */
static demo_scene scene;
#endif

static uint8_t arena[ARENA_BYTES];
static uint8_t band[BAND_BYTES];
static zs_renderer r;
static zs_panel panel;
static lm3s_port port;

static const char *word_value(const char *s, const char *key)
{
    size_t n = strlen(key);
    while (*s) {
        while (*s == ' ')
            s++;
        if (!strncmp(s, key, n))
            return s + n;
        while (*s && *s != ' ')
            s++;
    }
    return NULL;
}

static unsigned parse_uint(const char *s, unsigned dflt)
{
    unsigned v = 0;
    if (!s || *s < '0' || *s > '9')
        return dflt;
    while (*s >= '0' && *s <= '9')
        v = v * 10u + (unsigned)(*s++ - '0');
    return v;
}

int main(void)
{
    static char cmd[128];
    const char *board = port_this_board.name;
    unsigned frames = 3, halt = 0, f;
    uint32_t ipt, sys_hz;
    unsigned addr = ZS_SSD0303_I2C_ADDR;
    zs_panel_status ps;
    zs_status st;
    zs_config cfg;

    if (sh_get_cmdline(cmd, sizeof cmd) == 0) {
        frames = parse_uint(word_value(cmd, "frames="), frames);
        halt = word_value(cmd, "halt") != NULL;
        addr = parse_uint(word_value(cmd, "addr="), addr);
    }
    sys_hz = lm3s_clock_init(XTAL_CODE);
    port_timer_start();
    ipt = port_calibrate_ipt_milli();
#ifdef OLED_LM3S811
    lm3s_i2c_oled_init(&port, sys_hz, (uint8_t)addr);
    cfg = oled_small_config();
#else
    (void)addr;
    lm3s_ssi_oled_init(&port, sys_hz, PANEL_DESC.max_spi_hz);
    demo_scene_init(&scene);
    cfg = oled_big_config();
#endif
    ps = zs_panel_init(&panel, &PANEL_DESC, &port.bus, PANEL_FORMAT, 0);
    if (ps != ZS_PANEL_OK) {
        sh_printf("E %s panel init: %s / %s\n", board, zs_panel_strerror(ps),
                  lm3s_strerror(port.error));
        return 2;
    }
    st = zs_init(&r, arena, sizeof arena, &cfg);
    if (st != ZS_OK) {
        sh_printf("E %s zs_init: %s\n", board, zs_strerror(st));
        return 2;
    }
    for (f = 0; f < frames; f++) {
        uint64_t t0 = port_ticks(), t1;
        zs_panel_frame_stats fs;
#ifdef OLED_LM3S811
        st = oled_small_frame(&r, f);
#else
        st = oled_big_frame(&r, &scene, f);
#endif
        ps = st == ZS_OK ? zs_panel_stream(&panel, &r, band, NULL, sizeof band, BAND_ROWS, NULL,
                                           &fs)
                         : ZS_PANEL_ERR_RENDER;
        t1 = port_ticks();
        if (ps != ZS_PANEL_OK) {
            sh_printf("E %s frame %u: %s / %s / %s\n", board, f, zs_panel_strerror(ps),
                      zs_strerror(st), lm3s_strerror(port.error));
            return 2;
        }
        sh_printf("F %s %u instr=%lu stream=%08lx bytes=%lu dropped=%lu\n", board, f,
                  (unsigned long)((t1 - t0) * ipt / 1000u), (unsigned long)port.stream,
                  (unsigned long)fs.bytes,
                  (unsigned long)(r.stats.tris_dropped + r.stats.verts_dropped +
                                  r.stats.records_skipped));
    }
    sh_printf("M %s static_ram=%u arena=%u stack_used=%u stack_size=%u cpu_hz=%lu ipt_milli=%lu\n",
              board, (unsigned)port_static_ram(), (unsigned)sizeof arena,
              (unsigned)port_stack_high_water(), (unsigned)port_stack_size(),
              (unsigned long)sys_hz, (unsigned long)ipt);
    sh_printf("DONE %s\n", board);
    if (halt)
        for (;;)
            __asm__ volatile("wfi");
    return 0;
}
