/* SPDX-License-Identifier: MIT */
/*
 * zspan RISC-V port: the board layer the benchmark images use on RV32 parts
 * (QEMU's sifive_e: 16 KB RAM at 0x80000000, code at 0x20400000), the same
 * interface as ports/cortex-m/port.h so bench/bench_fw.c builds unchanged.
 *
 * picolibc with its semihosting back end: stdout and the command line through
 * RISC-V semihosting (QEMU -semihosting-config), time from the minstret
 * counter (retired instructions: exact under qemu -icount shift=0).
 */
#ifndef ZSPAN_PORT_H
#define ZSPAN_PORT_H

#include <stddef.h>
#include <stdint.h>

/* ---- board description (board_*.c) ---------------------------------- */
typedef struct port_board {
    const char *name;        /* "sifive_e" */
    const char *cpu;         /* "rv32imc" */
    uint32_t cpu_hz;         /* nominal core clock */
    /* Instructions per tick x1000: a tick is one retired instruction. */
    uint32_t nominal_ipt_milli;
} port_board;

extern const port_board port_this_board;

/* ---- memory (port_riscv.c) ------------------------------------------- */
/* The free RAM between .bss and the stack (picolibc's heap, unused). */
uint8_t *port_free_ram(size_t *bytes);
/* Bytes of the stack that were ever written (painted before main). */
size_t port_stack_high_water(void);
size_t port_stack_size(void);
/* .data + .bss bytes of the image. */
size_t port_static_ram(void);

/* ---- host I/O through semihosting (port_riscv.c) --------------------- */
void sh_write0(const char *s);
void sh_putc(char c);
void sh_flush(void);
void sh_printf(const char *fmt, ...);
/* Command line given by the host (QEMU: -semihosting-config arg=...).
 * Returns 0 and fills buf, or -1. */
int sh_get_cmdline(char *buf, size_t size);
void sh_exit(int status) __attribute__((noreturn));

/* ---- timing (port_riscv.c) ------------------------------------------- */
void port_timer_start(void);
uint64_t port_ticks(void);                /* minstret since reset */
/* Instructions per tick x1000: 1000 (a tick is one retired instruction). */
uint32_t port_calibrate_ipt_milli(void);
/* A loop executing exactly 2 * n instructions (addi + bnez), n >= 1. */
void port_spin(uint32_t n);

#endif
