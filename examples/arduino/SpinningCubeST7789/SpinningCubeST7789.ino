/*
 * zspan example: a spinning cube with vertex colours (Gouraud) on a 240x240
 * ST7789 module over the Arduino SPI API, one row at a time: no framebuffer.
 *
 * Wiring (change the pins below): SCK and MOSI on the board's SPI pins
 * (Mega 2560: 52 and 51; Uno: 13 and 11), CS 10, DC 9, RST 8, BL to 3.3 V.
 * The ST7789 is a 3.3 V part: use a level shifter on a 5 V board.
 * Modules without a CS pin need SPI_MODE3. About 3 KB of RAM (a Mega 2560 or
 * any board with more); for an ILI9341 use zs_panel_ili9341 and W, H 240, 320.
 * On AVR build with compiler.c.extra_flags=-fno-strict-aliasing (README: Arduino).
 */
#include <SPI.h>
#include <zspan.h>

#define PIN_CS 10
#define PIN_DC 9
#define PIN_RST 8
#define W 240
#define H 240
#define SPI_HZ 8000000

/* Corner i: x = bit 0, y = bit 1, z = bit 2; faces counter-clockwise from outside. */
static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1, -1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1,
};
static const uint16_t cube_idx[12 * 3] = {
    1, 3, 7, 1, 7, 5, 0, 6, 2, 0, 4, 6, 2, 6, 7, 2, 7, 3,
    0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 3, 1, 0, 2, 3,
};
static const zs_color cube_colors[8] = {
    ZS_RGB(40, 40, 40), ZS_RGB(255, 40, 40), ZS_RGB(40, 255, 40), ZS_RGB(255, 255, 40),
    ZS_RGB(40, 40, 255), ZS_RGB(255, 40, 255), ZS_RGB(40, 255, 255), ZS_RGB(255, 255, 255),
};

/* A cube stores at most 6 front triangles plus clipping's pieces. */
static uint8_t arena[ZS_ARENA_BYTES_CFG(W, H, 12, 16, 12, ZS_CFG_NO_ZLINE)];
static uint8_t line0[W * 2], line1[W * 2];
static zs_renderer renderer;
static zs_panel lcd;
static zs_bus bus;
static zs_camera cam;
static uint16_t frame = 24; /* a corner view from the first frame */

/* The bus for the panel driver: commands with DC low, then parameters and pixels
 * with DC high; blocking writes. */
static int bus_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    (void)user;
    SPI.beginTransaction(SPISettings(SPI_HZ, MSBFIRST, SPI_MODE0));
    digitalWrite(PIN_CS, LOW);
    digitalWrite(PIN_DC, LOW);
    SPI.transfer(cmd);
    digitalWrite(PIN_DC, HIGH);
    for (size_t i = 0; i < n; i++)
        SPI.transfer(params[i]);
    digitalWrite(PIN_CS, HIGH);
    SPI.endTransaction();
    return 0;
}

static int bus_pixels(void *user, const uint8_t *data, size_t n)
{
    (void)user;
    SPI.beginTransaction(SPISettings(SPI_HZ, MSBFIRST, SPI_MODE0));
    digitalWrite(PIN_CS, LOW);
    digitalWrite(PIN_DC, HIGH);
    for (size_t i = 0; i < n; i++)
        SPI.transfer(data[i]); /* the byte form: SPI.transfer(buf, n) would overwrite data */
    digitalWrite(PIN_CS, HIGH);
    SPI.endTransaction();
    return 0;
}

static void bus_reset(void *user, int level)
{
    (void)user;
    digitalWrite(PIN_RST, level ? HIGH : LOW);
}

static void bus_delay(void *user, uint32_t ms)
{
    (void)user;
    delay(ms);
}

static const zs_bus_ops ops = {bus_command, bus_pixels, bus_reset, NULL, bus_delay, NULL};

void setup()
{
    Serial.begin(115200);
    pinMode(PIN_CS, OUTPUT);
    pinMode(PIN_DC, OUTPUT);
    pinMode(PIN_RST, OUTPUT);
    digitalWrite(PIN_CS, HIGH);
    SPI.begin();
    zs_config cfg = zs_config_default(W, H, 12, 16, 12);
    cfg.flags = ZS_CFG_NO_ZLINE;
    zs_mat34 view = zs_mat34_identity();
    if (zs_bus_init(&bus, &ops, NULL, 0, 0) != ZS_BUS_OK ||
        zs_panel_init(&lcd, &zs_panel_st7789_240x240, &bus, ZS_FMT_RGB565_BE, 0) != ZS_PANEL_OK ||
        zs_init(&renderer, arena, sizeof arena, &cfg) != ZS_OK ||
        zs_camera_set_view(&cam, &view) != ZS_OK ||
        zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(20)) != ZS_OK) {
        Serial.println(F("zspan: init failed"));
        for (;;) {
        }
    }
}

void loop()
{
    zs_mesh cube = {cube_pos, cube_idx, NULL, cube_colors, NULL, NULL, ZS_FX_RATIO(6, 10), 8, 12, 0,
                    NULL, NULL};
    zs_shade_params look = zs_shade_default();
    look.shading = ZS_SHADE_GOURAUD;
    look.format = lcd.format;
    look.background = ZS_RGB(10, 12, 30);
    zs_mat34 ry = zs_mat34_rotate_y(ZS_FX((int32_t)(frame % 360u)));
    zs_mat34 rx = zs_mat34_rotate_x(ZS_FX((int32_t)((frame * 2u) % 360u)));
    zs_mat34 t = zs_mat34_translate(0, 0, -ZS_FX(3));
    zs_mat34 m = zs_mat34_mul(&rx, &ry);
    m = zs_mat34_mul(&t, &m);
    unsigned long t0 = millis();
    if (zs_frame_begin(&renderer, &cam, ZS_MODE_SPAN) != ZS_OK ||
        zs_frame_shading(&renderer, &look) != ZS_OK || zs_draw(&renderer, &cube, &m) != ZS_OK ||
        zs_panel_stream(&lcd, &renderer, line0, line1, sizeof line0, 1, NULL, NULL) != ZS_PANEL_OK) {
        Serial.println(F("zspan: frame failed"));
        delay(1000);
    }
    if (frame % 30u == 0) {
        Serial.print(F("frame ms: "));
        Serial.println(millis() - t0);
    }
    frame = (uint16_t)((frame + 3u) % 360u);
}
