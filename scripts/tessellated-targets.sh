#!/usr/bin/env bash
# Issue 15's frame-time targets, two builds side by side: per scene and filter, each run is one
# `bench --json` of per-pixel, spans (0.5 px) and tessellated (--split error --max-error 0.5), and one
# of tessellated under the default edge policy (32 px), first for build A, then for build B, so that
# both builds' ratios come from the same minute of the machine. With a glref binary, trilinear runs of
# build B also time Mesa llvmpipe on the same frame (A's ratios to llvmpipe use B's figure of the run).
# Prints per scene, filter and build the median ms of each path over the runs and each run's ratios.
#
#   scripts/tessellated-targets.sh OLD.jar NEW.jar [GLREF]
#   REPS=3 THREADS=2 SIZE=1920x1080 scripts/tessellated-targets.sh /tmp/old.jar target/trisect.jar /tmp/glref
#
# Environment: REPS (3), THREADS (2), SIZE (1920x1080), FRAMES (30), FILTERS ("nearest trilinear"),
# SCENES ("demo floor boxes sphere sphere160k").
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 OLD.jar NEW.jar [GLREF]" >&2
  exit 2
fi
jars=("$1" "$2")
glref=${3:-}
for j in "${jars[@]}"; do [[ -f $j ]] || { echo "$0: no such jar: $j" >&2; exit 2; }; done
reps=${REPS:-3}
threads=${THREADS:-2}
size=${SIZE:-1920x1080}
frames=${FRAMES:-30}
filters=${FILTERS:-nearest trilinear}
scenes=${SCENES:-demo floor boxes sphere sphere160k}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for ((r = 1; r <= reps; r++)); do
  for scene in $scenes; do
    for filter in $filters; do
      for b in 0 1; do
        common=(--json --threads "$threads" --size "$size" --frames "$frames" --warmup "$frames" --filter "$filter"
          --scene "$scene")
        extra=()
        [[ $b == 1 && $filter == trilinear && -n $glref ]] && extra=(--glref "$glref")
        java -jar "${jars[$b]}" bench "${common[@]}" --modes perspective,spans,tessellated --split error \
          --max-error 0.5 "${extra[@]}" 2>/dev/null | sed "s|^|$b $r $scene $filter error |" >>"$out"
        java -jar "${jars[$b]}" bench "${common[@]}" --modes tessellated 2>/dev/null \
          | sed "s|^|$b $r $scene $filter edge |" >>"$out"
      done
    done
  done
done
python3 - "$out" "${jars[0]}" "${jars[1]}" <<'PY'
import json, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    b, r, scene, filt, split, text = line.split(" ", 5)
    d = json.loads(text)
    path = d["path"]
    if path == "glref-llvmpipe":
        path = "llvmpipe"
    elif path == "tessellated":
        path = "tessellated-" + split
    runs.setdefault((scene, filt), {}).setdefault(int(r), {})[(int(b), path)] = d.get("median_ms", d.get("mean_ms"))
print(f"A = {sys.argv[2]}, B = {sys.argv[3]}; ms: medians over the runs; ratios: per run, (median)")
paths = ("perspective", "spans", "tessellated-edge", "tessellated-error")
for (scene, filt), rs in runs.items():
    print(f"{scene} {filt}")
    for b in (0, 1):
        ms = {p: statistics.median([x[(b, p)] for x in rs.values() if (b, p) in x])
              for p in paths if any((b, p) in x for x in rs.values())}
        line = f"  {'AB'[b]}: " + ", ".join(f"{p} {v:.2f}" for p, v in ms.items())
        for p in paths[1:]:
            v = [x[(b, p)] / x[(b, "perspective")] for x in rs.values() if (b, p) in x and (b, "perspective") in x]
            if v:
                line += f"\n     {p}/per-pixel " + " ".join(f"{y:.2f}" for y in v) + f" ({statistics.median(v):.2f})"
            w = [x[(b, p)] / x[(1, "llvmpipe")] for x in rs.values() if (b, p) in x and (1, "llvmpipe") in x]
            if w:
                line += f"; /llvmpipe " + " ".join(f"{y:.2f}" for y in w) + f" ({statistics.median(w):.2f})"
        print(line)
    ll = [x[(1, "llvmpipe")] for x in rs.values() if (1, "llvmpipe") in x]
    if ll:
        print(f"  llvmpipe {statistics.median(ll):.2f} ms")
PY
