#!/usr/bin/env python3
"""An experiment for texture coordinates (spec 15): how far parallelogram
prediction over the attribute mesh, what coding 0 builds on, lands from the
value, against a prediction guided by the mesh's own triangle.

Geometry-guided: for a value c of a triangle (a, b, c) whose a and b values
are known, c's position is split into its projection on the edge a-b
(t = (e.f) / (e.e), e = P_b - P_a, f = P_c - P_a) and its distance from the
edge relative to the edge's length (|e x f| / (e.e)); the same split is laid
on the edge's UV vector d = uv_b - uv_a and its perpendicular, on the side
away from the third value x of a known triangle across the edge (+ without
one). Parallelogram: a + b - x, the edge's midpoint without x.

A proxy, not the coder: positions on a 14-bit and values on a 12-bit grid
(one step for all axes, as in the benchmarks), faces fan-triangulated, values
visited in the order faces first name them (not the coder's order), a value
predicted only when a triangle of it has both other values known (the
others are left out of both columns). Each column: bits per predicted value
by the zeroth-order entropy of the residuals (both axes in one alphabet),
by an Elias-gamma length of each residual, and the mean |residual| (L1).

  bench/uv_prediction.py MESH.obj...   prints a Markdown table (meshes with
                                       texture coordinates only)
"""
import collections
import math
import sys


def load_obj(path):
    positions, uvs, triangles = [], [], []
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == 'v':
            positions.append(tuple(map(float, t[1:4])))
        elif t[0] == 'vt':
            uvs.append(tuple(map(float, t[1:3])))
        elif t[0] == 'f':
            corners = []
            for c in t[1:]:
                p = c.split('/')
                v, u = int(p[0]), int(p[1]) if len(p) > 1 and p[1] else 0
                corners.append((v - 1 if v > 0 else len(positions) + v, u - 1 if u > 0 else len(uvs) + u))
            if any(u < 0 for _, u in corners):
                continue
            for i in range(1, len(corners) - 1):
                tri = (corners[0], corners[i], corners[i + 1])
                triangles.append((tuple(c[0] for c in tri), tuple(c[1] for c in tri)))
    return positions, uvs, triangles


def quantize(values, bits):
    n = len(values[0])
    lo = [min(v[i] for v in values) for i in range(n)]
    side = max(max(v[i] for v in values) - lo[i] for i in range(n))
    step = side / ((1 << bits) - 1) or 1.0
    return [tuple(int(round((v[i] - lo[i]) / step)) for i in range(n)) for v in values]


def geometry_guided(P, U, ta, tb, pa, pb, pc, tx):
    e = [P[pb][i] - P[pa][i] for i in range(3)]
    f = [P[pc][i] - P[pa][i] for i in range(3)]
    ee = sum(x * x for x in e)
    if ee == 0:
        return None
    ef = sum(x * y for x, y in zip(e, f))
    cross = (e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0])
    t, s = ef / ee, math.sqrt(sum(x * x for x in cross)) / ee
    d = (U[tb][0] - U[ta][0], U[tb][1] - U[ta][1])
    perpendicular = (-d[1], d[0])
    side = 1
    if tx is not None and (U[tx][0] - U[ta][0]) * perpendicular[0] + (U[tx][1] - U[ta][1]) * perpendicular[1] > 0:
        side = -1
    return tuple(U[ta][k] + t * d[k] + side * s * perpendicular[k] for k in range(2))


def residuals(path):
    positions, uvs, triangles = load_obj(path)
    if not uvs or not triangles:
        return None
    P, U = quantize(positions, 14), quantize(uvs, 12)
    across = collections.defaultdict(list)  # uv edge -> third uv of each triangle
    for _, t in triangles:
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            across[(min(a, b), max(a, b))].append(t[(i + 2) % 3])
    known, parallelogram, guided, without_across = set(), [], [], 0
    for v, t in triangles:
        for i in range(3):
            c, a, b = t[i], t[(i + 1) % 3], t[(i + 2) % 3]
            if c in known:
                continue
            if a in known and b in known:
                xs = [x for x in across[(min(a, b), max(a, b))] if x != c and x in known]
                x = xs[0] if xs else None
                without_across += x is None
                mid = ((U[a][0] + U[b][0]) / 2, (U[a][1] + U[b][1]) / 2)
                p = mid if x is None else (U[a][0] + U[b][0] - U[x][0], U[a][1] + U[b][1] - U[x][1])
                g = geometry_guided(P, U, a, b, v[(i + 1) % 3], v[(i + 2) % 3], v[i], x) or p
                for k in range(2):
                    parallelogram.append(U[c][k] - int(round(p[k])))
                    guided.append(U[c][k] - int(round(g[k])))
            known.add(c)
    return len(uvs), len(parallelogram) // 2, without_across, parallelogram, guided


def entropy_bits(values):
    n = len(values)
    return -sum(k * math.log2(k / n) for k in collections.Counter(values).values())


def gamma_bits(values):
    return sum(2 * abs(r).bit_length() + 1 for r in values)


def main():
    print('| mesh | values | predicted (without a known triangle across) | entropy bits/value: parallelogram / '
          'guided | Elias-gamma bits/value: parallelogram / guided | mean L1: parallelogram / guided |')
    print('| --- | ---: | ---: | ---: | ---: | ---: |')
    for path in sys.argv[1:]:
        measured = residuals(path)
        if measured is None:  # no texture coordinates
            continue
        count, n, without, par, gui = measured
        if n == 0:
            print('| %s | %d | 0 | - | - | - |' % (path.split('/')[-1], count))
            continue
        print('| %s | %d | %d (%d) | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f |' % (
            path.split('/')[-1], count, n, without, entropy_bits(par) / n, entropy_bits(gui) / n,
            gamma_bits(par) / n, gamma_bits(gui) / n, sum(map(abs, par)) / n, sum(map(abs, gui)) / n))


if __name__ == '__main__':
    main()
