/* SPDX-License-Identifier: MIT */
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
#include <sys/stat.h>

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
    free(c->uv);
    free(c->quv);
    memset(c, 0, sizeof *c);
}

static zs_texture *model_add_texture(zs_model *scene)
{
    zs_texture **p = realloc(scene->textures, (scene->ntex + 1) * sizeof *p), *t;
    if (p == NULL)
        return NULL;
    scene->textures = p;
    t = calloc(1, sizeof *t);
    if (t != NULL)
        scene->textures[scene->ntex++] = t;
    return t;
}

void zs_model_free(zs_model *scene)
{
    size_t i;

    for (i = 0; i < scene->count; i++)
        chunk_free(&scene->chunks[i]);
    free(scene->chunks);
    for (i = 0; i < scene->ntex; i++) {
        free((void *)(uintptr_t)scene->textures[i]->texels);
        free((void *)(uintptr_t)scene->textures[i]->palette);
        free(scene->textures[i]);
    }
    free(scene->textures);
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
    const zs_model_opts *o;
    int want_normals;
    int up;               /* ZS_UP_* resolved (never AUTO) */
    const uint8_t *file_normals; /* per assimp mesh: the normals came from the file */
    unsigned long normals_checked, normals_against;
    int32_t *remap;       /* per source vertex: index in the current chunk or -1 */
    size_t remap_cap;
    const zs_texture **mat_tex; /* per material: its texture, once asked */
    uint8_t *mat_asked;
} load_ctx;

/* The texture of material `mat` (asked of the caller once per load). */
static int material_texture(load_ctx *lc, unsigned mat, const zs_texture **out)
{
    zs_texture t, *keep;
    int rc;
    *out = NULL;
    if (lc->o->load_texture == NULL || mat >= lc->ai->mNumMaterials || lc->mat_tex == NULL)
        return 0;
    if (lc->mat_asked[mat]) {
        *out = lc->mat_tex[mat];
        return 0;
    }
    lc->mat_asked[mat] = 1;
    memset(&t, 0, sizeof t);
    rc = lc->o->load_texture(lc->o->texture_user, lc->ai, mat, lc->path, &t);
    if (rc < 0)
        return -1;
    if (rc == 0)
        return 0;
    keep = model_add_texture(lc->scene);
    if (keep == NULL) {
        free((void *)(uintptr_t)t.texels);
        free((void *)(uintptr_t)t.palette);
        return -1;
    }
    *keep = t;
    lc->mat_tex[mat] = keep;
    *out = keep;
    return 0;
}

zs_model_opts zs_model_opts_default(void)
{
    zs_model_opts o;

    memset(&o, 0, sizeof o);
    o.prog = "zspan-sim";
    o.up = ZS_UP_AUTO;
    return o;
}

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

/* Counts a triangle whose file normals point against its winding (the sum
 * of its vertex normals on the back side of its plane). */
static void check_normals(load_ctx *lc, const zs_import_part *part, const unsigned src[3],
                          int flip)
{
    double p[3][3], n[3] = {0, 0, 0}, e1[3], e2[3], f[3], d;
    int j, a;

    for (j = 0; j < 3; j++) {
        double nj[3];
        zs_import_position(part, src[j], p[j]);
        zs_import_normal(part, src[j], nj);
        for (a = 0; a < 3; a++)
            n[a] += nj[a];
    }
    for (a = 0; a < 3; a++) {
        e1[a] = p[1][a] - p[0][a];
        e2[a] = p[2][a] - p[0][a];
    }
    f[0] = e1[1] * e2[2] - e1[2] * e2[1];
    f[1] = e1[2] * e2[0] - e1[0] * e2[2];
    f[2] = e1[0] * e2[1] - e1[1] * e2[0];
    d = f[0] * n[0] + f[1] * n[1] + f[2] * n[2];
    if (part->mirrored != flip)
        d = -d;
    if (d == 0.0 || !isfinite(d))
        return;
    lc->normals_checked++;
    lc->normals_against += d < 0.0;
}

/* Appends the triangles of one placed mesh (walk callback): only the
 * vertices faces use, in face order, split into chunks of CHUNK_MAX. */
static int add_mesh(void *user, const zs_import_part *part)
{
    load_ctx *lc = user;
    const struct aiMesh *m = part->mesh;
    const int normals = lc->want_normals && m->mNormals != NULL;
    const int colors = m->mColors[0] != NULL;
    const int flip = lc->o->flip_winding != 0;
    int file_normals = 0;
    zs_color mat_color = 0;
    int has_mat;
    uint32_t f, nv = m->mNumVertices, max_v, max_t;
    zs_model_chunk *c = NULL;
    const zs_texture *tex = NULL;
    size_t k;

    if (m->mTextureCoords[0] != NULL && material_texture(lc, m->mMaterialIndex, &tex) != 0)
        return -1;
    for (k = 0; k < lc->ai->mNumMeshes; k++)
        if (lc->ai->mMeshes[k] == m)
            file_normals = lc->file_normals[k] && m->mNormals != NULL;
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
        unsigned need = 0, j, src3[3];
        uint16_t tri[3];

        if (face->mNumIndices != 3)
            continue; /* points and lines */
        for (j = 0; j < 3; j++) {
            if (face->mIndices[j] >= nv) {
                fprintf(stderr, "%s: %s: face %u has a bad vertex index\n", lc->o->prog,
                        lc->path, (unsigned)f);
                return -1;
            }
            src3[j] = face->mIndices[j];
            if (c == NULL || lc->remap[face->mIndices[j]] < 0)
                need++;
        }
        if (file_normals)
            check_normals(lc, part, src3, flip);
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
            if (tex != NULL) {
                c->texture = tex;
                c->uv = malloc((size_t)max_v * 2 * sizeof *c->uv);
                if (c->uv == NULL)
                    goto oom;
            }
        }
        for (j = 0; j < 3; j++) {
            unsigned src = face->mIndices[j];
            if (lc->remap[src] < 0) {
                uint32_t d = c->vcount++;
                double *p = &c->pos[3 * d];
                int a;
                lc->scene->total_verts++;
                zs_import_position(part, src, p);
                zs_import_up_to_y(lc->up, p);
                for (a = 0; a < 3; a++) {
                    if (!isfinite(p[a])) {
                        fprintf(stderr, "%s: %s: vertex %u is not finite\n", lc->o->prog,
                                lc->path, src);
                        return -1;
                    }
                }
                if (normals) {
                    zs_import_normal(part, src, &c->nrm[3 * d]);
                    zs_import_up_to_y(lc->up, &c->nrm[3 * d]);
                    if (flip)
                        for (a = 0; a < 3; a++)
                            c->nrm[3 * d + (uint32_t)a] = -c->nrm[3 * d + (uint32_t)a];
                }
                if (colors)
                    c->vcol[d] = zs_import_color(m->mColors[0][src].r, m->mColors[0][src].g,
                                                 m->mColors[0][src].b);
                if (c->uv != NULL) {
                    c->uv[2 * d] = m->mTextureCoords[0][src].x;
                    c->uv[2 * d + 1] = m->mTextureCoords[0][src].y;
                    if (!isfinite(c->uv[2 * d]) || !isfinite(c->uv[2 * d + 1])) {
                        fprintf(stderr, "%s: %s: vertex %u has a texture coordinate that is "
                                        "not finite\n", lc->o->prog, lc->path, src);
                        return -1;
                    }
                }
                lc->remap[src] = (int32_t)d;
            }
            tri[j] = (uint16_t)lc->remap[src];
        }
        if (part->mirrored != flip) {
            /* A mirroring node transform turns the winding over (keep fronts
             * in front); --flip-winding turns it over on purpose. */
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
    fprintf(stderr, "%s: %s: out of memory\n", lc->o->prog, lc->path);
    return -1;
}

static uint32_t get_le(const uint8_t *p, int bytes)
{
    uint32_t v = 0;
    int k;

    for (k = bytes - 1; k >= 0; k--)
        v = (v << 8) | p[k];
    return v;
}

/* The converter's binary mesh (ZS_ZSM_MAGIC) as one chunk. */
static int load_zsm(zs_model *scene, const char *path, const zs_model_opts *o, FILE *fp)
{
    uint8_t hdr[ZS_ZSM_HEADER_BYTES];
    uint8_t *buf = NULL;
    uint32_t flags, color, vc, tc, t, k;
    int32_t scale;
    size_t need, off;
    zs_model_chunk *c;
    int up = o->up == ZS_UP_AUTO ? ZS_UP_Y : o->up, a;
    const char *why = NULL;
    zs_texture tex;

    memset(&tex, 0, sizeof tex);
    if (fread(hdr, 1, sizeof hdr, fp) != sizeof hdr) {
        why = "truncated header";
        goto bad;
    }
    flags = get_le(hdr + 8, 4);
    scale = (int32_t)get_le(hdr + 12, 4);
    color = get_le(hdr + 16, 4);
    vc = get_le(hdr + 20, 2);
    tc = get_le(hdr + 22, 2);
    if ((flags & ~31u) != 0 || scale <= 0 || color > 0xFFFFFFu || vc == 0 || tc == 0) {
        why = "bad header (flags, scale, colour or counts)";
        goto bad;
    }
    need = (size_t)vc * 6u + (size_t)tc * 6u;
    if (flags & ZS_ZSM_FACE_COLORS)
        need += (size_t)tc * 4u;
    if (flags & ZS_ZSM_VERTEX_COLORS)
        need += (size_t)vc * 4u;
    if (flags & ZS_ZSM_FACE_NORMALS)
        need += (size_t)tc * 6u;
    if (flags & ZS_ZSM_VERTEX_NORMALS)
        need += (size_t)vc * 6u;
    if (flags & ZS_ZSM_TEXTURE) {
        /* uvs and the texture's header; its texels follow */
        uint8_t th[8];
        size_t texbytes;
        need += (size_t)vc * 4u;
        if (fseek(fp, (long)(ZS_ZSM_HEADER_BYTES + need), SEEK_SET) != 0 ||
            fread(th, 1, sizeof th, fp) != sizeof th) {
            why = "the size does not match the header's counts";
            goto bad;
        }
        tex.width = (uint16_t)get_le(th, 2);
        tex.height = (uint16_t)get_le(th + 2, 2);
        tex.format = th[4];
        tex.flags = th[5];
        tex.texels = th; /* for the check only */
        tex.palette = (const uint16_t *)(const void *)th;
        if (zs_texture_check(&tex) != ZS_OK || get_le(th + 6, 2) != 0) {
            why = "a bad texture (size, format or flags)";
            goto bad;
        }
        texbytes = (size_t)tex.width * tex.height * (tex.format == ZS_TEX_PAL8 ? 1u : 2u) +
                   (tex.format == ZS_TEX_PAL8 ? 512u : 0u);
        need += sizeof th + texbytes;
        if (fseek(fp, (long)ZS_ZSM_HEADER_BYTES, SEEK_SET) != 0) {
            why = "cannot seek";
            goto bad;
        }
    }
    buf = malloc(need + 1);
    if (buf == NULL)
        goto oom;
    if (fread(buf, 1, need + 1, fp) != need) {
        why = "the size does not match the header's counts";
        goto bad;
    }
    c = scene_new_chunk(scene);
    if (c == NULL ||
        chunk_alloc(c, vc, tc, (flags & ZS_ZSM_VERTEX_NORMALS) != 0,
                    (flags & ZS_ZSM_VERTEX_COLORS) != 0) != 0)
        goto oom;
    c->first_tri = scene->total_tris;
    c->vcount = vc;
    c->tcount = tc;
    c->has_material_color = 1;
    c->material_color = color;
    for (k = 0; k < vc * 3u; k++)
        c->pos[k] = (double)(int16_t)get_le(buf + 2u * k, 2) * (double)scale / 65536.0;
    off = (size_t)vc * 6u;
    for (k = 0; k < tc * 3u; k++) {
        uint32_t v = get_le(buf + off + 2u * k, 2);
        if (v >= vc) {
            why = "a triangle index is not below the vertex count";
            goto bad;
        }
        c->idx[k] = (uint16_t)v;
    }
    off += (size_t)tc * 6u;
    if (flags & ZS_ZSM_FACE_COLORS) {
        c->fcol = malloc((size_t)tc * sizeof *c->fcol);
        if (c->fcol == NULL)
            goto oom;
        for (t = 0; t < tc; t++)
            c->fcol[t] = get_le(buf + off + 4u * t, 4) & 0xFFFFFFu;
        off += (size_t)tc * 4u;
    }
    if (flags & ZS_ZSM_VERTEX_COLORS) {
        for (k = 0; k < vc; k++)
            c->vcol[k] = get_le(buf + off + 4u * k, 4) & 0xFFFFFFu;
        off += (size_t)vc * 4u;
    }
    if (flags & ZS_ZSM_FACE_NORMALS)
        off += (size_t)tc * 6u; /* the core computes face normals from the winding */
    if (flags & ZS_ZSM_VERTEX_NORMALS) {
        for (k = 0; k < vc * 3u; k++)
            c->nrm[k] = (double)(int16_t)get_le(buf + off + 2u * k, 2) / 16384.0;
        off += (size_t)vc * 6u;
    }
    if (flags & ZS_ZSM_TEXTURE) {
        zs_texture *keep = model_add_texture(scene);
        size_t n = (size_t)tex.width * tex.height, j;
        uint16_t *pal = NULL;
        if (keep == NULL || (c->quv = malloc((size_t)vc * 2u * sizeof *c->quv)) == NULL)
            goto oom;
        for (k = 0; k < vc * 2u; k++)
            c->quv[k] = (int16_t)get_le(buf + off + 2u * k, 2);
        off += (size_t)vc * 4u + 8u;
        *keep = tex;
        keep->texels = NULL;
        keep->palette = NULL;
        if (tex.format == ZS_TEX_PAL8) {
            uint8_t *t8 = malloc(n);
            pal = malloc(256 * sizeof *pal);
            if (t8 == NULL || pal == NULL) {
                free(t8);
                free(pal);
                goto oom;
            }
            for (j = 0; j < 256; j++)
                pal[j] = (uint16_t)get_le(buf + off + 2u * j, 2);
            memcpy(t8, buf + off + 512u, n);
            keep->texels = t8;
            keep->palette = pal;
        } else {
            uint16_t *t16 = malloc(n * sizeof *t16);
            if (t16 == NULL)
                goto oom;
            for (j = 0; j < n; j++)
                t16[j] = (uint16_t)get_le(buf + off + 2u * j, 2);
            keep->texels = t16;
        }
        c->texture = keep;
    }
    for (k = 0; k < vc; k++) {
        zs_import_up_to_y(up, &c->pos[3 * k]);
        if (c->nrm != NULL) {
            zs_import_up_to_y(up, &c->nrm[3 * k]);
            if (o->flip_winding)
                for (a = 0; a < 3; a++)
                    c->nrm[3 * k + (uint32_t)a] = -c->nrm[3 * k + (uint32_t)a];
        }
    }
    if (o->flip_winding)
        for (t = 0; t < tc; t++) {
            uint16_t x = c->idx[3 * t + 1];
            c->idx[3 * t + 1] = c->idx[3 * t + 2];
            c->idx[3 * t + 2] = x;
        }
    scene->total_tris += tc;
    scene->total_verts += vc;
    free(buf);
    return 0;
bad:
    fprintf(stderr, "%s: %s: not a valid zspan-meshc binary mesh: %s\n", o->prog, path, why);
    free(buf);
    return -1;
oom:
    fprintf(stderr, "%s: %s: out of memory\n", o->prog, path);
    free(buf);
    return -1;
}

/* Signed volume the chunks from `first` enclose, as a share of their bounding
 * box: about -1..1 for closed meshes (negative: clockwise seen from
 * outside); 0 when too small to say (an open sheet, a thin mesh). */
static double winding_volume(const zs_model *scene, size_t first)
{
    double vol = 0.0, lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, box;
    size_t i;
    uint32_t t, v;
    int a, any = 0;

    for (i = first; i < scene->count; i++) {
        const zs_model_chunk *c = &scene->chunks[i];
        for (v = 0; v < c->vcount; v++)
            for (a = 0; a < 3; a++) {
                double x = c->pos[3 * v + (uint32_t)a];
                if (!any || x < lo[a])
                    lo[a] = x;
                if (!any || x > hi[a])
                    hi[a] = x;
                any = a == 2 ? 1 : any;
            }
    }
    for (i = first; i < scene->count; i++) {
        const zs_model_chunk *c = &scene->chunks[i];
        for (t = 0; t < c->tcount; t++) {
            double p[3][3];
            int j;
            for (j = 0; j < 3; j++)
                for (a = 0; a < 3; a++) /* about the box's centre: better rounding */
                    p[j][a] = c->pos[3u * c->idx[3 * t + (uint32_t)j] + (uint32_t)a] -
                              0.5 * (lo[a] + hi[a]);
            vol += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                    p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                    p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6.0;
        }
    }
    box = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    if (!(box > 0.0) || !isfinite(vol / box) || fabs(vol / box) < 0.02)
        return 0.0;
    return vol / box;
}

int zs_model_load(zs_model *scene, const char *path, int want_normals)
{
    zs_model_opts o = zs_model_opts_default();

    o.want_normals = want_normals;
    return zs_model_load_opts(scene, path, &o);
}

int zs_model_load_opts(zs_model *scene, const char *path, const zs_model_opts *o)
{
    const struct aiScene *ai;
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
    load_ctx lc;
    uint32_t before = scene->total_tris;
    uint8_t *file_normals = NULL;
    size_t first_chunk = scene->count;
    unsigned nmeshes;
    char magic[8];
    struct stat sb;
    FILE *probe;
    unsigned k;
    int rc;

    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        fprintf(stderr, "%s: %s is a directory, not a mesh file\n", o->prog, path);
        return -1;
    }
    probe = fopen(path, "rb");
    if (probe == NULL) {
        fprintf(stderr, "%s: cannot open %s: %s\n", o->prog, path, strerror(errno));
        return -1;
    }
    if (fread(magic, 1, sizeof magic, probe) == sizeof magic &&
        memcmp(magic, ZS_ZSM_MAGIC, sizeof magic) == 0) {
        rewind(probe);
        rc = load_zsm(scene, path, o, probe);
        fclose(probe);
        return rc;
    }
    fclose(probe);
    /* Which meshes bring their own normals: from an import without smooth
     * normals (assimp's normals step cannot run on its own afterwards). */
    if (o->want_normals > 1)
        flags |= aiProcess_GenSmoothNormals | aiProcess_ForceGenNormals;
    zs_import_guard_begin(o->prog, path, 1);
    ai = aiImportFile(path, flags);
    zs_import_guard_end();
    if (ai == NULL) {
        fprintf(stderr, "%s: cannot load %s: %s\n", o->prog, path, aiGetErrorString());
        return -1;
    }
    if ((ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || ai->mRootNode == NULL) {
        fprintf(stderr, "%s: %s has no triangles (an incomplete scene)\n", o->prog, path);
        aiReleaseImport(ai);
        return -1;
    }
    nmeshes = ai->mNumMeshes;
    file_normals = calloc(nmeshes + 1u, 1);
    if (file_normals == NULL) {
        aiReleaseImport(ai);
        fprintf(stderr, "%s: %s: out of memory\n", o->prog, path);
        return -1;
    }
    for (k = 0; k < nmeshes; k++)
        file_normals[k] = ai->mMeshes != NULL && ai->mMeshes[k] != NULL &&
                          ai->mMeshes[k]->mNormals != NULL && o->want_normals < 2;
    if (o->want_normals == 1) {
        /* Again, with smooth normals made where the file has none. */
        aiReleaseImport(ai);
        zs_import_guard_begin(o->prog, path, 1);
        ai = aiImportFile(path, flags | aiProcess_GenSmoothNormals);
        zs_import_guard_end();
        if (ai == NULL || ai->mNumMeshes != nmeshes || ai->mRootNode == NULL) {
            fprintf(stderr, "%s: cannot load %s: %s\n", o->prog, path,
                    ai == NULL ? aiGetErrorString() : "a second import differs");
            if (ai != NULL)
                aiReleaseImport(ai);
            free(file_normals);
            return -1;
        }
    }
    memset(&lc, 0, sizeof lc);
    lc.scene = scene;
    lc.ai = ai;
    lc.path = path;
    lc.o = o;
    lc.want_normals = o->want_normals;
    lc.up = o->up == ZS_UP_AUTO ? zs_import_file_up(ai) : o->up;
    lc.file_normals = file_normals;
    if (o->load_texture != NULL && ai->mNumMaterials > 0) {
        lc.mat_tex = calloc(ai->mNumMaterials, sizeof *lc.mat_tex);
        lc.mat_asked = calloc(ai->mNumMaterials, 1);
        if (lc.mat_tex == NULL || lc.mat_asked == NULL) {
            free(lc.mat_tex);
            free(lc.mat_asked);
            lc.mat_tex = NULL;
        }
    }
    rc = zs_import_walk(ai, add_mesh, &lc);
    free(lc.mat_tex);
    free(lc.mat_asked);
    if (rc == ZS_IMPORT_ERR_MESH || rc == ZS_IMPORT_ERR_DEPTH)
        fprintf(stderr, "%s: %s: %s\n", o->prog, path,
                rc == ZS_IMPORT_ERR_MESH ? "a node refers to a missing mesh"
                                         : "node hierarchy too deep");
    free(lc.remap);
    free(file_normals);
    aiReleaseImport(ai);
    if (rc != 0)
        return -1;
    if (scene->total_tris == before) {
        fprintf(stderr, "%s: %s has no triangles (points and lines are not drawn)\n", o->prog,
                path);
        return -1;
    }
    if (!o->quiet && lc.normals_checked == 0 && winding_volume(scene, first_chunk) < 0.0)
        fprintf(stderr,
                "%s: warning: %s: the triangles enclose a negative volume (they wind clockwise "
                "seen from outside): if it looks inside out, try --flip-winding\n",
                o->prog, path);
    if (!o->quiet && lc.normals_checked > 0 && lc.normals_against * 2 > lc.normals_checked)
        fprintf(stderr,
                "%s: warning: %s: the file's normals point against the winding of %lu of %lu "
                "triangles: if it looks inside out, try --flip-winding (clockwise faces); "
                "--smooth recomputes the normals from the winding\n",
                o->prog, path, lc.normals_against, lc.normals_checked);
    return 0;
}

int zs_model_add_back_faces(zs_model *scene)
{
    size_t n = scene->count, i;

    for (i = 0; i < n; i++) {
        zs_model_chunk *c, *src;
        uint32_t t, k, nv3;
        c = scene_new_chunk(scene);
        if (c == NULL)
            return -1;
        src = &scene->chunks[i]; /* after the realloc */
        nv3 = src->vcount * 3u;
        c->vcount = src->vcount;
        c->tcount = src->tcount;
        c->first_tri = scene->total_tris + src->first_tri;
        c->has_material_color = src->has_material_color;
        c->material_color = src->material_color;
        c->idx = malloc((size_t)(src->tcount ? src->tcount : 1) * 3u * sizeof *c->idx);
        if (c->idx == NULL)
            return -1;
        for (t = 0; t < src->tcount; t++) {
            c->idx[3 * t] = src->idx[3 * t];
            c->idx[3 * t + 1] = src->idx[3 * t + 2];
            c->idx[3 * t + 2] = src->idx[3 * t + 1];
        }
        c->mesh = src->mesh;
        c->mesh.indices = c->idx;
        if (src->qnrm != NULL) {
            c->qnrm = malloc((size_t)(nv3 ? nv3 : 1) * sizeof *c->qnrm);
            if (c->qnrm == NULL)
                return -1;
            for (k = 0; k < nv3; k++)
                c->qnrm[k] = (int16_t)-src->qnrm[k];
            c->mesh.vertex_normals = c->qnrm;
        }
        /* Positions, colours and face normals stay the originals' (shared,
         * owned by them); the core computes the copy's face normals. */
        c->mesh.face_normals = NULL;
    }
    scene->total_tris *= 2u;
    scene->total_verts *= 2u;
    return 0;
}

int zs_model_bounds(const zs_model *scene, double lo[3], double hi[3])
{
    size_t i;
    uint32_t v;
    int a, any = 0;

    for (i = 0; i < scene->count; i++) {
        const zs_model_chunk *c = &scene->chunks[i];
        if (c->pos == NULL)
            continue; /* a back-face copy (zs_model_add_back_faces) */
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
        if (c->pos == NULL)
            continue;
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
        if (ch->pos == NULL)
            continue;
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

        if (c->pos == NULL)
            continue;
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
        if (c->uv != NULL && c->texture != NULL && c->quv == NULL) {
            /* v turned to run down the rows; whole repeats taken off (not
             * with clamp) so that they fit Q3.12, as the converter does */
            double lo[2] = {0, 0}, hi[2] = {0, 0}, shift[2] = {0, 0};
            uint32_t v;
            int a;
            for (v = 0; v < c->vcount; v++)
                for (a = 0; a < 2; a++) {
                    double t = a ? 1.0 - c->uv[2 * v + 1] : c->uv[2 * v];
                    if (v == 0 || t < lo[a])
                        lo[a] = t;
                    if (v == 0 || t > hi[a])
                        hi[a] = t;
                }
            if (!(c->texture->flags & ZS_TEX_CLAMP))
                for (a = 0; a < 2; a++)
                    shift[a] = floor((lo[a] + hi[a]) / 2.0);
            c->quv = malloc((size_t)(c->vcount ? c->vcount : 1) * 2 * sizeof *c->quv);
            if (c->quv == NULL)
                goto oom;
            for (v = 0; v < c->vcount; v++)
                for (a = 0; a < 2; a++) {
                    double t = ((a ? 1.0 - c->uv[2 * v + 1] : c->uv[2 * v]) - shift[a]) * ZS_UV_ONE;
                    t = floor(t + 0.5);
                    if (t < -32768.0 || t > 32767.0) {
                        fprintf(stderr, "zspan-sim: texture coordinates span %g..%g: more than "
                                        "the core's -8..8\n", lo[a], hi[a]);
                        return -1;
                    }
                    c->quv[2 * v + (uint32_t)a] = (int16_t)t;
                }
        }
        memset(&c->mesh, 0, sizeof c->mesh);
        if (c->quv != NULL && c->texture != NULL) {
            c->mesh.uvs = c->quv;
            c->mesh.texture = c->texture;
        }
        c->mesh.positions = c->qpos;
        c->mesh.indices = c->idx;
        c->mesh.vertex_normals = c->qnrm;
        c->mesh.vertex_colors = c->vcol;
        c->mesh.face_colors = c->fcol; /* a binary mesh's own; else the caller's */
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
                          zs_shading shade, double deg, zs_format fmt, unsigned mono)
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
    sp.mono = (uint8_t)mono;
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
