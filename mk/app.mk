# SPDX-License-Identifier: MIT
# mk/app.mk: tests of the application layer (app/). Included by the top-level
# Makefile (see docs/BUILD-CONTRACT.md and README.md (Architecture)).
#
#   build/tests/app/test_app   options, sizing, the panel programs' command line,
#                              the demo scene's frame steps (TEST_SUITES)

APP_TEST := $(BUILD)/tests/app/test_app
# Without mesh loading (no assimp): the rest of app/ and the drivers (the
# frame loop's panel listing), with the sanitizers.
APP_TEST_SRCS := tests/app/test_app.c $(filter-out app/zs_model.c app/zs_import.c,$(APP_SRCS))

TEST_SUITES += $(APP_TEST)

# mk/panels.mk (included after this file) builds the drivers' sanitizer
# library: named by its path, as a prerequisite has to exist when read.
APP_TEST_DRV_LIB := $(BUILD)/asan/libzspan_drivers.a
$(APP_TEST): $(APP_TEST_SRCS) $(APP_HDRS) $(APP_TEST_DRV_LIB) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -DZS_APP_NO_MESH -Iapp -o $@ $(APP_TEST_SRCS) \
	    $(APP_TEST_DRV_LIB) $(ASAN_LIB) $(TEST_LIBS)
