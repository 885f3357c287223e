/* SPDX-License-Identifier: MIT */
/*
 * test_readme: the usage example of README.md ("Using the library"),
 * extracted from the README by the build (mk/cli.mk), compiled with the
 * strict flags of the core and run here: it must initialise, render frames
 * without an error, fill the panel row by row exactly once per row, and
 * show a shaded cube: the background around it, and at least two faces in
 * different shades of its one colour (not a silhouette).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "zspan/zspan.h"

#define W 240
#define H 240

zs_status cube_init(void);
zs_status cube_frame(zs_fixed degrees);
void panel_write_row(int y, const uint8_t *pixels, size_t bytes);

static uint8_t g_image[H][W * 2];
static int g_rows[H];

void panel_write_row(int y, const uint8_t *pixels, size_t bytes)
{
    if (y < 0 || y >= H || bytes != sizeof g_image[0])
        fail_msg("panel_write_row(%d, %lu bytes)", y, (unsigned long)bytes);
    memcpy(g_image[y], pixels, bytes);
    g_rows[y]++;
}

static unsigned pixel(int x, int y)
{
    return (unsigned)g_image[y][2 * x] << 8 | g_image[y][2 * x + 1];
}

static void test_readme_example(void **state)
{
    const unsigned bg = ((16u >> 3) << 11) | ((24u >> 2) << 5) | (48u >> 3);
    static const zs_fixed angles[] = {0, ZS_FX(30), ZS_FX(200)};
    size_t a;
    (void)state;
    assert_int_equal(cube_init(), ZS_OK);
    for (a = 0; a < sizeof angles / sizeof angles[0]; a++) {
        unsigned shades[8], n_shades = 0, k;
        long cube_px = 0;
        int x, y;
        memset(g_rows, 0, sizeof g_rows);
        assert_int_equal(cube_frame(angles[a]), ZS_OK);
        for (y = 0; y < H; y++)
            assert_int_equal(g_rows[y], 1);
        /* Corners and edges are background; the centre is cube. */
        assert_int_equal(pixel(0, 0), bg);
        assert_int_equal(pixel(W - 1, H - 1), bg);
        assert_int_not_equal(pixel(W / 2, H / 2), bg);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                unsigned p = pixel(x, y);
                if (p == bg)
                    continue;
                cube_px++;
                for (k = 0; k < n_shades && shades[k] != p; k++) {
                }
                if (k == n_shades && n_shades < 8)
                    shades[n_shades++] = p;
            }
        /* A 1-unit cube 3 units away in a 45-degree view: a few thousand pixels. */
        if (cube_px < 2000 || cube_px > 20000)
            fail_msg("frame %lu: %ld cube pixels", (unsigned long)a, cube_px);
        /* Flat shading: one colour per visible face, two or three faces. */
        if (n_shades < 2 || n_shades > 3)
            fail_msg("frame %lu: %u shades (a silhouette is 1)", (unsigned long)a, n_shades);
        /* Every shade is the cube's orange (R > G > B), lit to different levels. */
        for (k = 0; k < n_shades; k++) {
            unsigned r = shades[k] >> 11, g = (shades[k] >> 5) & 63u, b = shades[k] & 31u;
            if (!(2 * r > g && g > 2 * b))
                fail_msg("shade %04x is not the cube's colour", shades[k]);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_readme_example)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
