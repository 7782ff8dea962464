#!/usr/bin/env python3
"""Attributes (spec 15, issue 16): qmc's aTTR bytes against Draco cl10's bytes
for the same attribute at the same quantization bits, per corpus mesh.

Usage: attribute_sizes.py QMC DECODE_BENCH RUNS WORK_DIR MESH.obj...

Draco's bytes for an attribute are its file with positions and that
attribute minus its file with positions only (draco_encoder -cl 10 -qp P
-qt T -qn N on OBJ files written here with only those parts), so they
include the seams its connectivity records for the attribute; polygons are
written as fans of triangles (Draco's OBJ reader takes triangles and quads,
and triangulates quads itself), qmc keeps them. qmc's are the
aTTR chunk (12 bytes of framing included) of `qmc encode -q P --uv-bits T
--normal-bits N` on the whole input, read from `qmc info --json`. Both
quantize texture coordinates on one step over their largest range with T
bits; Draco codes normals octahedrally in N bits, qmc (format 1.6) per
component on a uniform grid of N bits: the normal errors differ, and the
table gives both files' largest angle error measured on the decoded meshes.
qmc's whole file also carries the OBJ's objects, groups, materials and
smoothing groups (fLBL, spec 16), which Draco's does not (cylinder_ngon_caps
and suzanne have them). Printed as Markdown.
"""
import json
import math
import os
import subprocess
import sys

POSITION_BITS, TEXCOORD_BITS, NORMAL_BITS = 12, 12, 10


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def parse_obj(path):
    lines = open(path).read().split('\n')
    v, vt, vn, faces = [], [], [], []
    for line in lines:
        t = line.split()
        if not t:
            continue
        if t[0] == 'v':
            v.append(line)
        elif t[0] == 'vt':
            vt.append(line)
        elif t[0] == 'vn':
            vn.append([float(x) for x in t[1:4]])
        elif t[0] == 'f':
            faces.append([c.split('/') for c in t[1:]])
    return v, vt, vn, faces


def write_obj(path, obj, keep_vt, keep_vn):
    v, vt, vn, faces = obj
    with open(path, 'w') as out:
        out.write('\n'.join(v) + '\n')
        if keep_vt:
            out.write('\n'.join(vt) + '\n')
        if keep_vn:
            out.write('\n'.join('vn %r %r %r' % tuple(n) for n in vn) + '\n')
        for f in faces:
            corners = []
            for c in f:
                s = c[0]
                if keep_vt or keep_vn:
                    s += '/' + (c[1] if keep_vt and len(c) > 1 else '')
                if keep_vn:
                    s += '/' + (c[2] if len(c) > 2 else '')
                corners.append(s)
            for i in range(1, len(corners) - 1):  # Draco's OBJ reader takes triangles and quads only
                out.write('f %s %s %s\n' % (corners[0], corners[i], corners[i + 1]))


def draco_bytes(work, name, obj, keep_vt, keep_vn):
    src = os.path.join(work, name + '.obj')
    drc = os.path.join(work, name + '.drc')
    write_obj(src, obj, keep_vt, keep_vn)
    run('draco_encoder', '-i', src, '-o', drc, '-cl', '10', '-qp', str(POSITION_BITS), '-qt', str(TEXCOORD_BITS),
        '-qn', str(NORMAL_BITS))
    return os.path.getsize(drc), drc


def attribute_errors(qmc, original, decoded):
    """What `qmc compare` says of the decoded OBJ's attributes, by name."""
    out = json.loads(run(qmc, 'compare', '--json', '--samples', '1000', original, decoded))
    return {a['name']: a for a in out['attributes']['compared']}


def error_cell(qmc_err, draco_err, key, fmt):
    cells = []
    for err in (qmc_err, draco_err):
        cells.append(fmt % err[key] if err is not None else '-')
    return ' / '.join(cells)


def main():
    qmc, decode_bench, runs, work, meshes = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
    rows, ratios = [], {'texcoord': [], 'normal': [], 'whole': []}
    pairs = []
    for path in meshes:
        name = os.path.splitext(os.path.basename(path))[0]
        obj = parse_obj(path)
        has_vt = bool(obj[1]) and all(len(c) > 1 and c[1] for f in obj[3] for c in f)
        has_vn = bool(obj[2]) and all(len(c) > 2 and c[2] for f in obj[3] for c in f)
        out = os.path.join(work, name + '.qmc')
        run(qmc, 'encode', '--quiet', '--drop-unsupported', '-q', str(POSITION_BITS), '--uv-bits', str(TEXCOORD_BITS),
            '--normal-bits', str(NORMAL_BITS), path, out)
        info = json.loads(run(qmc, 'info', '--json', out))
        qmc_attr = {a['name']: a['bytes'] for a in info['attributes']}
        base, _ = draco_bytes(work, name + '_pos', obj, False, False)
        whole, whole_drc = draco_bytes(work, name + '_all', obj, has_vt, has_vn)
        cells = []
        for attr, present, keep in (('texcoord', has_vt, (True, False)), ('normal', has_vn, (False, True))):
            if not present:
                cells.append('-')
                continue
            with_attr, _ = draco_bytes(work, name + '_' + attr, obj, *keep)
            draco = with_attr - base
            ratio = qmc_attr[attr] / draco
            ratios[attr].append(ratio)
            cells.append('%d / %d = **%.3f**' % (qmc_attr[attr], draco, ratio))
        whole_ratio = info['bytes'] / whole
        ratios['whole'].append(whole_ratio)
        qmc_obj = os.path.join(work, name + '_qmc.obj')
        draco_obj = os.path.join(work, name + '_draco.obj')
        run(qmc, 'decode', '--quiet', out, qmc_obj)
        run('draco_decoder', '-i', whole_drc, '-o', draco_obj)
        qmc_err, draco_err = attribute_errors(qmc, path, qmc_obj), attribute_errors(qmc, path, draco_obj)
        uv = angle = '-'
        if has_vt:
            uv = '%s; %s' % (error_cell(qmc_err.get('texcoord'), draco_err.get('texcoord'), 'distance_max', '%.2e'),
                             error_cell(qmc_err.get('texcoord'), draco_err.get('texcoord'), 'stretch_p99', '%.3f'))
        if has_vn:
            angle = error_cell(qmc_err.get('normal'), draco_err.get('normal'), 'angle_max_degrees', '%.3f')
        pairs.append((path.split('corpus/')[-1], len(obj[0]), out, whole_drc))
        rows.append('| %s | %d | %s | %s | %d / %d = **%.3f** | %s | %s |' %
                    (path.split('corpus/')[-1], len(obj[0]), cells[0], cells[1], info['bytes'], whole, whole_ratio,
                     uv, angle))
    times = run(decode_bench, '--runs', runs, *[f for p in pairs for f in p[2:]]).splitlines()
    print('Positions %d bits, texture coordinates %d bits, normals %d bits in both codecs. qmc codes unit normals '
          'octahedrally (spec 15.7), predicted from the positions, as Draco does; its whole files also carry the '
          'face labels (spec 16: OBJ o, g, usemtl, s) that Draco drops.' % (POSITION_BITS, TEXCOORD_BITS, NORMAL_BITS))
    print()
    print('| mesh | vertices | texcoord: qmc / Draco bytes | normal: qmc / Draco bytes | whole file: qmc / Draco | '
          'texcoord error, qmc / Draco: largest distance; stretch of 99 % of the texture area | '
          'largest normal angle error, degrees: qmc / Draco |')
    print('| --- | ---: | ---: | ---: | ---: | ---: | ---: |')
    print('\n'.join(rows))
    print()
    print('Decode of the whole files (positions, connectivity and every attribute; qmc\'s also its face labels), '
          'in process, %s interleaved rounds, median ms (`%s --runs %s` on each pair of files):' %
          (runs, os.path.relpath(decode_bench), runs))
    print()
    print('| mesh | vertices | qmc ms | Draco cl10 ms | speed-up (Draco ms / qmc ms) | >= 2 |')
    print('| --- | ---: | ---: | ---: | ---: | --- |')
    speedups = []
    for (name, vertices, _, _), line in zip(pairs, times):
        t = line.split()
        q, d = float(t[t.index('qmc_ms') + 1]), float(t[t.index('draco_ms') + 1])
        speedups.append(d / q)
        print('| %s | %d | %.3f | %.3f | %.3f | %s |' % (name, vertices, q, d, d / q, 'yes' if d / q >= 2 else '**no**'))
    print()
    for key, target in (('texcoord', 0.85), ('normal', 0.85), ('whole', 0.85)):
        r = ratios[key]
        if r:
            met = sum(1 for x in r if x <= target)
            print('- %s: qmc <= %.2fx Draco cl10 on %d of %d meshes; geometric mean %.3f.' %
                  (key, target, met, len(r), math.exp(sum(map(math.log, r)) / len(r))))
    print('- decode: qmc >= 2x Draco cl10\'s speed on %d of %d meshes; geometric mean %.3f.' %
          (sum(1 for x in speedups if x >= 2), len(speedups), math.exp(sum(map(math.log, speedups)) / len(speedups))))


if __name__ == '__main__':
    main()
