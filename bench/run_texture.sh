#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The textured scene's cost (make bench, after bench-firmware): runs the
# benchmark images' quick mode on QEMU mps2-an386 (Cortex-M4, -O2) and
# microbit (Cortex-M0, -Os), where bench_fw renders the six frames of
# bench_tex_frame, and the host for the covered pixel count; writes the
# section "Textured scene" of BENCH_OUT (replacing an earlier one).
#
# Environment (mk/texture.mk): BENCH_HOST, FW_M4, FW_M0, FW_QEMU,
# FW_QEMU_FLAGS, ARM_SIZE, CORE_M0_OBJS, CORE_M4_OBJS, BENCH_OUT, BENCH_WORK.
set -u
set -o pipefail
: "${BENCH_HOST:?}" "${FW_M4:?}" "${FW_M0:?}" "${BENCH_OUT:?}"
WORK=${BENCH_WORK:-build/bench/texture}
mkdir -p "$WORK"
"$BENCH_HOST" run --scene sphere285 --frames 1 --mono > "$WORK/host.txt" || exit 1
timeout 120 $FW_QEMU -M mps2-an386 $FW_QEMU_FLAGS,arg=bench,arg=quick -kernel "$FW_M4" \
    > "$WORK/m4.txt" 2>&1 || exit 1
timeout 120 $FW_QEMU -M microbit $FW_QEMU_FLAGS,arg=bench,arg=quick -kernel "$FW_M0" \
    > "$WORK/m0.txt" 2>&1 || exit 1

field() { # file board variant key
    sed -n "s/^R $2 textured $3 0 .*$4=\([0-9a-f]*\).*/\1/p" "$1" | head -1
}
covered=$(field "$WORK/host.txt" host tex-plain covered)
[ -n "$covered" ] && [ "$covered" -gt 0 ] || { echo "run_texture: no covered count" >&2; exit 1; }
size_of() { # objects... -> text bytes of texture.o
    for o in "$@"; do case "$o" in *texture.o) $ARM_SIZE "$o" | awk 'NR==2 {print $1}';; esac; done
}

{
    echo "## Textured scene"
    echo
    echo "bench_tex_frame (bench/bench_scenes.h): a ground trapezoid from 1.2 to 30 units ahead"
    echo "with its texture repeated and a textured cube, 240x240 RGB565, span mode unless named;"
    echo "$covered of the 57600 pixels are covered (host count). Instructions per frame (QEMU"
    echo "-icount shift=0, SysTick), and per textured pixel: (frame - tex-plain) / $covered."
    echo "Checksums equal on host, M4 and M0 (tests/firmware checks them in make test)."
    echo
    echo "| variant | what | M4 instructions | M4 per textured pixel | M0 instructions | M0 per textured pixel | checksum |"
    echo "| ------- | ---- | --------------: | --------------------: | --------------: | --------------------: | -------- |"
    p4=$(field "$WORK/m4.txt" mps2-an386 tex-plain instr)
    p0=$(field "$WORK/m0.txt" microbit tex-plain instr)
    while read -r v what; do
        i4=$(field "$WORK/m4.txt" mps2-an386 "$v" instr)
        i0=$(field "$WORK/m0.txt" microbit "$v" instr)
        sh=$(field "$WORK/host.txt" host "$v" sum)
        s4=$(field "$WORK/m4.txt" mps2-an386 "$v" sum)
        s0=$(field "$WORK/m0.txt" microbit "$v" sum)
        if [ "$sh" != "$s4" ] || [ "$sh" != "$s0" ]; then
            echo "run_texture: $v checksums differ: host $sh M4 $s4 M0 $s0" >&2; exit 1
        fi
        if [ "$v" = tex-plain ]; then
            q4="-"; q0="-"
        else
            q4=$(awk -v a="$i4" -v b="$p4" -v n="$covered" 'BEGIN {printf "%.1f", (a - b) / n}')
            q0=$(awk -v a="$i0" -v b="$p0" -v n="$covered" 'BEGIN {printf "%.1f", (a - b) / n}')
        fi
        echo "| $v | $what | $i4 | $q4 | $i0 | $q0 | $sh |"
    done <<'EOF'
tex-plain untextured, flat colours (the baseline)
tex-nearest 64x64 RGB565, nearest, exact, unlit
tex-nearest-zline the same in z-buffer mode (same bytes)
tex-subdiv the same subdivided (exact every 16 columns)
tex-bilinear bilinear, exact, flat lit
tex-lit-fog 32x32 palette, bilinear, subdivided, clamped, Gouraud lit, vertex colours, fog
EOF
    echo
    echo "Flash: the 64x64 RGB565 texture 8192 B, the 32x32 palette texture 1024 B + 512 B of"
    echo "palette; src/texture.c $(size_of ${CORE_M4_OBJS:-}) B of code on Cortex-M4 (-O2),"
    echo "$(size_of ${CORE_M0_OBJS:-}) B on Cortex-M0 (-Os)."
    echo
} > "$WORK/section.md" || exit 1

# replace an earlier section (up to the next "## " heading), else append
awk -v sec="$WORK/section.md" '
    /^## Textured scene$/ { skip = 1; while ((getline l < sec) > 0) print l; done = 1; next }
    skip && /^## / { skip = 0 }
    !skip { print }
    END { if (!done) while ((getline l < sec) > 0) print l }
' "$BENCH_OUT" > "$WORK/out.md" && mv "$WORK/out.md" "$BENCH_OUT"
echo "run_texture: wrote the textured scene section of $BENCH_OUT"
