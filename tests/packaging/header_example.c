/* SPDX-License-Identifier: MIT */
/*
 * The harness of the header's usage example (make check-header-example): the
 * example (cut out of include/zspan/zspan.h) renders its frame and hands each
 * row to send_row here. Checked: every row 0..239 once, in order, 480 bytes;
 * every pixel the background (0) or the mesh colour ZS_RGB(255, 160, 0) in
 * RGB565 big-endian (0xFD00); the covered area that of the triangle as the
 * camera sees it: a 2 x 2 unit triangle at distance 3 under a 60 degree
 * vertical field of view on 240 rows is 2 * 120 / (3 tan 30) = 138.56 px
 * wide and high, 9,600 px^2; apex up.
 */
#include <stdio.h>

#include "zspan/zspan.h"

zs_status draw_frame(void);
void send_row(int y, const uint8_t *row, size_t bytes);

static int next_row, bad, first = -1, last = -1, w_first, w_last;
static long covered;

void send_row(int y, const uint8_t *row, size_t bytes)
{
    size_t i;
    int w = 0;
    if (y != next_row++ || bytes != 240 * 2) {
        fprintf(stderr, "header example: row %d (%zu bytes), expected row %d\n", y, bytes,
                next_row - 1);
        bad++;
        return;
    }
    for (i = 0; i + 1 < bytes; i += 2) {
        unsigned v = (unsigned)row[i] << 8 | row[i + 1];
        if (v == 0xFD00u)
            w++;
        else if (v != 0)
            bad++;
    }
    if (w > 0) {
        if (first < 0) {
            first = y;
            w_first = w;
        }
        last = y;
        w_last = w;
    }
    covered += w;
}

int main(void)
{
    zs_status st = draw_frame();
    if (st != ZS_OK || bad || next_row != 240 || covered < 9400 || covered > 9800 ||
        w_first >= w_last || last - first < 134 || last - first > 140) {
        fprintf(stderr,
                "check-header-example: FAIL: %s, %d rows, %d bad, %ld px covered (9,600), "
                "rows %d..%d, widths %d..%d\n",
                zs_strerror(st), next_row, bad, covered, first, last, w_first, w_last);
        return 1;
    }
    printf("check-header-example: the header's example renders: %ld px covered (9,600 "
           "expected), rows %d..%d\n", covered, first, last);
    return 0;
}
