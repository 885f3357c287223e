# zspan.mk: zspan's sources and flags for another project's Makefile (GNU make).
#
#     ZSPAN_DIR := path/to/zspan          # optional: defaults to this file's directory
#     include $(ZSPAN_DIR)/zspan.mk
#
#     CFLAGS += $(ZSPAN_INCLUDES)
#     $(ZSPAN_OBJS_DIR)/%.o: ...          # or list $(ZSPAN_SRCS) with your own sources
#
# Defines, and changes nothing else (no rules unless ZSPAN_BUILD is set):
#
#   ZSPAN_DIR              the tree (absolute)
#   ZSPAN_CORE_SRCS        the renderer: src/*.c (freestanding C99: only a C compiler)
#   ZSPAN_DRIVER_SRCS      the panel drivers and bus layer: drivers/*.c (freestanding too)
#   ZSPAN_SRCS             both
#   ZSPAN_INCLUDES         -I for the public headers (zspan/zspan.h, zspan/bus.h, zspan/panel.h)
#   ZSPAN_REQUIRED_CFLAGS  flags the zspan sources must be compiled with, whatever else you
#                          pass: -fno-strict-aliasing (the core keeps its own record types in
#                          the caller's arena, whatever type the caller declared it with)
#   ZSPAN_FEATURES         (yours to set before the include; empty by default) features to
#                          leave out as -D flags, e.g. -DZS_LEAN or -DZS_NO_TEXTURE
#                          (include/zspan/zspan.h); give them to your own files too
#   ZSPAN_CFLAGS           $(ZSPAN_INCLUDES) $(ZSPAN_REQUIRED_CFLAGS) $(ZSPAN_FEATURES): for
#                          the zspan sources
#   ZSPAN_VERSION          the version (file VERSION)
#
# With ZSPAN_BUILD set to a directory, it also gives rules for two archives there,
# $(ZSPAN_BUILD)/libzspan.a and $(ZSPAN_BUILD)/libzspan_drivers.a (variables ZSPAN_LIB and
# ZSPAN_DRIVERS_LIB), compiled with $(CC) $(CFLAGS) $(ZSPAN_CFLAGS).

ZSPAN_DIR ?= $(patsubst %/,%,$(dir $(abspath $(lastword $(MAKEFILE_LIST)))))
ZSPAN_CORE_SRCS := $(sort $(wildcard $(ZSPAN_DIR)/src/*.c))
ZSPAN_DRIVER_SRCS := $(sort $(wildcard $(ZSPAN_DIR)/drivers/*.c))
ZSPAN_SRCS := $(ZSPAN_CORE_SRCS) $(ZSPAN_DRIVER_SRCS)
ZSPAN_INCLUDES := -I$(ZSPAN_DIR)/include
ZSPAN_REQUIRED_CFLAGS := -fno-strict-aliasing
ZSPAN_FEATURES ?=
ZSPAN_CFLAGS := $(ZSPAN_INCLUDES) $(ZSPAN_REQUIRED_CFLAGS) $(ZSPAN_FEATURES)
ZSPAN_VERSION := $(strip $(file < $(ZSPAN_DIR)/VERSION))

ifneq ($(strip $(ZSPAN_BUILD)),)
# These rules must not become the including Makefile's default goal.
zspan_saved_goal := $(.DEFAULT_GOAL)
ZSPAN_LIB := $(ZSPAN_BUILD)/libzspan.a
ZSPAN_DRIVERS_LIB := $(ZSPAN_BUILD)/libzspan_drivers.a
ZSPAN_CORE_OBJS := $(patsubst $(ZSPAN_DIR)/src/%.c,$(ZSPAN_BUILD)/zspan/core/%.o,$(ZSPAN_CORE_SRCS))
ZSPAN_DRIVER_OBJS := $(patsubst $(ZSPAN_DIR)/drivers/%.c,$(ZSPAN_BUILD)/zspan/drivers/%.o,$(ZSPAN_DRIVER_SRCS))
ZSPAN_HDRS := $(wildcard $(ZSPAN_DIR)/include/zspan/*.h $(ZSPAN_DIR)/src/*.h $(ZSPAN_DIR)/drivers/*.h)

$(ZSPAN_BUILD)/zspan/core/%.o: $(ZSPAN_DIR)/src/%.c $(ZSPAN_HDRS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(ZSPAN_CFLAGS) -c $< -o $@
$(ZSPAN_BUILD)/zspan/drivers/%.o: $(ZSPAN_DIR)/drivers/%.c $(ZSPAN_HDRS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(ZSPAN_CFLAGS) -c $< -o $@
$(ZSPAN_LIB): $(ZSPAN_CORE_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^
$(ZSPAN_DRIVERS_LIB): $(ZSPAN_DRIVER_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^
.DEFAULT_GOAL := $(zspan_saved_goal)
endif
