/* SPDX-License-Identifier: MIT */
/*
 * zspan-meshc: converts any model assimp can read into a C source and header
 * holding a zs_mesh in the core's format (int16 positions + Q16.16 scale,
 * uint16 indices, optional face/vertex colours and Q1.14 normals).
 *
 * Host tool, C99 + assimp (C API). See `zspan-meshc --help` and README.md (Meshes, firmware and the benchmark).
 *
 * Pipeline: import (validated) -> triangulate -> flatten the node hierarchy
 * (node transforms applied) -> merge identical vertices -> centre / fit /
 * scale -> optional decimation (vertex clustering) -> colours and normals ->
 * quantise -> write NAME.c and NAME.h.
 */
#define _POSIX_C_SOURCE 200809L
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <time.h>

#include "zs_bsp_build.h"
#include "zs_import.h"
#include "zs_opts.h"
#include "zs_teximg.h"
#include "zspan/zspan.h"

#define MESHC_VERSION ZSPAN_VERSION_STRING
#define MAX_OUT 65535u              /* uint16 indices and counts */
#define MAX_IN_VERTICES (1u << 26)  /* refuse absurd input before touching it */
#define MAX_IN_FACES (1u << 26)

enum { EXIT_USAGE = 2, EXIT_INPUT = 3, EXIT_LIMIT = 4, EXIT_IO = 5 };

enum color_src { COL_NONE, COL_MATERIAL, COL_VERTEX, COL_INDEX };
enum normal_kind { NRM_NONE, NRM_FACE, NRM_SMOOTH, NRM_FILE };

typedef struct options {
    const char *input;
    const char *output;      /* base path; NAME.c / NAME.h */
    const char *name;
    int center;
    int fit;                 /* scale so the largest vertex distance == fit_radius */
    double fit_radius;
    double scale;
    long quant_scale;        /* forced Q16.16 scale, 0 = automatic */
    unsigned long max_tris, max_verts;
    enum color_src colors;
    uint32_t base_color;
    enum normal_kind normals;
    int merge;
    int flip;
    int lenient;
    int info_only;
    int quiet;
    int zsm;                 /* --format zsm: BASE.zsm instead of BASE.c + BASE.h */
    int up_axis;             /* the file's up axis (zs_opt_up_axis), 0 = its metadata */
    long mem_limit_mb;       /* address-space limit while importing; 0 = none, -1 = auto */
    int bsp;                 /* --bsp: also a BSP tree (zspan/priority.h) */
    long bsp_weight, bsp_candidates;
    int tex_mode;            /* TEX_AUTO, TEX_NONE, TEX_FILE (--texture) */
    const char *tex_file;
    unsigned tex_size;       /* --texture-size: largest side, a power of two */
    int tex_resample;        /* 0: --no-resample */
    unsigned tex_format;     /* ZS_TEX_RGB565 or ZS_TEX_PAL8 */
    unsigned tex_flags;      /* ZS_TEX_BILINEAR | ZS_TEX_CLAMP | ZS_TEX_SUBDIV */
} options;

enum { TEX_AUTO, TEX_NONE, TEX_FILE };
#define TEX_DEFAULT_SIZE 64u

typedef struct vert {
    double p[3];
    double n[3];      /* file normal (NRM_FILE) */
    double c[3];      /* file colour (COL_VERTEX), 0..1 */
    double uv[2];     /* texture coordinates as the file has them (v up), textured models */
    int has_uv;
} vert;

typedef struct tri {
    uint32_t v[3];
    uint32_t color;   /* 0x00RRGGBB, for COL_MATERIAL / COL_INDEX */
} tri;

typedef struct model {
    vert *v;
    size_t nv, cap_v;
    tri *t;
    size_t nt, cap_t;
    size_t skipped_prims;  /* points and lines */
    size_t degenerate;     /* triangles with repeated indices after merging */
    int textured;          /* the mesh gets uvs and a texture */
    zs_texture tex;        /* decoded and sized (malloc'd texels) */
    char tex_ref[256];     /* its name in the model, or the --texture file */
    unsigned tex_w0, tex_h0; /* the image's own size */
    unsigned tex_mat;      /* the material it came from */
    size_t tex_missing;    /* triangles of the textured model without coordinates */
} model;

static const char *g_prog = "zspan-meshc";
static const char *g_input = "";

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: error: %s: ", g_prog, g_input);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

static void warn(const options *o, const char *fmt, ...)
{
    va_list ap;
    if (o->quiet)
        return;
    fprintf(stderr, "%s: warning: %s: ", g_prog, g_input);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q)
        die(EXIT_LIMIT, "out of memory (%zu bytes)", n);
    return q;
}

/* assimp aborts on a few internal assertions; turn that into a clear message. */
static void on_fatal_signal(int sig)
{
    static const char msg1[] = ": error: the model importer crashed (signal ";
    static const char msg2[] = ") while reading ";
    char num[4];
    int k = 0;
    num[k++] = (char)('0' + (sig / 10) % 10);
    num[k++] = (char)('0' + sig % 10);
    (void)!write(2, g_prog, strlen(g_prog));
    (void)!write(2, msg1, sizeof msg1 - 1);
    (void)!write(2, num, (size_t)k);
    (void)!write(2, msg2, sizeof msg2 - 1);
    (void)!write(2, g_input, strlen(g_input));
    (void)!write(2, "\n", 1);
    _exit(EXIT_INPUT);
}

/* ------------------------------------------------------------------ */
/* assimp log capture: loader errors are fatal unless --lenient          */
/* ------------------------------------------------------------------ */

static char g_log_errors[2048];
static size_t g_log_error_count;

static void log_cb(const char *msg, char *user)
{
    size_t len, have;
    (void)user;
    if (strncmp(msg, "Error,", 6) != 0)
        return;
    g_log_error_count++;
    msg += 6;
    while (*msg == ' ')
        msg++;
    if (strncmp(msg, "T0: ", 4) == 0)
        msg += 4;
    have = strlen(g_log_errors);
    len = strlen(msg);
    while (len && (msg[len - 1] == '\n' || msg[len - 1] == '\r'))
        len--;
    if (have + len + 8 < sizeof g_log_errors) {
        memcpy(g_log_errors + have, "\n  ", 3);
        memcpy(g_log_errors + have + 3, msg, len);
        g_log_errors[have + 3 + len] = 0;
    }
}

/* ------------------------------------------------------------------ */
/* Import                                                               */
/* ------------------------------------------------------------------ */

static void add_vert(model *m, const vert *v)
{
    if (m->nv == m->cap_v) {
        m->cap_v = m->cap_v ? m->cap_v * 2 : 1024;
        m->v = xrealloc(m->v, m->cap_v * sizeof *m->v);
    }
    m->v[m->nv++] = *v;
}

static void add_tri(model *m, const tri *t)
{
    if (m->nt == m->cap_t) {
        m->cap_t = m->cap_t ? m->cap_t * 2 : 1024;
        m->t = xrealloc(m->t, m->cap_t * sizeof *m->t);
    }
    m->t[m->nt++] = *t;
}

static void check_mesh(const struct aiMesh *me, unsigned idx)
{
    unsigned f;
    if (me->mNumVertices > MAX_IN_VERTICES)
        die(EXIT_LIMIT, "mesh %u declares %u vertices (more than %u): oversized model", idx,
            me->mNumVertices, MAX_IN_VERTICES);
    if (me->mNumFaces > MAX_IN_FACES)
        die(EXIT_LIMIT, "mesh %u declares %u faces (more than %u): oversized model", idx,
            me->mNumFaces, MAX_IN_FACES);
    if (me->mNumVertices && !me->mVertices)
        die(EXIT_INPUT, "mesh %u has no vertex positions", idx);
    if (me->mNumFaces && !me->mFaces)
        die(EXIT_INPUT, "mesh %u has no faces", idx);
    for (f = 0; f < me->mNumFaces; f++) {
        const struct aiFace *fc = &me->mFaces[f];
        unsigned k;
        if (fc->mNumIndices && !fc->mIndices)
            die(EXIT_INPUT, "mesh %u face %u has no indices", idx, f);
        for (k = 0; k < fc->mNumIndices; k++)
            if (fc->mIndices[k] >= me->mNumVertices)
                die(EXIT_INPUT, "mesh %u face %u: vertex index %u out of range (%u vertices)",
                    idx, f, fc->mIndices[k], me->mNumVertices);
    }
}

typedef struct collect_ctx {
    const options *o;
    model *m;
} collect_ctx;

/* The name of a material's diffuse texture, "" if it has none. */
static void material_tex_ref(const struct aiScene *s, unsigned mat, char *out, size_t n)
{
    struct aiString path;
    out[0] = 0;
    if (!s->mMaterials || mat >= s->mNumMaterials || !s->mMaterials[mat])
        return;
    if (aiGetMaterialTexture(s->mMaterials[mat], aiTextureType_DIFFUSE, 0, &path, NULL, NULL,
                             NULL, NULL, NULL, NULL) == aiReturn_SUCCESS ||
        aiGetMaterialTexture(s->mMaterials[mat], aiTextureType_BASE_COLOR, 0, &path, NULL, NULL,
                             NULL, NULL, NULL, NULL) == aiReturn_SUCCESS)
        snprintf(out, n, "%.*s", (int)path.length, path.data);
}

static int timg_exit(int rc)
{
    return rc == ZS_TIMG_ERR_SIZE || rc == ZS_TIMG_ERR_MEMORY ? EXIT_LIMIT : EXIT_INPUT;
}

/* Decodes and sizes the texture (from the material, or --texture's file). */
static void load_texture(const options *o, model *m, const struct aiScene *s, unsigned mat)
{
    zs_timg img;
    char msg[768];
    int rc;
    if (o->tex_mode == TEX_FILE) {
        snprintf(m->tex_ref, sizeof m->tex_ref, "%s", o->tex_file);
        rc = zs_timg_read_file(o->tex_file, &img, msg, sizeof msg);
    } else {
        rc = zs_timg_material(s, mat, o->input, &img, m->tex_ref, sizeof m->tex_ref, msg,
                              sizeof msg);
        if (rc == ZS_TIMG_NONE)
            die(EXIT_INPUT, "material %u: its texture %s cannot be found", mat, m->tex_ref);
    }
    if (rc != ZS_TIMG_OK)
        die(timg_exit(rc), "texture %s: %s (--texture none converts without it)", m->tex_ref,
            msg);
    m->tex_w0 = img.w;
    m->tex_h0 = img.h;
    m->tex_mat = mat;
    rc = zs_timg_make_texture(&img, m->tex_ref, o->tex_size, o->tex_resample, o->tex_format,
                              o->tex_flags, &m->tex, msg, sizeof msg);
    if (rc != ZS_TIMG_OK)
        die(timg_exit(rc), "%s", rc == ZS_TIMG_ERR_MEMORY ? "out of memory (texture)" : msg);
    m->textured = 1;
}

/* One mesh placed by its node (zs_import_walk callback): every vertex, and
 * its faces as triangles (fans for anything triangulation left). */
static int collect_mesh(void *user, const zs_import_part *part)
{
    const collect_ctx *cc = user;
    const options *o = cc->o;
    model *m = cc->m;
    const struct aiMesh *me = part->mesh;
    size_t base = m->nv;
    unsigned vi, f;
    uint32_t mcol = 0xFFFFFFu;
    int up = o->up_axis ? o->up_axis : zs_import_file_up(part->scene);
    int tex_here = 0;

    (void)zs_import_material_color(part->scene, me->mMaterialIndex, &mcol);
    if (o->tex_mode == TEX_FILE) {
        tex_here = me->mTextureCoords[0] != NULL;
        if (tex_here && !m->textured)
            load_texture(o, m, part->scene, me->mMaterialIndex);
    } else if (o->tex_mode == TEX_AUTO) {
        char ref[256];
        material_tex_ref(part->scene, me->mMaterialIndex, ref, sizeof ref);
        if (ref[0] && !me->mTextureCoords[0]) {
            warn(o, "material %u has the texture %s but its mesh has no texture coordinates",
                 me->mMaterialIndex, ref);
        } else if (ref[0]) {
            if (!m->textured)
                load_texture(o, m, part->scene, me->mMaterialIndex);
            else if (strcmp(ref, m->tex_ref) != 0)
                die(EXIT_INPUT, "the materials use more than one texture (%s, %s); a zs_mesh "
                                "takes one: pick one with --texture FILE, or --texture none",
                    m->tex_ref, ref);
            tex_here = 1;
        }
    }
    for (vi = 0; vi < me->mNumVertices; vi++) {
        vert v;
        memset(&v, 0, sizeof v);
        zs_import_position(part, vi, v.p);
        zs_import_up_to_y(up, v.p);
        if (o->normals == NRM_FILE && me->mNormals) {
            zs_import_normal(part, vi, v.n);
            zs_import_up_to_y(up, v.n);
        }
        if (o->colors == COL_VERTEX) {
            if (me->mColors[0]) {
                v.c[0] = me->mColors[0][vi].r;
                v.c[1] = me->mColors[0][vi].g;
                v.c[2] = me->mColors[0][vi].b;
            } else {
                v.c[0] = (double)((mcol >> 16) & 255) / 255.0;
                v.c[1] = (double)((mcol >> 8) & 255) / 255.0;
                v.c[2] = (double)(mcol & 255) / 255.0;
            }
        }
        if (tex_here) {
            v.uv[0] = me->mTextureCoords[0][vi].x;
            v.uv[1] = me->mTextureCoords[0][vi].y;
            v.has_uv = 1;
        }
        add_vert(m, &v);
    }
    for (f = 0; f < me->mNumFaces; f++) {
        const struct aiFace *fc = &me->mFaces[f];
        unsigned k2;
        if (fc->mNumIndices < 3) {
            m->skipped_prims++;
            continue;
        }
        /* Triangulated by assimp; a fan covers anything left (convex). A
         * mirroring node transform turns the winding over: keep fronts in front. */
        for (k2 = 1; k2 + 1 < fc->mNumIndices; k2++) {
            unsigned b = part->mirrored ? k2 + 1 : k2, c = part->mirrored ? k2 : k2 + 1;
            tri t;
            t.v[0] = (uint32_t)(base + fc->mIndices[0]);
            t.v[1] = (uint32_t)(base + fc->mIndices[b]);
            t.v[2] = (uint32_t)(base + fc->mIndices[c]);
            t.color = mcol;
            add_tri(m, &t);
        }
    }
    return 0;
}

static void import_model(const options *o, model *m)
{
    const struct aiScene *s;
    struct aiLogStream ls;
    collect_ctx cc;
    unsigned i;
    int rc;
    FILE *probe;
    struct stat st;
    rlim_t limit = 0;

    if (stat(o->input, &st) == 0 && S_ISDIR(st.st_mode))
        die(EXIT_INPUT, "is a directory, not a mesh file");
    probe = fopen(o->input, "rb");
    if (!probe)
        die(EXIT_INPUT, "cannot open: %s", strerror(errno));
    if (fgetc(probe) == EOF) {
        fclose(probe);
        die(EXIT_INPUT, "the file is empty");
    }
    fclose(probe);
    /* A corrupt header can make a loader reserve hundreds of gigabytes (see
     * assimp's invalid/OutOfMemory.off). Cap the address space so that such an
     * allocation fails at once and the importer reports it. */
    if (o->mem_limit_mb < 0 && stat(o->input, &st) == 0)
        limit = ((rlim_t)2048 << 20) + (rlim_t)st.st_size * 256u;
    else if (o->mem_limit_mb > 0)
        limit = (rlim_t)o->mem_limit_mb << 20;
    if (limit) {
        struct rlimit rl;
        if (getrlimit(RLIMIT_AS, &rl) == 0 && (rl.rlim_cur == RLIM_INFINITY || rl.rlim_cur > limit)) {
            rl.rlim_cur = limit;
            (void)setrlimit(RLIMIT_AS, &rl);
        }
    }

    ls.callback = log_cb;
    ls.user = NULL;
    aiAttachLogStream(&ls);
    /* Some malformed files make the importer loop forever (a 330-byte PLY
     * does in assimp 5.2): the shared guard stops it with a message. */
    zs_import_guard_begin("zspan-meshc: error", g_input, EXIT_INPUT);
    s = aiImportFile(o->input, aiProcess_ValidateDataStructure);
    zs_import_guard_end();
    if (!s) {
        const char *err = aiGetErrorString();
        if (strstr(err, "bad_alloc") || strstr(err, "memory"))
            die(EXIT_LIMIT, "cannot read the model: %s (it asks for more memory than the "
                            "%lu MB limit: a corrupt header or an oversized model; see "
                            "--mem-limit)", err, (unsigned long)(limit >> 20));
        die(EXIT_INPUT, "cannot read the model: %s", err);
    }
    if (g_log_error_count && !o->lenient) {
        aiReleaseImport(s);
        die(EXIT_INPUT, "the importer reported problems (use --lenient to convert anyway):%s",
            g_log_errors);
    }
    if (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        die(EXIT_INPUT, "has no triangles (the importer read no geometry)");
    if (!s->mNumMeshes || !s->mMeshes)
        die(EXIT_INPUT, "has no triangles (no meshes)");
    for (i = 0; i < s->mNumMeshes; i++) {
        if (!s->mMeshes[i])
            die(EXIT_INPUT, "mesh %u is missing", i);
        check_mesh(s->mMeshes[i], i);
    }
    /* Safe now: the structure is validated. Triangulate concave polygons. */
    s = aiApplyPostProcessing(s, aiProcess_Triangulate);
    if (!s)
        die(EXIT_INPUT, "triangulation failed: %s", aiGetErrorString());
    if (g_log_error_count && !o->lenient)
        die(EXIT_INPUT, "the importer reported problems (use --lenient to convert anyway):%s",
            g_log_errors);
    if (!s->mRootNode)
        die(EXIT_INPUT, "the model has no scene graph");
    cc.o = o;
    cc.m = m;
    rc = zs_import_walk(s, collect_mesh, &cc);
    if (rc == ZS_IMPORT_ERR_MESH)
        die(EXIT_INPUT, "node refers to a missing mesh");
    if (rc == ZS_IMPORT_ERR_DEPTH)
        die(EXIT_INPUT, "node hierarchy deeper than %d levels", ZS_IMPORT_MAX_DEPTH);
    aiReleaseImport(s);
    aiDetachAllLogStreams();
    if (o->tex_mode == TEX_FILE && !m->textured)
        die(EXIT_INPUT, "--texture %s: the model has no texture coordinates", o->tex_file);
    for (i = 0; i < m->nv; i++) {
        int r;
        for (r = 0; r < 3; r++)
            if (!isfinite(m->v[i].p[r]))
                die(EXIT_INPUT, "vertex %u has a non-finite coordinate", i);
        for (r = 0; r < 2; r++)
            if (!isfinite(m->v[i].uv[r]))
                die(EXIT_INPUT, "vertex %u has a non-finite texture coordinate", i);
    }
    for (i = 0; m->textured && i < m->nt; i++)
        if (!m->v[m->t[i].v[0]].has_uv || !m->v[m->t[i].v[1]].has_uv ||
            !m->v[m->t[i].v[2]].has_uv)
            m->tex_missing++;
    if (m->tex_missing)
        warn(o, "%zu triangles have no texture coordinates: they show texel (0, 0)",
             m->tex_missing);
    if (m->nt == 0) {
        if (m->skipped_prims)
            die(EXIT_INPUT, "has no triangles (only %zu points/lines)", m->skipped_prims);
        die(EXIT_INPUT, "has no triangles");
    }
    if (m->skipped_prims)
        warn(o, "skipped %zu point/line primitives", m->skipped_prims);
}

/* ------------------------------------------------------------------ */
/* Vertex merging (exact key on the output attributes)                  */
/* ------------------------------------------------------------------ */

static uint64_t hash_bytes(const void *p, size_t n)
{
    const unsigned char *b = p;
    uint64_t h = 1469598103934665603ull;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ull;
    }
    return h;
}

static size_t vert_key(const options *o, const vert *v, double key[11])
{
    size_t n = 0;
    int r;
    for (r = 0; r < 3; r++)
        key[n++] = v->p[r] == 0 ? 0.0 : v->p[r]; /* -0 == +0 */
    if (o->normals == NRM_FILE)
        for (r = 0; r < 3; r++)
            key[n++] = v->n[r] == 0 ? 0.0 : v->n[r];
    if (o->colors == COL_VERTEX)
        for (r = 0; r < 3; r++)
            key[n++] = v->c[r] == 0 ? 0.0 : v->c[r];
    for (r = 0; r < 2; r++) /* (zero unless the model is textured) */
        key[n++] = v->uv[r] == 0 ? 0.0 : v->uv[r];
    return n;
}

/* Merges vertices with identical keys and drops unreferenced ones.
 * Returns the number of degenerate triangles removed. */
static void merge_vertices(const options *o, model *m, int merge)
{
    size_t cap = 1, i, nv = 0, nt = 0;
    uint32_t *table, *remap;
    vert *out;
    while (cap < m->nv * 2 + 2)
        cap <<= 1;
    table = xrealloc(NULL, cap * sizeof *table);
    for (i = 0; i < cap; i++)
        table[i] = UINT32_MAX;
    remap = xrealloc(NULL, (m->nv ? m->nv : 1) * sizeof *remap);
    out = xrealloc(NULL, (m->nv ? m->nv : 1) * sizeof *out);
    for (i = 0; i < m->nv; i++)
        remap[i] = UINT32_MAX;
    /* Visit vertices in the order triangles reference them: deterministic and
     * drops unreferenced vertices. */
    for (i = 0; i < m->nt; i++) {
        int c;
        for (c = 0; c < 3; c++) {
            uint32_t vi = m->t[i].v[c];
            double key[11], key2[11];
            size_t kn, slot;
            if (remap[vi] != UINT32_MAX)
                continue;
            if (!merge) {
                out[nv] = m->v[vi];
                remap[vi] = (uint32_t)nv++;
                continue;
            }
            kn = vert_key(o, &m->v[vi], key);
            slot = (size_t)hash_bytes(key, kn * sizeof(double)) & (cap - 1);
            for (;;) {
                uint32_t e = table[slot];
                if (e == UINT32_MAX) {
                    table[slot] = (uint32_t)nv;
                    out[nv] = m->v[vi];
                    remap[vi] = (uint32_t)nv++;
                    break;
                }
                vert_key(o, &out[e], key2);
                if (memcmp(key, key2, kn * sizeof(double)) == 0) {
                    remap[vi] = e;
                    break;
                }
                slot = (slot + 1) & (cap - 1);
            }
        }
    }
    for (i = 0; i < m->nt; i++) {
        tri t = m->t[i];
        t.v[0] = remap[t.v[0]];
        t.v[1] = remap[t.v[1]];
        t.v[2] = remap[t.v[2]];
        if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2]) {
            m->degenerate++;
            continue;
        }
        m->t[nt++] = t;
    }
    free(m->v);
    free(table);
    free(remap);
    m->v = out;
    m->nv = nv;
    m->cap_v = nv;
    m->nt = nt;
}

/* ------------------------------------------------------------------ */
/* Decimation: uniform-grid vertex clustering                           */
/* ------------------------------------------------------------------ */

static void bbox(const model *m, double lo[3], double hi[3])
{
    size_t i;
    int r;
    for (r = 0; r < 3; r++) {
        lo[r] = m->nv ? m->v[0].p[r] : 0;
        hi[r] = lo[r];
    }
    for (i = 1; i < m->nv; i++)
        for (r = 0; r < 3; r++) {
            if (m->v[i].p[r] < lo[r])
                lo[r] = m->v[i].p[r];
            if (m->v[i].p[r] > hi[r])
                hi[r] = m->v[i].p[r];
        }
}

typedef struct cell_entry {
    uint64_t key;
    uint32_t id;
} cell_entry;

/* Clusters vertices on a grid with `res` cells along the longest bbox side.
 * Writes the result to *out (positions = cluster means). */
static void cluster(const options *o, const model *m, unsigned long res, model *out)
{
    double lo[3], hi[3], ext = 0, cell;
    size_t cap = 1, i, nv = 0;
    cell_entry *table;
    uint32_t *remap, *count;
    int r;
    bbox(m, lo, hi);
    for (r = 0; r < 3; r++)
        if (hi[r] - lo[r] > ext)
            ext = hi[r] - lo[r];
    cell = ext > 0 ? ext / (double)res : 1.0;
    while (cap < m->nv * 2 + 2)
        cap <<= 1;
    table = xrealloc(NULL, cap * sizeof *table);
    for (i = 0; i < cap; i++)
        table[i].id = UINT32_MAX;
    remap = xrealloc(NULL, (m->nv ? m->nv : 1) * sizeof *remap);
    count = xrealloc(NULL, (m->nv ? m->nv : 1) * sizeof *count);
    memset(out, 0, sizeof *out);
    out->v = xrealloc(NULL, (m->nv ? m->nv : 1) * sizeof *out->v);
    out->cap_v = m->nv;
    for (i = 0; i < m->nv; i++) {
        uint64_t c[3], key;
        size_t slot;
        for (r = 0; r < 3; r++) {
            double q = floor((m->v[i].p[r] - lo[r]) / cell);
            if (q < 0)
                q = 0;
            if (q > (double)res - 1)
                q = (double)res - 1;
            c[r] = (uint64_t)q;
        }
        key = (c[0] << 42) | (c[1] << 21) | c[2];
        slot = (size_t)hash_bytes(&key, sizeof key) & (cap - 1);
        while (table[slot].id != UINT32_MAX && table[slot].key != key)
            slot = (slot + 1) & (cap - 1);
        if (table[slot].id == UINT32_MAX) {
            table[slot].key = key;
            table[slot].id = (uint32_t)nv;
            memset(&out->v[nv], 0, sizeof out->v[nv]);
            count[nv] = 0;
            nv++;
        }
        {
            uint32_t id = table[slot].id;
            vert *d = &out->v[id];
            for (r = 0; r < 3; r++) {
                d->p[r] += m->v[i].p[r];
                d->n[r] += m->v[i].n[r];
                d->c[r] += m->v[i].c[r];
            }
            d->uv[0] += m->v[i].uv[0];
            d->uv[1] += m->v[i].uv[1];
            d->has_uv |= m->v[i].has_uv;
            count[id]++;
            remap[i] = id;
        }
    }
    for (i = 0; i < nv; i++) {
        double len;
        for (r = 0; r < 3; r++) {
            out->v[i].p[r] /= count[i];
            out->v[i].c[r] /= count[i];
        }
        out->v[i].uv[0] /= count[i];
        out->v[i].uv[1] /= count[i];
        len = sqrt(out->v[i].n[0] * out->v[i].n[0] + out->v[i].n[1] * out->v[i].n[1] +
                   out->v[i].n[2] * out->v[i].n[2]);
        for (r = 0; r < 3; r++)
            out->v[i].n[r] = len > 0 ? out->v[i].n[r] / len : 0;
    }
    out->nv = nv;
    for (i = 0; i < m->nt; i++) {
        tri t = m->t[i];
        t.v[0] = remap[t.v[0]];
        t.v[1] = remap[t.v[1]];
        t.v[2] = remap[t.v[2]];
        if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2])
            continue;
        add_tri(out, &t);
    }
    (void)o;
    free(table);
    free(remap);
    free(count);
    /* Drop vertices no longer referenced. */
    {
        options plain = *o;
        plain.normals = NRM_NONE;
        plain.colors = COL_NONE;
        merge_vertices(&plain, out, 0);
    }
}

static void free_model(model *m)
{
    free(m->v);
    free(m->t);
    zs_timg_texture_free(&m->tex);
    memset(m, 0, sizeof *m);
}

static void decimate(const options *o, model *m)
{
    unsigned long lim_t = o->max_tris ? o->max_tris : MAX_OUT;
    unsigned long lim_v = o->max_verts ? o->max_verts : MAX_OUT;
    unsigned long lo = 1, hi = 1u << 20, best = 0;
    model best_m;
    if (m->nt <= lim_t && m->nv <= lim_v)
        return;
    memset(&best_m, 0, sizeof best_m);
    /* Largest grid resolution whose result fits (counts grow with resolution,
     * nearly monotonically). */
    while (lo <= hi) {
        unsigned long mid = lo + (hi - lo) / 2;
        model t;
        cluster(o, m, mid, &t);
        if (t.nt <= lim_t && t.nv <= lim_v && t.nt > 0) {
            free_model(&best_m);
            best_m = t;
            best = mid;
            lo = mid + 1;
        } else {
            free_model(&t);
            hi = mid - 1;
        }
    }
    if (!best)
        die(EXIT_LIMIT, "cannot decimate %zu triangles / %zu vertices to the limits "
                        "(%lu triangles, %lu vertices)", m->nt, m->nv, lim_t, lim_v);
    warn(o, "decimated %zu triangles / %zu vertices to %zu / %zu (grid %lu)%s", m->nt, m->nv,
         best_m.nt, best_m.nv, best,
         m->textured ? "; merged vertices average their texture coordinates (seams smear)" : "");
    best_m.textured = m->textured;
    best_m.tex = m->tex;
    memcpy(best_m.tex_ref, m->tex_ref, sizeof best_m.tex_ref);
    best_m.tex_w0 = m->tex_w0;
    best_m.tex_h0 = m->tex_h0;
    best_m.tex_mat = m->tex_mat;
    best_m.tex_missing = m->tex_missing;
    m->tex.texels = NULL; /* moved */
    m->tex.palette = NULL;
    free_model(m);
    *m = best_m;
}

/* ------------------------------------------------------------------ */
/* Output                                                               */
/* ------------------------------------------------------------------ */

static uint32_t index_color(uint32_t i)
{
    /* A fixed integer hash of the triangle index; channels kept >= 0x30 so no
     * triangle is black (the default background). */
    uint32_t x = i + 0x9E3779B9u;
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return (x & 0xFFFFFFu) | 0x303030u;
}

static int16_t q14(double x)
{
    long q = lround(x * 16384.0);
    if (q > 16384)
        q = 16384;
    if (q < -16384)
        q = -16384;
    return (int16_t)q;
}

static void face_normal(const model *m, const tri *t, double n[3])
{
    const double *a = m->v[t->v[0]].p, *b = m->v[t->v[1]].p, *c = m->v[t->v[2]].p;
    double e1[3], e2[3];
    int r;
    for (r = 0; r < 3; r++) {
        e1[r] = b[r] - a[r];
        e2[r] = c[r] - a[r];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

static void normalize3(double n[3])
{
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    int r;
    for (r = 0; r < 3; r++)
        n[r] = len > 0 ? n[r] / len : 0;
}

static int valid_ident(const char *s)
{
    if (!*s || !(isalpha((unsigned char)*s) || *s == '_'))
        return 0;
    for (; *s; s++)
        if (!(isalnum((unsigned char)*s) || *s == '_'))
            return 0;
    return 1;
}

static int in_list(const char *s, const char *const *list)
{
    for (; *list != NULL; list++)
        if (strcmp(s, *list) == 0)
            return 1;
    return 0;
}

/* Why an identifier cannot name the mesh (an external const zs_mesh, with
 * NAME_positions etc. beside it), or NULL if it can. */
static const char *ident_problem(const char *s)
{
    static const char *const c_keywords[] = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double",
        "else", "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long",
        "register", "restrict", "return", "short", "signed", "sizeof", "static", "struct",
        "switch", "typedef", "union", "unsigned", "void", "volatile", "while",
        /* C23 */
        "alignas", "alignof", "bool", "constexpr", "false", "nullptr", "static_assert",
        "thread_local", "true", "typeof", "typeof_unqual", NULL};
    static const char *const cxx_keywords[] = {
        "and", "and_eq", "asm", "bitand", "bitor", "catch", "char8_t", "char16_t", "char32_t",
        "class", "compl", "concept", "consteval", "constinit", "const_cast", "co_await",
        "co_return", "co_yield", "decltype", "delete", "dynamic_cast", "explicit", "export",
        "friend", "mutable", "namespace", "new", "noexcept", "not", "not_eq", "operator",
        "or", "or_eq", "private", "protected", "public", "reinterpret_cast", "requires",
        "static_cast", "template", "this", "throw", "try", "typeid", "typename", "using",
        "virtual", "wchar_t", "xor", "xor_eq", NULL};
    /* Names the included headers (zspan.h: <stddef.h>, <stdint.h>) or the C
     * library already define with external linkage or as macros. */
    static const char *const library[] = {
        "NULL", "offsetof", "size_t", "ptrdiff_t", "max_align_t", "main", "errno", "assert",
        "abort", "abs", "atexit", "atof", "atoi", "atol", "bsearch", "calloc", "div", "exit",
        "free", "getenv", "labs", "ldiv", "malloc", "qsort", "rand", "realloc", "srand",
        "system", "printf", "fprintf", "sprintf", "snprintf", "scanf", "sscanf", "puts",
        "putchar", "getchar", "fopen", "fclose", "fread", "fwrite", "fflush", "remove",
        "rename", "signal", "raise", "time", "clock", "sin", "cos", "tan", "sqrt", "pow",
        "exp", "log", "floor", "ceil", "fabs", "round", "stdin", "stdout", "stderr", NULL};
    size_t n = strlen(s);

    if (!valid_ident(s))
        return "is not a C identifier (letters, digits and _, not starting with a digit)";
    if (in_list(s, c_keywords))
        return "is a C keyword";
    if (in_list(s, cxx_keywords))
        return "is a C++ keyword (the generated header is usable from C++)";
    if (s[0] == '_')
        return "begins with an underscore (reserved for the implementation at file scope)";
    if (in_list(s, library))
        return "is already defined by the C library or the headers zspan.h includes";
    if (n >= 2 && s[n - 2] == '_' && s[n - 1] == 't')
        return "ends in _t (reserved for type names by POSIX and <stdint.h>)";
    if (strncmp(s, "zs_", 3) == 0 || strncmp(s, "ZS_", 3) == 0 || strncmp(s, "zspan_", 6) == 0 ||
        strncmp(s, "ZSPAN_", 6) == 0)
        return "is in zspan's own namespace (zs_, ZS_, zspan_, ZSPAN_)";
    /* C's future library directions (C99 7.26): reserved external names. */
    if (((strncmp(s, "is", 2) == 0 || strncmp(s, "to", 2) == 0) && islower((unsigned char)s[2])) ||
        ((strncmp(s, "str", 3) == 0 || strncmp(s, "mem", 3) == 0 || strncmp(s, "wcs", 3) == 0) &&
         islower((unsigned char)s[3])) ||
        (s[0] == 'E' && (isdigit((unsigned char)s[1]) || isupper((unsigned char)s[1]))) ||
        (strncmp(s, "SIG", 3) == 0 && (isupper((unsigned char)s[3]) || s[3] == '_')) ||
        (strncmp(s, "LC_", 3) == 0 && isupper((unsigned char)s[3])) ||
        ((strncmp(s, "PRI", 3) == 0 || strncmp(s, "SCN", 3) == 0) &&
         (islower((unsigned char)s[3]) || s[3] == 'X')) ||
        ((strncmp(s, "int", 3) == 0 || strncmp(s, "uint", 4) == 0) && n >= 2 &&
         strcmp(s + n - 2, "_t") == 0) ||
        ((strncmp(s, "INT", 3) == 0 || strncmp(s, "UINT", 4) == 0) && n >= 4 &&
         (strcmp(s + n - 4, "_MAX") == 0 || strcmp(s + n - 4, "_MIN") == 0 ||
          strcmp(s + n - 2, "_C") == 0)))
        return "is reserved for the C library's future use (is*, to*, str*, mem*, wcs*, E*, "
               "SIG*, LC_*, PRI*, SCN*, INT*_MAX ...)";
    return NULL;
}

static char *name_from_path(const char *path)
{
    const char *b = strrchr(path, '/');
    const char *dot;
    size_t n, i, k = 0;
    char *out;
    b = b ? b + 1 : path;
    dot = strrchr(b, '.');
    n = dot && dot != b ? (size_t)(dot - b) : strlen(b);
    out = xrealloc(NULL, n + 8);
    /* A name the file suggests but C would not take (a keyword, reserved, a
     * leading digit or underscore) gets the prefix mesh_. */
    memcpy(out, "mesh_", 5);
    k = 5;
    for (i = 0; i < n; i++) {
        unsigned char ch = (unsigned char)b[i];
        out[k++] = (char)(isalnum(ch) ? tolower(ch) : '_');
    }
    out[k] = 0;
    if (n > 0 && ident_problem(out + 5) == NULL)
        memmove(out, out + 5, k - 5 + 1);
    return out;
}

typedef struct emitter {
    FILE *f;
    int col;
} emitter;

static void emit_begin(emitter *e, FILE *f, const char *decl)
{
    e->f = f;
    e->col = 0;
    fprintf(f, "%s = {\n", decl);
}

static void emit_val(emitter *e, const char *s)
{
    size_t len = strlen(s);
    if (e->col == 0) {
        fputs("   ", e->f);
        e->col = 3;
    }
    if (e->col + (int)len + 2 > 96) {
        fputs("\n   ", e->f);
        e->col = 3;
    }
    fprintf(e->f, " %s,", s);
    e->col += (int)len + 2;
}

static void emit_end(emitter *e)
{
    fputs(e->col ? "\n};\n\n" : "};\n\n", e->f);
}

/* The mesh as the core takes it: what both output forms hold. */
typedef struct out_mesh {
    int16_t *pos;        /* 3 per vertex */
    uint16_t *idx;       /* 3 per triangle */
    uint32_t *fcol;      /* per face, or NULL */
    uint32_t *vcol;      /* per vertex, or NULL */
    int16_t *fnrm;       /* 3 per face, or NULL */
    int16_t *vnrm;       /* 3 per vertex, or NULL */
    int16_t *uv;         /* 2 per vertex (Q3.12, v down the texture), or NULL */
    uint32_t color;
    size_t nv, nt;       /* counts (a BSP build splits triangles) */
    zs_bspb_result bsp;  /* --bsp: the tree; its mesh holds the arrays above */
} out_mesh;

static void build_output(const options *o, const model *m, long qscale, out_mesh *om)
{
    size_t i;
    int r;

    memset(om, 0, sizeof *om);
    om->pos = xrealloc(NULL, m->nv * 3 * sizeof *om->pos);
    for (i = 0; i < m->nv; i++)
        for (r = 0; r < 3; r++) {
            long qi = lround(m->v[i].p[r] * 65536.0 / (double)qscale);
            om->pos[i * 3 + (size_t)r] = (int16_t)(qi > 32767 ? 32767 : qi < -32767 ? -32767 : qi);
        }
    om->idx = xrealloc(NULL, m->nt * 3 * sizeof *om->idx);
    for (i = 0; i < m->nt; i++)
        for (r = 0; r < 3; r++)
            om->idx[i * 3 + (size_t)r] = (uint16_t)m->t[i].v[o->flip && r ? 3 - r : r];
    if (o->colors == COL_MATERIAL || o->colors == COL_INDEX) {
        int uniform = 1;
        for (i = 1; i < m->nt; i++)
            if (m->t[i].color != m->t[0].color)
                uniform = 0;
        if (o->colors == COL_INDEX || !uniform) {
            om->fcol = xrealloc(NULL, m->nt * sizeof *om->fcol);
            for (i = 0; i < m->nt; i++)
                om->fcol[i] = o->colors == COL_INDEX ? index_color((uint32_t)i) : m->t[i].color;
        }
    }
    if (o->colors == COL_VERTEX) {
        om->vcol = xrealloc(NULL, m->nv * sizeof *om->vcol);
        for (i = 0; i < m->nv; i++)
            om->vcol[i] = zs_import_color(m->v[i].c[0], m->v[i].c[1], m->v[i].c[2]);
    }
    if (o->normals == NRM_FACE) {
        om->fnrm = xrealloc(NULL, m->nt * 3 * sizeof *om->fnrm);
        for (i = 0; i < m->nt; i++) {
            double n[3];
            face_normal(m, &m->t[i], n);
            if (o->flip)
                for (r = 0; r < 3; r++)
                    n[r] = -n[r];
            normalize3(n);
            for (r = 0; r < 3; r++)
                om->fnrm[i * 3 + (size_t)r] = q14(n[r]);
        }
    }
    if (o->normals == NRM_SMOOTH || o->normals == NRM_FILE) {
        double *vn = xrealloc(NULL, m->nv * 3 * sizeof *vn);
        if (o->normals == NRM_FILE) {
            for (i = 0; i < m->nv; i++)
                for (r = 0; r < 3; r++)
                    vn[i * 3 + (size_t)r] = o->flip ? -m->v[i].n[r] : m->v[i].n[r];
        } else {
            memset(vn, 0, m->nv * 3 * sizeof *vn);
            for (i = 0; i < m->nt; i++) {
                double n[3]; /* area weighted */
                int c;
                face_normal(m, &m->t[i], n);
                for (c = 0; c < 3; c++)
                    for (r = 0; r < 3; r++)
                        vn[m->t[i].v[c] * 3 + (size_t)r] += o->flip ? -n[r] : n[r];
            }
            for (i = 0; i < m->nv; i++)
                normalize3(&vn[i * 3]);
        }
        om->vnrm = xrealloc(NULL, m->nv * 3 * sizeof *om->vnrm);
        for (i = 0; i < m->nv * 3; i++)
            om->vnrm[i] = q14(vn[i]);
        free(vn);
    }
    if (m->textured) {
        /* v turned to run down the rows (file row 0 first); with repeat a
         * whole number of repeats is taken off so that the coordinates sit
         * about 0 (the same texels), then they must fit Q3.12. */
        double lo[2] = {0, 0}, hi[2] = {0, 0}, shift[2] = {0, 0};
        for (i = 0; i < m->nv; i++)
            for (r = 0; r < 2; r++) {
                double t = r ? 1.0 - m->v[i].uv[1] : m->v[i].uv[0];
                if (i == 0 || t < lo[r])
                    lo[r] = t;
                if (i == 0 || t > hi[r])
                    hi[r] = t;
            }
        if (!(o->tex_flags & ZS_TEX_CLAMP))
            for (r = 0; r < 2; r++)
                shift[r] = floor((lo[r] + hi[r]) / 2.0);
        om->uv = xrealloc(NULL, m->nv * 2 * sizeof *om->uv);
        for (i = 0; i < m->nv; i++)
            for (r = 0; r < 2; r++) {
                double t = (r ? 1.0 - m->v[i].uv[1] : m->v[i].uv[0]) - shift[r];
                long q = lround(t * ZS_UV_ONE);
                if (q < -32768 || q > 32767)
                    die(EXIT_LIMIT, "texture coordinates span %g..%g %s: more than the core's "
                                    "Q3.12 range (-8..8)%s", lo[r], hi[r], r ? "in v" : "in u",
                        o->tex_flags & ZS_TEX_CLAMP ? " (with clamp nothing is shifted)" : "");
                om->uv[i * 2 + (size_t)r] = (int16_t)q;
            }
    }
    om->color = o->base_color;
    if (o->colors == COL_MATERIAL && !om->fcol && m->nt)
        om->color = m->t[0].color;
    om->nv = m->nv;
    om->nt = m->nt;
}

/* --bsp: the tree from the quantised mesh; its triangles (split ones and
 * all, in node order) replace the mesh's. */
static void build_bsp(const options *o, out_mesh *om)
{
    zs_bspb_mesh in;
    zs_bspb_params p;
    const char *err;
    clock_t t0 = clock();
    double ms;
    memset(&in, 0, sizeof in);
    in.pos = om->pos;
    in.idx = om->idx;
    in.fcol = om->fcol;
    in.fnrm = om->fnrm;
    in.vcol = om->vcol;
    in.vnrm = om->vnrm;
    in.uv = om->uv;
    in.nv = om->nv;
    in.nt = om->nt;
    p.split_weight = (int)o->bsp_weight;
    p.candidates = (int)o->bsp_candidates;
    err = zs_bspb_build(&in, &p, &om->bsp);
    if (err)
        die(EXIT_LIMIT, "--bsp: %s", err);
    ms = (double)(clock() - t0) * 1000.0 / CLOCKS_PER_SEC;
    if (!o->quiet)
        fprintf(stderr,
                "%s: %s: BSP: %zu nodes, %zu -> %zu triangles (%zu splits, %zu slivers, %zu "
                "without area left out), %zu -> %zu vertices, walk stack %d, largest "
                "rounding %.3f units, built in %.1f ms\n",
                g_prog, g_input, om->bsp.node_count, om->nt, om->bsp.mesh.nt, om->bsp.splits,
                om->bsp.slivers, om->bsp.dropped, om->nv, om->bsp.mesh.nv, om->bsp.stack,
                om->bsp.max_snap, ms);
    free(om->pos);
    free(om->idx);
    free(om->fcol);
    free(om->fnrm);
    free(om->vcol);
    free(om->vnrm);
    free(om->uv);
    om->pos = om->bsp.mesh.pos;
    om->idx = om->bsp.mesh.idx;
    om->fcol = om->bsp.mesh.fcol;
    om->fnrm = om->bsp.mesh.fnrm;
    om->vcol = om->bsp.mesh.vcol;
    om->vnrm = om->bsp.mesh.vnrm;
    om->uv = om->bsp.mesh.uv;
    om->nv = om->bsp.mesh.nv;
    om->nt = om->bsp.mesh.nt;
    memset(&om->bsp.mesh, 0, sizeof om->bsp.mesh);
}

static void free_output(out_mesh *om)
{
    free(om->pos);
    free(om->idx);
    free(om->fcol);
    free(om->vcol);
    free(om->fnrm);
    free(om->vnrm);
    free(om->uv);
    zs_bspb_free(&om->bsp);
}

static void put_le(FILE *f, uint32_t v, int bytes)
{
    int k;
    for (k = 0; k < bytes; k++)
        fputc((int)((v >> (8 * k)) & 255u), f);
}

/* BASE.zsm: the binary mesh zspan-sim reads (layout: app/zs_model.h). */
static void write_zsm(const options *o, const model *m, long qscale, const out_mesh *om)
{
    size_t len = strlen(o->output), i;
    char *path = xrealloc(NULL, len + 5);
    uint32_t flags = (om->fcol ? 1u : 0u) | (om->vcol ? 2u : 0u) | (om->fnrm ? 4u : 0u) |
                     (om->vnrm ? 8u : 0u) | (m->textured ? 16u : 0u);
    FILE *f;

    sprintf(path, "%s.zsm", o->output);
    f = fopen(path, "wb");
    if (!f)
        die(EXIT_IO, "cannot write %s: %s", path, strerror(errno));
    fwrite("ZSMESH1\n", 1, 8, f);
    put_le(f, flags, 4);
    put_le(f, (uint32_t)qscale, 4);
    put_le(f, om->color & 0xFFFFFFu, 4);
    put_le(f, (uint32_t)om->nv, 2);
    put_le(f, (uint32_t)om->nt, 2);
    for (i = 0; i < om->nv * 3; i++)
        put_le(f, (uint32_t)(uint16_t)om->pos[i], 2);
    for (i = 0; i < om->nt * 3; i++)
        put_le(f, om->idx[i], 2);
    for (i = 0; om->fcol && i < om->nt; i++)
        put_le(f, om->fcol[i], 4);
    for (i = 0; om->vcol && i < om->nv; i++)
        put_le(f, om->vcol[i], 4);
    for (i = 0; om->fnrm && i < om->nt * 3; i++)
        put_le(f, (uint32_t)(uint16_t)om->fnrm[i], 2);
    for (i = 0; om->vnrm && i < om->nv * 3; i++)
        put_le(f, (uint32_t)(uint16_t)om->vnrm[i], 2);
    if (m->textured) { /* uvs, then the texture (app/zs_model.h) */
        const zs_texture *t = &m->tex;
        size_t n = (size_t)t->width * t->height;
        for (i = 0; i < om->nv * 2; i++)
            put_le(f, (uint32_t)(uint16_t)om->uv[i], 2);
        put_le(f, t->width, 2);
        put_le(f, t->height, 2);
        put_le(f, t->format, 1);
        put_le(f, t->flags, 1);
        put_le(f, 0, 2);
        if (t->format == ZS_TEX_PAL8) {
            for (i = 0; i < 256; i++)
                put_le(f, t->palette[i], 2);
            for (i = 0; i < n; i++)
                put_le(f, ((const uint8_t *)t->texels)[i], 1);
        } else {
            for (i = 0; i < n; i++)
                put_le(f, ((const uint16_t *)t->texels)[i], 2);
        }
    }
    if (ferror(f) | (fclose(f) != 0))
        die(EXIT_IO, "cannot write %s", path);
    free(path);
}

static void emit_i16(emitter *e, const int16_t *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        char s[16];
        sprintf(s, "%d", v[i]);
        emit_val(e, s);
    }
}

static void emit_texture(FILE *fc, const char *name, const model *m, const out_mesh *om)
{
    const zs_texture *t = &m->tex;
    size_t n = (size_t)t->width * t->height, i;
    char buf[160];
    emitter e;
    snprintf(buf, sizeof buf, "static const int16_t %.60s_uvs[%zu]", name, om->nv * 2);
    emit_begin(&e, fc, buf);
    emit_i16(&e, om->uv, om->nv * 2);
    emit_end(&e);
    fprintf(fc, "/* Texture %s: %u x %u pixels, resampled to %u x %u (%s). */\n", m->tex_ref,
            m->tex_w0, m->tex_h0, (unsigned)t->width, (unsigned)t->height,
            t->format == ZS_TEX_PAL8 ? "8-bit palette" : "RGB565");
    if (t->format == ZS_TEX_PAL8) {
        const uint8_t *tx = t->texels;
        snprintf(buf, sizeof buf, "static const uint16_t %.60s_palette[256]", name);
        emit_begin(&e, fc, buf);
        for (i = 0; i < 256; i++) {
            char v[16];
            sprintf(v, "0x%04X", (unsigned)t->palette[i]);
            emit_val(&e, v);
        }
        emit_end(&e);
        snprintf(buf, sizeof buf, "static const uint8_t %.60s_texels[%zu]", name, n);
        emit_begin(&e, fc, buf);
        for (i = 0; i < n; i++) {
            char v[16];
            sprintf(v, "%u", (unsigned)tx[i]);
            emit_val(&e, v);
        }
    } else {
        const uint16_t *tx = t->texels;
        snprintf(buf, sizeof buf, "static const uint16_t %.60s_texels[%zu]", name, n);
        emit_begin(&e, fc, buf);
        for (i = 0; i < n; i++) {
            char v[16];
            sprintf(v, "0x%04X", (unsigned)tx[i]);
            emit_val(&e, v);
        }
    }
    emit_end(&e);
    fprintf(fc, "const zs_texture %s_texture = {\n    %s_texels,\n    %s%s,\n    %uu, %uu, /* width, "
                "height */\n    %s,\n    0x%02Xu /* flags:%s%s%s */\n};\n\n",
            name, name, t->format == ZS_TEX_PAL8 ? name : "NULL",
            t->format == ZS_TEX_PAL8 ? "_palette" : " /* palette */", (unsigned)t->width,
            (unsigned)t->height, t->format == ZS_TEX_PAL8 ? "ZS_TEX_PAL8" : "ZS_TEX_RGB565",
            (unsigned)t->flags, t->flags & ZS_TEX_BILINEAR ? " bilinear" : " nearest",
            t->flags & ZS_TEX_CLAMP ? " clamp" : " repeat",
            t->flags & ZS_TEX_SUBDIV ? " subdivided" : " exact");
}

static void write_files(const options *o, const model *m, const char *name, long qscale,
                        const double lo[3], const double hi[3], double radius,
                        const double xform_scale, const double xform_shift[3])
{
    char *cpath, *hpath, *guard, *upper, *buf;
    const char *hname;
    FILE *fc, *fh;
    size_t len = strlen(o->output), i;
    emitter e;
    out_mesh om;

    build_output(o, m, qscale, &om);
    if (o->bsp)
        build_bsp(o, &om);
    if (o->zsm) {
        write_zsm(o, m, qscale, &om);
        free_output(&om);
        return;
    }
    cpath = xrealloc(NULL, len + 3);
    hpath = xrealloc(NULL, len + 3);
    sprintf(cpath, "%s.c", o->output);
    sprintf(hpath, "%s.h", o->output);
    hname = strrchr(hpath, '/');
    hname = hname ? hname + 1 : hpath;
    guard = xrealloc(NULL, strlen(name) + 16);
    sprintf(guard, "ZSPAN_MESH_%s_H", name);
    for (i = 0; guard[i]; i++)
        guard[i] = (char)toupper((unsigned char)guard[i]);
    upper = xrealloc(NULL, strlen(name) + 1);
    for (i = 0; name[i]; i++)
        upper[i] = (char)toupper((unsigned char)name[i]);
    upper[i] = 0;
    /* declarations: the name plus fixed text and one count */
    buf = xrealloc(NULL, strlen(name) + 96);

    fh = fopen(hpath, "w");
    if (!fh)
        die(EXIT_IO, "cannot write %s: %s", hpath, strerror(errno));
    fprintf(fh,
            "/* Generated by zspan-meshc " MESHC_VERSION " from %s. Do not edit. */\n"
            "#ifndef %s\n#define %s\n\n#include \"zspan/%s.h\"\n\n"
            "#define %s_VERTEX_COUNT %zuu\n#define %s_TRIANGLE_COUNT %zuu\n"
            "/* Q16.16 scale of the int16 positions. */\n#define %s_SCALE %ld\n\n"
            "extern const zs_mesh %s;\n",
            g_input, guard, guard, o->bsp ? "priority" : "zspan", upper, om.nv, upper, om.nt,
            upper, qscale, name);
    if (m->textured)
        fprintf(fh, "/* Its texture (zs_mesh.texture; needs ZS_CFG_TEXTURE). */\n"
                    "#define %s_TEXTURE_WIDTH %uu\n#define %s_TEXTURE_HEIGHT %uu\n"
                    "extern const zs_texture %s_texture;\n",
                upper, (unsigned)m->tex.width, upper, (unsigned)m->tex.height, name);
    if (o->bsp)
        fprintf(fh, "/* Its BSP tree (zspan-meshc --bsp): draw with zs_draw_bsp. */\n"
                    "#define %s_BSP_NODE_COUNT %zuu\nextern const zs_bsp %s_bsp;\n",
                upper, om.bsp.node_count, name);
    fprintf(fh, "\n#endif\n");
    if (fclose(fh) != 0)
        die(EXIT_IO, "cannot write %s", hpath);

    fc = fopen(cpath, "w");
    if (!fc)
        die(EXIT_IO, "cannot write %s: %s", cpath, strerror(errno));
    fprintf(fc, "/* Generated by zspan-meshc " MESHC_VERSION " from %s. Do not edit.\n", g_input);
    fprintf(fc, " * %zu vertices, %zu triangles; model = int16 * %ld / 65536.\n", om.nv, om.nt,
            qscale);
    fprintf(fc, " * Source bounding box before transform: (%.6g %.6g %.6g) .. (%.6g %.6g %.6g)\n",
            lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    fprintf(fc, " * Transform applied: p' = (p - (%.9g %.9g %.9g)) * %.9g; radius after: %.6g\n",
            xform_shift[0], xform_shift[1], xform_shift[2], xform_scale, radius);
    fprintf(fc, " */\n#include \"%s\"\n\n", hname);

    sprintf(buf, "static const int16_t %s_positions[%zu]", name, om.nv * 3);
    emit_begin(&e, fc, buf);
    emit_i16(&e, om.pos, om.nv * 3);
    emit_end(&e);

    sprintf(buf, "static const uint16_t %s_indices[%zu]", name, om.nt * 3);
    emit_begin(&e, fc, buf);
    for (i = 0; i < om.nt * 3; i++) {
        char s[16];
        sprintf(s, "%u", (unsigned)om.idx[i]);
        emit_val(&e, s);
    }
    emit_end(&e);

    if (om.fcol) {
        sprintf(buf, "static const zs_color %s_face_colors[%zu]", name, om.nt);
        emit_begin(&e, fc, buf);
        for (i = 0; i < om.nt; i++) {
            char s[16];
            sprintf(s, "0x%06lX", (unsigned long)om.fcol[i]);
            emit_val(&e, s);
        }
        emit_end(&e);
    }
    if (om.vcol) {
        sprintf(buf, "static const zs_color %s_vertex_colors[%zu]", name, om.nv);
        emit_begin(&e, fc, buf);
        for (i = 0; i < om.nv; i++) {
            char s[16];
            sprintf(s, "0x%06lX", (unsigned long)om.vcol[i]);
            emit_val(&e, s);
        }
        emit_end(&e);
    }
    if (om.fnrm) {
        sprintf(buf, "static const int16_t %s_face_normals[%zu]", name, om.nt * 3);
        emit_begin(&e, fc, buf);
        emit_i16(&e, om.fnrm, om.nt * 3);
        emit_end(&e);
    }
    if (om.vnrm) {
        sprintf(buf, "static const int16_t %s_vertex_normals[%zu]", name, om.nv * 3);
        emit_begin(&e, fc, buf);
        emit_i16(&e, om.vnrm, om.nv * 3);
        emit_end(&e);
    }

    if (m->textured)
        emit_texture(fc, name, m, &om);
    fprintf(fc, "const zs_mesh %s = {\n", name);
    fprintf(fc, "    %s_positions,\n    %s_indices,\n", name, name);
    if (om.fcol)
        fprintf(fc, "    %s_face_colors,\n", name);
    else
        fprintf(fc, "    NULL, /* face_colors */\n");
    if (om.vcol)
        fprintf(fc, "    %s_vertex_colors,\n", name);
    else
        fprintf(fc, "    NULL, /* vertex_colors */\n");
    if (om.fnrm)
        fprintf(fc, "    %s_face_normals,\n", name);
    else
        fprintf(fc, "    NULL, /* face_normals */\n");
    if (om.vnrm)
        fprintf(fc, "    %s_vertex_normals,\n", name);
    else
        fprintf(fc, "    NULL, /* vertex_normals */\n");
    fprintf(fc, "    %ld, /* scale, Q16.16 */\n    %zuu, /* vertex_count */\n"
                "    %zuu, /* triangle_count */\n    0x%06lXu, /* color */\n",
            qscale, om.nv, om.nt, (unsigned long)om.color);
    if (m->textured)
        fprintf(fc, "    %s_uvs,\n    &%s_texture\n};\n", name, name);
    else
        fprintf(fc, "    NULL, /* uvs */\n    NULL /* texture */\n};\n");
    if (o->bsp) {
        /* nodes: {d, {n}, front, back, first, n_front, n_back} (zspan/priority.h) */
        fprintf(fc, "\nstatic const zs_bsp_node %s_bsp_nodes[%zu] = {\n", name,
                om.bsp.node_count);
        for (i = 0; i < om.bsp.node_count; i++) {
            const zs_bsp_node *nd = &om.bsp.nodes[i];
            fprintf(fc, "    {%lld, {%ld, %ld, %ld}, %u, %u, %u, %u, %u},\n", (long long)nd->d,
                    (long)nd->n[0], (long)nd->n[1], (long)nd->n[2], (unsigned)nd->front,
                    (unsigned)nd->back, (unsigned)nd->first, (unsigned)nd->n_front,
                    (unsigned)nd->n_back);
        }
        fprintf(fc, "};\n\nconst zs_bsp %s_bsp = {%s_bsp_nodes, &%s, %zuu};\n", name, name, name,
                om.bsp.node_count);
    }
    if (fclose(fc) != 0)
        die(EXIT_IO, "cannot write %s", cpath);
    free(cpath);
    free(hpath);
    free(guard);
    free(upper);
    free(buf);
    free_output(&om);
}

/* ------------------------------------------------------------------ */
/* Command line                                                         */
/* ------------------------------------------------------------------ */

static void usage(FILE *f)
{
    fprintf(f,
        "usage: zspan-meshc [options] MODEL\n"
        "Converts any model assimp reads into NAME.c + NAME.h holding a zs_mesh\n"
        "(int16 positions with a Q16.16 scale, uint16 indices).\n\n"
        "  -o, --output BASE     write BASE.c and BASE.h (default: ./NAME)\n"
        "      --format c|zsm    c (default): BASE.c + BASE.h; zsm: BASE.zsm, a binary\n"
        "                        mesh that zspan-sim render reads directly\n"
        "  -n, --name NAME       C identifier of the zs_mesh (default: from the file name)\n"
        "      --center          move the bounding-box centre to the origin\n"
        "      --fit R           scale so the largest vertex distance from the origin is R\n"
        "      --normalize       same as --center --fit 1\n"
        "      --scale S         multiply positions by S (after --center/--fit)\n"
        "      --quant-scale Q   use this Q16.16 scale (integer > 0) instead of the\n"
        "                        smallest one that keeps positions within int16\n"
        "      --max-triangles N decimate (vertex clustering) to at most N triangles\n"
        "      --max-vertices N  decimate to at most N vertices (both limits <= 65535)\n"
        "      --colors SRC      none (default): one colour (--color) for the mesh\n"
        "                        material: per-face colour from the material diffuse colour\n"
        "                        vertex: per-vertex colours from the file (else material)\n"
        "                        index: per-face colour from a fixed hash of the face index\n"
        "      --color RRGGBB    the mesh colour (default FFFFFF)\n"
        "      --normals KIND    none (default), face, smooth (area-weighted per vertex),\n"
        "                        file (per vertex from the model; keeps split vertices)\n"
        "      --bsp             also a BSP tree for zs_draw_bsp (zspan/priority.h): the\n"
        "                        triangles split where they straddle a splitting plane and\n"
        "                        ordered by node; NAME_bsp in the C file\n"
        "      --bsp-weight W    splitter score W * splits + |front - back| (default 8)\n"
        "      --bsp-candidates K  splitters scored per node (default 24)\n"
        "      --texture SRC     none (default): no texture; auto: the diffuse texture of\n"
        "                        the materials (embedded in the model or a file beside\n"
        "                        it; PNG, JPEG or TGA) on the mesh's texture coordinates\n"
        "                        (NAME_texture, NAME_uvs); a file name: that image\n"
        "      --texture-size N  largest texture side, a power of two 1..1024 (default\n"
        "                        64): each side becomes the largest power of two not\n"
        "                        above the image's, then at most N (area average)\n"
        "      --no-resample     refuse (exit 4) an image that is not already a power of\n"
        "                        two within --texture-size instead of resampling it\n"
        "      --texture-format F  rgb565 (default, 2 B a texel) or pal8 (1 B a texel and\n"
        "                        a 256-colour RGB565 palette, median cut)\n"
        "      --texture-filter F  nearest (default) or bilinear\n"
        "      --texture-wrap W  repeat (default) or clamp\n"
        "      --texture-perspective P  exact (default, every pixel) or subdiv (exact\n"
        "                        every 16 columns, affine between)\n"
        "      --no-merge        keep the importer's vertices (default: merge vertices\n"
        "                        with identical positions and output attributes)\n"
        "      --flip-winding    reverse every triangle (front faces must be CCW)\n"
        "      --up-axis AXIS    the file's up axis (x, y, z, -x, -y, -z): turned to +y\n"
        "                        (default auto: the file's metadata, e.g. FBX, else y)\n"
        "      --lenient         convert even if the importer reported errors\n"
        "      --info            print statistics only; write nothing\n"
        "      --mem-limit MB    address-space limit while importing (default 2048 MB +\n"
        "                        256 x the file size; 0 = no limit)\n"
        "  -q, --quiet           no warnings\n"
        "  -h, --help            this text\n"
        "      --version         the version\n\n"
        "An import running longer than 30 s ($ZSPAN_IMPORT_SECONDS) is stopped.\n"
        "Exit status: 0 ok, 2 usage, 3 unreadable/invalid/empty model, 4 over a limit,\n"
        "5 cannot write the output.\n");
}

/* Option messages say "zspan-meshc: error: ..." like every other failure. */
#define OPT_PROG "zspan-meshc: error"

/* A positive decimal number (--fit, --scale). */
static double positive_arg(const char *opt, const char *v)
{
    double x;
    if (zs_opt_double(OPT_PROG, opt, v, &x) != 0)
        exit(EXIT_USAGE);
    if (!(x > 0)) {
        fprintf(stderr, "%s: error: %s needs a positive number, got '%s'\n", g_prog, opt, v);
        exit(EXIT_USAGE);
    }
    return x;
}

/* An integer option "NAME N" at argv[*i] (1 = matched). */
static int long_arg(int argc, char **argv, int *i, const char *name, long lo, long hi, long *out)
{
    int m = zs_opt_long_at(argc, argv, i, name, lo, hi, out, OPT_PROG);
    if (m < 0)
        exit(EXIT_USAGE);
    return m;
}

/* A string option "NAME VALUE" (or a short alias) at argv[*i] (1 = matched). */
static int str_arg(int argc, char **argv, int *i, const char *name, const char *alias,
                   const char **out)
{
    int m = zs_opt_value(argc, argv, i, name, out, OPT_PROG);
    if (m == 0 && alias != NULL)
        m = zs_opt_value(argc, argv, i, alias, out, OPT_PROG);
    if (m < 0)
        exit(EXIT_USAGE);
    return m;
}

static void parse_args(int argc, char **argv, options *o)
{
    static const char *const color_srcs[] = {"none", "material", "vertex", "index"};
    static const char *const normal_kinds[] = {"none", "face", "smooth", "file"};
    const char *v;
    long n;
    int i, k;
    memset(o, 0, sizeof *o);
    o->scale = 1.0;
    o->merge = 1;
    o->base_color = 0xFFFFFFu;
    o->fit_radius = 1.0;
    o->mem_limit_mb = -1;
    o->tex_mode = TEX_NONE;
    o->tex_size = TEX_DEFAULT_SIZE;
    o->tex_resample = 1;
    o->tex_format = ZS_TEX_RGB565;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            exit(0);
        } else if (zs_opt_version(a, g_prog)) {
            exit(0);
        } else if (str_arg(argc, argv, &i, "--up-axis", NULL, &v)) {
            if (zs_opt_up_axis(OPT_PROG, "--up-axis", v, &o->up_axis) != 0)
                exit(EXIT_USAGE);
        } else if (str_arg(argc, argv, &i, "--format", NULL, &v)) {
            static const char *const formats[] = {"c", "zsm"};
            if (zs_opt_choice(OPT_PROG, "--format", v, formats, 2, &k) != 0)
                exit(EXIT_USAGE);
            o->zsm = k == 1;
        } else if (str_arg(argc, argv, &i, "--output", "-o", &o->output) ||
                   str_arg(argc, argv, &i, "--name", "-n", &o->name)) {
            continue;
        } else if (!strcmp(a, "--center")) {
            o->center = 1;
        } else if (str_arg(argc, argv, &i, "--fit", NULL, &v)) {
            o->fit = 1;
            o->fit_radius = positive_arg("--fit", v);
        } else if (!strcmp(a, "--normalize")) {
            o->center = 1;
            o->fit = 1;
            o->fit_radius = 1.0;
        } else if (str_arg(argc, argv, &i, "--scale", NULL, &v)) {
            o->scale = positive_arg("--scale", v);
        } else if (long_arg(argc, argv, &i, "--quant-scale", 1, 0x7FFFFFFF, &o->quant_scale)) {
            continue;
        } else if (long_arg(argc, argv, &i, "--max-triangles", 1, MAX_OUT, &n)) {
            o->max_tris = (unsigned long)n;
        } else if (long_arg(argc, argv, &i, "--max-vertices", 1, MAX_OUT, &n)) {
            o->max_verts = (unsigned long)n;
        } else if (str_arg(argc, argv, &i, "--colors", "--colours", &v)) {
            if (zs_opt_choice(OPT_PROG, "--colors", v, color_srcs, 4, &k) != 0)
                exit(EXIT_USAGE);
            o->colors = (enum color_src)k;
        } else if (str_arg(argc, argv, &i, "--color", "--colour", &v)) {
            if (zs_opt_color(OPT_PROG, "--color", v, &o->base_color) != 0)
                exit(EXIT_USAGE);
        } else if (str_arg(argc, argv, &i, "--normals", NULL, &v)) {
            if (zs_opt_choice(OPT_PROG, "--normals", v, normal_kinds, 4, &k) != 0)
                exit(EXIT_USAGE);
            o->normals = (enum normal_kind)k;
        } else if (long_arg(argc, argv, &i, "--mem-limit", 0, LONG_MAX >> 20, &o->mem_limit_mb)) {
            continue;
        } else if (!strcmp(a, "--bsp")) {
            o->bsp = 1;
        } else if (long_arg(argc, argv, &i, "--bsp-weight", 1, 1000, &o->bsp_weight) ||
                   long_arg(argc, argv, &i, "--bsp-candidates", 1, 100000, &o->bsp_candidates)) {
            continue;
        } else if (str_arg(argc, argv, &i, "--texture", NULL, &v)) {
            o->tex_mode = !strcmp(v, "auto") ? TEX_AUTO : !strcmp(v, "none") ? TEX_NONE : TEX_FILE;
            o->tex_file = v;
            if (!*v) {
                fprintf(stderr, "%s: error: --texture needs auto, none or an image file\n", g_prog);
                exit(EXIT_USAGE);
            }
        } else if (long_arg(argc, argv, &i, "--texture-size", 1, ZS_TEX_MAX_DIM, &n)) {
            if (n & (n - 1)) {
                fprintf(stderr, "%s: error: --texture-size must be a power of two (1..%d), got "
                                "%ld\n", g_prog, ZS_TEX_MAX_DIM, n);
                exit(EXIT_USAGE);
            }
            o->tex_size = (unsigned)n;
        } else if (!strcmp(a, "--no-resample")) {
            o->tex_resample = 0;
        } else if (str_arg(argc, argv, &i, "--texture-format", NULL, &v)) {
            static const char *const fmts[] = {"rgb565", "pal8"};
            if (zs_opt_choice(OPT_PROG, "--texture-format", v, fmts, 2, &k) != 0)
                exit(EXIT_USAGE);
            o->tex_format = k ? ZS_TEX_PAL8 : ZS_TEX_RGB565;
        } else if (str_arg(argc, argv, &i, "--texture-filter", NULL, &v)) {
            static const char *const filters[] = {"nearest", "bilinear"};
            if (zs_opt_choice(OPT_PROG, "--texture-filter", v, filters, 2, &k) != 0)
                exit(EXIT_USAGE);
            o->tex_flags = (o->tex_flags & ~ZS_TEX_BILINEAR) | (k ? ZS_TEX_BILINEAR : 0u);
        } else if (str_arg(argc, argv, &i, "--texture-wrap", NULL, &v)) {
            static const char *const wraps[] = {"repeat", "clamp"};
            if (zs_opt_choice(OPT_PROG, "--texture-wrap", v, wraps, 2, &k) != 0)
                exit(EXIT_USAGE);
            o->tex_flags = (o->tex_flags & ~ZS_TEX_CLAMP) | (k ? ZS_TEX_CLAMP : 0u);
        } else if (str_arg(argc, argv, &i, "--texture-perspective", NULL, &v)) {
            static const char *const persp[] = {"exact", "subdiv"};
            if (zs_opt_choice(OPT_PROG, "--texture-perspective", v, persp, 2, &k) != 0)
                exit(EXIT_USAGE);
            o->tex_flags = (o->tex_flags & ~ZS_TEX_SUBDIV) | (k ? ZS_TEX_SUBDIV : 0u);
        } else if (!strcmp(a, "--no-merge")) {
            o->merge = 0;
        } else if (!strcmp(a, "--flip-winding")) {
            o->flip = 1;
        } else if (!strcmp(a, "--lenient")) {
            o->lenient = 1;
        } else if (!strcmp(a, "--info")) {
            o->info_only = 1;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "%s: error: unknown option '%s' (see --help)\n", g_prog, a);
            exit(EXIT_USAGE);
        } else if (!o->input) {
            o->input = a;
        } else {
            fprintf(stderr, "%s: error: more than one input model ('%s', '%s')\n", g_prog,
                    o->input, a);
            exit(EXIT_USAGE);
        }
    }
    if (!o->input) {
        usage(stderr);
        exit(EXIT_USAGE);
    }
    if (o->bsp && o->zsm) {
        fprintf(stderr, "%s: error: --bsp writes C arrays; it does not go with --format zsm\n",
                g_prog);
        exit(EXIT_USAGE);
    }
    if (o->name && ident_problem(o->name) != NULL) {
        fprintf(stderr, "%s: error: --name '%s' %s; choose another, e.g. mesh_%s\n", g_prog,
                o->name, ident_problem(o->name),
                valid_ident(o->name) && o->name[0] != '_' ? o->name : "model");
        exit(EXIT_USAGE);
    }
}

int main(int argc, char **argv)
{
    options o;
    model m;
    char *name;
    double lo[3], hi[3], shift[3] = {0, 0, 0}, k = 1.0, radius = 0, maxabs = 0;
    size_t i, raw_v, raw_t;
    long qscale;
    int r;

    parse_args(argc, argv, &o);
    g_input = o.input;
    signal(SIGABRT, on_fatal_signal);
    signal(SIGSEGV, on_fatal_signal);
    signal(SIGBUS, on_fatal_signal);
    signal(SIGFPE, on_fatal_signal);
    name = o.name ? xrealloc(NULL, strlen(o.name) + 1) : name_from_path(o.input);
    if (o.name)
        strcpy(name, o.name);

    memset(&m, 0, sizeof m);
    import_model(&o, &m);
    raw_v = m.nv;
    raw_t = m.nt;
    merge_vertices(&o, &m, o.merge);
    if (m.nt == 0)
        die(EXIT_INPUT, "the model has no triangles with a non-zero area");
    if (m.degenerate)
        warn(&o, "dropped %zu degenerate triangles", m.degenerate);

    bbox(&m, lo, hi);
    if (o.center)
        for (r = 0; r < 3; r++)
            shift[r] = (lo[r] + hi[r]) / 2;
    for (i = 0; i < m.nv; i++) {
        double d = 0;
        for (r = 0; r < 3; r++)
            d += (m.v[i].p[r] - shift[r]) * (m.v[i].p[r] - shift[r]);
        if (d > radius)
            radius = d;
    }
    radius = sqrt(radius);
    if (o.fit) {
        if (!(radius > 0))
            die(EXIT_INPUT, "all vertices are at one point; cannot --fit");
        k = o.fit_radius / radius;
    }
    k *= o.scale;
    for (i = 0; i < m.nv; i++)
        for (r = 0; r < 3; r++)
            m.v[i].p[r] = (m.v[i].p[r] - shift[r]) * k;
    radius *= k;

    if (m.nt > MAX_OUT || m.nv > MAX_OUT || o.max_tris || o.max_verts) {
        if (!o.max_tris && !o.max_verts)
            die(EXIT_LIMIT, "oversized model: %zu triangles and %zu vertices after merging; "
                            "the core takes at most %u of each (use --max-triangles / "
                            "--max-vertices to decimate)", m.nt, m.nv, MAX_OUT);
        decimate(&o, &m);
    }

    for (i = 0; i < m.nv; i++)
        for (r = 0; r < 3; r++)
            if (fabs(m.v[i].p[r]) > maxabs)
                maxabs = fabs(m.v[i].p[r]);
    if (maxabs > 32767.0)
        die(EXIT_LIMIT, "oversized coordinates: |%g| exceeds the core's +-32767 model units "
                        "(use --scale or --normalize)", maxabs);
    if (o.quant_scale) {
        qscale = o.quant_scale;
        if (maxabs * 65536.0 / (double)qscale > 32767.0)
            die(EXIT_LIMIT, "--quant-scale %ld is too small: |%g| needs at least %ld", qscale,
                maxabs, (long)ceil(maxabs * 65536.0 / 32767.0));
    } else {
        qscale = (long)ceil(maxabs * 65536.0 / 32767.0);
        if (qscale < 1)
            qscale = 1;
    }

    if (o.info_only || !o.quiet) {
        FILE *f = o.info_only ? stdout : stderr;
        fprintf(f, "%s: %zu triangles, %zu vertices (importer: %zu triangles, %zu vertices); "
                   "radius %.6g; bbox (%.6g %.6g %.6g)..(%.6g %.6g %.6g); scale %ld/65536; "
                   "max quantisation error %.3g\n",
                o.input, m.nt, m.nv, raw_t, raw_v, radius, lo[0], lo[1], lo[2], hi[0], hi[1],
                hi[2], qscale, (double)qscale / 131072.0);
        if (m.textured)
            fprintf(f, "%s: texture %s: %u x %u -> %u x %u %s, %zu bytes\n", o.input, m.tex_ref,
                    m.tex_w0, m.tex_h0, (unsigned)m.tex.width, (unsigned)m.tex.height,
                    m.tex.format == ZS_TEX_PAL8 ? "pal8" : "rgb565",
                    (size_t)m.tex.width * m.tex.height * (m.tex.format == ZS_TEX_PAL8 ? 1u : 2u) +
                        (m.tex.format == ZS_TEX_PAL8 ? 512u : 0u));
    }
    if (o.info_only)
        return 0;
    if (!o.output) {
        char *p = xrealloc(NULL, strlen(name) + 1);
        strcpy(p, name);
        o.output = p;
    }
    write_files(&o, &m, name, qscale, lo, hi, radius, k, shift);
    free_model(&m);
    free(name);
    return 0;
}
