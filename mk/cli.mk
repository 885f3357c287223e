# SPDX-License-Identifier: MIT
# mk/cli.mk: the programs as a user meets them (README.md, "Meshes as they
# come" and "Command-line programs"). Included by the top-level Makefile
# (docs/BUILD-CONTRACT.md).
#
#   build/tests/tools/test_sim         the programs' command lines, files, messages
#   build/tests/tools/test_sim_models  assimp's test models through zspan-sim render
#   build/tests/tools/test_readme      README.md's usage example, extracted and run
#                                      (all three TEST_SUITES)
#   make test-fuzz-cli-smoke   (part of make test) the option-parser fuzzer over
#        its corpus, then FUZZ_CLI_SMOKE_RUNS more runs from a fixed seed
#   make fuzz-cli [FUZZ_CLI_SECONDS=600]   the option-parser fuzzer for that long
#        (logs in build/fuzz/logs/cli.log, crashes in build/fuzz/artifacts/cli/)
#   make readme-images   the README's pictures again (docs/images/)
#   make fuzz-cli-merge  folds build/fuzz/corpus/cli into tests/fuzz/corpus/cli

CLI_TEST_DIR := $(BUILD)/tests/tools
CLI_TEST_SIM := $(CLI_TEST_DIR)/test_sim
CLI_TEST_MODELS := $(CLI_TEST_DIR)/test_sim_models
CLI_TEST_README := $(CLI_TEST_DIR)/test_readme
# The programs under test by absolute path (the suites change directory).
CLI_PROG_DEFS = -DSIM='"$(CURDIR)/$(SIM)"' -DMESHC='"$(CURDIR)/$(BUILD)/zspan-meshc"' \
                -DLINUX_PROG='"$(CURDIR)/$(BUILD)/zspan-linux"' \
                -DMCP2210_PROG='"$(CURDIR)/$(BUILD)/zspan-mcp2210"' \
                -DTOOLS_DATA='"$(CURDIR)/tests/tools/data"' -DTOP='"$(CURDIR)"'
CLI_TEST_CFLAGS = $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L $(CLI_PROG_DEFS) \
                  $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
CLI_TEST_LIBS = $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng) $(TEST_LIBS)

TEST_SUITES += $(CLI_TEST_SIM) $(CLI_TEST_MODELS) $(CLI_TEST_README)
TEST_TARGETS += test-fuzz-cli-smoke

$(CLI_TEST_SIM): tests/tools/test_sim.c tests/tools/sim_run.h tests/tools/run_cmd.h $(SIM) $(BUILD)/zspan-meshc | deps
	@mkdir -p $(@D)
	$(CC) $(CLI_TEST_CFLAGS) -o $@ $< $(CLI_TEST_LIBS)

$(CLI_TEST_MODELS): tests/tools/test_sim_models.c tests/tools/sim_run.h tests/tools/run_cmd.h $(SIM) | deps
	@mkdir -p $(@D)
	$(CC) $(CLI_TEST_CFLAGS) -o $@ $< $(CLI_TEST_LIBS)

# The example is the C block between the readme-snippet markers of README.md,
# compiled as a user would (strict C99, pedantic) against the sanitizer core.
CLI_README_C := $(BUILD)/tests/readme/readme_usage.c
$(CLI_README_C): README.md
	@mkdir -p $(@D)
	@awk '/<!-- readme-snippet: begin -->/ {on = 1; next} /<!-- readme-snippet: end -->/ {on = 0} \
	      on && !/^```/ {print}' $< > $@
	@test -s $@ || { echo "README.md: no readme-snippet block" >&2; rm -f $@; exit 1; }

$(CLI_TEST_README): tests/tools/test_readme.c $(CLI_README_C) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -pedantic -o $@ $< $(CLI_README_C) $(ASAN_LIB) $(TEST_LIBS)

# ---------------------------------------------------------------------------
# The option-parser fuzzer (tests/fuzz/fuzz_cli.c): every program's parser,
# with the simulator, the application layer, the drivers and the port code
# instrumented; the core is mk/fuzz.mk's fuzzing build.
# ---------------------------------------------------------------------------
FUZZ_CLI := $(BUILD)/fuzz/fuzz_cli
FUZZ_CLI_SECONDS ?= 600
FUZZ_CLI_SMOKE_RUNS ?= 3000
# Deferred (=, and the link rule's prerequisites by second expansion): the
# simulator's extra sources and flags (SIM_EXTRA_*) and the fuzzing core come
# from mk files included after this one.
FUZZ_CLI_SRCS = $(sort tests/fuzz/fuzz_cli.c $(filter-out host_sim/sim_main.c,$(wildcard host_sim/*.c)) \
                $(wildcard host_sim/emu/*.c) $(APP_SRCS) $(wildcard drivers/*.c) \
                ports/linux/linux_bus.c ports/linux/gpio.c ports/mcp2210/mcp2210.c \
                ports/mcp2210/mcp2210_hidapi.c $(SIM_EXTRA_SRCS))
FUZZ_CLI_PROGS := SIM MESHC LINUX MCP2210
FUZZ_CLI_INC = -Iinclude -Iapp -Ihost_sim -Iports/linux -Iports/mcp2210 -Itests/fuzz \
               $(filter -I%,$(SIM_EXTRA_CFLAGS))
FUZZ_CLI_CFLAGS = -std=c99 -Wall -Wextra -Werror -g -O1 -D_POSIX_C_SOURCE=200809L \
                  -fsanitize=address,undefined -fno-sanitize-recover=all \
                  $(FUZZ_CLI_INC) $(PORTS_GPIOD_DEFS) \
                  $(shell $(PKG_CONFIG) --cflags assimp libpng libgpiod hidapi-hidraw 2>/dev/null)
FUZZ_CLI_LIBS = $(shell $(PKG_CONFIG) --libs assimp libpng libgpiod hidapi-hidraw 2>/dev/null) \
                -lSDL2 -lm
FUZZ_CLI_OBJS = $(patsubst %.c,$(BUILD)/fuzz/cli/%.o,$(FUZZ_CLI_SRCS)) \
                 $(foreach p,$(FUZZ_CLI_PROGS),$(BUILD)/fuzz/cli/progs_$(p).o)
FUZZ_CLI_FLAGS := -close_fd_mask=3 -dict=tests/fuzz/cli.dict -max_len=512 -timeout=20

$(BUILD)/fuzz/cli/%.o: %.c | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CLI_CFLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@
$(BUILD)/fuzz/cli/progs_%.o: tests/fuzz/fuzz_cli_progs.c | deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CLI_CFLAGS) -Wno-unused-function -fsanitize=fuzzer-no-link -DPROG_$* \
	    -MMD -MP -c $< -o $@
.SECONDEXPANSION:
$(FUZZ_CLI): $$(FUZZ_CLI_OBJS) $$(FUZZ_CORE_LIB) | deps
	$(FUZZ_CC) $(FUZZ_CLI_CFLAGS) -fsanitize=fuzzer -o $@ $(FUZZ_CLI_OBJS) $(FUZZ_CORE_LIB) \
	    $(FUZZ_CLI_LIBS)

.PHONY: fuzz-cli test-fuzz-cli-smoke
fuzz-cli: $(FUZZ_CLI) | deps
	@mkdir -p $(BUILD)/fuzz/logs $(BUILD)/fuzz/corpus/cli $(BUILD)/fuzz/artifacts/cli
	@echo "fuzz-cli: $(FUZZ_CLI_SECONDS) s (log $(BUILD)/fuzz/logs/cli.log)"
	@if $(FUZZ_CLI) $(FUZZ_CLI_FLAGS) -max_total_time=$(FUZZ_CLI_SECONDS) -print_final_stats=1 \
	    -artifact_prefix=$(BUILD)/fuzz/artifacts/cli/ $(BUILD)/fuzz/corpus/cli tests/fuzz/corpus/cli \
	    > $(BUILD)/fuzz/logs/cli.log 2>&1; then \
	    grep -E 'cov: ' $(BUILD)/fuzz/logs/cli.log | tail -1; \
	    grep -E '^(stat::|Done )' $(BUILD)/fuzz/logs/cli.log; \
	else \
	    echo "fuzz-cli: FAILED, see $(BUILD)/fuzz/logs/cli.log and $(BUILD)/fuzz/artifacts/cli/"; \
	    tail -30 $(BUILD)/fuzz/logs/cli.log; exit 1; \
	fi

test-fuzz-cli-smoke: $(FUZZ_CLI) | deps
	@out=$(BUILD)/fuzz/smoke/cli; rm -rf $$out; mkdir -p $$out $(BUILD)/fuzz/artifacts/smoke-cli; \
	n=$$(ls tests/fuzz/corpus/cli | wc -l); \
	if $(FUZZ_CLI) $(FUZZ_CLI_FLAGS) -runs=$$(( n + $(FUZZ_CLI_SMOKE_RUNS) )) -seed=1 \
	    -artifact_prefix=$(BUILD)/fuzz/artifacts/smoke-cli/ $$out tests/fuzz/corpus/cli \
	    > $(BUILD)/fuzz/smoke/cli.log 2>&1; then \
	    echo "test-fuzz-cli-smoke: ok ($$n seeds + $(FUZZ_CLI_SMOKE_RUNS) runs)"; \
	else \
	    echo "test-fuzz-cli-smoke: FAILED ($(BUILD)/fuzz/smoke/cli.log):"; tail -30 $(BUILD)/fuzz/smoke/cli.log; \
	    exit 1; \
	fi

-include $(shell find $(BUILD)/fuzz/cli -name '*.d' 2>/dev/null)

# The README's pictures (docs/images/): the demo and assimp's duck.
.PHONY: readme-images
readme-images: $(SIM) | deps
	$(SIM) demo --no-compare --out docs/images/demo.png
	$(SIM) render /usr/share/assimp/models/Collada/duck.dae --fit --rotate -15,-40,0 --eye 0,0,2.6 \
	    --shade gouraud --background 101830 --out docs/images/duck.png --quiet

# Folds build/fuzz/corpus/cli into the checked-in corpus (inputs that add coverage).
.PHONY: fuzz-cli-merge
fuzz-cli-merge: $(FUZZ_CLI) | deps
	@mkdir -p $(BUILD)/fuzz/corpus/cli
	@$(FUZZ_CLI) -close_fd_mask=3 -merge=1 -max_len=512 tests/fuzz/corpus/cli \
	    $(BUILD)/fuzz/corpus/cli 2>&1 | grep -E 'MERGE-OUTER: [0-9]+ new files'
