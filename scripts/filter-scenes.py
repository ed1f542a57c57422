#!/usr/bin/env python3
"""Writes the filtering benchmark's own scenes, generated here because no assets can be downloaded:

  photo.ppm       512x512 photo-like texture: soft light gradients, shapes with hard edges, and
                  value noise over seven octaves, each 0.7 of the amplitude of the one below
  photo300.ppm    the same picture at 300x200 (sides not powers of two: the general sampling path)
  head.obj        a tinyrenderer-style head: a UV sphere stretched into a skull with a brow, a nose,
                  cheeks, a chin and ears pushed out of it, 96 x 64 quads (12,288 triangles), with
                  texture coordinates wrapping the photo around it once and smooth normals (vn)
  plane.obj       a 40 x 40 m floor of two triangles, its texture repeated 20 times each way (to show
                  the photo the way the floor scene shows the grid)

Usage: scripts/filter-scenes.py OUTDIR. Then, e.g.:
  java -jar target/trisect.jar bench --obj OUTDIR/head.obj --texture OUTDIR/photo.ppm \\
      --eye 0,0.1,2.6 --target 0,0,0 --filter trilinear --modes perspective --glref /tmp/glref
"""
import math
import os
import random
import sys


def noise_layer(size, cells, rnd):
    """Value noise: a cells x cells grid of random values, smoothly interpolated, tiling."""
    grid = [[rnd.random() for _ in range(cells)] for _ in range(cells)]

    def at(x, y):
        gx = x * cells
        gy = y * cells
        i0 = int(math.floor(gx)) % cells
        j0 = int(math.floor(gy)) % cells
        fx = gx - math.floor(gx)
        fy = gy - math.floor(gy)
        fx = fx * fx * (3 - 2 * fx)
        fy = fy * fy * (3 - 2 * fy)
        i1 = (i0 + 1) % cells
        j1 = (j0 + 1) % cells
        a = grid[j0][i0] * (1 - fx) + grid[j0][i1] * fx
        b = grid[j1][i0] * (1 - fx) + grid[j1][i1] * fx
        return a * (1 - fy) + b * fy

    return at


def photo(width, height, seed=7):
    rnd = random.Random(seed)
    octaves = [(noise_layer(0, 2 << k, rnd), 0.7 ** k) for k in range(7)]
    shapes = []
    for _ in range(14):
        shapes.append((rnd.random(), rnd.random(), 0.04 + 0.16 * rnd.random(),
                       [rnd.random() for _ in range(3)], rnd.random() < 0.5))
    rows = []
    for j in range(height):
        y = (j + 0.5) / height
        row = bytearray()
        for i in range(width):
            x = (i + 0.5) / width
            n = sum(f(x, y) * a for f, a in octaves) / 2.92
            # Sky-to-ground light gradient with a warm cast, then the texture of the noise.
            r = 0.35 + 0.45 * (1 - y) + 1.4 * (n - 0.5)
            g = 0.40 + 0.30 * (1 - y) + 1.3 * (n - 0.5)
            b = 0.55 + 0.20 * (1 - y) + 1.1 * (n - 0.5) - 0.2 * y
            for cx, cy, rad, col, disc in shapes:
                dx = min(abs(x - cx), 1 - abs(x - cx))
                dy = min(abs(y - cy), 1 - abs(y - cy))
                inside = dx * dx + dy * dy < rad * rad if disc else max(dx, dy) < rad * 0.8
                if inside:
                    shade = 0.8 + 1.2 * (n - 0.5)
                    r, g, b = col[0] * shade, col[1] * shade, col[2] * shade
            for v in (r, g, b):
                row.append(max(0, min(255, int(round(v * 255)))))
        rows.append(bytes(row))
    return b"P6\n%d %d\n255\n" % (width, height) + b"".join(rows)


def bump(d2, width):
    return math.exp(-d2 / (width * width))


def head(columns=96, rows=64):
    verts = []
    uvs = []
    for j in range(rows + 1):
        v = j / rows
        theta = math.pi * (1 - v)  # 0 at the top, pi at the chin
        for i in range(columns + 1):
            u = i / columns
            phi = 2 * math.pi * u - math.pi / 2  # u = 0.25 faces the camera (+z)
            x = math.sin(theta) * math.cos(phi)
            z = -math.sin(theta) * math.sin(phi)
            y = math.cos(theta)
            # A skull: taller than wide, deeper at the back, a jaw narrowing to the chin.
            sx, sy, sz = 0.78, 1.05, 0.9
            if y < 0:
                narrow = 1 - 0.35 * (-y) ** 1.5
                sx *= narrow
                sz *= 0.9 + 0.1 * narrow
            px, py, pz = x * sx, y * sy, z * sz
            front = max(0.0, z)
            out = 0.0
            out += 0.16 * bump(x * x + (y + 0.05) ** 2, 0.12) * front          # nose
            out += 0.06 * bump(x * x + (y - 0.33) ** 2 * 4, 0.35) * front      # brow
            out += 0.05 * bump((abs(x) - 0.35) ** 2 + (y + 0.1) ** 2, 0.18) * front  # cheeks
            out += 0.07 * bump(x * x + (y + 0.75) ** 2, 0.15) * front          # chin
            out -= 0.05 * bump((abs(x) - 0.28) ** 2 + (y - 0.15) ** 2, 0.09) * front  # eye sockets
            side = max(0.0, abs(x) - 0.7)
            out += 0.35 * side * bump(z * z + (y - 0.02) ** 2, 0.22)            # ears
            n = math.sqrt(px * px + py * py + pz * pz) or 1
            verts.append((px + px / n * out, py + py / n * out, pz + pz / n * out))
            uvs.append((u, v))
    w = columns + 1
    faces = []
    for j in range(rows):
        for i in range(columns):
            a = j * w + i
            b = a + 1
            c = a + w
            d = c + 1
            # Counter-clockwise seen from outside.
            if j > 0:
                faces.append((a, c, b))
            if j < rows - 1:
                faces.append((b, c, d))
    # Smooth normals (vn), as a modelled head has: per position the sum of its faces' area-weighted
    # normals, so the seam's two columns and the poles' rows, which share positions, share a normal.
    key = [tuple(round(x, 6) for x in p) for p in verts]
    sums = {}
    for f in faces:
        p0, p1, p2 = (verts[k] for k in f)
        ux, uy, uz = (p1[m] - p0[m] for m in range(3))
        vx, vy, vz = (p2[m] - p0[m] for m in range(3))
        n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
        for k in f:
            acc = sums.setdefault(key[k], [0.0, 0.0, 0.0])
            for m in range(3):
                acc[m] += n[m]
    normals = []
    for k in key:
        n = sums.get(k, [0.0, 1.0, 0.0])
        length = math.sqrt(sum(x * x for x in n)) or 1
        normals.append(tuple(x / length for x in n))
    lines = ["# a tinyrenderer-style head, generated by scripts/filter-scenes.py"]
    lines += ["v %.6f %.6f %.6f" % p for p in verts]
    lines += ["vt %.6f %.6f" % t for t in uvs]
    lines += ["vn %.6f %.6f %.6f" % n for n in normals]
    for f in faces:
        lines.append("f " + " ".join("%d/%d/%d" % (k + 1, k + 1, k + 1) for k in f))
    return "\n".join(lines) + "\n"


def plane():
    return "\n".join([
        "# a 40 x 40 m floor, texture repeated 20 times each way; generated by scripts/filter-scenes.py",
        "v -20 0 20", "v 20 0 20", "v 20 0 -20", "v -20 0 -20",
        "vt 0 0", "vt 20 0", "vt 20 20", "vt 0 20",
        "f 1/1 2/2 3/3", "f 1/1 3/3 4/4", ""])


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: filter-scenes.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "photo.ppm"), "wb") as f:
        f.write(photo(512, 512))
    with open(os.path.join(out, "photo300.ppm"), "wb") as f:
        f.write(photo(300, 200))
    with open(os.path.join(out, "head.obj"), "w") as f:
        f.write(head())
    with open(os.path.join(out, "plane.obj"), "w") as f:
        f.write(plane())


if __name__ == "__main__":
    main()
