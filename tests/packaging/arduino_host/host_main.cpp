/*
 * Host side of the Arduino run check: the sketch's setup() and one loop()
 * (its first frame) on an emulated ST7789 240x240 wired as the sketch says
 * (CS 10, DC 9, RST 8); writes the panel's picture as RGB bytes.
 *
 *   host-SpinningCubeST7789 OUT.rgb
 */
#include <cstdio>
#include <cstdlib>

#include "Arduino.h"
#include "SPI.h"
#include "emu.h"

HardwareSerial Serial;
SPIClass SPI;
static emu_panel panel;
static int cs = 1, dc = 1;

void pinMode(int, int) {}

void digitalWrite(int pin, int level)
{
    if (pin == 10)
        cs = level;
    else if (pin == 9)
        dc = level;
    else if (pin == 8)
        emu_reset_line(&panel, level);
}

void delay(unsigned long ms)
{
    emu_delay_ms(&panel, (uint32_t)ms);
}

unsigned long millis(void)
{
    return (unsigned long)(panel.now_us / 1000u);
}

uint8_t SPIClass::transfer(uint8_t b)
{
    if (!cs) {
        if (dc)
            emu_data(&panel, &b, 1);
        else
            emu_command(&panel, b);
    }
    return 0;
}

int main(int argc, char **argv)
{
    unsigned w, h;
    if (argc < 2 || emu_init(&panel, emu_model_find("st7789-240x240")) != 0)
        return 2;
    setup();
    loop();
    emu_view_size(&panel, 0, &w, &h);
    uint8_t *rgb = static_cast<uint8_t *>(std::malloc((size_t)w * h * 3));
    if (!rgb)
        return 2;
    emu_view_rgb(&panel, 0, rgb);
    FILE *f = std::fopen(argv[1], "wb");
    if (!f || std::fwrite(rgb, 1, (size_t)w * h * 3, f) != (size_t)w * h * 3 || std::fclose(f))
        return 2;
    std::fprintf(stderr, "host: %llu bytes in, %u commands, errors 0x%x\n",
                 (unsigned long long)panel.bytes_in, (unsigned)panel.commands,
                 (unsigned)panel.errors);
    std::free(rgb);
    return panel.errors == 0 ? 0 : 1;
}
