#!/usr/bin/env bash
# The speed table of two builds: each of the four paths (per pixel, affine, tessellated with the
# default 32 px edges, spans at 0.5 px) with each texture filter, on demo, floor, boxes and
# sphere160k at 1920x1080, on one thread and on two.
#   One thread: scripts/side-by-side.sh (both builds in one JVM, frames interleaved, CPU time of the
#   rendering thread); the cell is the median of the per-pair B/A ratios, with their range.
#   Two threads: THREADS=2 scripts/side-by-side.sh (the same, each build's renderer on two threads,
#   the builds alternating frame by frame); the cell is the median of the per-pair B/A ratios of the
#   wall time (a pair's figure per build is the median of its frames), with their range, and a third
#   table gives the same of the CPU time of all threads.
# Prints a markdown table per measure; the raw outputs stay in OUT (default a temporary folder,
# removed on exit unless OUT is given). Takes about 25 minutes on two idle cores; on a busy machine
# the ranges say how far to trust a cell.
#
#   scripts/speed-table.sh OLD.jar NEW.jar
#   PAIRS=7 FRAMES=3 PAIRS2=7 FRAMES2=9 SCENES="demo floor" OUT=/tmp/table scripts/speed-table.sh OLD.jar NEW.jar
#
# Environment: PAIRS, FRAMES (one thread: pairs, frames per build in a pair; 7, 3), PAIRS2, FRAMES2
# (two threads: the same; 7, 9), SCENES, OUT.
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: $0 OLD.jar NEW.jar" >&2
  exit 2
fi
a=$1
b=$2
for jar in "$a" "$b"; do
  [[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
done
here=$(cd "$(dirname "$0")" && pwd)
pairs=${PAIRS:-7}
frames=${FRAMES:-3}
pairs2=${PAIRS2:-7}
frames2=${FRAMES2:-9}
scenes=${SCENES:-demo floor boxes sphere160k}
if [[ -n ${OUT:-} ]]; then
  mkdir -p "$OUT"
  out=$OUT
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
filters=(nearest bilinear trilinear)
for scene in $scenes; do
  paths=()
  for f in "${filters[@]}"; do
    suffix=""
    [[ $f == nearest ]] || suffix="@$f"
    paths+=("perspective$suffix" "affine$suffix" "edge$suffix" "spans$suffix")
  done
  "$here/side-by-side.sh" "$a" "$b" "$scene" 1920x1080 "$pairs" "$frames" "${paths[@]}" \
    >"$out/one-$scene.txt"
  THREADS=2 "$here/side-by-side.sh" "$a" "$b" "$scene" 1920x1080 "$pairs2" "$frames2" "${paths[@]}" \
    >"$out/two-$scene.txt"
done
python3 - "$out" $scenes <<'EOF'
import re, sys
out, scenes = sys.argv[1], sys.argv[2:]
filters = ["nearest", "bilinear", "trilinear"]
names = {"perspective": "per pixel", "affine": "affine", "edge": "tessellated", "spans": "spans"}
order = ["per pixel", "affine", "tessellated", "spans"]

def cells(file, prefix=""):
    cells = {}
    for line in open(file):
        m = re.match(prefix + r"(\w+)(?:@(\w+))?\s+\d+\s+[\d.]+\s+[\d.]+\s+([\d.]+) \[([\d.]+)\.\.([\d.]+)\]", line)
        if m:
            cells[(names[m[1]], m[2] or "nearest")] = f"{m[3]} [{m[4]}–{m[5]}]"
    return cells

tables = (("one thread, CPU time of the rendering thread", lambda s: cells(f"{out}/one-{s}.txt")),
          ("two threads, wall time", lambda s: cells(f"{out}/two-{s}.txt")),
          ("two threads, CPU time of all threads", lambda s: cells(f"{out}/two-{s}.txt", "cpu ")))
for title, read in tables:
    print(f"\n{title}: B/A median [range]\n")
    print("| scene | filter | " + " | ".join(order) + " |")
    print("|---|---|" + "---|" * len(order))
    for scene in scenes:
        row = read(scene)
        for f in filters:
            print(f"| {scene} | {f} | " + " | ".join(row.get((p, f), "–") for p in order) + " |")
EOF
