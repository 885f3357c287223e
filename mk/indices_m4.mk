# SPDX-License-Identifier: MIT
# mk/indices_m4.mk: the Cortex-M4 index check of zs_draw (geometry.c's SIMD path, which
# the host never builds) against its rule, on QEMU mps2-an386.
#   make check-indices-m4
IDX_M4_ELF := $(FW_BUILD)/check-indices-m4.elf
$(FW_BUILD)/m4/app/tests/firmware/check_indices_m4.o: tests/firmware/check_indices_m4.c \
                                                      $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(IDX_M4_ELF): $(FW_BUILD)/m4/app/tests/firmware/check_indices_m4.o \
               $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
               $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o $(FW_CORE_M4_OBJS) \
               $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
check-indices-m4: $(IDX_M4_ELF) | deps
	$(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(IDX_M4_ELF)
.PHONY: check-indices-m4
