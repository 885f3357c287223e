# SPDX-License-Identifier: MIT
# mk/area.mk: issue 15's host side (README: Warnock mode and picking; Ray casting
# and visible regions on the host). Included by the top-level Makefile.
#
#   build/tests/tools/test_area_sim   zspan-sim render --mode raycast and --svg against
#                                     span mode's images and librsvg (TEST_SUITES)
#   make bench-raycast                the ray caster's host cost (callgrind) on scenes of
#                                     4,000 and 40,000 triangles, with and without its grid
#                                     -> bench/raycast.md (BENCH_TARGETS)

DEB_PACKAGES += librsvg2-bin

AREA_TEST_SIM := $(BUILD)/tests/tools/test_area_sim
TEST_SUITES += $(AREA_TEST_SIM)

$(AREA_TEST_SIM): tests/tools/test_area_sim.c tests/tools/sim_run.h tests/tools/run_cmd.h $(SIM) | deps
	@mkdir -p $(@D)
	$(CC) $(CLI_TEST_CFLAGS) -o $@ $< $(CLI_TEST_LIBS)

BENCH_TARGETS += bench-raycast
.PHONY: bench-raycast
bench-raycast: $(SIM) | deps
	bash bench/run_raycast.sh $(SIM) $(BUILD)/bench/raycast bench/raycast.md
