#!/bin/bash
# SPDX-License-Identifier: MIT
# make bench-raycast: host instructions (callgrind, sim_raycast only) of
# zspan-sim render --mode raycast on scenes of 4,000 and 40,000 triangles
# (spheres of 400 triangles written here), with its grid of 8 x 8 pixel
# cells and without (--grid 0), at 240x240 and 120x120 (the grid-less
# 40,000 triangle frame at 240x240 takes long under callgrind: 120x120 is
# its stand-in, costs per pixel being the same).
#   bench/run_raycast.sh SIM WORKDIR OUT.md
set -u
sim=$1 work=$2 out=$3
mkdir -p "$work"
spheres() { # n seed file
    awk -v n="$1" -v seed="$2" 'BEGIN { srand(seed); S = 20; R = 11; pi = 3.14159265358979; v = 0
      for (k = 0; k < n; k++) { cx = rand() * 4 - 2; cy = rand() * 4 - 2; cz = rand() * 4 - 2
        rad = 0.25 + rand() * 0.35; base = v
        for (i = 0; i <= R; i++) for (j = 0; j < S; j++) { th = pi * i / R; ph = 2 * pi * j / S
          printf "v %.5f %.5f %.5f\n", cx + rad * sin(th) * cos(ph), cy + rad * cos(th), cz - rad * sin(th) * sin(ph); v++ }
        for (i = 0; i < R; i++) for (j = 0; j < S; j++) { a = base + i * S + j + 1; b = base + i * S + (j + 1) % S + 1
          c = a + S; d = b + S; if (i > 0) printf "f %d %d %d\n", a, b, c; if (i < R - 1) printf "f %d %d %d\n", b, d, c } } }' > "$3"
}
spheres 10 4 "$work/s4k.obj"
spheres 100 40 "$work/s40k.obj"
{
echo "# Ray caster host cost (\`make bench-raycast\`)"
echo
echo "x86-64 instructions under callgrind counting sim_raycast only (binning and casting,"
echo "not the core's frame), $(cc --version | head -1). Scenes: 10 and 100 spheres of"
echo "400 triangles in a cube, --fit, eye at distance 2.2. tests: ray-triangle tests made."
echo
echo "| scene | size | grid | records | instructions | tests | instructions per pixel |"
echo "| ----- | ---- | ---- | ------: | -----------: | ----: | ---------------------: |"
for s in s4k s40k; do for size in 240x240 120x120; do for grid in 8 0; do
    [ "$s$size$grid" = "s40k240x2400" ] && continue
    f="$work/cg.$s.$size.$grid"
    valgrind --tool=callgrind --callgrind-out-file="$f" --collect-atstart=no \
        --toggle-collect=sim_raycast "$sim" render "$work/$s.obj" --fit --eye 0,0,2.2 \
        --size "$size" --mode raycast --shade ids --grid "$grid" --out "$work/$s.png" \
        > "$f.txt" 2> "$f.log" || { echo "callgrind failed: $f.log" >&2; exit 1; }
    ins=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p; s/^totals: *\([0-9]*\).*/\1/p' "$f" | head -1)
    recs=$(sed -n 's/^raycast: \([0-9]*\) records.*/\1/p' "$f.txt")
    tests=$(sed -n 's/.*px, \([0-9]*\) ray-record tests.*/\1/p' "$f.txt")
    px=$(( ${size%x*} * ${size#*x} ))
    echo "| $s | $size | $([ "$grid" = 0 ] && echo none || echo "${grid}x$grid") | $recs | $ins | $tests | $(( ins / px )) |"
done; done; done
} > "$out"
cat "$out"
