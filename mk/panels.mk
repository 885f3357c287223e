# SPDX-License-Identifier: MIT
# mk/panels.mk: panel drivers, bus, emulated panels, simulator panel command.
# Included by the top-level Makefile (see docs/BUILD-CONTRACT.md).
#
#   build/libzspan_drivers.a        drivers/*.c (freestanding C99, like the core)
#   build/asan/libzspan_drivers.a   the same with the sanitizers, for the tests
#   build/tests/panel/*             one cmocka program per tests/panel/*.c
#   make demo-panel                 the animated ST7789 demo (part of make demo)
#   make check-drivers              Cortex-M0 build of drivers/*.c: no float,
#                                   no allocator, no stdio (part of make test)

DEB_PACKAGES += libsdl2-dev libx11-dev xvfb xauth

PANELS_DRV_SRCS := $(sort $(wildcard drivers/*.c))
PANELS_DRV_HDRS := $(wildcard drivers/*.h) include/zspan/bus.h include/zspan/panel.h
PANELS_DRV_OBJS := $(patsubst drivers/%.c,$(BUILD)/drivers/obj/%.o,$(PANELS_DRV_SRCS))
PANELS_DRV_ASAN_OBJS := $(patsubst drivers/%.c,$(BUILD)/asan/drivers/%.o,$(PANELS_DRV_SRCS))
PANELS_DRV_M0_OBJS := $(patsubst drivers/%.c,$(BUILD)/m0/drivers/%.o,$(PANELS_DRV_SRCS))
PANELS_LIB := $(BUILD)/libzspan_drivers.a
PANELS_ASAN_LIB := $(BUILD)/asan/libzspan_drivers.a

PANELS_EMU_SRCS := $(sort $(wildcard host_sim/emu/*.c))
PANELS_EMU_TEST_OBJS := $(patsubst host_sim/emu/%.c,$(BUILD)/tests/panel/emu/%.o,$(PANELS_EMU_SRCS))

PANELS_TEST_SRCS := $(sort $(wildcard tests/panel/*.c))
PANELS_TEST_BINS := $(patsubst tests/panel/%.c,$(BUILD)/tests/panel/%,$(PANELS_TEST_SRCS))

# Recursive: pkg-config runs in recipes, after `make deps`.
PANELS_PNG_CFLAGS = $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
PANELS_PNG_LIBS = $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null)
# ZT_TOP_DIR: test_panel_contract reads the headers (status texts).
PANELS_TEST_CFLAGS = $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -Ihost_sim/emu -Ihost_sim \
                     -DZT_TOP_DIR='"$(CURDIR)"' $(PANELS_PNG_CFLAGS)
PANELS_TEST_LIBS = $(PANELS_PNG_LIBS) -lSDL2 -lX11 $(TEST_LIBS)

ALL_TARGETS += $(PANELS_LIB) $(PANELS_ASAN_LIB)
TEST_SUITES += $(PANELS_TEST_BINS)
TEST_TARGETS += check-drivers
DEMO_TARGETS += demo-panel

# The simulator gets the drivers and the emulated panels as plain objects
# (no archive ordering issues) and SDL2 for --window.
SIM_EXTRA_SRCS += $(PANELS_DRV_SRCS) $(PANELS_EMU_SRCS)
SIM_EXTRA_LIBS += -lSDL2

# --- driver libraries ------------------------------------------------------
$(BUILD)/drivers/obj/%.o: drivers/%.c $(PANELS_DRV_HDRS)
	@mkdir -p $(@D)
	$(CC) $(CORE_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/asan/drivers/%.o: drivers/%.c $(PANELS_DRV_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(CORE_ASAN_CFLAGS) -MMD -MP -c $< -o $@

$(PANELS_LIB): $(PANELS_DRV_OBJS)
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

$(PANELS_ASAN_LIB): $(PANELS_DRV_ASAN_OBJS)
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

# --- tests -----------------------------------------------------------------
$(BUILD)/tests/panel/emu/%.o: host_sim/emu/%.c $(wildcard host_sim/emu/*.h) | deps
	@mkdir -p $(@D)
	$(CC) $(PANELS_TEST_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/tests/panel/%.o: tests/panel/%.c $(wildcard host_sim/emu/*.h) $(PANELS_DRV_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PANELS_TEST_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/tests/panel/%: $(BUILD)/tests/panel/%.o $(PANELS_EMU_TEST_OBJS) $(PANELS_ASAN_LIB) $(ASAN_LIB)
	$(CC) $(PANELS_TEST_CFLAGS) -o $@ $< $(PANELS_EMU_TEST_OBJS) $(PANELS_ASAN_LIB) $(ASAN_LIB) \
	    $(PANELS_TEST_LIBS)

.PRECIOUS: $(BUILD)/tests/panel/%.o $(BUILD)/tests/panel/emu/%.o

# Runs only the panel suites.
.PHONY: test-panels check-drivers demo-panel
test-panels: $(PANELS_TEST_BINS) | deps
	@$(SUITE_RUNNER) $(PANELS_TEST_BINS)

# --- freestanding check: the drivers must build for a Cortex-M0 with no
# float, allocator or stdio (reuses the core's checker) ----------------------
$(BUILD)/m0/drivers/%.o: drivers/%.c $(PANELS_DRV_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(M0_CFLAGS) -Wconversion -MMD -MP -c $< -o $@

check-drivers: $(PANELS_DRV_M0_OBJS) | deps
	@ARM_NM='$(ARM_NM)' ARM_SIZE='$(ARM_SIZE)' CC='$(CC)' bash tests/check_core.sh \
	    $(PANELS_DRV_M0_OBJS) 2>&1 | sed 's/check-core/check-drivers/g'; \
	    rc=$${PIPESTATUS[0]}; \
	    for f in drivers/*.[ch] include/zspan/bus.h include/zspan/panel.h; do \
	        if $(CC) -fpreprocessed -dD -E -P -x c "$$f" 2>/dev/null | grep -wqE 'float|double'; then \
	            echo "check-drivers: FAIL: $$f uses float/double"; rc=1; fi; \
	        bad=$$(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*<\([^>]*\)>.*/\1/p' "$$f" | \
	              grep -vxE 'stdint\.h|stddef\.h|string\.h'); \
	        if [ -n "$$bad" ]; then echo "check-drivers: FAIL: $$f includes <$$bad>"; rc=1; fi; \
	    done; \
	    [ $$rc -eq 0 ] && echo "check-drivers: sources use only <stdint.h> <stddef.h> <string.h>"; \
	    exit $$rc

# --- demo: the animated scene through an emulated ST7789 ---------------------
demo-panel: $(SIM) | deps
	@mkdir -p $(OUT)/panel
	$(SIM) panel --panel st7789-240x240 --frames 24 --seq $(OUT)/panel/frame_%03d.png \
	    --out $(OUT)/panel_st7789.png
