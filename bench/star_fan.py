#!/usr/bin/env python3
"""A fan of SPOKES triangles around one vertex, written as OBJ, whose centre
corners each have a texture coordinate of their own (each rim vertex one for
both its corners): a valid mesh of 2 SPOKES (vertex, texture coordinate)
pairs in which one vertex meets SPOKES values. docs/results/hardening.md
times what splitting it for drawing costs (qmc_decoder_split_mesh, QMCLoader).

  bench/star_fan.py SPOKES OUT.obj
"""
import math
import sys


def main():
    spokes, out = int(sys.argv[1]), sys.argv[2]
    with open(out, 'w') as f:
        f.write('v 0 0 0.5\n')
        ring = [(math.cos(2 * math.pi * i / spokes), math.sin(2 * math.pi * i / spokes)) for i in range(spokes)]
        for x, y in ring:
            f.write(f'v {x:.6f} {y:.6f} 0\n')
        for x, y in ring:  # the centre's corners: vt 1 .. SPOKES
            f.write(f'vt {0.5 + 0.01 * x:.6f} {0.5 + 0.01 * y:.6f}\n')
        for x, y in ring:  # the rim's: vt SPOKES + 1 .. 2 SPOKES
            f.write(f'vt {0.5 + 0.5 * x:.6f} {0.5 + 0.5 * y:.6f}\n')
        for i in range(spokes):
            j = (i + 1) % spokes
            f.write(f'f 1/{i + 1} {i + 2}/{spokes + i + 1} {j + 2}/{spokes + j + 1}\n')


if __name__ == '__main__':
    main()
