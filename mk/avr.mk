# SPDX-License-Identifier: MIT
# mk/avr.mk: the AVR target, an ATmega2560 (8 KB RAM, 16-bit int) under simavr, built with
# Debian's gcc-avr and avr-libc. bench/small_scene.c (three cubes and an octahedron at
# 160x128, flat and Gouraud, both visibility modes) runs on the host and on the AVR; every
# frame's checksum must be the same. ports/avr/simavr_run.c runs the image on libsimavr
# and counts its cycles exactly. See README.md (Building zspan into your project).
#
#   build/avr/small-atmega2560.elf   the image (core -Os)
#   build/avr/small-host             the same program on the host (reference checksums)
#   build/avr/simavr_run             the simulator harness
#   make test-avr                    the image against the host (TEST_TARGETS)
#   make bench-avr                   cycles per frame and RAM -> bench/results-avr.md (BENCH_TARGETS)

DEB_PACKAGES += gcc-avr avr-libc binutils-avr simavr libsimavr-dev libelf-dev

AVR_PREFIX ?= avr-
AVR_CC := $(AVR_PREFIX)gcc
AVR_SIZE := $(AVR_PREFIX)size
AVR_MCU := atmega2560
AVR_HZ := 16000000
AVR_BUILD := $(BUILD)/avr
AVR_PORT := ports/avr
# -Wno-sign-compare: gcc-avr warns where a uint16_t count (promoted to a 16-bit
# unsigned int) meets an int index; the counts stay below ZS_MAX_ACTIVE_EDGES.
AVR_CFLAGS := -mmcu=$(AVR_MCU) -DF_CPU=$(AVR_HZ)UL -Os -std=c99 -ffreestanding \
              $(CORE_REQUIRED_FLAGS) -Wall -Wextra -Werror -Wno-sign-compare \
              -ffunction-sections -fdata-sections -Iinclude
SMALL_DEFS := -DSMALL_FRAMES=4
AVR_CORE_OBJS := $(patsubst src/%.c,$(AVR_BUILD)/core/%.o,$(CORE_SRCS))
AVR_APP_SRCS := bench/small_scene.c bench/small_port_avr.c $(AVR_PORT)/avr_port.c
AVR_APP_OBJS := $(patsubst %.c,$(AVR_BUILD)/app/%.o,$(AVR_APP_SRCS))
AVR_ELF := $(AVR_BUILD)/small-$(AVR_MCU).elf
AVR_HOST := $(AVR_BUILD)/small-host
AVR_RUN := $(AVR_BUILD)/simavr_run

ALL_TARGETS += $(AVR_ELF) $(AVR_HOST) $(AVR_RUN)
TEST_TARGETS += test-avr
BENCH_TARGETS += bench-avr
.PHONY: test-avr bench-avr

$(AVR_BUILD)/core/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(AVR_CC) $(AVR_CFLAGS) -MMD -MP -c $< -o $@
# The scene sees bench/; the adapter bench/ and the port; the port itself only its directory.
$(AVR_BUILD)/app/bench/%.o: bench/%.c bench/small_port.h $(AVR_PORT)/avr_port.h | deps
	@mkdir -p $(@D)
	$(AVR_CC) $(AVR_CFLAGS) $(SMALL_DEFS) '-DSMALL_BOARD="avr"' -Ibench -I$(AVR_PORT) -MMD -MP -c $< -o $@
$(AVR_BUILD)/app/$(AVR_PORT)/%.o: $(AVR_PORT)/%.c $(AVR_PORT)/avr_port.h | deps
	@mkdir -p $(@D)
	$(AVR_CC) $(AVR_CFLAGS) -I$(AVR_PORT) -MMD -MP -c $< -o $@
$(AVR_ELF): $(AVR_APP_OBJS) $(AVR_CORE_OBJS)
	$(AVR_CC) -mmcu=$(AVR_MCU) -Wl,--gc-sections -o $@ $^
	@$(AVR_SIZE) $@

$(AVR_HOST): bench/small_scene.c bench/small_port_host.c bench/small_port.h $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SMALL_DEFS) '-DSMALL_BOARD="host"' -Ibench -o $@ bench/small_scene.c \
	    bench/small_port_host.c $(ASAN_LIB)

$(AVR_RUN): $(AVR_PORT)/simavr_run.c | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 $$($(PKG_CONFIG) --cflags simavr) -o $@ $< \
	    $$($(PKG_CONFIG) --libs simavr || echo -lsimavr) -lelf

test-avr: $(AVR_ELF) $(AVR_HOST) $(AVR_RUN) | deps
	@AVR_RUN=$(AVR_RUN) AVR_MCU=$(AVR_MCU) AVR_HZ=$(AVR_HZ) \
	    bash tests/packaging/run_avr.sh test $(AVR_ELF) $(AVR_HOST)

bench-avr: $(AVR_ELF) $(AVR_HOST) $(AVR_RUN) $(AVR_CORE_OBJS) | deps
	@AVR_RUN=$(AVR_RUN) AVR_MCU=$(AVR_MCU) AVR_HZ=$(AVR_HZ) AVR_SIZE=$(AVR_SIZE) \
	    AVR_CORE_OBJS='$(AVR_CORE_OBJS)' bash tests/packaging/run_avr.sh bench $(AVR_ELF) $(AVR_HOST)
