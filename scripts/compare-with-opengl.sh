#!/usr/bin/env bash
# Renders built-in scenes with Trisect's perspective path and with OpenGL (Mesa llvmpipe, through
# ../shared/tools/glref) and prints, per frame, how many pixels differ in colour and how far the
# UV outputs are apart (the diff command's JSON line), then the share of covered pixels within 2/255
# and their PSNR (scripts/within.py). Usage: [FILTER=nearest|bilinear|trilinear] [JAR=trisect.jar]
#   [TEXTURE=picture.ppm] scripts/compare-with-opengl.sh [glref-binary] [WxH]
# TEXTURE (a binary PPM, absolute path) replaces the scenes' own texture in both renderers.
# HEAD (an OBJ with vn, absolute path, e.g. the head.obj of scripts/filter-scenes.py, with TEXTURE)
# adds a frame of it; FRAMES="demo-60 boxes-60" runs only the frames named.
# FILTER (default nearest) is passed to both: --filter for Trisect, GLREF_FILTER for glref.
# OPTS: Trisect's light and fog options (e.g. OPTS="--light 1,2,3 --shade flat --fog exp,0.05"), given
# to Trisect and, as the GLREF_* variables `export` prints for them, to glref.
# Build glref first: gcc -O2 -o /tmp/glref ../shared/tools/glref/glref.c -lEGL -lGL -lGLU -lm
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${1:-/tmp/glref}
SIZE=${2:-1280x720}
FILTER=${FILTER:-nearest}
W=${SIZE%x*}
H=${SIZE#*x}
JAR=${JAR:-target/trisect.jar}
[[ -f $JAR ]] || mvn -B -q package -DskipTests
OUT=$(mktemp -d)
[[ -n ${KEEP:-} ]] && echo "keeping $OUT" >&2 || trap 'rm -rf "$OUT"' EXIT

# The GLREF_* variables that give glref the same light and fog as OPTS give Trisect.
mkdir -p "$OUT/env"
# shellcheck disable=SC2086 # OPTS is a list of options
GLREF_ENV=$(java -jar "$JAR" export --scene floor --to "$OUT/env/env.obj" ${OPTS:-} | sed -n 's/^glref: //p')

frame() { # name scene-or-file.obj eye target cull [far]
  local name=$1 scene=$2 eye=$3 target=$4 cull=$5 far=${6:-1000}
  mkdir -p "$OUT/$scene"
  [[ -n ${FRAMES:-} && " $FRAMES " != *" $name "* ]] && return
  local obj tex
  if [[ $scene == *.obj ]]; then # an OBJ file (absolute path) with TEXTURE
    obj=$scene
    tex=$TEXTURE
  else
    obj=$OUT/$scene/$scene.obj
    java -jar "$JAR" export --scene "$scene" --to "$obj" >/dev/null
    tex=${TEXTURE:-$(ls "$OUT/$scene/$scene"-*.ppm | head -n 1)}
  fi
  # glref takes one texture, so Trisect gets the same one for every material.
  java -jar "$JAR" render --obj "$obj" --texture "$tex" --size "$SIZE" --mode perspective --filter "$FILTER" \
    --eye "$eye" --target "$target" --near 0.1 --far "$far" --cull "$cull" ${OPTS:-} \
    --out "$OUT/$name-ours.ppm" --uv-out "$OUT/$name-ours.pfm"
  IFS=, read -r ex ey ez <<<"$eye"
  IFS=, read -r tx ty tz <<<"$target"
  # shellcheck disable=SC2086 # env is a list of NAME=value
  env $GLREF_ENV GLREF_FILTER="$FILTER" GLREF_UV="$OUT/$name-gl.pfm" "$GLREF" "$obj" "$tex" "$OUT/$name-gl.ppm" "$W" "$H" \
    "$ex" "$ey" "$ez" "$tx" "$ty" "$tz" 60 0.1 "$far" "$cull" 2>/dev/null
  printf '%-14s ' "$name"
  java -jar "$JAR" diff --image "$OUT/$name-ours.ppm" --uv "$OUT/$name-ours.pfm" \
    --reference "$OUT/$name-gl.ppm" --reference-uv "$OUT/$name-gl.pfm"
  # Over covered pixels: the share within 2/255 in every channel, and the PSNR.
  printf '%-14s ' "$name"
  python3 scripts/within.py "$OUT/$name-ours.ppm" "$OUT/$name-gl.ppm" "$OUT/$name-ours.pfm" "$OUT/$name-gl.pfm"
}

# Far planes of 40-60 m keep texel coordinates below a few thousand, where OpenGL's float32
# arithmetic resolves a hundredth of a texel; the frames to 1000 m reach coordinates of ~20000,
# where it does not (Trisect's values there match an exact ray-cast oracle to 0.002 texel).
frame floor-40     floor  1.3,1.7,6.2     0.4,0,-2      back  40
frame boxes-60     boxes  3.5,3.2,7       -0.5,0.8,-6   back  60
frame demo-60      demo   0.5,1.8,6       0,1,-10       back  60
frame floor        floor  1.3,1.7,6.2     0.4,0,-2      back
frame floor-high   floor  -3,12,20        2,0,-15       back
frame boxes        boxes  3.5,3.2,7       -0.5,0.8,-6   back
frame boxes-close  boxes  0.7,1.3,-3.6    0.2,1,-6      none
frame demo         demo   0.5,1.8,6       0,1,-10       back
frame demo-wall    demo   4.2,1.5,3       6,1.2,-30     back
frame sphere       sphere 0.6,0.9,3.6     0,0,0         back  20
[[ -n ${HEAD:-} ]] && frame head "$HEAD" 0,0.1,2.6 0,0,0 back 20
exit 0
