#!/usr/bin/env python3
"""How well a short pilot of each backend predicts which one is best at the full budget.

usage: pilot_fidelity.py [--time T] [--pilots 1,2,4] [--auto NAME=BACKEND ...] BENCH.csv [BENCH.csv ...]

Each BENCH.csv is one `lucerna bench` run (all candidate backends, one seed, --time T). Its scene
name is the name of the folder it is in. For each pilot time p and each backend the first row with
seconds >= p gives the film's estimated relmse e_p (column estimated_relmse) and the true relmse
r_p; the prediction at T assumes error proportional to 1/time: e_p * s / T, where s is that row's
own time (at least p; 12 samples a decade, so s is within about a fifth of p unless a backend's
passes are long, which is flagged with '*'). The predicted winner has the lowest prediction; the
true winner the lowest true relmse on its last row (about T).

Printed per run:
  - per backend: e_p / r_p at each p and at T (the estimate's fidelity; below 1: too optimistic),
  - the predicted and the true ranking,
  - regret = true final relmse of the predicted winner / that of the true winner (1: perfect),
  - the same with the pilot's cost counted: the winner gets only T - n p seconds (n candidates
    piloted p seconds each), so its relmse is scaled by T / (T - n p),
  - auto's regret: the true final relmse of the backend the current rule picks over the winner's.
    Auto's pick comes from --auto NAME=BACKEND, else from auto.txt next to the CSV (the line
    `lucerna info SCENE` prints, "auto backend: BACKEND: reason"), else from rows labelled
    "auto" in the CSV (which are then not a candidate).
  - the winner and regret had the pilot used the true relmse r_p instead of the estimate (what
    the 1/time extrapolation alone gets right or wrong, apart from the estimate's fidelity).
Then a summary table over all runs, the per-backend fidelity ratios e/r (geometric means over
runs) and the predictions over the true final relmse (estimate and 1/time extrapolation together).
The true relmse includes the reference's own error (and any bias); the estimate sees neither.
Standard library only.
"""
import csv
import math
import os
import sys
from collections import defaultdict


def usage(msg=None):
    if msg:
        print(f"pilot_fidelity.py: {msg}", file=sys.stderr)
    print(__doc__.split("\n\n")[1], file=sys.stderr)
    sys.exit(2)


def num(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def load(path):
    rows = defaultdict(list)
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[r["backend"]].append((num(r["seconds"]), num(r["relmse"]), num(r["estimated_relmse"])))
    for b in rows:
        rows[b].sort()
    return rows


def auto_choice(path, name, overrides, rows):
    if name in overrides:
        return overrides[name]
    txt = os.path.join(os.path.dirname(os.path.abspath(path)), "auto.txt")
    if os.path.exists(txt):
        for line in open(txt):
            if line.startswith("auto backend:"):
                return line.split(":", 2)[1].strip()
    if "auto" in rows:
        return "auto"
    return None


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if math.isinf(x):
        return "inf"
    return f"{x:.{digits}g}"


def geomean(xs):
    xs = [x for x in xs if x is not None and math.isfinite(x) and x > 0]
    if not xs:
        return math.nan
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def analyse(path, T, pilots, overrides):
    rows = load(path)
    name = os.path.basename(os.path.dirname(os.path.abspath(path))) or path
    auto = auto_choice(path, name, overrides, rows)
    cands = [b for b in rows if b != "auto"]
    n = len(cands)
    final = {b: rows[b][-1] for b in rows}  # (seconds, relmse, est)
    true_rank = sorted(cands, key=lambda b: final[b][1] if math.isfinite(final[b][1]) else math.inf)
    best = true_rank[0]
    rbest = final[best][1]
    auto_regret = final[auto][1] / rbest if auto in final else math.nan

    print(f"== {name} ({path})")
    print(f"   true winner at T: {best} (relmse {fmt(rbest)}); auto picks {auto or '?'}"
          f" (regret {fmt(auto_regret)})")
    print(f"   true ranking: " + " < ".join(f"{b} {fmt(final[b][1])}" for b in true_rank))
    fid = {}  # (backend, p or 'T') -> e/r
    results = []
    wd = max(8, max(len(b) for b in cands))
    hdr = "   " + "backend".ljust(wd) + " " + "".join(f"  e/r@{p:g}s  pred@{p:g}s " for p in pilots) + "  e/r@T     t_last"
    print(hdr)
    preds = {}
    oracle = {}  # the same prediction from the true relmse at the pilot: the 1/time model alone
    for b in cands:
        line = f"   {b:{wd}s}"
        for p in pilots:
            row = next((r for r in rows[b] if r[0] >= p), None)
            if row is None:
                fid[(b, p)] = math.nan
                preds[(b, p)] = math.nan
                oracle[(b, p)] = math.nan
                line += f"  {'-':>7s}  {'-':>9s} "
                continue
            s, r, e = row
            fid[(b, p)] = e / r if r > 0 else math.nan
            preds[(b, p)] = e * s / T
            oracle[(b, p)] = r * s / T
            flag = "*" if s > 1.5 * p else " "
            line += f"  {fmt(fid[(b, p)]):>7s}  {fmt(preds[(b, p)]):>8s}{flag} "
        s, r, e = final[b]
        fid[(b, "T")] = e / r if r > 0 else math.nan
        for p in pilots:
            fid[(b, ("pred", p))] = preds[(b, p)] / r if r > 0 else math.nan
        line += f"  {fmt(fid[(b, 'T')]):>7s}  {s:6.1f}"
        print(line)
    for p in pilots:
        ok = [b for b in cands if math.isfinite(preds[(b, p)])]
        pred_rank = sorted(ok, key=lambda b: preds[(b, p)])
        if not pred_rank:
            continue
        w = pred_rank[0]
        regret = final[w][1] / rbest
        left = T - n * p
        regret_cost = regret * T / left if left > 0 else math.inf
        okt = [b for b in cands if math.isfinite(oracle[(b, p)])]
        wt = min(okt, key=lambda b: oracle[(b, p)])
        regret_true = final[wt][1] / rbest
        print(f"   p={p:g}s predicted: " + " < ".join(pred_rank) +
              f" | winner {w}, regret {fmt(regret)}, with pilot cost {fmt(regret_cost)}"
              f" | from the true pilot relmse: {wt}, regret {fmt(regret_true)}")
        results.append(dict(scene=name, p=p, pred=w, true=best, regret=regret, regret_cost=regret_cost,
                            auto=auto or "?", auto_regret=auto_regret, pred_true=wt, regret_true=regret_true))
    print()
    return results, fid, cands


def main(argv):
    T = 30.0
    pilots = [1.0, 2.0, 4.0]
    overrides = {}
    files = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(__doc__)
            return 0
        if a == "--time":
            i += 1
            T = float(argv[i])
        elif a == "--pilots":
            i += 1
            pilots = [float(x) for x in argv[i].split(",")]
        elif a == "--auto":
            i += 1
            k, _, v = argv[i].partition("=")
            overrides[k] = v
        elif a.startswith("--"):
            usage(f"unknown option {a}")
        else:
            files.append(a)
        i += 1
    if not files:
        usage("no bench.csv given")
    allres = []
    allfid = defaultdict(list)
    backends = []
    for f in files:
        res, fid, cands = analyse(f, T, pilots, overrides)
        allres += res
        for k, v in fid.items():
            allfid[k].append(v)
        for b in cands:
            if b not in backends:
                backends.append(b)

    print("| scene | p (s) | predicted winner | true winner | regret | regret with pilot cost | auto | auto's regret "
          "| winner from true pilot relmse (regret) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in allres:
        print(f"| {r['scene']} | {r['p']:g} | {r['pred']} | {r['true']} | {fmt(r['regret'])} | "
              f"{fmt(r['regret_cost'])} | {r['auto']} | {fmt(r['auto_regret'])} | "
              f"{r['pred_true']} ({fmt(r['regret_true'])}) |")
    print()
    print("Estimated over true relmse, geometric mean over runs (min to max):")
    cols = pilots + ["T"]
    print("| backend | " + " | ".join(f"{c:g} s" if c != "T" else "T" for c in cols) + " |")
    print("|---|" + "---|" * len(cols))
    for b in backends:
        cells = []
        for c in cols:
            v = [x for x in allfid[(b, c)] if math.isfinite(x)]
            cells.append(f"{fmt(geomean(v), 2)} ({fmt(min(v), 2)}-{fmt(max(v), 2)})" if v else "-")
        print(f"| {b} | " + " | ".join(cells) + " |")
    print()
    print("Predicted relmse at T (e_p s / T) over the true final relmse, geometric mean over runs (min to max):")
    print("| backend | " + " | ".join(f"p = {p:g} s" for p in pilots) + " |")
    print("|---|" + "---|" * len(pilots))
    for b in backends:
        cells = []
        for p in pilots:
            v = [x for x in allfid[(b, ("pred", p))] if math.isfinite(x)]
            cells.append(f"{fmt(geomean(v), 2)} ({fmt(min(v), 2)}-{fmt(max(v), 2)})" if v else "-")
        print(f"| {b} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
