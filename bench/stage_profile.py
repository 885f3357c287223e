#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions per frame by pipeline stage, from a per-PC count of a firmware bench run.

usage: stage_profile.py ELF CORE_OBJ_DIR FRAMES PCFILE [PCFILE ...] [--check MEAN ...]
  ELF           the bench image that ran (no debug information needed)
  CORE_OBJ_DIR  the directory of the core objects linked into it (src/NAME.c -> NAME.o)
  FRAMES        frames each run rendered (the counts are divided by it)
  PCFILE        per-PC counts from ../shared/tools/qemu-pcprof (one run a scene), named
                SCENE.txt
  --check MEAN  one figure a PCFILE: the bench's own mean instructions per frame for that
                run (SysTick-timed); exit 1 if a stage total is more than 2% away from it

Each PC is credited to the function around it (inlined code counts where it was
inlined) and each function to the source file that defines it: local functions by the
FILE entries of the symbol table, global ones by the core objects' definitions. Files map
to stages (STAGES below); libgcc's and libc's routines called by the core are stages of
their own, and the benchmark's own code (timer calibration, checksums, start-up) is left
out. Prints one Markdown table: a row per stage, a column per run, instructions per frame
and the share of the frame."""
import bisect
import collections
import os
import subprocess
import sys

STAGES = [  # (stage, files of src/)
    ('front end: transform, project, cull, clip, set-up',
     ['geometry.c', 'setup.c', 'clip.c', 'camera.c', 'cull.c']),
    ('activation: edges, depth range, planes', ['activate.c']),
    ('edge table: new edges, stepping, retiring', ['raster.c']),
    ('visibility walk and span fills', ['span.c', 'zline.c', 'priority.c', 'warnock.c']),
    ('colour: shading set-up, pixel packing (at -Os also the flat fill)',
     ['shade.c', 'format.c', 'texture.c']),
    ('fixed-point helpers (reciprocals, divisions)', ['fixed.c']),
    ('frame and row loop', ['renderer.c']),
]
LIBC = {'memset', 'memcpy', 'memmove'}


def run(*cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout


def functions(elf, objdir):
    """[(start, end, name, file or None)] sorted by start."""
    global_file = {}
    for obj in sorted(os.listdir(objdir)):
        if obj.endswith('.o'):
            for line in run('arm-none-eabi-nm', '--defined-only',
                            os.path.join(objdir, obj)).splitlines():
                p = line.split()
                if len(p) == 3 and p[1] in 'TW':
                    global_file[p[2]] = obj[:-2] + '.c'
    out, cur_file = [], None
    for line in run('arm-none-eabi-readelf', '-sW', elf).splitlines():
        p = line.split()
        if len(p) < 8 or not p[0].endswith(':'):
            continue
        typ, bind = p[3], p[4]
        name = p[7] if len(p) > 7 else ''
        if typ == 'FILE':
            cur_file = name if name.endswith('.c') else None
            continue
        if typ != 'FUNC':
            continue
        start, size = int(p[1], 16) & ~1, int(p[2])
        f = cur_file if bind == 'LOCAL' else global_file.get(name)
        out.append((start, start + max(size, 2), name, f))
    out.sort()
    return out


def stage_of(name, f, core_files):
    if f in core_files:
        for stage, files in STAGES:
            if f in files:
                return stage
        return 'other core code'
    if name.startswith('__aeabi') or name.startswith('__') and name.endswith(('di3', 'si2',
                                                                             'si3', 'di4')):
        return 'libgcc helpers'
    if name in LIBC:
        return 'libc (memset, memcpy)'
    return None  # the benchmark's own code


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    args = sys.argv[1:]
    checks = []
    if '--check' in args:
        k = args.index('--check')
        checks = [float(v) for v in args[k + 1:]]
        args = args[:k]
    elf, objdir, frames, pcfiles = args[0], args[1], float(args[2]), args[3:]
    if checks and len(checks) != len(pcfiles):
        sys.exit('stage_profile: --check needs one figure a PCFILE')
    funcs = functions(elf, objdir)
    starts = [f[0] for f in funcs]
    core_files = {o[:-2] + '.c' for o in os.listdir(objdir) if o.endswith('.o')}
    order = [s for s, _ in STAGES] + ['other core code', 'libgcc helpers',
                                      'libc (memset, memcpy)']
    cols, totals = [], []
    for path in pcfiles:
        per = collections.Counter()
        for line in open(path):
            a, c = line.split()
            pc = int(a, 16)
            i = bisect.bisect_right(starts, pc) - 1
            if i < 0 or pc >= funcs[i][1]:
                continue
            st = stage_of(funcs[i][2], funcs[i][3], core_files)
            if st:
                per[st] += int(c)
        cols.append((os.path.basename(path).rsplit('.', 1)[0], per))
        totals.append(sum(per.values()))
    print('| stage | ' + ' | '.join(n for n, _ in cols) + ' |')
    print('| ----- |' + ' ---: |' * len(cols))
    for st in order:
        if not any(per[st] >= 50 * frames for _, per in cols):
            continue  # under 50 instructions a frame everywhere
        cells = []
        for (_, per), tot in zip(cols, totals):
            v = per[st] / frames
            cells.append(f'{v / 1000:,.1f} k ({100 * per[st] / max(tot, 1):.0f}%)')
        print(f'| {st} | ' + ' | '.join(cells) + ' |')
    print('| **frame** | ' + ' | '.join(f'**{t / frames / 1e6:.3f} M**' for t in totals) + ' |')
    bad = [(n, t / frames, m) for (n, _), t, m in zip(cols, totals, checks)
           if abs(t / frames - m) > 0.02 * m]
    for n, got, want in bad:
        print(f'stage_profile: {n}: the stages sum to {got:,.0f} instructions a frame, the '
              f'bench timed {want:,.0f}', file=sys.stderr)
    if bad:
        sys.exit(1)


if __name__ == '__main__':
    main()
