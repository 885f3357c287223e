/* SPDX-License-Identifier: MIT */
/* What bench/small_scene.c needs from a board (bench/small_port_*.c adapt a port). */
#ifndef ZSPAN_SMALL_PORT_H
#define ZSPAN_SMALL_PORT_H

#include <stddef.h>

void small_port_init(void);           /* stdout ready */
void small_mark(int what);            /* 1 begin, 2 end of a frame; 3/4 pause/resume */
unsigned long small_static_ram(void); /* .data + .bss bytes (0 where unknown) */
unsigned long small_stack_used(void); /* stack high-water bytes (0 where unknown) */
void small_port_exit(int status);     /* ends the program (returns on the host) */

#endif
