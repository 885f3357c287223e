/* SPDX-License-Identifier: MIT */
/*
 * The assimp importer of the host programs: walks an imported scene's node
 * hierarchy and hands every mesh over with its node's world transform, and
 * converts assimp's colours and materials. zspan-sim (app/zs_model.c) and
 * zspan-meshc build their own vertex and triangle lists from what it gives;
 * how a file is read (post-processing, validation) stays with the caller.
 */
#ifndef ZSPAN_APP_IMPORT_H
#define ZSPAN_APP_IMPORT_H

#include <assimp/scene.h>
#include <stdint.h>

/* Deepest node hierarchy walked (deeper is refused, not recursed into). */
#define ZS_IMPORT_MAX_DEPTH 256

/* zs_import_walk results besides 0 and the callback's own non-zero value. */
#define ZS_IMPORT_ERR_MESH (-1001)  /* a node names a mesh the scene does not have */
#define ZS_IMPORT_ERR_DEPTH (-1002) /* hierarchy deeper than ZS_IMPORT_MAX_DEPTH */

/* Seconds an import may take before zs_import_guard_begin's alarm stops the
 * program (a few malformed files make assimp loop forever: a 330-byte PLY
 * does in assimp 5.2). $ZSPAN_IMPORT_SECONDS overrides it. */
#define ZS_IMPORT_SECONDS 30u

/* Arms the import timeout around one aiImportFile call: if the importer has
 * not returned after the timeout, the program prints "PROG: PATH: the model
 * importer did not finish in N s (a malformed file?)" and exits with
 * exit_code. prog and path must stay valid until zs_import_guard_end. */
void zs_import_guard_begin(const char *prog, const char *path, int exit_code);
/* Disarms it (call right after the import returns). */
void zs_import_guard_end(void);
/* The timeout in seconds ($ZSPAN_IMPORT_SECONDS if set to 1..86400, else
 * ZS_IMPORT_SECONDS). */
unsigned zs_import_seconds(void);

/* One mesh of the scene placed by its node. */
typedef struct zs_import_part {
    const struct aiScene *scene;
    const struct aiMesh *mesh;
    double world[3][4];   /* the node's global transform (parents applied), affine */
    double normal[3][3];  /* cofactors of world's 3x3 (det x inverse transpose): maps normals */
    int mirrored;         /* det < 0: the transform turns windings inside out */
} zs_import_part;

/* Calls fn for every mesh of every node, depth first, each node's meshes in
 * order. Returns 0, the first non-zero value fn returns, or ZS_IMPORT_ERR_*. */
int zs_import_walk(const struct aiScene *scene,
                   int (*fn)(void *user, const zs_import_part *part), void *user);

/* Vertex v of the part in world coordinates. */
void zs_import_position(const zs_import_part *part, unsigned v, double out[3]);
/* Normal of vertex v in world coordinates, unit length and facing out even
 * through a mirroring transform; (0,0,0) if the file's normal is degenerate. */
void zs_import_normal(const zs_import_part *part, unsigned v, double out[3]);

/* Up axes: 0 auto (the file's metadata), 1 x, 2 y, 3 z, 4 -x, 5 -y, 6 -z
 * (zs_opt_up_axis's numbers, ZS_UP_* of zs_model.h). */
/* Turns a vector of a file whose up axis is `up` (1..6) so that up becomes
 * +y, by a rotation (lengths and windings are kept). */
void zs_import_up_to_y(int up, double v[3]);
/* The up axis the scene's metadata gives ("UpAxis" 0..2 and "UpAxisSign",
 * as assimp's FBX importer reports them), else 2 (+y). */
int zs_import_file_up(const struct aiScene *scene);

/* 0..1 channels -> 0x00RRGGBB, clamped, rounded to nearest. */
uint32_t zs_import_color(double r, double g, double b);

/* The diffuse colour of material index: ZS_IMPORT_MAT_NONE (no such material
 * or no diffuse colour; *out untouched), ZS_IMPORT_MAT_FILE, or
 * ZS_IMPORT_MAT_DEFAULT (assimp's own stand-in for a file without materials). */
enum { ZS_IMPORT_MAT_NONE, ZS_IMPORT_MAT_FILE, ZS_IMPORT_MAT_DEFAULT };
int zs_import_material_color(const struct aiScene *scene, unsigned index, uint32_t *out);

#endif /* ZSPAN_APP_IMPORT_H */
