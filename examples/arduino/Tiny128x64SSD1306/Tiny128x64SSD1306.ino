/*
 * zspan example for boards with little RAM: a turning pyramid and cube at
 * 128x64 on an SSD1306 monochrome OLED over I2C (Wire). Rows are rendered in
 * 8-bit grey one at a time, dithered (4x4 ordered) into one 128-byte page of
 * the OLED's memory, and each page is sent when its 8 rows are done: the whole
 * frame never exists in RAM. About 2.2 KB of RAM with the Wire library.
 *
 * Wiring: SDA and SCL on the board's I2C pins (Mega 2560: 20, 21; Uno: A4, A5),
 * VCC and GND; address 0x3C (some modules: 0x3D).
 * On AVR build with compiler.c.extra_flags=-fno-strict-aliasing (README: Arduino).
 */
#include <Wire.h>
#include <zspan.h>

#define OLED_ADDR 0x3C
#define W 128
#define H 64

static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1, -1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1,
};
static const uint16_t cube_idx[12 * 3] = {
    1, 3, 7, 1, 7, 5, 0, 6, 2, 0, 4, 6, 2, 6, 7, 2, 7, 3,
    0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 3, 1, 0, 2, 3,
};
/* Pyramid: base corners at y = 0, apex above; its base faces down. */
static const int16_t pyr_pos[5 * 3] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1, 0, 2, 0};
static const uint16_t pyr_idx[6 * 3] = {3, 2, 4, 2, 1, 4, 1, 0, 4, 0, 3, 4, 0, 1, 2, 0, 2, 3};

/* Flat shading and the span mode only: the smallest arena. */
#define FLAGS (ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE)
static uint8_t arena[ZS_ARENA_BYTES_CFG(W, H, 20, 20, 16, FLAGS)];
static uint8_t row[W];
static uint8_t page[W];
static zs_renderer renderer;
static zs_camera cam;
static uint16_t angle;

static void oled_commands(const uint8_t *c, uint8_t n)
{
    Wire.beginTransmission(OLED_ADDR);
    Wire.write((uint8_t)0x00); /* control byte: commands follow */
    Wire.write(c, n);
    Wire.endTransmission();
}

static void oled_data(const uint8_t *d, uint8_t n)
{
    /* the Wire buffer holds 32 bytes: 16 data bytes per transmission */
    for (uint8_t i = 0; i < n; i += 16) {
        Wire.beginTransmission(OLED_ADDR);
        Wire.write((uint8_t)0x40); /* control byte: data follows */
        Wire.write(d + i, (uint8_t)(n - i < 16 ? n - i : 16));
        Wire.endTransmission();
    }
}

void setup()
{
    /* SSD1306 datasheet: display off, clock, multiplex 64, offset 0, start line 0,
     * charge pump on, horizontal addressing, segment remap, COM scan reversed,
     * COM pins, contrast, precharge, VCOMH, resume RAM, normal, display on */
    static const uint8_t init_seq[] = {0xAE, 0xD5, 0x80, 0xA8, 0x3F, 0xD3, 0x00, 0x40,
                                       0x8D, 0x14, 0x20, 0x00, 0xA1, 0xC8, 0xDA, 0x12,
                                       0x81, 0xCF, 0xD9, 0xF1, 0xDB, 0x40, 0xA4, 0xA6, 0xAF};
    Wire.begin();
    oled_commands(init_seq, sizeof init_seq);
    zs_config cfg = zs_config_default(W, H, 20, 20, 16);
    cfg.flags = FLAGS;
    zs_vec3 eye = zs_vec3_make(0, ZS_FX(2), ZS_FX(5));
    zs_vec3 target = zs_vec3_make(0, ZS_FX_RATIO(5, 10), 0);
    zs_vec3 up = zs_vec3_make(0, ZS_FX(1), 0);
    if (zs_init(&renderer, arena, sizeof arena, &cfg) != ZS_OK ||
        zs_camera_look_at(&cam, eye, target, up) != ZS_OK ||
        zs_camera_perspective(&cam, ZS_FX(40), ZS_FX_RATIO(1, 10), ZS_FX(20)) != ZS_OK) {
        for (;;) {
        }
    }
}

void loop()
{
    static const uint8_t bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    static const uint8_t whole_screen[] = {0x21, 0, W - 1, 0x22, 0, H / 8 - 1};
    zs_mesh cube = {cube_pos, cube_idx, NULL, NULL, NULL, NULL, ZS_FX_RATIO(6, 10), 8, 12,
                    ZS_RGB(230, 230, 230), NULL, NULL};
    zs_mesh pyr = {pyr_pos, pyr_idx, NULL, NULL, NULL, NULL, ZS_FX_RATIO(7, 10), 5, 6,
                   ZS_RGB(200, 200, 200), NULL, NULL};
    zs_shade_params look = zs_shade_default();
    look.format = ZS_FMT_GRAY8;
    look.ambient = ZS_FX_RATIO(2, 10);
    look.light_count = 1;
    look.lights[0].direction = zs_vec3_make(-ZS_FX(1), ZS_FX(2), ZS_FX(1));
    look.lights[0].intensity = ZS_FX_RATIO(9, 10);
    zs_mat34 spin = zs_mat34_rotate_y(ZS_FX((int32_t)angle));
    zs_mat34 left = zs_mat34_translate(-ZS_FX_RATIO(13, 10), 0, 0);
    zs_mat34 right = zs_mat34_translate(ZS_FX_RATIO(13, 10), ZS_FX_RATIO(6, 10), 0);
    zs_mat34 mp = zs_mat34_mul(&left, &spin);
    zs_mat34 mc = zs_mat34_mul(&right, &spin);
    if (zs_frame_begin(&renderer, &cam, ZS_MODE_SPAN) != ZS_OK ||
        zs_frame_shading(&renderer, &look) != ZS_OK || zs_draw(&renderer, &pyr, &mp) != ZS_OK ||
        zs_draw(&renderer, &cube, &mc) != ZS_OK)
        return;
    oled_commands(whole_screen, sizeof whole_screen);
    for (int y = 0; y < H; y++) {
        if (zs_render_rows(&renderer, y, 1, row, sizeof row) != ZS_OK)
            return;
        uint8_t bit = (uint8_t)(1u << (y & 7));
        for (int x = 0; x < W; x++) {
            if ((y & 7) == 0)
                page[x] = 0;
            if (row[x] > (uint8_t)(bayer[y & 3][x & 3] * 16u + 8u))
                page[x] |= bit;
        }
        if ((y & 7) == 7)
            oled_data(page, W);
    }
    angle = (uint16_t)((angle + 4u) % 360u);
}
