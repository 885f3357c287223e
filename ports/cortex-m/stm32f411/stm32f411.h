/* SPDX-License-Identifier: MIT */
/*
 * The few STM32F411 registers the example uses (RM0383, STM32F411xC/E
 * reference manual; addresses and bits from its memory map and register
 * descriptions). Plain volatile pointers, CMSIS-style names.
 */
#ifndef ZSPAN_STM32F411_H
#define ZSPAN_STM32F411_H

#include <stdint.h>

#define REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* Flash interface (0x4002 3C00) */
#define FLASH_ACR REG32(0x40023C00u)
#define FLASH_ACR_LATENCY_2WS 2u
#define FLASH_ACR_PRFTEN (1u << 8)
#define FLASH_ACR_ICEN (1u << 9)
#define FLASH_ACR_DCEN (1u << 10)

/* RCC (0x4002 3800) */
#define RCC_BASE 0x40023800u
#define RCC_CR REG32(RCC_BASE + 0x00u)
#define RCC_PLLCFGR REG32(RCC_BASE + 0x04u)
#define RCC_CFGR REG32(RCC_BASE + 0x08u)
#define RCC_AHB1ENR REG32(RCC_BASE + 0x30u)
#define RCC_APB2ENR REG32(RCC_BASE + 0x44u)
#define RCC_CR_HSION (1u << 0)
#define RCC_CR_HSIRDY (1u << 1)
#define RCC_CR_PLLON (1u << 24)
#define RCC_CR_PLLRDY (1u << 25)
#define RCC_PLLCFGR_PLLM_POS 0    /* 6 bits, VCO input = source / M (1..2 MHz) */
#define RCC_PLLCFGR_PLLN_POS 6    /* 9 bits, VCO = input * N (100..432 MHz) */
#define RCC_PLLCFGR_PLLP_POS 16   /* 2 bits: 00 /2, 01 /4, 10 /6, 11 /8 */
#define RCC_PLLCFGR_PLLSRC_HSE (1u << 22)
#define RCC_PLLCFGR_PLLQ_POS 24   /* 4 bits, USB clock = VCO / Q */
#define RCC_CFGR_SW_PLL 2u        /* bits 1:0 */
#define RCC_CFGR_SWS_MASK (3u << 2)
#define RCC_CFGR_SWS_PLL (2u << 2)
#define RCC_CFGR_PPRE1_DIV2 (4u << 10) /* APB1 <= 50 MHz */
#define RCC_AHB1ENR_GPIOAEN (1u << 0)
#define RCC_AHB1ENR_DMA2EN (1u << 22)
#define RCC_APB2ENR_SPI1EN (1u << 12)

/* GPIOA (0x4002 0000) */
#define GPIOA_BASE 0x40020000u
#define GPIOA_MODER REG32(GPIOA_BASE + 0x00u)
#define GPIOA_OSPEEDR REG32(GPIOA_BASE + 0x08u)
#define GPIOA_BSRR REG32(GPIOA_BASE + 0x18u)
#define GPIOA_AFRL REG32(GPIOA_BASE + 0x20u)

/* SPI1 (0x4001 3000, APB2) */
#define SPI1_BASE 0x40013000u
#define SPI1_CR1 REG32(SPI1_BASE + 0x00u)
#define SPI1_CR2 REG32(SPI1_BASE + 0x04u)
#define SPI1_SR REG32(SPI1_BASE + 0x08u)
#define SPI1_DR_ADDR (SPI1_BASE + 0x0Cu)
#define SPI1_DR8 (*(volatile uint8_t *)(uintptr_t)SPI1_DR_ADDR)
#define SPI_CR1_CPHA (1u << 0)
#define SPI_CR1_CPOL (1u << 1)
#define SPI_CR1_MSTR (1u << 2)
#define SPI_CR1_BR_POS 3          /* 3 bits: fPCLK / 2^(BR+1) */
#define SPI_CR1_SPE (1u << 6)
#define SPI_CR1_SSI (1u << 8)
#define SPI_CR1_SSM (1u << 9)
#define SPI_CR2_TXDMAEN (1u << 1)
#define SPI_SR_TXE (1u << 1)
#define SPI_SR_BSY (1u << 7)

/* DMA2 (0x4002 6400). SPI1_TX is DMA2 stream 3, channel 3. */
#define DMA2_BASE 0x40026400u
#define DMA2_LISR REG32(DMA2_BASE + 0x00u)
#define DMA2_LIFCR REG32(DMA2_BASE + 0x08u)
#define DMA2_SxCR(x) REG32(DMA2_BASE + 0x10u + 0x18u * (x))
#define DMA2_SxNDTR(x) REG32(DMA2_BASE + 0x14u + 0x18u * (x))
#define DMA2_SxPAR(x) REG32(DMA2_BASE + 0x18u + 0x18u * (x))
#define DMA2_SxM0AR(x) REG32(DMA2_BASE + 0x1Cu + 0x18u * (x))
#define DMA2_SxFCR(x) REG32(DMA2_BASE + 0x24u + 0x18u * (x))
#define DMA_SxCR_EN (1u << 0)
#define DMA_SxCR_TEIE (1u << 2)
#define DMA_SxCR_TCIE (1u << 4)
#define DMA_SxCR_DIR_M2P (1u << 6)
#define DMA_SxCR_MINC (1u << 10)
#define DMA_SxCR_PL_HIGH (2u << 16)
#define DMA_SxCR_CHSEL_POS 25
/* Stream 3 flags in LISR / LIFCR */
#define DMA_S3_FEIF (1u << 22)
#define DMA_S3_DMEIF (1u << 24)
#define DMA_S3_TEIF (1u << 25)
#define DMA_S3_HTIF (1u << 26)
#define DMA_S3_TCIF (1u << 27)
#define DMA_S3_ALL (DMA_S3_FEIF | DMA_S3_DMEIF | DMA_S3_TEIF | DMA_S3_HTIF | DMA_S3_TCIF)
#define DMA2_STREAM3_IRQN 59u

/* Core peripherals (ARMv7-M) */
#define SYST_CSR REG32(0xE000E010u)
#define SYST_RVR REG32(0xE000E014u)
#define SYST_CVR REG32(0xE000E018u)
#define NVIC_ISER(n) REG32(0xE000E100u + 4u * (n))

#endif
