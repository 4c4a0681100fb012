#!/usr/bin/env python3
"""Compares `lucerna annual --hourly` (hours x points) with Radiance's dctimestep illuminance
(points x hours, rmtxop ASCII) over the occupied hours (8:00 to 18:00): sum |L - R| / sum R, the
plane's hourly ratio L / R (5%, median, 95%), DA300 and UDI.
usage: radiance_compare.py LUCERNA.csv RADIANCE.txt"""
import csv, sys
R = [[float(x) for x in line.split()] for line in open(sys.argv[2]).read().split('\n\n', 1)[1].strip().split('\n')]
rows = list(csv.reader(open(sys.argv[1])))[1:]
hours = [(int(r[0]), int(r[1]), int(r[2])) for r in rows]
L = [[float(x) for x in r[3:]] for r in rows]
n = len(R)
occ = [i for i, (m, d, h) in enumerate(hours) if 8 <= h - 0.5 < 18]
diff = sum(abs(L[i][p] - R[p][i]) for i in occ for p in range(n))
total_r = sum(R[p][i] for i in occ for p in range(n))
total_l = sum(L[i][p] for i in occ for p in range(n))
ratios = sorted(sum(L[i]) / sum(R[p][i] for p in range(n)) for i in occ if sum(R[p][i] for p in range(n)) > 0)
q = lambda f: ratios[min(len(ratios) - 1, int(f * len(ratios)))]
print("%d points, %d occupied hours: sum|L-R|/sum R %.2f%%, sum L/sum R %.4f; plane's hourly ratio 5%% %.3f, median %.3f, 95%% %.3f"
      % (n, len(occ), 100 * diff / total_r, total_l / total_r, q(0.05), q(0.5), q(0.95)))
da = lambda v: sum(sum(v(i, p) >= 300 for i in occ) / len(occ) for p in range(n)) / n
print("mean DA300: lucerna %.3f, radiance %.3f" % (da(lambda i, p: L[i][p]), da(lambda i, p: R[p][i])))
for lo, hi, name in [(0, 100, 'fell short'), (100, 3000.0001, 'useful'), (3000.0001, 1e12, 'exceeded')]:
    u = lambda v: sum(lo <= v(i, p) < hi for i in occ for p in range(n)) / (n * len(occ))
    print("UDI %s: lucerna %.3f, radiance %.3f" % (name, u(lambda i, p: L[i][p]), u(lambda i, p: R[p][i])))
