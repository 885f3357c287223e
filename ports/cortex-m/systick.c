/* SPDX-License-Identifier: MIT */
/* SysTick as a 64-bit tick counter, and the calibration against a loop of
 * known instruction count (under qemu -icount the ratio is exact). */
#include "port.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SYST_RELOAD 0xFFFFFFu

static volatile uint32_t wraps;

void SysTick_Handler(void)
{
    wraps++;
}

void port_timer_start(void)
{
    SYST_CSR = 0;
    SYST_RVR = SYST_RELOAD;
    SYST_CVR = 0;
    wraps = 0;
    SYST_CSR = 7; /* ENABLE | TICKINT | CLKSOURCE = processor clock */
}

uint64_t port_ticks(void)
{
    uint32_t w1, w2, cvr;
    do {
        w1 = wraps;
        cvr = SYST_CVR;
        w2 = wraps;
    } while (w1 != w2);
    /* After the start the counter reads 0, then RELOAD, RELOAD-1, ..., 1, 0
     * (the interrupt counts the 1 -> 0 step), then RELOAD again: so the
     * elapsed ticks are wraps * 2^24 + (RELOAD + 1 - cvr) mod 2^24. */
    return ((uint64_t)w1 << 24) + ((SYST_RELOAD + 1u - cvr) & SYST_RELOAD);
}

void port_spin(uint32_t n)
{
    __asm__ volatile(".syntax unified\n"
                     "1: subs %0, %0, #1\n"
                     "   bne 1b\n"
                     : "+l"(n)
                     :
                     : "cc");
}

uint32_t port_calibrate_ipt_milli(void)
{
    /* Two runs of different length: the difference cancels the fixed cost. */
    const uint32_t n1 = 100000u, n2 = 10100000u;
    uint64_t t0, t1, t2, t3, d;
    t0 = port_ticks();
    port_spin(n1);
    t1 = port_ticks();
    t2 = port_ticks();
    port_spin(n2);
    t3 = port_ticks();
    d = (t3 - t2) - (t1 - t0);
    if (d == 0)
        return 0;
    return (uint32_t)(((uint64_t)2u * (n2 - n1) * 1000u + d / 2) / d);
}
