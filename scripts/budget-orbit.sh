#!/usr/bin/env bash
# The budget controller over an orbit of the demo scene, a build before issue 18 (frame time alone:
# TimeOnlyOrbit) against this one (bench --target-ms --orbit, which also heeds the piece budget),
# alternating, at 16.7 and 40 ms, REPS times (default 2). Prints per run: frames over the piece budget,
# the threshold's reversals, the second half's median time and threshold; keeps the traces and this
# build's plots in OUT (default budget-orbit-out).
#
#   scripts/budget-orbit.sh OLD.jar NEW.jar [W H]      (default 1280 720, 400 frames after 50)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
old=$1
new=$2
w=${3:-1280}
h=${4:-720}
out=${OUT:-budget-orbit-out}
mkdir -p "$out"
for rep in $(seq "${REPS:-2}"); do
  for t in 16.7 40; do
    java -cp "$old" "$here/budget-orbit/TimeOnlyOrbit.java" "$t" "$w" "$h" 400 50 >"$out/before-$t-$rep.txt"
    java -jar "$new" bench --scene demo --size "${w}x$h" --threads 2 --target-ms "$t" --orbit --frames 400 \
      --warmup 50 --plot "$out/after-$t-$rep.png" >"$out/after-$t-$rep.txt"
    python3 "$here/budget-orbit/summary.py" "$out/before-$t-$rep.txt" "$out/after-$t-$rep.txt"
  done
done
