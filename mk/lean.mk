# SPDX-License-Identifier: MIT
# mk/lean.mk: the lean configuration (-DZS_LEAN, include/zspan/zspan.h: flat
# and lit faces, span mode, RGB565; no texture, A-buffer, z-buffer line,
# Warnock, list priority, Gouraud/fog, 1-bit output or other byte formats)
# and the core's linked flash footprint on Cortex-M0 (-Os).
#
#   build/fw/lean-microbit.elf          bench/bench_lean_fw.c on the core built -DZS_LEAN
#   build/fw/lean-m0code-mps2-an386.elf the same objects on the M4 board's RAM (all scenes)
#   build/fw/lean-full-microbit.elf     the same program on the full core (for comparison)
#   build/fw/lean-unlit-microbit.elf    the same on the core built -DZS_LEAN -DZS_NO_LIGHTING
#   build/tests/lean/lean_frames{,_full}  tests/lean/lean_frames.c on a host core built
#                                       -DZS_LEAN and on the full one
#   make check-lean (TEST_TARGETS)      bench/run_lean.sh: the lean objects call no left-out
#                                       stage; the lean image links none of their code; its
#                                       frames match the host's bench checksums; the host lean
#                                       core refuses every left-out feature and renders what
#                                       it supports byte for byte as the full core; writes
#                                       the Flash figures (build/fw/lean/flash.md, which
#                                       make bench puts in bench/results.md)

LEAN_BUILD := $(FW_BUILD)/lean
LEAN_CORE_OBJS := $(patsubst src/%.c,$(LEAN_BUILD)/core/%.o,$(CORE_SRCS))
LEAN_UNLIT_OBJS := $(patsubst src/%.c,$(LEAN_BUILD)/unlit/%.o,$(CORE_SRCS))
# The stages ZS_LEAN leaves out (their objects must not be called or linked).
LEAN_OFF := abuffer texture zline warnock priority depth_sort bsp painter mono lines gray4
LEAN_APP_SRCS := $(PORT_SRCS) bench/bench_scenes.c bench/bench_lean_fw.c $(BENCH_GEN_SRCS)
LEAN_APP_OBJS := $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(LEAN_APP_SRCS))
FW_LEAN_M0 := $(FW_BUILD)/lean-microbit.elf
FW_LEAN_M0BIG := $(FW_BUILD)/lean-m0code-mps2-an386.elf
FW_LEAN_FULL := $(FW_BUILD)/lean-full-microbit.elf
FW_LEAN_UNLIT := $(FW_BUILD)/lean-unlit-microbit.elf
LEAN_FLASH_MD := $(LEAN_BUILD)/flash.md
LEAN_HOST := $(BUILD)/tests/lean/lean_frames
LEAN_HOST_FULL := $(BUILD)/tests/lean/lean_frames_full
LEAN_HOST_UNLIT := $(BUILD)/tests/lean/lean_frames_unlit

ALL_TARGETS += $(FW_LEAN_M0) $(FW_LEAN_M0BIG) $(FW_LEAN_FULL) $(FW_LEAN_UNLIT)
TEST_TARGETS += check-lean
.PHONY: check-lean

$(LEAN_BUILD)/core/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) $(FW_M0_OPT) $(FW_COMMON) -Wconversion -DZS_LEAN -MMD -MP -c $< -o $@
$(LEAN_BUILD)/unlit/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) $(FW_M0_OPT) $(FW_COMMON) -Wconversion -DZS_LEAN -DZS_NO_LIGHTING \
	    -MMD -MP -c $< -o $@

$(FW_LEAN_M0): $(LEAN_APP_OBJS) $(FW_BUILD)/m0/app/$(PORT_DIR)/board_microbit.o \
               $(LEAN_CORE_OBJS) $(PORT_DIR)/ld/microbit.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/microbit.ld \
	    -Wl,-Map,$(@:.elf=.map) -o $@ $(filter %.o,$^) $(FW_LIBS)
$(FW_LEAN_M0BIG): $(LEAN_APP_OBJS) $(FW_BUILD)/m0/app/board_m0code_an386.o \
                  $(LEAN_CORE_OBJS) $(PORT_DIR)/ld/mps2-an386.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS)
$(FW_LEAN_UNLIT): $(LEAN_APP_OBJS) $(FW_BUILD)/m0/app/$(PORT_DIR)/board_microbit.o \
                  $(LEAN_UNLIT_OBJS) $(PORT_DIR)/ld/microbit.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/microbit.ld \
	    -Wl,-Map,$(@:.elf=.map) -o $@ $(filter %.o,$^) $(FW_LIBS)
$(FW_LEAN_FULL): $(LEAN_APP_OBJS) $(FW_BUILD)/m0/app/$(PORT_DIR)/board_microbit.o \
                 $(FW_CORE_M0_OBJS) $(PORT_DIR)/ld/microbit.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/microbit.ld \
	    -Wl,-Map,$(@:.elf=.map) -o $@ $(filter %.o,$^) $(FW_LIBS)

# Host: one program on both cores; the recipe of check-lean compares their frames.
LEAN_HOST_CFLAGS := -std=c99 -Wall -Wextra -Werror -Wconversion -g -O1 $(ASAN_FLAGS) \
                    $(CORE_REQUIRED_FLAGS) -Iinclude
$(LEAN_HOST): tests/lean/lean_frames.c $(CORE_SRCS) $(wildcard src/*.h) include/zspan/zspan.h | deps
	@mkdir -p $(@D)
	$(CC) $(LEAN_HOST_CFLAGS) -DZS_LEAN -ffunction-sections -Wl,--gc-sections -o $@ $< $(CORE_SRCS)
$(LEAN_HOST_UNLIT): tests/lean/lean_frames.c $(CORE_SRCS) $(wildcard src/*.h) include/zspan/zspan.h | deps
	@mkdir -p $(@D)
	$(CC) $(LEAN_HOST_CFLAGS) -DZS_LEAN -DZS_NO_LIGHTING -ffunction-sections -Wl,--gc-sections \
	    -o $@ $< $(CORE_SRCS)
$(LEAN_HOST_FULL): tests/lean/lean_frames.c $(CORE_SRCS) $(wildcard src/*.h) include/zspan/zspan.h | deps
	@mkdir -p $(@D)
	$(CC) $(LEAN_HOST_CFLAGS) -o $@ $< $(CORE_SRCS)

LEAN_RUN = LEAN_OBJS='$(LEAN_CORE_OBJS)' LEAN_OFF='$(LEAN_OFF)' LEAN_DIR=$(LEAN_BUILD) \
    FW_LEAN_M0=$(FW_LEAN_M0) FW_LEAN_M0BIG=$(FW_LEAN_M0BIG) FW_LEAN_FULL=$(FW_LEAN_FULL) \
    FW_LEAN_UNLIT=$(FW_LEAN_UNLIT) LEAN_HOST_UNLIT=$(LEAN_HOST_UNLIT) \
    FW_BENCH_M0=$(FW_BENCH_M0) BENCH_HOST=$(BENCH_HOST) LEAN_HOST=$(LEAN_HOST) \
    LEAN_HOST_FULL=$(LEAN_HOST_FULL) FULL_OBJS='$(FW_CORE_M0_OBJS)' \
    FW_QEMU='$(FW_QEMU)' FW_QEMU_FLAGS='$(FW_QEMU_FLAGS)' ARM_NM=$(ARM_NM) ARM_SIZE=$(ARM_SIZE) \
    LEAN_FLASH_MD=$(LEAN_FLASH_MD) bash bench/run_lean.sh
LEAN_DEPS := $(LEAN_CORE_OBJS) $(FW_LEAN_M0) $(FW_LEAN_M0BIG) $(FW_LEAN_FULL) $(FW_LEAN_UNLIT) \
             $(FW_BENCH_M0) $(FW_CORE_M0_OBJS) $(BENCH_HOST) $(LEAN_HOST) $(LEAN_HOST_FULL) \
             $(LEAN_HOST_UNLIT) bench/run_lean.sh \
             bench/map_text.awk

check-lean: $(LEAN_DEPS) | deps
	@$(LEAN_RUN)

# make bench: the Flash section of bench/results.md
$(LEAN_FLASH_MD): $(LEAN_DEPS) | deps
	@$(LEAN_RUN)
bench-firmware: $(LEAN_FLASH_MD)
