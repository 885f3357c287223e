/* SPDX-License-Identifier: MIT */
/*
 * The built-in demo scene (see demo_scene.h). Integer only: positions are
 * int16 in units of 1/4096 (mesh scale 16 in Q16.16) unless said otherwise.
 */
#include "demo_scene.h"

#include <stddef.h>

#if (32 % DEMO_TORUS_U) != 0 || (32 % DEMO_TORUS_V) != 0
#error "DEMO_TORUS_U and DEMO_TORUS_V must divide 32"
#endif

#define UNIT 4096                 /* 1.0 world unit in position integers */
#define UNIT_SCALE ((zs_fixed)16) /* Q16.16 scale: 16 / 65536 = 1 / 4096 */

/* sin(k * 11.25 deg) in Q16.16 for k = 0..8, rounded to nearest. */
static const int32_t sin_table[9] = {0, 12785, 25080, 36410, 46341, 54491, 60547, 64277, 65536};

/* sin and cos of k * 11.25 degrees, Q16.16. */
static int32_t sin32(int k)
{
    int q, r;

    k &= 31;
    q = k / 8;
    r = k % 8;
    switch (q) {
    case 0:
        return sin_table[r];
    case 1:
        return sin_table[8 - r];
    case 2:
        return -sin_table[r];
    default:
        return -sin_table[8 - r];
    }
}

static int32_t cos32(int k)
{
    return sin32(k + 8);
}

/* v / 2^s rounded to nearest, halves away from zero. */
static int32_t shift_round(int64_t v, int s)
{
    int64_t half = (int64_t)1 << (s - 1);

    if (v >= 0)
        return (int32_t)((v + half) >> s);
    return (int32_t)-((-v + half) >> s);
}

static zs_mesh mesh_empty(void)
{
    zs_mesh m;

    m.positions = NULL;
    m.indices = NULL;
    m.face_colors = NULL;
    m.vertex_colors = NULL;
    m.face_normals = NULL;
    m.vertex_normals = NULL;
    m.scale = UNIT_SCALE;
    m.vertex_count = 0;
    m.triangle_count = 0;
    m.color = ZS_RGB(200, 200, 200);
    return m;
}

/* ---- cube: corners +-1 (the mesh scale sets the half size) --------------- */

/* Corner i has x = bit 0, y = bit 1, z = bit 2 (set = +1). */
static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1,
    -1, -1, 1,  1, -1, 1,  -1, 1, 1,  1, 1, 1,
};
/* Counter-clockwise seen from outside: +x, -x, +y, -y, +z, -z. */
static const uint16_t cube_idx[12 * 3] = {
    1, 3, 7, 1, 7, 5, /* +x */
    0, 6, 2, 0, 4, 6, /* -x */
    2, 6, 7, 2, 7, 3, /* +y */
    0, 1, 5, 0, 5, 4, /* -y */
    4, 5, 7, 4, 7, 6, /* +z */
    0, 3, 1, 0, 2, 3, /* -z */
};
static const zs_color cube_colors[DEMO_CUBES][12] = {
    {ZS_RGB(66, 135, 245), ZS_RGB(66, 135, 245), ZS_RGB(40, 100, 210), ZS_RGB(40, 100, 210),
     ZS_RGB(120, 170, 255), ZS_RGB(120, 170, 255), ZS_RGB(30, 70, 160), ZS_RGB(30, 70, 160),
     ZS_RGB(80, 150, 250), ZS_RGB(80, 150, 250), ZS_RGB(55, 115, 225), ZS_RGB(55, 115, 225)},
    {ZS_RGB(70, 200, 110), ZS_RGB(70, 200, 110), ZS_RGB(50, 170, 90), ZS_RGB(50, 170, 90),
     ZS_RGB(120, 230, 150), ZS_RGB(120, 230, 150), ZS_RGB(40, 130, 70), ZS_RGB(40, 130, 70),
     ZS_RGB(90, 215, 125), ZS_RGB(90, 215, 125), ZS_RGB(60, 185, 100), ZS_RGB(60, 185, 100)},
    {ZS_RGB(235, 210, 60), ZS_RGB(235, 210, 60), ZS_RGB(210, 180, 40), ZS_RGB(210, 180, 40),
     ZS_RGB(250, 235, 120), ZS_RGB(250, 235, 120), ZS_RGB(170, 140, 30), ZS_RGB(170, 140, 30),
     ZS_RGB(240, 220, 80), ZS_RGB(240, 220, 80), ZS_RGB(220, 195, 50), ZS_RGB(220, 195, 50)},
};

/* ---- pyramid: base +-2 at y = 0, apex at y = 3 (scale 1/4) -------------- */

static const int16_t pyramid_pos[5 * 3] = {
    -2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2, 0, 3, 0,
};
static const uint16_t pyramid_idx[6 * 3] = {
    3, 2, 4, /* +z side */
    2, 1, 4, /* +x side */
    1, 0, 4, /* -z side */
    0, 3, 4, /* -x side */
    0, 1, 2, 0, 2, 3, /* base, facing down */
};
static const zs_color pyramid_colors[6] = {
    ZS_RGB(220, 70, 160), ZS_RGB(200, 60, 140), ZS_RGB(180, 50, 130),
    ZS_RGB(235, 90, 175), ZS_RGB(120, 40, 90), ZS_RGB(120, 40, 90),
};

/* Placement: rotate about x, then y, then z (degrees), then translate (1/4096 units). */
static zs_mat34 place(int rx, int ry, int rz, int32_t tx, int32_t ty, int32_t tz)
{
    zs_mat34 a = zs_mat34_rotate_x(ZS_FX(rx));
    zs_mat34 b = zs_mat34_rotate_y(ZS_FX(ry));
    zs_mat34 c = zs_mat34_rotate_z(ZS_FX(rz));
    zs_mat34 t = zs_mat34_translate(tx * UNIT_SCALE, ty * UNIT_SCALE, tz * UNIT_SCALE);
    zs_mat34 m = zs_mat34_mul(&b, &a);

    m = zs_mat34_mul(&c, &m);
    return zs_mat34_mul(&t, &m);
}

static void build_torus(demo_scene *s)
{
    /* Ring radius 0.875, tube radius 0.3125 (exact in 1/4096 units). */
    const int64_t ring = 3584, tube = 1280;
    int u, v, n = 0;
    size_t k = 0;

    for (u = 0; u < DEMO_TORUS_U; u++) {
        int ku = u * (32 / DEMO_TORUS_U);
        int64_t cu = cos32(ku), su = sin32(ku);
        for (v = 0; v < DEMO_TORUS_V; v++) {
            int kv = v * (32 / DEMO_TORUS_V);
            int64_t cv = cos32(kv), sv = sin32(kv);
            int64_t a = ring * 65536 + tube * cv; /* distance from the axis, Q16 */
            s->torus_pos[3 * n + 0] = (int16_t)shift_round(a * cu, 32);
            s->torus_pos[3 * n + 1] = (int16_t)shift_round(tube * sv, 16);
            s->torus_pos[3 * n + 2] = (int16_t)shift_round(a * su, 32);
            s->torus_nrm[3 * n + 0] = (int16_t)shift_round(cv * cu, 18);
            s->torus_nrm[3 * n + 1] = (int16_t)shift_round(sv, 2);
            s->torus_nrm[3 * n + 2] = (int16_t)shift_round(cv * su, 18);
            n++;
        }
    }
    for (u = 0; u < DEMO_TORUS_U; u++) {
        int u1 = (u + 1) % DEMO_TORUS_U;
        for (v = 0; v < DEMO_TORUS_V; v++) {
            int v1 = (v + 1) % DEMO_TORUS_V;
            uint16_t p00 = (uint16_t)(u * DEMO_TORUS_V + v);
            uint16_t p10 = (uint16_t)(u1 * DEMO_TORUS_V + v);
            uint16_t p01 = (uint16_t)(u * DEMO_TORUS_V + v1);
            uint16_t p11 = (uint16_t)(u1 * DEMO_TORUS_V + v1);
            /* d/du x d/dv points inward, so (p00, p01, p11) is counter-clockwise outside. */
            s->torus_idx[k++] = p00;
            s->torus_idx[k++] = p01;
            s->torus_idx[k++] = p11;
            s->torus_idx[k++] = p00;
            s->torus_idx[k++] = p11;
            s->torus_idx[k++] = p10;
        }
    }
    s->torus = mesh_empty();
    s->torus.positions = s->torus_pos;
    s->torus.vertex_normals = s->torus_nrm;
    s->torus.indices = s->torus_idx;
    s->torus.vertex_count = (uint16_t)DEMO_TORUS_VERTS;
    s->torus.triangle_count = (uint16_t)DEMO_TORUS_TRIS;
    s->torus.color = ZS_RGB(235, 130, 45);
}

static void build_ground(demo_scene *s)
{
    /* y = 0, x and z in [-3, 3]. */
    const int32_t half = 3 * UNIT, step = (2 * half) / DEMO_GROUND_N;
    int i, j, n = 0;
    size_t k = 0, f = 0;

    for (j = 0; j <= DEMO_GROUND_N; j++) {
        for (i = 0; i <= DEMO_GROUND_N; i++) {
            s->ground_pos[3 * n + 0] = (int16_t)(-half + i * step);
            s->ground_pos[3 * n + 1] = 0;
            s->ground_pos[3 * n + 2] = (int16_t)(-half + j * step);
            n++;
        }
    }
    for (j = 0; j < DEMO_GROUND_N; j++) {
        for (i = 0; i < DEMO_GROUND_N; i++) {
            uint16_t a = (uint16_t)(j * (DEMO_GROUND_N + 1) + i);
            uint16_t b = (uint16_t)(a + 1);
            uint16_t c = (uint16_t)(a + DEMO_GROUND_N + 1);
            uint16_t d = (uint16_t)(c + 1);
            zs_color col = ((i + j) & 1) ? ZS_RGB(70, 78, 96) : ZS_RGB(196, 198, 190);
            /* Counter-clockwise seen from above (+y). */
            s->ground_idx[k++] = a;
            s->ground_idx[k++] = c;
            s->ground_idx[k++] = b;
            s->ground_idx[k++] = b;
            s->ground_idx[k++] = c;
            s->ground_idx[k++] = d;
            s->ground_col[f++] = col;
            s->ground_col[f++] = col;
        }
    }
    s->ground = mesh_empty();
    s->ground.positions = s->ground_pos;
    s->ground.indices = s->ground_idx;
    s->ground.face_colors = s->ground_col;
    s->ground.vertex_count = (uint16_t)DEMO_GROUND_VERTS;
    s->ground.triangle_count = (uint16_t)DEMO_GROUND_TRIS;
}

void demo_scene_init(demo_scene *s)
{
    /* Half sizes of the cubes, in 1/4096 units (mesh scale = half size). */
    static const int32_t cube_half[DEMO_CUBES] = {1638, 1229, 1147}; /* 0.4, 0.3, 0.28 */
    int c;

    build_torus(s);
    build_ground(s);
    for (c = 0; c < DEMO_CUBES; c++) {
        s->cubes[c] = mesh_empty();
        s->cubes[c].positions = cube_pos;
        s->cubes[c].indices = cube_idx;
        s->cubes[c].face_colors = cube_colors[c];
        s->cubes[c].vertex_count = 8;
        s->cubes[c].triangle_count = 12;
        s->cubes[c].scale = cube_half[c] * UNIT_SCALE;
    }
    s->pyramid = mesh_empty();
    s->pyramid.positions = pyramid_pos;
    s->pyramid.indices = pyramid_idx;
    s->pyramid.face_colors = pyramid_colors;
    s->pyramid.vertex_count = 5;
    s->pyramid.triangle_count = 6;
    s->pyramid.scale = ZS_FX_RATIO(1, 4) + ZS_FX_RATIO(1, 16); /* 0.3125: base +-0.625 */

    /* The torus stands tilted, its lower part under the ground. */
    s->torus_model = place(70, 25, 0, 0, 1434, 0);               /* centre y = 0.35 */
    /* Two cubes cutting into each other, the first sunk into the ground. */
    s->cube_model[0] = place(0, 30, 0, 6144, 1229, 2867);        /* (1.5, 0.3, 0.7) */
    s->cube_model[1] = place(40, 0, 35, 7168, 2662, 1843);       /* (1.75, 0.65, 0.45) */
    /* A small cube the torus tube passes through. */
    s->cube_model[2] = place(25, 35, 10, -3277, 2048, 2253);     /* (-0.8, 0.5, 0.55) */
    s->pyramid_model = place(0, 20, 0, -6554, -410, -4096);      /* (-1.6, -0.1, -1.0) */
}

zs_status demo_camera(zs_camera *cam, uint32_t frame)
{
    zs_vec3 eye = zs_vec3_make(ZS_FX_RATIO(9, 10), ZS_FX_RATIO(26, 10), ZS_FX_RATIO(55, 10));
    zs_vec3 target = zs_vec3_make(ZS_FX_RATIO(2, 10), ZS_FX_RATIO(2, 10), 0);
    zs_vec3 up = zs_vec3_make(0, ZS_FX(1), 0);
    zs_status st;

    if (frame != 0) {
        zs_mat34 orbit = zs_mat34_rotate_y((zs_fixed)((frame % 120u) * 3u) * ZS_FX_ONE);
        eye = zs_mat34_apply(&orbit, eye);
    }
    st = zs_camera_look_at(cam, eye, target, up);
    if (st != ZS_OK)
        return st;
    return zs_camera_perspective(cam, ZS_FX(45), ZS_FX_RATIO(1, 10), ZS_FX(20));
}

zs_shade_params demo_shading(zs_shading shading, zs_format format)
{
    zs_shade_params p = zs_shade_default();

    p.shading = shading;
    p.format = format;
    p.background = ZS_RGB(22, 26, 38);
    p.ambient = ZS_FX_RATIO(22, 100);
    p.light_count = 2;
    p.lights[0].direction = zs_vec3_make(-ZS_FX_RATIO(6, 10), ZS_FX(1), ZS_FX_RATIO(7, 10));
    p.lights[0].intensity = ZS_FX_RATIO(75, 100);
    p.lights[1].direction = zs_vec3_make(ZS_FX_RATIO(8, 10), ZS_FX_RATIO(3, 10),
                                         -ZS_FX_RATIO(5, 10));
    p.lights[1].intensity = ZS_FX_RATIO(25, 100);
    p.fog.enabled = 1;
    p.fog.color = p.background;
    p.fog.start = ZS_FX(5);
    p.fog.end = ZS_FX(11);
    return p;
}

zs_status demo_scene_draw(zs_renderer *r, const demo_scene *s)
{
    zs_status st;
    int c;

    st = zs_draw(r, &s->ground, NULL);
    if (st != ZS_OK)
        return st;
    st = zs_draw(r, &s->torus, &s->torus_model);
    if (st != ZS_OK)
        return st;
    for (c = 0; c < DEMO_CUBES; c++) {
        st = zs_draw(r, &s->cubes[c], &s->cube_model[c]);
        if (st != ZS_OK)
            return st;
    }
    return zs_draw(r, &s->pyramid, &s->pyramid_model);
}

zs_status demo_frame(zs_renderer *r, const demo_scene *s, uint32_t frame, zs_visibility mode,
                     zs_shading shading, zs_format format)
{
    return demo_frame_mono(r, s, frame, mode, shading, format, 0);
}

zs_status demo_frame_mono(zs_renderer *r, const demo_scene *s, uint32_t frame,
                          zs_visibility mode, zs_shading shading, zs_format format, unsigned mono)
{
    zs_camera cam;
    zs_shade_params p;
    zs_status st;

    st = demo_camera(&cam, frame);
    if (st != ZS_OK)
        return st;
    st = zs_frame_begin(r, &cam, mode);
    if (st != ZS_OK)
        return st;
    p = demo_shading(shading, format);
    p.mono = (uint8_t)mono;
    st = zs_frame_shading(r, &p);
    if (st != ZS_OK)
        return st;
    return demo_scene_draw(r, s);
}
