# SPDX-License-Identifier: MIT
# mk/project_m4.mk: the Cortex-M4 projection loop of zs_draw (geometry.c's assembly,
# which the host never builds) against the C loop: vertex-pool hashes of random draws
# on the host and on QEMU mps2-an386 must be equal.
#   make check-project-m4
PROJ_M4_ELF := $(FW_BUILD)/check-project-m4.elf
PROJ_M4_HOST := $(BUILD)/tests/project-m4/host
$(FW_BUILD)/m4/app/tests/firmware/check_project_m4.o: tests/firmware/check_project_m4.c tests/firmware/check_rng.h \
                                                      $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(PROJ_M4_ELF): $(FW_BUILD)/m4/app/tests/firmware/check_project_m4.o \
                $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
                $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o $(FW_CORE_M4_OBJS) \
                $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(PROJ_M4_HOST): tests/firmware/check_project_m4.c tests/firmware/check_rng.h $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -Iinclude -o $@ $< $(LIB)
check-project-m4: $(PROJ_M4_ELF) $(PROJ_M4_HOST) | deps
	@$(PROJ_M4_HOST) > $(BUILD)/tests/project-m4/host.txt
	@timeout 300 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(PROJ_M4_ELF) \
	    > $(BUILD)/tests/project-m4/m4.txt 2>&1
	@grep -q '^N ' $(BUILD)/tests/project-m4/host.txt
	@cmp -s $(BUILD)/tests/project-m4/host.txt $(BUILD)/tests/project-m4/m4.txt || \
	    { echo "check-project-m4: host and M4 vertex pools differ"; \
	      diff $(BUILD)/tests/project-m4/host.txt $(BUILD)/tests/project-m4/m4.txt | head; exit 1; }
	@echo "check-project-m4: ok ($$(tail -n 1 $(BUILD)/tests/project-m4/host.txt))"
.PHONY: check-project-m4
