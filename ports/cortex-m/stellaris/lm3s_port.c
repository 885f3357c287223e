/* SPDX-License-Identifier: MIT */
/* Stellaris LM3S board port: clocks, GPIO, polled SSI0 and I2C0 buses
 * (see lm3s_port.h). */
#include "lm3s_port.h"

#include "lm3s.h"

#define FNV_PRIME 0x01000193u
#define DEFAULT_WAIT_LIMIT 200000u
#define I2C_MAX_FRAME 64u

/* OLED lines of the LM3S6965 evaluation board */
#define OLED_CS_PORT GPIO_PORT_D
#define OLED_CS_PIN (1u << 0)
#define OLED_DC_PORT GPIO_PORT_C
#define OLED_DC_PIN (1u << 7)
#define SSI0_PINS ((1u << 2) | (1u << 3) | (1u << 4) | (1u << 5)) /* port A: CLK FSS RX TX */
#define I2C0_PINS ((1u << 2) | (1u << 3))                         /* port B: SCL SDA */
#define GPIO_ODR(port) LM3S_REG(GPIO_BASE(port) + 0x50Cu)

const char *lm3s_strerror(lm3s_error e)
{
    switch (e) {
    case LM3S_OK: return "ok";
    case LM3S_ERR_SSI_TIMEOUT: return "the SSI never drained its FIFO or stayed busy";
    case LM3S_ERR_I2C_NO_DEVICE: return "nobody acknowledged the I2C address (NACK)";
    case LM3S_ERR_I2C_DATA_NACK: return "the I2C device did not acknowledge a data byte";
    case LM3S_ERR_I2C_ARBITRATION: return "another master took the I2C bus";
    case LM3S_ERR_I2C_TIMEOUT: return "the I2C controller stayed busy past the limit";
    case LM3S_ERR_TOO_LONG: return "a command with more parameters than a frame holds";
    }
    return "unknown port error";
}

static int fail(lm3s_port *p, lm3s_error e)
{
    if (p->error == LM3S_OK)
        p->error = e;
    return -1;
}

static void delay_loop(uint32_t n)
{
    volatile uint32_t i;
    for (i = 0; i < n; i++) {
    }
}

uint32_t lm3s_clock_init(uint32_t xtal_code)
{
    uint32_t rcc = SYSCTL_RCC, n;
    /* run from the oscillator while the PLL is set up (the datasheet's order) */
    rcc = (rcc | RCC_BYPASS) & ~RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    rcc &= ~(RCC_XTAL_MASK | RCC_OSCSRC_MASK | RCC_PWRDN | RCC_MOSCDIS);
    rcc |= (xtal_code << RCC_XTAL_SHIFT) & RCC_XTAL_MASK;
    SYSCTL_RCC = rcc;
    rcc = (rcc & ~RCC_SYSDIV_MASK) | (3u << RCC_SYSDIV_SHIFT) | RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    for (n = 0; n < 100000u && !(SYSCTL_RIS & SYSCTL_RIS_PLLLRIS); n++) {
    }
    SYSCTL_RCC = rcc & ~RCC_BYPASS; /* lock or not: the PLL's 50 MHz from here */
    return 50000000u;
}

/* ---- SSI0: 4-wire SPI to the SSD0323 ---- */

/* Waits until every byte has left the shifter (D/C may change then), and
 * throws away what came back. */
static int ssi_drain(lm3s_port *p)
{
    uint32_t n = 0;
    while ((SSI_SR & (SSI_SR_TFE | SSI_SR_BSY)) != SSI_SR_TFE || (SSI_SR & SSI_SR_RNE)) {
        while (SSI_SR & SSI_SR_RNE)
            (void)SSI_DR;
        if (++n > p->wait_limit)
            return fail(p, LM3S_ERR_SSI_TIMEOUT);
    }
    return 0;
}

static int ssi_send(lm3s_port *p, int dc, const uint8_t *d, size_t len)
{
    size_t i;
    if (ssi_drain(p) != 0)
        return -1;
    GPIO_DATA(OLED_DC_PORT, OLED_DC_PIN) = dc ? OLED_DC_PIN : 0u;
    for (i = 0; i < len; i++) {
        uint32_t n = 0;
        while (!(SSI_SR & SSI_SR_TNF)) {
            while (SSI_SR & SSI_SR_RNE) /* a full receive FIFO would stall the transmitter */
                (void)SSI_DR;
            if (++n > p->wait_limit)
                return fail(p, LM3S_ERR_SSI_TIMEOUT);
        }
        SSI_DR = d[i];
        while (SSI_SR & SSI_SR_RNE)
            (void)SSI_DR;
        p->stream = (((p->stream ^ (uint32_t)(dc ? 1u : 0u)) * FNV_PRIME) ^ d[i]) * FNV_PRIME;
    }
    return ssi_drain(p);
}

static int ssi_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    lm3s_port *p = user;
    p->transactions++;
    if (ssi_send(p, 0, &cmd, 1) != 0)
        return -1;
    return n ? ssi_send(p, 1, params, n) : 0;
}

static int ssi_pixels(void *user, const uint8_t *data, size_t n)
{
    lm3s_port *p = user;
    p->transactions++;
    return ssi_send(p, 1, data, n);
}

static void port_delay(void *user, uint32_t ms)
{
    (void)user;
    delay_loop(ms * 5000u); /* about 1 ms at 50 MHz; the panels only need at least */
}

static const zs_bus_ops ssi_ops = {
    .command = ssi_command,
    .pixels = ssi_pixels,
    .reset = NULL,
    .backlight = NULL,
    .delay_ms = port_delay,
    .poll = NULL,
};

static void port_clear(lm3s_port *p)
{
    p->error = LM3S_OK;
    p->wait_limit = DEFAULT_WAIT_LIMIT;
    p->stream = 0x811C9DC5u;
    p->transactions = 0;
}

int lm3s_ssi_oled_init(lm3s_port *p, uint32_t sys_hz, uint32_t spi_hz)
{
    uint32_t scr;
    port_clear(p);
    SYSCTL_RCGC1 |= RCGC1_SSI0;
    SYSCTL_RCGC2 |= RCGC2_GPIO(GPIO_PORT_A) | RCGC2_GPIO(GPIO_PORT_C) | RCGC2_GPIO(GPIO_PORT_D);
    delay_loop(16); /* a few clocks before the ports answer */
    GPIO_AFSEL(GPIO_PORT_A) |= SSI0_PINS;
    GPIO_DEN(GPIO_PORT_A) |= SSI0_PINS;
    GPIO_DIR(OLED_DC_PORT) |= OLED_DC_PIN;
    GPIO_DEN(OLED_DC_PORT) |= OLED_DC_PIN;
    GPIO_DIR(OLED_CS_PORT) |= OLED_CS_PIN;
    GPIO_DEN(OLED_CS_PORT) |= OLED_CS_PIN;
    /* QEMU's board routes SSI0 to the OLED while port D pin 0 is high (low:
     * the SD card slot) */
    GPIO_DATA(OLED_CS_PORT, OLED_CS_PIN) = OLED_CS_PIN;
    /* master, Freescale SPI mode 3, 8-bit frames; clock sys / (2 (1 + SCR)) */
    SSI_CR1 = 0;
    SSI_CPSR = 2;
    scr = spi_hz ? (sys_hz / 2u + spi_hz - 1u) / spi_hz : 256u;
    scr = scr < 1u ? 0u : scr - 1u;
    if (scr > 255u)
        scr = 255u;
    SSI_CR0 = (scr << SSI_CR0_SCR_SHIFT) | SSI_CR0_SPH | SSI_CR0_SPO | SSI_CR0_DSS_8;
    SSI_CR1 = SSI_CR1_SSE;
    return zs_bus_init(&p->bus, &ssi_ops, p, 0, 0) == ZS_BUS_OK ? 0 : -1;
}

/* ---- I2C0 master to the SSD0303 ---- */

/* One step of the master (MCS command), then its outcome. first: the
 * address phase (an error there means nobody answered). */
static int i2c_step(lm3s_port *p, uint8_t byte, uint32_t mcs, int first)
{
    uint32_t n = 0, st;
    I2C_MDR = byte;
    I2C_MCS = mcs;
    while ((st = I2C_MCS) & I2C_MCS_BUSY)
        if (++n > p->wait_limit) {
            I2C_MCS = I2C_MCS_STOP;
            return fail(p, LM3S_ERR_I2C_TIMEOUT);
        }
    if (st & I2C_MCS_ERROR) {
        if (!(st & I2C_MCS_ARBLST) || first) /* QEMU reports a missing device as lost */
            I2C_MCS = I2C_MCS_STOP;          /* release the bus */
        if (first || (st & I2C_MCS_ADRACK))
            return fail(p, LM3S_ERR_I2C_NO_DEVICE);
        return fail(p, (st & I2C_MCS_ARBLST) ? LM3S_ERR_I2C_ARBITRATION : LM3S_ERR_I2C_DATA_NACK);
    }
    return 0;
}

/* A write transaction of len bytes (len >= 1) to the display. */
static int i2c_write(lm3s_port *p, const uint8_t *d, size_t len)
{
    size_t i;
    p->transactions++;
    p->stream = (p->stream ^ (uint8_t)(p->i2c_addr << 1)) * FNV_PRIME;
    for (i = 0; i < len; i++)
        p->stream = (p->stream ^ d[i]) * FNV_PRIME;
    I2C_MSA = (uint32_t)p->i2c_addr << 1; /* bit 0 clear: write */
    for (i = 0; i < len; i++) {
        uint32_t mcs = I2C_MCS_RUN;
        if (i == 0)
            mcs |= I2C_MCS_START;
        if (i + 1 == len)
            mcs |= I2C_MCS_STOP;
        if (i2c_step(p, d[i], mcs, i == 0) != 0)
            return -1;
    }
    return 0;
}

static int i2c_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    lm3s_port *p = user;
    uint8_t frame[2u * (1u + I2C_MAX_FRAME / 2u)];
    size_t i;
    if (n > I2C_MAX_FRAME / 2u)
        return fail(p, LM3S_ERR_TOO_LONG);
    frame[0] = 0x80; /* Co = 1, D/C# = 0: one command byte, then another control byte */
    frame[1] = cmd;
    for (i = 0; i < n; i++) {
        frame[2 + 2 * i] = 0x80;
        frame[3 + 2 * i] = params[i];
    }
    return i2c_write(p, frame, 2u * (1u + n));
}

static int i2c_pixels(void *user, const uint8_t *data, size_t n)
{
    lm3s_port *p = user;
    uint8_t frame[1u + I2C_MAX_FRAME];
    while (n > 0) {
        size_t k = n < I2C_MAX_FRAME ? n : I2C_MAX_FRAME, i;
        frame[0] = 0x40; /* Co = 0, D/C# = 1: data to the stop */
        for (i = 0; i < k; i++)
            frame[1 + i] = data[i];
        if (i2c_write(p, frame, k + 1u) != 0)
            return -1;
        data += k;
        n -= k;
    }
    return 0;
}

static const zs_bus_ops i2c_ops = {
    .command = i2c_command,
    .pixels = i2c_pixels,
    .reset = NULL,
    .backlight = NULL,
    .delay_ms = port_delay,
    .poll = NULL,
};

int lm3s_i2c_oled_init(lm3s_port *p, uint32_t sys_hz, uint8_t addr)
{
    uint32_t tpr;
    port_clear(p);
    p->i2c_addr = addr;
    SYSCTL_RCGC1 |= RCGC1_I2C0;
    SYSCTL_RCGC2 |= RCGC2_GPIO(GPIO_PORT_B);
    delay_loop(16);
    GPIO_AFSEL(GPIO_PORT_B) |= I2C0_PINS;
    GPIO_DEN(GPIO_PORT_B) |= I2C0_PINS;
    GPIO_ODR(GPIO_PORT_B) |= 1u << 3; /* SDA open drain */
    I2C_MCR = I2C_MCR_MFE;
    /* SCL = sys / (20 (1 + TPR)): 100 kHz */
    tpr = sys_hz / (20u * 100000u);
    I2C_MTPR = tpr ? tpr - 1u : 0u;
    return zs_bus_init(&p->bus, &i2c_ops, p, 0, 0) == ZS_BUS_OK ? 0 : -1;
}
