# SPDX-License-Identifier: MIT
# mk/package.mk: installing the libraries (make install), the pkg-config file, and
# the packaging tests (a project outside the tree that takes zspan in through
# zspan.mk, CMake add_subdirectory / FetchContent, find_package and pkg-config;
# the Arduino library layout). See README.md (Building zspan into your project).
#
#   make install [PREFIX=/usr/local] [DESTDIR=]   libzspan.a, libzspan_drivers.a,
#                 include/zspan/*.h, lib/pkgconfig/zspan.pc (only a C compiler needed)
#   make uninstall [PREFIX=...] [DESTDIR=]
#   build/zspan.pc                                the pkg-config file for $(PREFIX)
#   make test-packaging                           only the packaging checks

DEB_PACKAGES += cmake pkg-config

PREFIX ?= /usr/local
DESTDIR ?=
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
INSTALL ?= install
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig

PKG_PC := $(BUILD)/zspan.pc
PKG_HDRS := $(sort $(wildcard include/zspan/*.h))
# (mk/panels.mk, included after this file, builds it)
PKG_DRIVERS_LIB := $(BUILD)/libzspan_drivers.a

.PHONY: install uninstall test-packaging FORCE-PC

# Rewritten when PREFIX (or the version) changes: the recipe compares.
$(PKG_PC): zspan.pc.in VERSION FORCE-PC
	@mkdir -p $(@D)
	@sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' \
	    -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|' -e 's|@VERSION@|$(ZSPAN_VERSION)|' $< > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; echo "wrote $@"; fi
FORCE-PC:

install: $(LIB) $(PKG_DRIVERS_LIB) $(PKG_PC)
	$(INSTALL) -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCLUDEDIR)/zspan $(DESTDIR)$(PKGCONFIGDIR)
	$(INSTALL) -m 644 $(LIB) $(PKG_DRIVERS_LIB) $(DESTDIR)$(LIBDIR)/
	$(INSTALL) -m 644 $(PKG_HDRS) $(DESTDIR)$(INCLUDEDIR)/zspan/
	$(INSTALL) -m 644 $(PKG_PC) $(DESTDIR)$(PKGCONFIGDIR)/zspan.pc

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/libzspan.a $(DESTDIR)$(LIBDIR)/libzspan_drivers.a \
	    $(DESTDIR)$(PKGCONFIGDIR)/zspan.pc $(addprefix $(DESTDIR)$(INCLUDEDIR)/zspan/,$(notdir $(PKG_HDRS)))
	-rmdir $(DESTDIR)$(INCLUDEDIR)/zspan

# --- the example and the packaging checks ---------------------------------------
PKG_EXAMPLE := $(BUILD)/examples/host-ppm
PKG_WAYS := make subdirectory fetchcontent package pkgconfig
PKG_CHECKS := $(addprefix check-package-,$(PKG_WAYS))
ALL_TARGETS += $(PKG_EXAMPLE)
TEST_TARGETS += $(PKG_CHECKS)
.PHONY: $(PKG_CHECKS)

# The smallest complete program: one frame to a PPM, no dependency but libc.
$(PKG_EXAMPLE): examples/host-ppm/main.c $(LIB)
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -Wconversion -pedantic -O2 -Iinclude -o $@ $< $(LIB)

$(PKG_CHECKS): check-package-%: $(PKG_EXAMPLE) | deps
	@bash tests/packaging/run_external.sh $* $(PKG_EXAMPLE)

test-packaging: $(PKG_CHECKS)

# --- the Arduino library ----------------------------------------------------------
# The library specification's layout (1.5 format): library.properties, src/ compiled
# recursively with src/ on the include path, examples/NAME/NAME.ino (mk/arduino_lib.sh).
# The core needs -fno-strict-aliasing, which a library cannot pass to the Arduino
# build: each source gets the same setting as a pragma on its first line.
ARDUINO_STAGE := $(BUILD)/arduino
ARDUINO_LIB := $(ARDUINO_STAGE)/zspan
ARDUINO_ZIP := $(ARDUINO_STAGE)/zspan-$(ZSPAN_VERSION).zip
ARDUINO_EXAMPLES := $(sort $(wildcard examples/arduino/*/*.ino))
ARDUINO_INPUTS := library.properties VERSION $(CORE_SRCS) $(wildcard src/*.h) \
                  $(wildcard drivers/*.c drivers/*.h) $(PKG_HDRS) $(ARDUINO_EXAMPLES)
.PHONY: arduino-lib arduino-zip check-arduino
arduino-lib: $(ARDUINO_LIB)/library.properties
arduino-zip: $(ARDUINO_ZIP)

$(ARDUINO_LIB)/library.properties: $(ARDUINO_INPUTS) mk/arduino_lib.sh
	bash mk/arduino_lib.sh -o $@ $(CORE_REQUIRED_FLAGS)

$(ARDUINO_ZIP): $(ARDUINO_LIB)/library.properties
	rm -f $@
	cd $(ARDUINO_STAGE) && python3 -c 'import shutil; shutil.make_archive("zspan-$(ZSPAN_VERSION)", "zip", ".", "zspan")'

# The layout rules, library.json, and every example compiled with Debian's
# arduino-builder for an ATmega2560 board (one check).
ARDUINO_FQBN := arduino:avr:mega:cpu=atmega2560
# Then the ST7789 example's Mega 2560 image runs under simavr with an emulated ST7789 on
# its pins (tests/packaging/avr_st7789.c); its first frame must equal, pixel for pixel,
# the same sketch built for the host against a small Arduino stand-in
# (tests/packaging/arduino_host/) driving the same emulated panel.
ARDUINO_AVR_PANEL := $(ARDUINO_STAGE)/avr_st7789
ARDUINO_HOST_CUBE := $(ARDUINO_STAGE)/host-SpinningCubeST7789
ARDUINO_EMU := host_sim/emu/emu.c tests/ports/png_stub.c
$(ARDUINO_AVR_PANEL): tests/packaging/avr_st7789.c $(ARDUINO_EMU) host_sim/emu/emu.h | deps
	@mkdir -p $(@D)
	$(CC) -std=gnu99 -Wall -Wextra -Werror -O2 $$($(PKG_CONFIG) --cflags simavr) -Ihost_sim/emu \
	    -o $@ $(filter %.c,$^) $$($(PKG_CONFIG) --libs simavr || echo -lsimavr) -lelf -lm
$(ARDUINO_HOST_CUBE): examples/arduino/SpinningCubeST7789/SpinningCubeST7789.ino \
                      tests/packaging/arduino_host/host_main.cpp $(wildcard tests/packaging/arduino_host/*.h) \
                      $(ARDUINO_EMU) $(ARDUINO_LIB)/library.properties $(PKG_DRIVERS_LIB) $(LIB) | deps
	@mkdir -p $(@D)/host-obj
	$(CC) -std=c99 -O2 -Ihost_sim/emu -c host_sim/emu/emu.c -o $(@D)/host-obj/emu.o
	$(CC) -std=c99 -O2 -Ihost_sim/emu -c tests/ports/png_stub.c -o $(@D)/host-obj/png_stub.o
	$(CXX) -std=gnu++11 -Wall -Wextra -Werror -O2 -I$(ARDUINO_LIB)/src -Itests/packaging/arduino_host \
	    -Ihost_sim/emu -include Arduino.h -x c++ $< -x none tests/packaging/arduino_host/host_main.cpp \
	    $(@D)/host-obj/emu.o $(@D)/host-obj/png_stub.o $(PKG_DRIVERS_LIB) $(LIB) -o $@

check-arduino: $(ARDUINO_LIB)/library.properties $(ARDUINO_AVR_PANEL) $(ARDUINO_HOST_CUBE) | deps
	@ARDUINO_FQBN=$(ARDUINO_FQBN) ZSPAN_VERSION=$(ZSPAN_VERSION) AVR_ST7789=$(ARDUINO_AVR_PANEL) \
	    HOST_CUBE=$(ARDUINO_HOST_CUBE) \
	    bash tests/packaging/check_arduino.sh $(ARDUINO_LIB) $(ARDUINO_STAGE)/work
TEST_TARGETS += check-arduino
DEB_PACKAGES += arduino-builder arduino-core-avr python3 simavr libsimavr-dev libelf-dev

# --- the Linux SPI and USB examples (on the ports of ports/linux and ports/mcp2210) ---
PKG_EX_LINUX := $(BUILD)/examples/example-linux-spidev
PKG_EX_MCP := $(BUILD)/examples/example-mcp2210-usb
ALL_TARGETS += $(PKG_EX_LINUX) $(PKG_EX_MCP)
PKG_EX_CFLAGS = -std=c99 -Wall -Wextra -Werror -O2 -Iinclude $(PORTS_GPIOD_DEFS)
$(PKG_EX_LINUX): examples/linux-spidev/main.c ports/linux/linux_bus.c ports/linux/gpio.c \
                 ports/linux/zs_linux.h $(PKG_DRIVERS_LIB) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(PKG_EX_CFLAGS) -Iports/linux $$($(PKG_CONFIG) --cflags libgpiod) -o $@ $(filter %.c,$^) \
	    $(PKG_DRIVERS_LIB) $(LIB) $$($(PKG_CONFIG) --libs libgpiod || echo -lgpiod)
$(PKG_EX_MCP): examples/mcp2210-usb/main.c ports/mcp2210/mcp2210.c ports/mcp2210/mcp2210_hidapi.c \
               ports/mcp2210/zs_mcp2210.h $(PKG_DRIVERS_LIB) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(PKG_EX_CFLAGS) -Iports/mcp2210 $$($(PKG_CONFIG) --cflags hidapi-hidraw) -o $@ \
	    $(filter %.c,$^) $(PKG_DRIVERS_LIB) $(LIB) \
	    $$($(PKG_CONFIG) --libs hidapi-hidraw || echo -lhidapi-hidraw)

# Each example starts and reports the missing device as an error (status 1), not a crash.
check-examples: $(PKG_EX_LINUX) $(PKG_EX_MCP) $(PKG_EXAMPLE)
	@out=$$($(PKG_EX_LINUX) /dev/zspan-no-such-spidev gpiochip-none 25 27 2>&1); rc=$$?; \
	    echo "check-examples: example-linux-spidev: $$out (status $$rc)"; test $$rc -eq 1 || exit 1; \
	    out=$$($(PKG_EX_MCP) /dev/zspan-no-such-hidraw 2>&1); rc=$$?; \
	    echo "check-examples: example-mcp2210-usb: $$out (status $$rc)"; test $$rc -eq 1 || exit 1; \
	    out=$$($(PKG_EX_LINUX) 2>&1); rc=$$?; test $$rc -eq 2 || { echo "usage: status $$rc"; exit 1; }
TEST_TARGETS += check-examples
.PHONY: check-examples

# --- the metadata files (ESP-IDF, Zephyr, PlatformIO, Arduino) agree with VERSION -------
check-package-metadata: $(PKG_PC) | deps
	@bash tests/packaging/check_metadata.sh
TEST_TARGETS += check-package-metadata
DEB_PACKAGES += python3-yaml
.PHONY: check-package-metadata
