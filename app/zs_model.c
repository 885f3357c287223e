/* Mesh files as zs_mesh chunks: loading, fitting, quantisation (see zs_model.h). */
#include "zs_model.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zs_import.h"

#define CHUNK_MAX 65535u

static void chunk_free(zs_model_chunk *c)
{
    free(c->pos);
    free(c->nrm);
    free(c->vcol);
    free(c->idx);
    free(c->qpos);
    free(c->qnrm);
    free(c->fcol);
    memset(c, 0, sizeof *c);
}

void zs_model_free(zs_model *scene)
{
    size_t i;

    for (i = 0; i < scene->count; i++)
        chunk_free(&scene->chunks[i]);
    free(scene->chunks);
    memset(scene, 0, sizeof *scene);
}

static zs_model_chunk *scene_new_chunk(zs_model *scene)
{
    zs_model_chunk *c;

    if (scene->count == scene->cap) {
        size_t cap = scene->cap ? scene->cap * 2 : 8;
        zs_model_chunk *p = realloc(scene->chunks, cap * sizeof *p);
        if (p == NULL)
            return NULL;
        scene->chunks = p;
        scene->cap = cap;
    }
    c = &scene->chunks[scene->count++];
    memset(c, 0, sizeof *c);
    return c;
}

typedef struct load_ctx {
    zs_model *scene;
    const struct aiScene *ai;
    const char *path;
    int want_normals;
    int32_t *remap;       /* per source vertex: index in the current chunk or -1 */
    size_t remap_cap;
} load_ctx;

static int chunk_alloc(zs_model_chunk *c, uint32_t max_v, uint32_t max_t, int normals, int colors)
{
    c->pos = malloc((size_t)max_v * 3 * sizeof *c->pos);
    c->idx = malloc((size_t)max_t * 3 * sizeof *c->idx);
    if (normals)
        c->nrm = malloc((size_t)max_v * 3 * sizeof *c->nrm);
    if (colors)
        c->vcol = malloc((size_t)max_v * sizeof *c->vcol);
    return c->pos != NULL && c->idx != NULL && (!normals || c->nrm != NULL) &&
                   (!colors || c->vcol != NULL)
               ? 0
               : -1;
}

/* Appends the triangles of one placed mesh (walk callback): only the
 * vertices faces use, in face order, split into chunks of CHUNK_MAX. */
static int add_mesh(void *user, const zs_import_part *part)
{
    load_ctx *lc = user;
    const struct aiMesh *m = part->mesh;
    const int normals = lc->want_normals && m->mNormals != NULL;
    const int colors = m->mColors[0] != NULL;
    zs_color mat_color = 0;
    int has_mat;
    uint32_t f, nv = m->mNumVertices, max_v, max_t;
    zs_model_chunk *c = NULL;
    size_t k;

    has_mat = zs_import_material_color(lc->ai, m->mMaterialIndex, &mat_color) ==
              ZS_IMPORT_MAT_FILE;
    if ((size_t)nv > lc->remap_cap) {
        int32_t *p = realloc(lc->remap, (size_t)nv * sizeof *p);
        if (p == NULL)
            goto oom;
        lc->remap = p;
        lc->remap_cap = nv;
    }
    for (k = 0; k < nv; k++)
        lc->remap[k] = -1;
    max_v = nv < CHUNK_MAX ? nv : CHUNK_MAX;
    max_t = m->mNumFaces < CHUNK_MAX ? m->mNumFaces : CHUNK_MAX;

    for (f = 0; f < m->mNumFaces; f++) {
        const struct aiFace *face = &m->mFaces[f];
        unsigned need = 0, j;
        uint16_t tri[3];

        if (face->mNumIndices != 3)
            continue; /* points and lines */
        for (j = 0; j < 3; j++) {
            if (face->mIndices[j] >= nv) {
                fprintf(stderr, "zspan-sim: %s: face %u has a bad vertex index\n", lc->path,
                        (unsigned)f);
                return -1;
            }
            if (c == NULL || lc->remap[face->mIndices[j]] < 0)
                need++;
        }
        if (c == NULL || c->vcount + need > CHUNK_MAX || c->tcount + 1 > CHUNK_MAX) {
            if (c != NULL) {
                /* Start a new chunk: forget the current chunk's vertices. */
                for (k = 0; k < nv; k++)
                    lc->remap[k] = -1;
            }
            c = scene_new_chunk(lc->scene);
            if (c == NULL || chunk_alloc(c, max_v, max_t, normals, colors) != 0)
                goto oom;
            c->first_tri = lc->scene->total_tris;
            c->has_material_color = has_mat;
            c->material_color = mat_color;
        }
        for (j = 0; j < 3; j++) {
            unsigned src = face->mIndices[j];
            if (lc->remap[src] < 0) {
                uint32_t d = c->vcount++;
                double *p = &c->pos[3 * d];
                int a;
                lc->scene->total_verts++;
                zs_import_position(part, src, p);
                for (a = 0; a < 3; a++) {
                    if (!isfinite(p[a])) {
                        fprintf(stderr, "zspan-sim: %s: vertex %u is not finite\n", lc->path,
                                src);
                        return -1;
                    }
                }
                if (normals)
                    zs_import_normal(part, src, &c->nrm[3 * d]);
                if (colors)
                    c->vcol[d] = zs_import_color(m->mColors[0][src].r, m->mColors[0][src].g,
                                                 m->mColors[0][src].b);
                lc->remap[src] = (int32_t)d;
            }
            tri[j] = (uint16_t)lc->remap[src];
        }
        if (part->mirrored) {
            /* A mirroring node transform turns the winding over: keep fronts in front. */
            uint16_t t = tri[1];
            tri[1] = tri[2];
            tri[2] = t;
        }
        c->idx[3 * c->tcount + 0] = tri[0];
        c->idx[3 * c->tcount + 1] = tri[1];
        c->idx[3 * c->tcount + 2] = tri[2];
        c->tcount++;
        lc->scene->total_tris++;
    }
    return 0;
oom:
    fprintf(stderr, "zspan-sim: %s: out of memory\n", lc->path);
    return -1;
}

int zs_model_load(zs_model *scene, const char *path, int want_normals)
{
    const struct aiScene *ai;
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
    load_ctx lc;
    uint32_t before = scene->total_tris;
    FILE *probe;
    int rc;

    probe = fopen(path, "rb");
    if (probe == NULL) {
        fprintf(stderr, "zspan-sim: cannot open %s: %s\n", path, strerror(errno));
        return -1;
    }
    fclose(probe);
    if (want_normals)
        flags |= aiProcess_GenSmoothNormals;
    if (want_normals > 1)
        flags |= aiProcess_ForceGenNormals; /* replace the file's normals by smooth ones */
    ai = aiImportFile(path, flags);
    if (ai == NULL) {
        fprintf(stderr, "zspan-sim: cannot load %s: %s\n", path, aiGetErrorString());
        return -1;
    }
    if ((ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || ai->mRootNode == NULL) {
        fprintf(stderr, "zspan-sim: %s: incomplete scene (no meshes?)\n", path);
        aiReleaseImport(ai);
        return -1;
    }
    lc.scene = scene;
    lc.ai = ai;
    lc.path = path;
    lc.want_normals = want_normals;
    lc.remap = NULL;
    lc.remap_cap = 0;
    rc = zs_import_walk(ai, add_mesh, &lc);
    if (rc == ZS_IMPORT_ERR_MESH || rc == ZS_IMPORT_ERR_DEPTH)
        fprintf(stderr, "zspan-sim: %s: %s\n", path,
                rc == ZS_IMPORT_ERR_MESH ? "a node refers to a missing mesh"
                                         : "node hierarchy too deep");
    free(lc.remap);
    aiReleaseImport(ai);
    if (rc == 0 && scene->total_tris == before)
        fprintf(stderr, "zspan-sim: warning: %s has no triangles\n", path);
    return rc == 0 ? 0 : -1;
}

int zs_model_bounds(const zs_model *scene, double lo[3], double hi[3])
{
    size_t i;
    uint32_t v;
    int a, any = 0;

    for (i = 0; i < scene->count; i++) {
        const zs_model_chunk *c = &scene->chunks[i];
        for (v = 0; v < c->vcount; v++) {
            for (a = 0; a < 3; a++) {
                double x = c->pos[3 * v + (uint32_t)a];
                if (!any || x < lo[a])
                    lo[a] = x;
                if (!any || x > hi[a])
                    hi[a] = x;
            }
            any = 1;
        }
    }
    return any;
}

void zs_model_transform(zs_model *scene, const double centre[3], double factor)
{
    size_t i;
    uint32_t v;
    int a;

    for (i = 0; i < scene->count; i++) {
        zs_model_chunk *c = &scene->chunks[i];
        for (v = 0; v < c->vcount; v++)
            for (a = 0; a < 3; a++)
                c->pos[3 * v + (uint32_t)a] = (c->pos[3 * v + (uint32_t)a] - centre[a]) * factor;
    }
}

double zs_model_radius(const zs_model *scene, const double c[3])
{
    double best = 0.0;
    size_t i;
    uint32_t v;

    for (i = 0; i < scene->count; i++) {
        const zs_model_chunk *ch = &scene->chunks[i];
        for (v = 0; v < ch->vcount; v++) {
            const double *p = &ch->pos[3 * v];
            double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
            double d = sqrt(dx * dx + dy * dy + dz * dz);
            if (d > best)
                best = d;
        }
    }
    return best;
}

static int16_t clamp16(double v, double lim)
{
    if (v > lim)
        v = lim;
    if (v < -lim)
        v = -lim;
    return (int16_t)v;
}

int zs_model_quantize(zs_model *scene)
{
    size_t i;
    uint32_t k, n;

    for (i = 0; i < scene->count; i++) {
        zs_model_chunk *c = &scene->chunks[i];
        double maxabs = 0.0, scale;

        n = c->vcount * 3;
        for (k = 0; k < n; k++)
            if (fabs(c->pos[k]) > maxabs)
                maxabs = fabs(c->pos[k]);
        if (maxabs > 32767.0) {
            fprintf(stderr,
                    "zspan-sim: a mesh reaches %g units from the origin; model coordinates must "
                    "stay within +-32767 (use --fit)\n",
                    maxabs);
            return -1;
        }
        /* Finest step (scale / 65536) that keeps every coordinate within int16. */
        scale = ceil(maxabs * 65536.0 / 32767.0);
        if (scale < 1.0)
            scale = 1.0;
        c->qpos = malloc((size_t)(n ? n : 1) * sizeof *c->qpos);
        if (c->qpos == NULL)
            goto oom;
        for (k = 0; k < n; k++)
            c->qpos[k] = clamp16(floor(c->pos[k] * 65536.0 / scale + 0.5), 32767.0);
        if (c->nrm != NULL) {
            c->qnrm = malloc((size_t)(n ? n : 1) * sizeof *c->qnrm);
            if (c->qnrm == NULL)
                goto oom;
            for (k = 0; k < n; k++)
                c->qnrm[k] = clamp16(floor(c->nrm[k] * 16384.0 + 0.5), 16384.0);
        }
        memset(&c->mesh, 0, sizeof c->mesh);
        c->mesh.positions = c->qpos;
        c->mesh.indices = c->idx;
        c->mesh.vertex_normals = c->qnrm;
        c->mesh.vertex_colors = c->vcol;
        c->mesh.scale = (zs_fixed)scale;
        c->mesh.vertex_count = (uint16_t)c->vcount;
        c->mesh.triangle_count = (uint16_t)c->tcount;
        c->mesh.color = c->has_material_color ? c->material_color : ZS_RGB(200, 200, 200);
    }
    return 0;
oom:
    fprintf(stderr, "zspan-sim: out of memory\n");
    return -1;
}

zs_status zs_model_frame(zs_renderer *r, const zs_model *scene, zs_visibility mode,
                          zs_shading shade, double deg, zs_format fmt)
{
    zs_camera cam;
    zs_shade_params sp = zs_shade_default();
    zs_mat34 rx, ry, m;
    zs_status st;
    size_t i;
    st = zs_camera_look_at(&cam, zs_vec3_make(0, ZS_FX_RATIO(6, 10), ZS_FX_RATIO(28, 10)),
                           zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0));
    if (st == ZS_OK)
        st = zs_camera_perspective(&cam, ZS_FX(45), ZS_FX_RATIO(1, 10), ZS_FX(20));
    if (st == ZS_OK)
        st = zs_frame_begin(r, &cam, mode);
    if (st != ZS_OK)
        return st;
    sp.shading = shade;
    sp.format = fmt;
    sp.background = ZS_RGB(16, 20, 36);
    sp.ambient = ZS_FX_RATIO(3, 10);
    sp.light_count = 1;
    sp.lights[0].direction = zs_vec3_make(ZS_FX(-1), ZS_FX(1), ZS_FX(2));
    sp.lights[0].intensity = ZS_FX_RATIO(75, 100);
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK)
        return st;
    rx = zs_mat34_rotate_x(ZS_FX(-15));
    ry = zs_mat34_rotate_y((zs_fixed)lround(deg * 65536.0));
    m = zs_mat34_mul(&rx, &ry);
    for (i = 0; i < scene->count; i++)
        if ((st = zs_draw(r, &scene->chunks[i].mesh, &m)) != ZS_OK)
            return st;
    return ZS_OK;
}

int zs_model_fit_and_colour(zs_model *scene)
{
    double lo[3], hi[3], c[3], radius;
    size_t i;
    int f;
    if (zs_model_bounds(scene, lo, hi)) {
        for (f = 0; f < 3; f++)
            c[f] = 0.5 * (lo[f] + hi[f]);
        radius = zs_model_radius(scene, c);
        zs_model_transform(scene, c, radius > 0.0 ? 1.0 / radius : 1.0);
    }
    if (zs_model_quantize(scene) != 0)
        return -1;
    for (i = 0; i < scene->count; i++) {
        zs_model_chunk *ch = &scene->chunks[i];
        uint32_t t;
        if (ch->vcol != NULL || ch->has_material_color || ch->tcount == 0)
            continue;
        ch->fcol = malloc((size_t)ch->tcount * sizeof *ch->fcol);
        if (ch->fcol == NULL)
            return -1;
        for (t = 0; t < ch->tcount; t++) {
            uint32_t h = (ch->first_tri + t + 1u) * 2654435761u;
            ch->fcol[t] = ZS_RGB(96 + (h >> 24) % 160, 96 + (h >> 16) % 160, 96 + (h >> 8) % 160);
        }
        ch->mesh.face_colors = ch->fcol;
    }
    return 0;
}
