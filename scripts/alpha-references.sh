#!/usr/bin/env bash
# Regenerates the OpenGL references of AlphaAgainstOpenGlTest: the held scene of scripts/alpha-scene.py
# drawn by glref (Mesa llvmpipe) with its RGBA textures, alpha-tested (GLREF_ALPHA=test, test.pam) and
# blended (GLREF_ALPHA=blend, blend.pam), from each camera, kept as PNG. Needs glref
# (../shared/tools/glref; GLREF=path to use another), python3 and pnmtopng (netpbm).
#
# usage: scripts/alpha-references.sh
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${GLREF:-/tmp/glref}
OUT=src/test/resources/dev/trisect/alpha
mkdir -p "$OUT"
python3 scripts/alpha-scene.py "$OUT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# name  eye  target (the cameras are also in AlphaAgainstOpenGlTest)
while read -r name eye target; do
  for alpha in test blend; do
    GLREF_ALPHA=$alpha "$GLREF" "$OUT/panes.obj" "$OUT/$alpha.pam" "$tmp/g.ppm" \
      320 240 ${eye//,/ } ${target//,/ } 60 0.1 100 none >/dev/null
    pnmtopng "$tmp/g.ppm" > "$OUT/$name-$alpha.png"
  done
done <<'CAMERAS'
front 0,1,5 0,0.8,0
side 3,2,4 -0.5,0.6,0
CAMERAS
ls -l "$OUT"
