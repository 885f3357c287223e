/* SPDX-License-Identifier: MIT */
/* Texture images for the host tools: decode, resample, convert (zs_teximg.h). */
#define _POSIX_C_SOURCE 200809L
#include "zs_teximg.h"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>
#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <strings.h>
#include <sys/stat.h>

#include <jpeglib.h>

static void say(char *msg, size_t len, const char *fmt, ...)
{
    va_list ap;
    if (!msg || !len)
        return;
    va_start(ap, fmt);
    vsnprintf(msg, len, fmt, ap);
    va_end(ap);
}

void zs_timg_free(zs_timg *img)
{
    free(img->rgb);
    memset(img, 0, sizeof *img);
}

static int check_size(unsigned w, unsigned h, char *msg, size_t len)
{
    if (w == 0 || h == 0) {
        say(msg, len, "the image has no pixels (%u x %u)", w, h);
        return ZS_TIMG_ERR_READ;
    }
    if (w > ZS_TIMG_MAX_SIDE || h > ZS_TIMG_MAX_SIDE ||
        (unsigned long long)w * h > ZS_TIMG_MAX_PIXELS) {
        say(msg, len, "oversized image: %u x %u pixels (at most %u a side and %u Mpixels)", w,
            h, ZS_TIMG_MAX_SIDE, ZS_TIMG_MAX_PIXELS >> 20);
        return ZS_TIMG_ERR_SIZE;
    }
    return ZS_TIMG_OK;
}

static int alloc_img(zs_timg *out, unsigned w, unsigned h)
{
    out->w = w;
    out->h = h;
    out->rgb = malloc((size_t)w * h * 3u);
    return out->rgb ? ZS_TIMG_OK : ZS_TIMG_ERR_MEMORY;
}

/* ---- PNG (libpng's simplified reader) ---------------------------------- */

static int decode_png(const uint8_t *data, size_t n, zs_timg *out, char *msg, size_t len)
{
    png_image im;
    uint8_t *rgba;
    size_t i, px;
    int rc;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&im, data, n)) {
        say(msg, len, "corrupt PNG: %s", im.message);
        png_image_free(&im);
        return ZS_TIMG_ERR_READ;
    }
    if ((rc = check_size(im.width, im.height, msg, len)) != ZS_TIMG_OK) {
        png_image_free(&im);
        return rc;
    }
    im.format = PNG_FORMAT_RGBA;
    px = (size_t)im.width * im.height;
    rgba = malloc(px * 4u);
    if (!rgba || alloc_img(out, im.width, im.height) != ZS_TIMG_OK) {
        free(rgba);
        png_image_free(&im);
        zs_timg_free(out);
        return ZS_TIMG_ERR_MEMORY;
    }
    if (!png_image_finish_read(&im, NULL, rgba, 0, NULL)) {
        say(msg, len, "corrupt PNG: %s", im.message);
        free(rgba);
        png_image_free(&im);
        zs_timg_free(out);
        return ZS_TIMG_ERR_READ;
    }
    for (i = 0; i < px; i++) /* alpha is not used */
        memcpy(out->rgb + 3u * i, rgba + 4u * i, 3);
    free(rgba);
    png_image_free(&im);
    return ZS_TIMG_OK;
}

/* ---- JPEG (libjpeg; its errors come back by longjmp) ------------------- */

typedef struct jerr {
    struct jpeg_error_mgr mgr;
    jmp_buf jb;
    char text[JMSG_LENGTH_MAX];
} jerr;

static void jpeg_fail(j_common_ptr c)
{
    jerr *e = (jerr *)c->err;
    (*c->err->format_message)(c, e->text);
    longjmp(e->jb, 1);
}

static void jpeg_quiet(j_common_ptr c, int level)
{
    (void)c;
    (void)level;
}

static int decode_jpeg(const uint8_t *data, size_t n, zs_timg *out, char *msg, size_t len)
{
    struct jpeg_decompress_struct d;
    jerr e;
    volatile int rc = ZS_TIMG_OK;
    memset(&d, 0, sizeof d);
    memset(out, 0, sizeof *out);
    d.err = jpeg_std_error(&e.mgr);
    e.mgr.error_exit = jpeg_fail;
    e.mgr.emit_message = jpeg_quiet;
    if (setjmp(e.jb)) {
        say(msg, len, "corrupt JPEG: %s", e.text);
        jpeg_destroy_decompress(&d);
        zs_timg_free(out);
        return ZS_TIMG_ERR_READ;
    }
    jpeg_create_decompress(&d);
    jpeg_mem_src(&d, data, (unsigned long)n);
    jpeg_read_header(&d, TRUE);
    if ((rc = check_size(d.image_width, d.image_height, msg, len)) != ZS_TIMG_OK) {
        jpeg_destroy_decompress(&d);
        return rc;
    }
    d.out_color_space = JCS_RGB;
    jpeg_start_decompress(&d);
    if (d.output_components != 3 || alloc_img(out, d.output_width, d.output_height) != 0) {
        jpeg_destroy_decompress(&d);
        zs_timg_free(out);
        say(msg, len, "cannot decode this JPEG to RGB");
        return ZS_TIMG_ERR_MEMORY;
    }
    while (d.output_scanline < d.output_height) {
        JSAMPROW row = out->rgb + (size_t)d.output_scanline * out->w * 3u;
        jpeg_read_scanlines(&d, &row, 1);
    }
    jpeg_finish_decompress(&d);
    jpeg_destroy_decompress(&d);
    return rc;
}

/* ---- TGA (the kinds models use: true colour and grey, raw or RLE) ------ */

static int is_tga(const uint8_t *p, size_t n)
{
    unsigned type, bpp;
    if (n < 18)
        return 0;
    type = p[2];
    bpp = p[16];
    if (p[1] > 1)
        return 0;
    return ((type == 2 || type == 10) && (bpp == 24 || bpp == 32)) ||
           ((type == 3 || type == 11) && bpp == 8);
}

static int decode_tga(const uint8_t *p, size_t n, zs_timg *out, char *msg, size_t len)
{
    unsigned w = (unsigned)p[12] | (unsigned)p[13] << 8, h = (unsigned)p[14] | (unsigned)p[15] << 8;
    unsigned type = p[2], bpp = p[16] / 8u, top = (p[17] & 0x20u) != 0, right = (p[17] & 0x10u) != 0;
    size_t off = 18u + p[0], px, i = 0, k;
    int rc;
    if (p[1]) /* a colour map before the pixels (unused by true colour) */
        off += (size_t)((unsigned)p[5] | (unsigned)p[6] << 8) * ((p[7] + 7u) / 8u);
    if ((rc = check_size(w, h, msg, len)) != ZS_TIMG_OK)
        return rc;
    if (alloc_img(out, w, h) != ZS_TIMG_OK)
        return ZS_TIMG_ERR_MEMORY;
    px = (size_t)w * h;
    while (i < px) {
        size_t run = 1, raw = 1;
        if (type >= 9) {
            if (off >= n)
                break;
            run = (p[off] & 127u) + 1u;
            raw = !(p[off] & 128u);
            off++;
        }
        for (k = 0; k < run && i < px; k++, i++) {
            size_t x = i % w, y = i / w, dst;
            const uint8_t *s;
            if (raw || k == 0) {
                if (off + bpp > n)
                    goto short_file;
                s = p + off;
                off += bpp;
            } else {
                s = p + off - bpp;
            }
            if (right)
                x = w - 1u - x;
            if (!top)
                y = h - 1u - y;
            dst = (y * w + x) * 3u;
            if (bpp == 1) {
                out->rgb[dst] = out->rgb[dst + 1] = out->rgb[dst + 2] = s[0];
            } else { /* BGR(A) */
                out->rgb[dst] = s[2];
                out->rgb[dst + 1] = s[1];
                out->rgb[dst + 2] = s[0];
            }
        }
    }
    if (i == px)
        return ZS_TIMG_OK;
short_file:
    say(msg, len, "corrupt TGA: the file ends before its %u x %u pixels", w, h);
    zs_timg_free(out);
    return ZS_TIMG_ERR_READ;
}

int zs_timg_decode(const uint8_t *data, size_t n, zs_timg *out, char *msg, size_t len)
{
    static const uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    memset(out, 0, sizeof *out);
    if (n >= 8 && memcmp(data, png_sig, 8) == 0)
        return decode_png(data, n, out, msg, len);
    if (n >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF)
        return decode_jpeg(data, n, out, msg, len);
    if (is_tga(data, n))
        return decode_tga(data, n, out, msg, len);
    say(msg, len, "unsupported image format (PNG, JPEG and true-colour or grey TGA are read)");
    return ZS_TIMG_ERR_FORMAT;
}

int zs_timg_read_file(const char *path, zs_timg *out, char *msg, size_t len)
{
    FILE *f;
    uint8_t *buf;
    long size;
    struct stat st;
    int rc;
    memset(out, 0, sizeof *out);
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        say(msg, len, "cannot read image %s: it is a directory", path);
        return ZS_TIMG_ERR_READ;
    }
    f = fopen(path, "rb");
    if (!f) {
        say(msg, len, "cannot read image %s: %s", path, strerror(errno));
        return ZS_TIMG_ERR_READ;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        say(msg, len, "cannot read image %s", path);
        return ZS_TIMG_ERR_READ;
    }
    if ((unsigned long)size > (unsigned long)ZS_TIMG_MAX_PIXELS * 4u + 65536u) {
        fclose(f);
        say(msg, len, "oversized image file %s (%ld bytes)", path, size);
        return ZS_TIMG_ERR_SIZE;
    }
    buf = malloc((size_t)size + 1u);
    if (!buf) {
        fclose(f);
        return ZS_TIMG_ERR_MEMORY;
    }
    if (fread(buf, 1, (size_t)size, f) != (size_t)size) {
        free(buf);
        fclose(f);
        say(msg, len, "cannot read image %s", path);
        return ZS_TIMG_ERR_READ;
    }
    fclose(f);
    if (size == 0) {
        free(buf);
        say(msg, len, "image %s is empty", path);
        return ZS_TIMG_ERR_READ;
    }
    rc = zs_timg_decode(buf, (size_t)size, out, msg, len);
    free(buf);
    if (rc != ZS_TIMG_OK && msg && len) { /* name the file */
        char tmp[512];
        snprintf(tmp, sizeof tmp, "%s", msg);
        say(msg, len, "image %s: %s", path, tmp);
    }
    return rc;
}

/* ---- size, resampling, formats ------------------------------------------ */

static unsigned pot_floor(unsigned v)
{
    unsigned p = 1;
    while (p * 2u <= v && p < 0x80000000u)
        p *= 2u;
    return p;
}

void zs_timg_pot_size(unsigned w, unsigned h, unsigned limit, unsigned *ow, unsigned *oh)
{
    unsigned lim = pot_floor(limit ? limit : 1u);
    *ow = pot_floor(w ? w : 1u);
    *oh = pot_floor(h ? h : 1u);
    if (*ow > lim)
        *ow = lim;
    if (*oh > lim)
        *oh = lim;
}

/* Overlap of source pixel s ([s w, (s + 1) w) in units of 1/(W w)) with
 * output texel i ([i W, (i + 1) W)). */
static uint64_t overlap(unsigned s, unsigned i, unsigned src, unsigned dst)
{
    uint64_t a0 = (uint64_t)s * dst, a1 = a0 + dst, b0 = (uint64_t)i * src, b1 = b0 + src;
    uint64_t lo = a0 > b0 ? a0 : b0, hi = a1 < b1 ? a1 : b1;
    return hi > lo ? hi - lo : 0;
}

int zs_timg_resample(const zs_timg *in, unsigned w, unsigned h, zs_timg *out)
{
    unsigned x, y;
    const uint64_t total = (uint64_t)in->w * in->h;
    if (alloc_img(out, w, h) != ZS_TIMG_OK)
        return ZS_TIMG_ERR_MEMORY;
    for (y = 0; y < h; y++) {
        unsigned sy0 = (unsigned)(((uint64_t)y * in->h) / h);
        unsigned sy1 = (unsigned)(((uint64_t)(y + 1u) * in->h + h - 1u) / h);
        for (x = 0; x < w; x++) {
            unsigned sx0 = (unsigned)(((uint64_t)x * in->w) / w);
            unsigned sx1 = (unsigned)(((uint64_t)(x + 1u) * in->w + w - 1u) / w);
            uint64_t acc[3] = {0, 0, 0};
            unsigned sx, sy, c;
            for (sy = sy0; sy < sy1; sy++) {
                uint64_t wy = overlap(sy, y, in->h, h);
                for (sx = sx0; sx < sx1; sx++) {
                    uint64_t wgt = wy * overlap(sx, x, in->w, w);
                    const uint8_t *p = in->rgb + ((size_t)sy * in->w + sx) * 3u;
                    for (c = 0; c < 3; c++)
                        acc[c] += wgt * p[c];
                }
            }
            for (c = 0; c < 3; c++) /* the weights add up to W H */
                out->rgb[((size_t)y * w + x) * 3u + c] = (uint8_t)((acc[c] + total / 2u) / total);
        }
    }
    return ZS_TIMG_OK;
}

uint16_t zs_timg_565(unsigned r, unsigned g, unsigned b)
{
    return (uint16_t)(((r * 31u + 127u) / 255u) << 11 | ((g * 63u + 127u) / 255u) << 5 |
                      (b * 31u + 127u) / 255u);
}

int zs_timg_to_rgb565(const zs_timg *img, uint16_t *texels)
{
    size_t i, n = (size_t)img->w * img->h;
    for (i = 0; i < n; i++)
        texels[i] = zs_timg_565(img->rgb[3 * i], img->rgb[3 * i + 1], img->rgb[3 * i + 2]);
    return 0;
}

/* RGB565 channels widened back to 8 bits (for distances and means). */
static void widen(uint16_t c, int out[3])
{
    out[0] = (int)(((c >> 11) & 31u) * 255u + 15u) / 31;
    out[1] = (int)(((c >> 5) & 63u) * 255u + 31u) / 63;
    out[2] = (int)((c & 31u) * 255u + 15u) / 31;
}

static int cmp_u16(const void *a, const void *b)
{
    uint16_t x = *(const uint16_t *)a, y = *(const uint16_t *)b;
    return x < y ? -1 : x > y;
}

static int sort_axis;
static int cmp_axis(const void *a, const void *b)
{
    int x[3], y[3];
    widen(*(const uint16_t *)a, x);
    widen(*(const uint16_t *)b, y);
    if (x[sort_axis] != y[sort_axis])
        return x[sort_axis] < y[sort_axis] ? -1 : 1;
    return cmp_u16(a, b);
}

int zs_timg_to_pal8(const zs_timg *img, uint8_t *texels, uint16_t palette[256])
{
    size_t i, n = (size_t)img->w * img->h, nu = 0;
    uint16_t *c565 = malloc(n * sizeof *c565 + 2), *uniq = malloc(n * sizeof *uniq + 2);
    size_t box_lo[256], box_hi[256];
    int nbox, used;
    if (!c565 || !uniq) {
        free(c565);
        free(uniq);
        return -1;
    }
    memset(palette, 0, 256 * sizeof *palette);
    zs_timg_to_rgb565(img, c565);
    memcpy(uniq, c565, n * sizeof *uniq);
    qsort(uniq, n, sizeof *uniq, cmp_u16);
    for (i = 0; i < n; i++)
        if (nu == 0 || uniq[nu - 1] != uniq[i])
            uniq[nu++] = uniq[i];
    /* Median cut over the distinct colours: split the box with the widest
     * channel range at its median until 256 boxes (or all colours). */
    box_lo[0] = 0;
    box_hi[0] = nu;
    nbox = 1;
    while (nbox < 256 && (size_t)nbox < nu) {
        int best = -1, best_axis = 0, best_range = 0, b;
        for (b = 0; b < nbox; b++) {
            int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0}, a;
            if (box_hi[b] - box_lo[b] < 2)
                continue;
            for (i = box_lo[b]; i < box_hi[b]; i++) {
                int c[3];
                widen(uniq[i], c);
                for (a = 0; a < 3; a++) {
                    lo[a] = c[a] < lo[a] ? c[a] : lo[a];
                    hi[a] = c[a] > hi[a] ? c[a] : hi[a];
                }
            }
            for (a = 0; a < 3; a++)
                if (hi[a] - lo[a] > best_range || best < 0) {
                    best_range = hi[a] - lo[a];
                    best_axis = a;
                    best = b;
                }
        }
        if (best < 0)
            break;
        sort_axis = best_axis;
        qsort(uniq + box_lo[best], box_hi[best] - box_lo[best], sizeof *uniq, cmp_axis);
        box_lo[nbox] = box_lo[best] + (box_hi[best] - box_lo[best]) / 2u;
        box_hi[nbox] = box_hi[best];
        box_hi[best] = box_lo[nbox];
        nbox++;
    }
    for (used = 0; used < nbox; used++) {
        long s[3] = {0, 0, 0}, cnt = (long)(box_hi[used] - box_lo[used]);
        int a;
        if (cnt == 1) { /* exact when the image has few colours */
            palette[used] = uniq[box_lo[used]];
            continue;
        }
        for (i = box_lo[used]; i < box_hi[used]; i++) {
            int c[3];
            widen(uniq[i], c);
            for (a = 0; a < 3; a++)
                s[a] += c[a];
        }
        palette[used] = zs_timg_565((unsigned)((s[0] + cnt / 2) / cnt),
                                    (unsigned)((s[1] + cnt / 2) / cnt),
                                    (unsigned)((s[2] + cnt / 2) / cnt));
    }
    for (i = 0; i < n; i++) { /* nearest palette colour, the first on ties */
        int c[3], b, best = 0;
        long bd = -1;
        widen(c565[i], c);
        for (b = 0; b < used; b++) {
            int p[3];
            long d;
            if (palette[b] == c565[i]) {
                best = b;
                break;
            }
            widen(palette[b], p);
            d = (long)(p[0] - c[0]) * (p[0] - c[0]) + (long)(p[1] - c[1]) * (p[1] - c[1]) +
                (long)(p[2] - c[2]) * (p[2] - c[2]);
            if (bd < 0 || d < bd) {
                bd = d;
                best = b;
            }
        }
        texels[i] = (uint8_t)best;
    }
    free(c565);
    free(uniq);
    return used;
}

/* ---- materials ----------------------------------------------------------- */

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

static int from_embedded(const struct aiTexture *t, zs_timg *out, char *msg, size_t len)
{
    if (!t || !t->pcData) {
        say(msg, len, "the embedded texture has no data");
        return ZS_TIMG_ERR_READ;
    }
    if (t->mHeight == 0) /* compressed: a file's bytes */
        return zs_timg_decode((const uint8_t *)t->pcData, t->mWidth, out, msg, len);
    {
        int rc = check_size(t->mWidth, t->mHeight, msg, len);
        size_t i, n;
        if (rc != ZS_TIMG_OK)
            return rc;
        if (alloc_img(out, t->mWidth, t->mHeight) != ZS_TIMG_OK)
            return ZS_TIMG_ERR_MEMORY;
        n = (size_t)t->mWidth * t->mHeight;
        for (i = 0; i < n; i++) {
            out->rgb[3 * i] = t->pcData[i].r;
            out->rgb[3 * i + 1] = t->pcData[i].g;
            out->rgb[3 * i + 2] = t->pcData[i].b;
        }
        return ZS_TIMG_OK;
    }
}

int zs_timg_material(const struct aiScene *s, unsigned mat, const char *model_path,
                     zs_timg *out, char *ref, size_t reflen, char *msg, size_t len)
{
    const struct aiMaterial *m;
    struct aiString path;
    char name[1024], full[2048];
    size_t i, dir;
    int rc;
    memset(out, 0, sizeof *out);
    if (ref && reflen)
        ref[0] = 0;
    if (!s || mat >= s->mNumMaterials || !s->mMaterials || !s->mMaterials[mat])
        return ZS_TIMG_NONE;
    m = s->mMaterials[mat];
    if (aiGetMaterialTexture(m, aiTextureType_DIFFUSE, 0, &path, NULL, NULL, NULL, NULL, NULL,
                             NULL) != aiReturn_SUCCESS &&
        aiGetMaterialTexture(m, aiTextureType_BASE_COLOR, 0, &path, NULL, NULL, NULL, NULL,
                             NULL, NULL) != aiReturn_SUCCESS)
        return ZS_TIMG_NONE;
    snprintf(name, sizeof name, "%.*s", (int)(path.length < sizeof name ? path.length : sizeof name - 1),
             path.data);
    if (ref && reflen)
        snprintf(ref, reflen, "%s", name);
    if (name[0] == 0)
        return ZS_TIMG_NONE;
    if (name[0] == '*') { /* embedded: "*N" */
        char *end;
        unsigned long k = strtoul(name + 1, &end, 10);
        if (*end || end == name + 1 || k >= s->mNumTextures || !s->mTextures) {
            say(msg, len, "texture %s: the model embeds %u textures", name, s->mNumTextures);
            return ZS_TIMG_ERR_READ;
        }
        rc = from_embedded(s->mTextures[k], out, msg, len);
        if (rc != ZS_TIMG_OK && msg && len) {
            char tmp[512];
            snprintf(tmp, sizeof tmp, "%s", msg);
            say(msg, len, "embedded texture %s: %s", name, tmp);
        }
        return rc;
    }
    for (i = 0; name[i]; i++) /* Windows separators */
        if (name[i] == '\\')
            name[i] = '/';
    if (strncmp(name, "file://", 7) == 0)
        memmove(name, name + 7, strlen(name + 7) + 1);
    /* An embedded texture that carries the referenced file's name (ZAE). */
    for (i = 0; s->mTextures && i < s->mNumTextures; i++) {
        const struct aiTexture *t = s->mTextures[i];
        if (t && t->mFilename.length && strcmp(base_name(t->mFilename.data), base_name(name)) == 0) {
            rc = from_embedded(t, out, msg, len);
            if (rc != ZS_TIMG_OK && msg && len) {
                char tmp[512];
                snprintf(tmp, sizeof tmp, "%s", msg);
                say(msg, len, "embedded texture %s: %s", name, tmp);
            }
            return rc;
        }
    }
    dir = 0;
    if (model_path && strrchr(model_path, '/'))
        dir = (size_t)(strrchr(model_path, '/') - model_path) + 1u;
    if (name[0] == '/')
        snprintf(full, sizeof full, "%s", name);
    else
        snprintf(full, sizeof full, "%.*s%s", (int)dir, model_path ? model_path : "", name);
    {
        struct stat st;
        if (stat(full, &st) != 0) { /* a path from another machine: the name beside the model */
            char dpath[1024];
            DIR *d;
            snprintf(full, sizeof full, "%.*s%s", (int)dir, model_path ? model_path : "",
                     base_name(name));
            snprintf(dpath, sizeof dpath, "%.*s", dir ? (int)dir : 1, dir ? model_path : ".");
            if (stat(full, &st) != 0 && (d = opendir(dpath)) != NULL) {
                struct dirent *de; /* written in another case (IMAGE1.JPG for IMAGE1.jpg) */
                while ((de = readdir(d)) != NULL)
                    if (strcasecmp(de->d_name, base_name(name)) == 0) {
                        snprintf(full, sizeof full, "%.*s%s", (int)dir, dir ? model_path : "",
                                 de->d_name);
                        break;
                    }
                closedir(d);
            }
        }
    }
    return zs_timg_read_file(full, out, msg, len);
}

int zs_timg_make_texture(zs_timg *img, const char *name, unsigned limit, int resample,
                         unsigned format, unsigned flags, zs_texture *tex, char *msg, size_t len)
{
    zs_timg sized;
    unsigned w, h;
    int rc;
    memset(tex, 0, sizeof *tex);
    zs_timg_pot_size(img->w, img->h, limit, &w, &h);
    if (w != img->w || h != img->h) {
        if (!resample) {
            say(msg, len, "oversized texture: %s is %u x %u, not a power of two within %u x %u "
                          "(resampling is off)", name, img->w, img->h, limit, limit);
            zs_timg_free(img);
            return ZS_TIMG_ERR_SIZE;
        }
        rc = zs_timg_resample(img, w, h, &sized);
        zs_timg_free(img);
        if (rc != ZS_TIMG_OK)
            return rc;
        *img = sized;
    }
    tex->width = (uint16_t)w;
    tex->height = (uint16_t)h;
    tex->format = (uint8_t)format;
    tex->flags = (uint8_t)flags;
    if (format == ZS_TEX_PAL8) {
        uint8_t *t = malloc((size_t)w * h);
        uint16_t *pal = malloc(256 * sizeof *pal);
        if (!t || !pal || zs_timg_to_pal8(img, t, pal) < 0) {
            free(t);
            free(pal);
            zs_timg_free(img);
            return ZS_TIMG_ERR_MEMORY;
        }
        tex->texels = t;
        tex->palette = pal;
    } else {
        uint16_t *t = malloc((size_t)w * h * sizeof *t);
        if (!t) {
            zs_timg_free(img);
            return ZS_TIMG_ERR_MEMORY;
        }
        zs_timg_to_rgb565(img, t);
        tex->texels = t;
    }
    zs_timg_free(img);
    return ZS_TIMG_OK;
}

int zs_timg_material_texture(const struct aiScene *s, unsigned mat, const char *model_path,
                             unsigned limit, int resample, unsigned format, unsigned flags,
                             zs_texture *tex, char *ref, size_t reflen, char *msg, size_t len)
{
    zs_timg img;
    char name[256];
    int rc = zs_timg_material(s, mat, model_path, &img, name, sizeof name, msg, len);
    memset(tex, 0, sizeof *tex);
    if (ref && reflen)
        snprintf(ref, reflen, "%s", name);
    if (rc != ZS_TIMG_OK)
        return rc;
    return zs_timg_make_texture(&img, name, limit, resample, format, flags, tex, msg, len);
}

void zs_timg_texture_free(zs_texture *tex)
{
    free((void *)(uintptr_t)tex->texels);
    free((void *)(uintptr_t)tex->palette);
    memset(tex, 0, sizeof *tex);
}
