#!/usr/bin/env bash
# Produces the tables and charts of docs/performance.md and docs/performance/paths.md: the machine,
# each path against Mesa llvmpipe (glref) with the same thread count, thread scaling, time against
# resolution and against triangle count, the cost/quality sweep charts, the budget controller's trace,
# and the JMH cost of one extra piece. Tables go to target/performance/tables.md (Markdown), charts
# to docs/perf-*.png.
#
# Usage: [FRAMES=100] [WARMUP=100] [THREADS=2] [JMH=1] scripts/performance.sh [glref-binary]
# Build glref first: gcc -O2 -o /tmp/glref ../shared/tools/glref/glref.c -lEGL -lGL -lGLU -lm
# Without a glref binary the llvmpipe column is left out. Run it on a quiet machine: every number is a
# median of FRAMES frames after WARMUP, and the script runs for a few minutes per scene.
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${1:-/tmp/glref}
FRAMES=${FRAMES:-100}
WARMUP=${WARMUP:-100}
THREADS=${THREADS:-2}
JAR=target/trisect.jar
OUT=target/performance
mkdir -p "$OUT"
[[ -f $JAR ]] || mvn -B -q package -DskipTests
TABLES=$OUT/tables.md
: >"$TABLES"
bench() { java -jar "$JAR" bench --frames "$FRAMES" --warmup "$WARMUP" --json "$@"; }
# median_ms of one path from bench's JSON lines on stdin
median() { python3 -c 'import json,sys
want=sys.argv[1]
for l in sys.stdin:
    r=json.loads(l)
    if r["path"]==want: print("%.2f" % (r.get("median_ms") or r.get("mean_ms"))); break' "$1"; }

{
  echo "## Machine"
  echo
  echo '```'
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //') x $(nproc)"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  java -version 2>&1 | head -n 1
  echo "frames per measurement: $FRAMES after $WARMUP warm-up; threads: $THREADS"
  echo '```'
  echo
} >>"$TABLES"

GL=()
[[ -x $GLREF ]] && GL=(--glref "$GLREF")
echo "## Each path against Mesa llvmpipe, 1920x1080, $THREADS threads (median ms)" >>"$TABLES"
echo >>"$TABLES"
echo "| scene | triangles | per-pixel | affine | tessellated edge 32 | tessellated error 0.5 | tess. edge / per-pixel | tess. error / per-pixel | llvmpipe (mean) | per-pixel / llvmpipe |" >>"$TABLES"
echo "|---|---|---|---|---|---|---|---|---|---|" >>"$TABLES"
for scene in demo floor boxes sphere sphere160k; do
  a=$(bench --scene "$scene" --size 1920x1080 --threads "$THREADS" "${GL[@]}")
  e=$(bench --scene "$scene" --size 1920x1080 --threads "$THREADS" --modes tessellated --split error)
  tris=$(java -jar "$JAR" render --scene "$scene" --size 64x36 --stats --out "$OUT/t.png" | python3 -c 'import json,sys; print(json.load(sys.stdin)["triangles_in"])')
  pp=$(median perspective <<<"$a"); af=$(median affine <<<"$a"); te=$(median tessellated <<<"$a"); tr=$(median tessellated <<<"$e")
  gl=$(median glref-llvmpipe <<<"$a"); gl=${gl:--}
  python3 - "$scene" "$tris" "$pp" "$af" "$te" "$tr" "$gl" >>"$TABLES" <<'PY'
import sys
s,t,pp,af,te,tr,gl=sys.argv[1:]
r=lambda a,b: "-" if "-" in (a,b) else "%.2fx" % (float(a)/float(b))
print(f"| {s} | {t} | {pp} | {af} | {te} | {tr} | {r(te,pp)} | {r(tr,pp)} | {gl} | {r(pp,gl)} |")
PY
done
echo >>"$TABLES"

echo "## Thread scaling, 1920x1080 (median ms; speed-up = 1 thread / 2 threads)" >>"$TABLES"
echo >>"$TABLES"
echo "| scene | path | 1 thread | 2 threads | speed-up |" >>"$TABLES"
echo "|---|---|---|---|---|" >>"$TABLES"
for scene in demo floor sphere160k; do
  one=$(bench --scene "$scene" --size 1920x1080 --threads 1)
  two=$(bench --scene "$scene" --size 1920x1080 --threads 2)
  for p in perspective affine tessellated; do
    a=$(median $p <<<"$one"); b=$(median $p <<<"$two")
    python3 -c "import sys; print('| $scene | $p | $a | $b | %.2fx |' % ($a/$b))" >>"$TABLES"
  done
done
echo >>"$TABLES"

echo "## Time against resolution, demo scene, $THREADS threads (median ms)" >>"$TABLES"
echo >>"$TABLES"
echo "| size | per-pixel | affine | tessellated edge 32 | tess. / per-pixel |" >>"$TABLES"
echo "|---|---|---|---|---|" >>"$TABLES"
for size in 1280x720 1920x1080 3840x2160; do
  a=$(bench --scene demo --size "$size" --threads "$THREADS")
  pp=$(median perspective <<<"$a"); af=$(median affine <<<"$a"); te=$(median tessellated <<<"$a")
  python3 -c "print('| $size | $pp | $af | $te | %.2fx |' % ($te/$pp))" >>"$TABLES"
done
echo >>"$TABLES"

echo "## Time against triangle count, textured globe, 1920x1080, $THREADS threads (median ms)" >>"$TABLES"
echo >>"$TABLES"
echo "| scene | triangles | per-pixel | affine | tessellated edge 32 | tess. / per-pixel |" >>"$TABLES"
echo "|---|---|---|---|---|---|" >>"$TABLES"
for scene in sphere sphere100k sphere1m; do
  a=$(bench --scene "$scene" --size 1920x1080 --threads "$THREADS")
  tris=$(java -jar "$JAR" render --scene "$scene" --size 64x36 --stats --out "$OUT/t.png" | python3 -c 'import json,sys; print(json.load(sys.stdin)["triangles_in"])')
  pp=$(median perspective <<<"$a"); af=$(median affine <<<"$a"); te=$(median tessellated <<<"$a")
  python3 -c "print('| $scene | $tris | $pp | $af | $te | %.2fx |' % ($te/$pp))" >>"$TABLES"
done
echo >>"$TABLES"

echo "## Cost/quality sweeps, 1920x1080, $THREADS threads" >>"$TABLES"
for scene in demo floor; do
  echo >>"$TABLES"
  echo "### $scene" >>"$TABLES"
  echo >>"$TABLES"
  echo '```' >>"$TABLES"
  java -jar "$JAR" bench --scene "$scene" --size 1920x1080 --threads "$THREADS" --frames "$FRAMES" --warmup "$WARMUP" \
    --sweep --plot "docs/perf-sweep-$scene.png" >>"$TABLES"
  echo '```' >>"$TABLES"
done
echo >>"$TABLES"

echo "## Budget controller over an orbit of the demo scene" >>"$TABLES"
echo >>"$TABLES"
echo '```' >>"$TABLES"
# The target: halfway between the per-pixel frame and the tessellated frame at the ceiling (64 px).
a=$(bench --scene demo --size 1920x1080 --threads "$THREADS" --modes perspective)
target=$(median perspective <<<"$a")
java -jar "$JAR" bench --scene demo --size 1920x1080 --threads "$THREADS" --warmup "$WARMUP" --frames 400 \
  --max-edge 64 --target-ms "$target" --orbit --plot docs/perf-budget.png | tail -n 1 >>"$TABLES"
echo '```' >>"$TABLES"
echo >>"$TABLES"

if [[ ${JMH:-1} == 1 ]]; then
  echo "## JMH: cost of one extra piece, 1280x720, one thread" >>"$TABLES"
  echo >>"$TABLES"
  mvn -B -q test-compile exec:exec@jmh -Djmh.args="PieceCostBenchmark -rf json -rff $OUT/jmh.json" >"$OUT/jmh.log"
  python3 - "$OUT/jmh.json" "$OUT/jmh.log" >>"$TABLES" <<'PY'
import json, re, sys
runs = json.load(open(sys.argv[1]))
pieces = {}
for m in re.finditer(r"pieces (\w+) (\w+) affine (\d+) tessellated (\d+)", open(sys.argv[2]).read()):
    pieces[(m[1], m[2])] = (int(m[3]), int(m[4]))
us = {}
paired = {}
for r in runs:
    p = r["params"]
    name = r["benchmark"].rsplit(".", 1)[1]
    us[(p["scene"], p["policy"], name)] = (r["primaryMetric"]["score"], r["primaryMetric"]["scoreError"])
    if name == "paired":
        m = r["secondaryMetrics"]
        paired[(p["scene"], p["policy"])] = m["extraNanos"]["score"] / max(1, m["extraPieces"]["score"])
print("| scene | policy | affine us | tessellated us | extra pieces | ns per extra piece | paired ns per extra piece |")
print("|---|---|---|---|---|---|---|")
for (scene, policy), (a, t) in sorted(pieces.items()):
    ua, ea = us[(scene, policy, "affine")]; ut, et = us[(scene, policy, "tessellated")]
    extra = t - a
    print(f"| {scene} | {policy} | {ua:.0f} ± {ea:.0f} | {ut:.0f} ± {et:.0f} | {extra} | {(ut - ua) * 1000 / extra:.0f} "
          f"| {paired[(scene, policy)]:.0f} |")
PY
fi
echo "tables in $TABLES" >&2
