# SPDX-License-Identifier: MIT
# mk/xtarget.mk: whole frames of random scenes (tests/firmware/check_frames_xtarget.c) on
# the host, on Cortex-M4 (core -O2) and on Cortex-M0 code (core -Os) under QEMU mps2-an386:
# the three lists of frame hashes and statistics must be identical (part of make test).
#   make check-frames-xtarget
XT_DIR := $(BUILD)/tests/xtarget
XT_SRC := tests/firmware/check_frames_xtarget.c
XT_HDR := tests/firmware/check_rng.h
XT_M4_ELF := $(FW_BUILD)/check-frames-m4.elf
XT_M0_ELF := $(FW_BUILD)/check-frames-m0code.elf
XT_HOST := $(XT_DIR)/host
$(FW_BUILD)/m4/app/tests/firmware/check_frames_xtarget.o: $(XT_SRC) $(XT_HDR) $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M4_CPU) -O2 $(FW_COMMON) -MMD -MP -c $< -o $@
$(FW_BUILD)/m0/app/tests/firmware/check_frames_xtarget.o: $(XT_SRC) $(XT_HDR) $(PORT_HDRS) | deps
	@mkdir -p $(@D)
	$(ARM_CC) $(FW_M0_CPU) -Os $(FW_COMMON) -MMD -MP -c $< -o $@
$(XT_M4_ELF): $(FW_BUILD)/m4/app/tests/firmware/check_frames_xtarget.o \
              $(patsubst %.c,$(FW_BUILD)/m4/app/%.o,$(PORT_SRCS)) \
              $(FW_BUILD)/m4/app/$(PORT_DIR)/board_mps2_an386.o $(FW_CORE_M4_OBJS) \
              $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M4_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(XT_M0_ELF): $(FW_BUILD)/m0/app/tests/firmware/check_frames_xtarget.o \
              $(patsubst %.c,$(FW_BUILD)/m0/app/%.o,$(PORT_SRCS)) \
              $(FW_BUILD)/m0/app/board_m0code_an386.o $(FW_CORE_M0_OBJS) \
              $(PORT_DIR)/ld/mps2-an386.ld
	$(ARM_CC) $(FW_M0_CPU) -mthumb $(FW_LDFLAGS) -T $(PORT_DIR)/ld/mps2-an386.ld -o $@ \
	    $(filter %.o,$^) $(FW_LIBS) > /dev/null
$(XT_HOST): $(XT_SRC) $(XT_HDR) $(LIB) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror -O2 -Iinclude -o $@ $< $(LIB)
check-frames-xtarget: $(XT_M4_ELF) $(XT_M0_ELF) $(XT_HOST) | deps
	@$(XT_HOST) > $(XT_DIR)/host.txt || { tail -3 $(XT_DIR)/host.txt; exit 1; }
	@timeout 600 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(XT_M4_ELF) > $(XT_DIR)/m4.txt 2>&1
	@timeout 600 $(FW_QEMU) -M mps2-an386 $(FW_QEMU_FLAGS) -kernel $(XT_M0_ELF) > $(XT_DIR)/m0.txt 2>&1
	@grep -q '^N ' $(XT_DIR)/host.txt
	@for t in m4 m0; do cmp -s $(XT_DIR)/host.txt $(XT_DIR)/$$t.txt || \
	    { echo "check-frames-xtarget: host and $$t differ"; \
	      diff $(XT_DIR)/host.txt $(XT_DIR)/$$t.txt | head; exit 1; }; done
	@echo "check-frames-xtarget: host == M4 == M0 ($$(tail -n 1 $(XT_DIR)/host.txt))"
.PHONY: check-frames-xtarget
TEST_TARGETS += check-frames-xtarget check-project-m4 check-indices-m4
