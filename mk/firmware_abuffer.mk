# SPDX-License-Identifier: MIT
# A-buffer benchmark (issue 17): the standard scenes on the Cortex-M4 image
# with anti-aliasing off and on (bench/bench_aa_fw.c), table in
# bench/results-abuffer.md (make bench-abuffer, part of make bench).
# Included after mk/firmware.mk (its FW_* variables).

FW_BENCH_AA_M4 := $(FW_BUILD)/bench-aa-mps2-an386.elf
FW_BENCH_AA_OBJS := $(filter-out %/bench/bench_fw.o,$(FW_M4_APP_OBJS)) \
                    $(FW_BUILD)/m4/app/bench/bench_aa_fw.o \
                    $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o

ALL_TARGETS += $(FW_BENCH_AA_M4)
BENCH_TARGETS += bench-abuffer

$(FW_BENCH_AA_M4): $(FW_BENCH_AA_OBJS) $(FW_CORE_M4_OBJS) $(PORT_DIR)/ld/mps2-an386.ld \
                   $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null

.PHONY: bench-abuffer
bench-abuffer: $(FW_BENCH_AA_M4) | deps
	@FW_QEMU='$(FW_QEMU)' FW_QEMU_FLAGS='$(FW_QEMU_FLAGS)' FW_AA_M4=$(FW_BENCH_AA_M4) \
	    BENCH_OUT=bench/results-abuffer.md BENCH_WORK=$(BENCH_BUILD)/run-abuffer \
	    bash bench/run_abuffer.sh

# --- make demo: an anti-aliased frame, the same aliased, and a transparent one ------
DEMO_TARGETS += demo-aa
.PHONY: demo-aa check-sim-aa
demo-aa: $(SIM) | deps
	@mkdir -p $(OUT)
	$(SIM) render --quiet --size 240x240 --fit --smooth --out $(OUT)/aa_off.png \
	    $(ASSIMP_MODELS)/OBJ/WusonOBJ.obj
	$(SIM) render --quiet --size 240x240 --fit --smooth --aa --out $(OUT)/aa_edges.png \
	    $(ASSIMP_MODELS)/OBJ/WusonOBJ.obj
	$(SIM) render --quiet --size 240x240 --fit --smooth --aa --opacity 255,120 \
	    --out $(OUT)/aa_transparent.png $(ASSIMP_MODELS)/OBJ/WusonOBJ.obj \
	    $(ASSIMP_MODELS)/OBJ/box.obj

# The options as a user meets them: --aa and --opacity render and report the
# A-buffer; the z-buffer mode refuses --aa (the core's ZS_ERR_MODE); a bad
# --opacity is a usage error.
TEST_TARGETS += check-sim-aa
check-sim-aa: $(SIM) | deps
	@mkdir -p $(BUILD)/tests/sim-aa
	@$(SIM) render --size 96x72 --fit --aa --out $(BUILD)/tests/sim-aa/a.png \
	    $(ASSIMP_MODELS)/OBJ/box.obj | grep -q 'a-buffer: [1-9][0-9]* pixels resolved'
	@$(SIM) render --size 96x72 --fit --aa --opacity 255,100 --out $(BUILD)/tests/sim-aa/t.png \
	    $(ASSIMP_MODELS)/OBJ/box.obj $(ASSIMP_MODELS)/OBJ/box.obj | grep -q 'a-buffer:'
	@if $(SIM) render --quiet --mode zline --aa --out $(BUILD)/tests/sim-aa/z.png \
	    $(ASSIMP_MODELS)/OBJ/box.obj 2> $(BUILD)/tests/sim-aa/z.err; then \
	    echo "check-sim-aa: zline --aa was accepted"; exit 1; fi
	@grep -q 'zs_frame_antialias' $(BUILD)/tests/sim-aa/z.err
	@$(SIM) render --quiet --opacity 300 --out $(BUILD)/tests/sim-aa/u.png \
	    $(ASSIMP_MODELS)/OBJ/box.obj 2> /dev/null; test $$? -eq 2
	@echo "check-sim-aa: ok"

# Host == Cortex-M4 for anti-aliased frames (frame 0 of each scene).
BENCH_AA_HOST := $(BENCH_BUILD)/bench_aa_host
ALL_TARGETS += $(BENCH_AA_HOST)
TEST_TARGETS += check-abuffer-m4
$(BENCH_AA_HOST): bench/bench_aa_host.c bench/bench_scenes.c bench/bench_scenes.h \
                  $(BENCH_GEN_SRCS) $(BENCH_GEN_HDRS) $(BENCH_GEN)/bench_caps.h $(LIB)
	@mkdir -p $(@D)
	$(CC) $(BENCH_HOST_CFLAGS) -I$(BENCH_GEN) -o $@ bench/bench_aa_host.c bench/bench_scenes.c \
	    $(BENCH_GEN_SRCS) $(LIB)
.PHONY: check-abuffer-m4
check-abuffer-m4: $(BENCH_AA_HOST) $(FW_BENCH_AA_M4) | deps
	@mkdir -p $(BUILD)/tests/abuffer-m4
	@$(BENCH_AA_HOST) > $(BUILD)/tests/abuffer-m4/host.txt
	@timeout 300 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS),arg=quick -kernel $(FW_BENCH_AA_M4) \
	    > $(BUILD)/tests/abuffer-m4/m4.txt 2>&1
	@awk '$$1 == "R" { split($$8, a, "="); print $$3, a[2] }' $(BUILD)/tests/abuffer-m4/m4.txt \
	    > $(BUILD)/tests/abuffer-m4/m4sums.txt
	@test -s $(BUILD)/tests/abuffer-m4/host.txt
	@cmp -s $(BUILD)/tests/abuffer-m4/host.txt $(BUILD)/tests/abuffer-m4/m4sums.txt || \
	    { echo "check-abuffer-m4: host and M4 checksums differ"; \
	      diff $(BUILD)/tests/abuffer-m4/host.txt $(BUILD)/tests/abuffer-m4/m4sums.txt; exit 1; }
	@echo "check-abuffer-m4: ok ($$(wc -l < $(BUILD)/tests/abuffer-m4/host.txt) scenes, host == M4)"
