/* SPDX-License-Identifier: MIT */
/* Reset and vector table of the STM32F411 example (16 system vectors and the
 * 86 interrupts of RM0383's vector table; only SysTick and DMA2 stream 3 are
 * used). */
#include <stdint.h>

extern uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end;
extern uint32_t __stack_top[];

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void SysTick_Handler(void);
void DMA2_Stream3_IRQHandler(void);

static void Default_Handler(void)
{
    for (;;) {
    }
}

typedef void (*vector_fn)(void);

#define N_IRQ 86
__attribute__((section(".isr_vector"), used)) const vector_fn stm32_vectors[16 + N_IRQ] = {
    [0] = (vector_fn)(uintptr_t)__stack_top,
    [1] = Reset_Handler,
    [2] = Default_Handler,   /* NMI */
    [3] = Default_Handler,   /* HardFault */
    [4] = Default_Handler,   /* MemManage */
    [5] = Default_Handler,   /* BusFault */
    [6] = Default_Handler,   /* UsageFault */
    [11] = Default_Handler,  /* SVCall */
    [12] = Default_Handler,  /* DebugMon */
    [14] = Default_Handler,  /* PendSV */
    [15] = SysTick_Handler,
    [16 + 59] = DMA2_Stream3_IRQHandler,
};

void Reset_Handler(void)
{
    uint32_t *src = &__data_load, *dst = &__data_start;
    while (dst < &__data_end)
        *dst++ = *src++;
    for (dst = &__bss_start; dst < &__bss_end;)
        *dst++ = 0;
    (void)main();
    for (;;) {
    }
}

void _init(void) {}
void _fini(void) {}
