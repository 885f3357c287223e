# SPDX-License-Identifier: MIT
# mk/ports.mk: the Linux (spidev + libgpiod) and MCP2210 (hidapi) ports and their tests.
# Included by the top-level Makefile (see docs/BUILD-CONTRACT.md and README.md (Linux and USB ports)).
#
#   build/zspan-linux                 spidev / bit-banged SPI + libgpiod (v1 or v2 API)
#   build/zspan-mcp2210               MCP2210 USB-to-SPI bridge through hidapi (hidraw)
#   build/tests/ports/test_mcp2210    MCP2210 protocol against the chip model (in process)
#   build/tests/ports/test_linux      real libgpiod 1.6 + spidev ioctls under umockdev
#   build/tests/ports/test_mcp2210_vm hidapi -> hidraw -> uhid -> chip model -> panel,
#                                     in Debian's kernel under qemu-system-x86_64 (TCG)
#   make test-ports                   only these suites

DEB_PACKAGES += libgpiod-dev libhidapi-dev umockdev libumockdev-dev \
                libglib2.0-dev qemu-system-x86 linux-image-cloud-amd64 busybox-static \
                cpio libcmocka-dev libassimp-dev libpng-dev

PORTS_BUILD := $(BUILD)/ports
PORTS_TEST_BUILD := $(BUILD)/tests/ports

# libgpiod's API generation: v2 has a different API (ZS_GPIOD_V2).
PORTS_GPIOD_DEFS = $(shell $(PKG_CONFIG) --atleast-version=2 libgpiod 2>/dev/null && echo -DZS_GPIOD_V2)
PORTS_WARN := -std=c99 -Wall -Wextra -Werror -g
# A port sees the core, the drivers' headers, the application layer and its
# own directory: never host_sim/ or bench/, nor another port.
PORTS_INC := -Iinclude -Iapp
PORT_INC = -I$(patsubst %/,%,$(dir $<))
PORTS_CFLAGS = $(PORTS_WARN) -O2 $(PORTS_INC) $(PORT_INC) $(PORTS_GPIOD_DEFS) \
               $(shell $(PKG_CONFIG) --cflags libgpiod hidapi-hidraw assimp 2>/dev/null)
PORTS_GPIOD_LIBS = $(shell $(PKG_CONFIG) --libs libgpiod 2>/dev/null || echo -lgpiod)
PORTS_HID_LIBS = $(shell $(PKG_CONFIG) --libs hidapi-hidraw 2>/dev/null || echo -lhidapi-hidraw)
PORTS_ASSIMP_LIBS = $(shell $(PKG_CONFIG) --libs assimp 2>/dev/null || echo -lassimp)
PORTS_PNG_LIBS = $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng)

# The application layer without mesh loading (no assimp), and with it.
PORTS_APP_SRCS_NO_MESH := $(filter-out app/zs_model.c app/zs_import.c,$(APP_SRCS))
PORTS_APP_OBJS := $(patsubst %.c,$(PORTS_BUILD)/obj/%.o,$(APP_SRCS))
PORTS_LINUX_OBJS := $(patsubst %.c,$(PORTS_BUILD)/obj/%.o,ports/linux/linux_bus.c \
                    ports/linux/gpio.c ports/linux/zspan-linux.c)
PORTS_MCP_OBJS := $(patsubst %.c,$(PORTS_BUILD)/obj/%.o,ports/mcp2210/mcp2210.c \
                  ports/mcp2210/mcp2210_hidapi.c ports/mcp2210/zspan-mcp2210.c)
PORTS_HDRS := $(wildcard ports/linux/*.h ports/mcp2210/*.h) include/zspan/bus.h \
              include/zspan/panel.h include/zspan/zspan.h $(APP_HDRS)

ZSPAN_LINUX := $(BUILD)/zspan-linux
ZSPAN_MCP2210 := $(BUILD)/zspan-mcp2210

ALL_TARGETS += $(ZSPAN_LINUX) $(ZSPAN_MCP2210)

$(PORTS_BUILD)/obj/%.o: %.c $(PORTS_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_CFLAGS) -c $< -o $@

$(ZSPAN_LINUX): $(PORTS_LINUX_OBJS) $(PORTS_APP_OBJS) $(PANELS_LIB) $(LIB)
	$(CC) -o $@ $(PORTS_LINUX_OBJS) $(PORTS_APP_OBJS) $(PANELS_LIB) $(LIB) \
	    $(PORTS_GPIOD_LIBS) $(PORTS_ASSIMP_LIBS) -lm

$(ZSPAN_MCP2210): $(PORTS_MCP_OBJS) $(PORTS_APP_OBJS) $(PANELS_LIB) $(LIB)
	$(CC) -o $@ $(PORTS_MCP_OBJS) $(PORTS_APP_OBJS) $(PANELS_LIB) $(LIB) \
	    $(PORTS_HID_LIBS) $(PORTS_ASSIMP_LIBS) -lm

# --- tests ----------------------------------------------------------------------
# The port code and the emulated panel are built with the sanitizers, like the
# other host tests; mesh loading is left out (ZS_APP_NO_MESH: no assimp).
PORTS_TEST_CFLAGS = $(TEST_CFLAGS) -DZS_APP_NO_MESH $(PORTS_INC) -Iports/linux -Iports/mcp2210 \
                    -Ihost_sim/emu -Itests/ports $(PORTS_GPIOD_DEFS)
# The ports' and the app layer's own objects in the tests: without the emulator's headers.
PORTS_TEST_PORT_CFLAGS = $(TEST_CFLAGS) -DZS_APP_NO_MESH $(PORTS_INC) $(PORT_INC) \
                         $(PORTS_GPIOD_DEFS)
PORTS_TEST_COMMON := tests/ports/ports_common.c tests/ports/mcp2210_model.c host_sim/emu/emu.c host_sim/emu/emu_png.c \
                     $(PORTS_APP_SRCS_NO_MESH)
PORTS_TEST_COMMON_OBJS := $(patsubst %.c,$(PORTS_TEST_BUILD)/obj/%.o,$(PORTS_TEST_COMMON))
PORTS_TEST_HDRS := $(PORTS_HDRS) $(wildcard tests/ports/*.h host_sim/emu/*.h)

PORTS_TEST_MCP := $(PORTS_TEST_BUILD)/test_mcp2210
PORTS_TEST_SUITES_ALL := $(PORTS_TEST_MCP)
TEST_SUITES += $(PORTS_TEST_MCP)

$(PORTS_TEST_BUILD)/obj/%.o: %.c $(PORTS_TEST_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_TEST_CFLAGS) -c $< -o $@
$(PORTS_TEST_BUILD)/obj/ports/%.o: ports/%.c $(PORTS_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_TEST_PORT_CFLAGS) -c $< -o $@
$(PORTS_TEST_BUILD)/obj/app/%.o: app/%.c $(PORTS_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_TEST_PORT_CFLAGS) -c $< -o $@

$(PORTS_TEST_MCP): $(PORTS_TEST_BUILD)/obj/tests/ports/test_mcp2210.o \
                   $(PORTS_TEST_BUILD)/obj/ports/mcp2210/mcp2210.o $(PORTS_TEST_COMMON_OBJS) \
                   $(PANELS_ASAN_LIB) $(ASAN_LIB)
	$(CC) $(PORTS_TEST_CFLAGS) -o $@ $(filter %.o,$^) $(PANELS_ASAN_LIB) $(ASAN_LIB) \
	    $(PORTS_PNG_LIBS) $(TEST_LIBS)


# --- the MCP2210 VM test ------------------------------------------------------------
# The model runs in the VM as a static program (no libraries to copy); the
# client is zspan-mcp2210 itself without mesh loading (no assimp in the VM),
# dynamically linked to Debian's hidapi-hidraw.
PORTS_VM_BUILD := $(PORTS_TEST_BUILD)/vm
PORTS_VM_MODEL := $(PORTS_VM_BUILD)/mcp2210-uhid
PORTS_VM_CLIENT := $(PORTS_VM_BUILD)/zspan-mcp2210
PORTS_VM_CFLAGS := $(PORTS_WARN) -O2 -DZS_APP_NO_MESH $(PORTS_INC) -Ihost_sim/emu -Itests/ports
PORTS_VM_CLIENT_CFLAGS := $(PORTS_WARN) -O2 -DZS_APP_NO_MESH $(PORTS_INC) -Iports/mcp2210
PORTS_TEST_VM := $(PORTS_TEST_BUILD)/test_mcp2210_vm
PORTS_TEST_SUITES_ALL += $(PORTS_TEST_VM)
TEST_SUITES += $(PORTS_TEST_VM)

$(PORTS_VM_MODEL): tests/ports/mcp2210_uhid.c tests/ports/mcp2210_model.c host_sim/emu/emu.c \
                   tests/ports/png_stub.c $(PORTS_TEST_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_VM_CFLAGS) -static -o $@ $(filter %.c,$^) -lm

$(PORTS_VM_CLIENT): ports/mcp2210/mcp2210.c ports/mcp2210/mcp2210_hidapi.c \
                    ports/mcp2210/zspan-mcp2210.c $(PORTS_APP_SRCS_NO_MESH) \
                    $(PANELS_LIB) $(LIB) $(PORTS_HDRS) | deps
	@mkdir -p $(@D)
	$(CC) $(PORTS_VM_CLIENT_CFLAGS) -o $@ $(filter %.c,$^) $(PANELS_LIB) $(LIB) $(PORTS_HID_LIBS) -lm

$(PORTS_TEST_VM): $(PORTS_TEST_BUILD)/obj/tests/ports/test_mcp2210_vm.o $(PORTS_TEST_COMMON_OBJS) \
                  $(PANELS_ASAN_LIB) $(ASAN_LIB) $(PORTS_VM_MODEL) $(PORTS_VM_CLIENT) \
                  tests/ports/vm/run_vm.sh tests/ports/vm/init.sh
	$(CC) $(PORTS_TEST_CFLAGS) -o $@ $(filter %.o,$^) $(PANELS_ASAN_LIB) $(ASAN_LIB) \
	    $(PORTS_PNG_LIBS) $(TEST_LIBS)

# --- the Linux port under umockdev (real libgpiod, emulated devices) -------------------
# No sanitizers here: umockdev's LD_PRELOAD library would have to come after
# AddressSanitizer's runtime, which must be first.
PORTS_TEST_LINUX := $(PORTS_TEST_BUILD)/test_linux
PORTS_TEST_SUITES_ALL += $(PORTS_TEST_LINUX)
TEST_SUITES += $(PORTS_TEST_LINUX)
PORTS_UMOCK_CFLAGS = -std=gnu99 -Wall -Wextra -Werror -g -O1 $(PORTS_INC) -Iports/linux \
                     -Ihost_sim/emu -Itests/ports $(PORTS_GPIOD_DEFS) \
                     $(shell $(PKG_CONFIG) --cflags umockdev-1.0 libgpiod libpng 2>/dev/null)
PORTS_UMOCK_LIBS = $(shell $(PKG_CONFIG) --libs umockdev-1.0 2>/dev/null || echo -lumockdev -lgobject-2.0 -lglib-2.0) \
                   $(PORTS_GPIOD_LIBS) $(PORTS_PNG_LIBS)
PORTS_UMOCK_SRCS := tests/ports/test_linux.c tests/ports/ports_common.c host_sim/emu/emu.c \
                    host_sim/emu/emu_png.c app/demo_scene.c
# The port itself is compiled on its own: it sees no test or emulator headers.
PORTS_UMOCK_PORT_SRCS := ports/linux/linux_bus.c ports/linux/gpio.c
PORTS_UMOCK_PORT_CFLAGS = -std=gnu99 -Wall -Wextra -Werror -g -O1 $(PORTS_INC) -Iports/linux \
                          $(PORTS_GPIOD_DEFS) $(shell $(PKG_CONFIG) --cflags libgpiod 2>/dev/null)

# Without umockdev's development files (not root, no `make deps`) the suite is
# replaced by one that skips with the reason.
$(PORTS_TEST_LINUX): $(PORTS_UMOCK_SRCS) $(PORTS_UMOCK_PORT_SRCS) $(PORTS_TEST_HDRS) $(PANELS_LIB) \
                     $(LIB) tests/ports/skip_suite.c | deps
	@mkdir -p $(@D)/umock
	@if $(PKG_CONFIG) --exists umockdev-1.0 libgpiod; then \
	    objs=""; \
	    for f in $(PORTS_UMOCK_PORT_SRCS); do \
	        o=$(@D)/umock/$$(basename $$f .c).o; objs="$$objs $$o"; \
	        $(CC) $(PORTS_UMOCK_PORT_CFLAGS) -c $$f -o $$o || exit 1; \
	    done; \
	    echo "$(CC) $(PORTS_UMOCK_CFLAGS) -o $@ $(PORTS_UMOCK_SRCS) $$objs ..."; \
	    $(CC) $(PORTS_UMOCK_CFLAGS) -o $@ $(PORTS_UMOCK_SRCS) $$objs $(PANELS_LIB) $(LIB) \
	        $(PORTS_UMOCK_LIBS) $(TEST_LIBS); \
	else \
	    echo "test_linux: umockdev-1.0 or libgpiod not found by pkg-config: building a skipping stand-in"; \
	    $(CC) -std=c99 -Wall -Wextra -Werror -o $@ tests/ports/skip_suite.c \
	        -DSKIP_WHAT='"linux port (spidev + libgpiod under umockdev)"' \
	        -DSKIP_WHY='"libumockdev-dev / libgpiod-dev were not installed when it was built (make deps)"' \
	        $(TEST_LIBS); \
	fi

# --- the libgpiod v2 code path: compile-only check against the v2 declarations
# (Debian 12 has only libgpiod 1.6; one check in make test) ---------------------------
TEST_TARGETS += check-gpiod-v2
.PHONY: check-gpiod-v2
check-gpiod-v2: | deps
	@$(CC) $(PORTS_WARN) -Wconversion -DZS_GPIOD_V2 -Itests/ports/gpiod_v2 $(PORTS_INC) \
	    -Iports/linux -fsyntax-only ports/linux/gpio.c && \
	    echo "check-gpiod-v2: ports/linux/gpio.c compiles against the libgpiod v2 API"

# --- only the port suites -------------------------------------------------------------
.PHONY: test-ports
test-ports: $(PORTS_TEST_SUITES_ALL) | deps
	@$(SUITE_RUNNER) $(PORTS_TEST_SUITES_ALL) make:check-gpiod-v2
