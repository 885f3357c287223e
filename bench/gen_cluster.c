/* SPDX-License-Identifier: MIT */
/* Writes the "cluster" benchmark scene as a Wavefront OBJ on stdout: 40
 * long octahedra ("spikes": half-length 0.45..0.9 along a random axis,
 * half-width 0.08..0.2) with centres within 0.55 of the origin, so that
 * they pierce one another everywhere: a scene for depth work (many active
 * edges per row, penetrations split inside spans), unlike the other
 * scenes. 6 vertices and 8 outward counter-clockwise triangles each (320 in
 * all). A fixed linear congruential generator makes it the same everywhere.
 * The converter turns it into C like the other scenes. */
#include <math.h>
#include <stdio.h>

static unsigned long state = 12345u;

/* Uniform in [lo, hi) from the top bits of a 32-bit LCG. */
static double uniform(double lo, double hi)
{
    state = (state * 1103515245u + 12345u) & 0xFFFFFFFFu;
    return lo + (hi - lo) * (double)(state >> 8) / 16777216.0;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
}

int main(void)
{
    /* octahedron corners: 0 +u, 1 -u, 2 +v, 3 -v, 4 +w, 5 -w; faces wound
     * counter-clockwise seen from outside for a right-handed (u, v, w) */
    static const int faces[8][3] = {
        {0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5},
    };
    int n, k, base = 1;
    printf("# zspan benchmark scene: 40 interpenetrating spikes\n");
    for (n = 0; n < 40; n++) {
        double c[3], u[3], v[3], w[3], t[3] = {0.0, 0.0, 1.0}, len, wid;
        double r = 0.55 * cbrt(uniform(0.0, 1.0));
        double ct = uniform(-1.0, 1.0), ph = uniform(0.0, 6.283185307179586);
        double st = sqrt(1.0 - ct * ct);
        c[0] = r * st * cos(ph);
        c[1] = r * st * sin(ph);
        c[2] = r * ct;
        ct = uniform(-1.0, 1.0);
        ph = uniform(0.0, 6.283185307179586);
        st = sqrt(1.0 - ct * ct);
        u[0] = st * cos(ph);
        u[1] = st * sin(ph);
        u[2] = ct;
        if (fabs(u[2]) > 0.9) {
            t[0] = 1.0;
            t[2] = 0.0;
        }
        cross(u, t, v);
        normalize(v);
        cross(u, v, w);
        len = uniform(0.45, 0.9);
        wid = uniform(0.08, 0.2);
        printf("o spike_%d\n", n);
        for (k = 0; k < 6; k++) {
            const double *axis = k < 2 ? u : k < 4 ? v : w;
            double s = (k & 1 ? -1.0 : 1.0) * (k < 2 ? len : wid);
            printf("v %.6f %.6f %.6f\n", c[0] + s * axis[0], c[1] + s * axis[1],
                   c[2] + s * axis[2]);
        }
        for (k = 0; k < 8; k++)
            printf("f %d %d %d\n", base + faces[k][0], base + faces[k][1], base + faces[k][2]);
        base += 6;
    }
    return 0;
}
