#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check-arduino: the Arduino library folder follows the library specification's layout
# rules (1.5 format), library.json is valid PlatformIO metadata, and every example
# compiles with Debian's arduino-builder for an ATmega2560 board.
#
#   check_arduino.sh LIB WORK     (make check-arduino; LIB from make arduino-lib)
# Then runs SpinningCubeST7789's image under simavr on an emulated ST7789 (AVR_ST7789)
# and compares its first frame with the same sketch built for the host (HOST_CUBE).
# Environment: ARDUINO_FQBN, ZSPAN_VERSION, AVR_ST7789, HOST_CUBE.
set -u
lib=$(realpath -m "$1") work=$(realpath -m "$2")
bad=0
err() { echo "check-arduino: FAIL: $*"; bad=1; }
ok() { echo "check-arduino: ok: $*"; }

# --- layout rules --------------------------------------------------------------
props=$lib/library.properties
[ -f "$props" ] || { err "no library.properties"; exit 1; }
field() { sed -n "s/^$1=//p" "$props" | head -1; }
for k in name version author maintainer sentence paragraph category url architectures; do
    [ -n "$(field $k)" ] || err "library.properties: required field $k missing or empty"
done
field name | grep -Eq '^[A-Za-z0-9][A-Za-z0-9 _.-]{0,62}$' ||
    err "name '$(field name)': letters, digits, space, _ . - only, starting with a letter or digit, at most 63"
field version | grep -Eq '^[0-9]+\.[0-9]+\.[0-9]+$' || err "version '$(field version)' is not MAJOR.MINOR.PATCH"
[ "$(field version)" = "$ZSPAN_VERSION" ] || err "version $(field version) != VERSION $ZSPAN_VERSION"
case "$(field category)" in
    Display|Communication|"Signal Input/Output"|Sensors|"Device Control"|Timing|"Data Storage"|"Data Processing"|Other) ;;
    *) err "category '$(field category)' is not one of the specification's" ;;
esac
field url | grep -Eq '^https?://' || err "url is not an http(s) address"
grep -Ev '^(#|$|[a-z_.]+=)' "$props" && err "library.properties: lines that are not key=value"
for h in $(field includes | tr ',' ' '); do [ -f "$lib/src/$h" ] || err "includes=$h: no src/$h"; done
[ -d "$lib/src" ] || err "no src/ folder"
[ -e "$lib/utility" ] && err "utility/ next to src/ (1.5 layout: everything under src/)"
ls "$lib"/*.c "$lib"/*.cpp "$lib"/*.h >/dev/null 2>&1 && err "sources in the root (1.5 layout: under src/)"
[ -e "$lib/.development" ] && err ".development present"
[ -z "$(find "$lib" -type l)" ] || err "symbolic links in the library"
[ -z "$(find "$lib" -name '*.exe' -o -name '.git')" ] || err "executables or a .git folder"
for top in "$lib"/* "$lib"/.[!.]*; do
    [ -e "$top" ] || continue
    case $(basename "$top") in
        library.properties|src|examples|extras|README*|LICENSE*|keywords.txt) ;;
        *) err "unexpected entry in the root: $(basename "$top")" ;;
    esac
done
n_ex=0
for d in "$lib"/examples/*/; do
    n=$(basename "$d")
    [ -f "$d/$n.ino" ] || err "examples/$n has no $n.ino"
    n_ex=$((n_ex + 1))
done
[ $n_ex -gt 0 ] || err "no examples"
# every source of the tree is in the library, with the pragma of the required flags
for f in src/*.c drivers/*.c; do
    case $f in src/*) p=$lib/src/core/$(basename "$f") ;; *) p=$lib/src/drivers/$(basename "$f") ;; esac
    [ -f "$p" ] || { err "$f not in the library"; continue; }
    head -1 "$p" | grep -q '^#pragma GCC optimize("no-strict-aliasing")' || err "$p lacks the strict-aliasing pragma"
done
[ $bad -eq 0 ] && ok "layout: library.properties fields, src/ layout, $n_ex examples"

# --- library.json ------------------------------------------------------------------
python3 - "$ZSPAN_VERSION" <<'PY' || bad=1
import json, os, sys
try:
    j = json.load(open("library.json"))
except ValueError as e:
    print("check-arduino: FAIL: library.json is not JSON:", e); sys.exit(1)
errs = []
for k in ("name", "version", "description", "keywords", "authors", "frameworks", "platforms", "build"):
    if k not in j: errs.append("field %s missing" % k)
if j.get("version") != sys.argv[1]: errs.append("version %r != VERSION %s" % (j.get("version"), sys.argv[1]))
b = j.get("build", {})
if "-fno-strict-aliasing" not in b.get("flags", []): errs.append("build.flags lacks -fno-strict-aliasing")
if not os.path.isfile(os.path.join(b.get("includeDir", ""), "zspan", "zspan.h")): errs.append("build.includeDir has no zspan/zspan.h")
for ex in j.get("examples", []):
    for f in ex.get("files", []):
        if not os.path.isfile(os.path.join(ex["base"], f)): errs.append("example file %s/%s missing" % (ex["base"], f))
for e in errs: print("check-arduino: FAIL: library.json:", e)
if not errs: print("check-arduino: ok: library.json is JSON with the fields PlatformIO needs")
sys.exit(1 if errs else 0)
PY

# --- compile the examples ---------------------------------------------------------------
rm -rf "$work"
mkdir -p "$work/libraries"
cp -r "$lib" "$work/libraries/zspan"
for d in "$lib"/examples/*/; do
    n=$(basename "$d")
    mkdir -p "$work/build-$n"
    # compiler.c.extra_flags: gcc-avr 5.4 ignores the sources' strict-aliasing pragma, so
    # the flag goes in as README.md tells Arduino users (platform.local.txt / build property)
    if arduino-builder -compile -verbose -hardware /usr/share/arduino-builder \
        -hardware /usr/share/arduino/hardware -tools /usr/bin -libraries "$work/libraries" \
        -fqbn "$ARDUINO_FQBN" -build-path "$work/build-$n" \
        -prefs=compiler.cpp.extra_flags=-DDECIMAL_DIG=__DECIMAL_DIG__ \
        -prefs=compiler.c.extra_flags=-fno-strict-aliasing \
        "$work/libraries/zspan/examples/$n/$n.ino" > "$work/$n.log" 2>&1; then
        ok "$n compiles for $ARDUINO_FQBN: $(grep -E '^(Sketch uses|Global variables)' "$work/$n.log" | sed 's/ Maximum is.*//; s/, leaving.*//' | tr '\n' ' ')"
        compiles=$(grep -E ' -c .*zspan/src/(core|drivers)/[a-z0-9_]+\.c" -o ' "$work/$n.log" | grep -v -- '-o "/dev/null"')
        nc=$(printf '%s\n' "$compiles" | grep -c .)
        nf=$(printf '%s\n' "$compiles" | grep -c -- '-fno-strict-aliasing')
        [ "$nc" -gt 0 ] && [ "$nc" = "$nf" ] || err "$n: $nf of $nc zspan source compiles have -fno-strict-aliasing"
    else
        cat "$work/$n.log"
        err "$n does not compile for $ARDUINO_FQBN"
    fi
done

# --- run the ST7789 example: AVR under simavr vs the host ------------------------------
elf=$work/build-SpinningCubeST7789/SpinningCubeST7789.ino.elf
if [ -f "$elf" ]; then
    if timeout 600 "$AVR_ST7789" "$elf" "$work/avr.rgb" > "$work/avr_st7789.log" 2>&1 &&
       "$HOST_CUBE" "$work/host.rgb" > "$work/host_cube.log" 2>&1; then
        if cmp -s "$work/avr.rgb" "$work/host.rgb" &&
           [ "$(od -An -v -tx1 -w3 "$work/host.rgb" | sort -u | wc -l)" -gt 100 ]; then
            ok "SpinningCubeST7789 on an ATmega2560 (simavr) -> emulated ST7789: first frame == the host build's ($(grep -o '[0-9]* cycles' "$work/avr_st7789.log"))"
        else
            err "SpinningCubeST7789: the AVR's frame differs from the host's (or is blank): $work/*.rgb"
        fi
    else
        cat "$work/avr_st7789.log" "$work/host_cube.log"
        err "SpinningCubeST7789: no clean frame on the emulated panel"
    fi
fi
exit $bad
