#!/usr/bin/env bash
# The frame-time targets of issue 16: per-pixel bilinear and trilinear frames against Mesa llvmpipe
# (glref) on the same frame, for each build given, alternating builds run by run. Each run is one
# `bench --json --modes perspective --glref` (ours: median of FRAMES frames after as many warm-up;
# llvmpipe: mean of its frames), so ours and llvmpipe's time come from the same minute of the machine.
# Prints per scene, filter and build the median ms of ours and of llvmpipe over the runs, and the
# ratio ours / llvmpipe of each run with their median.
#
#   scripts/filter-targets.sh GLREF SCENEDIR A.jar [B.jar ...]
#   REPS=3 THREADS=2 SIZE=1920x1080 scripts/filter-targets.sh /tmp/glref /tmp/scenes old.jar new.jar
#
# SCENEDIR is where scripts/filter-scenes.py wrote its files (head, plane, photo). Environment: REPS
# (default 3), THREADS (2), SIZE (1920x1080), FRAMES (40), FILTERS ("bilinear trilinear"), SCENES
# (default: demo floor boxes sphere160k head plane). Needs python3 for the summary.
set -euo pipefail
if [[ $# -lt 3 ]]; then
  echo "usage: $0 GLREF SCENEDIR A.jar [B.jar ...]" >&2
  exit 2
fi
glref=$1
dir=$2
shift 2
jars=("$@")
for jar in "${jars[@]}"; do
  [[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
done
[[ -f $dir/head.obj && -f $dir/photo.ppm ]] || { echo "$0: run scripts/filter-scenes.py $dir first" >&2; exit 2; }
reps=${REPS:-3}
threads=${THREADS:-2}
size=${SIZE:-1920x1080}
frames=${FRAMES:-40}
filters=${FILTERS:-bilinear trilinear}
scenes=${SCENES:-demo floor boxes sphere160k head plane}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
scene_args() {
  case $1 in
    head) echo "--obj $dir/head.obj --texture $dir/photo.ppm --eye 0,0.1,2.6 --target 0,0,0" ;;
    plane) echo "--obj $dir/plane.obj --texture $dir/photo.ppm --eye 0,1.5,8 --target 0,0,-5" ;;
    *) echo "--scene $1" ;;
  esac
}
for ((r = 1; r <= reps; r++)); do
  for scene in $scenes; do
    for filter in $filters; do
      for ((b = 0; b < ${#jars[@]}; b++)); do
        # shellcheck disable=SC2046
        java -jar "${jars[$b]}" bench --json --modes perspective --glref "$glref" --threads "$threads" \
          --size "$size" --frames "$frames" --warmup "$frames" --filter "$filter" $(scene_args "$scene") 2>/dev/null \
          | sed "s|^|$b $r $scene $filter |" >>"$out"
      done
    done
  done
done
python3 - "$out" "${jars[@]}" <<'EOF'
import json, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    b, r, scene, filt, text = line.split(" ", 4)
    d = json.loads(text)
    key = (scene, filt, int(b))
    slot = runs.setdefault(key, {}).setdefault(int(r), {})
    slot["ours" if d["path"] == "perspective" else "gl"] = d.get("median_ms", d.get("mean_ms"))
for i, jar in enumerate(sys.argv[2:]):
    print(f"build {i} = {jar}")
print(f"{'scene':<11}{'filter':<10}{'build':>5}{'ours ms':>9}{'llvmpipe':>9}  ours/llvmpipe per run (median)")
for (scene, filt, b), rs in runs.items():
    ours = [v["ours"] for v in rs.values() if "ours" in v and "gl" in v]
    gl = [v["gl"] for v in rs.values() if "ours" in v and "gl" in v]
    ratios = [o / g for o, g in zip(ours, gl)]
    if not ratios:
        continue
    print(f"{scene:<11}{filt:<10}{b:>5}{statistics.median(ours):9.2f}{statistics.median(gl):9.2f}  "
          + " ".join(f"{x:.2f}" for x in ratios) + f"  ({statistics.median(ratios):.2f})")
EOF
