#!/bin/sh
# The screenshots of docs/demo.md's newer developer-tools features (heat map legend, pinned pixels and
# the magnifier's note, the tools window docked), from the real demo window: needs an X server
# (DISPLAY, e.g. Xvfb :99 -screen 0 1920x1080x24) and ImageMagick's import. Usage:
#   scripts/demo-shots.sh [folder]      (default docs)
set -e
cd "$(dirname "$0")/.."
mkdir -p "${1:-docs}"
mvn -q test-compile
exec mvn -q exec:java -Dmain.class=dev.trisect.ui.DemoShots -Dexec.classpathScope=test -Dexec.args="${1:-docs}"
