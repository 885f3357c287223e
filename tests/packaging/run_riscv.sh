#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The RISC-V benchmark image under QEMU sifive_e against the host.
#
#   run_riscv.sh quick IMAGE   frame 0 of the first scene, both modes (make test-riscv):
#                              every checksum equals the host's (bench_host), no pool overflow
#   run_riscv.sh bench IMAGE   every scene that fits 16 KB, 10 frames, both modes, and every
#                              scene with the same code on QEMU virt (RV_BIG_IMAGE, 256 KB
#                              RAM, rows timed one by one as on sifive_e) (make bench-riscv):
#                              the same checks, then instructions per frame (minstret, exact
#                              under -icount shift=0), RAM and the core's .text into
#                              bench/results-riscv.md
# Environment: RV_QEMU, RV_QEMU_FLAGS, BENCH_HOST; for bench also RV_BIG_IMAGE,
# RV_BIG_QEMU_FLAGS, RV_SIZE, RV_CORE_OBJS, BENCH_WORK (scratch directory).
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
if [ "$what" = bench ]; then
    # shellcheck disable=SC2086
    timeout 900 $RV_QEMU $RV_BIG_QEMU_FLAGS,arg=bench,arg=rows -kernel "$RV_BIG_IMAGE" \
        > "$work/rv-big.txt" 2>&1 || { cat "$work/rv-big.txt"; fail "QEMU virt failed"; }
    cat "$work/rv-big.txt" >> "$work/rv.txt"
fi

if [ "$what" = quick ]; then
    "$BENCH_HOST" run --scene sphere285 --mode both --frames 1 --mono > "$work/host.txt" || fail "bench_host"
else
    # --mono: also the 1-bit and textured frames the image renders
    "$BENCH_HOST" run --mode both --mono > "$work/host.txt" || fail "bench_host"
fi

# "R BOARD SCENE MODE FRAME ... sum=X ... dropped=N": compare by (scene, mode, frame).
awk '
    function kv(line, k,   i, a, n) { n = split(line, a, " "); for (i = 1; i <= n; i++)
        if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
    FNR == 1 { file++ }
    /^R / { key = $3 " " $4 " " $5
        if (file == 1) host[key] = kv($0, "sum")
        else { rv[$2 " " key] = kv($0, "sum"); hk[$2 " " key] = key; n++
               if (kv($0, "dropped") != "0") drop++ } }
    END {
        for (k in rv) if (!(hk[k] in host)) { printf "no host frame for %s\n", k; bad++ }
            else if (rv[k] != host[hk[k]]) { printf "%s: riscv %s host %s\n", k, rv[k], host[hk[k]]; bad++ }
        printf "riscv: %d frames, %d checksums differ from the host, %d with pool overflow\n", n, bad, drop
        exit (bad || drop || n == 0) ? 1 : 0
    }' "$work/host.txt" "$work/rv.txt" || fail "checksums differ (outputs in $work)"
grep '^S sifive_e' "$work/rv.txt" | sed 's/^/riscv: does not fit 16 KB: /'

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
    /^A / { arena[$3] = kv($0, "arena") }
    /^S sifive_e / { skip[$3] = kv($0, "need") }
    /^M sifive_e / { st = kv($0, "static_ram"); sk = kv($0, "stack_used"); ss = kv($0, "stack_size") }
    /^I sifive_e / { free = kv($0, "free_ram") }
    /^R / { b = ($2 == "sifive_e") ? "e" : "v"; k = $3 SUBSEP $4; i = kv($0, "instr") + 0
        tot[b, k] += i; cnt[b, k]++; if (i > mx[b, k]) mx[b, k] = i
        if (!(k in order)) { order[k] = ++no; ks[no] = k } }
    function cell(b, k) { return cnt[b, k] ? sprintf("%.3f M (max %.3f M)", tot[b, k] / cnt[b, k] / 1e6, mx[b, k] / 1e6) : "-" }
    END {
        print "# RISC-V benchmark (RV32IMC)"
        print ""
        print "Written by `make bench-riscv` (tests/packaging/run_riscv.sh). Instructions per frame"
        print "(zs_frame_begin + zs_draw + the 240 zs_render_rows calls, each row timed on its own"
        print "and the cost of the counter reads subtracted, as on the Cortex-M0) from the minstret"
        print "counter under `-icount shift=0` (exact, repeatable), mean and maximum over 10 frames;"
        print "core -O2. **sifive_e**: QEMU sifive_e, 16 KB RAM; **virt**: the same RV32IMC code on"
        print "QEMU virt with 256 KB of RAM, for the scenes that do not fit. Every frame checksum of"
        print "both machines equals the host'"'"'s."
        print ""
        print "| scene | mode | sifive_e (16 KB) | virt (same code) | arena |"
        print "| ----- | ---- | ---------------: | ---------------: | ----: |"
        for (j = 1; j <= no; j++) { k = ks[j]; split(k, p, SUBSEP)
            e = cnt["e", k] ? cell("e", k) : sprintf("does not fit (%d B > %d B free)", skip[p[1]], free)
            printf "| %s | %s | %s | %s | %d B |\n", p[1], p[2], e, cell("v", k), arena[p[1]] }
        print ""
        printf "RAM on sifive_e: .data + .bss %d B (renderer state, line buffer), stack high-water %d B of %d B, %d B free for the arena. Core .text (src/*.c, RV32IMC -O2): %d B.\n", st, sk, ss, free, text
    }' "$work/rv.txt" > "$out"
cat "$out"
