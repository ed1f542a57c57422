#!/usr/bin/env bash
# Compares two builds in one JVM: each jar in its own class loader, their frames interleaved (A B,
# then B A, ...), each timed by the rendering thread's CPU time, one thread. Steadier than timing
# separate runs on a shared machine, since both builds see the same load at the same moments.
# THREADS=2 renders with two threads instead: each pair interleaves the builds frame by frame
# (A B B A ...) and times every frame by the wall clock (the table) and by the CPU time of that
# build's rendering threads (a second table): the calling thread's and the helpers its renderers
# started, each by its own clock, named in the output. Not the process clock, which would count the
# JIT compiler's and the collector's threads (serving both builds in this one JVM) into whichever
# frame is running, and ticks too coarsely for a frame.
# Prints per path the median CPU ms per frame of each build and the B/A ratio of each pair (median
# and range), and with the affine path listed, the CPU time per extra piece of the tessellated
# paths (their frames fill the affine frame's pixels).
#
#   scripts/side-by-side.sh OLD.jar NEW.jar [SCENE] [WxH] [PAIRS] [FRAMES] [PATH...]
#   scripts/side-by-side.sh /tmp/old.jar target/trisect.jar demo 1920x1080 15 5 affine edge error perspective
#   THREADS=2 scripts/side-by-side.sh /tmp/old.jar target/trisect.jar floor 1920x1080 9 6 perspective spans
#
# PATH: perspective, affine, edge (tessellated, 32 px edges), error (tessellated, 0.5 px), spans
# (0.5 px; builds from 3fa131c on); each may
# be followed by @bilinear or @trilinear (the texture filter; nearest without), then by +borders or
# +fade to draw the border overlay (plain or faded) with the frame, so that "edge edge+borders"
# shows what the overlay adds and "error@trilinear" times the tessellated path with trilinear.
# With perspective listed (with the same filter), each other path's time over the per-pixel path's
# in the same build and pair is printed too: "spans perspective" gives spans / per-pixel.
# Caution: each build is compiled once per run, and some loops' compiled speed is decided per JVM
# (the nearest affine loop runs in two modes ~2x apart on the floor scene, in every build so far):
# repeat the run, or use scripts/separate-jvms.sh, which shows the spread over many JVMs.
# Both jars must have the API Frame.java uses (DemoScenes in dev.trisect.scene or dev.trisect.content,
# RenderSettings, FrameRenderer).
set -euo pipefail
. "$(dirname "$0")/two-jars.sh"
two_jars "A.jar B.jar [scene] [WxH] [pairs] [frames] [path...]" 2 "" "$@"
a=$1
b=$2
scene=${3:-demo}
size=${4:-1920x1080}
pairs=${5:-15}
frames=${6:-5}
threads=${THREADS:-1}
[[ $threads =~ ^[1-9][0-9]*$ ]] || { echo "$0: THREADS must be a positive whole number, not '$threads'" >&2; exit 2; }
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "$0: the size must be WxH, as 1920x1080, not '$size'" >&2; exit 2; }
for n in "$pairs" "$frames"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "$0: pairs and frames must be positive whole numbers, not '$n'" >&2; exit 2; }
done
shift $(( $# < 6 ? $# : 6 ))
paths=("$@")
[[ ${#paths[@]} -gt 0 ]] || paths=(affine edge error perspective)
src=$(cd "$(dirname "$0")/side-by-side" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$src/frame-for.sh"
frame_for "$a" "$tmp/a"
frame_for "$b" "$tmp/b"
javac -sourcepath "$src" -d "$tmp/run" "$src/SideBySide.java"
java -cp "$tmp/run" SideBySide "$tmp/a" "$tmp/b" "$a" "$b" "$scene" "$size" "$pairs" "$frames" "$threads" "${paths[@]}"
