/* SPDX-License-Identifier: MIT */
/* QEMU sifive_e (SiFive E31-class RV32IMAC, 16 KB RAM): one tick = one instruction. */
#include "port.h"

const port_board port_this_board = {"sifive_e", "rv32imc", 16000000u, 1000u};
