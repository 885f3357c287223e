/* SPDX-License-Identifier: MIT */
/* Generous pool capacities, used only by the host run that measures the
 * real ones (build/bench/bench_caps writes build/bench/gen/bench_caps.h). */
#ifndef ZSPAN_BENCH_CAPS_H
#define ZSPAN_BENCH_CAPS_H
#define BENCH_CAPS_GENEROUS 1
#define BENCH_CAPS_SPHERE285 16000, 16000, 4096
#define BENCH_CAPS_CUBES 16000, 16000, 4096
#define BENCH_CAPS_WUSON 16000, 16000, 4096
#define BENCH_CAPS_CLUSTER 16000, 16000, 4096
#endif
