#!/usr/bin/env python3
"""Time each of two backends in a `lucerna bench` CSV takes to reach the same relmse.

usage: time_to_error.py bench.csv BACKEND_A BACKEND_B

The error is the larger of the two curves' final relmse (so both reach it); each time is when its
curve comes down to that error for good (a Metropolis curve can rise again when a chain sticks,
and the first crossing would flatter it), read off by log-log interpolation between the samples
around it. Prints both times, their
ratio (A / B: how many times sooner B gets there) and each backend's rays per second from the
`rays` column.
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


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    path, a, b = sys.argv[1:]
    ca, cb = curve(path, a), curve(path, b)
    target = max(ca[-1][1], cb[-1][1])
    ta, tb = time_to(ca, target), time_to(cb, target)
    rate = lambda c: c[-1][2] / c[-1][0] * 1e-6
    print(f"relmse {target:.4g}: {a} {ta:.1f} s, {b} {tb:.1f} s, ratio {ta / tb:.2f}; "
          f"Mrays/s {a} {rate(ca):.2f}, {b} {rate(cb):.2f}")


if __name__ == "__main__":
    main()
