/* SPDX-License-Identifier: MIT */
/* Writes the "cubes" benchmark scene as a Wavefront OBJ on stdout: 64 unit
 * cubes (edge 1) on a 4x4x4 grid with centres 1.5 apart (extent +-2.75),
 * 8 vertices and 12 outward counter-clockwise triangles each (768 in all).
 * The converter turns it into C like the other scenes. */
#include <stdio.h>

int main(void)
{
    /* Corner k: bit 0 = +x, bit 1 = +y, bit 2 = +z. */
    static const int quads[6][4] = {
        {0, 2, 3, 1}, /* -z: seen from -z, counter-clockwise */
        {4, 5, 7, 6}, /* +z */
        {0, 4, 6, 2}, /* -x */
        {1, 3, 7, 5}, /* +x */
        {0, 1, 5, 4}, /* -y */
        {2, 6, 7, 3}, /* +y */
    };
    int cx, cy, cz, k, q, base = 1;
    printf("# zspan benchmark scene: 64 unit cubes, 4x4x4, centres 1.5 apart\n");
    for (cz = 0; cz < 4; cz++)
        for (cy = 0; cy < 4; cy++)
            for (cx = 0; cx < 4; cx++) {
                double c[3];
                c[0] = -2.25 + 1.5 * cx;
                c[1] = -2.25 + 1.5 * cy;
                c[2] = -2.25 + 1.5 * cz;
                printf("o cube_%d_%d_%d\n", cx, cy, cz);
                for (k = 0; k < 8; k++)
                    printf("v %g %g %g\n", c[0] + ((k & 1) ? 0.5 : -0.5),
                           c[1] + ((k & 2) ? 0.5 : -0.5), c[2] + ((k & 4) ? 0.5 : -0.5));
                for (q = 0; q < 6; q++) {
                    printf("f %d %d %d\n", base + quads[q][0], base + quads[q][1],
                           base + quads[q][2]);
                    printf("f %d %d %d\n", base + quads[q][0], base + quads[q][2],
                           base + quads[q][3]);
                }
                base += 8;
            }
    return 0;
}
