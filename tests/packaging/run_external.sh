#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A project outside the tree (tests/packaging/external + examples/host-ppm/main.c, copied
# to a temporary directory) takes zspan in one way, builds, runs, and must print the same
# checksum and write the same PPM as the in-tree build of the example (REF, a program).
#
#   run_external.sh WAY REF
#   WAY: make          plain Makefile including zspan.mk
#        subdirectory  CMake add_subdirectory()
#        fetchcontent  CMake FetchContent (SOURCE_DIR: the tree)
#        package       cmake --install of the tree into a prefix, then find_package(zspan)
#        pkgconfig     make install PREFIX=... of the tree, then cc $(pkg-config --cflags --libs zspan)
set -u
way=$1 ref=$2
tree=$(pwd)
name=check-package-$way
fail() { echo "$name: FAIL: $*"; exit 1; }
# Inner makes must not inherit the outer one's job server or variables.
unset MAKEFLAGS MFLAGS MAKELEVEL
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zspan-ext.XXXXXX") || fail "mktemp"
trap 'rm -rf "$tmp"' EXIT
proj=$tmp/project
mkdir -p "$proj"
cp tests/packaging/external/Makefile tests/packaging/external/CMakeLists.txt \
   examples/host-ppm/main.c "$proj/"
log=$tmp/log
cmake_user() { cmake -S "$proj" -B "$proj/build" "$@" >> "$log" 2>&1 &&
               cmake --build "$proj/build" -j2 >> "$log" 2>&1; }

case $way in
make)
    make -C "$proj" ZSPAN_DIR="$tree" >> "$log" 2>&1 || { cat "$log"; fail "make"; }
    prog=$proj/host-ppm ;;
subdirectory|fetchcontent)
    cmake_user -DEXT_WAY="$way" -DZSPAN_DIR="$tree" || { cat "$log"; fail "cmake"; }
    prog=$proj/build/host-ppm ;;
package)
    { cmake -S "$tree" -B "$tmp/zspan-build" -DCMAKE_INSTALL_PREFIX="$tmp/prefix" \
          -DZSPAN_BUILD_SIM=OFF && cmake --build "$tmp/zspan-build" -j2 &&
      cmake --install "$tmp/zspan-build"; } >> "$log" 2>&1 || { cat "$log"; fail "cmake --install"; }
    [ -f "$tmp/prefix/lib/cmake/zspan/zspanConfig.cmake" ] || fail "no zspanConfig.cmake installed"
    # the source tree must not be needed any more
    cmake_user -DEXT_WAY=package -DCMAKE_PREFIX_PATH="$tmp/prefix" || { cat "$log"; fail "find_package"; }
    grep -q "$tree" "$proj/build/CMakeCache.txt" && fail "the build refers to the source tree"
    prog=$proj/build/host-ppm ;;
pkgconfig)
    make -C "$tree" --no-print-directory install PREFIX="$tmp/prefix" BUILD="$tmp/zspan-build" \
        >> "$log" 2>&1 || { cat "$log"; fail "make install"; }
    flags=$(PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig" pkg-config --cflags --libs zspan) ||
        fail "pkg-config --cflags --libs zspan"
    echo "$name: pkg-config --cflags --libs zspan: $flags"
    # shellcheck disable=SC2086
    ${CC:-cc} -std=c99 -Wall -Wextra -Werror -O2 -o "$proj/host-ppm" "$proj/main.c" $flags \
        >> "$log" 2>&1 || { cat "$log"; fail "compile with pkg-config's flags"; }
    prog=$proj/host-ppm ;;
*) fail "unknown way $way" ;;
esac

[ -x "$prog" ] || fail "no program built"
want=$("$ref" "$tmp/ref.ppm" | sed 's/.*checksum //') || fail "$ref"
got=$("$prog" "$tmp/got.ppm" | sed 's/.*checksum //') || fail "the built program failed"
cmp -s "$tmp/ref.ppm" "$tmp/got.ppm" || fail "PPM differs from the in-tree build's"
[ -n "$want" ] && [ "$got" = "$want" ] || fail "checksum $got, in-tree $want"
echo "$name: built outside the tree, checksum $got == in-tree"
