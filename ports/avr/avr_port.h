/* SPDX-License-Identifier: MIT */
/*
 * zspan AVR port: the minimal board layer of the ATmega2560 images run under
 * simavr (8 KB RAM, 16-bit int). avr-libc; stdout on USART0; markers and the
 * exit status through the general-purpose I/O registers, which the simulator
 * harness (ports/avr/simavr_run.c) watches to count cycles exactly.
 */
#ifndef ZSPAN_AVR_PORT_H
#define ZSPAN_AVR_PORT_H

#include <stddef.h>
#include <stdint.h>

/* USART0 at the fastest rate, stdout and stderr on it. */
void avr_port_init(void);
/* Writes GPIOR0: the harness notes the cycle count of each write. */
void avr_port_mark(uint8_t what);
/* Exit status to GPIOR1, then sleeps with interrupts off (simavr stops). */
void avr_port_exit(uint8_t status) __attribute__((noreturn));
/* .data + .bss bytes, and the stack's high-water mark (painted at reset). */
size_t avr_port_static_ram(void);
size_t avr_port_stack_used(void);

#endif
