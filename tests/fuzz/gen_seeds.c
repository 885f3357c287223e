/* SPDX-License-Identifier: MIT */
/*
 * gen_seeds: writes the starting seeds of a harness into a directory
 * (make fuzz-seeds: tests/fuzz/corpus/{frame,panel}/seed-*).
 *
 * frame: each seed is encoded in
 * the byte layout that fuzz_frame.c's decode_scene reads, so that the fuzzer
 * starts from visible scenes (penetrating triangles, shared edges, clipped
 * triangles, every format, lights, fog, small pools, bands) and from each
 * error path, instead of discovering the layout byte by byte.
 *
 * panel: wire programs in fuzz_panel.c's encoding: the usual init sequence of
 * each controller family, windows, memory writes in 16 and 18 bpp, and a few
 * protocol errors (stray data, short parameters, commands mid-pixel).
 *
 *   gen_seeds frame|panel DIR
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct out {
    uint8_t b[8192];
    size_t n;
} out;

static void u8(out *o, unsigned v) { o->b[o->n++] = (uint8_t)v; }
static void u16(out *o, unsigned v) { u8(o, v & 255u); u8(o, (v >> 8) & 255u); }
static void u32(out *o, uint32_t v) { u16(o, v & 0xFFFFu); u16(o, v >> 16); }
static void i8(out *o, int v) { u8(o, (unsigned)(v & 255)); }

static uint64_t g_state = 0x5EED5EED12345678ull;
static uint32_t rnd(void)
{
    uint64_t z = (g_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (uint32_t)((z ^ (z >> 31)) >> 32);
}
static int rr(int lo, int hi) { return lo + (int)(rnd() % (uint32_t)(hi - lo + 1)); }

typedef struct cfg {
    int w, h, tris, verts, edges;
    int flags; /* ZS_CFG_*: 1 no z-buffer line, 2 flat only */
} cfg;

static void header(out *o, cfg c)
{
    u8(o, 0); /* arena offset 0 */
    u8(o, (unsigned)(c.w - 1));
    u8(o, (unsigned)(c.h - 1));
    u8(o, (unsigned)(c.tris - 1));
    u8(o, (unsigned)(c.verts - 1));
    u8(o, (unsigned)(c.edges - 2));
    u8(o, (unsigned)c.flags);
}

/* Camera kind 0: eye at the origin looking down -Z, up +Y; fov in degrees
 * (1..179), near and far in 1/64 units. */
static void camera_std(out *o, int fov, int near64, int far64)
{
    u8(o, 0);
    for (int i = 0; i < 6; i++)
        u8(o, 0);
    u8(o, 0); /* up = +Y */
    u8(o, (unsigned)(fov - 1));
    u8(o, (unsigned)(near64 - 1));
    u16(o, (unsigned)(far64 - near64 - 1));
}

static void mode_ok(out *o) { u8(o, 0); }

/* Shading: flags bit0 call, bit2 lit, bit3 fog. */
static void shading(out *o, int call, int fmt, int gouraud, uint32_t bg, int lit, int fog)
{
    unsigned k = (call ? 1u : 0u) | (lit ? 4u : 0u) | (fog ? 8u : 0u);
    u8(o, k);
    if (!call)
        return;
    u8(o, (unsigned)fmt);
    u8(o, (unsigned)gouraud);
    u32(o, bg);
    if (lit) {
        u8(o, 40);  /* ambient 40/128 */
        u8(o, 2);   /* two lights */
        for (int i = 0; i < 2; i++) {
            u8(o, 0);
            i8(o, i ? -20 : 30);
            i8(o, 50);
            i8(o, 60);
            u8(o, 100);
        }
    }
    if (fog) {
        u8(o, 0);
        u32(o, 0x808080);
        u8(o, 64);  /* start 4 units */
        u8(o, 96);  /* end start + 97/16 */
    }
}

/* A mesh with int8 positions (kind 0), one-byte indices, scale (1+sk)/256 and
 * a model matrix translating by (tx, ty, tz) / 8 units and rotating. */
typedef struct mesh {
    int nv, nt;
    int pos[3 * 48];
    int idx[3 * 48];
    int fcol, vcol, fnorm, vnorm;
    int sk;
    int ik, zero_scale;
    int tx, ty, tz, ax, ay, az;
    uint32_t color;
} mesh;

static void put_mesh(out *o, const mesh *m)
{
    unsigned flags = (m->fcol ? 1u : 0u) | (m->vcol ? 2u : 0u) | (m->fnorm ? 4u : 0u) |
                     (m->vnorm ? 8u : 0u);
    u8(o, flags);
    u8(o, (unsigned)m->nv);
    u8(o, (unsigned)m->nt);
    for (int i = 0; i < 3 * m->nv; i++)
        i8(o, m->pos[i]);
    u8(o, (unsigned)m->ik); /* 0: indices mod vertex count; 224: mod count + 2 */
    for (int i = 0; i < 3 * m->nt; i++)
        u8(o, (unsigned)m->idx[i]);
    if (m->zero_scale) {
        u8(o, 216); /* raw scale: special value 0 */
        u8(o, 1);
        u8(o, 0);
    } else {
        u8(o, (unsigned)m->sk);
    }
    u32(o, m->color);
    if (m->fcol)
        for (int i = 0; i < m->nt; i++)
            u32(o, rnd() & 0xFFFFFFu);
    if (m->vcol)
        for (int i = 0; i < m->nv; i++)
            u32(o, rnd() & 0xFFFFFFu);
    if (m->fnorm)
        for (int i = 0; i < 3 * m->nt; i++)
            u16(o, (unsigned)(rr(-16384, 16384) & 0xFFFF));
    if (m->vnorm)
        for (int i = 0; i < 3 * m->nv; i++)
            u16(o, (unsigned)(rr(-16384, 16384) & 0xFFFF));
    u8(o, 1); /* model: translate, rotate, scale */
    i8(o, m->tx);
    i8(o, m->ty);
    i8(o, m->tz);
    u8(o, (unsigned)m->ax);
    u8(o, (unsigned)m->ay);
    u8(o, (unsigned)m->az);
    u8(o, 0); /* scale 1 */
}

static void plan(out *o, int band, int start_row, int frame_api, int pad)
{
    u8(o, (unsigned)(band - 1));
    u8(o, start_row ? (unsigned)(3 | (start_row << 2)) : 0u);
    u8(o, frame_api ? 1u : 0u);
    u8(o, (unsigned)pad);
    u8(o, 0);
}

static void write_seed(const char *dir, int n, const out *o)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/seed-%03d", dir, n);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(o->b, 1, o->n, f) != o->n) {
        perror(path);
        exit(1);
    }
    fclose(f);
}

/* Random triangles in front of the camera (model translated to z = -6). */
static void random_mesh(mesh *m, int nt, int shared)
{
    memset(m, 0, sizeof *m);
    m->nv = shared ? (nt + 2 < 48 ? nt + 2 : 48) : (3 * nt < 48 ? 3 * nt : 48);
    m->nt = nt;
    for (int i = 0; i < 3 * m->nv; i++)
        m->pos[i] = rr(-60, 60);
    for (int t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            m->idx[3 * t + k] = shared ? (t + k) % m->nv : (3 * t + k) % m->nv;
    m->sk = 15; /* 1/16 unit per position unit: +-3.75 units */
    m->tz = -48; /* -6 units */
    m->color = rnd() & 0xFFFFFFu;
}

/* ---- panel programs (ops of fuzz_panel.c: op % 9) ---- */
static void p_cmd(out *o, unsigned c) { u8(o, 0); u8(o, c); }
static void p_data(out *o, const uint8_t *b, unsigned n)
{
    u8(o, 2);
    u8(o, n);
    for (unsigned i = 0; i < n; i++)
        u8(o, b[i]);
}
static void p_cmd1(out *o, unsigned c, unsigned v) { uint8_t b = (uint8_t)v; p_cmd(o, c); p_data(o, &b, 1); }
static void p_long(out *o, unsigned n, unsigned k, unsigned a, unsigned b, unsigned c)
{
    u8(o, 4);
    u16(o, n);
    u8(o, k - 1);
    u8(o, a);
    u8(o, b);
    u8(o, c);
}
static void p_delay(out *o, unsigned ms) { u8(o, 5); u8(o, ms < 200 ? ms : 199 + ms / 1000); }
static void p_reset(out *o, int level) { u8(o, 6); u8(o, (unsigned)level); }
static void p_view(out *o, unsigned rot) { u8(o, 8); u8(o, rot); }

static void p_window(out *o, unsigned x0, unsigned y0, unsigned x1, unsigned y1)
{
    uint8_t b[4];
    b[0] = (uint8_t)(x0 >> 8); b[1] = (uint8_t)x0; b[2] = (uint8_t)(x1 >> 8); b[3] = (uint8_t)x1;
    p_cmd(o, 0x2A);
    p_data(o, b, 4);
    b[0] = (uint8_t)(y0 >> 8); b[1] = (uint8_t)y0; b[2] = (uint8_t)(y1 >> 8); b[3] = (uint8_t)y1;
    p_cmd(o, 0x2B);
    p_data(o, b, 4);
}

static int panel_seeds(const char *dir)
{
    int n = 0;
    out o;
    /* DCS models 0..6: reset, SWRESET, SLPOUT, COLMOD, MADCTL, window, write, DISPON */
    for (unsigned model = 0; model < 7; model++) {
        for (unsigned v = 0; v < 3; v++) {
            memset(&o, 0, sizeof o);
            u8(&o, model);
            p_reset(&o, 0);
            p_delay(&o, 10);
            p_reset(&o, 1);
            p_delay(&o, 120);
            p_cmd(&o, 0x01);
            p_delay(&o, 150);
            p_cmd(&o, 0x11);
            p_delay(&o, 120);
            p_cmd1(&o, 0x3A, v == 1 ? 0x66 : 0x55);
            p_cmd1(&o, 0x36, v == 2 ? 0xA8 : 0x00);
            p_cmd(&o, 0x21);
            p_cmd(&o, 0x29);
            p_window(&o, 3 * v, 5, 40 + 7 * v, 30);
            p_cmd(&o, 0x2C);
            p_long(&o, v == 1 ? 3 * 38 * 26 : 2 * 38 * 26, v == 1 ? 3 : 2, 0xF8, 0x1F, 0xFC);
            p_cmd(&o, 0x3C); /* continue */
            p_long(&o, 100, 1, 0x55, 0, 0);
            u8(&o, 7);
            p_view(&o, v);
            write_seed(dir, n++, &o);
        }
    }
    /* SSD1351 (model 7): unlock, remap, window, write */
    for (unsigned v = 0; v < 3; v++) {
        memset(&o, 0, sizeof o);
        u8(&o, 7);
        p_reset(&o, 0);
        p_reset(&o, 1);
        p_delay(&o, 5);
        p_cmd1(&o, 0xFD, 0x12);
        p_cmd1(&o, 0xFD, 0xB1);
        p_cmd(&o, 0xAE);
        p_cmd1(&o, 0xA0, v == 1 ? 0xB4 : (v == 2 ? 0x75 : 0x74));
        uint8_t w[2] = {10, 50};
        p_cmd(&o, 0x15);
        p_data(&o, w, 2);
        w[0] = 20;
        w[1] = 90;
        p_cmd(&o, 0x75);
        p_data(&o, w, 2);
        p_cmd(&o, 0x5C);
        p_long(&o, (v == 1 ? 3u : 2u) * 41u * 71u, v == 1 ? 3 : 2, 0x3F, 0x01, 0x20);
        p_cmd(&o, 0xAF);
        p_view(&o, v);
        write_seed(dir, n++, &o);
    }
    /* protocol errors: stray data, short parameters, a command mid-pixel,
     * bytes in reset, locked SSD1351, bad COLMOD, window outside the RAM */
    {
        static const uint8_t junk[] = {1, 2, 3, 4, 5, 6, 7};
        memset(&o, 0, sizeof o);
        u8(&o, 0);
        p_data(&o, junk, 7);
        p_cmd(&o, 0x2A);
        p_data(&o, junk, 2);
        p_cmd(&o, 0x2C);
        p_data(&o, junk, 3);
        p_cmd(&o, 0x00);
        p_reset(&o, 0);
        p_cmd(&o, 0x11);
        p_data(&o, junk, 3);
        p_reset(&o, 1);
        p_cmd1(&o, 0x3A, 0x77);
        p_window(&o, 200, 300, 400, 500);
        p_cmd(&o, 0x2C);
        p_long(&o, 500, 2, 1, 2, 3);
        p_cmd(&o, 0x29);
        p_data(&o, junk, 5);
        write_seed(dir, n++, &o);
        memset(&o, 0, sizeof o);
        u8(&o, 7);
        p_cmd1(&o, 0xFD, 0x16);
        p_cmd(&o, 0x5C);
        p_data(&o, junk, 6);
        p_cmd1(&o, 0xFD, 0x12);
        p_cmd1(&o, 0xB3, 0xF1);
        p_cmd1(&o, 0xA0, 0xF4);
        uint8_t w[2] = {100, 20};
        p_cmd(&o, 0x15);
        p_data(&o, w, 2);
        p_cmd(&o, 0xB8);
        p_data(&o, junk, 7);
        write_seed(dir, n++, &o);
    }
    printf("gen_seeds: %d panel seeds in %s\n", n, dir);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 3 || (strcmp(argv[1], "frame") != 0 && strcmp(argv[1], "panel") != 0)) {
        fprintf(stderr, "usage: gen_seeds frame|panel DIR\n");
        return 2;
    }
    const char *dir = argv[2];
    if (!strcmp(argv[1], "panel"))
        return panel_seeds(dir);
    int n = 0;
    out o;

    /* 1. two penetrating triangles, RGB565 BE, every band size */
    for (int band = 1; band <= 4; band++) {
        memset(&o, 0, sizeof o);
        header(&o, (cfg){48, 40, 16, 16, 8, 0});
        camera_std(&o, 60, 6, 6400);
        mode_ok(&o);
        shading(&o, 0, 0, 0, 0, 0, 0);
        u8(&o, 0); /* one mesh */
        mesh m;
        memset(&m, 0, sizeof m);
        m.nv = 6;
        m.nt = 2;
        int p[] = {-40, -30, 0, 40, -30, 0, 0, 40, 0, -40, 0, -30, 40, 0, 30, 0, 10, 40};
        memcpy(m.pos, p, sizeof p);
        int ix[] = {0, 1, 2, 3, 4, 5};
        memcpy(m.idx, ix, sizeof ix);
        m.fcol = 1;
        m.sk = 15;
        m.tz = -48;
        put_mesh(&o, &m);
        plan(&o, band * band, 0, band % 2, band - 1);
        write_seed(dir, n++, &o);
    }
    /* 2. random scenes: every format, flat/Gouraud, lights, fog, pools */
    for (int s = 0; s < 36; s++) {
        memset(&o, 0, sizeof o);
        int w = rr(1, 64), h = rr(1, 64);
        int small = s % 3 == 0;
        header(&o, (cfg){w, h, small ? rr(1, 12) : 128, small ? rr(3, 30) : 160,
                         small ? rr(2, 8) : 49, s % 8 == 5 ? 1 : (s % 8 == 6 ? 2 : 0)});
        camera_std(&o, rr(20, 120), rr(1, 64), rr(400, 20000));
        mode_ok(&o);
        shading(&o, s % 4 != 0, s % 6, s % 2, rnd() & 0xFFFFFFu, s % 5 == 1, s % 7 == 2);
        int nm = 1 + s % 4;
        u8(&o, (unsigned)(nm - 1));
        for (int i = 0; i < nm; i++) {
            mesh m;
            random_mesh(&m, rr(1, 16), (s + i) % 2);
            m.fcol = (s + i) % 3 == 0;
            m.vcol = (s + i) % 4 == 1;
            m.fnorm = (s + i) % 5 == 2;
            m.vnorm = (s + i) % 3 == 1;
            m.ax = rr(0, 255);
            m.ay = rr(0, 255);
            m.az = rr(0, 255);
            if (s % 9 == 4)
                m.tz = -4; /* through the near plane: clipping */
            put_mesh(&o, &m);
        }
        plan(&o, rr(1, h), s % 5 == 3 ? rr(0, 15) : 0, s % 2, rr(0, 7));
        write_seed(dir, n++, &o);
    }
    /* 3. error paths */
    /* 3a. invalid configs */
    {
        static const unsigned c[][5] = {{0, 10, 10, 10, 10}, {10, 2049, 10, 10, 10},
                                        {10, 10, 0, 10, 10}, {10, 10, 10, 10, 1},
                                        {10, 10, 10, 10, 4097}, {64, 64, 100, 100, 64}};
        for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
            memset(&o, 0, sizeof o);
            u8(&o, 0xFF);
            for (int k = 0; k < 5; k++)
                u16(&o, c[i][k]);
            u32(&o, 1000);
            write_seed(dir, n++, &o);
        }
    }
    /* 3b. degenerate cameras: eye == target, fov 0 / 180, near == far */
    {
        memset(&o, 0, sizeof o);
        header(&o, (cfg){16, 16, 8, 8, 4, 0});
        u8(&o, 0);
        for (int i = 0; i < 3; i++)
            u8(&o, 0);
        u8(&o, 0);
        u8(&o, 0);
        u8(&o, 16); /* target z = 16/16 - 1 = 0: eye == target */
        u8(&o, 0);
        u8(&o, 59);
        u8(&o, 10);
        u16(&o, 100);
        write_seed(dir, n++, &o);
        static const uint8_t fovsel[][3] = {{1, 0, 0}, {1, 8, 0}, {1, 9, 0}, {1, 18, 0}};
        for (size_t i = 0; i < sizeof fovsel / sizeof fovsel[0]; i++) {
            memset(&o, 0, sizeof o);
            header(&o, (cfg){16, 16, 8, 8, 4, 0});
            u8(&o, 2);  /* set_view */
            u8(&o, 0);  /* identity */
            u8(&o, 200); /* raw perspective */
            u8(&o, fovsel[i][0]);
            u8(&o, fovsel[i][1]); /* special: 0, 180, 180-, 179 */
            u8(&o, 1);
            u8(&o, 15); /* near 0.1 */
            u8(&o, 1);
            u8(&o, 16); /* far 100 */
            write_seed(dir, n++, &o);
        }
        memset(&o, 0, sizeof o);
        header(&o, (cfg){16, 16, 8, 8, 4, 0});
        u8(&o, 2);
        u8(&o, 0);
        u8(&o, 255); /* near == far */
        u8(&o, 1);
        u8(&o, 22);
        u8(&o, 1);
        u8(&o, 15);
        u8(&o, 1);
        u8(&o, 16);
        write_seed(dir, n++, &o);
    }
    /* 3c. bad shading and meshes: unknown format, out-of-range index, zero scale */
    for (int v = 0; v < 3; v++) {
        memset(&o, 0, sizeof o);
        header(&o, (cfg){32, 32, 32, 32, 16, 0});
        camera_std(&o, 60, 6, 6400);
        mode_ok(&o);
        if (v == 0) {
            u8(&o, 1);
            u8(&o, 250); /* format -6 */
            u8(&o, 0);
            u32(&o, 0);
        } else {
            shading(&o, 0, 0, 0, 0, 0, 0);
        }
        u8(&o, 0);
        mesh m;
        random_mesh(&m, 4, 0);
        if (v == 1) {
            m.ik = 224; /* indices read modulo the vertex count + 2 */
            m.idx[5] = m.nv + 1;
        }
        m.zero_scale = v == 2;
        put_mesh(&o, &m);
        plan(&o, 3, 0, 0, 0);
        write_seed(dir, n++, &o);
    }
    printf("gen_seeds: %d seeds in %s\n", n, dir);
    return 0;
}
