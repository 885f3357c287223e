/* SPDX-License-Identifier: MIT */
/* The llvmpipe oracle's drawing (test_llvmpipe, test_meshc_llvmpipe): the
 * renderer's screen triangles (setup-hook records) through OpenGL with the
 * texture coordinates of their mesh triangles, nearest filtering,
 * perspective-correct, into the current (OSMesa) context. Include after
 * GL/gl.h and zt_test.h. */
#ifndef ZSPAN_TESTS_ZT_GL_H
#define ZSPAN_TESTS_ZT_GL_H

/* recs: record tag t is mesh triangle t - 1 of indices; uv in ZS_UV_ONE
 * units; texels tw x th RGB565; depth_a = far / (far - near) of the camera
 * (window depth z gives w = 1 / (depth_a - z), up to a scale). */
static void zt_gl_draw_records(const zt_recs *recs, const uint16_t *indices, const int16_t *uv,
                               const uint16_t *texels, int tw, int th, int w, int h,
                               double depth_a, int clamp)
{
    GLuint tex;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, tw, th, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, clamp ? GL_CLAMP_TO_EDGE : GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, clamp ? GL_CLAMP_TO_EDGE : GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_TRIANGLES);
    for (size_t k = 0; k < recs->n; k++) {
        const zt_rec *r = &recs->v[k];
        const uint16_t *idx = indices + 3u * (r->tag - 1u);
        for (int i = 0; i < 3; i++) {
            double z = r->z[i] / 1073741824.0;
            double wc = 1.0 / (depth_a - z); /* any scale: only ratios matter */
            double xn = r->xy[2 * i] / 16.0 / w * 2 - 1, yn = 1 - r->xy[2 * i + 1] / 16.0 / h * 2;
            glTexCoord2f((float)(uv[2 * idx[i]] / (double)ZS_UV_ONE),
                         (float)(uv[2 * idx[i] + 1] / (double)ZS_UV_ONE));
            glVertex4f((float)(xn * wc), (float)(yn * wc), (float)((2 * z - 1) * wc), (float)wc);
        }
    }
    glEnd();
    glFinish();
    glDeleteTextures(1, &tex);
}

#endif
