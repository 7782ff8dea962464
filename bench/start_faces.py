#!/usr/bin/env python3
"""What `qmc encode --start-faces N` (EncodeOptions::start_faces: the polygon
coder's first faces, spec 5.4.2) buys and costs.

Usage: start_faces.py QMC QMC_ENCODE_ONCE WORK_DIR BITS MESH...

Whole files: `qmc encode -q BITS MESH OUT --start-faces N` for N = 1 (the
default), 4, 16 and 64, every attribute of the mesh included, as a user's
file. Positions and faces alone, as docs/results/compression.md reads the
mesh: `qmc_encode_once MESH BITS 5 N` (bench/encode_once.cc, in process,
the allocator keeping its memory) for N = 1 and 16, run in turns three
times; its bytes, and the median of the three runs' medians of five
encodes. Printed as Markdown.
"""
import os
import re
import statistics
import subprocess
import sys

WHOLE_STARTS = (1, 4, 16, 64)
TIMED_STARTS = (1, 16)
ROUNDS = 3
KEEP_MEMORY = 'glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=1073741824'


def whole_file(qmc, mesh, bits, starts, out):
    report = subprocess.run([qmc, 'encode', '-q', str(bits), mesh, out, '--start-faces', str(starts)],
                            check=True, capture_output=True, text=True).stdout
    kept = re.search(r'kept start (\d+) of', report)
    vertices = re.search(r'input\s+\S+: (\d+) vertices', report)
    return os.path.getsize(out), int(kept.group(1)) if kept else 0, int(vertices.group(1))


def timed(encode_once, mesh, bits, starts):
    env = dict(os.environ, GLIBC_TUNABLES=KEEP_MEMORY)
    line = subprocess.run([encode_once, mesh, str(bits), '5', str(starts)], check=True, capture_output=True,
                          text=True, env=env).stdout
    m = re.search(r'repeats median ([0-9.]+) ms.*; (\d+) bytes', line)
    return float(m.group(1)), int(m.group(2))


def main():
    qmc, encode_once, work, bits = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    meshes = sys.argv[5:]
    out = os.path.join(work, 'start_faces.qmc')
    print('| mesh | vertices | whole file, N = 1 | N = 4 | N = 16 | N = 64 (start kept) | '
          'positions and faces, N = 1 / 16 | encode ms, N = 1 / 16 (ratio) |')
    print('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |')
    gains = []
    for mesh in meshes:
        name = '/'.join(mesh.split('/')[-2:])
        row, base = [], None
        for n in WHOLE_STARTS:
            size, kept, vertices = whole_file(qmc, mesh, bits, n, out)
            if base is None:
                base = size
                row.append(str(size))
            elif n == WHOLE_STARTS[-1]:
                row.append('%d (%.3f; %d)' % (size, size / base, kept))
            else:
                row.append('%d (%.3f)' % (size, size / base))
        gains.append(size / base)
        ms = {n: [] for n in TIMED_STARTS}
        sizes = {}
        for _ in range(ROUNDS):
            for n in TIMED_STARTS:
                t, b = timed(encode_once, mesh, bits, n)
                ms[n].append(t)
                sizes[n] = b
        m1, m16 = statistics.median(ms[1]), statistics.median(ms[16])
        print('| %s | %d | %s | %d / %d (%.3f) | %.3f / %.3f (%.1f) |' %
              (name, vertices, ' | '.join(row), sizes[1], sizes[16], sizes[16] / sizes[1], m1, m16, m16 / m1))
    print()
    print('Whole files at N = 64 against N = 1: geometric mean %.4f, least %.3f, %d of %d meshes smaller.' %
          (statistics.geometric_mean(gains), min(gains), sum(g < 1 for g in gains), len(gains)))


if __name__ == '__main__':
    main()
