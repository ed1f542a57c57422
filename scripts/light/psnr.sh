#!/usr/bin/env bash
# How far the span path and the tessellated path (error policy) are from the per-pixel path when lit
# smooth: PSNR (dB) of `compare` on demo, boxes, sphere (each exported to OBJ with its camera) and the
# head of LightAgainstOpenGlTest (src/test/resources/dev/trisect/light/head.obj, its camera there),
# lit by a directional light, a coloured point light with attenuation 1,0.2,0.05 and a coloured
# ambient (the tests' "both-smooth"), nearest sampling (or FILTER's). Each scene three times: unlit with its textures
# (what the texel flips alone give), lit with its textures, and lit with a white texture on every
# material, so that only the light's interpolation differs between the paths (no texel flips). Prints
# one line per scene, case and path.
#
#   [FILTER=nearest|bilinear|trilinear] [SCENES="demo boxes"] scripts/light/psnr.sh [WxH] [MAX_ERROR]
#
# Defaults: nearest, every frame of frames.txt (demo boxes sphere head), 1280x720, 0.5. PSNR is
# compare's: over every pixel of the frame (the sky and the background count, as equal pixels).
set -euo pipefail
cd "$(dirname "$0")/../.."
JAR=${JAR:-target/trisect.jar}
size=${1:-1280x720}
err=${2:-0.5}
filter=${FILTER:-nearest}
scenes=" ${SCENES:-demo boxes sphere head} "
[[ -f $JAR ]] || mvn -B -q package -DskipTests
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf 'P3\n1 1\n255\n255 255 255\n' >"$tmp/white.ppm"
light=(--light 1,2,3 --light-colour 0.8,0.9,1 --point-colour 1,0.7,0.4 --attenuation 1,0.2,0.05
  --ambient 0.25,0.2,0.35 --shade smooth --size "$size" --max-error "$err")
printf '%-7s %-12s %-12s %s\n' scene case path psnr_db
grep '^frame ' src/test/resources/dev/trisect/light/frames.txt | while read -r _ name scene eye target far point; do
  [[ $scenes == *" $name "* ]] || continue
  if [[ $scene == head ]]; then
    obj=src/test/resources/dev/trisect/light/head.obj
    textured=(--texture src/test/resources/dev/trisect/lines/checker.ppm)
  else
    obj=$tmp/$scene/$scene.obj
    java -jar "$JAR" export --scene "$scene" --to "$obj" >/dev/null
    textured=()
  fi
  for case in unlit lit lit-white; do
    lit=("${light[@]}" --point "$point")
    if [[ $case == unlit ]]; then lit=(--size "$size" --max-error "$err"); fi
    if [[ $case == lit-white ]]; then tex=(--texture "$tmp/white.ppm"); else tex=("${textured[@]}"); fi
    for mode in spans tessellated; do
      extra=(--filter "$filter"); [[ $mode == tessellated ]] && extra+=(--split error)
      psnr=$(java -jar "$JAR" compare --obj "$obj" "${tex[@]}" --eye "$eye" --target "$target" --far "$far" \
        "${lit[@]}" --mode "$mode" "${extra[@]}" | sed -n 's/.*"psnr_db":\([^,}]*\).*/\1/p')
      # Identical images have no PSNR (compare prints null): infinite.
      [[ $psnr == null ]] && psnr=inf || psnr=$(printf '%.1f' "$psnr")
      printf '%-7s %-12s %-12s %s\n' "$name" "$case" "$mode" "$psnr"
    done
  done
done
