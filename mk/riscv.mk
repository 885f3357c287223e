# SPDX-License-Identifier: MIT
# mk/riscv.mk: the RISC-V target, RV32IMC code on QEMU's sifive_e machine (16 KB RAM,
# like an ESP32-C3-class part), built with Debian's gcc-riscv64-unknown-elf and picolibc.
# The benchmark image is bench/bench_fw.c on the board layer of ports/riscv/ (the same
# interface as ports/cortex-m/port.h); instructions are counted by minstret, exact
# under qemu -icount shift=0. See README.md (Building zspan into your project).
#
#   build/rv/bench-sifive_e.elf   benchmark image (core at -O2, like the Cortex-M4's)
#   make test-riscv               frame 0 of sphere285, both modes: checksums == host's
#                                 (TEST_TARGETS, part of make test)
#   build/rv/bench-rv32code-virt.elf  the same code on QEMU virt (256 KB RAM): the scenes
#                                 that do not fit 16 KB, counted the same way
#   make bench-riscv              every scene, 10 frames, both modes, on both machines;
#                                 instructions per frame and RAM -> bench/results-riscv.md
#                                 (BENCH_TARGETS)

DEB_PACKAGES += gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc

comma := ,
RV_PREFIX ?= riscv64-unknown-elf-
RV_CC := $(RV_PREFIX)gcc
RV_SIZE := $(RV_PREFIX)size
RV_QEMU ?= qemu-system-riscv32
RV_QEMU_FLAGS := -M sifive_e -nographic -monitor none -serial none -icount shift=0 \
                 -semihosting-config enable=on,target=native
RV_BUILD := $(BUILD)/rv
# Compiled for RV32IMC (zicsr for the counter reads); linked with the rv32imac
# multilib of picolibc (there is no rv32imc one; the A extension is never used).
RV_ARCH := -march=rv32imc_zicsr -mabi=ilp32
RV_LINK_ARCH := -march=rv32imac -mabi=ilp32
RV_COMMON := --specs=picolibc.specs $(RV_ARCH) -std=c99 -ffreestanding $(CORE_REQUIRED_FLAGS) \
             -Wall -Wextra -Werror -ffunction-sections -fdata-sections -Iinclude
RV_LDFLAGS := --specs=picolibc.specs --oslib=semihost --crt0=semihost $(RV_LINK_ARCH) \
              -Wl,--gc-sections -Wl,--defsym=__flash=0x20400000 -Wl,--defsym=__flash_size=0x1000000 \
              -Wl,--defsym=__ram=0x80000000 -Wl,--defsym=__ram_size=0x4000 \
              -Wl,--defsym=__stack_size=0x800
RV_PORT := ports/riscv
RV_CORE_OBJS := $(patsubst src/%.c,$(RV_BUILD)/core/%.o,$(CORE_SRCS))
RV_APP_SRCS := $(RV_PORT)/port_riscv.c $(RV_PORT)/board_sifive_e.c bench/bench_scenes.c \
               bench/bench_fw.c $(BENCH_GEN_SRCS)
RV_APP_OBJS := $(patsubst %.c,$(RV_BUILD)/app/%.o,$(RV_APP_SRCS))
RV_BENCH := $(RV_BUILD)/bench-sifive_e.elf
RV_BENCH_BIG := $(RV_BUILD)/bench-rv32code-virt.elf
RV_BIG_QEMU_FLAGS := -M virt -bios none -nographic -monitor none -serial none -icount shift=0 \
                     -semihosting-config enable=on,target=native
RV_BIG_LDFLAGS := $(filter-out -Wl$(comma)--defsym=__%,$(RV_LDFLAGS)) \
                  -Wl,--defsym=__flash=0x80000000 -Wl,--defsym=__flash_size=0x100000 \
                  -Wl,--defsym=__ram=0x80100000 -Wl,--defsym=__ram_size=0x40000 \
                  -Wl,--defsym=__stack_size=0x800

ALL_TARGETS += $(RV_BENCH) $(RV_BENCH_BIG)
TEST_TARGETS += test-riscv
BENCH_TARGETS += bench-riscv
.PHONY: test-riscv bench-riscv

$(RV_BUILD)/core/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(RV_CC) $(RV_COMMON) -O2 -Wconversion -MMD -MP -c $< -o $@
# Only the benchmark's sources see its headers; the port sees its own directory.
$(RV_BUILD)/app/%.o: %.c $(RV_PORT)/port.h bench/bench_scenes.h $(BENCH_GEN)/bench_caps.h \
                     $(BENCH_GEN_HDRS) | deps
	@mkdir -p $(@D)
	$(RV_CC) $(RV_COMMON) -O2 -I$(RV_PORT) $(if $(filter bench/% $(BENCH_GEN)/%,$<),-Ibench -I$(BENCH_GEN)) \
	    -MMD -MP -c $< -o $@
$(RV_BENCH): $(RV_APP_OBJS) $(RV_CORE_OBJS)
	$(RV_CC) $(RV_LDFLAGS) -o $@ $^
$(RV_BENCH_BIG): $(filter-out %/board_sifive_e.o,$(RV_APP_OBJS)) $(RV_BUILD)/app/$(RV_PORT)/board_virt.o \
                 $(RV_CORE_OBJS)
	$(RV_CC) $(RV_BIG_LDFLAGS) -o $@ $^

# The host's checksums of the same frames (bench_host) against the image's.
test-riscv: $(RV_BENCH) $(BENCH_HOST) | deps
	@RV_QEMU='$(RV_QEMU)' RV_QEMU_FLAGS='$(RV_QEMU_FLAGS)' BENCH_HOST=$(BENCH_HOST) \
	    bash tests/packaging/run_riscv.sh quick $(RV_BENCH)

bench-riscv: $(RV_BENCH) $(RV_BENCH_BIG) $(BENCH_HOST) $(RV_CORE_OBJS) | deps
	@RV_QEMU='$(RV_QEMU)' RV_QEMU_FLAGS='$(RV_QEMU_FLAGS)' BENCH_HOST=$(BENCH_HOST) \
	    RV_BIG_IMAGE=$(RV_BENCH_BIG) RV_BIG_QEMU_FLAGS='$(RV_BIG_QEMU_FLAGS)' \
	    RV_SIZE=$(RV_SIZE) RV_CORE_OBJS='$(RV_CORE_OBJS)' BENCH_WORK=$(BENCH_BUILD)/run-riscv \
	    bash tests/packaging/run_riscv.sh bench $(RV_BENCH)
