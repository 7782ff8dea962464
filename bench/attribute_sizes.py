#!/usr/bin/env python3
"""Attributes (spec 15, issue 16): qmc's aTTR bytes against Draco cl10's bytes
for the same attribute at the same quantization bits, per corpus mesh.

Usage: attribute_sizes.py QMC WORK_DIR MESH.obj...

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


def normal_corners(obj):
    """The input normal of every corner, in face order."""
    _, _, vn, faces = obj
    return [vn[int(c[2]) - 1] for f in faces for c in f]


def max_angle(a_list, b_list):
    worst = 0.0
    for a, b in zip(a_list, b_list):
        la, lb = math.sqrt(sum(x * x for x in a)), math.sqrt(sum(x * x for x in b))
        if la == 0 or lb == 0:
            continue
        cos = max(-1.0, min(1.0, sum(x * y for x, y in zip(a, b)) / (la * lb)))
        worst = max(worst, math.degrees(math.acos(cos)))
    return worst


def positions(v_lines):
    return [tuple(float(x) for x in line.split()[1:4]) for line in v_lines]


def normal_error(obj, decoded_obj, step):
    """Largest, over the input's corners, of the smallest angle between the
    corner's normal and a normal of a decoded vertex within 2 grid steps of
    its position (both codecs move a vertex by less than one step; several
    vertices may share a position, and a seam gives one vertex several
    normals, so the best match is taken)."""
    v, _, vn, faces = obj
    dv, _, dvn, dfaces = parse_obj(decoded_obj)
    dpos = positions(dv)
    normals_at = {}
    for f in dfaces:
        for c in f:
            normals_at.setdefault(int(c[0]) - 1, []).append(dvn[int(c[2]) - 1])
    cell = 2 * step
    grid = {}
    for i, p in enumerate(dpos):
        grid.setdefault(tuple(int(math.floor(x / cell)) for x in p), []).append(i)
    pos = positions(v)
    worst = 0.0
    for f in faces:
        for c in f:
            p = pos[int(c[0]) - 1]
            key = tuple(int(math.floor(x / cell)) for x in p)
            near = [i for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                    for i in grid.get((key[0] + dx, key[1] + dy, key[2] + dz), [])
                    if sum((a - b) ** 2 for a, b in zip(p, dpos[i])) <= cell * cell]
            normals = [d for i in near for d in normals_at.get(i, [])]
            if not normals:
                return float('nan')
            worst = max(worst, min(max_angle([vn[int(c[2]) - 1]], [d]) for d in normals))
    return worst


def main():
    qmc, work, meshes = sys.argv[1], sys.argv[2], sys.argv[3:]
    rows, ratios = [], {'texcoord': [], 'normal': [], 'whole': []}
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
        angle = '-'
        if has_vn:
            qmc_obj = os.path.join(work, name + '_qmc.obj')
            draco_obj = os.path.join(work, name + '_draco.obj')
            run(qmc, 'decode', '--quiet', out, qmc_obj)
            run('draco_decoder', '-i', whole_drc, '-o', draco_obj)
            pos = positions(obj[0])
            side = max(max(p[a] for p in pos) - min(p[a] for p in pos) for a in range(3))
            step = side / (2 ** POSITION_BITS - 1)
            angle = '%.3f / %.3f' % (normal_error(obj, qmc_obj, step), normal_error(obj, draco_obj, step))
        rows.append('| %s | %d | %s | %s | %d / %d = **%.3f** | %s |' %
                    (path.split('corpus/')[-1], len(obj[0]), cells[0], cells[1], info['bytes'], whole, whole_ratio,
                     angle))
    print('Positions %d bits, texture coordinates %d bits, normals %d bits in both codecs. qmc codes unit normals '
          'octahedrally (spec 15.7), predicted from the positions, as Draco does; its whole files also carry the '
          'face labels (spec 16: OBJ o, g, usemtl, s) that Draco drops.' % (POSITION_BITS, TEXCOORD_BITS, NORMAL_BITS))
    print()
    print('| mesh | vertices | texcoord: qmc / Draco bytes | normal: qmc / Draco bytes | whole file: qmc / Draco | '
          'largest normal angle error, degrees: qmc / Draco |')
    print('| --- | ---: | ---: | ---: | ---: | ---: |')
    print('\n'.join(rows))
    print()
    for key, target in (('texcoord', 0.85), ('normal', 0.85), ('whole', 0.85)):
        r = ratios[key]
        if r:
            met = sum(1 for x in r if x <= target)
            print('- %s: qmc <= %.2fx Draco cl10 on %d of %d meshes; geometric mean %.3f.' %
                  (key, target, met, len(r), math.exp(sum(map(math.log, r)) / len(r))))


if __name__ == '__main__':
    main()
