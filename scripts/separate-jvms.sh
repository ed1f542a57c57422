#!/usr/bin/env bash
# Compares two builds over many JVMs: RUNS JVMs of each build, alternating A B A B ..., each
# warming up the paths in the order given and then timing each path (median CPU ms per frame of the
# rendering thread, one thread). Prints every run's line, then per path the median over runs of
# each build, their range, and B/A of the medians.
#
# Why: one JVM's JIT decides some loops' speed for the whole run. The nearest affine fixed-point
# loop, for one, runs in two modes ~2x apart on the floor scene (C2's compiled code, not memory
# layout: the mode holds for freshly allocated frames and textures in the same JVM, in both builds),
# so scripts/side-by-side.sh, whose two builds each get one compile in one JVM, can report a
# ratio from either mode pairing. Many JVMs show the distribution of modes instead.
#
#   scripts/separate-jvms.sh OLD.jar NEW.jar [SCENE] [WxH] [RUNS] [PATH...]
#   RUNS=8: scripts/separate-jvms.sh /tmp/old.jar target/trisect.jar floor 1920x1080 8 perspective affine edge error
#
# PATH as for side-by-side.sh (edge, error@trilinear, edge+borders, ...). Environment: WARMUP
# (frames per path before timing, default 40), FRAMES (timed frames per path, default 25).
set -euo pipefail
. "$(dirname "$0")/two-jars.sh"
two_jars "A.jar B.jar [scene] [WxH] [runs] [path...]" 2 "" "$@"
a=$1
b=$2
scene=${3:-demo}
size=${4:-1920x1080}
runs=${5:-8}
shift $(( $# < 5 ? $# : 5 ))
paths=("$@")
[[ ${#paths[@]} -gt 0 ]] || paths=(perspective affine edge error)
warmup=${WARMUP:-40}
frames=${FRAMES:-25}
src=$(cd "$(dirname "$0")/side-by-side" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$src/frame-for.sh"
frame_for "$a" "$tmp/a"
frame_for "$b" "$tmp/b"
javac -sourcepath "$src" -d "$tmp/run" "$src/OneBuild.java"
echo "$scene $size, one thread, CPU ms per frame (median of $frames after $warmup warm-up frames per path), $runs JVMs per build"
echo "A = $a"
echo "B = $b"
for ((r = 1; r <= runs; r++)); do
  for side in A B; do
    jar=$a
    dir=$tmp/a
    [[ $side == B ]] && { jar=$b; dir=$tmp/b; }
    echo "$side $r $(java -cp "$tmp/run" OneBuild "$dir" "$jar" "$scene" "$size" "$warmup" "$frames" "${paths[@]}")"
  done
done | tee "$tmp/runs.txt"
python3 - "$tmp/runs.txt" <<'PY'
import statistics, sys
data = {}
for line in open(sys.argv[1]):
    side, run, *pairs = line.split()
    for pair in pairs:
        path, ms = pair.split("=")
        data.setdefault(path, {}).setdefault(side, []).append(float(ms))
print(f"{'path':<22}{'A median [range]':<26}{'B median [range]':<26}B/A of medians")
for path, sides in data.items():
    a, b = sides["A"], sides["B"]
    ma, mb = statistics.median(a), statistics.median(b)
    print(f"{path:<22}{f'{ma:.2f} [{min(a):.2f}..{max(a):.2f}]':<26}{f'{mb:.2f} [{min(b):.2f}..{max(b):.2f}]':<26}{mb / ma:.3f}")
PY
