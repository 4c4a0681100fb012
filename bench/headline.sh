#!/usr/bin/env bash
# A quick check of BENCHMARKS.md's figures (its "Quick check (`bench/headline.sh`)"): a small set
# of its benchmarks with short budgets (about 6 minutes on 2 cores), printed as a markdown table
# (figure, value, command).
#
# It is a quick check, not the authoritative figures: every figure here is ONE run with a budget
# shorter than BENCHMARKS.md's (which says for each of its figures how many runs and what budget
# it rests on), and the Metropolis ratios in particular scatter by a factor of 2 to 3 from run to
# run. Ratios of two backends are measured within one `lucerna bench` run (backends in turns).
#
# usage: bench/headline.sh [BUILD_DIR]
#   BUILD_DIR  a Release build holding app/lucerna, bench/bench_rays and bench/bench_preview
#              (default: build, relative to the current folder)
#   HEADLINE_OUT=DIR keeps the raw outputs (logs, bench CSVs, images) there; default: a new
#              folder under /tmp, named at the end.
# Scenes are read from the repository (resources/scenes/) and the Cornell box and its reference
# from ../shared/scenes/ beside it. Needs bash, awk and python3 (stdlib only).

set -u
BUILD=${1:-build}
if ! BUILD_ABS=$(cd "$BUILD" 2>/dev/null && pwd); then
    echo "headline.sh: no build folder '$BUILD'" >&2
    exit 2
fi
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$ROOT" || exit 2
LUCERNA=$BUILD_ABS/app/lucerna
BENCH_RAYS=$BUILD_ABS/bench/bench_rays
BENCH_PREVIEW=$BUILD_ABS/bench/bench_preview
for exe in "$LUCERNA" "$BENCH_RAYS" "$BENCH_PREVIEW"; do
    [ -x "$exe" ] || { echo "headline.sh: $exe is missing (a Release build of the whole tree is needed)" >&2; exit 2; }
done
# How the binaries are written in the printed commands: relative to the repository if inside it.
B=${BUILD_ABS#"$ROOT"/}
CB=../shared/scenes/cornell-box.json
CB_REF=../shared/scenes/cornell-box.ref.exr
DOOR=resources/scenes/door.json
DOOR_REF=resources/scenes/door.ref.exr
CAUSTICS=resources/scenes/caustics.json
INTERIOR=resources/scenes/interior.json
for f in "$CB" "$CB_REF" "$DOOR" "$DOOR_REF" "$CAUSTICS" "$INTERIOR"; do
    [ -f "$f" ] || { echo "headline.sh: $ROOT/$f is missing" >&2; exit 2; }
done
OUT=${HEADLINE_OUT:-$(mktemp -d /tmp/headline.XXXXXX)}
mkdir -p "$OUT" || exit 2
OUT=$(cd "$OUT" && pwd)

START=$(date +%s)
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
ROWS=()
row() { ROWS+=("| $1 | $2 | \`$3\` |"); }
note() { echo "[$(($(date +%s) - START)) s] $*" >&2; }

# run NAME CMD...: stdout and stderr to $OUT/NAME.log; the step's seconds in $OUT/NAME.seconds.
run() {
    local name=$1 t0 rc
    shift
    note "$name: $*"
    t0=$(date +%s.%N)
    "$@" >"$OUT/$name.log" 2>&1
    rc=$?
    python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$t0" "$(date +%s.%N)" \
        >"$OUT/$name.seconds"
    [ $rc -eq 0 ] || note "$name failed (exit $rc), see $OUT/$name.log"
    return $rc
}

# Small readers of the outputs, in Python (stdlib): bench summaries and CSVs, time_to_error.py.
cat >"$OUT/read.py" <<'EOF'
import csv, math, os, sys
sys.path.insert(0, os.path.join(os.getcwd(), "bench"))
import time_to_error as tte

def summary(log, backend, field):
    # lucerna bench's closing lines: backend seconds spp rmse relmse est.relmse mean/ref Mrays/s
    cols = {"seconds": 1, "spp": 2, "rmse": 3, "relmse": 4, "est": 5, "mean": 6, "mrays": 7}
    for line in open(log):
        parts = line.split()
        if len(parts) == 8 and parts[0] == backend:
            return parts[cols[field]]
    return "n/a"

def time_to(path, backend, target):
    # When the curve comes down to the target for good (time_to_error.py's rule).
    c = tte.curve(path, backend)
    if c[-1][1] > target:
        return f"not reached in {c[-1][0]:.1f} s (relmse {c[-1][1]:.3g} at the end)"
    return f"{tte.time_to(c, target):.2f} s"

def estimated(src, dst):
    # The same CSV with relmse replaced by the film's half-buffer estimate (no reference needed).
    rows = list(csv.DictReader(open(src)))
    with open(dst, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=rows[0].keys())
        w.writeheader()
        for r in rows:
            try:
                e = float(r["estimated_relmse"])
            except ValueError:
                continue
            if math.isfinite(e) and e > 0:
                r["relmse"] = r["estimated_relmse"]
                w.writerow(r)

cmd, args = sys.argv[1], sys.argv[2:]
if cmd == "summary":
    print(summary(*args))
elif cmd == "time_to":
    print(time_to(args[0], args[1], float(args[2])))
elif cmd == "estimated":
    estimated(*args)
elif cmd == "ratio":
    # time_to_error.py's line: "relmse E: A ta s, B tb s, ratio R; Mrays/s ..."
    line = open(args[0]).read().strip().splitlines()[-1]
    try:
        head, rest = line.split(", ratio ")
        ratio = rest.split(";")[0]
        print(f"{ratio} ({head.replace('relmse ', 'to relmse ')})")
    except ValueError:
        print("n/a (" + line + ")")
EOF
read_() { python3 "$OUT/read.py" "$@" 2>>"$OUT/read.log" || echo "n/a"; }
fails() { echo "failed (see $OUT/$1.log)"; }

# ---------------------------------------------------------------------------------------------
# auto's choice for each scene (lucerna info: a probe of what the camera sees, no rendering)
for s in "$CB" "$INTERIOR" "$DOOR" "$CAUSTICS"; do
    name=auto-$(basename "$s" .json)
    if run "$name" "$LUCERNA" info "$s"; then
        row "auto's choice, $(basename "$s")" "$(sed -n 's/^auto backend: //p' "$OUT/$name.log" | cut -d: -f1)" \
            "$B/app/lucerna info $s"
    else
        row "auto's choice, $(basename "$s")" "$(fails "$name")" "$B/app/lucerna info $s"
    fi
done

# ---------------------------------------------------------------------------------------------
# The path tracer's rays per second against bare Embree on the same rays (BENCHMARKS.md's commands)
rays_row() {
    local name=$1 label=$2
    shift 2
    local cmd="$B/bench/bench_rays $*"
    if run "$name" "$BENCH_RAYS" "$@"; then
        local p e r
        p=$(sed -n 's/^path tracer: .*, \([0-9.]*\) Mrays\/s/\1/p' "$OUT/$name.log")
        e=$(sed -n 's/^bare embree: .*, \([0-9.]*\) Mrays\/s/\1/p' "$OUT/$name.log")
        r=$(sed -n 's/^ratio: //p' "$OUT/$name.log")
        row "$label: path tracer / bare Embree rays per second (target 0.8)" "$r ($p against $e Mrays/s)" "$cmd"
    else
        row "$label: path tracer / bare Embree rays per second" "$(fails "$name")" "$cmd"
    fi
}
rays_row rays-cornell "Cornell box" "$CB" --spp 16
rays_row rays-million "Cornell box + bumpy sphere (1 M triangles)" "$CB" --spp 32 --million

# ---------------------------------------------------------------------------------------------
# Progressive backends on the Cornell box and the door, 10 s each (the command of the 10 s rows of
# BENCHMARKS.md, "Progressive backends (issue 3)")
BACKENDS=path,bdpt,ir,mir,mlt,cmlt
bench_scene() {
    local name=$1 scene=$2 ref=$3 label=$4
    local cmd="$B/app/lucerna bench $scene --reference $ref --backends $BACKENDS --time 10 --seed 1 --out $OUT/$name"
    if ! run "$name" "$LUCERNA" bench "$scene" --reference "$ref" --backends "$BACKENDS" --time 10 --seed 1 \
            --out "$OUT/$name"; then
        row "$label, every backend 10 s" "$(fails "$name")" "$cmd"
        return 1
    fi
    local v="" b
    for b in ${BACKENDS//,/ }; do
        v+="$b $(read_ summary "$OUT/$name.log" "$b" relmse) / $(read_ summary "$OUT/$name.log" "$b" mrays); "
    done
    row "$label, relmse / Mrays/s after 10 s a backend (1 run)" "${v%; }" "$cmd"
}

ratio_row() {  # ratio_row LABEL CSV A B: how many times sooner B reaches A's final error
    local label=$1 csvfile=$2 a=$3 b=$4 name
    name=tte-$(basename "$(dirname "$csvfile")")-$a-$b
    if run "$name" python3 bench/time_to_error.py "$csvfile" "$a" "$b"; then
        row "$label" "$(read_ ratio "$OUT/$name.log")" "python3 bench/time_to_error.py $csvfile $a $b"
    else
        row "$label" "$(fails "$name")" "python3 bench/time_to_error.py $csvfile $a $b"
    fi
}

if bench_scene cornell "$CB" "$CB_REF" "Cornell box 256x256"; then
    row "Cornell box: path's time to relmse 1e-3 (passes only; target 3.75 s)" \
        "$(read_ time_to "$OUT/cornell/bench.csv" path 1e-3)" "(read off $OUT/cornell/bench.csv)"
    row "Cornell box: mir's mean / reference mean after 10 s (target within 0.5%, converged)" \
        "$(read_ summary "$OUT/cornell.log" mir mean)" "(the bench's summary line)"
    ratio_row "Cornell box, 10 s: cmlt against mlt, times sooner to equal error (1 run)" "$OUT/cornell/bench.csv" mlt cmlt
    ratio_row "Cornell box, 10 s: cmlt against path (auto picks path)" "$OUT/cornell/bench.csv" path cmlt
fi
if bench_scene door "$DOOR" "$DOOR_REF" "Door 256x192"; then
    ratio_row "Door, 10 s: cmlt against mlt, times sooner to equal error (1 run; target 1.5)" "$OUT/door/bench.csv" mlt cmlt
    ratio_row "Door, 10 s: cmlt against bdpt (auto picks cmlt)" "$OUT/door/bench.csv" bdpt cmlt
    m=$(read_ summary "$OUT/door.log" mir relmse)
    i=$(read_ summary "$OUT/door.log" ir relmse)
    p=$(read_ summary "$OUT/door.log" path relmse)
    row "Door, 10 s: mir's relmse / ir's and / path's (target at most 0.5 each, at equal time)" \
        "$(python3 -c "import sys; m, i, p = map(float, sys.argv[1:]); print(f'{m / i:.2f} and {m / p:.2f}')" "$m" "$i" "$p" 2>/dev/null || echo n/a)" \
        "(the bench's summary lines)"
fi

# ---------------------------------------------------------------------------------------------
# The caustic scene at 240x180: a 40 s bdpt reference (BENCHMARKS.md's: 300 s), then 10 s a backend.
# The reference's own noise pulls the ratios against it towards 1; the half-buffer row is free of it.
CREF=$OUT/caustics.ref.exr
cmd_ref="$B/app/lucerna render $CAUSTICS -o $CREF --backend bdpt --time 40 --width 240 --height 180 --seed 99"
if run caustics-ref "$LUCERNA" render "$CAUSTICS" -o "$CREF" --backend bdpt --time 40 --width 240 --height 180 --seed 99; then
    row "Caustic scene: the quick reference's own estimated relmse (bdpt, 40 s)" \
        "$(sed -n 's/.*estimated relmse \([^ ]*\)$/\1/p' "$OUT/caustics-ref.log")" "$cmd_ref"
    cmd="$B/app/lucerna bench $CAUSTICS --reference $CREF --width 240 --height 180 --backends mlt,cmlt,bdpt --time 10 --seed 1 --out $OUT/caustics"
    if run caustics "$LUCERNA" bench "$CAUSTICS" --reference "$CREF" --width 240 --height 180 --backends mlt,cmlt,bdpt \
            --time 10 --seed 1 --out "$OUT/caustics"; then
        v=""
        for b in mlt cmlt bdpt; do
            v+="$b $(read_ summary "$OUT/caustics.log" "$b" relmse) (est. $(read_ summary "$OUT/caustics.log" "$b" est)); "
        done
        row "Caustic scene 240x180, relmse after 10 s a backend (1 run)" "${v%; }" "$cmd"
        ratio_row "Caustic scene, 10 s: cmlt against mlt (1 run; target 1.5 in expected error)" "$OUT/caustics/bench.csv" mlt cmlt
        ratio_row "Caustic scene, 10 s: cmlt against bdpt (auto picks bdpt)" "$OUT/caustics/bench.csv" bdpt cmlt
        mkdir -p "$OUT/caustics-est"
        read_ estimated "$OUT/caustics/bench.csv" "$OUT/caustics-est/bench.csv" >/dev/null
        ratio_row "Caustic scene, 10 s: cmlt against mlt on the half-buffer estimates (no reference)" \
            "$OUT/caustics-est/bench.csv" mlt cmlt
    else
        row "Caustic scene 240x180, 10 s a backend" "$(fails caustics)" "$cmd"
    fi
else
    row "Caustic scene: quick reference" "$(fails caustics-ref)" "$cmd_ref"
fi

# ---------------------------------------------------------------------------------------------
# The interactive preview on this machine's OpenGL (llvmpipe without a GPU): 640x480, 256 VPLs only
cmd="$B/bench/bench_preview $ROOT/resources/scenes/cornell-box.json --quick --frames 3"
if (cd "$OUT" && run preview "$BENCH_PREVIEW" "$ROOT/resources/scenes/cornell-box.json" --quick --frames 3); then
    P=$OUT/preview.log
    row "Preview renderer" "$(sed -n 's/^renderer: //p' "$P")" "$cmd"
    # | 640x480 | 256 | 4x4 | G | split | shading | gather | direct | read-back | frame | fps | shading x | frame x | maps |
    row "Preview 640x480, 256 VPLs, 4x4, defaults: ms a frame (least of 3; target 50 ms)" \
        "$(awk -F'|' '/^## ms per frame/ {s = 1} /^## VPL shading pass/ {s = 0}
            s && $4 ~ /4x4/ {gsub(/ /, "", $11); print $11 " (shading " $7+0 ")"}' "$P")" "$cmd"
    row "Preview 640x480, 256 VPLs: interleaving speedup of the shading pass / frame, 4x4 and 8x6" \
        "$(awk -F'|' '/^## ms per frame/ {s = 1} /^## VPL shading pass/ {s = 0}
            s && ($4 ~ /4x4/ || $4 ~ /8x6/) {gsub(/ /, "", $4); gsub(/ /, "", $13); gsub(/ /, "", $14);
            out = out (out ? "; " : "") $4 " " $13 " / " $14} END {print out}' "$P")" "$cmd"
    row "Preview: G-buffer split ms, one pass / two passes, 640x480 4x4" \
        "$(awk -F'|' '/^## G-buffer split/ {s = 1} /^## VPL visibility/ {s = 0}
            s && $2 ~ /640x480/ && $3 ~ /4x4/ {print $4+0 " / " $5+0}' "$P")" "$cmd"
    row "Preview: VPL visibility off / on, frame ms, 640x480 256 VPLs 4x4" \
        "$(awk -F'|' '/^## VPL visibility/ {s = 1} /^## Accuracy/ {s = 0}
            s && $3 ~ /256/ {v[$5 ~ /on/] = $7+0} END {print v[0] " / " v[1]}' "$P")" "$cmd"
    if grep -q '^## Accuracy' "$P"; then
        row "Preview accuracy, Cornell box 256x256, visibility on, 64 frames: relmse, mean / reference mean, lost to the clamp" \
            "$(awk -F'|' '/^## Accuracy/ {s = 1} s && $2 ~ /on/ && $6+0 == 64 {
                printf "%s, %s / %s, %s", $7+0, $8+0, $9+0, $10}' "$P" | tr -s ' ')" "$cmd"
    else
        row "Preview accuracy" "not measured: $(grep -m1 'no reference' "$P")" "$cmd"
    fi
else
    row "Preview (EGL, OpenGL 4.5)" "failed: $(tail -n 1 "$OUT/preview.log")" "$cmd"
fi

# ---------------------------------------------------------------------------------------------
# Calculation grid: time to a 2% error bar on every point of the interior's work plane
for m in path ir bdpt; do
    cmd="$B/app/lucerna grid $INTERIOR --work-plane 0.8 --method $m --error 0.02 --time 60 --seed 1"
    if run "grid-$m" "$LUCERNA" grid "$INTERIOR" --work-plane 0.8 --method "$m" --error 0.02 --time 60 --seed 1; then
        row "Interior work plane, $m: time to a 2% error bar on every point; Eavg" \
            "$(sed -n "s/^error bar (95%) at most .* samples per point, \(.*\)$/\1/p" "$OUT/grid-$m.log"); $(sed -n 's/^Eavg \([0-9.]* lx\).*/\1/p' "$OUT/grid-$m.log")" \
            "$cmd"
    else
        row "Interior work plane, $m" "$(fails "grid-$m")" "$cmd"
    fi
done

# ---------------------------------------------------------------------------------------------
# Per-light layers: a plain render against one with a layer per light, equal time (5 s; BENCHMARKS.md's: 10 s)
base="$B/app/lucerna render $INTERIOR --backend path --time 5 --width 320 --height 240 --seed 1"
if run layers-none "$LUCERNA" render "$INTERIOR" -o "$OUT/none.exr" --backend path --time 5 --width 320 --height 240 --seed 1 &&
    run layers-lights "$LUCERNA" render "$INTERIOR" -o "$OUT/lights.exr" --backend path --time 5 --width 320 --height 240 \
        --seed 1 --layers lights; then
    est() { sed -n 's/.*, \([0-9.]*\) spp in .*, estimated relmse \([^ ]*\)$/\2 (\1 spp)/p' "$OUT/$1.log"; }
    row "Interior 320x240, path, 5 s: estimated relmse, plain / a layer per light" \
        "$(est layers-none) / $(est layers-lights)" "$base -o none.exr [--layers lights]"
else
    row "Interior, per-light layers" "failed (see $OUT/layers-*.log)" "$base -o none.exr [--layers lights]"
fi

# ---------------------------------------------------------------------------------------------
END=$(date +%s)
echo
echo "## Quick check (bench/headline.sh), $(date -u +%Y-%m-%d)"
echo
echo "Single runs with short budgets (10 s a backend; BENCHMARKS.md's figures rest on 20 to 60 s and"
echo "up to 22 runs; the caustic scene's reference is a 40 s bdpt render, not 300 s, and its noise"
echo "pulls the ratios against it towards 1): a quick check, not the authoritative figures. $(nproc) cores, load average"
echo "$LOAD_START at the start and $(cut -d' ' -f1-3 /proc/loadavg) at the end, niceness $(nice);"
echo "binaries from $B; $((END - START)) s in all. Raw outputs: $OUT."
echo
echo "| figure | value | command |"
echo "|---|---|---|"
printf '%s\n' "${ROWS[@]}"
