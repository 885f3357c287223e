# SPDX-License-Identifier: MIT
# mk/portals.mk: portal levels (zspan/portal.h, src/portal.c). Included by the
# top-level Makefile (see docs/BUILD-CONTRACT.md and README.md (Portal levels)).
#
#   build/zspan-level                  level files -> PVS -> C arrays; random levels
#   build/tests/tools/test_level       format, PVS, conservativeness, frame equality (TEST_SUITES)
#   make check-portals-full            the long run: 100 eye positions per cell, every frame
#   zspan-sim walk LEVEL               (host_sim/walk_cmd.c) a scripted flight, PNG frames

DEB_PACKAGES += gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm libassimp-dev \
                libcmocka-dev libsdl2-dev valgrind

LEVEL_TOOL := $(BUILD)/zspan-level
LEVEL_LIB_SRCS := $(sort $(wildcard tools/level/*.c))
LEVEL_LIB_HDRS := tools/level/level.h include/zspan/portal.h
LEVEL_CFLAGS := -std=c99 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L -O2 -g -Iinclude -Itools/level
LEVEL_TEST := $(BUILD)/tests/tools/test_level
# The mesh importer (assimp through app/zs_import.c): the tool and the tests only.
LEVEL_IMPORT_SRCS := tools/level_import/level_import.c app/zs_import.c
LEVEL_IMPORT_HDRS := tools/level_import/level_import.h app/zs_import.h
LEVEL_IMPORT_CFLAGS = -Itools/level_import -Iapp $(shell $(PKG_CONFIG) --cflags assimp 2>/dev/null)
LEVEL_IMPORT_LIBS = $(shell $(PKG_CONFIG) --libs assimp 2>/dev/null || echo -lassimp)

ALL_TARGETS += $(LEVEL_TOOL)
TEST_SUITES += $(LEVEL_TEST)
SIM_EXTRA_SRCS += $(LEVEL_LIB_SRCS)
SIM_EXTRA_CFLAGS += -Itools/level

.PHONY: check-portals-full

$(LEVEL_TOOL): tools/zspan-level.c $(LEVEL_LIB_SRCS) $(LEVEL_LIB_HDRS) $(LEVEL_IMPORT_SRCS) \
               $(LEVEL_IMPORT_HDRS) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(LEVEL_CFLAGS) $(LEVEL_IMPORT_CFLAGS) -o $@ tools/zspan-level.c $(LEVEL_LIB_SRCS) \
	    $(LEVEL_IMPORT_SRCS) $(LIB) $(LEVEL_IMPORT_LIBS) -lm

check-portals-full: $(LEVEL_TEST)
	LEVEL_TEST_FULL=1 $(LEVEL_TEST)

# --- the M4 bench scene: a generated building floor and its flight ---------------
PORTALS_BENCH_DIR := $(BUILD)/bench/level
PORTALS_BENCH_LVL := $(PORTALS_BENCH_DIR)/bench.lvl
PORTALS_BENCH_GEN := $(PORTALS_BENCH_DIR)/bench_level.c
PORTALS_FW_M4 := $(FW_BUILD)/bench-portals-mps2-an386.elf
PORTALS_FW_OBJS := $(FW_BUILD)/m4/portals/bench_portals_fw.o $(FW_BUILD)/m4/portals/bench_level.o \
                   $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
                   $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o
# Cortex-M0 code of the same program on the M4 machine's RAM (the level's
# arena does not fit the microbit): host == M0 == M4 checksums.
PORTALS_FW_M0 := $(FW_BUILD)/bench-portals-m0code-mps2-an386.elf
PORTALS_FW_M0_OBJS := $(FW_BUILD)/m0/portals/bench_portals_fw.o $(FW_BUILD)/m0/portals/bench_level.o \
                      $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(PORT_SRCS)) \
                      $(FW_BUILD)/m0/app/board_m0code_an386.o
ALL_TARGETS += $(PORTALS_FW_M4) $(PORTALS_FW_M0)
BENCH_TARGETS += bench-portals
TEST_TARGETS += check-portals-m4
.PHONY: bench-portals check-portals-m4

$(PORTALS_BENCH_LVL): $(LEVEL_TOOL)
	@mkdir -p $(@D)
	$(LEVEL_TOOL) gen building 8x6 7 -o $@
$(PORTALS_BENCH_GEN): $(PORTALS_BENCH_LVL) $(LEVEL_TOOL)
	$(LEVEL_TOOL) c $< -n bench_level -o $(basename $@) -p 8
$(PORTALS_BENCH_GEN:.c=.h): $(PORTALS_BENCH_GEN) ;

$(FW_BUILD)/m4/portals/bench_portals_fw.o: bench/bench_portals_fw.c $(PORTALS_BENCH_GEN:.c=.h) \
                                           $(PORT_HDRS) include/zspan/portal.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -I$(PORTALS_BENCH_DIR) -MMD -MP -c $< -o $@
$(FW_BUILD)/m4/portals/bench_level.o: $(PORTALS_BENCH_GEN) include/zspan/portal.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/portals/bench_portals_fw.o: bench/bench_portals_fw.c $(PORTALS_BENCH_GEN:.c=.h) \
                                           $(PORT_HDRS) include/zspan/portal.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -I$(PORTALS_BENCH_DIR) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/portals/bench_level.o: $(PORTALS_BENCH_GEN) include/zspan/portal.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -MMD -MP -c $< -o $@
$(PORTALS_FW_M0): $(PORTALS_FW_M0_OBJS) $(FW_CORE_M0_OBJS) $(PORT_DIR)/ld/mps2-an386.ld \
                  $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(PORTALS_FW_M4): $(PORTALS_FW_OBJS) $(FW_CORE_M4_OBJS) $(PORT_DIR)/ld/mps2-an386.ld \
                  $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null

# The same program on the host (bench/bench_portals_host.c stands in for the port).
PORTALS_HOST := $(BUILD)/bench/bench_portals_host
ALL_TARGETS += $(PORTALS_HOST)
$(PORTALS_HOST): bench/bench_portals_fw.c bench/bench_portals_host.c $(PORTALS_BENCH_GEN) \
                 $(PORT_HDRS) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -Iinclude -I$(PORT_DIR) -I$(PORTALS_BENCH_DIR) -o $@ \
	    bench/bench_portals_fw.c bench/bench_portals_host.c $(PORTALS_BENCH_GEN) $(LIB)

# make test: two frames of the flight on the M4 and in M0 code: every cull
# gives the same frame, with the same checksums as the host
PORTALS_CHECK = $(BUILD)/bench/portals-check
check-portals-m4: $(PORTALS_FW_M4) $(PORTALS_FW_M0) $(PORTALS_HOST) | deps
	@mkdir -p $(PORTALS_CHECK); rc=0; \
	for cpu in m4 m0; do \
	    elf=$(PORTALS_FW_M4); test $$cpu = m0 && elf=$(PORTALS_FW_M0); \
	    $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS),arg=quick -kernel $$elf \
	        > $(PORTALS_CHECK)/$$cpu.txt 2>&1 || rc=1; \
	    cat $(PORTALS_CHECK)/$$cpu.txt; \
	    test $$(grep -c '^C .* equal$$' $(PORTALS_CHECK)/$$cpu.txt) -eq 2 || rc=1; \
	    grep '^L ' $(PORTALS_CHECK)/$$cpu.txt | awk '{print $$3, $$4, $$6}' > $(PORTALS_CHECK)/$$cpu.sums; \
	done; \
	BENCH_ARGS=quick $(PORTALS_HOST) > $(PORTALS_CHECK)/host.txt || rc=1; \
	grep '^L ' $(PORTALS_CHECK)/host.txt | awk '{print $$3, $$4, $$6}' > $(PORTALS_CHECK)/host.sums; \
	if cmp -s $(PORTALS_CHECK)/m4.sums $(PORTALS_CHECK)/host.sums && \
	   cmp -s $(PORTALS_CHECK)/m0.sums $(PORTALS_CHECK)/host.sums; then \
	    echo "check-portals-m4: host == M0 == M4 checksums ($$(wc -l < $(PORTALS_CHECK)/host.sums) frames)"; \
	else echo "check-portals-m4: host, M0 and M4 checksums differ"; rc=1; fi; \
	exit $$rc

bench-portals: $(PORTALS_FW_M4) $(PORTALS_FW_M0) $(PORTALS_HOST) $(LEVEL_TOOL) $(PORTALS_BENCH_LVL) | deps
	@LEVEL_TOOL=$(LEVEL_TOOL) LEVEL_FILE=$(PORTALS_BENCH_LVL) FW=$(PORTALS_FW_M4) HOST=$(PORTALS_HOST) \
	    FW_M0=$(PORTALS_FW_M0) \
	    FW_QEMU="$(FW_QEMU)" FW_QEMU_FLAGS="$(FW_QEMU_FLAGS)" OUT=bench/portals.md \
	    WORK=$(BUILD)/bench bash bench/run_portals.sh

# The suite also checks the emitted C of the bench level against the level
# built in memory from the same file (LEVEL_FILE).
$(LEVEL_TEST): tests/tools/test_level.c $(LEVEL_LIB_SRCS) $(LEVEL_LIB_HDRS) $(PORTALS_BENCH_GEN) \
               $(LEVEL_IMPORT_SRCS) $(LEVEL_IMPORT_HDRS) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -Itools/level -I$(PORTALS_BENCH_DIR) \
	    $(LEVEL_IMPORT_CFLAGS) -DLEVEL_FILE='"$(PORTALS_BENCH_LVL)"' -o $@ tests/tools/test_level.c \
	    $(LEVEL_LIB_SRCS) $(LEVEL_IMPORT_SRCS) $(PORTALS_BENCH_GEN) $(ASAN_LIB) \
	    $(LEVEL_IMPORT_LIBS) $(TEST_LIBS)

# --- a libFuzzer harness of the core's level checks and walk (mk/fuzz.mk runs it)
ifdef FUZZ_DIR
FUZZ_HARNESSES += level
# fuzz.mk's rules took their prerequisites before this file added the harness
fuzz fuzz-build test-fuzz-smoke fuzz-merge: $(FUZZ_DIR)/fuzz_level
$(FUZZ_DIR)/fuzz_level: tests/fuzz/fuzz_level.c tests/fuzz/fuzz_util.h $(LEVEL_LIB_SRCS) \
                        $(LEVEL_LIB_HDRS) $(FUZZ_CORE_LIB) | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -D_POSIX_C_SOURCE=200809L -Itools/level -fsanitize=fuzzer -o $@ $< \
	    $(LEVEL_LIB_SRCS) $(FUZZ_CORE_LIB) -lm
endif

# make test: zspan-sim walk on a generated building, the scripted flight and
# the window (SDL's dummy video driver) driven by a key script; every frame
# must equal the frame drawn with every cell (walk fails otherwise).
TEST_TARGETS += check-walk
.PHONY: check-walk
check-walk: $(SIM) $(LEVEL_TOOL) | deps
	@mkdir -p $(OUT)/check-walk
	$(LEVEL_TOOL) gen building 5x4 11 -o $(OUT)/check-walk/level.lvl
	$(SIM) walk $(OUT)/check-walk/level.lvl --frames 16 --size 120x90 --mode zline \
	    --out $(OUT)/check-walk/path --quiet
	SDL_VIDEODRIVER=dummy $(SIM) walk $(OUT)/check-walk/level.lvl --window --size 96x72 \
	    --keys UUUUUUUULLLUUUUUUUURRRRRRUUUUUUUUUUUU --out $(OUT)/check-walk/window \
	    > $(OUT)/check-walk/window.txt
	tail -1 $(OUT)/check-walk/window.txt
	test $$(ls $(OUT)/check-walk/window | wc -l) -eq 38
	test $$(grep '^frame' $(OUT)/check-walk/window.txt | awk '{print $$4}' | sort -u | wc -l) -ge 2
