#!/usr/bin/env bash
# Regenerates the pictures in docs/ from the built-in scenes. Needs ImageMagick's montage.
set -euo pipefail
cd "$(dirname "$0")/.."
JAR=target/trisect.jar
[[ -f $JAR ]] || mvn -B -q package -DskipTests
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
SKY=9db8d3
for mode in perspective affine tessellated; do
  extra=()
  [[ $mode == tessellated ]] && extra=(--borders)
  java -jar "$JAR" render --scene floor --mode "$mode" --size 640x400 --background $SKY \
    --out "$TMP/$mode.png" "${extra[@]}"
done
montage -label '%t' "$TMP/perspective.png" "$TMP/affine.png" "$TMP/tessellated.png" \
  -tile 3x1 -geometry +4+4 -pointsize 20 -background '#1e1e1e' -fill white docs/floor-paths.png
for filter in nearest bilinear trilinear; do
  java -jar "$JAR" render --scene floor --split error --max-error 0.5 --filter "$filter" --size 640x400 \
    --background $SKY --out "$TMP/$filter.png"
done
montage -label '%t' "$TMP/nearest.png" "$TMP/bilinear.png" "$TMP/trilinear.png" \
  -tile 3x1 -geometry +4+4 -pointsize 20 -background '#1e1e1e' -fill white docs/floor-filters.png
java -jar "$JAR" compare --scene floor --size 640x400 --split error --max-error 0.5 \
  --heatmap docs/floor-error-heatmap.png --heatmap-max 0.5 >/dev/null
java -jar "$JAR" compare --scene floor --size 640x400 --mode affine \
  --heatmap docs/floor-affine-heatmap.png --heatmap-max 8 >/dev/null
echo "wrote docs/floor-paths.png, docs/floor-filters.png, docs/floor-error-heatmap.png, docs/floor-affine-heatmap.png"
