#!/usr/bin/env python3
"""Writes the held line scene (lines.obj, lines.mtl, checker.ppm) into a directory.

A textured floor and a tilted wall, with magenta lines (Kd 1 0 1): a grid on the floor and lines on the
wall (lines on faces), floating polylines (depth-tested against the faces) and segments from behind the
camera to in front of it (crossing the near plane for the cameras of scripts/line-references.sh).
Deterministic: the same files every time.

usage: line-scene.py DIR
"""
import os
import random
import sys


def scene(path, seed=1, floating=40):
    r = random.Random(seed)
    v, vt, faces, lines = [], [], [], []

    def vertex(x, y, z):
        v.append((x, y, z))
        return len(v)

    a, b, c, d = vertex(-10, 0, 10), vertex(10, 0, 10), vertex(10, 0, -10), vertex(-10, 0, -10)
    vt.extend([(0, 0), (10, 0), (10, 10), (0, 10)])
    faces += [((a, 1), (b, 2), (c, 3)), ((a, 1), (c, 3), (d, 4))]
    e, g, h, i = vertex(-2, 0, -2), vertex(2, 0, -2), vertex(2, 2.5, -3), vertex(-2, 2.5, -3)
    vt.extend([(0, 0), (2, 0), (2, 2), (0, 2)])
    faces += [((e, 5), (g, 6), (h, 7)), ((e, 5), (h, 7), (i, 8))]
    for k in range(-4, 5):
        lines.append([vertex(k * 0.7, 0, 3), vertex(k * 0.9 + 0.13, 0, -6)])
        lines.append([vertex(-5, 0, k * 0.8 - 1.1), vertex(5, 0, k * 0.6 - 1.3)])
    for k in range(5):
        t = 0.15 + 0.17 * k
        lines.append([vertex(-2, 2.5 * t, -2 - t), vertex(2, 2.5 * t, -2 - t)])
        lines.append([vertex(-1.6 + 0.8 * k, 0, -2), vertex(-1.6 + 0.8 * k, 2.5, -3)])
    for _ in range(floating):
        lines.append([vertex(r.uniform(-4, 4), r.uniform(0.05, 3), r.uniform(-6, 3))
                      for _ in range(r.choice([2, 2, 3, 4]))])
    for _ in range(6):
        lines.append([vertex(r.uniform(-1, 1), r.uniform(0.8, 2.2), 5.5), vertex(r.uniform(-3, 3), r.uniform(0, 2), -4)])
    with open(path, 'w') as o:
        o.write("mtllib lines.mtl\n")
        o.writelines("v %g %g %g\n" % p for p in v)
        o.writelines("vt %g %g\n" % t for t in vt)
        o.write("usemtl floor\n")
        o.writelines("f " + " ".join("%d/%d" % c for c in f) + "\n" for f in faces)
        o.write("usemtl ink\n")
        o.writelines("l " + " ".join(str(x) for x in p) + "\n" for p in lines)


def main():
    out = sys.argv[1]
    scene(os.path.join(out, "lines.obj"))
    with open(os.path.join(out, "lines.mtl"), 'w') as o:
        o.write("newmtl floor\nmap_Kd checker.ppm\nnewmtl ink\nKd 1 0 1\n")
    n, cell = 64, 8
    with open(os.path.join(out, "checker.ppm"), 'wb') as o:
        o.write(b"P6\n%d %d\n255\n" % (n, n))
        for y in range(n):
            o.write(b"".join(bytes([200, 200, 90] if ((x // cell) + (y // cell)) % 2 else [40, 90, 160])
                             for x in range(n)))


if __name__ == "__main__":
    main()
