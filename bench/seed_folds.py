#!/usr/bin/env python3
"""A skirt's placement with k folds seeded in it, for cold-drape experiments
(bench/drape_bench.txt, session 42).

Each vertex moves outward from the garment's vertical axis (through the mean of its vertices,
y up) by  amplitude * w * (1 + sin(k * theta)) / 2,  where theta is its angle around the axis
and w = (top - y) / (top - bottom) grows from 0 at the waist (the pins, which stay put) to 1 at
the hem. Outward only, so a placement clear of the body stays clear. Only `v` lines change.

    bench/seed_folds.py GARMENT.obj OUT.obj K [AMPLITUDE_M]      (amplitude 0.01 m by default)
    bench/cold_paths.sh D/scene.xml 3 --start OUT.obj
"""
import math
import sys


def seeded(lines, k, amplitude):
    vertices = [[float(t) for t in line.split()[1:4]] for line in lines if line.startswith("v ")]
    if not vertices:
        sys.exit("seed_folds.py: no vertices")
    top = max(v[1] for v in vertices)
    bottom = min(v[1] for v in vertices)
    cx = sum(v[0] for v in vertices) / len(vertices)
    cz = sum(v[2] for v in vertices) / len(vertices)
    out = []
    for line in lines:
        if not line.startswith("v "):
            out.append(line)
            continue
        fields = line.split()
        x, y, z = (float(t) for t in fields[1:4])
        r = math.hypot(x - cx, z - cz)
        if r > 0 and top > bottom:
            w = (top - y) / (top - bottom)
            move = amplitude * w * 0.5 * (1 + math.sin(k * math.atan2(z - cz, x - cx)))
            x += move * (x - cx) / r
            z += move * (z - cz) / r
        out.append(" ".join(["v", repr(x), repr(y), repr(z)] + fields[4:]))
    return out


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit("usage: bench/seed_folds.py GARMENT.obj OUT.obj K [AMPLITUDE_M]")
    k = int(sys.argv[3])
    amplitude = float(sys.argv[4]) if len(sys.argv) == 5 else 0.01
    with open(sys.argv[1]) as f:
        lines = f.read().split("\n")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(seeded(lines, k, amplitude)))


if __name__ == "__main__":
    main()
