/* SPDX-License-Identifier: MIT */
/* Renders a Gouraud, fogged cube in every colour format and prints a hash of
 * the pixels. Built twice, against the core compiled for speed (-O2) and for
 * size (-Os, which takes other code paths in shade.c): the hashes must match. */
#include <stdio.h>
#include <string.h>
#include "zspan/zspan.h"
static const int16_t P[] = {-1,-1,-1, 1,-1,-1, 1,1,-1, -1,1,-1, -1,-1,1, 1,-1,1, 1,1,1, -1,1,1};
static const uint16_t I[] = {0,2,1, 0,3,2, 4,5,6, 4,6,7, 0,1,5, 0,5,4, 3,7,6, 3,6,2, 0,4,7, 0,7,3, 1,2,6, 1,6,5};
static const zs_color VC[] = {0xff0000,0x00ff00,0x0000ff,0xffff00,0xff00ff,0x00ffff,0x808080,0xffffff};
static uint8_t arena[ZS_ARENA_BYTES(96,96,100,100,64)];
int main(void){ unsigned h = 2166136261u;
 for (int fmt = 0; fmt < 5; fmt++) {
  zs_renderer r; zs_config cfg = zs_config_default(96,96,100,100,64); zs_init(&r, arena, sizeof arena, &cfg);
  zs_camera cam; memset(&cam,0,sizeof cam);
  zs_camera_look_at(&cam, zs_vec3_make(ZS_FX(2),ZS_FX(2),ZS_FX(4)), zs_vec3_make(0,0,0), zs_vec3_make(0,ZS_FX(1),0));
  zs_camera_perspective(&cam, ZS_FX(50), ZS_FX(1)/4, ZS_FX(50));
  zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
  zs_shade_params sp = zs_shade_default(); sp.format = (zs_format)fmt; sp.shading = ZS_SHADE_GOURAUD;
  sp.fog.enabled = 1; sp.fog.start = ZS_FX(3); sp.fog.end = ZS_FX(7); sp.fog.color = 0x204060;
  zs_frame_shading(&r, &sp);
  zs_mesh m; memset(&m,0,sizeof m); m.positions=P; m.indices=I; m.vertex_colors=VC; m.scale=ZS_FX(1); m.vertex_count=8; m.triangle_count=12;
  zs_draw(&r, &m, 0);
  static uint8_t img[96*96*3]; zs_render_rows(&r, 0, 96, img, 96*3);
  for (int i = 0; i < 96*96*3; i++) { h ^= img[i]; h *= 16777619u; }
 }
 printf("%08x\n", h); return 0; }
