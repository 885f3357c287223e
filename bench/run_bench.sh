#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the zspan benchmark and writes the Markdown table (make bench).
#
# Environment (set by mk/firmware.mk): BENCH_HOST, FW_M4, FW_M0, FW_M0BIG,
# FW_QEMU, FW_QEMU_FLAGS (ending with -semihosting-config ...), ARM_SIZE,
# CORE_M0_OBJS, CORE_M4_OBJS, BENCH_OUT (the Markdown file), BENCH_WORK (a
# scratch directory).
#
# Measures, for the four scenes and both visibility modes, ten frames each:
#   host:  x86-64 instructions per frame under callgrind, counting only
#          zs_frame_begin + zs_draw + zs_render_rows (--toggle-collect);
#   M4:    guest instructions per frame on QEMU mps2-an386 (-icount shift=0,
#          SysTick calibrated), core built -O2;
#   M0:    the same on QEMU microbit (16 KB RAM), core built -Os, for the
#          scenes whose arena fits; the M0 code of the others is measured on
#          mps2-an386 (same instructions, more RAM);
# and checks that every frame's checksum is the same on host, M4 and M0.
# With BENCH_SCALE_BIN set (mk/firmware_scale.mk), it then runs the scaling
# benchmark (bench/run_scale.sh) and appends its section "How cost grows".

set -u
set -o pipefail

: "${BENCH_HOST:?}" "${FW_M4:?}" "${FW_M0:?}" "${FW_M0BIG:?}"
FW_QEMU=${FW_QEMU:-qemu-system-arm}
FW_QEMU_FLAGS=${FW_QEMU_FLAGS:--nographic -monitor none -serial none -icount shift=0 -semihosting-config enable=on,target=native}
ARM_SIZE=${ARM_SIZE:-arm-none-eabi-size}
BENCH_OUT=${BENCH_OUT:-bench/results.md}
WORK=${BENCH_WORK:-build/bench/run}
SCENES="sphere285 cubes wuson cluster"
MODES="span zline"
FRAMES=10

mkdir -p "$WORK"
rm -f "$WORK"/*.txt "$WORK"/callgrind.*

fail=0
note() { echo "bench: $*" >&2; }

# --- host checksums and arena sizes --------------------------------------------
note "host run"
if ! "$BENCH_HOST" run > "$WORK/host.txt"; then
    note "host run failed"; fail=1
fi

# --- callgrind --------------------------------------------------------------------
if command -v valgrind >/dev/null 2>&1; then
    for s in $SCENES; do
        for m in $MODES; do
            note "callgrind $s $m"
            out="$WORK/callgrind.$s.$m"
            if valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
                   --toggle-collect=zs_frame_begin --toggle-collect=zs_draw \
                   --toggle-collect=zs_render_rows \
                   "$BENCH_HOST" run --scene "$s" --mode "$m" > /dev/null 2> "$out.log"; then
                total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p; s/^totals: *\([0-9]*\).*/\1/p' \
                        "$out" | head -1)
                echo "CG $s $m ${total:-0}" >> "$WORK/callgrind.txt"
            else
                note "callgrind failed for $s $m (see $out.log)"; fail=1
            fi
        done
    done
else
    note "valgrind not installed: no host instruction counts"
fi

# --- QEMU -----------------------------------------------------------------------------
run_qemu() { # machine elf outfile
    note "qemu $1 $(basename "$2")"
    timeout 900 $FW_QEMU -M "$1" $FW_QEMU_FLAGS,arg=bench -kernel "$2" > "$3" 2>&1
    local rc=$?
    if [ $rc -ne 0 ]; then
        note "$1 $(basename "$2") exited with $rc:"; tail -5 "$3" >&2; fail=1
    fi
}
run_qemu mps2-an386 "$FW_M4" "$WORK/m4.txt"
run_qemu microbit "$FW_M0" "$WORK/m0.txt"
run_qemu mps2-an386 "$FW_M0BIG" "$WORK/m0big.txt"

# --- sizes ------------------------------------------------------------------------------
core_text() { "$ARM_SIZE" -t $1 2>/dev/null | awk 'END {print $1}'; }
M0_TEXT=$(core_text "${CORE_M0_OBJS:-}")
M4_TEXT=$(core_text "${CORE_M4_OBJS:-}")
ARENA_1000=$("$BENCH_HOST" arena 1000 800 256)

# --- the table --------------------------------------------------------------------------
cat "$WORK"/host.txt "$WORK"/callgrind.txt "$WORK"/m4.txt "$WORK"/m0.txt "$WORK"/m0big.txt \
    2>/dev/null > "$WORK/all.txt"
# the linked footprint of make check-lean (mk/lean.mk): its figures for the targets table
if [ -n "${LEAN_FLASH:-}" ] && [ -s "$LEAN_FLASH" ]; then
    sed -n 's/^<!-- FLASH \([a-z]*\) \([0-9]*\) -->$/FLASH \1 \2/p' "$LEAN_FLASH" >> "$WORK/all.txt"
fi

awk -v scenes="$SCENES" -v modes="$MODES" -v frames="$FRAMES" -v m0text="${M0_TEXT:-0}" \
    -v m4text="${M4_TEXT:-0}" -v arena1000="${ARENA_1000:-0}" -v date="$(date -u +%Y-%m-%d)" \
    -v qemu="$($FW_QEMU --version | head -1)" -v gcc="$(arm-none-eabi-gcc --version | head -1)" \
    -v hostcc="$(${CC:-cc} --version | head -1)" '
function kv(line, key,    i, n, f) {
    n = split(line, f, " ")
    for (i = 1; i <= n; i++) if (index(f[i], key "=") == 1) return substr(f[i], length(key) + 2)
    return ""
}
function fmtm(x) { return x == "" ? "-" : sprintf("%.3f M", x / 1e6) }
function fmtk(x) { return x == "" ? "-" : sprintf("%.1f KB", x / 1024) }
$1 == "A" { arena[$2, $3] = kv($0, "arena") }
$1 == "R" {
    b = $2; s = $3; m = $4; f = $5
    sum[b, s, m, f] = kv($0, "sum")
    if (b != "host") { ins[b, s, m, f] = kv($0, "instr"); n[b, s, m]++ ; tot[b, s, m] += kv($0, "instr")
        if (kv($0, "instr") + 0 > mx[b, s, m]) mx[b, s, m] = kv($0, "instr") + 0 }
    if (kv($0, "dropped") + 0 > 0) dropped[b, s]++
}
$1 == "S" { skip[$2, $3] = "needs " kv($0, "need") " B of arena, " kv($0, "free") " B free" }
$1 == "M" { sram[$2] = kv($0, "static_ram"); stk[$2] = kv($0, "stack_used"); stksz[$2] = kv($0, "stack_size") }
$1 == "I" { ipt[$2] = kv($0, "ipt_milli"); free[$2] = kv($0, "free_ram") }
$1 == "CG" { cg[$2, $3] = $4 / frames }
$1 == "FLASH" { leanrow[$2] = $3 }
END {
    ns = split(scenes, S, " "); nm = split(modes, MO, " ")
    tgt["sphere285"] = 0.28e6; tgt["cubes"] = 1.1e6; tgt["wuson"] = 0.87e6
    print "# zspan benchmark results"
    print ""
    print "Generated by `make bench` (bench/run_bench.sh) on " date ". 240x240 RGB565, flat unlit,"
    print "one colour per triangle, back faces culled; camera at the origin looking down -Z,"
    print "fov 60, near 0.1, far 100; ten frames per scene (rotation 30 + 2f degrees)."
    print "Instructions are per frame (mean of 10, max in brackets), counting zs_frame_begin +"
    print "zs_draw + zs_render_rows only. Host: x86-64 under callgrind, core -O2 (" hostcc ")."
    print "Cortex-M4: QEMU mps2-an386, core -O2; Cortex-M0: QEMU microbit (16 KB RAM), core -Os;"
    print "both " gcc ", " qemu ", -icount shift=0,"
    printf "SysTick calibrated against a loop of known length (M4 %.3f, M0 %.3f instructions per tick);\n", ipt["mps2-an386"] / 1000, ipt["microbit"] / 1000
    print "on mps2-an386 the rows go to a framebuffer and the frame is one timed section, on the"
    print "microbit (no room for a framebuffer) each call is timed around a one-row buffer and the"
    print "timer-read cost is subtracted; the same M0 code measured both ways agrees within 0.25%"
    print "(the whole-frame figure also counts the benchmark'"'"'s own row loop, ~10 instructions a row)."
    print "M0 figures marked * are the same Cortex-M0 code run on mps2-an386 because the scene"
    print "does not fit the microbit'"'"'s 16 KB (see below)."
    print ""
    print "| scene | mode | host x86 | Cortex-M4 | Cortex-M0 | M4 target | checksums host = M4 = M0 |"
    print "| ----- | ---- | -------: | --------: | --------: | --------- | ------------------------ |"
    for (i = 1; i <= ns; i++) for (j = 1; j <= nm; j++) {
        s = S[i]; m = MO[j]
        m4 = n["mps2-an386", s, m] ? tot["mps2-an386", s, m] / n["mps2-an386", s, m] : ""
        m4s = m4 == "" ? "-" : fmtm(m4) " (" fmtm(mx["mps2-an386", s, m]) ")"
        if (n["microbit", s, m]) { m0 = tot["microbit", s, m] / n["microbit", s, m]; m0s = fmtm(m0) " (" fmtm(mx["microbit", s, m]) ")"; m0b = "microbit" }
        else if (n["m0code-an386", s, m]) { m0 = tot["m0code-an386", s, m] / n["m0code-an386", s, m]; m0s = fmtm(m0) "* (" fmtm(mx["m0code-an386", s, m]) ")"; m0b = "m0code-an386" }
        else { m0s = "-"; m0b = "" }
        t = "-"
        if (m == "span" && (s in tgt)) t = (m4 != "" && m4 <= tgt[s] ? "met" : "MISSED") " (<= " fmtm(tgt[s]) ")"
        # checksums of every frame
        ok = 0; bad = 0
        for (f = 0; f < frames; f++) {
            h = sum["host", s, m, f]; a = sum["mps2-an386", s, m, f]; c = (m0b == "" ? "" : sum[m0b, s, m, f])
            if (h != "" && h == a && h == c) ok++; else bad++
            if (m0b != "microbit" && sum["m0code-an386", s, m, f] != "" && sum["m0code-an386", s, m, f] != h) bad++
        }
        cs = bad ? sprintf("**DIFFER** (%d/%d frames equal)", ok, frames) : sprintf("identical (%d frames)", ok)
        if (bad) anybad = 1
        printf "| %s | %s | %s | %s | %s | %s | %s |\n", s, m, cg[s, m] == "" ? "-" : fmtm(cg[s, m]), m4s, m0s, t, cs
        if (m == "span") { spanm4[s] = m4 }
    }
    print ""
    print "## Memory"
    print ""
    print "Pool capacities: the largest use over the ten frames and both modes of a host run, grown"
    print "where a pool still overflowed (build/bench/gen/bench_caps.h): no frame drops anything."
    print "RAM = arena + .data + .bss + stack high-water (the one-row line buffer, 480 B, is in"
    print ".bss). For scenes that do not run on the microbit, its columns are an estimate with the"
    print "image'"'"'s .data+.bss and the stack high-water measured with sphere285."
    print ""
    print "| scene | capacities (tris, verts, edges) | arena | microbit: .data+.bss | microbit: stack high-water | microbit: total RAM | fits 16 KB microbit |"
    print "| ----- | ------------------------------- | ----: | -------------------: | -------------------------: | -----------------: | ------------------- |"
    for (i = 1; i <= ns; i++) {
        s = S[i]
        fits = n["microbit", s, "span"] ? "yes" : (skip["microbit", s] != "" ? "no: " skip["microbit", s] : "not run")
        tot_ram = arena["host", s] + sram["microbit"] + stk["microbit"]
        printf "| %s | %s | %d B | %d B | %d B (of %d reserved) | %d B (%s) | %s |\n", s, caps[s] == "" ? capsof(s) : caps[s], arena["host", s], sram["microbit"], stk["microbit"], stksz["microbit"], tot_ram, fmtk(tot_ram), fits
    }
    big = ""
    for (i = 1; i <= ns; i++) if (n["microbit", S[i], "span"]) big = S[i]
    print ""
    printf "Largest scene that runs on the 16 KB microbit: **%s**. ", big == "" ? "none" : big
    print "The others do not fit because their arena alone exceeds the free RAM (16 KB minus"
    printf ".data+.bss and the %d B stack reserve = %d B); their M0 figures above come from the same\n", stksz["microbit"], free["microbit"]
    print "Cortex-M0 image linked for mps2-an386."
    print ""
    printf "Cortex-M4 image: .data+.bss %d B, stack high-water %d B (all scenes).\n", sram["mps2-an386"], stk["mps2-an386"]
    print ""
    print "## Flash"
    print ""
    printf "Core `.text` alone (src/*.c, every object, unlinked): Cortex-M0 -Os **%d B (%s)**, Cortex-M4 -O2 %d B (%s).\n", m0text, fmtk(m0text), m4text, fmtk(m4text)
    print ""
    print "@LEAN_FLASH@"
    print ""
    print "## Targets"
    print ""
    print "| target | measured | |"
    print "| ------ | -------- | - |"
    for (i = 1; i <= ns; i++) {
        s = S[i]
        if (!(s in tgt)) continue
        printf "| Cortex-M4 span whole frame %s <= %s | %s | %s |\n", s, fmtm(tgt[s]), fmtm(spanm4[s]), (spanm4[s] != "" && spanm4[s] <= tgt[s]) ? "met" : "**missed**"
    }
    ram1000 = arena1000 + 2 * 480
    printf "| RAM 240x240, 1,000 triangles, two line buffers <= 24 KB | arena %d B (1000 tris, 800 verts, 256 edges; flat, span-only flags) + 960 B = %d B (%s) | %s |\n", arena1000, ram1000, fmtk(ram1000), ram1000 <= 24576 ? "met" : "**missed**"
    printf "| sphere285 runs on the 16 KB microbit | %s | %s |\n", n["microbit", "sphere285", "span"] ? "runs" : "does not run", n["microbit", "sphere285", "span"] ? "met" : "**missed**"
    printf "| core .text on Cortex-M0 (-Os) <= 16 KB, every feature (linked: the bench image) | %s | %s |\n", leanrow["bench"] == "" ? m0text " B (unlinked)" : leanrow["bench"] " B", (leanrow["bench"] == "" ? m0text : leanrow["bench"]) <= 16384 ? "met" : "**missed**"
    if (leanrow["lean"] != "") printf "| core .text on Cortex-M0 (-Os) <= 12 KB, lean (-DZS_LEAN, linked) | %d B | %s |\n", leanrow["lean"], leanrow["lean"] <= 12288 ? "met" : "**missed**"
    printf "| frame checksums identical on host, M0, M4 | %s | %s |\n", anybad ? "some differ" : "all equal", anybad ? "**missed**" : "met"
    print ""
    print "## Frame checksums"
    print ""
    print "FNV-1a 32 (basis 0x811C9DC5, prime 0x01000193) over the RGB565 big-endian bytes of all"
    print "rows in order. Span and z-line modes give the same image, so one list per scene:"
    print ""
    print "| scene | f=0 | 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 | 9 |"
    print "| ----- | --- | - | - | - | - | - | - | - | - | - |"
    for (i = 1; i <= ns; i++) {
        s = S[i]; line = "| " s
        for (f = 0; f < frames; f++) {
            h = sum["host", s, "span", f]
            if (sum["host", s, "zline", f] != h) h = h "/" sum["host", s, "zline", f]
            line = line " | " h
        }
        print line " |"
    }
}
function capsof(s) { return "" }
' "$WORK/all.txt" > "$WORK/table.md" || fail=1

# Capacities column: from the generated header.
caps_h=$(dirname "$BENCH_HOST")/gen/bench_caps.h
if [ -f "$caps_h" ]; then
    for s in $SCENES; do
        u=$(echo "$s" | tr a-z A-Z)
        c=$(sed -n "s/^#define BENCH_CAPS_$u //p" "$caps_h")
        sed -i "s/^| $s |  | /| $s | $c | /" "$WORK/table.md"
    done
fi

# --- how cost grows: the scaling benchmark (mk/firmware_scale.mk sets BENCH_SCALE_BIN);
# its frames-per-second estimates use the Cortex-M counts above --------------------------
if [ -n "${BENCH_SCALE_BIN:-}" ]; then
    note "scaling benchmark"
    BENCH_SCALE=$BENCH_SCALE_BIN SCALE_WORK="$WORK/scale" SCALE_OUT="$WORK/scale.md" \
        FW_FILES="$WORK/m4.txt $WORK/m0.txt $WORK/m0big.txt" bash bench/run_scale.sh || fail=1
    [ -s "$WORK/scale.md" ] && { echo; cat "$WORK/scale.md"; } >> "$WORK/table.md"
fi

# the Flash section's linked figures (bench/run_lean.sh)
if [ -n "${LEAN_FLASH:-}" ] && [ -s "$LEAN_FLASH" ]; then
    awk -v f="$LEAN_FLASH" '$0 == "@LEAN_FLASH@" { while ((getline l < f) > 0) if (l !~ /^<!--/) print l; next } { print }' \
        "$WORK/table.md" > "$WORK/table.tmp" && mv "$WORK/table.tmp" "$WORK/table.md"
else
    grep -v '^@LEAN_FLASH@$' "$WORK/table.md" > "$WORK/table.tmp" && mv "$WORK/table.tmp" "$WORK/table.md"
fi
cp "$WORK/table.md" "$BENCH_OUT"
cat "$BENCH_OUT"
echo
echo "bench: raw outputs in $WORK; table written to $BENCH_OUT"
exit $fail
