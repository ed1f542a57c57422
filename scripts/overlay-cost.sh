#!/usr/bin/env bash
# What the border overlay adds to a tessellated frame (issue 15, item 4), for one or two builds:
# `bench --json --modes tessellated` without and with --borders, the runs of the builds and of the
# two settings alternating (A plain, A borders, B plain, B borders, ...), REPS rounds, each run
# the median of FRAMES frames after WARMUP. Prints per scene and policy each build's median ms
# without and with the overlay over the rounds, and what the overlay adds, per round (with and
# without taken from the same round) and its median.
#
#   scripts/overlay-cost.sh A.jar [B.jar]
#   REPS=5 THREADS=2 SIZE=1920x1080 scripts/overlay-cost.sh /tmp/old.jar target/trisect.jar
#
# Scenes (SCENES, default "demo floor boxes sphere2k"): built-in scenes, and sphere2k, a textured
# UV sphere of 1,984 triangles (32 x 32 segments) written to a temporary OBJ with a checker texture,
# seen from (0, 0, 2.2). Policies (POLICIES, default "edge error"): the edge policy's default 32 px,
# and --split error --max-error 0.5. Environment: REPS (3), THREADS (2), SIZE (1920x1080),
# FRAMES (60), WARMUP (120).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 A.jar [B.jar]" >&2
  exit 2
fi
jars=("$@")
for jar in "${jars[@]}"; do
  [[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
done
reps=${REPS:-3}
threads=${THREADS:-2}
size=${SIZE:-1920x1080}
frames=${FRAMES:-60}
warmup=${WARMUP:-120}
scenes=${SCENES:-demo floor boxes sphere2k}
policies=${POLICIES:-edge error}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import math, sys
d = sys.argv[1]
n = 32
with open(f"{d}/sphere2k.obj", "w") as f:
    for j in range(n + 1):
        lat = math.pi * j / n
        for i in range(n + 1):
            lon = 2 * math.pi * i / n
            f.write(f"v {math.sin(lat) * math.cos(lon):.6f} {math.cos(lat):.6f} {-math.sin(lat) * math.sin(lon):.6f}\n")
            f.write(f"vt {i / n:.6f} {1 - j / n:.6f}\n")
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i + 1
            b, c, e = a + 1, a + n + 1, a + n + 2
            if j > 0:
                f.write(f"f {a}/{a} {c}/{c} {b}/{b}\n")
            if j < n - 1:
                f.write(f"f {b}/{b} {c}/{c} {e}/{e}\n")
with open(f"{d}/checker.ppm", "wb") as f:
    f.write(b"P6 256 256 255\n")
    f.write(bytes(v for y in range(256) for x in range(256)
                  for v in ((230, 200, 60) if (x // 16 + y // 16) % 2 else (40, 60, 160))))
PY
out=$tmp/runs
for ((r = 1; r <= reps; r++)); do
  for scene in $scenes; do
    args=(--scene "$scene")
    [[ $scene == sphere2k ]] && args=(--obj "$tmp/sphere2k.obj" --texture "$tmp/checker.ppm" --eye 0,0,2.2 --target 0,0,0)
    for policy in $policies; do
      split=(--split edge)
      [[ $policy == error ]] && split=(--split error --max-error 0.5)
      for k in "${!jars[@]}"; do
        for borders in plain borders; do
          extra=()
          [[ $borders == borders ]] && extra=(--borders)
          java -jar "${jars[$k]}" bench --json --modes tessellated "${split[@]}" --threads "$threads" --size "$size" \
            --frames "$frames" --warmup "$warmup" "${args[@]}" "${extra[@]}" 2>/dev/null \
            | sed "s|^|$r $scene $policy $k $borders |" >>"$out"
        done
      done
    done
  done
done
python3 - "$out" "${jars[@]}" <<'PY'
import json, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    r, scene, policy, k, borders, text = line.split(" ", 5)
    runs.setdefault((scene, policy, int(k)), {}).setdefault(int(r), {})[borders] = json.loads(text)["median_ms"]
jars = sys.argv[2:]
for k, jar in enumerate(jars):
    print(f"build {'AB'[k]} = {jar}")
print("scene     policy build  plain ms  borders ms  borders add per round (median)")
for (scene, policy, k), rs in runs.items():
    plain = statistics.median(x["plain"] for x in rs.values())
    with_b = statistics.median(x["borders"] for x in rs.values())
    adds = [x["borders"] / x["plain"] - 1 for x in rs.values() if "plain" in x and "borders" in x]
    print(f"{scene:9} {policy:6} {'AB'[k]:5} {plain:9.2f} {with_b:11.2f}  "
          + " ".join(f"{100 * a:+.0f}%" for a in adds) + f" ({100 * statistics.median(adds):+.0f}%)")
PY
