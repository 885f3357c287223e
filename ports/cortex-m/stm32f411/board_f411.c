/* SPDX-License-Identifier: MIT */
/*
 * Board layer of the STM32F411 ("Black Pill" STM32F411CEU6 or Nucleo-F411RE)
 * with an SPI panel on SPI1 + DMA2 stream 3 (see board_f411.h); the example
 * application is examples/stm32f411-st7789/.
 *
 * Wiring (3.3 V):  PA5 SPI1_SCK -> SCL,  PA7 SPI1_MOSI -> SDA,
 *                  PA4 -> CS,  PA3 -> DC,  PA2 -> RES,  PA1 -> BLK (backlight)
 *
 * Clock: HSI 16 MHz -> PLL (M 16, N 336, P 4, Q 7) -> 84 MHz SYSCLK,
 * APB2 84 MHz so SPI1 runs at 42 MHz (BR = /2), APB1 42 MHz, flash 2 wait
 * states. SysTick 1 kHz for the panel's delays.
 */
#include "board_f411.h"

#include "spi_dma_port.h"
#include "stm32f411.h"
#define PIN_BL 1u
#define PIN_RST 2u
#define PIN_DC 3u
#define PIN_CS 4u

static volatile uint32_t ms_ticks;
static spi_dma_port port;
static zs_bus bus;

void SysTick_Handler(void)
{
    ms_ticks++;
}

static void pin(uint32_t n, int high)
{
    GPIOA_BSRR = high ? (1u << n) : (1u << (n + 16u));
}

static void hw_cs(int selected) { pin(PIN_CS, !selected); }
static void hw_dc(int data) { pin(PIN_DC, data); }
static void hw_reset(int level) { pin(PIN_RST, level); }
static void hw_backlight(uint8_t level) { pin(PIN_BL, level != 0); }

static void hw_drain(void)
{
    while (!(SPI1_SR & SPI_SR_TXE)) {
    }
    while (SPI1_SR & SPI_SR_BSY) {
    }
}

static void hw_spi_write(const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        while (!(SPI1_SR & SPI_SR_TXE)) {
        }
        SPI1_DR8 = p[i];
    }
    hw_drain();
}

static void hw_dma_start(const uint8_t *p, size_t n)
{
    DMA2_SxCR(3) = 0; /* EN = 0; it is already off after the last transfer */
    while (DMA2_SxCR(3) & DMA_SxCR_EN) {
    }
    DMA2_LIFCR = DMA_S3_ALL;
    DMA2_SxPAR(3) = SPI1_DR_ADDR;
    DMA2_SxM0AR(3) = (uint32_t)(uintptr_t)p;
    DMA2_SxNDTR(3) = (uint32_t)n; /* bytes: 8-bit memory and peripheral sizes */
    DMA2_SxFCR(3) = 0;            /* direct mode */
    DMA2_SxCR(3) = (3u << DMA_SxCR_CHSEL_POS) | DMA_SxCR_PL_HIGH | DMA_SxCR_MINC |
                   DMA_SxCR_DIR_M2P | DMA_SxCR_TCIE | DMA_SxCR_TEIE | DMA_SxCR_EN;
}

static void hw_delay_ms(uint32_t ms)
{
    uint32_t start = ms_ticks;
    while (ms_ticks - start < ms) {
        __asm__ volatile("wfi");
    }
}

void DMA2_Stream3_IRQHandler(void)
{
    uint32_t flags = DMA2_LISR & DMA_S3_ALL;
    DMA2_LIFCR = flags;
    if (flags & (DMA_S3_TCIF | DMA_S3_TEIF))
        spi_dma_port_irq(&port);
}

static const spi_dma_hw f411_hw = {
    hw_cs, hw_dc, hw_reset, hw_backlight, hw_spi_write, hw_dma_start, hw_drain,
    hw_delay_ms, NULL, 65535u,
};

static void clock_init(void)
{
    RCC_CR |= RCC_CR_HSION;
    while (!(RCC_CR & RCC_CR_HSIRDY)) {
    }
    FLASH_ACR = FLASH_ACR_LATENCY_2WS | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    RCC_PLLCFGR = (16u << RCC_PLLCFGR_PLLM_POS) | (336u << RCC_PLLCFGR_PLLN_POS) |
                  (1u << RCC_PLLCFGR_PLLP_POS) | (7u << RCC_PLLCFGR_PLLQ_POS);
    RCC_CR |= RCC_CR_PLLON;
    while (!(RCC_CR & RCC_CR_PLLRDY)) {
    }
    RCC_CFGR = RCC_CFGR_PPRE1_DIV2 | RCC_CFGR_SW_PLL;
    while ((RCC_CFGR & RCC_CFGR_SWS_MASK) != RCC_CFGR_SWS_PLL) {
    }
    SYST_RVR = 84000u - 1u; /* 1 kHz */
    SYST_CVR = 0;
    SYST_CSR = 7u;
}

static void spi_init(void)
{
    uint32_t moder;
    RCC_AHB1ENR |= RCC_AHB1ENR_GPIOAEN | RCC_AHB1ENR_DMA2EN;
    RCC_APB2ENR |= RCC_APB2ENR_SPI1EN;
    /* PA1..PA4 outputs, PA5 and PA7 alternate function 5 (SPI1). */
    moder = GPIOA_MODER;
    moder &= ~((3u << 2) | (3u << 4) | (3u << 6) | (3u << 8) | (3u << 10) | (3u << 14));
    moder |= (1u << 2) | (1u << 4) | (1u << 6) | (1u << 8) | (2u << 10) | (2u << 14);
    GPIOA_MODER = moder;
    GPIOA_OSPEEDR |= (3u << 10) | (3u << 14) | (3u << 6) | (3u << 8);
    GPIOA_AFRL = (GPIOA_AFRL & ~((15u << 20) | (15u << 28))) | (5u << 20) | (5u << 28);
    pin(PIN_CS, 1);
    pin(PIN_RST, 1);
    /* Master, mode 3 (CPOL 1, CPHA 1: what CS-less ST7789 modules need; fine
     * with CS too), fPCLK/2 = 42 MHz, software NSS, 8-bit, TX DMA. */
    SPI1_CR1 = SPI_CR1_MSTR | SPI_CR1_CPOL | SPI_CR1_CPHA | (0u << SPI_CR1_BR_POS) |
               SPI_CR1_SSM | SPI_CR1_SSI;
    SPI1_CR2 = SPI_CR2_TXDMAEN;
    SPI1_CR1 |= SPI_CR1_SPE;
    NVIC_ISER(DMA2_STREAM3_IRQN / 32u) = 1u << (DMA2_STREAM3_IRQN % 32u);
}

zs_bus *port_f411_bus(void)
{
    clock_init();
    spi_init();
    return spi_dma_port_init(&port, &f411_hw, &bus) == ZS_BUS_OK ? &bus : NULL;
}
