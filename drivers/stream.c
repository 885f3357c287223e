/* SPDX-License-Identifier: MIT */
/* zspan frame streaming: render band k into one buffer while band k-1 is on
 * the bus, and account for the frame's wire traffic. */
#include "panel_internal.h"

/* The renderer's size and the frame's format. The core has no accessors for
 * them; zs_renderer is public so it can be allocated statically, and its
 * config and shading are the caller's own zs_config / zs_shade_params. */
static zs_panel_status frame_fits(const zs_panel *p, const zs_renderer *r)
{
    if (r->cfg.width != p->width || r->cfg.height != p->height)
        return ZS_PANEL_ERR_SIZE;
    if (zs_frame_format(r) != p->format)
        return ZS_PANEL_ERR_FRAME_FORMAT;
    return ZS_PANEL_OK;
}

zs_panel_status zs_panel_stream(zs_panel *p, zs_renderer *r, uint8_t *buf0, uint8_t *buf1,
                                size_t buf_bytes, int band_rows, const zs_wire_model *wire,
                                zs_panel_frame_stats *stats)
{
    zs_panel_frame_stats local;
    zs_panel_frame_stats *st = stats != NULL ? stats : &local;
    zs_bus_counters before;
    uint8_t *bufs[2];
    const uint8_t *last_sent = NULL;
    size_t stride, fit;
    int band, y, k = 0, page = p->format == ZS_FMT_MONO_PAGE;
    zs_panel_status s;

    if (p == NULL || r == NULL || buf0 == NULL || p->bus == NULL)
        return ZS_PANEL_ERR_NULL;
    st->bands = 0;
    st->wire_waits = 0;
    st->wire_ns = 0;
    st->bytes = 0;
    st->render_status = ZS_OK;
    if (!p->ready)
        return ZS_PANEL_ERR_STATE;
    if ((s = frame_fits(p, r)) != ZS_PANEL_OK)
        return s;
    /* a buffer row: one row of pixels, or one page of 8 rows */
    stride = (size_t)zs_panel_window_bytes(p->format, p->width, 1); /* one row: small */
    if (stride == 0 || buf_bytes < stride || band_rows < 1)
        return ZS_PANEL_ERR_BUFFER;
    fit = buf_bytes / stride;
    if (page) { /* whole pages: band_rows rounded down to 8 (at least 8) */
        band_rows = band_rows < 8 ? 8 : band_rows - band_rows % 8;
        fit *= 8u;
    }
    band = (size_t)band_rows < fit ? band_rows : (int)fit;
    bufs[0] = buf0;
    bufs[1] = buf1 != NULL ? buf1 : buf0;

    before = p->bus->count;
    if ((s = zs_panel_window(p, 0, 0, p->width, p->height)) != ZS_PANEL_OK)
        return s;
    for (y = 0; y < (int)p->height; y += band) {
        int rows = (int)p->height - y < band ? (int)p->height - y : band;
        uint8_t *b = bufs[k & 1];
        size_t n = (size_t)(page ? (rows + 7) / 8 : rows) * stride;
        zs_status rs;

        /* At most one transfer is in flight: the previous band. Only when it
         * lives in the buffer we are about to render into must we wait. */
        if (b == last_sent && !zs_bus_idle(p->bus)) {
            st->wire_waits++;
            if ((s = zs__panel_from_bus(zs_bus_wait(p->bus))) != ZS_PANEL_OK)
                return s;
        }
        rs = zs_render_rows(r, y, rows, b, stride);
        st->render_status = rs;
        if (rs != ZS_OK) {
            (void)zs_bus_wait(p->bus); /* the render failure is the one to report */
            return ZS_PANEL_ERR_RENDER;
        }
        if (b != last_sent && !zs_bus_idle(p->bus))
            st->wire_waits++; /* band ready before the wire was free */
        /* Our own buffer, rendered for this band only: convert in place.
         * Pages go one write each (SH1106 addresses every page itself). */
        {
            size_t piece = page ? stride : n, off;
            for (off = 0; off < n; off += piece)
                if ((s = zs_panel_write_inplace(p, b + off, piece)) != ZS_PANEL_OK) {
                    (void)zs_bus_wait(p->bus);
                    return s;
                }
        }
        last_sent = b;
        st->bands++;
        k++;
    }
    s = zs__panel_from_bus(zs_bus_wait(p->bus));
    if (s == ZS_PANEL_OK && p->desc->ops->frame_end != NULL)
        s = p->desc->ops->frame_end(p);
    st->bus = zs_bus_counters_diff(&p->bus->count, &before);
    st->bytes = zs_bus_counters_bytes(&st->bus);
    st->wire_ns = wire != NULL ? zs_wire_time_ns(&st->bus, wire) : 0;
    return s;
}
