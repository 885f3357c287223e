#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check-core-flags: every build rule of src/ passes the flags the core needs.
#
#   bash tests/check_core_flags.sh        (make check-core-flags; part of make test)
#
# include/zspan/zspan.h (zs_init) requires src/ to be built with
# -fno-strict-aliasing: the core keeps its own record types in the caller's
# arena whatever type the caller declared it with. The Makefile keeps that flag
# in one variable, CORE_REQUIRED_FLAGS, which every rule compiling src/ uses.
#
# The script asks make itself, so it sees the rules as they are, in the
# Makefile and in every mk/*.mk, present and future:
#  1. `make -p` prints make's database; every rule (pattern or explicit) with a
#     recipe and a src/*.c (or src/%.c) prerequisite is a core build rule;
#  2. each one is made concrete (a pattern rule becomes a target of the tree
#     it matches, e.g. build/obj/%.o -> build/obj/activate.o) and `make -n -B TARGET` prints its commands without running them; the
#     command that writes the target (`-o TARGET`), and any command that
#     compiles a src/*.c, must end up with -fno-strict-aliasing (the last of
#     -fstrict-aliasing / -fno-strict-aliasing on the line wins);
#  3. the same with CORE_REQUIRED_FLAGS= on make's command line must fail for
#     every rule: each gets the flag from the shared variable, not from a copy
#     of it, and the check above can see a rule lose it.
# Exits 1 if a rule lacks the flag, 0 otherwise; prints one line per rule.

set -u
MAKE_CMD=${MAKE_CMD:-make}
FLAG=-fno-strict-aliasing
VAR=CORE_REQUIRED_FLAGS

# The inner makes must not inherit the outer one's job server or options.
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL $MAKE_CMD --no-print-directory "$@"; }

first_src=$(ls src/*.c 2>/dev/null | head -1)
if [ -z "$first_src" ]; then
    echo "check-core-flags: no src/*.c" >&2
    exit 1
fi
stem=$(basename "$first_src" .c)

# 1. Core build rules: "TARGET<TAB>FILE:LINE" for each rule with a recipe and a
# src/ C source among its prerequisites.
db=$(mk -p -q core-present 2>/dev/null)
rules=$(printf '%s\n' "$db" | awk '
    /^#  recipe to execute \(from / {
        if (tgt != "" && src) {
            where = $0
            sub(/^#  recipe to execute \(from \047/, "", where)
            sub(/\047, line /, ":", where)
            sub(/\):$/, "", where)
            print tgt "\t" where
        }
        tgt = ""; next
    }
    /^\t/ || /^#/ { next }
    /^$/ { tgt = ""; next }
    / (:|::|\?|\+|!)?= / || /^define / { tgt = ""; next }
    /^[^ ][^:]*:/ {
        i = index($0, ":")
        tgt = substr($0, 1, i - 1); pre = substr($0, i + 1)
        sub(/\|.*/, "", pre)
        src = 0
        n = split(pre, w, " ")
        for (k = 1; k <= n; k++)
            if (w[k] ~ /^src\/[^\/]*\.c$/ || w[k] == "src/%.c") src = 1
        split(tgt, t, " "); tgt = t[1]
        next
    }
    { tgt = "" }' | sort -u)

if [ -z "$rules" ]; then
    echo "check-core-flags: make's database shows no rule building src/*.c" >&2
    exit 1
fi

# Every word on the database's rule lines: the files make knows about.
words=$(printf '%s\n' "$db" | grep -v -e '^#' -e '^	' -e ' [:?+!]*= ' | tr ' |:' '\n\n\n' |
        grep -v -e '^$' -e '%' | sort -u)

# A target of the tree that pattern $1 matches with a stem without a slash
# (a core source's name if none).
instance() {
    local p=$1 pre=${1%%\%*} suf=${1#*\%} w s
    while read -r w; do
        case "$w" in
        "$pre"?*"$suf")
            s=${w#"$pre"}
            s=${s%"$suf"}
            case "$s" in */*) ;; *) echo "$w"; return ;; esac ;;
        esac
    done <<< "$words"
    echo "${p//%/$stem}"
}

# Checks the commands make prints for target $1 (extra make arguments after it).
# Prints the offending command lines; returns 1 if the flag is missing from any.
check_target() {
    local t=$1
    shift
    mk -n -B "$@" "$t" 2>&1 | awk -v T="$t" -v FLAG="$FLAG" '
        /\\$/ { cont = cont substr($0, 1, length($0) - 1) " "; next }
        {
            if (cont != "") { $0 = cont $0; cont = "" }
            writes = 0; compiles_src = 0; last = ""
            for (i = 1; i <= NF; i++) {
                if ($i == "-o" && i < NF && $(i + 1) == T) writes = 1
                if ($i ~ /^src\/[^\/]*\.c$/) compiles_src = 1
                if ($i == "-fstrict-aliasing" || $i == "-fno-strict-aliasing") last = $i
            }
            if (!writes && !compiles_src) next
            if (writes) seen = 1
            if (last != FLAG) { print "    " $0; bad = 1 }
        }
        END {
            if (!seen) { print "    (no command writes " T " with -o)"; bad = 1 }
            exit bad
        }'
}

fail=0
n=0
while IFS=$'\t' read -r rule where; do
    [ -n "$rule" ] || continue
    n=$((n + 1))
    target=$rule
    case "$rule" in *%*) target=$(instance "$rule") ;; esac
    if out=$(check_target "$target"); then
        if check_target "$target" "$VAR=" > /dev/null; then
            echo "check-core-flags: FAIL: $rule ($where) still has $FLAG with $VAR= :" \
                 "it must take it from \$($VAR), not from a copy"
            fail=1
        else
            echo "check-core-flags: ok: $rule ($where)"
        fi
    else
        echo "check-core-flags: FAIL: $rule ($where) builds src/ without $FLAG:"
        echo "$out"
        fail=1
    fi
done <<< "$rules"

if [ $fail -eq 0 ]; then
    echo "check-core-flags: all $n rules that build src/ pass $FLAG (from \$($VAR))"
fi
exit $fail
