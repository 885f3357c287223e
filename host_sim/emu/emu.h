/* SPDX-License-Identifier: MIT */
/*
 * Emulated display controllers for the host simulator and the tests.
 *
 * An emu_panel consumes exactly what a 4-wire SPI display sees: bytes with
 * the D/C line low (commands) or high (parameters and pixel data), the reset
 * line, and the passing of time (delays). It keeps its own RAM, decodes the
 * pixel formats, follows the address window and orientation registers like the
 * silicon does, and flags protocol errors a real panel would silently turn
 * into a wrong picture. The picture a viewer sees is read back with
 * emu_view_666() / emu_view_rgb() / emu_write_png().
 *
 * Host C99 (uses malloc). Independent of the zspan driver tables: the module
 * facts below (RAM size, where the glass sits in the RAM, how the glass is
 * mounted, BGR/IPS glass) are written down separately so that a wrong driver
 * table shows up as a wrong picture.
 */
#ifndef ZSPAN_EMU_H
#define ZSPAN_EMU_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Protocol error flags (emu_panel.errors). */
enum {
    EMU_E_SLEEP = 1u << 0,        /* pixel data while in sleep (no SLPOUT yet) */
    EMU_E_DISPOFF = 1u << 1,      /* pixel data while the display is off (no DISPON) */
    EMU_E_WINDOW = 1u << 2,       /* window start > end, or outside the RAM */
    EMU_E_PARAM_COUNT = 1u << 3,  /* wrong number of parameters for a command */
    EMU_E_PARAM_VALUE = 1u << 4,  /* unsupported parameter value (COLMOD, depth) */
    EMU_E_STRAY_DATA = 1u << 5,   /* data bytes that no command takes */
    EMU_E_PARTIAL_PIXEL = 1u << 6,/* a command arrived in the middle of a pixel */
    EMU_E_TIMING = 1u << 7,       /* a command too soon after reset/SWRESET/SLPOUT */
    EMU_E_LOCKED = 1u << 8,       /* SSD1351: command while the interface is locked */
    EMU_E_PIXEL_BITS = 1u << 9,   /* SSD1351 262k: bits 7..6 set in a pixel byte */
    EMU_E_IN_RESET = 1u << 10     /* bytes while the reset line is held low */
};
#define EMU_E_COUNT 11

/* Controller families. */
enum { EMU_DCS = 0, EMU_SSD1351 = 1 };

/* What a module is, physically. */
typedef struct emu_model {
    const char *name;          /* matches the zspan table name */
    int family;                /* EMU_DCS or EMU_SSD1351 */
    uint16_t ram_w, ram_h;     /* controller RAM: columns x rows */
    uint16_t vis_w, vis_h;     /* glass, pixels */
    uint16_t vis_col, vis_row; /* first RAM column/row shown on the glass */
    uint8_t mount_mirror_x;    /* glass columns run opposite to RAM columns */
    uint8_t mount_mirror_y;    /* glass rows run opposite to RAM rows (SSD1351: COM) */
    uint8_t glass_bgr;         /* BGR colour filter: needs the BGR bit for true colour */
    uint8_t glass_inverted;    /* IPS normally-black: needs INVON for true colour */
    uint8_t spi_no_16bpp;      /* 16 bpp not available on the SPI interface */
    uint8_t default_bpp;       /* pixel size after reset (16 or 18) */
    uint32_t max_spi_hz;       /* rated clock (for the emulator's reports) */
} emu_model;

/* Built-in models; emu_model_find returns NULL for an unknown name. */
const emu_model *emu_model_find(const char *name);
unsigned emu_model_count(void);
const emu_model *emu_model_at(unsigned i);

/* One recorded event of the byte stream (when recording is on). */
typedef struct emu_event {
    uint8_t kind;              /* 'C' command, 'P' parameter, 'D' pixel run */
    uint8_t byte;              /* command or parameter byte */
    uint32_t n;                /* 'D': number of pixel bytes in the run */
} emu_event;

#define EMU_MAX_PARAMS 64
#define EMU_LOG_LINES 16

typedef struct emu_panel {
    const emu_model *m;
    uint32_t *ram;             /* ram_w * ram_h cells, 0x00RRGGBB with 6-bit channels
                                  (r << 12 | g << 6 | b) */
    /* state */
    uint8_t reset_low;         /* reset line asserted */
    uint8_t sleeping, display_on, inverted, idle;
    uint8_t madctl;            /* DCS MADCTL or SSD1351 remap (raw) */
    uint8_t bpp;               /* 16 or 18 */
    uint8_t writing;           /* inside RAMWR / WRITERAM */
    uint8_t ssd_locked;        /* 0x16 lock */
    uint8_t ssd_protected;     /* A2/B1/B3/BB/BE/C1 not yet unlocked (0xB1) */
    uint8_t backlight;
    uint16_t xs, xe, ys, ye;   /* window (inclusive); SSD1351: column, row */
    uint16_t cx, cy;           /* address counters */
    uint8_t win_ok;            /* window checked and inside the RAM */
    uint8_t wrap_pending;      /* the counters wrapped after the window's last pixel */
    /* pending command */
    int cmd;                   /* -1 none */
    int expect;                /* parameter count, -1 any */
    unsigned nparams;
    uint8_t params[EMU_MAX_PARAMS];
    uint8_t part[3];
    unsigned npart;
    int last_cmd;              /* last command whose parameters are complete */
    uint8_t extra_is_count;    /* data now would be surplus parameters of last_cmd */
    uint8_t pix_flagged;       /* sleep/display-off already reported for this write */
    /* time, microseconds */
    uint64_t now_us, t_hwreset, t_swreset, t_slpout;
    uint8_t seen_hwreset, seen_swreset, seen_slpout;
    /* results */
    uint32_t errors;           /* EMU_E_* bits */
    uint32_t error_count;
    char log[EMU_LOG_LINES][120];
    unsigned log_lines;
    uint64_t bytes_in;         /* every byte received, D/C low or high */
    uint32_t commands;
    uint64_t pixels;           /* pixels written to RAM */
    uint32_t wraps;            /* window wrap-arounds */
    uint32_t frames_written;   /* memory-write commands seen */
    /* recording */
    int record;
    emu_event *ev;
    size_t nev, capev;
} emu_panel;

/* Creates a panel (RAM filled with a noise pattern, as after power-on).
 * Returns 0 on success. */
int emu_init(emu_panel *e, const emu_model *m);
void emu_free(emu_panel *e);

/* The wire. */
void emu_reset_line(emu_panel *e, int level);       /* 0 = asserted */
void emu_command(emu_panel *e, uint8_t cmd);        /* one byte, D/C low */
void emu_data(emu_panel *e, const uint8_t *d, size_t n); /* bytes, D/C high */
void emu_delay_ms(emu_panel *e, uint32_t ms);
/* Ends the stream: checks the last command's parameter count. */
void emu_flush(emu_panel *e);

/* Starts recording events (clears earlier ones). */
void emu_record(emu_panel *e, int on);

/* Size of the picture a viewer sees with the module turned for `rotation`
 * (0..3, the zspan rotation the driver was given). */
void emu_view_size(const emu_panel *e, unsigned rotation, unsigned *w, unsigned *h);
/* The picture as 6-bit channels (r << 12 | g << 6 | b), row-major; black
 * where the display is off or asleep. out holds w*h entries. */
void emu_view_666(const emu_panel *e, unsigned rotation, uint32_t *out);
/* The same as 8-bit RGB (3 bytes per pixel). */
void emu_view_rgb(const emu_panel *e, unsigned rotation, uint8_t *out);
/* Writes the picture to a PNG file; 0 on success. */
int emu_write_png(const emu_panel *e, unsigned rotation, const char *path);

/* One-line description of an error flag (a single EMU_E_* bit). */
const char *emu_error_name(uint32_t bit);

/* Pixel helpers shared by the tests: expand wire pixels to 6-bit channels. */
uint32_t emu_666_from_565be(const uint8_t *p);
uint32_t emu_666_from_666(const uint8_t *p);

/* 8-bit RGB image writer (libpng); 0 on success. */
int emu_png_write_rgb(const char *path, const uint8_t *rgb, unsigned w, unsigned h);
/* Reads any PNG as 8-bit RGB into a malloc'd buffer (free() it); 0 on success. */
int emu_png_read_rgb(const char *path, uint8_t **rgb, unsigned *w, unsigned *h);

#ifdef __cplusplus
}
#endif

#endif
