/* SPDX-License-Identifier: MIT */
/* Registers of the Stellaris LM3S6965 / LM3S811 used by the board port
 * (addresses and bits from the parts' datasheets). */
#ifndef ZSPAN_LM3S_H
#define ZSPAN_LM3S_H

#include <stdint.h>

#define LM3S_REG(a) (*(volatile uint32_t *)(uintptr_t)(a))

/* System control */
#define SYSCTL_BASE 0x400FE000u
#define SYSCTL_RIS LM3S_REG(SYSCTL_BASE + 0x050u)
#define SYSCTL_RCC LM3S_REG(SYSCTL_BASE + 0x060u)
#define SYSCTL_RCGC1 LM3S_REG(SYSCTL_BASE + 0x104u)
#define SYSCTL_RCGC2 LM3S_REG(SYSCTL_BASE + 0x108u)
#define SYSCTL_RIS_PLLLRIS (1u << 6)
#define RCC_MOSCDIS (1u << 0)
#define RCC_OSCSRC_MASK (3u << 4)  /* 0: main oscillator */
#define RCC_XTAL_SHIFT 6           /* 4 bits: the crystal's frequency code */
#define RCC_XTAL_MASK (0xFu << 6)
#define RCC_BYPASS (1u << 11)
#define RCC_PWRDN (1u << 13)
#define RCC_USESYSDIV (1u << 22)
#define RCC_SYSDIV_SHIFT 23        /* 4 bits: 200 MHz PLL / (SYSDIV + 1) */
#define RCC_SYSDIV_MASK (0xFu << 23)
#define RCGC1_SSI0 (1u << 4)
#define RCGC1_I2C0 (1u << 12)
#define RCGC2_GPIO(port) (1u << (port)) /* A = 0, B = 1, ... */

/* GPIO ports (APB): DATA is addressed through a mask in address bits 9..2 */
#define GPIO_BASE(port) (0x40004000u + 0x1000u * (uint32_t)(port))
#define GPIO_PORT_A 0u
#define GPIO_PORT_B 1u
#define GPIO_PORT_C 2u
#define GPIO_PORT_D 3u
#define GPIO_DATA(port, mask) LM3S_REG(GPIO_BASE(port) + ((uint32_t)(mask) << 2))
#define GPIO_DIR(port) LM3S_REG(GPIO_BASE(port) + 0x400u)
#define GPIO_AFSEL(port) LM3S_REG(GPIO_BASE(port) + 0x420u)
#define GPIO_DEN(port) LM3S_REG(GPIO_BASE(port) + 0x51Cu)

/* SSI0 (an ARM PL022) */
#define SSI0_BASE 0x40008000u
#define SSI_CR0 LM3S_REG(SSI0_BASE + 0x000u)
#define SSI_CR1 LM3S_REG(SSI0_BASE + 0x004u)
#define SSI_DR LM3S_REG(SSI0_BASE + 0x008u)
#define SSI_SR LM3S_REG(SSI0_BASE + 0x00Cu)
#define SSI_CPSR LM3S_REG(SSI0_BASE + 0x010u)
#define SSI_CR0_DSS_8 0x7u         /* 8-bit frames */
#define SSI_CR0_SPO (1u << 6)      /* clock idles high */
#define SSI_CR0_SPH (1u << 7)      /* data on the second edge */
#define SSI_CR0_SCR_SHIFT 8
#define SSI_CR1_SSE (1u << 1)      /* enable */
#define SSI_SR_TFE (1u << 0)       /* transmit FIFO empty */
#define SSI_SR_TNF (1u << 1)       /* transmit FIFO not full */
#define SSI_SR_RNE (1u << 2)       /* receive FIFO not empty */
#define SSI_SR_BSY (1u << 4)

/* I2C0 master */
#define I2C0_BASE 0x40020000u
#define I2C_MSA LM3S_REG(I2C0_BASE + 0x000u)
#define I2C_MCS LM3S_REG(I2C0_BASE + 0x004u)
#define I2C_MDR LM3S_REG(I2C0_BASE + 0x008u)
#define I2C_MTPR LM3S_REG(I2C0_BASE + 0x00Cu)
#define I2C_MCR LM3S_REG(I2C0_BASE + 0x020u)
#define I2C_MCR_MFE (1u << 4)      /* master function enable */
/* MCS written: the next step */
#define I2C_MCS_RUN (1u << 0)
#define I2C_MCS_START (1u << 1)
#define I2C_MCS_STOP (1u << 2)
/* MCS read: the state */
#define I2C_MCS_BUSY (1u << 0)
#define I2C_MCS_ERROR (1u << 1)
#define I2C_MCS_ADRACK (1u << 2)   /* the address was not acknowledged */
#define I2C_MCS_DATACK (1u << 3)   /* a data byte was not acknowledged */
#define I2C_MCS_ARBLST (1u << 4)

#endif
