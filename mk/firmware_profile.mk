# SPDX-License-Identifier: MIT
# mk/firmware_profile.mk: where a frame's instructions go, by pipeline stage
# (bench/run_profile.sh -> bench/profile.md), from the firmware bench images of
# mk/firmware.mk (named to be included after it) run under the per-PC counting
# plugin of ../shared/tools/qemu-pcprof. Part of make bench; skipped with a
# message where ../shared is not beside the tree.
#
#   make bench-profile    M4 span and zline, M0 code span: a table each

PCPROF_SRC := ../shared/tools/qemu-pcprof/pcprof.c
PCPROF_SO := $(BENCH_BUILD)/profile/pcprof.so

BENCH_TARGETS += bench-profile
.PHONY: bench-profile

$(PCPROF_SO): $(PCPROF_SRC) | deps
	@mkdir -p $(@D)
	$(CC) -shared -fPIC -O2 -o $@ $<

ifneq ($(wildcard $(PCPROF_SRC)),)
bench-profile: $(PCPROF_SO) $(FW_BENCH_M4) $(FW_BENCH_M0BIG) | deps
	@FW_M4=$(FW_BENCH_M4) FW_M0BIG=$(FW_BENCH_M0BIG) M4_OBJS=$(FW_BUILD)/m4/core \
	    M0_OBJS=$(FW_BUILD)/m0/core FW_QEMU='$(FW_QEMU)' FW_QEMU_FLAGS='$(FW_QEMU_FLAGS)' \
	    PCPROF_SO=$(PCPROF_SO) PROFILE_OUT=bench/profile.md PROFILE_WORK=$(BENCH_BUILD)/profile \
	    bash bench/run_profile.sh
else
bench-profile:
	@echo "bench-profile: skipped: $(PCPROF_SRC) is not there (../shared beside the tree)"
endif
