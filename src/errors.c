/* Status codes and their descriptions. */
#include "zs_internal.h"

const char *zs_strerror(zs_status status)
{
    switch (status) {
    case ZS_OK: return "ok";
    case ZS_ERR_NULL: return "a required pointer is NULL";
    case ZS_ERR_SIZE: return "width or height is zero or above ZS_MAX_DIM";
    case ZS_ERR_CAPACITY: return "a capacity is zero or above its limit";
    case ZS_ERR_ARENA_SMALL: return "the arena is smaller than zs_arena_bytes()";
    case ZS_ERR_CAMERA: return "degenerate camera (eye at target, up along the view, or no view/projection)";
    case ZS_ERR_FOV: return "field of view outside (0, 180) degrees";
    case ZS_ERR_DEPTH_RANGE: return "depth range needs 0 < near < far";
    case ZS_ERR_MESH: return "mesh without positions or indices, or with a zero scale";
    case ZS_ERR_INDEX: return "a triangle index is outside the mesh's vertices";
    case ZS_ERR_STATE: return "call out of order for the frame";
    case ZS_ERR_ROW: return "row range outside the screen or before the next row";
    case ZS_ERR_BUFFER: return "buffer stride too small for the width and pixel format";
    case ZS_ERR_FORMAT: return "unknown pixel format";
    case ZS_ERR_MODE: return "unknown visibility or shading mode";
    case ZS_ERR_ARGUMENT: return "argument outside its documented range";
    case ZS_STATUS_COUNT: break;
    }
    return "unknown status code";
}
