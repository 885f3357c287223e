/* SPDX-License-Identifier: MIT */
/* ATmega2560 board layer for simavr: USART0 stdout, GPIOR markers, RAM figures. */
#include "avr_port.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <stdio.h>

extern uint8_t __data_start[], __bss_end[];

#define STACK_PAINT 0xC5u

static int uart_put(char c, FILE *f)
{
    (void)f;
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    UDR0 = (uint8_t)c;
    return 0;
}

static FILE uart_out = FDEV_SETUP_STREAM(uart_put, NULL, _FDEV_SETUP_WRITE);

/* Before main and before the stack is used for anything: paint the free RAM
 * between .bss and the stack pointer. */
void avr_port_paint(void) __attribute__((naked, used, section(".init3")));
void avr_port_paint(void)
{
    uint8_t *p = __bss_end;
    while (p < (uint8_t *)SP - 2)
        *p++ = STACK_PAINT;
}

void avr_port_init(void)
{
    UBRR0 = 0;
    UCSR0A = (uint8_t)(1 << U2X0);
    UCSR0B = (uint8_t)(1 << TXEN0);
    UCSR0C = (uint8_t)((1 << UCSZ01) | (1 << UCSZ00));
    stdout = &uart_out;
    stderr = &uart_out;
}

void avr_port_mark(uint8_t what)
{
    GPIOR0 = what;
}

void avr_port_exit(uint8_t status)
{
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    GPIOR1 = status;
    cli();
    sleep_enable();
    for (;;)
        sleep_cpu();
}

size_t avr_port_static_ram(void)
{
    return (size_t)(__bss_end - __data_start);
}

size_t avr_port_stack_used(void)
{
    const uint8_t *p = __bss_end;
    while (p <= (const uint8_t *)RAMEND && *p == STACK_PAINT)
        p++;
    return (size_t)((const uint8_t *)RAMEND + 1 - p);
}
