# SPDX-License-Identifier: MIT
# mk/texture.mk: texture mapping (src/texture.c, README: Texture mapping).
# tests/core/test_llvmpipe.c compares the textured fill with Mesa's llvmpipe
# through an offscreen OSMesa context (its LIBS line links -lOSMesa).
DEB_PACKAGES += libosmesa6-dev

# make bench: the textured scene's cost on Cortex-M4 and M0 (bench/run_texture.sh
# writes its section of bench/results.md, after bench-firmware rewrote the file).
BENCH_TARGETS += bench-texture
.PHONY: bench-texture
bench-texture: $(BENCH_HOST) $(FW_BENCH_M4) $(FW_BENCH_M0) $(FW_CORE_M0_OBJS) \
               $(FW_CORE_M4_OBJS) | deps
	@BENCH_HOST=$(BENCH_HOST) FW_M4=$(FW_BENCH_M4) FW_M0=$(FW_BENCH_M0) \
	    FW_QEMU='$(FW_QEMU)' FW_QEMU_FLAGS='$(FW_QEMU_FLAGS)' ARM_SIZE=$(ARM_SIZE) \
	    CORE_M0_OBJS='$(FW_CORE_M0_OBJS)' CORE_M4_OBJS='$(FW_CORE_M4_OBJS)' \
	    BENCH_OUT=bench/results.md BENCH_WORK=$(BUILD)/bench/texture \
	    bash bench/run_texture.sh
