# SPDX-License-Identifier: MIT
# The core's size-optimised code paths (-Os) must render what the fast ones do.
VARIANT_SRC := tests/variants/gouraud_hash.c

$(BUILD)/variants/hash-%: $(VARIANT_SRC) $(CORE_SRCS) $(wildcard src/*.h include/zspan/*.h) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror $(CORE_REQUIRED_FLAGS) -$* -Iinclude -o $@ $(VARIANT_SRC) \
	    $(CORE_SRCS)

check-size-variant: $(BUILD)/variants/hash-O2 $(BUILD)/variants/hash-Os
	@a=$$($(BUILD)/variants/hash-O2); b=$$($(BUILD)/variants/hash-Os); \
	  echo "check-size-variant: -O2 $$a, -Os $$b"; test "$$a" = "$$b"

.PHONY: check-size-variant
TEST_TARGETS += check-size-variant
