#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs test suites in order and sums their results.
#
#   tests/run_suites.sh ITEM...
#
# ITEM is either
#   - a cmocka test program: run with CMOCKA_MESSAGE_OUTPUT=stdout; its
#     "[  PASSED  ] N test(s)." and "[  FAILED  ] N test(s), listed below:" lines
#     are summed (a program may run several groups). A program that exits
#     non-zero without reporting a failed test (crash, sanitizer abort, group
#     setup error, timeout) counts one extra failure; so does one that prints no
#     cmocka summary at all.
#   - make:TARGET: runs "$MAKE TARGET" (MAKE defaults to make); it counts as one
#     check, passed if it exits 0.
#
# Keeps going after failures. Prints a table of the items, then, as the very
# last line, "N passed, N failed"; exits 1 if anything failed.
#
# Environment: SUITE_TIMEOUT seconds per item (default 1800, 0 = none).

set -u

MAKE_CMD=${MAKE:-make}
TIMEOUT=${SUITE_TIMEOUT:-1800}
export CMOCKA_MESSAGE_OUTPUT=stdout

total_pass=0
total_fail=0
summary=()

logdir=$(mktemp -d "${TMPDIR:-/tmp}/zspan-suites.XXXXXX")
trap 'rm -rf "$logdir"' EXIT

run_with_timeout() {
    if [ "$TIMEOUT" != 0 ] && command -v timeout >/dev/null 2>&1; then
        timeout -k 10 "$TIMEOUT" "$@"
    else
        "$@"
    fi
}

n=0
for item in "$@"; do
    n=$((n + 1))
    log="$logdir/$n.log"
    case "$item" in
    make:*)
        target=${item#make:}
        echo "=== make $target"
        run_with_timeout $MAKE_CMD --no-print-directory "$target" 2>&1 | tee "$log"
        rc=${PIPESTATUS[0]}
        if [ "$rc" -eq 0 ]; then
            total_pass=$((total_pass + 1))
            summary+=("$(printf '%-40s %s' "make $target" "ok")")
        else
            total_fail=$((total_fail + 1))
            summary+=("$(printf '%-40s %s' "make $target" "FAILED (exit $rc)")")
        fi
        ;;
    *)
        echo "=== $item"
        if [ ! -x "$item" ]; then
            echo "run_suites: $item: not an executable" >&2
            total_fail=$((total_fail + 1))
            summary+=("$(printf '%-40s %s' "$item" "FAILED (missing)")")
            continue
        fi
        run_with_timeout "$item" 2>&1 | tee "$log"
        rc=${PIPESTATUS[0]}
        # Sum every group summary the program printed.
        p=$(sed -n 's/^\[  PASSED  \] \([0-9][0-9]*\) test(s)\..*/\1/p' "$log" |
            awk '{s += $1} END {print s + 0}')
        f=$(sed -n 's/^\[  FAILED  \] \([0-9][0-9]*\) test(s), listed below.*/\1/p' "$log" |
            awk '{s += $1} END {print s + 0}')
        s=$(sed -n 's/^\[  SKIPPED \] \([0-9][0-9]*\) test(s), listed below.*/\1/p' "$log" |
            awk '{s += $1} END {print s + 0}')
        seen=$(grep -c '^\[  PASSED  \] [0-9]* test(s)\.' "$log")
        note=""
        if [ "$seen" -eq 0 ]; then
            f=$((f + 1))
            note=" (no cmocka summary, exit $rc)"
        elif [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
            f=$((f + 1))
            note=" (exit $rc without a reported failure)"
        fi
        total_pass=$((total_pass + p))
        total_fail=$((total_fail + f))
        extra=""
        [ "$s" -gt 0 ] && extra=", $s skipped"
        summary+=("$(printf '%-40s %s' "$(basename "$item")" "$p passed, $f failed$extra$note")")
        ;;
    esac
done

echo
echo "=== summary"
for line in "${summary[@]+"${summary[@]}"}"; do
    echo "  $line"
done
echo "$total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
