/* SPDX-License-Identifier: MIT */
/*
 * Partial updates of the animated programs (--partial): only the parts of a
 * frame that changed since the last one go to the panel.
 */
#ifndef ZSPAN_APP_PARTIAL_H
#define ZSPAN_APP_PARTIAL_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/panel.h"

/* Sends the rectangles of `cur` that differ from `prev` (everything when
 * prev is NULL): runs of changed rows (gaps of up to 2 unchanged rows are
 * merged, as a new window costs more than two short rows), each narrowed to
 * the columns that changed in it; tmp (tmp_bytes, at least one row) gathers
 * the pixels of a window. Returns rows sent, or -1 with *ps on a bus error. */
long zs_app_send_changes(zs_panel *lcd, const uint8_t *cur, const uint8_t *prev, size_t stride,
                         unsigned bpp, uint8_t *tmp, size_t tmp_bytes, zs_panel_status *ps);

#endif /* ZSPAN_APP_PARTIAL_H */
