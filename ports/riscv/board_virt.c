/* SPDX-License-Identifier: MIT */
/* QEMU virt with RV32 code: the same images with 256 KB of RAM, for the benchmark
 * scenes that do not fit the sifive_e's 16 KB (same instructions, more room). */
#include "port.h"

const port_board port_this_board = {"rv32-virt", "rv32imc code on virt", 16000000u, 1000u};
