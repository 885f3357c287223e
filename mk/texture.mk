# SPDX-License-Identifier: MIT
# mk/texture.mk: texture mapping (src/texture.c, README: Texture mapping).
# tests/core/test_llvmpipe.c compares the textured fill with Mesa's llvmpipe
# through an offscreen OSMesa context (its LIBS line links -lOSMesa).
DEB_PACKAGES += libosmesa6-dev
