#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The AVR image (ATmega2560 under simavr) against the same program on the host.
#
#   run_avr.sh test IMAGE HOST   (make test-avr) every frame's checksum equals the host's,
#                                no pool overflow, and the largest configuration is refused
#                                (its arena cannot be addressed with a 16-bit size_t)
#   run_avr.sh bench IMAGE HOST  (make bench-avr) the same, then cycles per frame and RAM
#                                into bench/results-avr.md
# Environment: AVR_RUN (the simavr harness), AVR_MCU, AVR_HZ; for bench AVR_SIZE, AVR_CORE_OBJS.
set -u
what=$1 image=$2 host=$3
work=build/avr/run
mkdir -p "$work"
fail() { echo "$what-avr: FAIL: $*"; exit 1; }

timeout 900 "$AVR_RUN" "$AVR_MCU" "$AVR_HZ" "$image" > "$work/avr.txt" 2> "$work/avr.err"
rc=$?
[ $rc -eq 0 ] || { cat "$work/avr.txt" "$work/avr.err"; fail "simavr_run exit status $rc"; }
"$host" > "$work/host.txt" || fail "$host failed"

# "R BOARD small SHADE MODE FRAME sum=X ... dropped=N [cycles=N]"
awk '
    function kv(line, k,   i, a, n) { n = split(line, a, " "); for (i = 1; i <= n; i++)
        if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
    FNR == 1 { file++ }
    /^R / { key = $3 " " $4 " " $5 " " $6
        if (file == 1) { host[key] = kv($0, "sum"); nh++ }
        else { avr[key] = kv($0, "sum"); n++; if (kv($0, "dropped") != "0") drop++ } }
    /^K / { big[file] = kv($0, "big_arena") " " kv($0, "init") }
    END {
        for (k in host) if (!(k in avr)) { printf "no AVR frame for %s\n", k; bad++ }
            else if (avr[k] != host[k]) { printf "%s: avr %s host %s\n", k, avr[k], host[k]; bad++ }
        printf "avr: %d frames (host %d), %d checksums differ from the host, %d with pool overflow\n", n, nh, bad, drop
        # ZS_ERR_CAPACITY is 3 (include/zspan/zspan.h); the host (64-bit size_t) says ARENA_SMALL (4)
        if (big[2] != "0 3") { printf "avr: largest configuration: arena %s (want \"0 3\": refused)\n", big[2]; bad++ }
        if (big[1] !~ /^[0-9]+ 4$/ || big[1] + 0 <= 65535) { printf "host: largest configuration: %s\n", big[1]; bad++ }
        exit (bad || drop || n == 0 || n != nh) ? 1 : 0
    }' "$work/host.txt" "$work/avr.txt" || fail "see $work/host.txt and $work/avr.txt"

if [ "$what" = test ]; then
    grep '^[RM] ' "$work/avr.txt" | head -3 | sed 's/^/test-avr: /'
    echo "test-avr: ATmega2560 (simavr, 16-bit int) checksums == host's; largest arena refused"
    exit 0
fi

text=$($AVR_SIZE -t $AVR_CORE_OBJS | tail -1 | awk '{print $1}')
out=bench/results-avr.md
awk -v text="$text" -v hz="$AVR_HZ" '
    function kv(line, k,   i, a, n) { n = split(line, a, " "); for (i = 1; i <= n; i++)
        if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
    /^M / { ar = kv($0, "arena"); st = kv($0, "static"); sk = kv($0, "stack") }
    /^R / { k = $4 SUBSEP $5; c = kv($0, "cycles") + 0; tot[k] += c; cnt[k]++
        if (c > mx[k]) mx[k] = c; if (!(k in order)) { order[k] = ++no; ks[no] = k } }
    END {
        print "# AVR benchmark (ATmega2560 under simavr, 8 KB RAM, 16-bit int)"
        print ""
        print "Written by `make bench-avr` (tests/packaging/run_avr.sh). bench/small_scene.c: three"
        print "cubes (two cutting into each other) and an octahedron with vertex colours, 160x128"
        print "RGB565, two lights; Gouraud frames with fog. Cycles per frame (zs_frame_begin +"
        print "zs_draw + the 128 zs_render_rows calls, the checksum excluded) counted by libsimavr"
        print "(ports/avr/simavr_run.c), exact and repeatable; core -Os. Every checksum equals the"
        print "host'"'"'s."
        print ""
        print "| shading | mode | frames | cycles per frame (mean) | max | ms at 16 MHz |"
        print "| ------- | ---- | -----: | ----------------------: | --: | -----------: |"
        for (j = 1; j <= no; j++) { k = ks[j]; split(k, p, SUBSEP)
            printf "| %s | %s | %d | %.3f M | %.3f M | %.0f |\n", p[1], p[2], cnt[k], tot[k] / cnt[k] / 1e6, mx[k] / 1e6, tot[k] / cnt[k] / hz * 1000 }
        print ""
        printf "RAM: arena %d B (28 records, 36 vertices, 36 edge sides, all features), .data + .bss %d B in all (arena, renderer, line buffer, meshes, stdio), stack high-water %d B; %d B of 8192 used. Core .text (src/*.c, avr-gcc -Os): %d B.\n", ar, st, sk, st + sk, text
    }' "$work/avr.txt" > "$out"
cat "$out"
