#!/usr/bin/env python3
"""Time each of two backends in `lucerna bench` CSVs takes to reach the same relmse.

usage: time_to_error.py BENCH.csv [BENCH.csv ...] BACKEND_A BACKEND_B

The error is the larger of the two curves' final relmse (so both reach it); each time is when its
curve comes down to that error for good (a Metropolis curve can rise again when a chain sticks,
and the first crossing would flatter it), read off by log-log interpolation between the samples
around it. Prints both times, their ratio (A / B: how many times sooner B gets there) and each
backend's rays per second from the `rays` column.

With several CSVs (runs with different seeds), each backend's curve is the mean relmse of its runs
(each interpolated log-log onto common times, from the latest first sample to the earliest last
one): the expected error, in which a run whose chain stuck counts as much as it weighs, where the
median of per-run ratios would pass over it. Their per-run ratios are printed too.
"""
import csv
import math
import sys


def curve(path, name):
    rows = [r for r in csv.DictReader(open(path)) if r["backend"] == name]
    if not rows:
        sys.exit(f"{path}: no backend {name}")
    return [(float(r["seconds"]), float(r["relmse"]), float(r.get("rays", "nan"))) for r in rows]


def time_to(c, target):
    # The last sample above the target; the curve stays at or below it after the next one.
    above = [i for i, (_, e, _) in enumerate(c) if e > target]
    if not above:
        return c[0][0]
    i = above[-1]
    if i + 1 == len(c):
        return c[-1][0]
    (t0, e0, _), (t1, e1, _) = c[i], c[i + 1]
    a = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
    return math.exp(math.log(t0) + a * (math.log(t1) - math.log(t0)))


def at(c, t):
    """relmse and rays of curve c at time t (log-log within its samples)."""
    for (t0, e0, r0), (t1, e1, r1) in zip(c, c[1:]):
        if t0 <= t <= t1:
            a = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(e0) + a * (math.log(e1) - math.log(e0))), r0 + a * (r1 - r0)
    return (c[0][1], c[0][2]) if t < c[0][0] else (c[-1][1], c[-1][2])


def mean_curve(curves, n=64):
    start, end = max(c[0][0] for c in curves), min(c[-1][0] for c in curves)
    times = [start * (end / start) ** (i / (n - 1)) for i in range(n)]
    return [(t, sum(at(c, t)[0] for c in curves) / len(curves), sum(at(c, t)[1] for c in curves) / len(curves))
            for t in times]


def compare(ca, cb, a, b):
    target = max(ca[-1][1], cb[-1][1])
    ta, tb = time_to(ca, target), time_to(cb, target)
    rate = lambda c: c[-1][2] / c[-1][0] * 1e-6
    return (f"relmse {target:.4g}: {a} {ta:.1f} s, {b} {tb:.1f} s, ratio {ta / tb:.2f}; "
            f"Mrays/s {a} {rate(ca):.2f}, {b} {rate(cb):.2f}")


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    paths, a, b = sys.argv[1:-2], sys.argv[-2], sys.argv[-1]
    runs = [(curve(p, a), curve(p, b)) for p in paths]
    if len(runs) == 1:
        print(compare(*runs[0], a, b))
        return
    for p, (ca, cb) in zip(paths, runs):
        print(f"{p}: {compare(ca, cb, a, b)}")
    print(f"mean of {len(runs)} runs: " + compare(mean_curve([r[0] for r in runs]), mean_curve([r[1] for r in runs]), a, b))


if __name__ == "__main__":
    main()
