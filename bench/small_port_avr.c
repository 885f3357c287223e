/* SPDX-License-Identifier: MIT */
/* bench/small_scene.c on the AVR board layer (ports/avr). */
#include "avr_port.h"
#include "small_port.h"

void small_port_init(void)
{
    avr_port_init();
}

void small_mark(int what)
{
    avr_port_mark((uint8_t)what);
}

unsigned long small_static_ram(void)
{
    return avr_port_static_ram();
}

unsigned long small_stack_used(void)
{
    return avr_port_stack_used();
}

void small_port_exit(int status)
{
    avr_port_exit((uint8_t)status);
}
