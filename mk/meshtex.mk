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
