/* SPDX-License-Identifier: MIT */
/*
 * Textures for the host tools (zspan-meshc, zspan-sim render): a material's
 * diffuse image found through assimp (embedded in the model, "*0" etc., or a
 * file beside it), decoded (PNG through libpng, JPEG through libjpeg, TGA
 * here), resampled by area averaging to a power-of-two size and turned into
 * the core's zs_texture formats (RGB565, or 8-bit indices into 256 RGB565
 * colours).
 *
 * Rules (README: Textures in the converter):
 *  - the size: each side becomes the largest power of two not above it,
 *    then at most `limit`; with resampling off the image must already be a
 *    power of two within the limit (else ZS_TIMG_ERR_SIZE);
 *  - a texel is the exact area average of the source pixels it covers, each
 *    channel rounded to nearest; alpha is ignored;
 *  - 8-bit channels become RGB565 by round(c * 31 / 255) (63 for green).
 */
#ifndef ZSPAN_TOOLS_TEXIMG_H
#define ZSPAN_TOOLS_TEXIMG_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/zspan.h"

struct aiScene;

/* Largest image side and pixel count decoded (larger: ZS_TIMG_ERR_SIZE). */
#define ZS_TIMG_MAX_SIDE 16384u
#define ZS_TIMG_MAX_PIXELS (64u << 20)

enum {
    ZS_TIMG_OK = 0,
    ZS_TIMG_NONE = 1,          /* zs_timg_material: the material has no diffuse texture */
    ZS_TIMG_ERR_READ = -1,     /* missing or unreadable file, or a corrupt image */
    ZS_TIMG_ERR_FORMAT = -2,   /* not PNG, JPEG or TGA (or a TGA kind not read) */
    ZS_TIMG_ERR_SIZE = -3,     /* oversized (see above) */
    ZS_TIMG_ERR_MEMORY = -4
};

/* An 8-bit RGB image, row 0 at the top, 3 bytes per pixel. */
typedef struct zs_timg {
    unsigned w, h;
    uint8_t *rgb;
} zs_timg;

/* Decodes PNG, JPEG or TGA (told apart by their first bytes; TGA by its
 * header's sanity). msg gets a reason on failure. */
int zs_timg_decode(const uint8_t *data, size_t n, zs_timg *out, char *msg, size_t msglen);
int zs_timg_read_file(const char *path, zs_timg *out, char *msg, size_t msglen);
void zs_timg_free(zs_timg *img);

/* The power-of-two size the rule above gives for w x h. */
void zs_timg_pot_size(unsigned w, unsigned h, unsigned limit, unsigned *ow, unsigned *oh);
/* Area-average resample to w x h. */
int zs_timg_resample(const zs_timg *in, unsigned w, unsigned h, zs_timg *out);

uint16_t zs_timg_565(unsigned r, unsigned g, unsigned b);

/* Texels of a power-of-two image in the core's formats: rgb565 gets w * h
 * values; pal8 gets w * h indices and 256 colours (the image's own colours
 * when it has at most 256 in RGB565, else a median cut; unused entries 0).
 * Returns the number of palette colours used (0 for RGB565), or -1 when out
 * of memory. */
int zs_timg_to_rgb565(const zs_timg *img, uint16_t *texels);
int zs_timg_to_pal8(const zs_timg *img, uint8_t *texels, uint16_t palette[256]);

/* Finds and decodes the diffuse texture of material `mat` (assimp's
 * aiTextureType_DIFFUSE, else BASE_COLOR): ZS_TIMG_OK with *out, ZS_TIMG_NONE,
 * or an error with msg. `ref` gets the texture's name in the file ("*0",
 * "duck.png"), `where` the place it was read from (the path, or
 * "embedded"). model_path: the model file, for references beside it. */
int zs_timg_material(const struct aiScene *s, unsigned mat, const char *model_path,
                     zs_timg *out, char *ref, size_t reflen, char *msg, size_t msglen);

/* Sizes (limit; resample 0: the image must already fit, else
 * ZS_TIMG_ERR_SIZE naming `name`) and converts *img (freed) into *tex with
 * malloc'd texels (and palette), format ZS_TEX_RGB565 or ZS_TEX_PAL8, flags
 * as given. */
int zs_timg_make_texture(zs_timg *img, const char *name, unsigned limit, int resample,
                         unsigned format, unsigned flags, zs_texture *tex, char *msg, size_t len);

/* The whole way for one material: found, decoded, sized (limit; resample 0:
 * the image must already fit) and converted into *tex with malloc'd texels
 * (and palette): format ZS_TEX_RGB565 or ZS_TEX_PAL8, flags as given. Same
 * results as zs_timg_material. */
int zs_timg_material_texture(const struct aiScene *s, unsigned mat, const char *model_path,
                             unsigned limit, int resample, unsigned format, unsigned flags,
                             zs_texture *tex, char *ref, size_t reflen, char *msg, size_t msglen);

/* Frees the texels and palette of a texture made above. */
void zs_timg_texture_free(zs_texture *tex);

#endif /* ZSPAN_TOOLS_TEXIMG_H */
