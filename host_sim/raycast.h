/* SPDX-License-Identifier: MIT */
/* zspan-sim render --mode raycast: a ray caster over the core's snapped
 * triangle records, with a uniform grid of screen cells (host_sim/raycast.c). */
#ifndef SIM_RAYCAST_H
#define SIM_RAYCAST_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zspan/zspan.h"

/* One record as the setup hook gives it: 28.4 screen vertices, Q2.30 depths. */
typedef struct sim_rc_rec {
    int32_t xy[6];
    uint32_t z[3];
    uint16_t tag;
} sim_rc_rec;

typedef struct sim_rc_set {
    sim_rc_rec *v;
    size_t n, cap;
    FILE *dump;  /* when set, the hook also writes --dump-tris lines */
    int failed;  /* out of memory */
} sim_rc_set;

/* zs_set_setup_hook function; user is a sim_rc_set. */
void sim_rc_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3]);
void sim_rc_free(sim_rc_set *s);

typedef struct sim_rc_image {
    int w, h;
    uint16_t *tag;   /* tag of the nearest record at each pixel centre, 0 = none */
    int32_t *rec;    /* its record index, -1 = none */
    double *z1;      /* its depth (2.0 = none) */
    unsigned long tests; /* record-versus-centre tests made */
} sim_rc_image;

/* Casts a ray through every pixel centre: coverage by edge functions on the
 * 28.4 vertices with the top-left rule (exact), depth by interpolating the
 * window depths in double, the nearest wins, copies of a record (the same
 * three vertices in any order) go to the first. cell > 0: the records are
 * binned into cells of cell x cell pixels first and a ray tests only its
 * cell's; cell == 0: every record. Returns 0, or -1 out of memory. */
int sim_raycast(const sim_rc_set *s, int w, int h, int cell, sim_rc_image *out);
/* The least depth at centre (x, y) of the records of one tag covering it
 * (0 if none): for the report of near ties. */
int sim_rc_depth_of(const sim_rc_set *s, uint16_t tag, int x, int y, double *z);
void sim_rc_image_free(sim_rc_image *im);

#endif
