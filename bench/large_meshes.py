#!/usr/bin/env python3
"""Decode time of meshes of a million vertices and more, where the decoder's
tables outgrow the processor's caches, against Draco cl10 on the same mesh.

Usage: large_meshes.py QMC MESHGEN DECODE_ONCE DRACO_DECODE_ONCE WORK_DIR
                       ROUNDS BITS BUNNY [BEFORE_DECODE_ONCE]

Meshes, made in WORK_DIR (none is committed):
- bunny x16: BUNNY (stanford-bunny) with every triangle split into four at
  its edges' midpoints, twice: the same surface, 16 times the triangles;
  not symmetric, so its file has no mirror plane (spec 14.10);
- bunny x16 and its mirror image: that mesh beside its reflection across the
  plane x = its smallest x, two components, every vertex with a twin: the
  file takes POSN's mirror plane (methods 9 - 14), as modelled meshes do;
- jittered sphere: `qmc-meshgen jittered-sphere 7 1` (983,042 vertices, an
  irregular triangulation of a sphere, whose file takes the mirror plane
  too).

Each is encoded by `qmc encode -q BITS` and by `draco_encoder -qp BITS -cl 10`
(from the OBJ qmc decodes, so that both code the same vertices), then
decoded in process by DECODE_ONCE (bench/decode_once.cc), BEFORE_DECODE_ONCE
(the same program built at another revision, if given) and DRACO_DECODE_ONCE,
in turns, ROUNDS times, each run the median of 3 decodes after a first one;
the allocator keeps its memory (as in docs/results/compression.md). Printed
as Markdown: medians of the rounds.
"""
import os
import re
import statistics
import subprocess
import sys

KEEP_MEMORY = 'glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=1073741824'
REPEAT = 3


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'v':
                vertices.append(tuple(float(x) for x in p[1:4]))
            elif p[0] == 'f':
                corners = [int(x.split('/')[0]) - 1 for x in p[1:]]
                faces += [(corners[0], corners[k], corners[k + 1]) for k in range(1, len(corners) - 1)]
    return vertices, faces


def split_at_midpoints(vertices, faces):
    vertices = list(vertices)
    midpoint = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(vertices)
            vertices.append(tuple((vertices[a][i] + vertices[b][i]) / 2 for i in range(3)))
        return midpoint[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def write_obj(path, vertices, faces):
    with open(path, 'w') as f:
        for v in vertices:
            f.write('v %.9g %.9g %.9g\n' % v)
        for t in faces:
            f.write('f %d %d %d\n' % (t[0] + 1, t[1] + 1, t[2] + 1))


def with_mirror_image(vertices, faces):
    x0 = min(v[0] for v in vertices)
    n = len(vertices)
    mirrored = [(2 * x0 - x, y, z) for x, y, z in vertices]
    return vertices + mirrored, faces + [(a + n, c + n, b + n) for a, b, c in faces]


def run(command, env=None):
    return subprocess.run(command, check=True, capture_output=True, text=True, env=env).stdout


def median_ms(program, path):
    line = run([program, path, str(REPEAT)], env=dict(os.environ, GLIBC_TUNABLES=KEEP_MEMORY))
    return float(re.search(r'repeats median ([0-9.]+) ms', line).group(1))


def main():
    qmc, meshgen, decode_once, draco_once, work = sys.argv[1:6]
    rounds, bits, bunny = int(sys.argv[6]), int(sys.argv[7]), sys.argv[8]
    before = sys.argv[9] if len(sys.argv) > 9 else None
    vertices, faces = read_obj(bunny)
    for _ in range(2):
        vertices, faces = split_at_midpoints(vertices, faces)
    meshes = [('bunny x16', os.path.join(work, 'bunny16.obj'), vertices, faces)]
    pair = with_mirror_image(vertices, faces)
    meshes.append(('bunny x16 and its mirror image', os.path.join(work, 'bunny16_pair.obj')) + pair)
    sphere = os.path.join(work, 'jittered_sphere.ply')
    run([meshgen, 'jittered-sphere', '7', '1', sphere])
    meshes.append(('jittered sphere (qmc-meshgen jittered-sphere 7 1)', sphere, None, None))

    programs = [('qmc', decode_once)] + ([('qmc before', before)] if before else []) + [('Draco cl10', draco_once)]
    rows = []
    for name, path, v, f in meshes:
        if v is not None:
            write_obj(path, v, f)
        qmc_file, obj, drc = path + '.qmc', path + '.decoded.obj', path + '.drc'
        run([qmc, 'encode', '-q', str(bits), '--quiet', path, qmc_file])
        run([qmc, 'decode', qmc_file, obj])
        run(['draco_encoder', '-i', obj, '-o', drc, '-qp', str(bits), '-cl', '10'])
        info = run([qmc, 'info', qmc_file])
        count = re.search(r'mesh\s+(\d+) vertices', info).group(1)
        method = re.search(r'positions\s+predicted \(spec 14, method (\d+)', info)
        mirrored = 'mirror' in info.split('positions', 1)[1].split('\n', 1)[0]
        times = {label: [] for label, _ in programs}
        for _ in range(rounds):
            for label, program in programs:
                times[label].append(median_ms(program, drc if label == 'Draco cl10' else qmc_file))
        rows.append((name, count, method.group(1) if method else '-', 'yes' if mirrored else 'no',
                     os.path.getsize(qmc_file), os.path.getsize(drc),
                     {label: statistics.median(t) for label, t in times.items()}))
        for p in (path, obj, drc, qmc_file):
            os.remove(p)

    labels = [label for label, _ in programs]
    print('| mesh | vertices | POSN method | mirror plane | qmc bytes | Draco cl10 bytes | ' +
          ' | '.join('%s ms' % label for label in labels) +
          (' | qmc / qmc before' if before else '') + ' | Draco ms / qmc ms |')
    print('| --- | ---: | ---: | --- | ---: | ---: | ' + ' | '.join('---:' for _ in labels) +
          (' | ---:' if before else '') + ' | ---: |')
    for name, count, method, mirrored, qbytes, dbytes, ms in rows:
        cells = ['%.1f' % ms[label] for label in labels]
        ratio = [' %.3f |' % (ms['qmc'] / ms['qmc before'])] if before else []
        print('| %s | %s | %s | %s | %d | %d | %s |%s %.3f |' %
              (name, count, method, mirrored, qbytes, dbytes, ' | '.join(cells), ''.join(ratio),
               ms['Draco cl10'] / ms['qmc']))


if __name__ == '__main__':
    main()
