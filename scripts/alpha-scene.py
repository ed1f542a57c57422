#!/usr/bin/env python3
"""Writes the held transparency scene into a directory: panes.obj, panes.mtl (map_Kd panes-test.pam), and
the two RGBA textures as PAM (P7, RGB_ALPHA): test.pam (alpha 0 or 255: disks and bars cut out of a
coloured checker) and blend.pam (the same colours with alpha from 0 to 255 in a ramp).

Five textured quads that do not overlap one another on screen from the cameras of
scripts/alpha-references.sh: one facing the camera, two turned, one on the floor seen at a grazing
angle, one far away, so that every path's interpolation is at work. Deterministic.

usage: alpha-scene.py DIR
"""
import os
import sys

SIZE = 64


def texel(x, y):
    """The colour of texel (x, y), row 0 at the top."""
    cell = (x // 8 + y // 8) % 2
    return (200, 60 + 3 * x, 40) if cell else (30, 90, 160 + y)


def pam(path, alpha):
    rows = []
    for y in range(SIZE):
        for x in range(SIZE):
            r, g, b = texel(x, y)
            rows.append(bytes((r, g, b, alpha(x, y))))
    with open(path, 'wb') as o:
        o.write(b"P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n" % (SIZE, SIZE))
        o.write(b"".join(rows))


def cut(x, y):
    """A cut-out: disks of radius 11 around two centres and a bar, alpha 255; elsewhere 0."""
    inside = (x - 20) ** 2 + (y - 22) ** 2 < 121 or (x - 44) ** 2 + (y - 40) ** 2 < 121 or 28 <= x < 34
    return 255 if inside else 0


def ramp(x, y):
    return min(255, (x * 4 + y * 2) * 255 // (4 * 63 + 2 * 63) + (30 if y % 16 < 8 else 0))


def scene(directory):
    quads = [
        [(-2.6, 0.2, 0), (-1.2, 0.2, 0), (-1.2, 1.6, 0), (-2.6, 1.6, 0)],
        [(-0.8, 0.2, 0.4), (0.4, 0.2, -0.3), (0.4, 1.6, -0.3), (-0.8, 1.6, 0.4)],
        [(0.9, 0.3, -0.6), (2.3, 0.1, 0.3), (2.3, 1.5, 0.4), (0.9, 1.7, -0.5)],
        [(-3, -0.6, 2.5), (3, -0.6, 2.5), (3, -0.6, 0.6), (-3, -0.6, 0.6)],
        [(-0.6, 2.2, -8), (0.6, 2.2, -8), (0.6, 3.4, -8), (-0.6, 3.4, -8)],
    ]
    uvs = [(0, 0), (1, 0), (1, 1), (0, 1)]
    with open(os.path.join(directory, "panes.obj"), 'w') as o:
        o.write("mtllib panes.mtl\nusemtl pane\n")
        for q in quads:
            o.writelines("v %g %g %g\n" % p for p in q)
        for q in quads:
            o.writelines("vt %g %g\n" % t for t in uvs)
        for k in range(len(quads)):
            a = 4 * k
            o.write("f %d/%d %d/%d %d/%d\n" % (a + 1, a + 1, a + 2, a + 2, a + 3, a + 3))
            o.write("f %d/%d %d/%d %d/%d\n" % (a + 1, a + 1, a + 3, a + 3, a + 4, a + 4))
    with open(os.path.join(directory, "panes.mtl"), 'w') as o:
        o.write("newmtl pane\nmap_Kd test.pam\n")
    pam(os.path.join(directory, "test.pam"), cut)
    pam(os.path.join(directory, "blend.pam"), ramp)


if __name__ == "__main__":
    scene(sys.argv[1])
