#!/bin/sh
# Issue 22's figures on the bundled daylit office (BENCHMARKS.md, "Daylight (issue 22)"):
#   bench/daylight.sh BUILD_DIR OUT_DIR ref [SECONDS]   the reference at 240 x 160: mir and path for
#                                                        SECONDS each (default 480), their relmse
#                                                        against each other, and their combination
#   bench/daylight.sh BUILD_DIR OUT_DIR bench SECONDS SEED   every backend for SECONDS against it,
#                                                        then each one's time to relmse 1e-2
set -e
build=$1 out=$2 mode=$3
shift 3
scene=$(dirname "$0")/../resources/scenes/daylit_office.json
mkdir -p "$out"
case $mode in
ref)
    t=${1:-480}
    "$build/app/lucerna" render "$scene" -o "$out/mir.exr" --backend mir --time "$t" --width 240 --height 160 --seed 1000
    "$build/app/lucerna" render "$scene" -o "$out/path.exr" --backend path --time "$t" --width 240 --height 160 --seed 1001
    "$build/bench/bench_combine_references" "$out/daylit_office.ref.exr" "$out/mir.exr" "$out/path.exr" ;;
bench)
    t=$1 seed=${2:-1}
    "$build/app/lucerna" bench "$scene" --reference "$out/daylit_office.ref.exr" --time "$t" --seed "$seed" \
        --width 240 --height 160 --backends path,bdpt,ir,mir,mlt,cmlt --out "$out/bench-$seed" > /dev/null
    python3 - "$out/bench-$seed/bench.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
target = 1e-2
for name in dict.fromkeys(r["backend"] for r in rows):
    c = [(float(r["seconds"]), float(r["relmse"])) for r in rows if r["backend"] == name]
    # The last sample above the target; log-log interpolation to the next one.
    above = [i for i, (_, e) in enumerate(c) if e > target]
    if not above:
        print(f"{name:5s} below {target} from its first sample ({c[0][0]:.1f} s)")
    elif above[-1] + 1 >= len(c):
        print(f"{name:5s} not reached in {c[-1][0]:.0f} s (relmse {c[-1][1]:.3g})")
    else:
        (t0, e0), (t1, e1) = c[above[-1]], c[above[-1] + 1]
        f = math.log(target / e0) / math.log(e1 / e0)
        print(f"{name:5s} {math.exp(math.log(t0) + f * math.log(t1 / t0)):7.1f} s to relmse {target}")
PY
    ;;
*) echo "usage: $0 BUILD_DIR OUT_DIR ref [SECONDS] | bench SECONDS [SEED]" >&2; exit 2 ;;
esac
