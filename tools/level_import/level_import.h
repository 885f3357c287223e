/* SPDX-License-Identifier: MIT */
/* A portal level from a mesh file whose groups name cells and portals
 * (tools/level_import/level_import.c; README.md, Portal levels). Host only:
 * assimp through the application layer's importer. */
#ifndef ZSPAN_TOOLS_LEVEL_IMPORT_H
#define ZSPAN_TOOLS_LEVEL_IMPORT_H

#include "level.h"

/* Groups cell_NAME and portal_A_B of the file at path; unit level units per
 * world unit (a power of two, 1..256). Returns 0, or -1 with a message. */
int lv_import_mesh(const char *path, int unit, lv_level *lv, char *err, size_t errlen);

#endif
