#!/usr/bin/env python3
"""Picks a sample of hours of an EPW file for annual_vs_grid.py: hours whose global horizontal
illuminance (a rough efficacy of 110 lm/W) is at least 1000 lx, in three kinds spread over the
year: clear (beam at least 3x the diffuse), overcast (no beam or beam under a fifth of the
diffuse) and low sun (elevation under 15 degrees with a beam). The sun's elevation by NOAA's
approximate formulas (selection only; the renderer uses NREL's SPA).

usage: annual_hours.py FILE.epw [PER_KIND]   prints MM-DD-HH lines"""
import csv, math, sys

def elevation(lat, lon, tz, day, hour):
    g = 2 * math.pi / 365 * (day - 1 + (hour - 12) / 24)
    eqt = 229.18 * (0.000075 + 0.001868 * math.cos(g) - 0.032077 * math.sin(g) - 0.014615 * math.cos(2 * g) - 0.040849 * math.sin(2 * g))
    decl = 0.006918 - 0.399912 * math.cos(g) + 0.070257 * math.sin(g) - 0.006758 * math.cos(2 * g) + 0.000907 * math.sin(2 * g)
    minutes = hour * 60 + eqt + 4 * lon - 60 * tz
    ha = math.radians(minutes / 4 - 180)
    la = math.radians(lat)
    return math.degrees(math.asin(math.sin(la) * math.sin(decl) + math.cos(la) * math.cos(decl) * math.cos(ha)))

rows = list(csv.reader(open(sys.argv[1])))
per = int(sys.argv[2]) if len(sys.argv) > 2 else 17
loc = rows[0]
lat, lon, tz = float(loc[6]), float(loc[7]), float(loc[8])
kinds = {"clear": [], "overcast": [], "low": []}
days = [0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334]
for r in rows[8:]:
    m, d, h = int(r[1]), int(r[2]), int(r[3])
    ib, ed = float(r[14]), float(r[15])
    e = elevation(lat, lon, tz, days[m - 1] + d, h - 0.5)
    if e <= 2: continue
    gh = 110 * (ed + ib * math.sin(math.radians(e)))
    if gh < 1000: continue
    key = "%02d-%02d-%02d" % (m, d, h)
    if ib > 0 and e < 15: kinds["low"].append(key)
    elif ib >= 3 * ed: kinds["clear"].append(key)
    elif ib < 0.2 * ed: kinds["overcast"].append(key)
for name, hours in kinds.items():
    step = max(1, len(hours) // per)
    for key in hours[step // 2::step][:per]: print(key)
