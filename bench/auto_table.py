#!/usr/bin/env python3
"""auto's relmse against the single methods' at equal time (issue 38).

usage: auto_table.py --time T AUTO_DIR SINGLES_DIR [SINGLES_DIR ...]

AUTO_DIR/NAME-sS/ holds either one `lucerna bench` whose entries include `auto` beside the single
methods (bench.csv; the backends ran in turns in that one run: the firm comparison), or one
`lucerna render ... --time T --seed S` of auto: compare.txt (the output of `lucerna compare
auto.exr REF`) and render.log (its stderr, whose last line is auto's summary).
SINGLES_DIR/NAME-sS/bench.csv is one `lucerna bench` of the single methods (and `auto-rule`, the
backend the rule auto was picks, or its name in auto.txt beside it) on the same scene and seed, run for at least T seconds; each
method's relmse is its last row at or before T (1.02 T + 0.5 s). Prints a Markdown table: per
scene and seed, auto's relmse, the best single method's, auto over the best, over the worst, the
rule's pick over auto, and auto's share of the time; then per scene the same over the seeds'
means (the expected error). Standard library only.
"""
import csv
import os
import re
import sys


def main(argv):
    if len(argv) < 4 or argv[0] != "--time":
        sys.exit(__doc__)
    t, auto_dir, singles_dirs = float(argv[1]), argv[2], argv[3:]
    rows, per_scene = [], {}
    for d in sorted(os.listdir(auto_dir)):
        m = re.match(r"(.*)-s(\d+)$", d)
        if not m:
            continue
        cmp_path = os.path.join(auto_dir, d, "compare.txt")
        own = os.path.join(auto_dir, d, "bench.csv")
        bench = own if os.path.exists(own) else next(
            (os.path.join(s, d, "bench.csv") for s in singles_dirs if os.path.exists(os.path.join(s, d, "bench.csv"))), None)
        if not bench:
            continue
        single = {}
        for r in csv.DictReader(open(bench)):
            if float(r["seconds"]) <= 1.02 * t + 0.5:
                single[r["backend"]] = float(r["relmse"])
        if "auto" in single:
            auto = single.pop("auto")
        elif os.path.exists(cmp_path):
            relmse = re.search(r"^relmse: (\S+)", open(cmp_path).read(), re.M)
            if not relmse:
                continue
            auto = float(relmse.group(1))
        else:
            continue
        rule = single.pop("auto-rule", None)
        # Or the rule's pick named in auto.txt beside the CSV (`lucerna info`'s last line before
        # auto measured: "auto backend: NAME: reason").
        info = os.path.join(os.path.dirname(bench), "auto.txt")
        if rule is None and os.path.exists(info):
            picked = re.match(r"auto backend: (\w+):", open(info).read())
            if picked and picked.group(1) in single:
                rule = single[picked.group(1)]
        log_path = os.path.join(auto_dir, d, "render.log")
        log = open(log_path).read().strip().splitlines() if os.path.exists(log_path) else []
        time = re.search(r"time: (.*?); image", log[-1] if log else "")
        rows.append((m.group(1), m.group(2), auto, single, rule, time.group(1) if time else ""))
        s = per_scene.setdefault(m.group(1), {"auto": [], "single": {}, "rule": []})
        s["auto"].append(auto)
        for k, v in single.items():
            s["single"].setdefault(k, []).append(v)
        if rule is not None:
            s["rule"].append(rule)
    print("| scene | seed | auto | best single | auto / best | auto / worst | rule's pick / auto | auto's time |")
    print("|---|---|---|---|---|---|---|---|")
    for name, seed, auto, single, rule, time in rows:
        best, worst = min(single, key=single.get), max(single, key=single.get)
        r = f"{rule / auto:.1f}" if rule is not None else "-"
        print(f"| {name} | {seed} | {auto:.3g} | {best} {single[best]:.3g} | {auto / single[best]:.2f} | "
              f"{auto / single[worst]:.3f} | {r} | {time} |")
    print()
    print("| scene | seeds | mean auto | best single (mean) | auto / best | auto / worst | rule's pick / auto |")
    print("|---|---|---|---|---|---|---|")
    mean = lambda v: sum(v) / len(v)
    for name, s in sorted(per_scene.items()):
        n = len(s["auto"])
        means = {k: mean(v) for k, v in s["single"].items() if len(v) == n}
        best, worst = min(means, key=means.get), max(means, key=means.get)
        a = mean(s["auto"])
        r = f"{mean(s['rule']) / a:.1f}" if len(s["rule"]) == n else "-"
        print(f"| {name} | {n} | {a:.3g} | {best} {means[best]:.3g} | {a / means[best]:.2f} | {a / means[worst]:.3f} | {r} |")


if __name__ == "__main__":
    main(sys.argv[1:])
