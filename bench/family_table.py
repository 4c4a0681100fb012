#!/usr/bin/env python3
"""Expected relmse of each backend at given times over several `lucerna bench` runs (seeds), and
which backend is best and how long `auto`'s choice takes to reach the best one's final error.

usage: family_table.py [--auto BACKEND] [--times 10,20] BENCH.csv [BENCH.csv ...]

Each backend's relmse at time t is read off its curve in each CSV by log-log interpolation and
averaged over the CSVs (the expected error: a run whose chain stuck counts as much as it weighs).
With --auto, prints the time the chosen backend's mean curve takes to reach the best backend's
mean error at the last time, as a multiple of that time (1: auto is the best; 2: twice as long),
extrapolated as relmse ~ 1/t where it does not get there within the runs.
"""
import csv
import math
import sys


def curves(path):
    out = {}
    for r in csv.DictReader(open(path)):
        out.setdefault(r["backend"], []).append((float(r["seconds"]), float(r["relmse"])))
    return out


def at(c, t):
    if t <= c[0][0]:
        return c[0][1]
    for (t0, e0), (t1, e1) in zip(c, c[1:]):
        if t0 <= t <= t1:
            if t1 == t0 or e0 <= 0 or e1 <= 0:
                return e1
            f = math.log(t / t0) / math.log(t1 / t0)
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return c[-1][1]


def main():
    args = sys.argv[1:]
    auto, times = None, [10.0, 20.0]
    while args and args[0].startswith("--"):
        if args[0] == "--auto":
            auto = args[1]
        elif args[0] == "--times":
            times = [float(x) for x in args[1].split(",")]
        args = args[2:]
    runs = [curves(p) for p in args]
    backends = [b for b in runs[0] if all(b in r for r in runs)]
    mean = {b: {t: sum(at(r[b], t) for r in runs) / len(runs) for t in times} for b in backends}
    print("backend " + " ".join(f"relmse@{t:g}s" for t in times) + f"   ({len(runs)} runs)")
    for b in backends:
        print(f"{b} " + " ".join(f"{mean[b][t]:.3g}" for t in times))
    last = times[-1]
    best = min(backends, key=lambda b: mean[b][last])
    print(f"best at {last:g} s: {best}")
    if auto:
        target = mean[best][last]
        grid = [last * k / 200.0 for k in range(1, 201)]
        reach = next((t for t in grid if sum(at(r[auto], t) for r in runs) / len(runs) <= target), None)
        if reach is None:
            # Not reached within the runs: relmse of an unbiased estimate falls as 1 / time.
            print(f"auto ({auto}): time to the best's {target:.3g} about {mean[auto][last] / target:.2f} times "
                  f"the best's (extrapolated as relmse ~ 1/t)")
        else:
            print(f"auto ({auto}): time to the best's {target:.3g} {reach / last:.2f} times the best's")


if __name__ == "__main__":
    main()
