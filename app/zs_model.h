/* SPDX-License-Identifier: MIT */
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

struct aiScene;

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
    double *uv;           /* 2 per vertex as the file has them (v up), or NULL */
    int16_t *quv;         /* 2 per vertex in Q3.12 (v down the texture), or NULL */
    const zs_texture *texture; /* owned by the zs_model, or NULL */

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
    zs_texture **textures; /* the chunks' textures (malloc'd texels), freed with it */
    size_t ntex;
} zs_model;

/* The file's up axis (zs_model_opts.up): the model is turned so that it
 * points along +y, the world's up. AUTO: what the file's metadata says
 * (assimp's "UpAxis"/"UpAxisSign", e.g. FBX), else +y. */
enum { ZS_UP_AUTO, ZS_UP_X, ZS_UP_Y, ZS_UP_Z, ZS_UP_NEG_X, ZS_UP_NEG_Y, ZS_UP_NEG_Z };
/* (zs_opt_up_axis parses them from the command line.) */

typedef struct zs_model_opts {
    const char *prog;   /* message prefix, e.g. "zspan-sim" */
    int want_normals;   /* as zs_model_load */
    int flip_winding;   /* the file's triangles are clockwise: reverse them */
    int up;             /* ZS_UP_* */
    int quiet;          /* no warnings */
    /* Textures of assimp files (NULL: none). Called once per material that
     * textured vertices use: 1 with *out filled (texels and palette
     * malloc'd, the model frees them), 0 for no texture, -1 to fail the load
     * (after a message). */
    int (*load_texture)(void *user, const struct aiScene *ai, unsigned material,
                        const char *path, zs_texture *out);
    void *texture_user;
} zs_model_opts;

/* zs_model_opts with prog "zspan-sim", up AUTO, nothing else. */
zs_model_opts zs_model_opts_default(void);

/* Signature of the converter's binary mesh (zspan-meshc --format zsm): a file
 * that starts with it is read directly, without assimp. Layout, little-endian:
 * magic (8 bytes), u32 flags (ZS_ZSM_*), i32 scale (Q16.16), u32 colour,
 * u16 vertex count, u16 triangle count, then i16 positions[3 V], u16
 * indices[3 T], and as the flags say u32 face colours[T], u32 vertex
 * colours[V], i16 face normals[3 T], i16 vertex normals[3 V] (Q1.14). */
#define ZS_ZSM_MAGIC "ZSMESH1\n"
#define ZS_ZSM_FACE_COLORS 1u
#define ZS_ZSM_VERTEX_COLORS 2u
#define ZS_ZSM_FACE_NORMALS 4u
#define ZS_ZSM_VERTEX_NORMALS 8u
/* With ZS_ZSM_TEXTURE, after those: i16 uvs[2 V] (Q3.12, zs_mesh.uvs), u16
 * width, u16 height, u8 format (zs_tex_format), u8 flags (ZS_TEX_*), u16 0,
 * then for ZS_TEX_PAL8 u16 palette[256] and u8 texels[width height], else
 * u16 texels[width height] (RGB565). */
#define ZS_ZSM_TEXTURE 16u
#define ZS_ZSM_HEADER_BYTES 24u

/* Loads a file with assimp (triangulated, identical vertices joined; points
 * and lines are skipped) and appends its triangles to the scene, in the order
 * of the node hierarchy (depth first), each node's meshes in order, faces in
 * file order. want_normals: 0 none, 1 the file's normals (generated smooth if
 * absent), 2 smooth normals generated even when the file has its own.
 * Returns 0, or -1 with a message on stderr. */
int zs_model_load(zs_model *scene, const char *path, int want_normals);
/* The same with options. A directory, an unreadable file and a file without
 * triangles are errors; an import that runs longer than zs_import_seconds()
 * stops the program (zs_import_guard_begin, exit status 1). Warns (unless
 * quiet) when the file's normals point against the winding of most
 * triangles. Files starting with ZS_ZSM_MAGIC are read as the converter's
 * binary meshes (up and flip_winding apply to them too). */
int zs_model_load_opts(zs_model *scene, const char *path, const zs_model_opts *o);

/* Adds a reversed copy of every chunk (indices reversed, normals negated,
 * same colours): drawn after the originals, it shows the back faces, so the
 * model is two-sided (the tags of the copies follow all the originals).
 * Call after zs_model_quantize and after the colours are set. Returns 0, or
 * -1 when out of memory. */
int zs_model_add_back_faces(zs_model *scene);

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
 * about y; draws every chunk. mono: the 1-bit options (ZS_MONO_*) of a 1-bit
 * or GRAY4 fmt. */
zs_status zs_model_frame(zs_renderer *r, const zs_model *scene, zs_visibility mode,
                          zs_shading shade, double deg, zs_format fmt, unsigned mono);

void zs_model_free(zs_model *scene);

#endif /* ZSPAN_APP_MODEL_H */
