/* SPDX-License-Identifier: MIT */
/* bench/small_scene.c on the host: the reference checksums. */
#include "small_port.h"

void small_port_init(void)
{
}

void small_mark(int what)
{
    (void)what;
}

unsigned long small_static_ram(void)
{
    return 0;
}

unsigned long small_stack_used(void)
{
    return 0;
}

void small_port_exit(int status)
{
    (void)status;
}
