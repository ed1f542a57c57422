#!/usr/bin/env bash
# How far the span path's one level of detail per segment (and the tessellated path's one per piece,
# --split error --max-error 0.5) is from OpenGL's exact per-pixel lambda, both clamped to the levels a
# trilinear sample blends, on demo, floor, boxes and sphere: every 2nd pixel of every 2nd row, found
# through FrameRecord.pieceAt and knotsAt (one pixel at a time: slow at 1920x1080, a minute or two).
# Prints max, p99, p99.9 and mean, in levels. Needs target/classes (mvn -q compile).
#
#   scripts/span-lod.sh [W H]          (default 480 270)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
javac -d "$tmp" -cp "$root/target/classes" "$root/scripts/span-lod/LodDeviation.java"
java -cp "$root/target/classes:$tmp" LodDeviation "${1:-480}" "${2:-270}"
