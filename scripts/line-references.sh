#!/usr/bin/env bash
# Regenerates the OpenGL references of LinesAgainstOpenGlTest: the held line scene (scripts/line-scene.py)
# drawn by glref (Mesa llvmpipe, GL_LINES with GL_LEQUAL) from each camera at each line width, kept as
# one-bit masks (PBM) of the pixels in the lines' colour. Needs glref (../shared/tools/glref, built as
# its README says; GLREF=path to use another) and python3.
#
# usage: scripts/line-references.sh
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${GLREF:-/tmp/glref}
OUT=src/test/resources/dev/trisect/lines
mkdir -p "$OUT"
python3 scripts/line-scene.py "$OUT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# name  eye  target (the cameras are also in LinesAgainstOpenGlTest)
while read -r name eye target; do
  for width in 1 3; do
    GLREF_LINE_COLOUR=255,0,255 GLREF_LINE_WIDTH=$width "$GLREF" "$OUT/lines.obj" "$OUT/checker.ppm" "$tmp/g.ppm" \
      320 240 ${eye//,/ } ${target//,/ } 60 0.1 100 back >/dev/null
    python3 - "$tmp/g.ppm" "$OUT/$name-w$width.pbm" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
fields, i = [], 0
while len(fields) < 4:
    while data[i:i + 1].isspace():
        i += 1
    j = i
    while not data[j:j + 1].isspace():
        j += 1
    fields.append(data[i:j]); i = j
w, h, px = int(fields[1]), int(fields[2]), data[i + 1:]
rows = []
for y in range(h):
    bits = [px[3 * (y * w + x):3 * (y * w + x) + 3] == b'\xff\x00\xff' for x in range(w)]
    rows.append(bytes(sum(bit << (7 - k) for k, bit in enumerate(bits[b:b + 8])) for b in range(0, w, 8)))
open(sys.argv[2], 'wb').write(b"P4\n%d %d\n" % (w, h) + b"".join(rows))
PY
  done
done <<'CAMERAS'
straight 0,1.5,4 0,0.5,0
turned -1,1.6,4.2 1.3,0.4,0
low 2.5,0.3,3.5 -1,0.8,-2
CAMERAS
ls -l "$OUT"
