#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The scaling benchmark (bench/bench_scale.c): statistics, callgrind counts
# and the Markdown section "How cost grows".
#
# Environment:
#   BENCH_SCALE   the bench_scale program (required)
#   SCALE_WORK    scratch directory (build/bench/scale)
#   SCALE_OUT     the Markdown section (SCALE_WORK/scale.md)
#   SCALE_FRAMES  frames per case and mode (10)
#   SCALE_QUICK   1: only the short set of cases (make test)
#   FW_FILES      the firmware bench's outputs (R lines with instr=), for the
#                 frames-per-second estimates; optional
#
# Host instructions are counted with callgrind over zs_frame_begin, zs_draw
# and zs_render_rows only (--toggle-collect), as bench/run_bench.sh does;
# the program's own set-up (mesh generation, arena) is not counted.

set -u
set -o pipefail

: "${BENCH_SCALE:?}"
WORK=${SCALE_WORK:-build/bench/scale}
OUT=${SCALE_OUT:-$WORK/scale.md}
FRAMES=${SCALE_FRAMES:-10}
QUICK=${SCALE_QUICK:-0}
note() { echo "bench-scale: $*" >&2; }

mkdir -p "$WORK"
rm -f "$WORK"/stats.txt "$WORK"/cg.txt "$WORK"/callgrind.*
fail=0
quick_flag=
[ "$QUICK" = 1 ] && quick_flag=--quick

note "statistics and edge counts ($FRAMES frames per case and mode)"
if ! "$BENCH_SCALE" stats $quick_flag --frames "$FRAMES" > "$WORK/stats.txt"; then
    note "a check of the statistics run failed (see above)"; fail=1
fi
if ! command -v valgrind > /dev/null 2>&1; then
    note "valgrind not installed: no instruction counts"; exit 1
fi

: > "$WORK/cg.txt"
while read -r tag name mode rest; do
    [ "$tag" = ST ] || continue
    caps=$(sed -n 's/.* caps=\([0-9,]*\).*/\1/p' <<< "$rest")
    out="$WORK/callgrind.$name.$mode"
    if valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
           --toggle-collect=zs_frame_begin --toggle-collect=zs_draw \
           --toggle-collect=zs_render_rows \
           "$BENCH_SCALE" run "$name" "$mode" --caps "$caps" --frames "$FRAMES" \
           > /dev/null 2> "$out.log"; then
        total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p; s/^totals: *\([0-9]*\).*/\1/p' \
                "$out" | head -1)
        echo "CG $name $mode ${total:-0}" >> "$WORK/cg.txt"
        note "$name $mode: $(( ${total:-0} / FRAMES )) instructions per frame"
    else
        note "callgrind failed for $name $mode (see $out.log)"; fail=1
    fi
done < "$WORK/stats.txt"

fw_args=()
for f in ${FW_FILES:-}; do
    [ -f "$f" ] && fw_args+=(--fw "$f")
done
if ! "$BENCH_SCALE" report --stats "$WORK/stats.txt" --cg "$WORK/cg.txt" "${fw_args[@]}" \
       > "$OUT"; then
    note "the report could not fit the model (see above)"; fail=1
fi
exit $fail
