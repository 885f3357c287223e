/* SPDX-License-Identifier: MIT */
/*
 * The few Arduino calls the examples use, on the host, for the packaging test:
 * examples/arduino/SpinningCubeST7789 built with g++ against this file drives
 * an emulated ST7789 (host_sim/emu) directly, giving the picture the AVR
 * build under simavr must show (tests/packaging/avr_st7789.c). Not an Arduino
 * core: pins, SPI and time only as far as the example needs them.
 */
#ifndef ZSPAN_TEST_ARDUINO_H
#define ZSPAN_TEST_ARDUINO_H

#include <stddef.h>
#include <stdint.h>

#define HIGH 1
#define LOW 0
#define OUTPUT 1
#define F(s) (s)

void pinMode(int pin, int mode);
void digitalWrite(int pin, int level);
void delay(unsigned long ms);
unsigned long millis(void);

struct HardwareSerial {
    void begin(long) {}
    template <class T> void print(T) {}
    template <class T> void println(T) {}
};
extern HardwareSerial Serial;

void setup(void);
void loop(void);

#endif
