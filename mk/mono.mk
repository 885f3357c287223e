# SPDX-License-Identifier: MIT
# mk/mono.mk: the monochrome panels in `make demo`: the demo scene on an
# emulated SSD1306 (filled with ordered dithering, and as a hidden-line
# drawing) and on an emulated SSD1680 e-paper.
DEMO_TARGETS += demo-mono

.PHONY: demo-mono
demo-mono: $(SIM) | deps
	@mkdir -p $(OUT)
	$(SIM) panel --panel ssd1306-128x64 --out $(OUT)/mono_ssd1306.png \
	    --lines-out $(OUT)/lines_ssd1306.png
	$(SIM) panel --panel ssd1680-122x250 --diffuse --out $(OUT)/mono_ssd1680.png \
	    --lines-out $(OUT)/lines_ssd1680.png

# The vector hidden lines of app/zs_hlines.c against a ray caster.
HLINES_TEST := $(BUILD)/tests/app/test_hlines
TEST_SUITES += $(HLINES_TEST)

$(HLINES_TEST): tests/app/test_hlines.c app/zs_hlines.c app/zs_hlines.h | deps
	@mkdir -p $(@D) $(OUT)
	$(CC) $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -Iapp -o $@ tests/app/test_hlines.c \
	    app/zs_hlines.c $(TEST_LIBS)

# The Linux I2C port through i2c-dev under umockdev (no sanitizers: see
# mk/ports.mk). Without umockdev's files a stand-in skips with the reason.
I2C_TEST := $(BUILD)/tests/ports/test_linux_i2c
TEST_SUITES += $(I2C_TEST)
I2C_TEST_SRCS := tests/ports/test_linux_i2c.c host_sim/emu/emu_mono.c host_sim/emu/emu_png.c \
                 app/demo_scene.c
I2C_TEST_CFLAGS = -std=gnu99 -Wall -Wextra -Werror -g -O1 -Iinclude -Iapp -Iports/linux \
                  -DZT_TOP_DIR='"$(CURDIR)"' \
                  -Ihost_sim/emu $(shell $(PKG_CONFIG) --cflags umockdev-1.0 libpng 2>/dev/null)
I2C_TEST_LIBS = $(shell $(PKG_CONFIG) --libs umockdev-1.0 libpng 2>/dev/null)

$(I2C_TEST): $(I2C_TEST_SRCS) ports/linux/i2c_bus.c ports/linux/zs_linux_i2c.h $(PANELS_LIB) \
             $(LIB) tests/ports/skip_suite.c $(I2C_PROG) | deps
	@mkdir -p $(@D)/i2c
	@if $(PKG_CONFIG) --exists umockdev-1.0; then \
	    $(CC) -std=gnu99 -Wall -Wextra -Werror -g -O1 -Iinclude -Iports/linux \
	        -c ports/linux/i2c_bus.c -o $(@D)/i2c/i2c_bus.o || exit 1; \
	    echo "$(CC) ... -o $@ $(I2C_TEST_SRCS) i2c_bus.o"; \
	    $(CC) $(I2C_TEST_CFLAGS) -o $@ $(I2C_TEST_SRCS) $(@D)/i2c/i2c_bus.o $(PANELS_LIB) $(LIB) \
	        $(I2C_TEST_LIBS) $(TEST_LIBS); \
	else \
	    echo "test_linux_i2c: umockdev-1.0 not found by pkg-config: building a skipping stand-in"; \
	    $(CC) -std=c99 -Wall -Wextra -Werror -o $@ tests/ports/skip_suite.c \
	        -DSKIP_WHAT='"linux port (i2c-dev under umockdev)"' \
	        -DSKIP_WHY='"libumockdev-dev was not installed when it was built (make deps)"' \
	        $(TEST_LIBS); \
	fi

# -DZS_NO_MONO leaves the 1-bit stages (and GRAY4) out of a firmware link: the core's
# objects built that way must not refer to them.
TEST_TARGETS += check-no-mono
.PHONY: check-no-mono
check-no-mono: | deps
	@mkdir -p $(BUILD)/m0-nomono
	@for f in $(filter-out src/mono.c src/lines.c src/gray4.c,$(CORE_SRCS)); do \
	    $(ARM_CC) $(M0_CFLAGS) -Wconversion -DZS_NO_MONO -c $$f \
	        -o $(BUILD)/m0-nomono/$$(basename $$f .c).o || exit 1; done; \
	if $(ARM_NM) -u $(BUILD)/m0-nomono/*.o | grep -E 'zs_(mono|lines|gray4)_'; then \
	    echo "check-no-mono: FAIL: objects built with ZS_NO_MONO call the 1-bit stages"; exit 1; fi; \
	echo "check-no-mono: without the 1-bit stages .text is" \
	    $$($(ARM_SIZE) -t $(BUILD)/m0-nomono/*.o | tail -1 | cut -f1 | tr -d ' ') "bytes (Cortex-M0)"

# zspan-i2c: the demo on an SSD1306/SH1106 over /dev/i2c-N (Raspberry Pi).
I2C_PROG := $(BUILD)/zspan-i2c
ALL_TARGETS += $(I2C_PROG)
# The frame loop is the application layer's (zs_app), as for zspan-linux;
# no mesh loading (ZS_APP_NO_MESH: no assimp on a small board).
I2C_APP_SRCS := $(filter-out app/zs_model.c app/zs_import.c,$(APP_SRCS))
$(I2C_PROG): ports/linux/zspan-i2c.c ports/linux/i2c_bus.c ports/linux/zs_linux_i2c.h \
             $(I2C_APP_SRCS) $(wildcard app/*.h) $(PANELS_LIB) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=gnu99 -Wall -Wextra -Werror -O2 -g -DZS_APP_NO_MESH -Iinclude -Iapp -Iports/linux \
	    -o $@ ports/linux/zspan-i2c.c ports/linux/i2c_bus.c $(I2C_APP_SRCS) $(PANELS_LIB) $(LIB) -lm
