# SPDX-License-Identifier: MIT
# mk/fuzz.mk: libFuzzer harnesses (clang, AddressSanitizer, UBSan). Included by
# the top-level Makefile (docs/BUILD-CONTRACT.md). The bad-input unit tests are
# core suites (tests/core/test_api.c, test_extremes.c, test_pools.c).
#
#   make fuzz [FUZZ_SECONDS=60] [FUZZ_ONLY="frame panel"]
#        runs every harness for FUZZ_SECONDS each, one after the other, with
#        -max_total_time and -print_final_stats; logs in build/fuzz/logs/,
#        new inputs in build/fuzz/corpus/<h>/ (tests/fuzz/corpus/<h>/ is read
#        only), crashes in build/fuzz/artifacts/<h>/.
#   make test-fuzz-smoke   (part of make test) each harness over its checked-in
#        corpus, then FUZZ_SMOKE_RUNS (meshc: FUZZ_SMOKE_RUNS_meshc) more runs
#        from -seed=1: well under a minute for all of them.
#   make fuzz-merge        folds build/fuzz/corpus/<h>/ into the checked-in
#        corpus (libFuzzer -merge=1 keeps only inputs that add coverage).
#
# The harnesses (tests/fuzz/fuzz_<h>.c):
#   frame  whole frames from bytes: camera, meshes, pools, shading, bands
#   panel  the emulated panel (host_sim/emu) decoding arbitrary wire streams
#   meshc  the mesh converter's input path (tools/zspan-meshc.c), if present
#   mcp2210 the MCP2210 port's answer handling (ports/mcp2210/mcp2210.c), if present

DEB_PACKAGES += clang libclang-rt-14-dev libcmocka-dev

FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_SMOKE_RUNS ?= 2000
FUZZ_SMOKE_SEED ?= 1
FUZZ_MAX_LEN ?= 8192
FUZZ_DIR := $(BUILD)/fuzz
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all
# The core as the fuzzer sees it: coverage-instrumented, sanitized, and with
# span.c's fills counted (tests/fuzz/span_counted.c replaces span.o).
FUZZ_CORE_CFLAGS := -std=c99 -Wall -Wextra -Wconversion -ffreestanding $(CORE_REQUIRED_FLAGS) \
                    -g -O1 -Iinclude \
                    $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_CFLAGS := -std=c99 -Wall -Wextra -Werror -g -O1 -Iinclude -Itests/core/common \
               -Itests/fuzz $(FUZZ_SAN)

FUZZ_CORE_SRCS := $(filter-out src/span.c,$(CORE_SRCS))
FUZZ_CORE_OBJS := $(patsubst src/%.c,$(FUZZ_DIR)/core/%.o,$(FUZZ_CORE_SRCS)) \
                  $(FUZZ_DIR)/core/span_counted.o
FUZZ_CORE_LIB := $(FUZZ_DIR)/libzspan_fuzz.a
FUZZ_ZT_OBJ := $(FUZZ_DIR)/zt.o

# Harnesses whose code under test is in the tree (others' areas may not be yet).
FUZZ_HARNESSES := frame $(if $(wildcard host_sim/emu/emu.c),panel) \
                  $(if $(wildcard host_sim/emu/emu_mono.c),mono) \
                  $(if $(wildcard tools/zspan-meshc.c),meshc) \
                  $(if $(wildcard ports/mcp2210/mcp2210.c),mcp2210)
FUZZ_BINS = $(addprefix $(FUZZ_DIR)/fuzz_,$(FUZZ_HARNESSES))
FUZZ_ONLY ?= $(FUZZ_HARNESSES)
# Extra libFuzzer flags per harness. assimp leaks a scene on some failed
# imports (outside our code), so leak checking is off for the converter.
FUZZ_FLAGS_meshc := -detect_leaks=0
# Smoke runs per harness (the converter is slow: assimp per input).
FUZZ_SMOKE_RUNS_meshc ?= 300
# Shell: sets $extra to the flags and $runs to the smoke runs of harness $h.
FUZZ_RPAREN := )
FUZZ_EXTRA = extra=; runs=$(FUZZ_SMOKE_RUNS); case $$h in $(foreach h,$(FUZZ_HARNESSES),$(h)$(FUZZ_RPAREN) extra='$(FUZZ_FLAGS_$(h))' $(if $(FUZZ_SMOKE_RUNS_$(h)),runs=$(FUZZ_SMOKE_RUNS_$(h)));;) esac

TEST_TARGETS += test-fuzz-smoke

.PHONY: fuzz fuzz-build test-fuzz-smoke fuzz-merge

$(FUZZ_DIR)/core/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CORE_CFLAGS) -MMD -MP -c $< -o $@

$(FUZZ_DIR)/core/span_counted.o: tests/fuzz/span_counted.c src/span.c src/zs_internal.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CORE_CFLAGS) -Isrc -MMD -MP -c $< -o $@

$(FUZZ_CORE_LIB): $(FUZZ_CORE_OBJS) | core-present
	@rm -f $@
	$(AR) rcs $@ $^

$(FUZZ_ZT_OBJ): tests/core/common/zt.c tests/core/common/zt.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_DIR)/fuzz_frame: tests/fuzz/fuzz_frame.c tests/fuzz/fuzz_util.h $(FUZZ_ZT_OBJ) \
                        $(FUZZ_CORE_LIB) include/zspan/zspan.h | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_ZT_OBJ) $(FUZZ_CORE_LIB) -lm

# (b) the emulated panel: emu.c instrumented; emu_png.c (libpng) plain.
FUZZ_PNG_CFLAGS = $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
FUZZ_PNG_LIBS = $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng)
$(FUZZ_DIR)/emu/emu.o: host_sim/emu/emu.c host_sim/emu/emu.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=c99 -g -O1 $(FUZZ_SAN) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_DIR)/emu/emu_png.o: host_sim/emu/emu_png.c host_sim/emu/emu.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=c99 -D_POSIX_C_SOURCE=200809L -g -O1 $(FUZZ_SAN) $(FUZZ_PNG_CFLAGS) -c $< -o $@
$(FUZZ_DIR)/fuzz_panel: tests/fuzz/fuzz_panel.c tests/fuzz/fuzz_util.h $(FUZZ_DIR)/emu/emu.o \
                        $(FUZZ_DIR)/emu/emu_png.o | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Ihost_sim/emu -fsanitize=fuzzer -o $@ $< $(FUZZ_DIR)/emu/emu.o \
	    $(FUZZ_DIR)/emu/emu_png.o $(FUZZ_PNG_LIBS)

# (b') the emulated monochrome controllers: emu_mono.c instrumented.
$(FUZZ_DIR)/emu/emu_mono.o: host_sim/emu/emu_mono.c host_sim/emu/emu_mono.h | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=c99 -g -O1 -Iinclude $(FUZZ_SAN) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_DIR)/fuzz_mono: tests/fuzz/fuzz_mono.c tests/fuzz/fuzz_util.h $(FUZZ_DIR)/emu/emu_mono.o \
                       $(FUZZ_DIR)/emu/emu_png.o $(FUZZ_DIR)/emu/emu.o | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Ihost_sim/emu -fsanitize=fuzzer -o $@ $< $(FUZZ_DIR)/emu/emu_mono.o \
	    $(FUZZ_DIR)/emu/emu_png.o $(FUZZ_DIR)/emu/emu.o $(FUZZ_PNG_LIBS)

# (c) the mesh converter, compiled into the harness (see fuzz_meshc.c); the core
# checks its output.
FUZZ_ASSIMP_CFLAGS = $(shell $(PKG_CONFIG) --cflags assimp 2>/dev/null)
FUZZ_ASSIMP_LIBS = $(shell $(PKG_CONFIG) --libs assimp 2>/dev/null || echo -lassimp)
$(FUZZ_DIR)/fuzz_meshc: tests/fuzz/fuzz_meshc.c tests/fuzz/fuzz_util.h tools/zspan-meshc.c \
                        app/zs_import.c app/zs_opts.c app/zs_bsp_build.c tools/zs_teximg.c \
                        tools/zs_teximg.h $(FUZZ_CORE_LIB) | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Wno-unused-function -Iapp -Itools $(FUZZ_ASSIMP_CFLAGS) \
	    $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null) -fsanitize=fuzzer \
	    -o $@ $< app/zs_import.c app/zs_opts.c app/zs_bsp_build.c tools/zs_teximg.c \
	    $(FUZZ_CORE_LIB) $(FUZZ_ASSIMP_LIBS) $(TEXIMG_LIBS) -lm

# (d) the MCP2210 port against a chip whose answers are the fuzz input; the
# port uses the zs_bus glue of drivers/bus.c.
$(FUZZ_DIR)/mcp2210/%.o: %.c | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=c99 -D_POSIX_C_SOURCE=200809L -g -O1 -Iinclude -Iports/mcp2210 $(FUZZ_SAN) \
	    -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@
$(FUZZ_DIR)/fuzz_mcp2210: tests/fuzz/fuzz_mcp2210.c tests/fuzz/fuzz_util.h \
                          $(FUZZ_DIR)/mcp2210/ports/mcp2210/mcp2210.o \
                          $(FUZZ_DIR)/mcp2210/drivers/bus.o | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Iports/mcp2210 -fsanitize=fuzzer -o $@ $< \
	    $(FUZZ_DIR)/mcp2210/ports/mcp2210/mcp2210.o $(FUZZ_DIR)/mcp2210/drivers/bus.o

fuzz-build: $(FUZZ_BINS)

# One harness after the other (the machine is shared: one job at a time).
fuzz: $(FUZZ_BINS) | deps
	@mkdir -p $(FUZZ_DIR)/logs; fail=0; \
	for h in $(FUZZ_ONLY); do \
	    $(FUZZ_EXTRA); \
	    mkdir -p $(FUZZ_DIR)/corpus/$$h $(FUZZ_DIR)/artifacts/$$h tests/fuzz/corpus/$$h; \
	    echo "fuzz: $$h for $(FUZZ_SECONDS) s (log $(FUZZ_DIR)/logs/$$h.log)"; \
	    if ! $(FUZZ_DIR)/fuzz_$$h $$extra -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	        -max_len=$(FUZZ_MAX_LEN) -timeout=20 -artifact_prefix=$(FUZZ_DIR)/artifacts/$$h/ \
	        $(FUZZ_DIR)/corpus/$$h tests/fuzz/corpus/$$h > $(FUZZ_DIR)/logs/$$h.log 2>&1; then \
	        echo "fuzz: $$h FAILED, see $(FUZZ_DIR)/logs/$$h.log and $(FUZZ_DIR)/artifacts/$$h/"; \
	        fail=1; \
	    fi; \
	    { grep -E 'cov: ' $(FUZZ_DIR)/logs/$$h.log | tail -1; grep -E '^(stat::|Done )' \
	        $(FUZZ_DIR)/logs/$$h.log; } | sed "s/^/  $$h: /"; \
	done; exit $$fail

# make test: the checked-in corpora (every earlier crash is a seed there), then
# a short fixed-seed run; quick and deterministic.
test-fuzz-smoke: $(FUZZ_BINS) | deps
	@fail=0; \
	for h in $(FUZZ_HARNESSES); do \
	    $(FUZZ_EXTRA); \
	    out=$(FUZZ_DIR)/smoke/$$h; rm -rf $$out; mkdir -p $$out $(FUZZ_DIR)/artifacts/smoke-$$h; \
	    n=$$(ls tests/fuzz/corpus/$$h 2>/dev/null | wc -l); \
	    if $(FUZZ_DIR)/fuzz_$$h $$extra -runs=$$(( n + runs )) -seed=$(FUZZ_SMOKE_SEED) \
	        -max_len=$(FUZZ_MAX_LEN) -timeout=20 \
	        -artifact_prefix=$(FUZZ_DIR)/artifacts/smoke-$$h/ $$out tests/fuzz/corpus/$$h \
	        > $(FUZZ_DIR)/smoke/$$h.log 2>&1; then \
	        echo "test-fuzz-smoke: $$h ok ($$n seeds + $$runs runs)"; \
	    else \
	        echo "test-fuzz-smoke: $$h FAILED ($(FUZZ_DIR)/smoke/$$h.log):"; \
	        grep -A12 -E 'invariant failed|ERROR: |runtime error' $(FUZZ_DIR)/smoke/$$h.log | head -40; \
	        fail=1; \
	    fi; \
	done; exit $$fail

fuzz-merge: $(FUZZ_BINS) | deps
	@for h in $(FUZZ_ONLY); do \
	    $(FUZZ_EXTRA); \
	    mkdir -p tests/fuzz/corpus/$$h $(FUZZ_DIR)/corpus/$$h; \
	    $(FUZZ_DIR)/fuzz_$$h $$extra -merge=1 -max_len=$(FUZZ_MAX_LEN) tests/fuzz/corpus/$$h \
	        $(FUZZ_DIR)/corpus/$$h 2>&1 | grep -E 'MERGE-OUTER: [0-9]+ new files' | sed "s/^/$$h: /"; \
	done

-include $(shell find $(FUZZ_DIR) -name '*.d' 2>/dev/null)

# Regenerates the hand-made starting seeds (seed-*) of the frame and panel harnesses.
.PHONY: fuzz-seeds
fuzz-seeds: | deps
	@mkdir -p $(FUZZ_DIR) tests/fuzz/corpus/frame tests/fuzz/corpus/panel
	$(CC) -std=c99 -Wall -Wextra -Werror -O1 -o $(FUZZ_DIR)/gen_seeds tests/fuzz/gen_seeds.c
	$(FUZZ_DIR)/gen_seeds frame tests/fuzz/corpus/frame
	$(FUZZ_DIR)/gen_seeds panel tests/fuzz/corpus/panel
