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

# Cortex-M0's products from 32-bit halves (src/zs_internal.h, ZS_SPLIT_PRODUCTS)
# must equal the plain ones: helper checks plus a hash of random scenes, built
# with and without them.
SPLIT_SRC := tests/variants/split_products.c
$(BUILD)/variants/split-%: $(SPLIT_SRC) $(CORE_SRCS) $(wildcard src/*.h include/zspan/*.h) | deps
	@mkdir -p $(@D)
	$(CC) -std=c99 -Wall -Wextra -Werror $(CORE_REQUIRED_FLAGS) -O2 $(if $(filter split,$*),-DZS_SPLIT_PRODUCTS) \
	    -Iinclude -o $@ $(SPLIT_SRC) $(CORE_SRCS)

check-split-products: $(BUILD)/variants/split-plain $(BUILD)/variants/split-split
	@a=$$($(BUILD)/variants/split-plain) && b=$$($(BUILD)/variants/split-split) && \
	  echo "check-split-products: plain $$a, split $$b" && test "$$a" = "$$b"

.PHONY: check-split-products
TEST_TARGETS += check-split-products
