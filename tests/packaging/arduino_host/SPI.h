/* SPDX-License-Identifier: MIT */
/* The Arduino SPI API as far as the examples use it (see Arduino.h here). */
#ifndef ZSPAN_TEST_SPI_H
#define ZSPAN_TEST_SPI_H

#include "Arduino.h"

#define MSBFIRST 1
#define SPI_MODE0 0

struct SPISettings {
    SPISettings(uint32_t, int, int) {}
};

struct SPIClass {
    void begin() {}
    void beginTransaction(SPISettings) {}
    void endTransaction() {}
    uint8_t transfer(uint8_t b);
};
extern SPIClass SPI;

#endif
