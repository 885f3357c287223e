/* SPDX-License-Identifier: MIT */
/* The assimp scene walk shared by zspan-sim and zspan-meshc (see zs_import.h). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* sigaction, alarm */
#endif
#include "zs_import.h"

#include <assimp/material.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* What the alarm handler prints: async-signal-safe writes of saved strings. */
static const char *g_guard_prog = "";
static const char *g_guard_path = "";
static int g_guard_exit = 1;
static char g_guard_secs[12];

static void guard_write(const char *s)
{
    (void)!write(2, s, strlen(s));
}

static void on_import_timeout(int sig)
{
    (void)sig;
    guard_write(g_guard_prog);
    guard_write(": ");
    guard_write(g_guard_path);
    guard_write(": the model importer did not finish in ");
    guard_write(g_guard_secs);
    guard_write(" s (a malformed file?); $ZSPAN_IMPORT_SECONDS sets the limit\n");
    _exit(g_guard_exit);
}

unsigned zs_import_seconds(void)
{
    const char *env = getenv("ZSPAN_IMPORT_SECONDS");
    char *end = NULL;
    unsigned long v;

    if (env == NULL)
        env = getenv("ZSPAN_MESHC_IMPORT_SECONDS"); /* the converter's older name */
    if (env == NULL)
        return ZS_IMPORT_SECONDS;
    v = strtoul(env, &end, 10);
    return end != env && *end == '\0' && v >= 1 && v <= 86400 ? (unsigned)v : ZS_IMPORT_SECONDS;
}

void zs_import_guard_begin(const char *prog, const char *path, int exit_code)
{
    unsigned secs = zs_import_seconds(), k = sizeof g_guard_secs - 1;
    struct sigaction sa;

    g_guard_prog = prog;
    g_guard_path = path;
    g_guard_exit = exit_code;
    g_guard_secs[k] = '\0';
    do {
        g_guard_secs[--k] = (char)('0' + secs % 10u);
        secs /= 10u;
    } while (secs != 0 && k > 0);
    memmove(g_guard_secs, g_guard_secs + k, sizeof g_guard_secs - k);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_import_timeout;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGALRM, &sa, NULL);
    alarm(zs_import_seconds());
}

void zs_import_guard_end(void)
{
    alarm(0);
}

static void affine_from_ai(const struct aiMatrix4x4 *m, double a[3][4])
{
    a[0][0] = m->a1; a[0][1] = m->a2; a[0][2] = m->a3; a[0][3] = m->a4;
    a[1][0] = m->b1; a[1][1] = m->b2; a[1][2] = m->b3; a[1][3] = m->b4;
    a[2][0] = m->c1; a[2][1] = m->c2; a[2][2] = m->c3; a[2][3] = m->c4;
}

/* r = a * b (b applies first). Node transforms are affine: the bottom row is
 * taken as (0 0 0 1) even where a file's is off by a rounding error. */
static void affine_mul(double a[3][4], double b[3][4], double r[3][4])
{
    int i, j, k;

    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            double s = 0;
            for (k = 0; k < 3; k++)
                s += a[i][k] * b[k][j];
            r[i][j] = j == 3 ? s + a[i][3] : s;
        }
}

/* Cofactors of the 3x3 part and the sign of its determinant. */
static void normal_matrix(zs_import_part *p)
{
    int i, k;

    for (i = 0; i < 3; i++)
        for (k = 0; k < 3; k++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            p->normal[i][k] =
                p->world[i1][k1] * p->world[i2][k2] - p->world[i1][k2] * p->world[i2][k1];
        }
    p->mirrored = p->world[0][0] * p->normal[0][0] + p->world[0][1] * p->normal[0][1] +
                      p->world[0][2] * p->normal[0][2] < 0.0;
}

typedef struct walk {
    const struct aiScene *scene;
    int (*fn)(void *user, const zs_import_part *part);
    void *user;
} walk;

static int walk_node(const walk *w, const struct aiNode *node, double parent[3][4], int depth)
{
    zs_import_part part;
    double local[3][4];
    unsigned i;
    int rc;

    if (depth > ZS_IMPORT_MAX_DEPTH)
        return ZS_IMPORT_ERR_DEPTH;
    affine_from_ai(&node->mTransformation, local);
    affine_mul(parent, local, part.world);
    normal_matrix(&part);
    part.scene = w->scene;
    for (i = 0; i < node->mNumMeshes; i++) {
        if (node->mMeshes == NULL || node->mMeshes[i] >= w->scene->mNumMeshes ||
            w->scene->mMeshes[node->mMeshes[i]] == NULL)
            return ZS_IMPORT_ERR_MESH;
        part.mesh = w->scene->mMeshes[node->mMeshes[i]];
        if ((rc = w->fn(w->user, &part)) != 0)
            return rc;
    }
    for (i = 0; i < node->mNumChildren; i++)
        if (node->mChildren != NULL && node->mChildren[i] != NULL &&
            (rc = walk_node(w, node->mChildren[i], part.world, depth + 1)) != 0)
            return rc;
    return 0;
}

int zs_import_walk(const struct aiScene *scene,
                   int (*fn)(void *user, const zs_import_part *part), void *user)
{
    double id[3][4];
    walk w;
    int i, j;

    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            id[i][j] = i == j ? 1.0 : 0.0;
    w.scene = scene;
    w.fn = fn;
    w.user = user;
    return scene->mRootNode != NULL ? walk_node(&w, scene->mRootNode, id, 0) : 0;
}

void zs_import_position(const zs_import_part *part, unsigned v, double out[3])
{
    const struct aiVector3D *p = &part->mesh->mVertices[v];
    int r;

    for (r = 0; r < 3; r++)
        out[r] = part->world[r][0] * p->x + part->world[r][1] * p->y +
                 part->world[r][2] * p->z + part->world[r][3];
}

void zs_import_normal(const zs_import_part *part, unsigned v, double out[3])
{
    const struct aiVector3D *n = &part->mesh->mNormals[v];
    double len;
    int r;

    for (r = 0; r < 3; r++)
        out[r] = (part->normal[r][0] * n->x + part->normal[r][1] * n->y +
                  part->normal[r][2] * n->z) *
                 (part->mirrored ? -1.0 : 1.0);
    len = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    for (r = 0; r < 3; r++)
        out[r] = len > 0.0 && isfinite(len) ? out[r] / len : 0.0;
}

uint32_t zs_import_color(double r, double g, double b)
{
    double c[3];
    uint32_t out = 0;
    int i;

    c[0] = r;
    c[1] = g;
    c[2] = b;
    for (i = 0; i < 3; i++) {
        double x = c[i];
        if (!(x > 0.0))
            x = 0.0;
        if (x > 1.0)
            x = 1.0;
        out = (out << 8) | (uint32_t)floor(x * 255.0 + 0.5);
    }
    return out;
}

int zs_import_material_color(const struct aiScene *scene, unsigned index, uint32_t *out)
{
    const struct aiMaterial *mat;
    struct aiColor4D c;
    struct aiString name;

    if (index >= scene->mNumMaterials || scene->mMaterials == NULL ||
        scene->mMaterials[index] == NULL)
        return ZS_IMPORT_MAT_NONE;
    mat = scene->mMaterials[index];
    if (aiGetMaterialColor(mat, AI_MATKEY_COLOR_DIFFUSE, &c) != aiReturn_SUCCESS)
        return ZS_IMPORT_MAT_NONE;
    *out = zs_import_color(c.r, c.g, c.b);
    if (aiGetMaterialString(mat, AI_MATKEY_NAME, &name) == aiReturn_SUCCESS &&
        strcmp(name.data, AI_DEFAULT_MATERIAL_NAME) == 0)
        return ZS_IMPORT_MAT_DEFAULT;
    return ZS_IMPORT_MAT_FILE;
}

void zs_import_up_to_y(int up, double v[3])
{
    double x = v[0], y = v[1], z = v[2];

    switch (up) {
    case 3: v[1] = z; v[2] = -y; break;  /* +z up: -90 degrees about x */
    case 6: v[1] = -z; v[2] = y; break;  /* -z up: +90 about x */
    case 1: v[0] = -y; v[1] = x; break;  /* +x up: +90 about z */
    case 4: v[0] = y; v[1] = -x; break;  /* -x up: -90 about z */
    case 5: v[1] = -y; v[2] = -z; break; /* -y up: 180 about x */
    default: break;
    }
}

int zs_import_file_up(const struct aiScene *scene)
{
    const struct aiMetadata *md = scene->mMetaData;
    int axis = -1, sign = 1;
    unsigned i;

    if (md == NULL || md->mKeys == NULL || md->mValues == NULL)
        return 2;
    for (i = 0; i < md->mNumProperties; i++) {
        const struct aiMetadataEntry *e = &md->mValues[i];
        int32_t v;
        if (e->mType != AI_INT32 || e->mData == NULL)
            continue;
        memcpy(&v, e->mData, sizeof v);
        if (strcmp(md->mKeys[i].data, "UpAxis") == 0 && v >= 0 && v <= 2)
            axis = (int)v;
        else if (strcmp(md->mKeys[i].data, "UpAxisSign") == 0)
            sign = v < 0 ? -1 : 1;
    }
    if (axis < 0)
        return 2;
    return (sign > 0 ? 1 : 4) + axis;
}
