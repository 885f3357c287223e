# SPDX-License-Identifier: MIT
# zspan top-level Makefile (GNU make). See docs/BUILD-CONTRACT.md.
#
#   make          build/libzspan.a and build/libzspan_drivers.a with only a C compiler (installs
#                 nothing); also `programs` when every package of $(DEB_PACKAGES) is installed
#   make programs build/asan/libzspan.a, build/zspan-sim, $(ALL_TARGETS)
#   make install  the libraries, headers, zspan.pc into $(DESTDIR)$(PREFIX) (mk/package.mk)
#   make test     programs, then core tests, check-core, check-core-flags, $(TEST_SUITES),
#                 $(TEST_TARGETS);
#                 ends with one line "N passed, N failed"
#   make demo     renders the built-in scene to out/demo.png, then $(DEMO_TARGETS)
#   make bench    runs $(BENCH_TARGETS)
#   make deps     installs the Debian packages in $(DEB_PACKAGES) that are missing (as root)
#   make check-core  Cortex-M0 build of src/*.c: no float, no malloc, no stdio; .text size
#   make check-core-flags  every rule compiling src/ passes $(CORE_REQUIRED_FLAGS)
#   make clean

SHELL := /bin/bash
.DEFAULT_GOAL := all
.SUFFIXES:
.DELETE_ON_ERROR:

BUILD := build
OUT := out

PKG_CONFIG ?= pkg-config
ARM_PREFIX ?= arm-none-eabi-
ARM_CC := $(ARM_PREFIX)gcc
ARM_NM := $(ARM_PREFIX)nm
ARM_SIZE := $(ARM_PREFIX)size

# ---------------------------------------------------------------------------
# Variables the mk/*.mk extensions append to (see docs/BUILD-CONTRACT.md)
# ---------------------------------------------------------------------------
DEB_PACKAGES := build-essential pkg-config libcmocka-dev libpng-dev libassimp-dev \
                assimp-testmodels clang valgrind gcc-arm-none-eabi \
                libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-system-arm
ALL_TARGETS :=
TEST_SUITES :=
TEST_TARGETS :=
DEMO_TARGETS :=
BENCH_TARGETS :=
SIM_EXTRA_SRCS :=
SIM_EXTRA_CFLAGS :=
SIM_EXTRA_LIBS :=

# ---------------------------------------------------------------------------
# The core
# ---------------------------------------------------------------------------
CORE_SRCS := $(sort $(wildcard src/*.c))
# Flags every rule that compiles src/ must pass, whatever else it adds: the core
# keeps its own record types in the caller's arena whatever type the caller
# declared it with (include/zspan/zspan.h, zs_init). `make check-core-flags`
# (part of make test) fails if a rule of the Makefile or mk/*.mk lacks them.
# The same list a user's Makefile gets from zspan.mk (ZSPAN_REQUIRED_CFLAGS).
include zspan.mk
CORE_REQUIRED_FLAGS := $(ZSPAN_REQUIRED_CFLAGS)
CORE_WARN := -std=c99 -Wall -Wextra -Werror -Wconversion -ffreestanding $(CORE_REQUIRED_FLAGS)
CORE_CFLAGS := $(CORE_WARN) -O2 -Iinclude
ASAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all
CORE_ASAN_CFLAGS := $(CORE_WARN) $(ASAN_FLAGS) -g -O1 -Iinclude
M0_CFLAGS := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -Os -std=c99 -ffreestanding $(CORE_REQUIRED_FLAGS) \
             -Wall -Wextra -Werror -Iinclude

# The application layer (app/): scenes, options, sizing, the panel frame loop.
APP_SRCS := $(sort $(wildcard app/*.c))
APP_HDRS := $(wildcard app/*.h)

LIB := $(BUILD)/libzspan.a
ASAN_LIB := $(BUILD)/asan/libzspan.a
SIM := $(BUILD)/zspan-sim

CORE_OBJS := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(CORE_SRCS))
CORE_ASAN_OBJS := $(patsubst src/%.c,$(BUILD)/asan/obj/%.o,$(CORE_SRCS))
M0_OBJS := $(patsubst src/%.c,$(BUILD)/m0/%.o,$(CORE_SRCS))

# Host test programs (cmocka) link the sanitizer library with these flags.
TEST_CFLAGS := -std=c99 -Wall -Wextra -Werror -g -O1 $(ASAN_FLAGS) -Iinclude -Itests/core/common
TEST_LIBS := -lcmocka -lm
# The suite runner: runs cmocka binaries and make targets, sums, prints "N passed, N failed".
SUITE_RUNNER := bash tests/run_suites.sh

# ---------------------------------------------------------------------------
# Extensions (panels, firmware, ports, ...). Included before anything below
# uses the variables above; DEB_PACKAGES is only expanded in the deps recipe.
# ---------------------------------------------------------------------------
-include $(sort $(wildcard mk/*.mk))

# ---------------------------------------------------------------------------
# Host simulator (host_sim/*.c at the top level only, the application layer
# app/*.c, plus SIM_EXTRA_SRCS)
# ---------------------------------------------------------------------------
SIM_SRCS := $(sort $(wildcard host_sim/*.c)) $(APP_SRCS) $(SIM_EXTRA_SRCS)
SIM_OBJS := $(patsubst %.c,$(BUILD)/sim/%.o,$(SIM_SRCS))
# Recursive (=): pkg-config runs when a recipe needs it, i.e. after `deps`.
SIM_CFLAGS = -std=c99 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L -O2 -g -Iinclude -Iapp \
             $(shell $(PKG_CONFIG) --cflags assimp libpng) $(SIM_EXTRA_CFLAGS)
SIM_LIBS = $(shell $(PKG_CONFIG) --libs assimp libpng) -lm $(SIM_EXTRA_LIBS)

# ---------------------------------------------------------------------------
# Core tests: each tests/core/*.c is one cmocka program (+ tests/core/common/*.c)
# ---------------------------------------------------------------------------
CORE_TEST_SRCS := $(sort $(wildcard tests/core/*.c))
CORE_TEST_COMMON_SRCS := $(sort $(wildcard tests/core/common/*.c))
CORE_TEST_COMMON_OBJS := $(patsubst tests/core/common/%.c,$(BUILD)/tests/core/common/%.o,$(CORE_TEST_COMMON_SRCS))
CORE_TEST_BINS := $(patsubst tests/core/%.c,$(BUILD)/tests/core/%,$(CORE_TEST_SRCS))
# Core tests may load meshes (assimp) and write images (libpng), like the simulator;
# ZT_TOP_DIR lets a suite read the tree's files (test_status reads the header).
CORE_TEST_CFLAGS = $(TEST_CFLAGS) -DZT_TOP_DIR='"$(CURDIR)"' \
                   $(shell $(PKG_CONFIG) --cflags assimp libpng 2>/dev/null)
CORE_TEST_LIBS = $(shell $(PKG_CONFIG) --libs assimp libpng 2>/dev/null) $(TEST_LIBS)

.PHONY: all programs deps test test-core check-core check-core-flags demo bench clean core-present \
        $(TEST_TARGETS) $(DEMO_TARGETS) $(BENCH_TARGETS)

# Plain `make` needs only a C compiler and installs nothing: the core and the
# panel drivers (both freestanding). The host programs, sanitizer builds and
# firmware images need Debian packages: `make programs` (after `make deps`);
# plain `make` builds them too when every package is already installed.
ALL_LIBS := $(LIB) $(PANELS_LIB)
DEB_INSTALLED := $(shell dpkg-query -W -f='$${db:Status-Abbrev}|$${Package}\n' \
                   $(sort $(DEB_PACKAGES)) 2>/dev/null | sed -n 's/^ii.|//p')
DEB_MISSING := $(filter-out $(DEB_INSTALLED),$(sort $(DEB_PACKAGES)))
HAVE_ALL_PACKAGES := $(if $(DEB_INSTALLED),$(if $(DEB_MISSING),,y))

all: $(ALL_LIBS) $(if $(HAVE_ALL_PACKAGES),programs)
ifeq ($(HAVE_ALL_PACKAGES),)
	@echo "make: built $(ALL_LIBS) only; 'make deps' (as root) then 'make programs' builds the rest"
endif

programs: $(ALL_LIBS) $(ASAN_LIB) $(SIM) $(ALL_TARGETS) | deps

# ---------------------------------------------------------------------------
# deps: install missing Debian packages (root) or list them (non-root).
# ---------------------------------------------------------------------------
deps:
	@if ! command -v dpkg-query >/dev/null 2>&1; then \
	    echo "deps: dpkg-query not found (not Debian?); not checking packages: $(sort $(DEB_PACKAGES))"; \
	    exit 0; \
	fi; \
	missing=""; \
	for p in $(sort $(DEB_PACKAGES)); do \
	    case "$$(dpkg-query -W -f='$${Status}' "$$p" 2>/dev/null)" in \
	        *"install ok installed") ;; \
	        *) missing="$$missing $$p" ;; \
	    esac; \
	done; \
	if [ -z "$$missing" ]; then exit 0; fi; \
	if [ "$$(id -u)" -ne 0 ]; then \
	    echo "deps: missing Debian packages:$$missing"; \
	    echo "deps: not root, not installing; run 'make deps' as root (or apt-get install them). Continuing."; \
	    exit 0; \
	fi; \
	echo "deps: installing:$$missing"; \
	apt-get update && \
	DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing

core-present:
	@if [ -z "$(CORE_SRCS)" ]; then echo "error: no src/*.c: the core is not there yet" >&2; exit 1; fi

# ---------------------------------------------------------------------------
# Libraries
# ---------------------------------------------------------------------------
$(BUILD)/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(CORE_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/asan/obj/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(CORE_ASAN_CFLAGS) -MMD -MP -c $< -o $@

$(LIB): $(CORE_OBJS) | core-present
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

$(ASAN_LIB): $(CORE_ASAN_OBJS) | core-present
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

# ---------------------------------------------------------------------------
# Simulator
# ---------------------------------------------------------------------------
$(BUILD)/sim/%.o: %.c | deps
	@mkdir -p $(@D)
	$(CC) $(SIM_CFLAGS) -MMD -MP -c $< -o $@

$(SIM): $(SIM_OBJS) $(LIB)
	$(CC) -o $@ $(SIM_OBJS) $(LIB) $(SIM_LIBS)

# ---------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------
$(BUILD)/tests/core/common/%.o: tests/core/common/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(CORE_TEST_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/tests/core/%.o: tests/core/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(CORE_TEST_CFLAGS) -MMD -MP -c $< -o $@

# A suite that needs more libraries names them on its first or second line (after the
# SPDX line): /* LIBS: -lfoo */
$(BUILD)/tests/core/%: $(BUILD)/tests/core/%.o $(CORE_TEST_COMMON_OBJS) $(ASAN_LIB)
	$(CC) $(CORE_TEST_CFLAGS) -o $@ $< $(CORE_TEST_COMMON_OBJS) $(ASAN_LIB) $(CORE_TEST_LIBS) \
	    $$(sed -n '1,2s|^/\* LIBS: \(.*\) \*/$$|\1|p' tests/core/$*.c)

.PRECIOUS: $(BUILD)/tests/core/%.o $(BUILD)/tests/core/common/%.o

test-core: $(CORE_TEST_BINS) | deps
	@$(SUITE_RUNNER) $(CORE_TEST_BINS)

# Runs, in order: the core suites, check-core, check-core-flags, the TEST_SUITES of mk/*.mk, then
# each of TEST_TARGETS; keeps going after a failure; the last line is the total.
test: programs $(CORE_TEST_BINS) $(TEST_SUITES) | deps
	@MAKE='$(MAKE)' $(SUITE_RUNNER) $(CORE_TEST_BINS) make:check-core make:check-core-flags \
	    $(TEST_SUITES) \
	    $(addprefix make:,$(TEST_TARGETS))

# The suites link the libraries (mk/app.mk names the driver libraries before
# mk/panels.mk defines their variables, so it misses them as prerequisites).
$(TEST_SUITES): | $(ALL_LIBS) $(ASAN_LIB) $(PANELS_ASAN_LIB)

$(BUILD)/m0/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(M0_CFLAGS) -MMD -MP -c $< -o $@

check-core: $(M0_OBJS) | deps core-present
	@ARM_NM='$(ARM_NM)' ARM_SIZE='$(ARM_SIZE)' CC='$(CC)' bash tests/check_core.sh $(M0_OBJS)

# Every rule of the Makefile and mk/*.mk that compiles src/ passes $(CORE_REQUIRED_FLAGS)
# (asks make for the rules and their commands; builds nothing).
check-core-flags: | core-present
	@MAKE_CMD='$(MAKE)' bash tests/check_core_flags.sh

# ---------------------------------------------------------------------------
# Demo and benchmarks
# ---------------------------------------------------------------------------
demo: programs | deps
	@mkdir -p $(OUT)
	$(SIM) demo --out $(OUT)/demo.png
ifneq ($(strip $(DEMO_TARGETS)),)
	@$(MAKE) --no-print-directory $(DEMO_TARGETS)
endif

bench: programs | deps
ifneq ($(strip $(BENCH_TARGETS)),)
	@$(MAKE) --no-print-directory $(BENCH_TARGETS)
else
	@echo "bench: no benchmarks registered yet (BENCH_TARGETS is empty)"
endif

clean:
	rm -rf $(BUILD) $(OUT)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
