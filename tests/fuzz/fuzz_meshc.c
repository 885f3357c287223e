/* SPDX-License-Identifier: MIT */
/*
 * fuzz_meshc: the mesh converter's input path (tools/zspan-meshc.c), in
 * process (libFuzzer).
 *
 * The converter is compiled into this harness with its exits turned into a
 * longjmp back here, its signal handlers and address-space limit disabled
 * (they would hide crashes from the fuzzer and starve ASan) and its messages
 * sent to /dev/null. Input: byte 0 picks the file type (the extension assimp
 * sees), byte 1 and 2 the options (--center/--normalize, --colors, --normals,
 * --no-merge, --flip-winding, --lenient, --max-triangles, the mesh name; its
 * bit 5 --texture auto, bit 6 --texture-format pal8); the rest is the model
 * file, written to a scratch file and converted. With bit 7 of byte 0 the
 * rest is an image instead (PNG, JPEG or TGA by bits 0-1: the name, not its
 * bytes, picks the decoder tried first) that a fixed textured OBJ quad
 * names: the image decoders and the resampler get the input. (Not .glb:
 * assimp 5.2's glTF importer itself crashes on some, which the converter
 * reports, see its signal handler, but in process that ends the fuzzer.)
 *
 * Invariants:
 *   - no memory error in the converter (ASan/UBSan; assimp itself is not
 *     instrumented, but ASan's interceptors check its memcpy/strlen etc.);
 *   - it ends with exit code 0 (success) or one of its documented failure
 *     codes 3 (input), 4 (limit), 5 (I/O), never anything else;
 *   - on success the generated C is a valid zs_mesh: array sizes match the
 *     counts, 1 <= counts <= 65535, every index < vertex_count, positions
 *     int16 (and |p| <= 32767), Q1.14 normals within +-16384, colours 24-bit,
 *     a positive Q16.16 scale, at most --max-triangles triangles, uvs and
 *     texels (when textured) sized by the counts and the texture's powers of
 *     two; and the core accepts it (with ZS_CFG_TEXTURE): zs_draw returns
 *     ZS_OK and the statistics add up.
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "fuzz_util.h"
#include "zspan/zspan.h"

/* Names up to this length (the converter once overflowed a 64-byte buffer
 * with names of 30 characters; tests/tools/test_meshc.c keeps that fixed). */
#ifndef FUZZ_MESHC_MAX_NAME
#define FUZZ_MESHC_MAX_NAME 64
#endif

/* The converter caps the address space while importing (a corrupt header can
 * make a loader reserve gigabytes); ASan cannot run under such a cap, so the
 * same effect comes from ASan's allocator: an oversized allocation fails (C++
 * new throws, the importer reports bad_alloc) instead of being made. assimp
 * leaks a scene on some failed imports: no leak checking here. */
const char *__asan_default_options(void);
const char *__asan_default_options(void)
{
    return "allocator_may_return_null=1:max_allocation_size_mb=256:detect_leaks=0";
}

static jmp_buf g_jmp;
static int g_exit_code;
static FILE *g_null;

__attribute__((noreturn)) void fuzz_meshc_exit(int code);
void fuzz_meshc_exit(int code)
{
    g_exit_code = code;
    longjmp(g_jmp, 1);
}

typedef void (*fuzz_sighandler)(int);
static fuzz_sighandler fuzz_signal(int sig, fuzz_sighandler h)
{
    (void)sig;
    (void)h;
    return SIG_DFL;
}

static void fuzz_guard_begin(const char *prog, const char *path, int code)
{
    (void)prog;
    (void)path;
    (void)code;
}

static void fuzz_guard_end(void)
{
}

static int fuzz_setrlimit(int res, const struct rlimit *rl)
{
    (void)res;
    (void)rl;
    return 0;
}

/* Every exit of the converter is a longjmp here: what it had allocated and
 * the imported scene are tracked and released afterwards (no leak per run). */
#define MAX_LIVE 4096
static void *g_live[MAX_LIVE];
static size_t g_nlive;
static const struct aiScene *g_scene;

static void *fuzz_realloc(void *p, size_t n)
{
    void *q = realloc(p, n);
    size_t i;
    if (!q)
        return q;
    for (i = 0; i < g_nlive; i++)
        if (p && g_live[i] == p) {
            g_live[i] = q;
            return q;
        }
    FZ_CHECK(g_nlive < MAX_LIVE, "more than %d live blocks", MAX_LIVE);
    g_live[g_nlive++] = q;
    return q;
}

static void *fuzz_malloc(size_t n) { return fuzz_realloc(NULL, n); }

static void *fuzz_calloc(size_t n, size_t k)
{
    void *p = calloc(n, k);
    FZ_CHECK(g_nlive < MAX_LIVE, "more than %d live blocks", MAX_LIVE);
    if (p)
        g_live[g_nlive++] = p;
    return p;
}

static void fuzz_free(void *p)
{
    size_t i;
    if (!p)
        return;
    for (i = 0; i < g_nlive; i++)
        if (g_live[i] == p) {
            g_live[i] = g_live[--g_nlive];
            break;
        }
    free(p);
}

static void fuzz_free_all(void)
{
    while (g_nlive)
        free(g_live[--g_nlive]);
}

#include <assimp/cimport.h>
static const struct aiScene *fuzz_import(const char *path, unsigned flags)
{
    g_scene = aiImportFile(path, flags);
    return g_scene;
}

static const struct aiScene *fuzz_post(const struct aiScene *s, unsigned flags)
{
    const struct aiScene *t = aiApplyPostProcessing(s, flags);
    g_scene = t; /* NULL: assimp has dropped the scene */
    return t;
}

static void fuzz_release(const struct aiScene *s)
{
    if (s == g_scene)
        g_scene = NULL;
    aiReleaseImport(s);
}

#define realloc fuzz_realloc
#define malloc fuzz_malloc
#define calloc fuzz_calloc
#define free fuzz_free
#define aiImportFile fuzz_import
#define aiApplyPostProcessing fuzz_post
#define aiReleaseImport fuzz_release
#define exit fuzz_meshc_exit
/* libFuzzer's own -timeout uses SIGALRM: the converter's import guard stays off. */
#define zs_import_guard_begin fuzz_guard_begin
#define zs_import_guard_end fuzz_guard_end
#define signal fuzz_signal
#define setrlimit fuzz_setrlimit
#define main meshc_main
#undef stderr
#define stderr g_null
#undef stdout
#define stdout g_null
#include "../../tools/zspan-meshc.c"
#undef realloc
#undef malloc
#undef calloc
#undef free
#undef aiImportFile
#undef aiApplyPostProcessing
#undef aiReleaseImport
#undef exit
#undef signal
#undef setrlimit
#undef main
#undef stderr
#undef stdout

/* ------------------------------------------------------------------ */
/* Reading the generated C back                                        */
/* ------------------------------------------------------------------ */

typedef struct arr {
    long *v;
    size_t n, declared;
    int present;
} arr;

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *b;
    long n;
    FZ_CHECK(f != NULL, "exit 0 but no %s", path);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = malloc((size_t)n + 1);
    FZ_CHECK(fread(b, 1, (size_t)n, f) == (size_t)n, "short read of %s", path);
    b[n] = 0;
    fclose(f);
    *len = (size_t)n;
    return b;
}

/* "static const T NAME_field[N] = { v, v, ... };" */
static void parse_array(const char *src, const char *name, const char *field, arr *a)
{
    char key[160];
    const char *p;
    memset(a, 0, sizeof *a);
    snprintf(key, sizeof key, "%s_%s[", name, field);
    p = strstr(src, key);
    if (!p || !strstr(p, "] = {"))
        return;
    a->present = 1;
    p += strlen(key);
    a->declared = strtoul(p, NULL, 10);
    p = strchr(p, '{') + 1;
    a->v = malloc((a->declared + 1) * sizeof *a->v);
    for (;;) {
        char *end;
        while (*p == ' ' || *p == '\n' || *p == ',')
            p++;
        if (*p == '}')
            break;
        long v = strtol(p, &end, 0);
        FZ_CHECK(end != p, "%s: cannot parse at \"%.20s\"", field, p);
        FZ_CHECK(a->n < a->declared, "%s: more values than the declared %zu", field, a->declared);
        a->v[a->n++] = v;
        p = end;
    }
    FZ_CHECK(a->n == a->declared, "%s: %zu values, declared %zu", field, a->n, a->declared);
}

/* A "    V, /" "* what *" "/" line of the zs_mesh initializer. */
static long mesh_field(const char *src, const char *what)
{
    const char *p = strstr(src, what), *line;
    FZ_CHECK(p != NULL, "no %s in the zs_mesh initializer", what);
    line = p;
    while (line > src && line[-1] != '\n')
        line--;
    return strtol(line, NULL, 0);
}

static void check_output(const char *cpath, const char *name, unsigned long max_tris)
{
    size_t len;
    char *src = slurp(cpath, &len);
    arr pos, idx, fc, vc, fn, vn, uv, tx, pal;
    long scale = mesh_field(src, "/* scale, Q16.16 */");
    long nv = mesh_field(src, "/* vertex_count */");
    long nt = mesh_field(src, "/* triangle_count */");
    long color = mesh_field(src, "/* color */");
    parse_array(src, name, "positions", &pos);
    parse_array(src, name, "indices", &idx);
    parse_array(src, name, "face_colors", &fc);
    parse_array(src, name, "vertex_colors", &vc);
    parse_array(src, name, "face_normals", &fn);
    parse_array(src, name, "vertex_normals", &vn);
    parse_array(src, name, "uvs", &uv);
    parse_array(src, name, "texels", &tx);
    parse_array(src, name, "palette", &pal);
    FZ_CHECK(nv >= 1 && nv <= 65535 && nt >= 1 && nt <= 65535, "counts %ld vertices %ld triangles",
             nv, nt);
    FZ_CHECK(!max_tris || (unsigned long)nt <= max_tris, "%ld triangles above --max-triangles %lu",
             nt, max_tris);
    FZ_CHECK(scale > 0 && scale <= 0x7FFFFFFF, "scale %ld", scale);
    FZ_CHECK(color >= 0 && color <= 0xFFFFFF, "colour %#lx", color);
    FZ_CHECK(pos.present && pos.n == 3u * (size_t)nv, "%zu positions for %ld vertices", pos.n, nv);
    FZ_CHECK(idx.present && idx.n == 3u * (size_t)nt, "%zu indices for %ld triangles", idx.n, nt);
    for (size_t i = 0; i < pos.n; i++)
        FZ_CHECK(pos.v[i] >= -32767 && pos.v[i] <= 32767, "position %zu = %ld", i, pos.v[i]);
    for (size_t i = 0; i < idx.n; i++)
        FZ_CHECK(idx.v[i] >= 0 && idx.v[i] < nv, "index %zu = %ld of %ld vertices", i, idx.v[i],
                 nv);
    FZ_CHECK(!fc.present || fc.n == (size_t)nt, "%zu face colours", fc.n);
    FZ_CHECK(!vc.present || vc.n == (size_t)nv, "%zu vertex colours", vc.n);
    FZ_CHECK(!fn.present || fn.n == 3u * (size_t)nt, "%zu face normal values", fn.n);
    FZ_CHECK(!vn.present || vn.n == 3u * (size_t)nv, "%zu vertex normal values", vn.n);
    for (size_t i = 0; i < fc.n; i++)
        FZ_CHECK(fc.v[i] >= 0 && fc.v[i] <= 0xFFFFFF, "face colour %#lx", fc.v[i]);
    for (size_t i = 0; i < vc.n; i++)
        FZ_CHECK(vc.v[i] >= 0 && vc.v[i] <= 0xFFFFFF, "vertex colour %#lx", vc.v[i]);
    for (size_t i = 0; i < fn.n; i++)
        FZ_CHECK(fn.v[i] >= -16384 && fn.v[i] <= 16384, "face normal value %ld", fn.v[i]);
    for (size_t i = 0; i < vn.n; i++)
        FZ_CHECK(vn.v[i] >= -16384 && vn.v[i] <= 16384, "vertex normal value %ld", vn.v[i]);
    long tw = 0, th = 0;
    FZ_CHECK(uv.present == tx.present, "uvs without texels or the other way round");
    if (uv.present) {
        char key[160];
        const char *p;
        FZ_CHECK(uv.n == 2u * (size_t)nv, "%zu uv values for %ld vertices", uv.n, nv);
        for (size_t i = 0; i < uv.n; i++)
            FZ_CHECK(uv.v[i] >= -32768 && uv.v[i] <= 32767, "uv %ld", uv.v[i]);
        snprintf(key, sizeof key, "%s_texture = {", name);
        p = strstr(src, key);
        FZ_CHECK(p != NULL, "no %s", key);
        p = strstr(p, "u, ");
        FZ_CHECK(p != NULL, "no texture size");
        while (p[-1] >= '0' && p[-1] <= '9')
            p--;
        tw = strtol(p, (char **)&p, 10);
        th = strtol(p + 3, NULL, 10);
        FZ_CHECK(tw >= 1 && tw <= 1024 && th >= 1 && th <= 1024 && !(tw & (tw - 1)) &&
                     !(th & (th - 1)), "texture %ld x %ld", tw, th);
        FZ_CHECK(tx.n == (size_t)(tw * th), "%zu texels for %ld x %ld", tx.n, tw, th);
        FZ_CHECK(!pal.present || pal.n == 256, "%zu palette colours", pal.n);
        for (size_t i = 0; i < tx.n; i++)
            FZ_CHECK(tx.v[i] >= 0 && tx.v[i] <= (pal.present ? 255 : 65535), "texel %ld",
                     tx.v[i]);
    }

    /* the core takes it as it is */
    {
        int16_t *p16 = malloc(pos.n * sizeof *p16 + 1);
        uint16_t *i16 = malloc(idx.n * sizeof *i16 + 1);
        int16_t *fn16 = fn.present ? malloc(fn.n * sizeof *fn16 + 1) : NULL;
        int16_t *vn16 = vn.present ? malloc(vn.n * sizeof *vn16 + 1) : NULL;
        zs_color *fc32 = fc.present ? malloc(fc.n * sizeof *fc32 + 1) : NULL;
        zs_color *vc32 = vc.present ? malloc(vc.n * sizeof *vc32 + 1) : NULL;
        for (size_t i = 0; i < pos.n; i++) p16[i] = (int16_t)pos.v[i];
        for (size_t i = 0; i < idx.n; i++) i16[i] = (uint16_t)idx.v[i];
        for (size_t i = 0; i < fn.n; i++) fn16[i] = (int16_t)fn.v[i];
        for (size_t i = 0; i < vn.n; i++) vn16[i] = (int16_t)vn.v[i];
        for (size_t i = 0; i < fc.n; i++) fc32[i] = (zs_color)fc.v[i];
        for (size_t i = 0; i < vc.n; i++) vc32[i] = (zs_color)vc.v[i];
        int16_t *uv16 = uv.present ? malloc(uv.n * sizeof *uv16 + 1) : NULL;
        uint16_t *t16 = NULL, *pal16 = NULL;
        uint8_t *t8 = NULL;
        zs_texture tex;
        memset(&tex, 0, sizeof tex);
        for (size_t i = 0; i < uv.n; i++) uv16[i] = (int16_t)uv.v[i];
        if (uv.present) {
            tex.width = (uint16_t)tw;
            tex.height = (uint16_t)th;
            if (pal.present) {
                t8 = malloc(tx.n + 1);
                pal16 = malloc(256 * sizeof *pal16);
                for (size_t i = 0; i < tx.n; i++) t8[i] = (uint8_t)tx.v[i];
                for (size_t i = 0; i < 256; i++) pal16[i] = (uint16_t)pal.v[i];
                tex.texels = t8;
                tex.palette = pal16;
                tex.format = ZS_TEX_PAL8;
            } else {
                t16 = malloc(tx.n * sizeof *t16 + 1);
                for (size_t i = 0; i < tx.n; i++) t16[i] = (uint16_t)tx.v[i];
                tex.texels = t16;
                tex.format = ZS_TEX_RGB565;
            }
            FZ_CHECK(zs_texture_check(&tex) == ZS_OK, "the core refused the texture");
        }
        zs_mesh m = {p16, i16, fc32, vc32, fn16, vn16, (zs_fixed)scale, (uint16_t)nv,
                     (uint16_t)nt, (zs_color)color, uv16, uv.present ? &tex : NULL};
        static uint8_t arena[ZS_ARENA_BYTES_CFG(32, 32, 4096, 4096, 64, ZS_CFG_TEXTURE)];
        zs_config cfg = zs_config_default(32, 32, 4096, 4096, 64);
        cfg.flags |= ZS_CFG_TEXTURE;
        zs_renderer r;
        zs_camera cam;
        FZ_CHECK(zs_init(&r, arena, sizeof arena, &cfg) == ZS_OK, "init");
        FZ_CHECK(zs_camera_look_at(&cam, zs_vec3_make(0, 0, ZS_FX(3)), zs_vec3_make(0, 0, 0),
                                   zs_vec3_make(0, ZS_FX(1), 0)) == ZS_OK, "look_at");
        FZ_CHECK(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 10, ZS_FX(1000)) == ZS_OK,
                 "perspective");
        FZ_CHECK(zs_frame_begin(&r, &cam, ZS_MODE_SPAN) == ZS_OK, "frame_begin");
        zs_shade_params sp = zs_shade_default();
        sp.shading = ZS_SHADE_GOURAUD;
        sp.light_count = 1;
        sp.ambient = ZS_FX(1) / 4;
        sp.lights[0].direction = zs_vec3_make(ZS_FX(1), ZS_FX(1), ZS_FX(1));
        sp.lights[0].intensity = ZS_FX(1);
        FZ_CHECK(zs_frame_shading(&r, &sp) == ZS_OK, "shading");
        zs_status st = zs_draw(&r, &m, NULL);
        FZ_CHECK(st == ZS_OK, "the core refused the converted mesh: %d (%s)", (int)st,
                 zs_strerror(st));
        const zs_stats *s = zs_frame_stats(&r);
        FZ_CHECK(s->tris_submitted == (uint32_t)nt &&
                     s->tris_submitted == s->tris_culled + s->tris_rejected + s->tris_empty +
                                              s->tris_dropped + s->tris_stored,
                 "statistics of the converted mesh do not add up");
        uint8_t line[32 * 2];
        FZ_CHECK(zs_render_rows(&r, 0, 32, line, 0) == ZS_ERR_BUFFER, "stride 0 accepted");
        for (int y = 0; y < 32; y++)
            FZ_CHECK(zs_render_rows(&r, y, 1, line, sizeof line) == ZS_OK, "render");
        free(p16); free(i16); free(fn16); free(vn16); free(fc32); free(vc32);
        free(uv16); free(t16); free(t8); free(pal16);
    }
    free(pos.v); free(idx.v); free(fc.v); free(vc.v); free(fn.v); free(vn.v);
    free(uv.v); free(tx.v); free(pal.v);
    free(src);
}

/* ------------------------------------------------------------------ */

/* File types. Not PLY: Debian's assimp 5.2 PLY loader loops forever on some
 * malformed headers; the converter stops such an import with a timeout
 * (tests/tools/data/ply-hang.ply), but in process that ends the fuzzer. */
static const char *const k_ext[] = {"obj", "off", "stl", "raw", "nff"};
static char g_in[256], g_out[256], g_cpath[300];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    const char *dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    (void)argc;
    (void)argv;
    g_null = fopen("/dev/null", "w");
    if (getenv("FUZZ_VERBOSE"))
        g_null = fdopen(dup(2), "w");
    snprintf(g_out, sizeof g_out, "%s/zspan-fuzz-meshc-%ld-out", dir, (long)getpid());
    snprintf(g_cpath, sizeof g_cpath, "%s.c", g_out);
    snprintf(g_in, sizeof g_in, "%s/zspan-fuzz-meshc-%ld", dir, (long)getpid());
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[300], maxt[16], name[80];
    static char *argv[32];
    fz_reader d;
    int argc = 0;
    unsigned long max_tris = 0;
    fz_init(&d, data, size);
    uint8_t kind = fz_u8(&d), o1 = fz_u8(&d), o2 = fz_u8(&d);
    const char *ext = k_ext[kind % (sizeof k_ext / sizeof k_ext[0])];
    snprintf(path, sizeof path, "%s.%s", g_in, ext);
    if (kind & 0x80u) { /* the input is the image of a fixed model */
        static const char *const img_ext[] = {"png", "jpg", "tga", "png"};
        char ipath[300], mpath[300];
        const char *base = strrchr(g_in, '/') + 1;
        FILE *f;
        ext = "obj";
        snprintf(path, sizeof path, "%s.obj", g_in);
        snprintf(mpath, sizeof mpath, "%s.mtl", g_in);
        snprintf(ipath, sizeof ipath, "%s.%s", g_in, img_ext[kind & 3u]);
        f = fopen(mpath, "w");
        FZ_CHECK(f != NULL, "cannot write %s", mpath);
        fprintf(f, "newmtl m\nKd 1 1 1\nmap_Kd %s.%s\n", base, img_ext[kind & 3u]);
        fclose(f);
        f = fopen(path, "w");
        FZ_CHECK(f != NULL, "cannot write %s", path);
        fprintf(f, "mtllib %s.mtl\nusemtl m\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n", base);
        fclose(f);
        f = fopen(ipath, "wb");
        FZ_CHECK(f != NULL, "cannot write %s", ipath);
        fwrite(data + d.pos, 1, fz_left(&d), f);
        fclose(f);
    } else {
        FILE *f = fopen(path, "wb");
        FZ_CHECK(f != NULL, "cannot write %s", path);
        fwrite(data + d.pos, 1, fz_left(&d), f);
        fclose(f);
    }
    remove(g_cpath);
    argv[argc++] = "zspan-meshc";
    argv[argc++] = "-q";
    argv[argc++] = "--mem-limit";
    argv[argc++] = "0";
    argv[argc++] = "-o";
    argv[argc++] = g_out;
    {
        size_t nl = 1 + (o2 >> 3) % FUZZ_MESHC_MAX_NAME;
        for (size_t i = 0; i < nl; i++)
            name[i] = (char)(i == 0 ? 'm' : "abcdefghijklmnopqrstuvwxyz_0123456789"[(i * 7u + o2) % 37u]);
        name[nl] = 0;
    }
    argv[argc++] = "-n";
    argv[argc++] = name;
    if (o1 & 1u)
        argv[argc++] = (o1 & 2u) ? "--normalize" : "--center";
    switch ((o1 >> 2) & 3u) {
    case 1: argv[argc++] = "--colors"; argv[argc++] = "material"; break;
    case 2: argv[argc++] = "--colors"; argv[argc++] = "vertex"; break;
    case 3: argv[argc++] = "--colors"; argv[argc++] = "index"; break;
    default: break;
    }
    switch ((o1 >> 4) & 3u) {
    case 1: argv[argc++] = "--normals"; argv[argc++] = "face"; break;
    case 2: argv[argc++] = "--normals"; argv[argc++] = "smooth"; break;
    case 3: argv[argc++] = "--normals"; argv[argc++] = "file"; break;
    default: break;
    }
    if (o1 & 0x40u)
        argv[argc++] = "--no-merge";
    if (o1 & 0x80u)
        argv[argc++] = "--flip-winding";
    if (o2 & 1u)
        argv[argc++] = "--lenient";
    if (o2 & 2u) {
        max_tris = 1 + (o2 >> 2) % 40u;
        snprintf(maxt, sizeof maxt, "%lu", max_tris);
        argv[argc++] = "--max-triangles";
        argv[argc++] = maxt;
    }
    if (kind & 0xA0u) {
        argv[argc++] = "--texture";
        argv[argc++] = "auto";
    }
    if (kind & 0x40u) {
        argv[argc++] = "--texture-format";
        argv[argc++] = "pal8";
    }
    argv[argc++] = path;
    argv[argc] = NULL;

    /* the converter's globals start clean for every input */
    g_log_errors[0] = 0;
    g_log_error_count = 0;
    g_exit_code = -1;
    int rc;
    if (setjmp(g_jmp) == 0)
        rc = meshc_main(argc, argv);
    else
        rc = g_exit_code;
    aiDetachAllLogStreams();
    if (g_scene) {
        aiReleaseImport(g_scene);
        g_scene = NULL;
    }
    fuzz_free_all(); /* a successful run has freed everything but o.output */
    FZ_CHECK(rc == 0 || rc == EXIT_INPUT || rc == EXIT_LIMIT || rc == EXIT_IO,
             "zspan-meshc %s exited with %d", ext, rc);
    if (rc == 0)
        check_output(g_cpath, name, max_tris);
    remove(path);
    return 0;
}
