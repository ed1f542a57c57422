#!/usr/bin/env bash
# Compares the frame times of two builds side by side: runs `bench --json` of jar A and jar B in
# alternation, REPS times each, with the same arguments, and prints per path the median ms of each
# run, the median of those medians, and the B/A ratio of each pair (its spread is the noise of this
# machine; a single timing on a shared machine says little).
#
#   scripts/compare-builds.sh OLD.jar NEW.jar [bench options...]
#   REPS=5 scripts/compare-builds.sh /tmp/old.jar target/trisect.jar --scene demo --size 1920x1080
#
# Environment: REPS (default 3), JAVA (default java). Needs python3 for the summary.
set -euo pipefail
. "$(dirname "$0")/two-jars.sh"
two_jars "A.jar B.jar [bench options...]" 2 "" "$@"
a=$1
b=$2
shift 2
reps=${REPS:-3}
java=${JAVA:-java}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for ((r = 1; r <= reps; r++)); do
  for side in A B; do
    jar=$a
    [[ $side == B ]] && jar=$b
    "$java" -jar "$jar" bench --json "$@" 2>/dev/null | sed "s/^/$side $r /" >>"$out"
  done
done
python3 - "$out" "$a" "$b" <<'EOF'
import json, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    side, rep, text = line.split(" ", 2)
    d = json.loads(text)
    if "median_ms" not in d:
        continue
    rows.setdefault(d["path"], {}).setdefault(side, {})[int(rep)] = d["median_ms"]
print(f"A = {sys.argv[2]}\nB = {sys.argv[3]}")
print(f"{'path':<14}{'A median ms (runs)':<34}{'B median ms (runs)':<34}B/A per run")
for path, sides in rows.items():
    a, b = sides.get("A", {}), sides.get("B", {})
    fa = " ".join(f"{a[k]:.2f}" for k in sorted(a))
    fb = " ".join(f"{b[k]:.2f}" for k in sorted(b))
    ratios = [b[k] / a[k] for k in sorted(a) if k in b and a[k] > 0]
    ma = statistics.median(a.values()) if a else float("nan")
    mb = statistics.median(b.values()) if b else float("nan")
    rs = " ".join(f"{x:.2f}" for x in ratios)
    print(f"{path:<14}{ma:7.2f} ({fa})".ljust(48) + f"{mb:7.2f} ({fb})".ljust(34) + rs)
EOF
