#!/usr/bin/env bash
# Builds the Arduino library folder (1.5 layout) from the tree; run by mk/package.mk.
#
#   bash mk/arduino_lib.sh -o LIB/library.properties FLAG...
#
# LIB/src/zspan/*.h   the public headers (src/ is on the sketch's include path)
# LIB/src/zspan.h     the library's main header (library.properties: includes=)
# LIB/src/core/       src/*.c and *.h;  LIB/src/drivers/: drivers/*.c and *.h
# LIB/examples/       examples/arduino/*/
# The Arduino build takes no per-library compiler flags, so each FLAG the sources
# need (-fno-strict-aliasing, from CORE_REQUIRED_FLAGS) becomes a
# `#pragma GCC optimize` line at the top of every source; `#line 1` keeps the
# compiler's line numbers those of the tree. (gcc-avr 5.4 ignores the pragma: on AVR
# the user adds compiler.c.extra_flags=-fno-strict-aliasing; README.md, Arduino.)
set -eu
[ "$1" = -o ] || { echo "usage: $0 -o LIB/library.properties FLAG..." >&2; exit 2; }
out=$2
shift 2
lib=$(dirname "$out")
pragmas=""
for f in "$@"; do
    case $f in
    -f*) pragmas="$pragmas#pragma GCC optimize(\"${f#-f}\") /* zspan.mk: ZSPAN_REQUIRED_CFLAGS */
" ;;
    *) echo "$0: cannot turn $f into a pragma" >&2; exit 2 ;;
    esac
done
[ -n "$pragmas" ] || { echo "$0: no flags given (CORE_REQUIRED_FLAGS)" >&2; exit 2; }
rm -rf "$lib"
mkdir -p "$lib/src/zspan" "$lib/src/core" "$lib/src/drivers" "$lib/examples"
cp include/zspan/*.h "$lib/src/zspan/"
cp src/*.h "$lib/src/core/"
cp drivers/*.h "$lib/src/drivers/"
for f in src/*.c drivers/*.c; do
    case $f in src/*) d=core ;; *) d=drivers ;; esac
    { printf '%s' "$pragmas"; printf '#line 1 "%s"\n' "$f"; cat "$f"; } > "$lib/src/$d/$(basename "$f")"
done
cat > "$lib/src/zspan.h" <<'H'
/* zspan for Arduino: the renderer, the bus layer and the panel drivers. */
#ifndef ZSPAN_ARDUINO_H
#define ZSPAN_ARDUINO_H
#include "zspan/zspan.h"
#include "zspan/bus.h"
#include "zspan/panel.h"
#endif
H
for e in examples/arduino/*/; do cp -r "$e" "$lib/examples/"; done
cp README.md "$lib/"
cp library.properties "$out"
