#!/usr/bin/env python3
"""Agreement of two renders over their covered pixels, for scripts/compare-with-opengl.sh.

  within.py ours.ppm reference.ppm ours.pfm reference.pfm

Prints one JSON line: covered_pixels (drawn by either render: a non-zero triangle id in either UV
output), within_2_share (the share of those whose every colour channel is within 2/255 of the
reference's) and psnr_covered_db (PSNR of the colour over those pixels, peak 255). Plain Python,
binary PPM (P6) and PFM (PF, three floats a pixel: s, t, triangle id + 1) only.
"""
import json
import math
import struct
import sys


def tokens(data, count):
    """The first `count` whitespace-separated header fields and the offset after them (one byte past)."""
    out = []
    i = 0
    while len(out) < count:
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        out.append(data[i:j].decode("ascii"))
        i = j
    return out, i + 1


def ppm(path):
    data = open(path, "rb").read()
    (magic, w, h, maxval), start = tokens(data, 4)
    if magic != "P6" or maxval != "255":
        sys.exit(f"{path}: not an 8-bit binary PPM")
    return int(w), int(h), data[start:start + 3 * int(w) * int(h)]


def pfm_ids(path):
    """Triangle id + 1 per pixel, rows from the top (PFM stores them from the bottom)."""
    data = open(path, "rb").read()
    (magic, w, h, scale), start = tokens(data, 4)
    if magic != "PF":
        sys.exit(f"{path}: not a colour PFM")
    w, h = int(w), int(h)
    endian = "<" if float(scale) < 0 else ">"
    floats = struct.unpack(endian + "%df" % (3 * w * h), data[start:start + 12 * w * h])
    ids = [0] * (w * h)
    for y in range(h):
        src = (h - 1 - y) * w
        for x in range(w):
            ids[y * w + x] = floats[3 * (src + x) + 2]
    return w, h, ids


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    w, h, ours = ppm(sys.argv[1])
    w2, h2, ref = ppm(sys.argv[2])
    _, _, ids = pfm_ids(sys.argv[3])
    _, _, ref_ids = pfm_ids(sys.argv[4])
    if (w, h) != (w2, h2):
        sys.exit("sizes differ")
    covered = 0
    within = 0
    squared = 0
    for i in range(w * h):
        if ids[i] == 0 and ref_ids[i] == 0:
            continue
        covered += 1
        k = 3 * i
        d = max(abs(ours[k] - ref[k]), abs(ours[k + 1] - ref[k + 1]), abs(ours[k + 2] - ref[k + 2]))
        if d <= 2:
            within += 1
        squared += (ours[k] - ref[k]) ** 2 + (ours[k + 1] - ref[k + 1]) ** 2 + (ours[k + 2] - ref[k + 2]) ** 2
    mse = squared / (3 * covered) if covered else 0
    psnr = 10 * math.log10(255 * 255 / mse) if mse > 0 else float("inf")
    print(json.dumps({"covered_pixels": covered, "within_2_share": within / covered if covered else 1,
                      "psnr_covered_db": round(psnr, 2)}))


if __name__ == "__main__":
    main()
