# SPDX-License-Identifier: MIT
# mk/stellaris.mk: the Stellaris boards of QEMU with their OLEDs (issue 20).
#
#   build/fw/oled-lm3s6965.elf          LM3S6965 + SSD0323 (SSI0), GRAY4 (examples/stellaris-oled)
#   build/fw/oled-lm3s811.elf           LM3S811 (8 KB SRAM) + SSD0303 (I2C), 1-bit pages
#   build/tests/stellaris/test_stellaris  boots each image in qemu-system-arm, takes the
#                                       display with the monitor's screendump and compares
#                                       it with the host's render of the same frames
#                                       through zspan's emulated controllers (TEST_SUITES)
#   make bench-stellaris                (make bench) instructions per frame and RAM, both boards
# Uses FW_* of mk/firmware.mk (included before this file: the names sort so).

STELLARIS_DIR := $(PORT_DIR)/stellaris
OLED_EX := examples/stellaris-oled
FW_M3_CPU := -mcpu=cortex-m3
FW_M3 := $(FW_BUILD)/m3
OLED_FW_6965 := $(FW_BUILD)/oled-lm3s6965.elf
OLED_FW_811 := $(FW_BUILD)/oled-lm3s811.elf
STELLARIS_TEST := $(BUILD)/tests/stellaris/test_stellaris
# The big scene's torus: 16 x 8 segments (firmware and host alike).
OLED_DEMO_DEFS := -DDEMO_TORUS_U=16 -DDEMO_TORUS_V=8
OLED_INC := -I$(STELLARIS_DIR) -Iapp -I$(OLED_EX)
OLED_HDRS := $(PORT_HDRS) $(wildcard $(STELLARIS_DIR)/*.h) $(OLED_EX)/oled_scene.h app/demo_scene.h \
             include/zspan/panel.h include/zspan/bus.h include/zspan/zspan.h

OLED_DRV_SRCS := $(sort $(wildcard drivers/*.c))
OLED_COMMON_SRCS := $(PORT_SRCS) $(STELLARIS_DIR)/lm3s_port.c $(OLED_EX)/oled_scene.c \
                    $(OLED_EX)/oled_fw.c $(OLED_DRV_SRCS)
OLED_6965_SRCS := $(OLED_COMMON_SRCS) app/demo_scene.c $(STELLARIS_DIR)/board_lm3s6965.c
OLED_811_SRCS := $(OLED_COMMON_SRCS) $(STELLARIS_DIR)/board_lm3s811.c
FW_M3_CORE_OBJS := $(patsubst src/%.c,$(FW_M3)/core/%.o,$(CORE_SRCS))
FW_M3S_CORE_OBJS := $(patsubst src/%.c,$(FW_M3)/core-os/%.o,$(CORE_SRCS))
OLED_6965_OBJS := $(patsubst %.c,$(FW_M3)/6965/%.o,$(OLED_6965_SRCS))
OLED_811_OBJS := $(patsubst %.c,$(FW_M3)/811/%.o,$(OLED_811_SRCS))

ALL_TARGETS += $(OLED_FW_6965) $(OLED_FW_811) $(STELLARIS_TEST)
TEST_SUITES += $(STELLARIS_TEST)
BENCH_TARGETS += bench-stellaris

.PHONY: bench-stellaris

# Core: -O2 on the LM3S6965 (256 KB flash), -Os on the LM3S811 (64 KB).
$(FW_M3)/core/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M3_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_M3)/core-os/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M3_CPU) -Os $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_M3)/6965/%.o: %.c $(OLED_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M3_CPU) -O2 $(FW_COMMON) $(OLED_INC) $(OLED_DEMO_DEFS) -MMD -MP -c $< -o $@
$(FW_M3)/811/%.o: %.c $(OLED_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M3_CPU) -Os $(FW_COMMON) $(OLED_INC) -DOLED_LM3S811 -MMD -MP -c $< -o $@

$(OLED_FW_6965): $(OLED_6965_OBJS) $(FW_M3_CORE_OBJS) $(PORT_DIR)/ld/lm3s6965.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M3_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/lm3s6965.ld \
	    -Wl,-Map,$(@:.elf=.map) -o $@ $(filter %.o,$^) $(FW_LIBS)
$(OLED_FW_811): $(OLED_811_OBJS) $(FW_M3S_CORE_OBJS) $(PORT_DIR)/ld/lm3s811.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M3_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/lm3s811.ld \
	    -Wl,-Map,$(@:.elf=.map) -o $@ $(filter %.o,$^) $(FW_LIBS)

# --- the harness ----------------------------------------------------------------
STELLARIS_TEST_SRCS := tests/stellaris/test_stellaris.c $(OLED_EX)/oled_scene.c app/demo_scene.c \
                       host_sim/emu/emu_gray.c host_sim/emu/emu_mono.c host_sim/emu/emu_mono_bus.c \
                       host_sim/emu/emu_png.c
STELLARIS_TEST_CFLAGS = $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L $(OLED_DEMO_DEFS) -Iapp -I$(OLED_EX) \
                        -Ihost_sim/emu $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null) \
                        -DFW_QEMU='"$(FW_QEMU)"' -DOLED_FW_6965='"$(OLED_FW_6965)"' \
                        -DOLED_FW_811='"$(OLED_FW_811)"' -DSTELLARIS_OUT='"$(OUT)/stellaris"'
$(STELLARIS_TEST): $(STELLARIS_TEST_SRCS) $(OLED_HDRS) $(wildcard host_sim/emu/*.h) $(OLED_FW_6965) \
                   $(OLED_FW_811) $(PANELS_ASAN_LIB) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(STELLARIS_TEST_CFLAGS) -o $@ $(STELLARIS_TEST_SRCS) $(PANELS_ASAN_LIB) $(ASAN_LIB) \
	    $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null) $(TEST_LIBS)

# --- benchmark -------------------------------------------------------------------
# Each image renders 15 frames (the big scene's orbit repeats after 15) under
# -icount shift=0; per frame: the instructions from zs_frame_begin to the last
# byte on the wire (SPI or I2C polled: the port's own loops are counted).
STELLARIS_BENCH_OUT := bench/results-stellaris.md
bench-stellaris: $(OLED_FW_6965) $(OLED_FW_811) | deps
	@mkdir -p $(BUILD)/bench
	@{ echo "# Stellaris boards (QEMU lm3s6965evb, lm3s811evb)"; echo; \
	   echo "Written by \`make bench-stellaris\` (mk/stellaris.mk): 15 frames of each image of"; \
	   echo "examples/stellaris-oled under \`qemu-system-arm -icount shift=0\`. Instructions per frame"; \
	   echo "from zs_frame_begin to the last byte on the wire (the polled bus's loops included);"; \
	   echo "RAM = .data + .bss (the arena, the band buffer, the scene) + the stack's high water."; echo; \
	   echo "| board | display, format | scene | instructions per frame (mean, max) | RAM used | flash |"; \
	   echo "| ----- | --------------- | ----- | ---------------------------------- | -------- | ----- |"; } \
	    > $(BUILD)/bench/stellaris.md
	@for b in lm3s6965:$(OLED_FW_6965) lm3s811:$(OLED_FW_811); do \
	    m=$${b%%:*}; elf=$${b#*:}; \
	    timeout 300 $(FW_QEMU) -M $${m}evb -nographic -monitor none -serial none -icount shift=0 \
	        -semihosting-config enable=on,target=native,arg=frames=15 -kernel $$elf \
	        > $(BUILD)/bench/stellaris-$$m.txt 2>&1 || { cat $(BUILD)/bench/stellaris-$$m.txt; exit 1; }; \
	    flash=$$($(ARM_SIZE) $$elf | tail -1 | awk '{print $$1 + $$2}'); \
	    awk -v m=$$m -v flash=$$flash ' \
	        function kv(k, i) { for (i = 1; i <= NF; i++) if (index($$i, k "=") == 1) \
	            return substr($$i, length(k) + 2); return "" } \
	        /^F / { i = kv("instr") + 0; t += i; n++; if (i > mx) mx = i; if (kv("dropped") != "0") d++ } \
	        /^M / { st = kv("static_ram"); ar = kv("arena"); su = kv("stack_used"); ss = kv("stack_size") } \
	        END { if (!n || d) { print "bench-stellaris: " m ": no frames or pool drops" > "/dev/stderr"; exit 1 } \
	            ram = (m == "lm3s811") ? 8192 : 65536; \
	            what = (m == "lm3s811") ? "SSD0303 96x16 (I2C), 1-bit pages | spinning lit cube, 12 triangles" \
	                                    : "SSD0323 128x64 (SPI), GRAY4 dithered | demo scene (16x8 torus), 586 triangles, Gouraud, fog"; \
	            printf "| %s | %s | %.3f M, %.3f M | %d B (%d static, arena %d, stack %d of %d) of %d | %d B |\n", \
	                m, what, t / n / 1e6, mx / 1e6, st + su, st, ar, su, ss, ram, flash }' \
	        $(BUILD)/bench/stellaris-$$m.txt >> $(BUILD)/bench/stellaris.md || exit 1; \
	done
	@cp $(BUILD)/bench/stellaris.md $(STELLARIS_BENCH_OUT)
	@tail -2 $(STELLARIS_BENCH_OUT)

# --- the emulated SSD0323 joins the fuzz harnesses of mk/fuzz.mk ------------------
FUZZ_HARNESSES += gray
test-fuzz-smoke fuzz fuzz-merge fuzz-build: $(FUZZ_DIR)/fuzz_gray
$(FUZZ_DIR)/emu/emu_gray.o: host_sim/emu/emu_gray.c host_sim/emu/emu_gray.h host_sim/emu/emu_mono.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=c99 -g -O1 -Iinclude $(FUZZ_SAN) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_DIR)/fuzz_gray: tests/fuzz/fuzz_gray.c tests/fuzz/fuzz_util.h $(FUZZ_DIR)/emu/emu_gray.o \
                       $(FUZZ_DIR)/emu/emu_png.o $(FUZZ_DIR)/mcp2210/drivers/bus.o | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Ihost_sim/emu -fsanitize=fuzzer -o $@ $< $(FUZZ_DIR)/emu/emu_gray.o \
	    $(FUZZ_DIR)/emu/emu_png.o $(FUZZ_DIR)/mcp2210/drivers/bus.o $(FUZZ_PNG_LIBS)
