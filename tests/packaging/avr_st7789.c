/* SPDX-License-Identifier: MIT */
/*
 * Runs an Arduino Mega 2560 sketch image under libsimavr with an emulated
 * ST7789 240x240 (host_sim/emu) on its SPI pins, until the panel has received
 * one whole frame after the driver's init, and writes what the panel shows.
 *
 *   avr_st7789 IMAGE.elf OUT.rgb [MAX_MCYCLES]
 *
 * Wiring as examples/arduino/SpinningCubeST7789: CS D10 (PB4), DC D9 (PH6),
 * RST D8 (PH5); bytes from the SPI master go to the panel while CS is low, as
 * commands when DC is low. The panel's clock is the AVR's (cycles / 16 MHz),
 * so its datasheet delay checks see the sketch's real delays. OUT gets the
 * 240x240 picture as RGB bytes. Exit 0 when a frame arrived and the panel
 * flagged no protocol error, 1 otherwise, 2 on bad use.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <avr_ioport.h>
#include <avr_spi.h>
#include <sim_avr.h>
#include <sim_elf.h>
#include <sim_io.h>

#include "emu.h"

static avr_t *avr;
static emu_panel panel;
static int cs = 1, dc = 1;
static uint64_t frame_bytes; /* pixel bytes since the last memory write command */
static int frames;

static void sync_clock(void)
{
    uint64_t us = avr->cycle / 16u;
    if (us > panel.now_us)
        panel.now_us = us;
}

static void on_cs(struct avr_irq_t *irq, uint32_t v, void *p)
{
    (void)irq;
    (void)p;
    cs = v != 0;
}

static void on_dc(struct avr_irq_t *irq, uint32_t v, void *p)
{
    (void)irq;
    (void)p;
    dc = v != 0;
}

static void on_rst(struct avr_irq_t *irq, uint32_t v, void *p)
{
    (void)irq;
    (void)p;
    sync_clock();
    emu_reset_line(&panel, v != 0);
}

static void on_spi(struct avr_irq_t *irq, uint32_t v, void *p)
{
    uint8_t b = (uint8_t)v;
    (void)irq;
    (void)p;
    if (cs)
        return;
    sync_clock();
    if (!dc) {
        emu_command(&panel, b);
        if (b == 0x2C) { /* RAMWR: a frame's pixels follow */
            frame_bytes = 0;
        }
    } else {
        emu_data(&panel, &b, 1);
        if (panel.writing && ++frame_bytes == 240u * 240u * 2u)
            frames++;
    }
}

static void watch(char port, int pin, avr_irq_notify_t fn)
{
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), pin), fn, NULL);
}

int main(int argc, char **argv)
{
    elf_firmware_t fw;
    unsigned long long max_cycles;
    unsigned w, h;
    uint8_t *rgb;
    FILE *f;
    int state;

    if (argc < 3) {
        fprintf(stderr, "usage: avr_st7789 IMAGE.elf OUT.rgb [MAX_MCYCLES]\n");
        return 2;
    }
    max_cycles = (argc > 3 ? strtoull(argv[3], NULL, 10) : 2000ull) * 1000000ull;
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[1], &fw) != 0 || !(avr = avr_make_mcu_by_name("atmega2560")))
        return 2;
    avr_init(avr);
    avr->frequency = 16000000u;
    avr->log = 0;
    avr_load_firmware(avr, &fw);
    if (emu_init(&panel, emu_model_find("st7789-240x240")) != 0)
        return 2;
    watch('B', IOPORT_IRQ_PIN4, on_cs);
    watch('H', IOPORT_IRQ_PIN6, on_dc);
    watch('H', IOPORT_IRQ_PIN5, on_rst);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_SPI_GETIRQ(0), SPI_IRQ_OUTPUT), on_spi,
                            NULL);
    do {
        state = avr_run(avr);
    } while (frames == 0 && avr->cycle < max_cycles && state != cpu_Done && state != cpu_Crashed);
    fprintf(stderr, "avr_st7789: %llu cycles, %d frame(s), %llu bytes in, %u commands, errors 0x%x\n",
            (unsigned long long)avr->cycle, frames, (unsigned long long)panel.bytes_in,
            (unsigned)panel.commands, (unsigned)panel.errors);
    for (unsigned i = 0; i < panel.log_lines && i < EMU_LOG_LINES; i++)
        fprintf(stderr, "  panel: %s\n", panel.log[i]);
    emu_view_size(&panel, 0, &w, &h);
    rgb = malloc((size_t)w * h * 3);
    if (!rgb)
        return 2;
    emu_view_rgb(&panel, 0, rgb);
    f = fopen(argv[2], "wb");
    if (!f || fwrite(rgb, 1, (size_t)w * h * 3, f) != (size_t)w * h * 3 || fclose(f) != 0)
        return 2;
    free(rgb);
    return frames > 0 && panel.errors == 0 ? 0 : 1;
}
