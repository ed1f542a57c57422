#!/usr/bin/env bash
# The speed table of two builds: each of the four paths (per pixel, affine, tessellated with the
# default 32 px edges, spans at 0.5 px) with each texture filter, on demo, floor, boxes and
# sphere160k at 1920x1080, on one thread and on two.
#   One thread: scripts/side-by-side.sh (both builds in one JVM, frames interleaved, CPU time of the
#   rendering thread); the cell is the median of the per-pair B/A ratios, with their range.
#   Two threads: THREADS=2 scripts/side-by-side.sh (the same, each build's renderer on two threads,
#   the builds alternating frame by frame); the cell is the median of the per-pair B/A ratios of the
#   wall time (a pair's figure per build is the median of its frames), with their range, and a third
#   table gives the same of the CPU time of the frame's rendering threads (the calling thread and its
#   build's helpers, each by its own clock: not the compiler's or the collector's threads).
# With JVMS=n (default 1) each scene and thread count is measured in n JVMs one after the other: a
# loop's compiled speed can differ from one JVM to the next (performance.md, "Two compiled forms"),
# so one JVM's median is one draw. The cell is then the median of the n JVMs' medians, with the lowest
# and highest of those medians (not of the pairs); take n odd.
# Prints a markdown table per measure; the raw outputs stay in OUT (default a temporary folder,
# removed on exit unless OUT is given). Takes about 25 minutes per JVM on two idle cores; on a busy
# machine the ranges say how far to trust a cell.
#
#   scripts/speed-table.sh OLD.jar NEW.jar
#   PAIRS=7 FRAMES=3 PAIRS2=7 FRAMES2=9 SCENES="demo floor" OUT=/tmp/table scripts/speed-table.sh OLD.jar NEW.jar
#   JVMS=3 SCENES=boxes COUNTS=2 PATHS="perspective spans" FILTERS=nearest scripts/speed-table.sh OLD.jar NEW.jar
#
# Environment: PAIRS, FRAMES (one thread: pairs, frames per build in a pair; 7, 3), PAIRS2, FRAMES2
# (two threads: the same; 7, 9), SCENES, COUNTS (thread counts: "1 2"), PATHS ("perspective affine
# edge spans"), FILTERS ("nearest bilinear trilinear"), JVMS (1), OUT.
set -euo pipefail
. "$(dirname "$0")/two-jars.sh"
two_jars "OLD.jar NEW.jar" 2 "2" "$@"
a=$1
b=$2
here=$(cd "$(dirname "$0")" && pwd)
pairs=${PAIRS:-7}
frames=${FRAMES:-3}
pairs2=${PAIRS2:-7}
frames2=${FRAMES2:-9}
scenes=${SCENES:-demo floor boxes sphere160k}
counts=${COUNTS:-1 2}
jvms=${JVMS:-1}
[[ $jvms =~ ^[1-9][0-9]*$ ]] || { echo "$0: JVMS must be a positive whole number, not '$jvms'" >&2; exit 2; }
for c in $counts; do
  [[ $c == 1 || $c == 2 ]] || { echo "$0: COUNTS holds 1 and/or 2, not '$c'" >&2; exit 2; }
done
for p in ${PATHS:-}; do
  [[ $p =~ ^(perspective|affine|edge|spans)$ ]] \
    || { echo "$0: PATHS holds perspective, affine, edge and/or spans, not '$p'" >&2; exit 2; }
done
for f in ${FILTERS:-}; do
  [[ $f =~ ^(nearest|bilinear|trilinear)$ ]] \
    || { echo "$0: FILTERS holds nearest, bilinear and/or trilinear, not '$f'" >&2; exit 2; }
done
for n in "$pairs" "$frames" "$pairs2" "$frames2"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "$0: PAIRS, FRAMES, PAIRS2 and FRAMES2 must be positive whole numbers, not '$n'" >&2; exit 2; }
done
if [[ -n ${OUT:-} ]]; then
  mkdir -p "$OUT"
  out=$OUT
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
filters=${FILTERS:-nearest bilinear trilinear}
paths=()
for f in $filters; do
  suffix=""
  [[ $f == nearest ]] || suffix="@$f"
  for p in ${PATHS:-perspective affine edge spans}; do
    paths+=("$p$suffix")
  done
done
for scene in $scenes; do
  for ((k = 1; k <= jvms; k++)); do
    for c in $counts; do
      if [[ $c == 1 ]]; then
        THREADS=1 "$here/side-by-side.sh" "$a" "$b" "$scene" 1920x1080 "$pairs" "$frames" "${paths[@]}" \
          >"$out/one-$scene-$k.txt"
      else
        THREADS=2 "$here/side-by-side.sh" "$a" "$b" "$scene" 1920x1080 "$pairs2" "$frames2" "${paths[@]}" \
          >"$out/two-$scene-$k.txt"
      fi
    done
  done
done
python3 - "$out" "$jvms" "$counts" "$filters" $scenes <<'EOF'
import re, sys
out, jvms, counts, filters, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4].split(), sys.argv[5:]
names = {"perspective": "per pixel", "affine": "affine", "edge": "tessellated", "spans": "spans"}
order = ["per pixel", "affine", "tessellated", "spans"]

def cells(name, prefix=""):
    # One JVM: the median of the per-pair ratios [their range]; several: the median of the JVMs'
    # medians [the lowest and highest of those medians].
    found = {}
    for k in range(1, jvms + 1):
        for line in open(f"{out}/{name}-{k}.txt"):
            m = re.match(prefix + r"(\w+)(?:@(\w+))?\s+\d+\s+[\d.]+\s+[\d.]+\s+([\d.]+) \[([\d.]+)\.\.([\d.]+)\]", line)
            if m:
                found.setdefault((names[m[1]], m[2] or "nearest"), []).append((m[3], m[4], m[5]))
    cells = {}
    for key, runs in found.items():
        if jvms == 1:
            cells[key] = f"{runs[0][0]} [{runs[0][1]}–{runs[0][2]}]"
        else:
            medians = sorted((r[0] for r in runs), key=float)
            cells[key] = f"{medians[len(medians) // 2]} [{medians[0]}–{medians[-1]}]"
    return cells

across = " over JVMs" if jvms > 1 else ""
tables = []
if "1" in counts:
    tables.append(("one thread, CPU time of the rendering thread", lambda s: cells(f"one-{s}")))
if "2" in counts:
    tables.append(("two threads, wall time", lambda s: cells(f"two-{s}")))
    tables.append(("two threads, CPU time of the rendering threads", lambda s: cells(f"two-{s}", "cpu ")))
for title, read in tables:
    print(f"\n{title}: B/A median [range]{across}\n")
    print("| scene | filter | " + " | ".join(order) + " |")
    print("|---|---|" + "---|" * len(order))
    for scene in scenes:
        row = read(scene)
        for f in filters:
            print(f"| {scene} | {f} | " + " | ".join(row.get((p, f), "–") for p in order) + " |")
EOF
