# SPDX-License-Identifier: MIT
# The flash a set of objects takes in a linked image, from its GNU ld map file
# (-Wl,-Map): the sizes of their input sections that the output section .text
# holds (code and read-only data; --gc-sections has dropped the rest).
#
#   awk -v pat=REGEX [-v top=N] -f bench/map_text.awk IMAGE.map
#
# pat: an extended regex on the object path (e.g. "/lean/core/"). Prints
#   total BYTES
#   obj BYTES OBJECT            (per object, largest first)
#   fn BYTES SECTION OBJECT     (the top N input sections, largest first; 0 = none)
# mawk-compatible (no strtonum).
function hex(h,   i, v) {
    v = 0
    h = tolower(h)
    sub(/^0x/, "", h)
    for (i = 1; i <= length(h); i++)
        v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
    return v
}
BEGIN { intext = 0; tot = 0; nf = 0; if (top == "") top = 0 }
/^\.text([ \t]|$)/ { intext = 1; next }
/^\.[A-Za-z_]/ { intext = 0 }
intext {
    if ($1 ~ /^\./ && NF == 1) { name = $1; next }
    if ($1 ~ /^\./ && NF >= 4 && $2 ~ /^0x/) { name = $1; sz = $3; f = $4 }
    else if ($1 ~ /^0x/ && NF == 3 && $3 ~ /\.o$/) { sz = $2; f = $3 }
    else next
    if (f !~ pat) next
    s = hex(sz)
    if (s == 0) next
    tot += s
    per[f] += s
    nf++
    fsz[nf] = s
    fname[nf] = name " " f
}
END {
    print "total " tot
    for (k in per) print "obj " per[k] " " k | "sort -k2,2nr"
    close("sort -k2,2nr")
    if (top > 0) {
        for (i = 1; i <= nf; i++) print "fn " fsz[i] " " fname[i] | ("sort -k2,2nr | head -" top)
        close("sort -k2,2nr | head -" top)
    }
}
