#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make check-lean (mk/lean.mk): the lean configuration (-DZS_LEAN) and the
# core's linked flash on Cortex-M0 (-Os, -ffunction-sections, --gc-sections).
#
# Environment (set by mk/lean.mk): LEAN_OBJS (the core built -DZS_LEAN),
# LEAN_OFF (the stages it leaves out: object base names), FW_LEAN_M0,
# FW_LEAN_M0BIG, FW_LEAN_FULL, FW_BENCH_M0 (images; *.map beside the
# microbit ones), FULL_OBJS, BENCH_HOST, LEAN_HOST, LEAN_HOST_FULL, FW_QEMU,
# FW_QEMU_FLAGS, ARM_NM, ARM_SIZE, LEAN_DIR (scratch), LEAN_FLASH_MD (the
# Markdown fragment written for bench/results.md's Flash section).
#
# Checks, in order (any failure: exit 1, no fragment):
#   1. no lean object but the left-out stages' own refers to a symbol they define;
#   2. the lean image links no byte of the left-out stages' objects;
#   3. the lean image's frames (span mode, every bench scene that fits, 10 frames;
#      the others from the same objects on mps2-an386) have the host's checksums;
#   4. the host core built -DZS_LEAN refuses every left-out feature with its
#      documented code, and renders what it supports as the full core does.
set -u
set -o pipefail
: "${LEAN_OBJS:?}" "${LEAN_OFF:?}" "${FW_LEAN_M0:?}" "${FW_LEAN_M0BIG:?}" "${FW_LEAN_FULL:?}"
: "${FW_BENCH_M0:?}" "${BENCH_HOST:?}" "${LEAN_HOST:?}" "${LEAN_HOST_FULL:?}" "${LEAN_DIR:?}"
ARM_NM=${ARM_NM:-arm-none-eabi-nm}
FW_QEMU=${FW_QEMU:-qemu-system-arm}
FW_QEMU_FLAGS=${FW_QEMU_FLAGS:--nographic -monitor none -serial none -icount shift=0 -semihosting-config enable=on,target=native}
here=$(dirname "$0")
mkdir -p "$LEAN_DIR"
fail=0
say() { echo "check-lean: $*"; }

# --- 1. references ---------------------------------------------------------------
off_re=$(echo $LEAN_OFF | tr ' ' '|')
off_objs="" keep_objs=""
for o in $LEAN_OBJS; do
    if [[ $(basename "$o" .o) =~ ^($off_re)$ ]]; then off_objs="$off_objs $o"; else keep_objs="$keep_objs $o"; fi
done
off_syms=$("$ARM_NM" --defined-only -g $off_objs | awk 'NF >= 3 {print $3}' | sort -u)
used=$("$ARM_NM" -u $keep_objs | awk '$1 == "U" {print $2}' | sort -u)
bad=$(comm -12 <(printf '%s\n' "$off_syms") <(printf '%s\n' "$used"))
if [ -n "$bad" ]; then
    say "FAIL: objects built with ZS_LEAN call left-out stages:"; printf '    %s\n' $bad; fail=1
else
    say "the lean objects call none of the left-out stages ($LEAN_OFF)"
fi

# --- 2. the link -------------------------------------------------------------------
kb() { awk -v b="$1" 'BEGIN { printf "%.1f", b / 1024 }'; }
mapsum() { awk -v pat="$2" -v top="${3:-0}" -f "$here/map_text.awk" "$1"; }
lean_map=${FW_LEAN_M0%.elf}.map
for s in $LEAN_OFF; do
    n=$(mapsum "$lean_map" "/lean/core/$s\\.o\$" | awk '$1 == "total" {print $2}')
    if [ "${n:-0}" -ne 0 ]; then say "FAIL: the lean image links $n B of $s.o"; fail=1; fi
done

# --- 3. the lean image's frames = the host's ---------------------------------------------
"$BENCH_HOST" run --mode span > "$LEAN_DIR/host.txt" || { say "FAIL: $BENCH_HOST run"; fail=1; }
timeout 600 $FW_QEMU -M microbit $FW_QEMU_FLAGS -kernel "$FW_LEAN_M0" > "$LEAN_DIR/m0.txt" 2>&1 ||
    { say "FAIL: $FW_LEAN_M0 exited with $?"; tail -3 "$LEAN_DIR/m0.txt"; fail=1; }
timeout 600 $FW_QEMU -M mps2-an386 $FW_QEMU_FLAGS -kernel "$FW_LEAN_M0BIG" > "$LEAN_DIR/m0big.txt" 2>&1 ||
    { say "FAIL: $FW_LEAN_M0BIG exited with $?"; tail -3 "$LEAN_DIR/m0big.txt"; fail=1; }
timeout 600 $FW_QEMU -M microbit $FW_QEMU_FLAGS -kernel "$FW_LEAN_FULL" > "$LEAN_DIR/m0full.txt" 2>&1 ||
    { say "FAIL: $FW_LEAN_FULL exited with $?"; tail -3 "$LEAN_DIR/m0full.txt"; fail=1; }
timeout 600 $FW_QEMU -M microbit $FW_QEMU_FLAGS -kernel "$FW_LEAN_UNLIT" > "$LEAN_DIR/m0unlit.txt" 2>&1 ||
    { say "FAIL: $FW_LEAN_UNLIT exited with $?"; tail -3 "$LEAN_DIR/m0unlit.txt"; fail=1; }
sums() { awk '$1 == "R" && $4 == "span" { for (i = 6; i <= NF; i++) if ($i ~ /^sum=/) print $3, $5, substr($i, 5) }' "$@" | sort; }
sums "$LEAN_DIR/host.txt" > "$LEAN_DIR/host.sums"
sums "$LEAN_DIR/m0.txt" "$LEAN_DIR/m0big.txt" | sort -u > "$LEAN_DIR/lean.sums"
sums "$LEAN_DIR/m0unlit.txt" "$LEAN_DIR/m0full.txt" >> "$LEAN_DIR/lean.sums" # (checked alike)
sort -u -o "$LEAN_DIR/lean.sums" "$LEAN_DIR/lean.sums"
n_lean=$(wc -l < "$LEAN_DIR/lean.sums")
# the microbit's frames and the big image's must agree where both ran
if [ "$(cut -d' ' -f1,2 "$LEAN_DIR/lean.sums" | uniq -d | wc -l)" -ne 0 ]; then
    say "FAIL: the images disagree on a frame (lean microbit, lean mps2-an386, unlit, full core)"; fail=1
fi
missing=$(comm -23 "$LEAN_DIR/lean.sums" "$LEAN_DIR/host.sums")
if [ "$n_lean" -eq 0 ] || [ -n "$missing" ]; then
    say "FAIL: the lean image's frames are not the host's (scene, frame, lean checksum):"
    printf '%s\n' "$missing" | head -10
    fail=1
else
    fits=$(awk '$1 == "R" {print $3}' "$LEAN_DIR/m0.txt" | sort -u | tr '\n' ' ')
    say "the lean images (and the full core's) render the host's frames: $n_lean frames, span mode (microbit: ${fits:-none})"
fi

# --- 4. host: refusals, and the lean core's frames = the full core's -------------------
"$LEAN_HOST" > "$LEAN_DIR/host-lean.txt" || { say "FAIL: $LEAN_HOST"; grep FAIL "$LEAN_DIR/host-lean.txt"; fail=1; }
"$LEAN_HOST_FULL" > "$LEAN_DIR/host-full.txt" || { say "FAIL: $LEAN_HOST_FULL"; grep FAIL "$LEAN_DIR/host-full.txt"; fail=1; }
if ! diff <(grep '^F ' "$LEAN_DIR/host-lean.txt") <(grep '^F ' "$LEAN_DIR/host-full.txt") ||
   [ "$(grep -c '^F ' "$LEAN_DIR/host-lean.txt")" -eq 0 ]; then
    say "FAIL: the host lean core's frames differ from the full core's"; fail=1
else
    say "host: $(tail -1 "$LEAN_DIR/host-lean.txt"); $(grep -c '^F ' "$LEAN_DIR/host-lean.txt") frames as the full core's"
fi

"$LEAN_HOST_UNLIT" > "$LEAN_DIR/host-unlit.txt" || { say "FAIL: $LEAN_HOST_UNLIT"; grep FAIL "$LEAN_DIR/host-unlit.txt"; fail=1; }
extra=$(comm -23 <(grep '^F ' "$LEAN_DIR/host-unlit.txt" | sort) <(grep '^F ' "$LEAN_DIR/host-full.txt" | sort))
if [ -n "$extra" ] || [ "$(grep -c '^F ' "$LEAN_DIR/host-unlit.txt")" -eq 0 ]; then
    say "FAIL: the host lean unlit core's frames differ from the full core's:"; printf '%s\n' "$extra" | head -5; fail=1
else
    say "host: $(tail -1 "$LEAN_DIR/host-unlit.txt") (ZS_NO_LIGHTING); $(grep -c '^F ' "$LEAN_DIR/host-unlit.txt") unlit frames as the full core's"
fi

# --- figures -------------------------------------------------------------------------
full_map=${FW_LEAN_FULL%.elf}.map
bench_map=${FW_BENCH_M0%.elf}.map
LEAN_TEXT=$(mapsum "$lean_map" '/lean/core/' | awk '$1 == "total" {print $2}')
FULLP_TEXT=$(mapsum "$full_map" '/m0/core/' | awk '$1 == "total" {print $2}')
BENCH_TEXT=$(mapsum "$bench_map" '/m0/core/' | awk '$1 == "total" {print $2}')
ALL_TEXT=$("${ARM_SIZE:-arm-none-eabi-size}" -t ${FULL_OBJS:-} 2>/dev/null | awk 'END {print $1}')
UNLIT_TEXT=$(mapsum "${FW_LEAN_UNLIT%.elf}.map" '/lean/unlit/' | awk '$1 == "total" {print $2}')
LIBGCC=$(mapsum "$lean_map" 'libgcc\.a' | awk '$1 == "total" {print $2}')
lean_i=$(awk '$1 == "R" && $3 == "sphere285" {s += substr($6, 7); n++} END {if (n) printf "%.3f M", s / n / 1e6}' "$LEAN_DIR/m0.txt")
full_i=$(awk '$1 == "R" && $3 == "sphere285" {s += substr($6, 7); n++} END {if (n) printf "%.3f M", s / n / 1e6}' "$LEAN_DIR/m0full.txt")
say "core .text linked on Cortex-M0 -Os: lean $LEAN_TEXT B (with ZS_NO_LIGHTING $UNLIT_TEXT B); the same program on the full core $FULLP_TEXT B; the bench image (every feature used) $BENCH_TEXT B; all objects $ALL_TEXT B"
say "sphere285 span on the microbit: lean $lean_i, full core $full_i instructions per frame"
{
    echo "Core \`.text\` (code and read-only data of src/*.c) on Cortex-M0, -Os, linked with"
    echo "-ffunction-sections -fdata-sections -Wl,--gc-sections (from the images' map files;"
    echo "\`make check-lean\`, bench/run_lean.sh):"
    echo ""
    echo "| build | core .text | target |"
    echo "| ----- | --------: | ------ |"
    printf '| every feature: the bench image (all modes, textures, A-buffer, 1-bit outputs) | %d B (%s KB) | <= 16 KB: %s |\n' \
        "$BENCH_TEXT" "$(kb "$BENCH_TEXT")" "$([ "$BENCH_TEXT" -le 16384 ] && echo met || echo '**missed**')"
    printf '| full core, lean program (bench/bench_lean_fw.c: flat span frames) | %d B (%s KB) | - |\n' \
        "$FULLP_TEXT" "$(kb "$FULLP_TEXT")"
    printf '| `-DZS_LEAN` core, lean program | **%d B (%s KB)** | <= 12 KB: %s |\n' \
        "$LEAN_TEXT" "$(kb "$LEAN_TEXT")" "$([ "$LEAN_TEXT" -le 12288 ] && echo met || echo '**missed**')"
    printf '| `-DZS_LEAN -DZS_NO_LIGHTING` core (unlit colours, as the bench scenes), lean program | %d B (%s KB) | - |\n' \
        "$UNLIT_TEXT" "$(kb "$UNLIT_TEXT")"
    printf '| all of src/*.o, unlinked (arm-none-eabi-size) | %d B (%s KB) | - |\n' \
        "$ALL_TEXT" "$(kb "$ALL_TEXT")"
    echo ""
    echo "The lean program also links ${LIBGCC:-0} B of libgcc (division, 64-bit shifts and"
    echo "multiplies). Its frames are the bench's (checked: every span frame of the scenes above,"
    echo "host = lean M0), at ${lean_i:-?} instructions per sphere285 frame on the microbit"
    echo "(full core: ${full_i:-?}). Largest lean functions:"
    echo ""
    echo "| bytes | function | object |"
    echo "| ----: | -------- | ------ |"
    mapsum "$lean_map" '/lean/core/' 12 | awk '$1 == "fn" {f = $3; sub(/^\.(text|rodata)(\.unlikely)?\./, "", f); o = $4; sub(/.*\//, "", o); printf "| %d | %s | %s |\n", $2, f, o}'
    echo "<!-- FLASH bench $BENCH_TEXT -->"
    echo "<!-- FLASH lean $LEAN_TEXT -->"
    echo "<!-- FLASH unlit $UNLIT_TEXT -->"
} > "$LEAN_DIR/flash.tmp"
if [ $fail -eq 0 ]; then
    mv "$LEAN_DIR/flash.tmp" "${LEAN_FLASH_MD:-$LEAN_DIR/flash.md}"
    say "PASS"
fi
exit $fail
