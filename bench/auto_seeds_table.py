#!/usr/bin/env python3
"""The table of bench/auto_seeds.sh: per scene, the mean over seeds of each backend's relmse at
the end of its run, auto's over the best single method's (the ratio of the means: expected
errors), the per-seed ratios, and path's over auto's where path (the former rule's pick) ran and
is not the best.
    python3 bench/auto_seeds_table.py OUT"""
import collections
import csv
import glob
import os
import re
import sys

final = collections.defaultdict(lambda: collections.defaultdict(dict))  # scene -> backend -> seed -> relmse
for path in glob.glob(os.path.join(sys.argv[1], '*', 'bench.csv')):
    m = re.match(r'(.*)-s(\d+)$', os.path.basename(os.path.dirname(path)))
    last = {row['backend']: float(row['relmse']) for row in csv.DictReader(open(path))}
    for backend, value in last.items():
        final[m.group(1)][backend][int(m.group(2))] = value

print("| scene | seeds | auto | best single | auto / best | per seed | path / auto |")
print("|---|---|---|---|---|---|---|")
for scene in sorted(final):
    d = final[scene]
    singles = [b for b in d if b != 'auto']
    seeds = [s for s in sorted(d['auto']) if all(s in d[b] for b in singles)]
    mean = lambda b: sum(d[b][s] for s in seeds) / len(seeds)
    best = min(singles, key=mean)
    per = ', '.join('%.2f' % (d['auto'][s] / d[best][s]) for s in seeds)
    rule = '%.1f' % (mean('path') / mean('auto')) if 'path' in singles and best != 'path' else ''
    print("| %s | %s | %.3g | %s %.3g | %.2f | %s | %s |" % (scene, ','.join(map(str, seeds)), mean('auto'), best,
                                                           mean(best), mean('auto') / mean(best), per, rule))
