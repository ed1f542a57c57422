#!/usr/bin/env bash
# The speed table of two builds: each of the four paths (per pixel, affine, tessellated with the
# default 32 px edges, spans at 0.5 px) with each texture filter, on demo, floor, boxes and
# sphere160k at 1920x1080, on one thread and on two.
#   One thread: scripts/side-by-side.sh (both builds in one JVM, frames interleaved, CPU time of the
#   rendering thread); the cell is the median of the per-pair B/A ratios, with their range.
#   Two threads: scripts/compare-builds.sh (bench --json of each build in turn, wall time); the cell
#   is the median of the per-run B/A ratios, with their range.
# Prints a markdown table per thread count; the raw outputs stay in OUT (default a temporary folder,
# removed on exit unless OUT is given). Takes about 20 minutes on two idle cores; on a busy machine
# the ranges say how far to trust a cell.
#
#   scripts/speed-table.sh OLD.jar NEW.jar
#   PAIRS=7 FRAMES=3 REPS=3 SCENES="demo floor" OUT=/tmp/table scripts/speed-table.sh OLD.jar NEW.jar
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
reps=${REPS:-3}
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
  for f in "${filters[@]}"; do
    REPS=$reps "$here/compare-builds.sh" "$a" "$b" --scene "$scene" --size 1920x1080 --threads 2 \
      --filter "$f" --frames 30 --warmup 30 --modes perspective,affine,tessellated,spans \
      >"$out/two-$scene-$f.txt"
  done
done
python3 - "$out" $scenes <<'EOF'
import re, statistics, sys
out, scenes = sys.argv[1], sys.argv[2:]
filters = ["nearest", "bilinear", "trilinear"]
names = {"perspective": "per pixel", "affine": "affine", "edge": "tessellated",
         "tessellated": "tessellated", "spans": "spans"}
order = ["per pixel", "affine", "tessellated", "spans"]

def one(scene):
    cells = {}
    for line in open(f"{out}/one-{scene}.txt"):
        m = re.match(r"(\w+)(?:@(\w+))?\s+\d+\s+[\d.]+\s+[\d.]+\s+([\d.]+) \[([\d.]+)\.\.([\d.]+)\]", line)
        if m:
            cells[(names[m[1]], m[2] or "nearest")] = f"{m[3]} [{m[4]}–{m[5]}]"
    return cells

def two(scene):
    cells = {}
    for f in filters:
        for line in open(f"{out}/two-{scene}-{f}.txt"):
            parts = line.split(")")
            path = line.split()[0] if line.strip() else ""
            if path in names and len(parts) == 3:
                ratios = [float(x) for x in parts[2].split()]
                if ratios:
                    cells[(names[path], f)] = (f"{statistics.median(ratios):.2f} "
                                               f"[{min(ratios):.2f}–{max(ratios):.2f}]")
    return cells

for title, read in (("one thread, CPU time, side by side", one), ("two threads, wall time, runs alternated", two)):
    print(f"\n{title}: B/A median [range]\n")
    print("| scene | filter | " + " | ".join(order) + " |")
    print("|---|---|" + "---|" * len(order))
    for scene in scenes:
        cells = read(scene)
        for f in filters:
            print(f"| {scene} | {f} | " + " | ".join(cells.get((p, f), "–") for p in order) + " |")
EOF
