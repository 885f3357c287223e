# mk/portals.mk: portal levels (zspan/portal.h, src/portal.c). Included by the
# top-level Makefile (see docs/BUILD-CONTRACT.md and README.md (Portal levels)).
#
#   build/zspan-level                  level files -> PVS -> C arrays; random levels
#   build/tests/tools/test_level       format, PVS, conservativeness, frame equality (TEST_SUITES)
#   make check-portals-full            the long run: 100 eye positions per cell, every frame
#   zspan-sim walk LEVEL               (host_sim/walk_cmd.c) a scripted flight, PNG frames

LEVEL_TOOL := $(BUILD)/zspan-level
LEVEL_LIB_SRCS := $(sort $(wildcard tools/level/*.c))
LEVEL_LIB_HDRS := tools/level/level.h include/zspan/portal.h
LEVEL_CFLAGS := -std=c99 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L -O2 -g -Iinclude -Itools/level
LEVEL_TEST := $(BUILD)/tests/tools/test_level

ALL_TARGETS += $(LEVEL_TOOL)
TEST_SUITES += $(LEVEL_TEST)
SIM_EXTRA_SRCS += $(LEVEL_LIB_SRCS)
SIM_EXTRA_CFLAGS += -Itools/level

.PHONY: check-portals-full

$(LEVEL_TOOL): tools/zspan-level.c $(LEVEL_LIB_SRCS) $(LEVEL_LIB_HDRS) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(LEVEL_CFLAGS) -o $@ tools/zspan-level.c $(LEVEL_LIB_SRCS) $(LIB)

$(LEVEL_TEST): tests/tools/test_level.c $(LEVEL_LIB_SRCS) $(LEVEL_LIB_HDRS) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -Itools/level -DZT_TOP_DIR='"$(CURDIR)"' \
	    -o $@ tests/tools/test_level.c $(LEVEL_LIB_SRCS) $(ASAN_LIB) $(TEST_LIBS)

check-portals-full: $(LEVEL_TEST)
	LEVEL_TEST_FULL=1 $(LEVEL_TEST)
