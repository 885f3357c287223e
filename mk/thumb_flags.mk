# SPDX-License-Identifier: MIT
# mk/thumb_flags.mk: the core's inline assembly (raster.c's edge step, setup.c's
# back-face loops, geometry.c's projection) must build for Cortex-M0 and Cortex-M4
# under the optimisation and frame-pointer flags a firmware project may use: a
# Thumb-1 asm that asks for more low registers than a frame pointer leaves
# ("impossible constraints") fails here, not in the user's build.
#   make check-thumb-flags
THUMB_FLAG_SETS := -O0 -Og -O1 -Os -O2 -O3 -O1_-fno-omit-frame-pointer \
                   -Os_-fno-omit-frame-pointer -O2_-fno-omit-frame-pointer
check-thumb-flags: | deps core-present
	@fail=0; for cpu in cortex-m0 cortex-m4; do for set in $(THUMB_FLAG_SETS); do \
	    opt=$$(printf '%s' "$$set" | tr _ ' '); \
	    for f in $(CORE_SRCS); do \
	        $(ARM_CC) -mcpu=$$cpu -mthumb -mfloat-abi=soft $$opt -std=c99 -ffreestanding \
	            $(CORE_REQUIRED_FLAGS) -Wall -Wextra -Werror -Iinclude -c $$f -o /dev/null \
	            2> $(BUILD)/thumb-flags.err || \
	        { echo "check-thumb-flags: $$f fails for $$cpu $$opt:"; head -4 $(BUILD)/thumb-flags.err; \
	          fail=1; }; \
	    done; done; done; \
	if [ $$fail = 0 ]; then echo "check-thumb-flags: ok (cortex-m0, cortex-m4 x $(words $(THUMB_FLAG_SETS)) flag sets)"; fi; \
	exit $$fail
.PHONY: check-thumb-flags
TEST_TARGETS += check-thumb-flags
