/*
 * Mesh files (anything assimp reads, through zs_import.h) as zs_mesh records
 * in memory: int16 positions with a per-mesh Q16.16 scale. Host only; used
 * by zspan-sim render and the animated programs (zs_scene.h).
 */
#ifndef ZSPAN_APP_MODEL_H
#define ZSPAN_APP_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/zspan.h"

/* One piece of a loaded mesh, at most 65535 vertices and 65535 triangles, so
 * it becomes one zs_mesh. World coordinates (node transforms applied). */
typedef struct zs_model_chunk {
    double *pos;          /* 3 per vertex */
    double *nrm;          /* 3 per vertex (unit), or NULL */
    zs_color *vcol;       /* 1 per vertex, or NULL */
    uint16_t *idx;        /* 3 per triangle, counter-clockwise front */
    uint32_t vcount, tcount;
    uint32_t first_tri;   /* index of the first triangle in the whole scene (0-based) */
    int has_material_color;
    zs_color material_color;

    /* Filled by zs_model_quantize. */
    int16_t *qpos;
    int16_t *qnrm;
    zs_color *fcol;       /* per-face colours chosen by the caller, or NULL */
    zs_mesh mesh;
} zs_model_chunk;

typedef struct zs_model {
    zs_model_chunk *chunks;
    size_t count, cap;
    uint32_t total_tris;  /* triangles over all chunks (the tags run 1..total_tris) */
    uint32_t total_verts;
} zs_model;

/* Loads a file with assimp (triangulated, identical vertices joined; points
 * and lines are skipped) and appends its triangles to the scene, in the order
 * of the node hierarchy (depth first), each node's meshes in order, faces in
 * file order. want_normals: 0 none, 1 the file's normals (generated smooth if
 * absent), 2 smooth normals generated even when the file has its own.
 * Returns 0, or -1 with a message on stderr. */
int zs_model_load(zs_model *scene, const char *path, int want_normals);

/* Axis-aligned bounds over every triangle vertex. Returns 0 when empty. */
int zs_model_bounds(const zs_model *scene, double lo[3], double hi[3]);

/* p = (p - centre) * factor for every vertex. */
void zs_model_transform(zs_model *scene, const double centre[3], double factor);

/* Largest distance of a vertex from c. */
double zs_model_radius(const zs_model *scene, const double c[3]);

/* Quantises every chunk: scale = the smallest Q16.16 value s with
 * max|coordinate| <= 32767 * s / 65536, positions rounded to nearest;
 * normals to Q1.14. Fills chunk->mesh (colours are left to the caller).
 * Returns 0, or -1 with a message (coordinates beyond +-32767 units). */
int zs_model_quantize(zs_model *scene);

/* The animated viewers' preparation of a loaded scene: bounding-box centre to
 * the origin, farthest vertex at distance 1, quantised, and a hashed pastel
 * colour per triangle for chunks without colours of their own. Returns 0, or
 * -1 (a message for quantisation errors, none for out of memory). */
int zs_model_fit_and_colour(zs_model *scene);

/* Begins a frame of a loaded (quantised) scene as the animated viewers show
 * it: fixed camera and light, the scene tilted 15 degrees and turned by deg
 * about y; draws every chunk. */
zs_status zs_model_frame(zs_renderer *r, const zs_model *scene, zs_visibility mode,
                          zs_shading shade, double deg, zs_format fmt);

void zs_model_free(zs_model *scene);

#endif /* ZSPAN_APP_MODEL_H */
