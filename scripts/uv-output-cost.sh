#!/usr/bin/env bash
# What recording the UV output costs a frame (docs/view.md, picking): one JVM, the frame drawn
# without and with it, interleaved. Run from the repository root after mvn -q package -DskipTests.
#   scripts/uv-output-cost.sh [scene] [WxH] [threads] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -f target/trisect.jar ]] || { echo "$0: build first: mvn -q package -DskipTests" >&2; exit 2; }
exec java -Xmx2g -cp target/trisect.jar scripts/uv-output-cost/UvOutputCost.java "$@"
