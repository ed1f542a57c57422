#!/usr/bin/env bash
# What a view of a still scene costs (docs/view.md, frames only when needed): the process's CPU time
# over 30 s as a share of one core (under 2 % passes, exit 0), and how long a change takes to reach
# a frame. Needs a display (e.g. Xvfb :99 & export DISPLAY=:99). Run from the repository root after
# mvn -q package -DskipTests.
#   scripts/idle-cpu.sh [seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -f target/trisect.jar ]] || { echo "$0: build first: mvn -q package -DskipTests" >&2; exit 2; }
exec java -cp target/trisect.jar scripts/idle-cpu/IdleCpu.java "$@"
