#!/usr/bin/env bash
# The heap a long-lived SceneRenderer keeps after one huge frame (docs/reading-limits.md, working
# memory): a box drawn, one frame of a 2,000,000-triangle grid, then 5 frames of the box again; the
# heap in use after a full collection before and after, and their ratio (exit 1 above 2). Run from the
# repository root after mvn -q package -DskipTests.
#   scripts/retained-heap.sh [cells] [WxH] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -f target/trisect.jar ]] || { echo "$0: build first: mvn -q package -DskipTests" >&2; exit 2; }
exec java -Xmx2g -cp target/trisect.jar scripts/retained-heap/RetainedHeap.java "$@"
