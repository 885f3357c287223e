# SPDX-License-Identifier: MIT
# mk/meshtex.mk: textures in the host tools (tools/zs_teximg.c: a material's
# image found through assimp, decoded with libpng / libjpeg or as TGA,
# resampled to a power of two and converted to the core's formats), linked
# into zspan-meshc, zspan-sim and their fuzzers. Included by the top-level
# Makefile (see README.md: Textures in the converter).

DEB_PACKAGES += libpng-dev libjpeg62-turbo-dev

TEXIMG_SRCS := tools/zs_teximg.c
TEXIMG_LIBS = $(shell $(PKG_CONFIG) --libs libpng libjpeg 2>/dev/null || echo -lpng -ljpeg)

MESHC_APP_SRCS += $(TEXIMG_SRCS)
MESHC_CFLAGS += -Itools $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
MESHC_LIBS += $(TEXIMG_LIBS)
$(MESHC): $(TEXIMG_SRCS) tools/zs_teximg.h

SIM_EXTRA_SRCS += $(TEXIMG_SRCS)
SIM_EXTRA_CFLAGS += -Itools
SIM_EXTRA_LIBS += $(TEXIMG_LIBS)
FUZZ_CLI_LIBS += $(TEXIMG_LIBS)

# Tests: build/tests/tools/test_meshc_tex (TEST_SUITES), tests/tools/test_meshc_tex.c.
# The duck (a 512 x 512 TGA beside it) and tex_planes.obj (--bsp) are converted
# at build time and compiled in; the rest runs the converter and the simulator.
MESHTEX_TEST := $(BUILD)/tests/tools/test_meshc_tex
TEST_SUITES += $(MESHTEX_TEST)
$(TOOLS_TEST_GEN)/t_duck.c: $(MESHC) mk/meshtex.mk | deps
	@mkdir -p $(@D)
	$(MESHC) -q -n t_duck --normalize --texture auto -o $(basename $@) $(ASSIMP_MODELS)/Collada/duck.dae
$(TOOLS_TEST_GEN)/t_texbsp.c: tests/tools/data/tex_planes.obj $(MESHC) mk/meshtex.mk | deps
	@mkdir -p $(@D)
	$(MESHC) -q -n t_texbsp --bsp --texture $(ASSIMP_MODELS)/Collada/duckCM.tga \
	    --texture-size 16 -o $(basename $@) $<
MESHTEX_GEN_SRCS := $(TOOLS_TEST_GEN)/t_duck.c $(TOOLS_TEST_GEN)/t_texbsp.c
$(MESHTEX_GEN_SRCS:.c=.h): %.h: %.c ;
$(MESHTEX_TEST): tests/tools/test_meshc_tex.c tests/tools/run_cmd.h $(MESHTEX_GEN_SRCS) $(MESHTEX_GEN_SRCS:.c=.h) \
                 $(MESHC) $(SIM) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -Wconversion -D_POSIX_C_SOURCE=200809L -I$(TOOLS_TEST_GEN) \
	    $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null) \
	    -DMESHC='"$(MESHC)"' -DSIM='"$(SIM)"' -DASSIMP_MODELS='"$(ASSIMP_MODELS)"' \
	    -DTOOLS_DATA='"tests/tools/data"' -o $@ $< $(MESHTEX_GEN_SRCS) $(ASAN_LIB) \
	    $(TEXIMG_LIBS) $(TEST_LIBS)
.PRECIOUS: $(TOOLS_TEST_GEN)/%.c

# --- make demo: the textured duck (the simulator's own loading) and the converter's
# .zsm of it; the demo's main frame (out/demo.png) is untouched ---------------------
DEMO_TARGETS += demo-texture
.PHONY: demo-texture
demo-texture: $(SIM) $(MESHC) | deps
	@mkdir -p $(OUT)
	$(SIM) render $(ASSIMP_MODELS)/Collada/duck.dae --textures --fit --rotate -15,-40,0 \
	    --eye 0,0,2.6 --shade gouraud --background 101830 --quiet --out $(OUT)/duck_textured.png
	$(MESHC) -q --normalize --normals smooth --texture auto --format zsm -o $(OUT)/duck \
	    $(ASSIMP_MODELS)/Collada/duck.dae
	$(SIM) render $(OUT)/duck.zsm --rotate -15,-40,0 --eye 0,0,2.6 --shade gouraud \
	    --background 101830 --quiet --out $(OUT)/duck_textured_zsm.png

# The converted duck against Mesa's llvmpipe (tests/tools/test_meshc_llvmpipe.c):
# the core tests' helpers (ray caster, setup-hook records) and OSMesa.
MESHTEX_LLVMPIPE := $(BUILD)/tests/tools/test_meshc_llvmpipe
MESHTEX_ZT_OBJS := $(patsubst tests/core/common/%.c,$(BUILD)/tests/core/common/%.o,\
                     $(sort $(wildcard tests/core/common/*.c)))
TEST_SUITES += $(MESHTEX_LLVMPIPE)
$(MESHTEX_LLVMPIPE): tests/tools/test_meshc_llvmpipe.c tests/core/common/zt_gl.h $(TOOLS_TEST_GEN)/t_duck.c \
                     $(TOOLS_TEST_GEN)/t_duck.h $(MESHTEX_ZT_OBJS) $(ASAN_LIB) | deps
	@mkdir -p $(@D)
	$(CC) $(CORE_TEST_CFLAGS) -I$(TOOLS_TEST_GEN) -o $@ $< $(TOOLS_TEST_GEN)/t_duck.c \
	    $(MESHTEX_ZT_OBJS) $(ASAN_LIB) $(CORE_TEST_LIBS) -lOSMesa
