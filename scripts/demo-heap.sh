#!/usr/bin/env bash
# The smallest heap at which the demo opens a 2,000,000-triangle OBJ on its own, and whether at that heap
# it also opens it after a 1,000,000-triangle OBJ and a small one (docs/reading-limits.md, working
# memory). Opens the files through File > Open as a user does (DemoHeapProbe, in the test classes); needs
# an X display (DISPLAY). Run from the repository root after mvn -q package -DskipTests (which also
# compiles the test classes).
#   scripts/demo-heap.sh [low-MiB] [high-MiB] [step-MiB]     defaults 256 1024 16
set -euo pipefail
cd "$(dirname "$0")/.."
low=${1:-256}; high=${2:-1024}; step=${3:-16}
[[ -f target/trisect.jar && -f target/test-classes/dev/trisect/ui/DemoHeapProbe.class ]] \
    || { echo "$0: build first: mvn -q package -DskipTests" >&2; exit 2; }
cp=target/test-classes:target/trisect.jar
models=$(mktemp -d)
trap 'rm -rf "$models"' EXIT
java -cp "$cp" dev.trisect.ui.DemoHeapProbe --make "$models"
probe() { java -Xmx"$1"m -cp "$cp" dev.trisect.ui.DemoHeapProbe "${@:2}" > "$models/out" 2>&1; }
probe "$high" "$models/grid2m.obj" || { echo "the 2M-triangle OBJ does not open even at -Xmx${high}m:"; cat "$models/out"; exit 1; }
# Bisect on multiples of the step: lo fails (or is the floor), hi opens.
lo=$((low - step)); hi=$high
while (( hi - lo > step )); do
    mid=$(( (lo + hi) / 2 / step * step ))
    (( mid <= lo )) && mid=$((lo + step))
    if probe "$mid" "$models/grid2m.obj"; then hi=$mid; echo "-Xmx${mid}m: opens grid2m.obj alone"; else lo=$mid; echo "-Xmx${mid}m: does not: $(tail -1 "$models/out")"; fi
done
echo "smallest heap (step ${step} MiB) at which the demo opens grid2m.obj on its own: -Xmx${hi}m"
if probe "$hi" "$models/grid1m.obj" "$models/small.obj" "$models/grid2m.obj"; then
    echo "at -Xmx${hi}m, after grid1m.obj and small.obj, grid2m.obj opens too:"; cat "$models/out"
else
    echo "at -Xmx${hi}m, after grid1m.obj and small.obj, grid2m.obj does NOT open:"; cat "$models/out"; exit 1
fi
