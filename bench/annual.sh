#!/usr/bin/env bash
# Annual daylight (issue 39; BENCHMARKS.md, "Annual daylight"): a year on the bundled side-lit
# office and its weather file, from scratch; SPEC.md section 6's contract against `grid` on a
# sample of hours; scaling with points, sky subdivision and paths.
# usage: bench/annual.sh [OUTDIR]   (run on a quiet machine: the times are wall-clock)
set -euo pipefail
cd "$(dirname "$0")/.."
LUCERNA=${LUCERNA:-build/app/lucerna}
OUT=${1:-/tmp/annual_bench}
SCENE=resources/scenes/daylit_office.json
EPW=resources/weather/paris_synthetic.epw
AREA=(--task-area "Reference plane")
mkdir -p "$OUT"

echo "== a year, 204 points (spacing 0.3 m), default settings"
/usr/bin/time -f "wall %e s" "$LUCERNA" annual "$SCENE" --weather "$EPW" "${AREA[@]}" --spacing 0.3 \
    --csv "$OUT/points.csv" --hourly "$OUT/hourly.csv" 2>&1 | grep -v "^wrote"

echo "== the contract against grid on 51 hours (clear, overcast, low sun; Eh >= 1000 lx)"
python3 bench/annual_hours.py "$EPW" 17 > "$OUT/hours.txt"
python3 bench/annual_vs_grid.py "$LUCERNA" "$SCENE" "$EPW" "$OUT/contract" \
    --annual-args "--task-area 'Reference plane' --spacing 0.3" \
    --grid-args "--task-area 'Reference plane' --spacing 0.3 --error 0.01 --time 30 --seed 7" $(cat "$OUT/hours.txt")

echo "== scaling with points (default settings)"
for spacing in 0.6 0.3 0.13; do
    echo "spacing $spacing:"
    "$LUCERNA" annual "$SCENE" --weather "$EPW" "${AREA[@]}" --spacing $spacing 2>/dev/null | grep -E "^annual grid|^stated"
done

echo "== sky subdivision and paths (204 points)"
for mf in 1 2 4 8; do
    echo "MF:$mf:"
    "$LUCERNA" annual "$SCENE" --weather "$EPW" "${AREA[@]}" --spacing 0.3 --sky-subdivision $mf 2>/dev/null | grep "^stated"
done
for paths in 16384 32768 131072; do
    echo "paths $paths:"
    "$LUCERNA" annual "$SCENE" --weather "$EPW" "${AREA[@]}" --spacing 0.3 --paths $paths 2>/dev/null | grep "^stated"
done
