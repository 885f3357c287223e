/* SPDX-License-Identifier: MIT */
/* Status codes and their descriptions: each says what the comment of its code
 * in include/zspan/zspan.h says (tests/core/test_status.c checks it). */
#include "zs_internal.h"

#define ZS_STR_(x) #x
#define ZS_STR(x) ZS_STR_(x)

const char *zs_strerror(zs_status status)
{
    switch (status) {
    case ZS_OK: return "ok";
    case ZS_ERR_NULL: return "a required pointer argument is NULL";
    case ZS_ERR_SIZE:
        return "width or height is zero or above ZS_MAX_DIM (" ZS_STR(ZS_MAX_DIM) ")";
    case ZS_ERR_CAPACITY:
        return "a capacity (max_triangles, max_vertices, max_active_edges) is zero, below its "
               "minimum or above its limit";
    case ZS_ERR_ARENA_SMALL: return "the arena is smaller than zs_arena_bytes() of the config";
    case ZS_ERR_CAMERA:
        return "degenerate camera: eye at the target, up parallel to the view direction, or a "
               "missing or bad view/projection";
    case ZS_ERR_FOV: return "field of view not in (0, 180) degrees";
    case ZS_ERR_DEPTH_RANGE: return "depth range needs 0 < near < far";
    case ZS_ERR_MESH: return "mesh with no positions or indices (NULL), or a zero scale";
    case ZS_ERR_INDEX:
        return "a triangle index is >= the mesh's vertex_count (the whole draw is rejected)";
    case ZS_ERR_STATE:
        return "call out of order for the frame (e.g. zs_draw before zs_frame_begin or after "
               "rendering started)";
    case ZS_ERR_ROW: return "row range outside the screen or before the next row";
    case ZS_ERR_BUFFER: return "buffer stride too small for the width and pixel format";
    case ZS_ERR_FORMAT: return "unknown pixel format";
    case ZS_ERR_MODE:
        return "unknown visibility or shading mode, or one the config's flags left out";
    case ZS_ERR_ARGUMENT: return "some other argument is outside its documented range";
    case ZS_ERR_LEVEL:
        return "malformed level or PVS data (zspan/portal.h): a count, index, cell polygon, "
               "portal or PVS row that zs_level_check refuses";
    case ZS_ERR_TEXTURE:
        return "bad texture (see zs_texture_check): a size that is not a power of two in "
               "1..ZS_TEX_MAX_DIM, no texels (or palette), an unknown format or flags, or a mesh "
               "with uvs and no texture or the other way round";
    case ZS_STATUS_COUNT: break;
    }
    return "unknown status code";
}
