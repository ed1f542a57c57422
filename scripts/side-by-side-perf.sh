#!/usr/bin/env bash
# Where two builds' frame time goes, method by method, measured in one JVM: both builds' frames of
# one path alternate (A B, then B A, ...) under `perf record -k mono` (timer sampling, 2000 Hz, every
# thread), and each sample of a rendering thread (the main thread and the renderers' helpers) is
# given to the build whose frame it fell in by its time. Prints the samples per frame of each build
# (one sample is 0.5 ms of one thread's time) and, per method (the JIT's own names, inlined callees
# counted in their caller), A's and B's samples per frame and B's extra samples in all. Separate JVMs
# drift too much on this shared machine to compare methods across them; here both builds share the
# JVM's moments, compiler and collector (their threads are not counted). A method that both builds
# have by the same name is still two methods: each sample falls in one build's frame.
# Needs perf (`perf record` allowed for this user).
#
#   scripts/side-by-side-perf.sh OLD.jar NEW.jar [scene] [path] [threads] [pairs] [top]
#   scripts/side-by-side-perf.sh final-1067f75.jar target/trisect.jar boxes spans 2 300 30
#
# PATH as for side-by-side.sh (perspective, affine, edge, error, spans, each with @bilinear or
# @trilinear). Defaults: demo, perspective, 1 thread, 300 pairs, the top 30 methods.
set -euo pipefail
. "$(dirname "$0")/two-jars.sh"
two_jars "A.jar B.jar [scene] [path] [threads] [pairs] [top]" 2 "" "$@"
a=$1
b=$2
command -v perf >/dev/null || { echo "$0: perf is not installed" >&2; exit 2; }
scene=${3:-demo}
path=${4:-perspective}
threads=${5:-1}
pairs=${6:-300}
top=${7:-30}
for n in "$threads" "$pairs" "$top"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "$0: threads, pairs and top must be positive whole numbers, not '$n'" >&2; exit 2; }
done
src=$(cd "$(dirname "$0")/side-by-side" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$src/frame-for.sh"
frame_for "$a" "$tmp/a"
frame_for "$b" "$tmp/b"
javac -sourcepath "$src" -d "$tmp/run" "$src/PerfPair.java"
# The frames are checked before perf runs, so that a bad scene or path is one line, not a profile.
java -cp "$tmp/run" PerfPair "$tmp/a" "$a" "$tmp/b" "$b" "$scene" 1920x1080 "$path" "$threads" 0 -
perf record -q -k mono -F 2000 -o "$tmp/perf.data" -- java -XX:+UnlockDiagnosticVMOptions -XX:+DumpPerfMapAtExit \
  -cp "$tmp/run" PerfPair "$tmp/a" "$a" "$tmp/b" "$b" "$scene" 1920x1080 "$path" "$threads" "$pairs" "$tmp/frames.txt"
perf script -i "$tmp/perf.data" -F comm,time,ip,sym -G --ns 2>/dev/null \
  | python3 -c '
import bisect, collections, re, sys
frames = sorted(tuple(map(int, line.split())) for line in open(sys.argv[1]))
starts = [f[0] for f in frames]
count = [collections.Counter(), collections.Counter()]
for line in sys.stdin:
    m = re.match(r"\s*(.+?)\s+(\d+)\.(\d+):\s+[0-9a-f]+\s*(.*)$", line)
    # The rendering threads: the main thread ("java") and the renderers helpers ("trisect-render-...").
    if not m or not (m[1] == "java" or m[1].startswith("trisect-render")):
        continue
    t = int(m[2]) * 10**9 + int(m[3].ljust(9, "0"))
    i = bisect.bisect_right(starts, t) - 1
    if i < 0 or t > frames[i][1]:
        continue
    sym = m[4].strip() or "[unknown]"
    name = re.match(r"\S+ ([\w.$]+)\(", sym)
    count[frames[i][2]][(name[1] if name else sym).replace("dev.trisect.", "")] += 1
n = len(frames) // 2
a, b = count
ta, tb = sum(a.values()), sum(b.values())
if ta == 0 or tb == 0:
    sys.exit("side-by-side-perf: perf gave no samples of a rendering thread inside the frames of "
             + ("A" if ta == 0 else "B") + " (may perf sample the threads of this user?)")
print(f"{sys.argv[2]} {sys.argv[3]}, {sys.argv[4]} threads, {n} frames each; samples per frame (0.5 ms each): "
      f"A {ta / n:.2f}, B {tb / n:.2f}, B/A {tb / ta:.3f}")
print("%8s %8s %6s  method (samples per frame; B-A: samples in all)" % ("A", "B", "B-A"))
for k in sorted(set(a) | set(b), key=lambda k: -(a[k] + b[k]))[:int(sys.argv[5])]:
    print(f"{a[k] / n:8.3f} {b[k] / n:8.3f} {b[k] - a[k]:+6d}  {k[:110]}")
' "$tmp/frames.txt" "$scene" "$path" "$threads" "$top"
