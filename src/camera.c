/* SPDX-License-Identifier: MIT */
/* Camera: look-at view transform and perspective parameters. */
#include "zs_internal.h"

zs_status zs_camera_look_at(zs_camera *cam, zs_vec3 eye, zs_vec3 target, zs_vec3 up)
{
    int64_t d[3], u64[3], s64[3];
    int32_t f[3], upn[3], row[3][3], e[3]; /* rows of the view: side, up, -forward */
    uint64_t l2 = 0;
    int i, k;
    if (!cam)
        return ZS_ERR_NULL;
    e[0] = eye.x;
    e[1] = eye.y;
    e[2] = eye.z;
    d[0] = (int64_t)target.x - e[0];
    d[1] = (int64_t)target.y - e[1];
    d[2] = (int64_t)target.z - e[2];
    u64[0] = up.x;
    u64[1] = up.y;
    u64[2] = up.z;
    if (!zs_normalize3(d, f) || !zs_normalize3(u64, upn))
        return ZS_ERR_CAMERA;
    zs_cross3(f, upn, s64); /* side = forward x up (Q32) */
    /* up within ~0.001 rad of the view direction is degenerate */
    for (i = 0; i < 3; i++)
        d[i] = s64[i];
    zs_shrink3(d, (int64_t)1 << 40);
    for (i = 0; i < 3; i++) {
        int64_t c = d[i] / 65536; /* Q16 */
        l2 += (uint64_t)(c * c);
    }
    if (zs_isqrt64(l2) < 64) /* |sin| < 0.001 */
        return ZS_ERR_CAMERA;
    if (!zs_normalize3(s64, row[0]))
        return ZS_ERR_CAMERA;
    zs_cross3(row[0], f, u64); /* true up = side x forward */
    if (!zs_normalize3(u64, row[1]))
        return ZS_ERR_CAMERA;
    for (i = 0; i < 3; i++)
        row[2][i] = -f[i];
    for (k = 0; k < 3; k++) {
        for (i = 0; i < 3; i++)
            cam->view.m[k][i] = row[k][i];
        cam->view.m[k][3] = zs_sat32(-zs_dot3_q16(row[k], e), 0);
    }
    cam->has_view = 1;
    return ZS_OK;
}

zs_status zs_camera_set_view(zs_camera *cam, const zs_mat34 *view)
{
    if (!cam || !view)
        return ZS_ERR_NULL;
    cam->view = *view;
    cam->has_view = 1;
    return ZS_OK;
}

zs_status zs_camera_perspective(zs_camera *cam, zs_fixed fov_deg, zs_fixed near_z,
                                zs_fixed far_z)
{
    int32_t s;
    if (!cam)
        return ZS_ERR_NULL;
    if (fov_deg <= 0 || fov_deg >= ZS_FX(180))
        return ZS_ERR_FOV;
    /* cot(fov/2) must fit Q16.16 (fov above ~0.004 degrees) */
    s = zs_sin_q30(fov_deg / 2);
    if ((int64_t)s * 32767 < ((int64_t)1 << 30))
        return ZS_ERR_FOV;
    if (near_z <= 0 || far_z <= near_z)
        return ZS_ERR_DEPTH_RANGE;
    cam->fov_deg = fov_deg;
    cam->near_z = near_z;
    cam->far_z = far_z;
    cam->has_projection = 1;
    return ZS_OK;
}
