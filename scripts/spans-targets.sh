#!/usr/bin/env bash
# The span path's frame-time targets (issue 15): spans at --max-error 0.5 against the per-pixel path
# of the same build (nearest: at most 1.0x; trilinear: at most 0.8x) and, with trilinear, against Mesa
# llvmpipe on the same frame (at most 0.6x), with the tessellated path (--split error --max-error 0.5)
# beside them. Each run is one `bench --json` of all three paths (median of FRAMES frames after as many
# warm-up; llvmpipe: mean of its frames), so the ratios of a run come from the same minute of the
# machine. Prints per scene and filter the median ms of each path over the runs and the ratios of
# each run with their median.
#
#   scripts/spans-targets.sh JAR [GLREF]
#   REPS=5 THREADS=2 SIZE=1920x1080 scripts/spans-targets.sh target/trisect.jar /tmp/glref
#
# Scenes (SCENES, default "demo floor boxes sphere sphere160k floor-rolled demo-rolled"): the
# built-in ones, and floor-rolled / demo-rolled, the same with the camera rolled (--up 0.5,1,0), so
# that depth changes along every row (glref always uses up = 0,1,0: no llvmpipe figure for those).
# Environment: REPS (3), THREADS (2), SIZE (1920x1080), FRAMES (40), FILTERS ("nearest trilinear").
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 JAR [GLREF]" >&2
  exit 2
fi
jar=$1
glref=${2:-}
[[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
reps=${REPS:-3}
threads=${THREADS:-2}
size=${SIZE:-1920x1080}
frames=${FRAMES:-40}
filters=${FILTERS:-nearest trilinear}
scenes=${SCENES:-demo floor boxes sphere sphere160k floor-rolled demo-rolled}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for ((r = 1; r <= reps; r++)); do
  for scene in $scenes; do
    for filter in $filters; do
      args=(--scene "${scene%-rolled}")
      [[ $scene == *-rolled ]] && args+=(--up 0.5,1,0)
      [[ $filter == trilinear && -n $glref && $scene != *-rolled ]] && args+=(--glref "$glref")
      java -jar "$jar" bench --json --modes perspective,spans,tessellated --split error --max-error 0.5 \
        --threads "$threads" --size "$size" --frames "$frames" --warmup "$frames" --filter "$filter" "${args[@]}" \
        2>/dev/null | sed "s|^|$r $scene $filter |" >>"$out"
    done
  done
done
python3 - "$out" "$jar" <<'PY'
import json, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    r, scene, filt, text = line.split(" ", 3)
    d = json.loads(text)
    path = "llvmpipe" if d["path"] == "glref-llvmpipe" else d["path"]
    runs.setdefault((scene, filt), {}).setdefault(int(r), {})[path] = d.get("median_ms", d.get("mean_ms"))
print(f"jar = {sys.argv[2]}; ms are medians over the runs; ratios per run, (median)")
def ratios(rs, a, b):
    v = [x[a] / x[b] for x in rs.values() if a in x and b in x]
    return (" ".join(f"{x:.2f}" for x in v) + f" ({statistics.median(v):.2f})") if v else "-"
for (scene, filt), rs in runs.items():
    ms = {p: statistics.median([x[p] for x in rs.values() if p in x])
          for p in ("perspective", "spans", "tessellated", "llvmpipe") if any(p in x for x in rs.values())}
    print(f"{scene} {filt}: " + ", ".join(f"{p} {v:.2f}" for p, v in ms.items()))
    print(f"  spans/per-pixel {ratios(rs, 'spans', 'perspective')}; tessellated/per-pixel "
          f"{ratios(rs, 'tessellated', 'perspective')}"
          + (f"; spans/llvmpipe {ratios(rs, 'spans', 'llvmpipe')}; tessellated/llvmpipe "
             f"{ratios(rs, 'tessellated', 'llvmpipe')}" if "llvmpipe" in ms else ""))
PY
