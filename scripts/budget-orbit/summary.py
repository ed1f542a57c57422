#!/usr/bin/env python3
"""Summarises budget-controller traces (bench --target-ms tables, or TimeOnlyOrbit's): frames over the
piece budget, reversals of the threshold (all, and in the second half), second-half median frame time
and threshold with the threshold's range. bench tables also say which frames the piece budget held."""
import statistics
import sys

for name in sys.argv[1:]:
    rows = [l.split() for l in open(name) if l.strip() and l.split()[0].isdigit()]
    th = [float(r[1]) for r in rows]
    ms = [float(r[2]) for r in rows]
    over = sum(1 for r in rows if len(r) > 4 and r[4] == 'over')
    held = sum(1 for r in rows if len(r) > 5 and r[5] == 'pieces')
    n = len(rows)
    half = n // 2

    def reversals(start):
        count, last = 0, 0
        for i in range(max(1, start + 1), n):
            d = (th[i] > th[i - 1]) - (th[i] < th[i - 1])
            if d:
                count += 1 if last and d != last else 0
                last = d
        return count

    print(f"{name}: {n} frames, {over} over the piece budget, {held} held by it, threshold reversals {reversals(0)} "
          f"(second half {reversals(half)}), second half: median {statistics.median(ms[half:]):.2f} ms, "
          f"threshold median {statistics.median(th[half:]):.2f} px, range {min(th[half:]):.2f}-{max(th[half:]):.2f} px")
