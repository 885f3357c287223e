#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make test-bench-scale: a short run of the scaling benchmark (the six small
# cases of `bench_scale list --quick`, 2 frames each, both modes, under
# callgrind) into DIR. Checks that the tool runs end to end and that its
# output holds together; no instruction count is compared with a target.
#   - the statistics run's own checks pass (span == z-line images, nothing
#     dropped, the hook's per-row edge sides == the core's max_active_edges);
#   - every case has a positive instruction count in both modes;
#   - both fits are well-posed (the report fails otherwise) and every
#     coefficient, R^2 and condition number is printed as a number;
#   - the edge events never exceed the edge sides (shared edges are counted
#     once), and are positive for every case.
# Usage: BENCH_SCALE=build/bench/bench_scale bash tests/bench/check_scale.sh DIR

set -u
: "${BENCH_SCALE:?}"
dir=${1:?usage: check_scale.sh DIR}
fail=0
bad() { echo "check-scale: FAIL: $*" >&2; fail=1; }

if ! BENCH_SCALE=$BENCH_SCALE SCALE_WORK=$dir SCALE_QUICK=1 SCALE_FRAMES=2 \
        bash bench/run_scale.sh; then
    bad "bench/run_scale.sh failed"
fi

cases=$("$BENCH_SCALE" list --quick)
[ "$(echo "$cases" | wc -l)" -ge 6 ] || bad "fewer than 6 quick cases"
for c in $cases; do
    for m in span zline; do
        n=$(awk -v c="$c" -v m="$m" '$1 == "CG" && $2 == c && $3 == m && $4 > 0' \
            "$dir/cg.txt" | wc -l)
        [ "$n" = 1 ] || bad "$c $m: no instruction count"
        line=$(awk -v c="$c" -v m="$m" '$1 == "ST" && $2 == c && $3 == m' "$dir/stats.txt")
        [ -n "$line" ] || { bad "$c $m: no statistics line"; continue; }
        sides=$(sed -n 's/.* edge_sides=\([0-9]*\).*/\1/p' <<< "$line")
        events=$(sed -n 's/.* edge_events=\([0-9]*\).*/\1/p' <<< "$line")
        if [ -z "$sides" ] || [ -z "$events" ] || [ "$events" -le 0 ] ||
           [ "$events" -gt "$sides" ]; then
            bad "$c $m: edge events '$events' vs sides '$sides'"
        fi
        grep -q 'span_eq_zline=yes' <<< "$line" || bad "$c: span and z-line differ"
    done
done

md=$dir/scale.md
num='-?[0-9]+\.[0-9]+'
for term in "row" "submitted triangle" "drawn triangle" "edge event" "pixel"; do
    grep -Eq "^\| $term \| $num \| $num \| $num \| $num \|$" "$md" ||
        bad "the report has no fitted coefficients per $term"
done
grep -Eq "^\| R\^2 \| $num \| $num \| $num \| $num \|$" "$md" || bad "no R^2 in the report"
grep -Eq "^\| runs, condition number \| 6, $num \| 6, $num \|" "$md" ||
    bad "the fits do not use the 6 runs"
grep -q "Estimates, not measurements" "$md" || bad "the frames-per-second section is missing"

[ $fail = 0 ] && echo "check-scale: ok ($(echo "$cases" | wc -l) cases, report $md)"
exit $fail
