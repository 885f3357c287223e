# SPDX-License-Identifier: MIT
# mk/priority.mk: list-priority visibility (issue 14, zspan/priority.h). Included by the
# top-level Makefile (docs/BUILD-CONTRACT.md).
#
#   build/tests/core/test_priority   (a core suite) links the host BSP compiler
#                                    app/zs_bsp_build.c (named on its LIBS line)

$(BUILD)/tests/core/test_priority: app/zs_bsp_build.c app/zs_bsp_build.h

# the converter's --bsp
MESHC_APP_SRCS += app/zs_bsp_build.c
$(MESHC): app/zs_bsp_build.c app/zs_bsp_build.h
$(BUILD)/tests/core/test_cull: app/zs_cells_build.c app/zs_cells_build.h
