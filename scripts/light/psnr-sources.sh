#!/usr/bin/env bash
# Where the tessellated path's error against the per-pixel path comes from, with trilinear filtering
# (or FILTER's): the texel coordinates (the affine pieces' displacement, within the bound) or the level
# of detail (one per piece or unsplit triangle, not one per pixel). Builds a copy of the committed
# sources (git archive HEAD) with psnr-sources.patch applied, which is not part of the product: under
# the system property trisect.experiment it fills each affine piece and unsplit triangle
#   exact-coordinates  with the per-pixel path's texel coordinates and the piece's own level of detail
#                      (what the level of detail alone costs),
#   exact-lod          with the piece's affine coordinates and the per-pixel path's exact lambda at
#                      every pixel (what the coordinates alone cost),
#   offset             with each piece's affine map moved by OFFSET (default 0.5) of its error at the
#                      piece's centroid (a fit that no longer passes through the corners),
# then prints compare's PSNR and largest displacement of each against the per-pixel path, unlit and lit
# by psnr.sh's lights, on one frame of src/test/resources/dev/trisect/light/frames.txt. One thread
# (the experiment's state is static). A minute or two, most of it the build.
#
#   [FILTER=trilinear] [OFFSET=0.5] scripts/light/psnr-sources.sh [FRAME] [WxH] [MAX_ERROR]   (default demo 1280x720 0.5)
set -euo pipefail
cd "$(dirname "$0")/../.."
frame=${1:-demo}
size=${2:-1280x720}
err=${3:-0.5}
filter=${FILTER:-trilinear}
offset=${OFFSET:-0.5}
read -r _ name scene eye target far point < <(grep "^frame $frame " src/test/resources/dev/trisect/light/frames.txt) || {
  echo "$0: no frame '$frame' in src/test/resources/dev/trisect/light/frames.txt" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
git archive HEAD | tar -x -C "$tmp"
patch -s -d "$tmp" -p1 <scripts/light/psnr-sources.patch || { echo "$0: psnr-sources.patch no longer applies to HEAD" >&2; exit 1; }
(cd "$tmp" && mvn -B -q package -DskipTests -Dmaven.javadoc.skip=true >"$tmp/build.log" 2>&1) || { cat "$tmp/build.log" >&2; exit 1; }
jar=$tmp/target/trisect.jar
if [[ $scene == head ]]; then
  obj=src/test/resources/dev/trisect/light/head.obj
  textured=(--texture src/test/resources/dev/trisect/lines/checker.ppm)
else
  obj=$tmp/$scene/$scene.obj
  java -jar "$jar" export --scene "$scene" --to "$obj" >/dev/null
  textured=()
fi
lit=(--light 1,2,3 --light-colour 0.8,0.9,1 --point "$point" --point-colour 1,0.7,0.4 --attenuation 1,0.2,0.05
  --ambient 0.25,0.2,0.35 --shade smooth)
printf '%-7s %-18s %-6s %-8s %s\n' frame experiment case psnr_db max_displacement
for experiment in none exact-coordinates exact-lod offset; do
  for case in unlit lit; do
    light=(); [[ $case == lit ]] && light=("${lit[@]}")
    out=$(java -Dtrisect.experiment="$experiment" -Dtrisect.offset="$offset" -jar "$jar" compare --obj "$obj" \
      "${textured[@]}" --eye "$eye" --target "$target" --far "$far" --size "$size" --max-error "$err" \
      --mode tessellated --split error --filter "$filter" --threads 1 "${light[@]}")
    psnr=$(sed -n 's/.*"psnr_db":\([^,}]*\).*/\1/p' <<<"$out")
    disp=$(sed -n 's/.*"max_displacement":\([^,}]*\).*/\1/p' <<<"$out")
    [[ $psnr == null ]] && psnr=inf || psnr=$(printf '%.1f' "$psnr")
    printf '%-7s %-18s %-6s %-8s %.3f\n' "$name" "$experiment" "$case" "$psnr" "$disp"
  done
done
