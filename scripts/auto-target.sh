#!/bin/sh
# The frame budget as a user sees it: the demo at 1280x720 with the developer tools open, Auto on with
# targets from 10 to 100 ms, and after 5 s each the status bar's frames per second against 1000 / target
# (within 15 %, or the tools say why not). Needs a display (DISPLAY, e.g. Xvfb :99). Usage:
#   scripts/auto-target.sh [threads]
set -e
cd "$(dirname "$0")/.."
mvn -q test-compile
exec mvn -q exec:java -Dmain.class=dev.trisect.ui.AutoTargetCheck -Dexec.classpathScope=test \
    -Dexec.args="${1:-}"
