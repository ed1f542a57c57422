#!/usr/bin/env bash
# Regenerates the OpenGL references of LightAgainstOpenGlTest: each frame of
# src/test/resources/dev/trisect/light/frames.txt under each of its lights, drawn by glref (Mesa
# llvmpipe's fixed-function lighting and fog) at 160x120 with nearest sampling, kept as PNG. The head
# is scripts/filter-scenes.py's at 24 x 16 quads (head.obj there). Needs glref (../shared/tools/glref,
# built as its README says; GLREF=path to use another), python3, pnmtopng and target/trisect.jar.
#
# usage: scripts/light-references.sh
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${GLREF:-/tmp/glref}
JAR=${JAR:-target/trisect.jar}
[[ -f $JAR ]] || mvn -B -q package -DskipTests
OUT=src/test/resources/dev/trisect/light
TEX=src/test/resources/dev/trisect/lines/checker.ppm
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 - "$OUT/head.obj" <<'PY'
import importlib.util, sys
spec = importlib.util.spec_from_file_location("fs", "scripts/filter-scenes.py")
fs = importlib.util.module_from_spec(spec)
spec.loader.exec_module(fs)
open(sys.argv[1], "w").write(fs.head(24, 16))
PY
grep '^light ' "$OUT/frames.txt" | while read -r _ light opts; do
  grep '^frame ' "$OUT/frames.txt" | while read -r _ name scene eye target far point; do
    if [[ $scene == head ]]; then obj=$OUT/head.obj; else
      obj=$tmp/$scene/$scene.obj
      [[ -f $obj ]] || java -jar "$JAR" export --scene "$scene" --to "$obj" >/dev/null
    fi
    # shellcheck disable=SC2086 # opts is a list of options
    env=$(java -jar "$JAR" export --scene floor --to "$tmp/env/env.obj" ${opts//POINT/$point} | sed -n 's/^glref: //p')
    IFS=, read -r ex ey ez <<<"$eye"
    IFS=, read -r tx ty tz <<<"$target"
    # shellcheck disable=SC2086 # env is a list of NAME=value
    env $env "$GLREF" "$obj" "$TEX" "$tmp/g.ppm" 160 120 "$ex" "$ey" "$ez" "$tx" "$ty" "$tz" 60 0.1 "$far" back \
      >/dev/null 2>&1
    pnmtopng "$tmp/g.ppm" >"$OUT/$name-$light.png"
  done
done
