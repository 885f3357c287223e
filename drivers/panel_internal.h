/* Internal interface between the common panel code and the two command-set
 * back ends (generic DCS and SSD1351). Not installed; not public API. */
#ifndef ZSPAN_DRIVERS_PANEL_INTERNAL_H
#define ZSPAN_DRIVERS_PANEL_INTERNAL_H

#include "zspan/panel.h"

/* Sends one command; maps bus failures to ZS_PANEL_ERR_IO. */
zs_panel_status zs__panel_cmd(zs_panel *p, uint8_t cmd, const uint8_t *params, size_t n);
/* Runs the description's init records. */
zs_panel_status zs__panel_run_records(zs_panel *p, const uint8_t *rec, size_t len);

zs_panel_status zs__dcs_init(zs_panel *p);
zs_panel_status zs__dcs_orient(zs_panel *p);
zs_panel_status zs__dcs_invert(zs_panel *p);
zs_panel_status zs__dcs_display(zs_panel *p, int on);
zs_panel_status zs__dcs_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe, uint16_t ye);

zs_panel_status zs__ssd1351_init(zs_panel *p);
zs_panel_status zs__ssd1351_orient(zs_panel *p);
zs_panel_status zs__ssd1351_invert(zs_panel *p);
zs_panel_status zs__ssd1351_display(zs_panel *p, int on);
zs_panel_status zs__ssd1351_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe,
                                   uint16_t ye);
/* The remap (0xA0) parameter for the panel's current orientation and format. */
uint8_t zs__ssd1351_remap(const zs_panel *p);

#endif
