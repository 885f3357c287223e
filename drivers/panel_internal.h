/* SPDX-License-Identifier: MIT */
/* Internal helpers shared by the common panel code and the command-set back
 * ends (dcs.c, ssd1351.c). Not installed; not public API. */
#ifndef ZSPAN_DRIVERS_PANEL_INTERNAL_H
#define ZSPAN_DRIVERS_PANEL_INTERNAL_H

#include "zspan/panel.h"

/* A bus result as a panel result: a timeout keeps its own code, every other
 * bus failure is ZS_PANEL_ERR_IO. */
zs_panel_status zs__panel_from_bus(zs_bus_status s);
/* Sends one command; maps bus failures (zs__panel_from_bus). */
zs_panel_status zs__panel_cmd(zs_panel *p, uint8_t cmd, const uint8_t *params, size_t n);
/* Sends yes when on is non-zero, else no (commands without parameters:
 * display on/off, inversion on/off). */
zs_panel_status zs__panel_cmd_if(zs_panel *p, int on, uint8_t yes, uint8_t no);
/* Should the controller invert now? The description's default inversion
 * (a panel wired inverted) flipped by the user's zs_panel_invert. */
int zs__panel_invert_wanted(const zs_panel *p);
/* Runs the description's init records. */
zs_panel_status zs__panel_run_records(zs_panel *p, const uint8_t *rec, size_t len);

#endif
