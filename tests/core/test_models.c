/* SPDX-License-Identifier: MIT */
/* LIBS: -lassimp */
/*
 * test_models: span == zline == Warnock, byte for byte, on real meshes from Debian's
 * assimp-testmodels (loaded with assimp's C API), normalised to the unit
 * sphere and seen from several camera angles (one close enough to cut the
 * near plane), at 160x120, flat and Gouraud, lit, in RGB565_BE and ID16.
 * A missing model file is skipped with a message (at least one must load).
 * In the ID16 frames zs_pick must name the pixel's tag at every pixel.
 */
#include "zt_test.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120

static const char *k_models[] = {
    "/usr/share/assimp/models/STL/sphereWithHole.stl",
    "/usr/share/assimp/models/OBJ/WusonOBJ.obj",
    "/usr/share/assimp/models/OBJ/spider.obj",
};

static unsigned long g_warnock_bytes, g_windows, g_picks, g_pick_records;
static unsigned long g_loaded, g_renders, g_tris, g_bytes, g_covered, g_clipped;

typedef struct model {
    int16_t *pos, *nrm;
    uint16_t *idx;
    zs_color *vcol;
    unsigned nv, nt;
} model;

static int load(const char *path, model *md)
{
    memset(md, 0, sizeof *md);
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fclose(f);
    const struct aiScene *s =
        aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                               aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals);
    if (!s) {
        print_error("assimp failed on %s: %s\n", path, aiGetErrorString());
        return -1;
    }
    unsigned nv = 0, nt = 0;
    for (unsigned m = 0; m < s->mNumMeshes; m++) {
        nv += s->mMeshes[m]->mNumVertices;
        for (unsigned k = 0; k < s->mMeshes[m]->mNumFaces; k++)
            nt += s->mMeshes[m]->mFaces[k].mNumIndices == 3;
    }
    if (nv > 65535 || nt > 65535 || nv == 0) {
        aiReleaseImport(s);
        return -1;
    }
    /* bounding-box centre and radius */
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (unsigned m = 0; m < s->mNumMeshes; m++)
        for (unsigned i = 0; i < s->mMeshes[m]->mNumVertices; i++) {
            const struct aiVector3D *v = &s->mMeshes[m]->mVertices[i];
            double p[3] = {v->x, v->y, v->z};
            for (int k = 0; k < 3; k++) {
                if (p[k] < lo[k]) lo[k] = p[k];
                if (p[k] > hi[k]) hi[k] = p[k];
            }
        }
    double ctr[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}, rad = 0;
    for (unsigned m = 0; m < s->mNumMeshes; m++)
        for (unsigned i = 0; i < s->mMeshes[m]->mNumVertices; i++) {
            const struct aiVector3D *v = &s->mMeshes[m]->mVertices[i];
            double dx = v->x - ctr[0], dy = v->y - ctr[1], dz = v->z - ctr[2];
            double r = sqrt(dx * dx + dy * dy + dz * dz);
            if (r > rad) rad = r;
        }
    if (rad <= 0) rad = 1;
    md->pos = malloc(sizeof(int16_t) * 3 * nv);
    md->nrm = malloc(sizeof(int16_t) * 3 * nv);
    md->vcol = malloc(sizeof(zs_color) * nv);
    md->idx = malloc(sizeof(uint16_t) * 3 * (nt ? nt : 1));
    unsigned base = 0, t = 0;
    for (unsigned m = 0; m < s->mNumMeshes; m++) {
        const struct aiMesh *am = s->mMeshes[m];
        for (unsigned i = 0; i < am->mNumVertices; i++) {
            const struct aiVector3D *v = &am->mVertices[i];
            double p[3] = {(v->x - ctr[0]) / rad, (v->y - ctr[1]) / rad, (v->z - ctr[2]) / rad};
            for (int k = 0; k < 3; k++) md->pos[3 * (base + i) + k] = (int16_t)lrint(p[k] * 16384);
            double n[3] = {0, 0, 1};
            if (am->mNormals) {
                n[0] = am->mNormals[i].x;
                n[1] = am->mNormals[i].y;
                n[2] = am->mNormals[i].z;
            }
            double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(nl > 0)) { n[0] = 0; n[1] = 0; n[2] = 1; nl = 1; }
            for (int k = 0; k < 3; k++) md->nrm[3 * (base + i) + k] = (int16_t)lrint(n[k] / nl * 16384);
            md->vcol[base + i] = ZS_RGB(80 + (int)(p[0] * 70 + 70), 80 + (int)(p[1] * 70 + 70),
                                        80 + (int)(p[2] * 70 + 70));
        }
        for (unsigned k = 0; k < am->mNumFaces; k++) {
            const struct aiFace *fc = &am->mFaces[k];
            if (fc->mNumIndices != 3) continue;
            for (int j = 0; j < 3; j++) md->idx[3 * t + j] = (uint16_t)(base + fc->mIndices[j]);
            t++;
        }
        base += am->mNumVertices;
    }
    md->nv = nv;
    md->nt = t;
    aiReleaseImport(s);
    return 1;
}

static void free_model(model *md)
{
    free(md->pos);
    free(md->nrm);
    free(md->idx);
    free(md->vcol);
    memset(md, 0, sizeof *md);
}

static void test_models(void **state)
{
    (void)state;
    zt_ctx c;
    zt_ctx_init(&c, W, H, 12000, 24000, 4096);
    size_t cap = (size_t)W * H * 2;
    uint8_t *a = malloc(cap), *b = malloc(cap), *wn = malloc(cap);
    for (size_t fi = 0; fi < sizeof k_models / sizeof k_models[0]; fi++) {
        model md;
        int st = load(k_models[fi], &md);
        if (st == 0) {
            printf("test_models: %s missing, skipped (install assimp-testmodels)\n", k_models[fi]);
            continue;
        }
        ZT_CHECK(st > 0, "could not load %s", k_models[fi]);
        g_loaded++;
        zs_mesh m;
        memset(&m, 0, sizeof m);
        m.positions = md.pos;
        m.indices = md.idx;
        m.vertex_count = (uint16_t)md.nv;
        m.triangle_count = (uint16_t)md.nt;
        m.scale = ZS_FX(1) / 16384;
        m.color = ZS_RGB(200, 170, 120);
        for (int view = 0; view < 8; view++) {
            /* eye on a sphere around the model; view 7 is close (cuts near plane) */
            double az = view * 47.0 * 3.14159265358979 / 180, el = (view % 3 - 1) * 0.45;
            double dist = view == 7 ? 0.9 : 2.2 + 0.2 * view;
            zs_vec3 eye = zs_vec3_make((zs_fixed)lrint(dist * cos(el) * sin(az) * 65536),
                                       (zs_fixed)lrint(dist * sin(el) * 65536),
                                       (zs_fixed)lrint(dist * cos(el) * cos(az) * 65536));
            zs_camera cam;
            ZT_ST(zs_camera_look_at(&cam, eye, zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)),
                  ZS_OK);
            ZT_ST(zs_camera_perspective(&cam, ZS_FX(60), view == 7 ? ZS_FX(1) / 2 : ZS_FX(1) / 10, ZS_FX(10)),
                  ZS_OK);
            zs_mat34 rot = zs_mat34_rotate_y(ZS_FX(view * 13));
            for (int look = 0; look < 4; look++) {
                zs_shade_params sp = zs_shade_default();
                sp.format = (look & 1) ? ZS_FMT_ID16 : ZS_FMT_RGB565_BE;
                sp.shading = (look & 2) ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
                sp.ambient = ZS_FX(1) / 5;
                sp.light_count = 2;
                sp.lights[0].direction = zs_vec3_make(ZS_FX(1), ZS_FX(2), ZS_FX(3));
                sp.lights[0].intensity = ZS_FX(3) / 4;
                sp.lights[1].direction = zs_vec3_make(-ZS_FX(2), ZS_FX(1), 0);
                sp.lights[1].intensity = ZS_FX(1) / 3;
                sp.fog.enabled = view % 2;
                sp.fog.color = ZS_RGB(30, 40, 50);
                sp.fog.start = ZS_FX(2);
                sp.fog.end = ZS_FX(4);
                zs_mesh mm = m;
                mm.vertex_normals = (look & 2) ? md.nrm : NULL;
                mm.vertex_colors = (view % 3 == 0) ? md.vcol : NULL;
                static const zs_visibility modes[] = {ZS_MODE_SPAN, ZS_MODE_ZLINE, ZS_MODE_WARNOCK};
                static const int warnock_bands[] = {3, 8, 20, H};
                for (int mode = 0; mode < 3; mode++) {
                    uint8_t *img = mode == 2 ? wn : mode ? b : a;
                    int band = mode == 2 ? warnock_bands[(view + look) % 4] : mode ? 1 : 8;
                    memset(img, mode ? 0x11 : 0x22, cap);
                    ZT_ST(zs_frame_begin(&c.r, &cam, modes[mode]), ZS_OK);
                    ZT_ST(zs_frame_shading(&c.r, &sp), ZS_OK);
                    ZT_ST(zs_draw(&c.r, &mm, &rot), ZS_OK);
                    ZT_ST(zt_render_rows_all(&c.r, img, W, H, sp.format, band), ZS_OK);
                    if (mode == 2)
                        g_windows += zs_frame_stats(&c.r)->windows;
                    if (mode == 2 && sp.format == ZS_FMT_ID16) {
                        /* picking names what the ID16 image shows, at every pixel */
                        for (int y = 0; y < H; y++)
                            for (int x = 0; x < W; x++) {
                                zs_pick_hit hit;
                                ZT_ST(zs_pick(&c.r, x, y, &hit), ZS_OK);
                                uint16_t id = zt_id_at(a, W, x, y);
                                ZT_CHECK(hit.tag == id && (hit.record == ZS_PICK_NONE) == (id == 0),
                                         "%s view %d: pick (%d,%d) says tag %u (record %u), the "
                                         "ID16 image %u", k_models[fi], view, x, y, hit.tag,
                                         hit.record, id);
                                g_picks++;
                                g_pick_records += id != 0;
                            }
                    }
                    const zs_stats *s = zs_frame_stats(&c.r);
                    ZT_CHECK(s->tris_dropped == 0 && s->records_skipped == 0 && s->verts_dropped == 0,
                             "%s: pools too small for the test", k_models[fi]);
                    if (mode == 0) g_clipped += s->tris_clipped;
                    g_renders++;
                }
                size_t n = (size_t)W * H * 2;
                long d = zt_first_diff(a, b, n);
                if (d >= 0)
                    ZT_FAIL("%s view %d look %d: span and zline differ at byte %ld (pixel %ld,%ld): "
                            "%02x vs %02x",
                            k_models[fi], view, look, d, (d / 2) % W, (d / 2) / W, a[d], b[d]);
                g_bytes += n;
                d = zt_first_diff(a, wn, n);
                if (d >= 0)
                    ZT_FAIL("%s view %d look %d: span and Warnock differ at byte %ld (pixel %ld,%ld): "
                            "%02x vs %02x",
                            k_models[fi], view, look, d, (d / 2) % W, (d / 2) / W, a[d], wn[d]);
                g_warnock_bytes += n;
                if (sp.format == ZS_FMT_ID16)
                    for (int i = 0; i < W * H; i++) g_covered += zt_id_at(a, W, i % W, i / W) != 0;
            }
        }
        g_tris += md.nt;
        free_model(&md);
    }
    free(a);
    free(b);
    free(wn);
    zt_ctx_free(&c);
    ZT_CHECK(g_loaded > 0, "no model could be loaded");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_models),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    fflush(stderr);
    printf("test_models: %lu models loaded (%lu triangles), %lu renders at %dx%d, %lu bytes span == "
           "zline, %lu bytes span == Warnock (%lu windows), %lu picks equal to the ID16 pixel "
           "(%lu on a triangle), %lu covered pixels in ID16 frames, %lu triangles clipped; %d "
           "failed\n",
           g_loaded, g_tris, g_renders, W, H, g_bytes, g_warnock_bytes, g_windows, g_picks,
           g_pick_records, g_covered, g_clipped, rc);
    fflush(stdout);
    return rc;
}
