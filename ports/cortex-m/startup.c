/* SPDX-License-Identifier: MIT */
/* Reset and vector table for the QEMU Cortex-M boards (and any ARMv6-M/v7-M
 * part with the same layout): copy .data, zero .bss, paint the stack, call
 * main, report faults through semihosting. */
#include "port.h"

#include <string.h>

extern uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end;
extern uint8_t __free_ram_start[], __free_ram_end[];
extern uint32_t __stack_limit[], __stack_top[];

#define STACK_PAINT 0xA5C3E1F7u

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void SysTick_Handler(void);

static void fault(const char *what)
{
    sh_flush();
    sh_write0("\n*** fault: ");
    sh_write0(what);
    sh_write0("\n");
    sh_exit(99);
}

void NMI_Handler(void) { fault("NMI"); }
void HardFault_Handler(void) { fault("HardFault"); }
void Default_Handler(void) { fault("unexpected interrupt"); }
void MemManage_Handler(void) __attribute__((weak, alias("Default_Handler")));
void BusFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void UsageFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SVC_Handler(void) __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler(void) __attribute__((weak, alias("Default_Handler")));

typedef void (*vector_fn)(void);

__attribute__((section(".isr_vector"), used)) const vector_fn port_vectors[16 + 32] = {
    (vector_fn)(uintptr_t)__stack_top,
    Reset_Handler,
    NMI_Handler,
    HardFault_Handler,
    MemManage_Handler,
    BusFault_Handler,
    UsageFault_Handler,
    0, 0, 0, 0,
    SVC_Handler,
    0, 0,
    PendSV_Handler,
    SysTick_Handler,
    /* 32 external interrupts: none used by the QEMU images */
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler,
};

void Reset_Handler(void)
{
    uint32_t *src = &__data_load, *dst = &__data_start;
    uint32_t *p, *sp;
    while (dst < &__data_end)
        *dst++ = *src++;
    for (dst = &__bss_start; dst < &__bss_end;)
        *dst++ = 0;
    /* Paint the stack below the current frame (with a little margin). */
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (p = __stack_limit; p < sp - 16; p++)
        *p = STACK_PAINT;
    sh_exit(main());
}

uint8_t *port_free_ram(size_t *bytes)
{
    *bytes = (size_t)(__free_ram_end - __free_ram_start);
    return __free_ram_start;
}

size_t port_stack_size(void)
{
    return (size_t)((uint8_t *)__stack_top - (uint8_t *)__stack_limit);
}

size_t port_stack_high_water(void)
{
    const uint32_t *p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT)
        p++;
    return (size_t)((const uint8_t *)__stack_top - (const uint8_t *)p);
}

size_t port_static_ram(void)
{
    return (size_t)((uint8_t *)&__data_end - (uint8_t *)&__data_start) +
           (size_t)((uint8_t *)&__bss_end - (uint8_t *)&__bss_start);
}

/* newlib's memcpy etc. may reference these when linked with -nostartfiles. */
void _init(void) {}
void _fini(void) {}
