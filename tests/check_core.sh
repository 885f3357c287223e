#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check-core: the core's Cortex-M0 objects (build/m0/*.o, compiled from src/*.c
# by the Makefile) must not need floating point, an allocator or stdio.
#
#   tests/check_core.sh OBJ...
#
# Environment: CHECK_SRCS, the sources to scan in checks 2 and 3 (default
# src/*.c src/*.h); CHECK_NAME, the label of the messages (default check-core);
# ARM_NM, ARM_SIZE, CC.
#
# Checks
#   1. undefined symbols of every object (arm-none-eabi-nm -u), minus the ones
#      another core object defines: fail on soft-float helpers, libm, allocators,
#      stdio/exit/assert. Integer helpers (__aeabi_idiv, __aeabi_lmul,
#      __aeabi_uldivmod, __gnu_thumb1_case_*, ...) and memcpy/memset/memmove/
#      memcmp are fine.
#   2. the words float and double outside comments and strings in src/*.[ch];
#   3. #include <...> of anything but a freestanding header or <string.h>.
# Then prints the .text / .data / .bss totals (arm-none-eabi-size).

set -u
ARM_NM=${ARM_NM:-arm-none-eabi-nm}
ARM_SIZE=${ARM_SIZE:-arm-none-eabi-size}
CC=${CC:-cc}
NAME=${CHECK_NAME:-check-core}

if [ $# -eq 0 ]; then
    echo "$NAME: no objects (is src/ empty?)" >&2
    exit 1
fi

fail=0

# --- 1. undefined symbols -------------------------------------------------
defined=$("$ARM_NM" --defined-only -g "$@" 2>/dev/null | awk 'NF >= 3 {print $3}' | sort -u)
undefined=$("$ARM_NM" -u "$@" 2>/dev/null | awk 'NF >= 2 && $1 == "U" {print $2}' | sort -u)
external=$(comm -23 <(printf '%s\n' "$undefined" | sed '/^$/d') \
                    <(printf '%s\n' "$defined" | sed '/^$/d'))

float_re='^(__aeabi_(c?[fd]|[ui]*l?2[fd])|__(add|sub|mul|div|neg)[sdtx]f[23]|__(eq|ne|lt|le|gt|ge|un|cmp)[sdtx]f2|__float|__fix|__extend|__trunc|__pow[isdt]f2|__gnu_[fh]2|_fp_)'
libm_re='^(sqrt|cbrt|hypot|sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|exp|exp2|expm1|log|log2|log10|log1p|pow|floor|ceil|trunc|round|lround|llround|rint|lrint|nearbyint|fabs|fmod|remainder|frexp|ldexp|modf|fmin|fmax|fma|copysign)[fl]?$'
alloc_re='^(_?malloc|_?calloc|_?realloc|_?free|aligned_alloc|posix_memalign|memalign|valloc|_?sbrk|_malloc_r|_calloc_r|_realloc_r|_free_r)$'
stdio_re='^(_?printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|iprintf|siprintf|sniprintf|puts|putchar|fputs|fputc|putc|fwrite|fread|fopen|fclose|fflush|perror|_printf_r|_vfprintf_r|_puts_r|__printf_chk|__sprintf_chk|__snprintf_chk|exit|_exit|abort|__assert_func|__assert_fail|assert|_impure_ptr|errno|__errno)$'

bad_float=$(printf '%s\n' "$external" | grep -E "$float_re|$libm_re")
bad_alloc=$(printf '%s\n' "$external" | grep -E "$alloc_re")
bad_stdio=$(printf '%s\n' "$external" | grep -E "$stdio_re")

echo "$NAME: $# Cortex-M0 objects (arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -Os)"
echo "$NAME: symbols the objects need from outside themselves:"
if [ -n "$external" ]; then
    printf '%s\n' "$external" | sed 's/^/    /'
else
    echo "    (none)"
fi
for obj in "$@"; do
    for kind in float alloc stdio; do
        case $kind in
        float) re="$float_re|$libm_re" ;;
        alloc) re="$alloc_re" ;;
        stdio) re="$stdio_re" ;;
        esac
        hits=$("$ARM_NM" -u "$obj" 2>/dev/null | awk '{print $2}' | grep -E "$re" | tr '\n' ' ')
        if [ -n "$hits" ]; then
            echo "$NAME: FAIL: $obj needs $kind symbols: $hits"
        fi
    done
done
[ -n "$bad_float" ] && fail=1
[ -n "$bad_alloc" ] && fail=1
[ -n "$bad_stdio" ] && fail=1

# --- 2. float / double in the source (comments and strings stripped) -------
srcs=${CHECK_SRCS-$(ls src/*.c src/*.h 2>/dev/null)}
for f in $srcs; do
    # -fpreprocessed -dD: strip comments without expanding macros or includes.
    hits=$("$CC" -fpreprocessed -dD -E -P -x c "$f" 2>/dev/null |
           sed -e 's/"\([^"\\]\|\\.\)*"/""/g' -e "s/'\\([^'\\\\]\\|\\\\.\\)*'/''/g" |
           grep -wE 'float|double|_Complex' )
    if [ -n "$hits" ]; then
        echo "$NAME: FAIL: $f uses float/double (outside comments):"
        printf '%s\n' "$hits" | sed 's/^/    /'
        fail=1
    fi
done

# --- 3. hosted headers ------------------------------------------------------
allowed_re='^((stdint|stddef|string|stdbool|limits|stdarg|iso646|stdalign|stdnoreturn)\.h|zspan/.*)$'
for f in $srcs; do
    incs=$(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*<\([^>]*\)>.*/\1/p' "$f")
    for h in $incs; do
        if ! printf '%s\n' "$h" | grep -qE "$allowed_re"; then
            echo "$NAME: FAIL: $f includes <$h> (freestanding headers, <string.h> and <zspan/...> only)"
            fail=1
        fi
    done
done

# --- size -------------------------------------------------------------------
echo "$NAME: size of the objects (Cortex-M0, -Os):"
"$ARM_SIZE" -t "$@" | sed 's/^/    /'
text=$("$ARM_SIZE" -t "$@" | awk '/\(TOTALS\)/ {print $1}')
echo "$NAME: .text total: ${text:-?} bytes"

if [ "$fail" -ne 0 ]; then
    [ -n "$bad_float" ] && echo "$NAME: float helpers/libm needed: $(echo $bad_float)"
    [ -n "$bad_alloc" ] && echo "$NAME: allocator needed: $(echo $bad_alloc)"
    [ -n "$bad_stdio" ] && echo "$NAME: stdio/exit/assert needed: $(echo $bad_stdio)"
    echo "$NAME: FAILED"
    exit 1
fi
echo "$NAME: OK (no float, no allocator, no stdio)"
