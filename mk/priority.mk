# SPDX-License-Identifier: MIT
# mk/priority.mk: list-priority visibility (issue 14, zspan/priority.h). Included by the
# top-level Makefile (docs/BUILD-CONTRACT.md).
#
#   build/tests/core/test_priority   (a core suite) links the host BSP compiler
#                                    app/zs_bsp_build.c (named on its LIBS line)

$(BUILD)/tests/core/test_priority: app/zs_bsp_build.c app/zs_bsp_build.h

# the converter's --bsp
MESHC_APP_SRCS += app/zs_bsp_build.c
$(MESHC): app/zs_bsp_build.c app/zs_bsp_build.h
$(BUILD)/tests/core/test_cull: app/zs_cells_build.c app/zs_cells_build.h

# --- benchmark: the bench scenes in priority mode with BSP order (bench/bench_priority_fw.c)
#   make bench-priority      M4 and M0 code on QEMU mps2-an386 + host: bench/priority.md
#   make check-priority-m4   (make test) frame 0 of every scene: host == M0 == M4 checksums
PRI_BSP_DIR := $(BENCH_BUILD)/bsp
PRI_BSP_NAMES := sphere285 cubes wuson cluster
PRI_BSP_SRCS := $(addprefix $(PRI_BSP_DIR)/bsp_,$(addsuffix .c,$(PRI_BSP_NAMES)))
PRI_BSP_HDRS := $(PRI_BSP_SRCS:.c=.h)
# the bench meshes' conversions (mk/firmware.mk) with --bsp
PRI_BSP_ARGS_sphere285 := --normalize --colors index $(ASSIMP_MODELS)/STL/sphereWithHole.stl
PRI_BSP_ARGS_wuson := --normalize --colors index $(ASSIMP_MODELS)/OBJ/WusonOBJ.obj
PRI_BSP_ARGS_cubes := --quant-scale 8 --colors index $(BENCH_GEN)/cubes.obj
PRI_BSP_ARGS_cluster := --normalize --colors index $(BENCH_GEN)/cluster.obj
$(PRI_BSP_DIR)/bsp_%.c: $(MESHC) $(BENCH_GEN)/cubes.obj $(BENCH_GEN)/cluster.obj | deps
	@mkdir -p $(@D)
	$(MESHC) --bsp -n bsp_$* -o $(basename $@) $(PRI_BSP_ARGS_$*) 2> $(basename $@).log || \
	    { cat $(basename $@).log; exit 1; }
$(PRI_BSP_HDRS): %.h: %.c ;

PRI_APP_SRCS := $(PORT_SRCS) bench/bench_scenes.c $(BENCH_GEN_SRCS)
PRI_INC := -Ibench -I$(BENCH_GEN) -I$(PRI_BSP_DIR)
PRI_FW_M4 := $(FW_BUILD)/bench-priority-mps2-an386.elf
PRI_FW_M0 := $(FW_BUILD)/bench-priority-m0code-mps2-an386.elf
PRI_M4_OBJS := $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PRI_APP_SRCS)) \
               $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o \
               $(FW_BUILD)/m4/pri/bench_priority_fw.o \
               $(patsubst $(PRI_BSP_DIR)/%.c,$(FW_BUILD)/m4/pri/%.o,$(PRI_BSP_SRCS))
PRI_M0_OBJS := $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(PRI_APP_SRCS)) \
               $(FW_BUILD)/m0/app/board_m0code_an386.o \
               $(FW_BUILD)/m0/pri/bench_priority_fw.o \
               $(patsubst $(PRI_BSP_DIR)/%.c,$(FW_BUILD)/m0/pri/%.o,$(PRI_BSP_SRCS))
PRI_HOST := $(BENCH_BUILD)/bench_priority_host
ALL_TARGETS += $(PRI_FW_M4) $(PRI_FW_M0) $(PRI_HOST)
BENCH_TARGETS += bench-priority
TEST_TARGETS += check-priority-m4
.PHONY: bench-priority check-priority-m4

$(FW_BUILD)/m4/pri/bench_priority_fw.o: bench/bench_priority_fw.c $(PRI_BSP_HDRS) $(FW_APP_DEPS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) $(PRI_INC) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/pri/bench_priority_fw.o: bench/bench_priority_fw.c $(PRI_BSP_HDRS) $(FW_APP_DEPS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) $(PRI_INC) -MMD -MP -c $< -o $@
$(FW_BUILD)/m4/pri/bsp_%.o: $(PRI_BSP_DIR)/bsp_%.c $(PRI_BSP_DIR)/bsp_%.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/pri/bsp_%.o: $(PRI_BSP_DIR)/bsp_%.c $(PRI_BSP_DIR)/bsp_%.h | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -MMD -MP -c $< -o $@
$(PRI_FW_M4): $(PRI_M4_OBJS) $(FW_CORE_M4_OBJS) $(PORT_DIR)/ld/mps2-an386.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(PRI_FW_M0): $(PRI_M0_OBJS) $(FW_CORE_M0_OBJS) $(PORT_DIR)/ld/mps2-an386.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null
# the host stand-in for port.h is the portal bench's
$(PRI_HOST): bench/bench_priority_fw.c bench/bench_portals_host.c bench/bench_scenes.c \
             $(BENCH_GEN_SRCS) $(BENCH_GEN)/bench_caps.h $(PRI_BSP_SRCS) $(PRI_BSP_HDRS) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -Iinclude -I$(PORT_DIR) $(PRI_INC) -o $@ \
	    bench/bench_priority_fw.c bench/bench_portals_host.c bench/bench_scenes.c \
	    $(BENCH_GEN_SRCS) $(PRI_BSP_SRCS) $(LIB)

PRI_CHECK := $(BENCH_BUILD)/priority-check
check-priority-m4: $(PRI_FW_M4) $(PRI_FW_M0) $(PRI_HOST) | deps
	@mkdir -p $(PRI_CHECK); rc=0; \
	for cpu in m4 m0; do \
	    elf=$(PRI_FW_M4); test $$cpu = m0 && elf=$(PRI_FW_M0); \
	    $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS),arg=quick -kernel $$elf \
	        > $(PRI_CHECK)/$$cpu.txt 2>&1 || rc=1; \
	    grep '^R ' $(PRI_CHECK)/$$cpu.txt | awk '{print $$3, $$4, $$5, $$7}' > $(PRI_CHECK)/$$cpu.sums; \
	done; \
	BENCH_ARGS=quick $(PRI_HOST) > $(PRI_CHECK)/host.txt || rc=1; \
	grep '^R ' $(PRI_CHECK)/host.txt | awk '{print $$3, $$4, $$5, $$7}' > $(PRI_CHECK)/host.sums; \
	n=$$(wc -l < $(PRI_CHECK)/host.sums); \
	paint=$$(awk '$$2 == "priority-paint" {print $$1, $$3, $$4}' $(PRI_CHECK)/host.sums); \
	band=$$(awk '$$2 == "priority-bsp" {print $$1, $$3, $$4}' $(PRI_CHECK)/host.sums); \
	if [ $$rc = 0 ] && [ $$n = 12 ] && cmp -s $(PRI_CHECK)/m4.sums $(PRI_CHECK)/host.sums && \
	   cmp -s $(PRI_CHECK)/m0.sums $(PRI_CHECK)/host.sums && [ "$$paint" = "$$band" ]; then \
	    echo "check-priority-m4: host == M0 == M4 checksums ($$n frames, span, priority-bsp and" \
	         "priority-paint; painted == rendered)"; \
	else cat $(PRI_CHECK)/m4.txt $(PRI_CHECK)/host.txt; \
	    echo "check-priority-m4: host, M0 and M4 differ or failed"; rc=1; fi; \
	exit $$rc

bench-priority: $(PRI_FW_M4) $(PRI_FW_M0) $(PRI_HOST) $(PRI_BSP_SRCS) $(MESHC) \
                $(CELLS_HOST) $(CELLS_FW_M4) $(CELLS_FW_M0) | deps
	@MESHC=$(MESHC) FW=$(PRI_FW_M4) FW_M0=$(PRI_FW_M0) HOST=$(PRI_HOST) \
	    CELLS_HOST=$(CELLS_HOST) CELLS_FW=$(CELLS_FW_M4) CELLS_FW_M0=$(CELLS_FW_M0) \
	    BSP_DIR=$(PRI_BSP_DIR) ASSIMP_MODELS=$(ASSIMP_MODELS) BENCH_GEN=$(BENCH_GEN) \
	    FW_QEMU="$(FW_QEMU)" FW_QEMU_FLAGS="$(FW_QEMU_FLAGS)" OUT=bench/priority.md \
	    WORK=$(BENCH_BUILD)/priority bash bench/run_priority.sh

# --- a libFuzzer harness of the BSP and cell checks, their walks and the depth sort
ifdef FUZZ_DIR
FUZZ_HARNESSES += priority
# fuzz.mk's rules took their prerequisites before this file added the harness
fuzz fuzz-build test-fuzz-smoke fuzz-merge: $(FUZZ_DIR)/fuzz_priority
$(FUZZ_DIR)/fuzz_priority: tests/fuzz/fuzz_priority.c tests/fuzz/fuzz_util.h $(FUZZ_CORE_LIB) | deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_CORE_LIB)
endif

# --- benchmark: scene cells, k-d tree against uniform grid (bench/bench_cells.c)
#   build/bench/bench_cells               host: build time, culled share, cells visited (table)
#   bench_cells --emit build/bench/cells/cells_data.c   the scenes and cells as C
#   bench-priority runs both and appends the section to bench/priority.md
CELLS_HOST := $(BENCH_BUILD)/bench_cells
CELLS_DIR := $(BENCH_BUILD)/cells
CELLS_DATA := $(CELLS_DIR)/cells_data.c
CELLS_FW_M4 := $(FW_BUILD)/bench-cells-mps2-an386.elf
CELLS_FW_M0 := $(FW_BUILD)/bench-cells-m0code-mps2-an386.elf
CELLS_M4_OBJS := $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
                 $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o \
                 $(FW_BUILD)/m4/cells/bench_cells_fw.o $(FW_BUILD)/m4/cells/cells_data.o
CELLS_M0_OBJS := $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(PORT_SRCS)) \
                 $(FW_BUILD)/m0/app/board_m0code_an386.o \
                 $(FW_BUILD)/m0/cells/bench_cells_fw.o $(FW_BUILD)/m0/cells/cells_data.o
ALL_TARGETS += $(CELLS_HOST) $(CELLS_FW_M4) $(CELLS_FW_M0)

$(CELLS_HOST): bench/bench_cells.c app/zs_cells_build.c app/zs_cells_build.h $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -Iinclude -o $@ bench/bench_cells.c \
	    app/zs_cells_build.c $(LIB) -lm
$(CELLS_DATA): $(CELLS_HOST) | deps
	@mkdir -p $(@D)
	$(CELLS_HOST) --emit $@
$(CELLS_DIR)/cells_data.h: $(CELLS_DATA) ;
$(FW_BUILD)/m4/cells/%.o: bench/%.c $(CELLS_DIR)/cells_data.h $(FW_APP_DEPS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -I$(CELLS_DIR) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/cells/%.o: bench/%.c $(CELLS_DIR)/cells_data.h $(FW_APP_DEPS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -I$(CELLS_DIR) -MMD -MP -c $< -o $@
$(FW_BUILD)/m4/cells/cells_data.o: $(CELLS_DATA) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -I$(CELLS_DIR) -c $< -o $@
$(FW_BUILD)/m0/cells/cells_data.o: $(CELLS_DATA) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -I$(CELLS_DIR) -c $< -o $@
$(CELLS_FW_M4): $(CELLS_M4_OBJS) $(FW_CORE_M4_OBJS) $(PORT_DIR)/ld/mps2-an386.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(CELLS_FW_M0): $(CELLS_M0_OBJS) $(FW_CORE_M0_OBJS) $(PORT_DIR)/ld/mps2-an386.ld $(PORT_DIR)/ld/sections.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld \
	    -o $@ $(filter %.o,$^) $(FW_LIBS) > /dev/null
