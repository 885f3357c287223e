/* SPDX-License-Identifier: MIT */
/*
 * Runs an AVR image under libsimavr and counts its cycles exactly.
 *
 *   simavr_run MCU HZ IMAGE.elf [MAX_MCYCLES]
 *
 * Copies USART0's output to stdout; a line starting "R " gets " cycles=N"
 * appended, N the cycles the image marked since its previous line: marks are
 * writes to GPIOR0 (1 start, 2 stop, 3 pause, 4 resume; ports/avr/avr_port.c).
 * Exits with the image's status (written to GPIOR1 before it sleeps with
 * interrupts off), 98 if it crashed, 97 if it ran past MAX_MCYCLES million
 * cycles (default 20000).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sim_avr.h>
#include <sim_elf.h>
#include <sim_io.h>
#include <avr_uart.h>

/* Data-space addresses of GPIOR0 and GPIOR1 (ATmega640/1280/2560 and most AVRs). */
#define GPIOR0_ADDR 0x3E
#define GPIOR1_ADDR 0x4A

static avr_t *avr;
static char line[512];
static size_t line_len;
static avr_cycle_count_t run_from, counted, last_frame;
static int running, status;

static void on_mark(struct avr_t *a, avr_io_addr_t addr, uint8_t v, void *param)
{
    (void)addr;
    (void)param;
    if (v == 1 || v == 4) {
        if (v == 1)
            counted = 0;
        run_from = a->cycle;
        running = 1;
    } else if ((v == 2 || v == 3) && running) {
        counted += a->cycle - run_from;
        running = 0;
        if (v == 2)
            last_frame = counted;
    }
}

static void on_status(struct avr_t *a, avr_io_addr_t addr, uint8_t v, void *param)
{
    (void)a;
    (void)addr;
    (void)param;
    status = v;
}

static void on_uart(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    (void)param;
    if (value == '\n') {
        line[line_len] = 0;
        if (strncmp(line, "R ", 2) == 0)
            printf("%s cycles=%llu\n", line, (unsigned long long)last_frame);
        else
            printf("%s\n", line);
        fflush(stdout);
        line_len = 0;
    } else if (line_len + 1 < sizeof line) {
        line[line_len++] = (char)value;
    }
}

int main(int argc, char **argv)
{
    elf_firmware_t fw;
    uint32_t flags = 0;
    unsigned long long max_cycles;
    int state;

    if (argc < 4) {
        fprintf(stderr, "usage: simavr_run MCU HZ IMAGE.elf [MAX_MCYCLES]\n");
        return 2;
    }
    max_cycles = (argc > 4 ? strtoull(argv[4], NULL, 10) : 20000ull) * 1000000ull;
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[3], &fw) != 0) {
        fprintf(stderr, "simavr_run: cannot read %s\n", argv[3]);
        return 2;
    }
    avr = avr_make_mcu_by_name(argv[1]);
    if (!avr) {
        fprintf(stderr, "simavr_run: unknown MCU %s\n", argv[1]);
        return 2;
    }
    avr_init(avr);
    avr->frequency = (uint32_t)strtoul(argv[2], NULL, 10);
    avr->log = 0;
    avr_load_firmware(avr, &fw);
    /* our own copy of the UART output: not simavr's console printing */
    avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)AVR_UART_FLAG_STDIO;
    avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                            on_uart, NULL);
    avr_register_io_write(avr, GPIOR0_ADDR, on_mark, NULL);
    avr_register_io_write(avr, GPIOR1_ADDR, on_status, NULL);
    status = -1;
    do {
        state = avr_run(avr);
        if (avr->cycle > max_cycles) {
            fprintf(stderr, "simavr_run: more than %llu cycles\n", max_cycles);
            return 97;
        }
    } while (state != cpu_Done && state != cpu_Crashed);
    if (state == cpu_Crashed || status < 0) {
        fprintf(stderr, "simavr_run: the image %s (pc 0x%x)\n",
                state == cpu_Crashed ? "crashed" : "stopped without an exit status",
                (unsigned)avr->pc);
        return 98;
    }
    fprintf(stderr, "simavr_run: %llu cycles in all, exit status %d\n",
            (unsigned long long)avr->cycle, status);
    return status;
}
