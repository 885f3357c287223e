/* SPDX-License-Identifier: MIT */
/* RISC-V board layer on picolibc: semihosted stdio, minstret, RAM figures. */
#include "port.h"

#include <semihost.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* picolibc.ld: .data, .bss, the heap (free RAM) and the stack above it. */
extern uint8_t __data_start[], __data_end[], __bss_start[], __bss_end[];
extern uint8_t __heap_start[], __heap_end[], __stack[];

#define STACK_PAINT 0xA5u

/* Before main (picolibc runs the constructors): paint the stack below the
 * current frame, to measure its high-water mark. */
__attribute__((constructor)) static void paint_stack(void)
{
    uint8_t *p = __heap_end;
    uint8_t *sp = (uint8_t *)__builtin_frame_address(0) - 64;
    while (p < sp)
        *p++ = STACK_PAINT;
}

uint8_t *port_free_ram(size_t *bytes)
{
    *bytes = (size_t)(__heap_end - __heap_start);
    return __heap_start;
}

size_t port_stack_size(void)
{
    return (size_t)(__stack - __heap_end);
}

size_t port_stack_high_water(void)
{
    const uint8_t *p = __heap_end;
    while (p < __stack && *p == STACK_PAINT)
        p++;
    return (size_t)(__stack - p);
}

size_t port_static_ram(void)
{
    return (size_t)(__data_end - __data_start) + (size_t)(__bss_end - __bss_start);
}

void sh_write0(const char *s)
{
    fputs(s, stdout);
}

void sh_putc(char c)
{
    putchar(c);
}

void sh_flush(void)
{
    fflush(stdout);
}

void sh_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

int sh_get_cmdline(char *buf, size_t size)
{
    if (size == 0 || size > 0x7FFFFFFFu)
        return -1;
    return sys_semihost_get_cmdline(buf, (int)size) == 0 ? 0 : -1;
}

void sh_exit(int status)
{
    fflush(stdout);
    exit(status);
}

void port_timer_start(void)
{
}

uint64_t port_ticks(void)
{
    uint32_t hi, lo, hi2;
    do {
        __asm__ volatile("csrr %0, minstreth" : "=r"(hi));
        __asm__ volatile("csrr %0, minstret" : "=r"(lo));
        __asm__ volatile("csrr %0, minstreth" : "=r"(hi2));
    } while (hi != hi2);
    return ((uint64_t)hi << 32) | lo;
}

void port_spin(uint32_t n)
{
    __asm__ volatile("1: addi %0, %0, -1\n\tbnez %0, 1b" : "+r"(n));
}

uint32_t port_calibrate_ipt_milli(void)
{
    return 1000u; /* a tick is one retired instruction */
}
