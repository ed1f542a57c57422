#!/usr/bin/env bash
# The border overlay's own parts for two builds (issue 15 item 4), in one JVM, interleaved: per pair
# each build renders a tessellated frame without borders, prepares the plain overlay's plans, draws
# them band by band (each band's rows read first, as drawBorders does), and renders the frame with
# borders; one thread, CPU ms. Prints per part the median of each build and B/A (median [range]),
# and what the borders add to each build's frame. Unlike side-by-side.sh, which sees the overlay only
# as the difference of two frames, this times the preparation and the drawing apart.
#
#   scripts/overlay-probe.sh A.jar B.jar [SCENE] [WxH] [POLICY] [PAIRS]
#   scripts/overlay-probe.sh /work/jars/main-3bddc29.jar target/trisect.jar demo 1920x1080 edge 30
#
# POLICY: edge (32 px edges) or error (0.5 px). Both jars must have Outlines.begin/prepare/drawBand
# and FrameRenderer's private fields outlines, geometry and drawn (builds from 3bddc29 on).
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 A.jar B.jar [scene] [WxH] [edge|error] [pairs]" >&2
  exit 2
fi
for jar in "$1" "$2"; do
  [[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
done
src=$(cd "$(dirname "$0")/overlay-probe" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
javac -d "$tmp/a" -cp "$1" "$src/Probe.java"
javac -d "$tmp/b" -cp "$2" "$src/Probe.java"
javac -d "$tmp/run" "$src/ProbePair.java"
java -cp "$tmp/run" ProbePair "$tmp/a" "$1" "$tmp/b" "$2" "${3:-demo}" "${4:-1920x1080}" "${5:-edge}" "${6:-30}"
