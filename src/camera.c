/* Camera: look-at view transform and perspective parameters. */
#include "zs_internal.h"

static void sub3(zs_vec3 a, zs_vec3 b, int64_t out[3])
{
    out[0] = (int64_t)a.x - b.x;
    out[1] = (int64_t)a.y - b.y;
    out[2] = (int64_t)a.z - b.z;
}

static void cross3(const int32_t a[3], const int32_t b[3], int64_t out[3])
{
    out[0] = (int64_t)a[1] * b[2] - (int64_t)a[2] * b[1];
    out[1] = (int64_t)a[2] * b[0] - (int64_t)a[0] * b[2];
    out[2] = (int64_t)a[0] * b[1] - (int64_t)a[1] * b[0];
}

zs_status zs_camera_look_at(zs_camera *cam, zs_vec3 eye, zs_vec3 target, zs_vec3 up)
{
    int64_t d[3], u64[3], s64[3], t64[3];
    int32_t f[3], s[3], u[3], e[3];
    int i;
    if (!cam)
        return ZS_ERR_NULL;
    sub3(target, eye, d);
    if (!zs_normalize3(d, f))
        return ZS_ERR_CAMERA;
    u64[0] = up.x;
    u64[1] = up.y;
    u64[2] = up.z;
    {
        int32_t upn[3];
        if (!zs_normalize3(u64, upn))
            return ZS_ERR_CAMERA;
        cross3(f, upn, s64); /* side = forward x up (Q32) */
    }
    /* up within ~0.001 rad of the view direction is degenerate */
    t64[0] = s64[0];
    t64[1] = s64[1];
    t64[2] = s64[2];
    zs_shrink3(t64, (int64_t)1 << 40);
    {
        uint64_t l2 = 0;
        for (i = 0; i < 3; i++) {
            int64_t c = t64[i] / 65536; /* Q16 */
            l2 += (uint64_t)(c * c);
        }
        if (zs_isqrt64(l2) < 64) /* |sin| < 0.001 */
            return ZS_ERR_CAMERA;
    }
    if (!zs_normalize3(s64, s))
        return ZS_ERR_CAMERA;
    cross3(s, f, u64); /* true up = side x forward */
    if (!zs_normalize3(u64, u))
        return ZS_ERR_CAMERA;
    e[0] = eye.x;
    e[1] = eye.y;
    e[2] = eye.z;
    for (i = 0; i < 3; i++) {
        cam->view.m[0][i] = s[i];
        cam->view.m[1][i] = u[i];
        cam->view.m[2][i] = -f[i];
    }
    {
        int32_t nf[3];
        nf[0] = -f[0];
        nf[1] = -f[1];
        nf[2] = -f[2];
        cam->view.m[0][3] = zs_sat32(-zs_dot3_q16(s, e), 0);
        cam->view.m[1][3] = zs_sat32(-zs_dot3_q16(u, e), 0);
        cam->view.m[2][3] = zs_sat32(-zs_dot3_q16(nf, e), 0);
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
