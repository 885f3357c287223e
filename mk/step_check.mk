# SPDX-License-Identifier: MIT
# mk/step_check.mk: raster.c's edge step (inline assembly on Thumb-2 and Thumb-1, C on
# the host) against the DDA it stands for, on the host, Cortex-M4 (-O2) and Cortex-M0
# code (-Os) under QEMU mps2-an386: each must find no wrong step and all three print
# the same hash (tests/firmware/check_edge_step.c compiles raster.c in; the images
# link the rest of the core).
#   make check-edge-step
ES_DIR := $(BUILD)/tests/edge-step
ES_SRC := tests/firmware/check_edge_step.c
ES_M4_ELF := $(FW_BUILD)/check-edge-step-m4.elf
ES_M0_ELF := $(FW_BUILD)/check-edge-step-m0code.elf
ES_HOST := $(ES_DIR)/host
$(FW_BUILD)/m4/app/tests/firmware/check_edge_step.o: $(ES_SRC) $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) $(FW_M4_OPT) $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/app/tests/firmware/check_edge_step.o: $(ES_SRC) $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) $(FW_M0_OPT) $(FW_COMMON) -MMD -MP -c $< -o $@
$(ES_M4_ELF): $(FW_BUILD)/m4/app/tests/firmware/check_edge_step.o \
              $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
              $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o \
              $(filter-out %/raster.o,$(FW_CORE_M4_OBJS)) $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(ES_M0_ELF): $(FW_BUILD)/m0/app/tests/firmware/check_edge_step.o \
              $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(PORT_SRCS)) \
              $(FW_BUILD)/m0/app/board_m0code_an386.o \
              $(filter-out %/raster.o,$(FW_CORE_M0_OBJS)) $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(ES_HOST): $(ES_SRC) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -MMD -MP $(CORE_REQUIRED_FLAGS) -Iinclude -o $@ $< $(LIB)
check-edge-step: $(ES_M4_ELF) $(ES_M0_ELF) $(ES_HOST) | deps
	@$(ES_HOST) > $(ES_DIR)/host.txt || { cat $(ES_DIR)/host.txt; exit 1; }
	@timeout 300 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(ES_M4_ELF) > $(ES_DIR)/m4.txt 2>&1
	@timeout 300 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(ES_M0_ELF) > $(ES_DIR)/m0.txt 2>&1
	@grep -q '^N .* 0 wrong' $(ES_DIR)/host.txt
	@for t in m4 m0; do cmp -s $(ES_DIR)/host.txt $(ES_DIR)/$$t.txt || \
	    { echo "check-edge-step: host and $$t differ"; \
	      diff $(ES_DIR)/host.txt $(ES_DIR)/$$t.txt | head; exit 1; }; done
	@echo "check-edge-step: host == M4 == M0 ($$(tail -n 1 $(ES_DIR)/host.txt))"
.PHONY: check-edge-step
TEST_TARGETS += check-edge-step
