#!/usr/bin/env python3
"""SPEC.md section 6's contract for `lucerna annual` against `lucerna grid`: for a sample of hours,
the hour's scene (--export-hour) is computed by `grid` on the same points, and each annual value is
compared with the grid's: the share of values that differ by more than sqrt(U_annual^2 + U_grid^2)
(at most 5% plus the binomial allowance) and sum |E_annual - E_grid| / sum E_grid.

usage: annual_vs_grid.py LUCERNA SCENE WEATHER OUTDIR --grid-args "..." --annual-args "..." HOURS...
HOURS are MM-DD-HH; annual's --hourly and --hourly-error are written once to OUTDIR."""
import argparse, csv, math, os, shlex, subprocess, sys, time

def run(cmd):
    t = time.time()
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), out.stderr))
    return out.stdout, time.time() - t

def read_hourly(path):
    rows = {}
    with open(path) as f:
        r = csv.reader(f)
        next(r)
        for row in r:
            rows["%02d-%02d-%02d" % (int(row[0]), int(row[1]), int(row[2]))] = [float(x) for x in row[3:]]
    return rows

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("lucerna"); ap.add_argument("scene"); ap.add_argument("weather"); ap.add_argument("out")
    ap.add_argument("--grid-args", default=""); ap.add_argument("--annual-args", default="")
    ap.add_argument("hours", nargs="+")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    hourly, hourly_err = os.path.join(a.out, "hourly.csv"), os.path.join(a.out, "hourly_error.csv")
    text, seconds = run([a.lucerna, "annual", a.scene, "--weather", a.weather, "--hourly", hourly, "--hourly-error", hourly_err]
                        + shlex.split(a.annual_args))
    print("annual: %.1f s" % seconds)
    for line in text.splitlines():
        if line.startswith("stated"): print(line)
    E, U = read_hourly(hourly), read_hourly(hourly_err)
    total_n = total_out = 0
    sum_abs = sum_grid = 0.0
    for hour in a.hours:
        scene = os.path.join(a.out, "hour_%s.json" % hour)
        run([a.lucerna, "annual", a.scene, "--weather", a.weather, "--export-hour", hour, scene])
        gcsv = os.path.join(a.out, "grid_%s.csv" % hour)
        _, gs = run([a.lucerna, "grid", scene, "--csv", gcsv] + shlex.split(a.grid_args))
        with open(gcsv) as f:
            g = [r for r in csv.DictReader(f)]
        key = "%02d-%02d-%02d" % tuple(int(x) for x in hour.split("-"))
        n = out = 0
        ha = hg = 0.0
        for p, r in enumerate(g):
            if r["inside_geometry"] == "1": continue
            eg, ug = float(r["illuminance_lux"]), float(r["error_lux"])
            ea, ua = E[key][p], U[key][p]
            n += 1
            out += abs(ea - eg) > math.sqrt(ua * ua + ug * ug)
            ha += abs(ea - eg); hg += eg
        total_n += n; total_out += out; sum_abs += ha; sum_grid += hg
        print("%s: grid %.0f s, Eavg grid %.1f lx, annual %.1f lx, sum|dE|/sumE %.2f%%, outside the bars %d of %d"
              % (hour, gs, hg / n, (hg + sum(E[key][p] - float(r["illuminance_lux"]) for p, r in enumerate(g)
                                             if r["inside_geometry"] != "1")) / n, 100 * ha / hg, out, n))
    allowance = 0.05 * total_n + 1.645 * math.sqrt(total_n * 0.05 * 0.95)
    print("all: sum|dE|/sumE %.2f%% (target 3%%); outside the bars %d of %d, allowed %.0f (5%% plus the binomial allowance): %s"
          % (100 * sum_abs / sum_grid, total_out, total_n, allowance, "met" if total_out <= allowance else "NOT met"))

main()
