#!/usr/bin/env bash
# The RISC-V benchmark image under QEMU sifive_e against the host.
#
#   run_riscv.sh quick IMAGE   frame 0 of the first scene, both modes (make test-riscv):
#                              every checksum equals the host's (bench_host), no pool overflow
#   run_riscv.sh bench IMAGE   every scene that fits 16 KB, 10 frames, both modes
#                              (make bench-riscv): the same checks, then instructions per
#                              frame (minstret, exact under -icount shift=0), RAM and the
#                              core's .text into bench/results-riscv.md
# Environment: RV_QEMU, RV_QEMU_FLAGS, BENCH_HOST; for bench also RV_SIZE, RV_CORE_OBJS,
# BENCH_WORK (scratch directory).
set -u
what=$1 image=$2
work=${BENCH_WORK:-build/bench/run-riscv}
mkdir -p "$work"
fail() { echo "$what-riscv: FAIL: $*"; exit 1; }

args=arg=bench
[ "$what" = quick ] && args="$args,arg=quick"
# shellcheck disable=SC2086
timeout 600 $RV_QEMU $RV_QEMU_FLAGS,$args -kernel "$image" > "$work/rv.txt" 2>&1
rc=$?
[ $rc -eq 0 ] || { cat "$work/rv.txt"; fail "QEMU exit status $rc"; }
grep -q '^R ' "$work/rv.txt" || fail "no frame lines from the image"

if [ "$what" = quick ]; then
    "$BENCH_HOST" run --scene sphere285 --mode both --frames 1 > "$work/host.txt" || fail "bench_host"
else
    "$BENCH_HOST" run --mode both > "$work/host.txt" || fail "bench_host"
fi

# "R BOARD SCENE MODE FRAME ... sum=X ... dropped=N": compare by (scene, mode, frame).
awk '
    function kv(line, k,   i, a, n) { n = split(line, a, " "); for (i = 1; i <= n; i++)
        if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
    FNR == 1 { file++ }
    /^R / { key = $3 " " $4 " " $5
        if (file == 1) host[key] = kv($0, "sum")
        else { rv[key] = kv($0, "sum"); n++; if (kv($0, "dropped") != "0") drop++ } }
    END {
        for (k in rv) if (!(k in host)) { printf "no host frame for %s\n", k; bad++ }
            else if (rv[k] != host[k]) { printf "%s: riscv %s host %s\n", k, rv[k], host[k]; bad++ }
        printf "riscv: %d frames, %d checksums differ from the host, %d with pool overflow\n", n, bad, drop
        exit (bad || drop || n == 0) ? 1 : 0
    }' "$work/host.txt" "$work/rv.txt" || fail "checksums differ (outputs in $work)"
grep '^S ' "$work/rv.txt" | sed 's/^/riscv: skipped (RAM): /'

if [ "$what" = quick ]; then
    grep '^R ' "$work/rv.txt" | sed 's/^/test-riscv: /'
    echo "test-riscv: RV32IMC (QEMU sifive_e) checksums == host's"
    exit 0
fi

text=$($RV_SIZE -t $RV_CORE_OBJS | tail -1 | awk '{print $1}')
out=bench/results-riscv.md
awk -v text="$text" '
    function kv(line, k,   i, a, n) { n = split(line, a, " "); for (i = 1; i <= n; i++)
        if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
    /^A / { arena[$3] = kv($0, "arena"); timing[$3] = kv($0, "timing") }
    /^S / { skip[++ns] = $3; need[ns] = kv($0, "need") }
    /^M / { st = kv($0, "static_ram"); sk = kv($0, "stack_used"); ss = kv($0, "stack_size") }
    /^I / { free = kv($0, "free_ram") }
    /^R / { k = $3 SUBSEP $4; i = kv($0, "instr") + 0; tot[k] += i; cnt[k]++
        if (i > mx[k]) mx[k] = i; if (!(k in order)) { order[k] = ++no; ks[no] = k } }
    END {
        print "# RISC-V benchmark (RV32IMC on QEMU sifive_e, 16 KB RAM)"
        print ""
        print "Written by `make bench-riscv` (tests/packaging/run_riscv.sh). Instructions per frame"
        print "(zs_frame_begin + zs_draw + the rows) from the minstret counter under"
        print "`-icount shift=0` (exact, repeatable), mean and maximum over the frames; core -O2,"
        print "rows timed one by one (no room for a framebuffer). Every checksum equals the host'"'"'s."
        print ""
        print "| scene | mode | frames | instructions per frame (mean) | max | arena |"
        print "| ----- | ---- | -----: | ----------------------------: | --: | ----: |"
        for (j = 1; j <= no; j++) { k = ks[j]; split(k, p, SUBSEP)
            printf "| %s | %s | %d | %.3f M | %.3f M | %d B |\n", p[1], p[2], cnt[k], tot[k] / cnt[k] / 1e6, mx[k] / 1e6, arena[p[1]] }
        for (j = 1; j <= ns; j++) printf "| %s | - | 0 | does not fit: arena %d B > %d B free | | |\n", skip[j], need[j], free
        print ""
        printf "RAM: .data + .bss %d B (renderer state, line buffer), stack high-water %d B of %d B, %d B free for the arena. Core .text (src/*.c, RV32IMC -O2): %d B.\n", st, sk, ss, free, text
    }' "$work/rv.txt" > "$out"
cat "$out"
