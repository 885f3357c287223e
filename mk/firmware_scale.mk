# SPDX-License-Identifier: MIT
# mk/firmware_scale.mk: the scaling benchmark (how the cost of a frame grows
# with triangles and screen size; bench/bench_scale.c, bench/run_scale.sh).
# It links the bench scenes of mk/firmware.mk and adds its section to that
# bench's bench/results.md, so it is named to be included after it (the
# Makefile includes mk/*.mk sorted by name) and uses its variables.
#
#   build/bench/bench_scale              the program (host, public API only)
#   make bench-scale                     the full run alone -> build/bench/scale/scale.md
#   make bench                           runs it inside bench-firmware (bench/run_bench.sh
#                                        appends "How cost grows" to bench/results.md)
#   build/tests/bench/test_scale_fit     the least-squares fit against oracles (TEST_SUITES)
#   make test-bench-scale                a short run: 6 small cases, 2 frames (TEST_TARGETS)

BENCH_SCALE := $(BENCH_BUILD)/bench_scale
BENCH_SCALE_SRCS := bench/bench_scale.c bench/scale_fit.c
SCALE_FIT_TEST := $(BUILD)/tests/bench/test_scale_fit

ALL_TARGETS += $(BENCH_SCALE)
TEST_SUITES += $(SCALE_FIT_TEST)
TEST_TARGETS += test-bench-scale

.PHONY: bench-scale test-bench-scale

$(BENCH_SCALE): $(BENCH_SCALE_SRCS) bench/scale_fit.h bench/bench_scenes.c bench/bench_scenes.h \
                $(BENCH_GEN)/bench_caps.h $(BENCH_GEN_SRCS) $(BENCH_GEN_HDRS) $(LIB)
	$(CC) $(BENCH_HOST_CFLAGS) -I$(BENCH_GEN) -o $@ $(BENCH_SCALE_SRCS) bench/bench_scenes.c \
	    $(BENCH_GEN_SRCS) $(LIB) -lm

# The firmware bench runs the scaling bench after its own measurements (the
# frames-per-second estimates need its Cortex-M counts) and appends the section.
bench-firmware: $(BENCH_SCALE)
bench-firmware: export BENCH_SCALE_BIN = $(BENCH_SCALE)

bench-scale: $(BENCH_SCALE) | deps
	@BENCH_SCALE=$(BENCH_SCALE) SCALE_WORK=$(BENCH_BUILD)/scale \
	    FW_FILES='$(addprefix $(BENCH_BUILD)/run/,m4.txt m0.txt m0big.txt)' \
	    bash bench/run_scale.sh && cat $(BENCH_BUILD)/scale/scale.md

test-bench-scale: $(BENCH_SCALE) | deps
	@BENCH_SCALE=$(BENCH_SCALE) bash tests/bench/check_scale.sh $(BENCH_BUILD)/scale-quick

$(SCALE_FIT_TEST): tests/bench/test_scale_fit.c bench/scale_fit.c bench/scale_fit.h | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -Ibench -o $@ tests/bench/test_scale_fit.c bench/scale_fit.c \
	    $(TEST_LIBS)
