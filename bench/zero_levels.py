#!/usr/bin/env python3
"""Writes a valid progressive file (spec 12) whose levels all have zero
displacements: about one bit of input per edge point, so each level costs
little input and much output. It measures what spec 8.1's limits bound.

usage: zero_levels.py QMC MESH.off K OUT.qmc
The base mesh is MESH (a closed or bordered manifold triangle mesh) coded by
`QMC encode --connectivity indexed`."""
import os
import struct
import subprocess
import sys
import tempfile
import zlib


def chunks(data):
    pos, out = 8, []
    while pos < len(data):
        length = struct.unpack('<I', data[pos + 4:pos + 8])[0]
        out.append((data[pos:pos + 4], data[pos + 8:pos + 8 + length]))
        pos += 12 + length
    return out


def frame(kind, payload):  # spec 3.2, 3.4
    head = kind + struct.pack('<I', len(payload))
    return head + payload + struct.pack('<I', zlib.crc32(head + payload))


def varint(v):  # spec 2.1
    out = bytearray()
    while True:
        low, v = v & 0x7F, v >> 7
        out.append(low | (0x80 if v else 0))
        if not v:
            return bytes(out)


def off_triangles(path):
    words = [w for line in open(path) for w in line.split('#')[0].split()]
    assert words[0] == 'OFF'
    nv, nf = int(words[1]), int(words[2])
    at = 4 + 3 * nv
    faces = []
    for _ in range(nf):
        assert words[at] == '3', 'triangles only'
        faces.append([int(w) for w in words[at + 1:at + 4]])
        at += 4
    return faces


def main(qmc, mesh, levels, out):
    with tempfile.TemporaryDirectory() as tmp:
        base = os.path.join(tmp, 'base.qmc')
        subprocess.run([qmc, 'encode', mesh, base, '--connectivity', 'indexed', '--quiet'], check=True)
        data = open(base, 'rb').read()
    parts = dict(chunks(data))
    faces = off_triangles(mesh)
    edges = len({tuple(sorted((f[i], f[(i + 1) % 3]))) for f in faces for i in range(3)})
    face_count = len(faces)
    body = [frame(b'QHDR', bytes([1, 3])), frame(b'LOOP', bytes([levels, 0])),
            frame(b'CONN', parts[b'CONN']), frame(b'POSN', parts[b'POSN'])]
    for j in range(1, levels + 1):  # spec 12.1, 12.7: every displacement the 1-bit zero
        payload = bytes([j, 0]) + varint(edges) + struct.pack('<d', 1.0) + bytes((edges + 7) // 8)
        body.append(frame(b'LEVL', payload))
        edges, face_count = 2 * edges + 3 * face_count, 4 * face_count  # spec 12.5
    body.append(frame(b'QEND', b''))
    open(out, 'wb').write(data[:8] + b''.join(body))


if __name__ == '__main__':
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4])
