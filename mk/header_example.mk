# SPDX-License-Identifier: MIT
# mk/header_example.mk: the usage example at the top of include/zspan/zspan.h
# cut out of the header (tests/packaging/header_example.sh), compiled as C99
# with -pedantic -Wall -Wextra -Werror and run against its harness
# (tests/packaging/header_example.c), so that the example cannot go stale.
#
#   make check-header-example   (part of make test)

HEADER_EXAMPLE_DIR := $(BUILD)/tests/header-example
TEST_TARGETS += check-header-example
.PHONY: check-header-example

$(HEADER_EXAMPLE_DIR)/example.c: include/zspan/zspan.h tests/packaging/header_example.sh | deps
	@mkdir -p $(@D)
	sh tests/packaging/header_example.sh $< > $@.tmp && mv $@.tmp $@

$(HEADER_EXAMPLE_DIR)/run: $(HEADER_EXAMPLE_DIR)/example.c tests/packaging/header_example.c $(LIB)
	$(CC) -std=c99 -pedantic -Wall -Wextra -Werror -Iinclude -o $@ \
	    $(HEADER_EXAMPLE_DIR)/example.c tests/packaging/header_example.c $(LIB)

check-header-example: $(HEADER_EXAMPLE_DIR)/run
	@$(HEADER_EXAMPLE_DIR)/run
