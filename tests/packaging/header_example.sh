#!/bin/sh
# SPDX-License-Identifier: MIT
# Prints the usage example of include/zspan/zspan.h's opening comment as C:
# the lines indented by four spaces after " * One frame" up to " * Conventions",
# without the comment's " *     " margin. Fails if there is none.
#
#   tests/packaging/header_example.sh include/zspan/zspan.h > example.c
set -eu
out=$(awk '
    /^ \* One frame/ { on = 1; next }
    /^ \* Conventions/ { on = 0 }
    on && /^ \*     / { sub(/^ \*     /, ""); print; n++; next }
    on && /^ \*$/ { print ""; next }
    END { if (n == 0) exit 1 }
' "$1") || { echo "header_example.sh: no example in $1" >&2; exit 1; }
printf '/* Cut out of %s by tests/packaging/header_example.sh. */\n%s\n' "$1" "$out"
