/* SPDX-License-Identifier: MIT */
/*
 * zspan Cortex-M port: the minimal board layer the firmware images use.
 *
 * Bare metal, no newlib stdio: output goes through ARM semihosting (which
 * QEMU implements with -semihosting), time through SysTick. Freestanding C99.
 */
#ifndef ZSPAN_PORT_H
#define ZSPAN_PORT_H

#include <stddef.h>
#include <stdint.h>

/* ---- board description (board_*.c) ---------------------------------- */
typedef struct port_board {
    const char *name;        /* "mps2-an386", "microbit", ... */
    const char *cpu;         /* "cortex-m4", "cortex-m0" */
    uint32_t cpu_hz;         /* SysTick clock with CLKSOURCE = processor clock */
    /* Guest instructions per SysTick tick under qemu -icount shift=0, x1000
     * (the nominal figure: 1 instruction per ns, so 1e12 / cpu_hz). */
    uint32_t nominal_ipt_milli;
} port_board;

extern const port_board port_this_board;

/* ---- startup (startup.c) -------------------------------------------- */
/* Linker symbols: the free RAM between .bss and the stack reserve, which the
 * application may use as its renderer arena. */
uint8_t *port_free_ram(size_t *bytes);
/* Bytes of the stack reserve that were ever written (painted at reset). */
size_t port_stack_high_water(void);
size_t port_stack_size(void);
/* .data + .bss bytes of the image. */
size_t port_static_ram(void);

/* ---- semihosting (semihost.c) --------------------------------------- */
void sh_write0(const char *s);            /* NUL-terminated string to the host */
void sh_putc(char c);                     /* buffered; flushed at '\n' */
void sh_flush(void);
/* printf subset: %d %u %x %X %s %c %%, flags 0 and -, width, l / ll. */
void sh_printf(const char *fmt, ...);
/* Command line given by the host (QEMU: -semihosting-config arg=...).
 * Returns 0 and fills buf, or -1. */
int sh_get_cmdline(char *buf, size_t size);
/* Ends the program; status reaches the host as QEMU's exit status. */
void sh_exit(int status) __attribute__((noreturn));

/* ---- timing (systick.c) --------------------------------------------- */
void port_timer_start(void);              /* SysTick free-running, 24-bit + IRQ */
uint64_t port_ticks(void);                /* ticks since port_timer_start */
/* Measures guest instructions per tick (x1000) with a loop of known length. */
uint32_t port_calibrate_ipt_milli(void);
/* A loop executing exactly 2 * n instructions (subs + bne), n >= 1. */
void port_spin(uint32_t n);

#endif
