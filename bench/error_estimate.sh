#!/usr/bin/env bash
# The estimated relmse against the true one on scenes with and without fireflies (BENCHMARKS.md,
# "The estimated error (issue 25)"). Usage: bench/error_estimate.sh BUILD_DIR WORK_DIR
# WORK_DIR gets the generated office and the references this script renders (about 45 minutes
# of the machine for the two long references).
set -euo pipefail
build=$1 work=$2
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
"$build/bench/bench_make_scenes" "$work/scenes" > /dev/null
[ -f "$work/office-ref.exr" ] || "$build/app/lucerna" render "$work/scenes/office-135.json" -o "$work/office-ref.exr" \
    --backend path --width 160 --height 120 --time 1500 --seed 999
[ -f "$work/caustics-ref.exr" ] || "$build/app/lucerna" render "$here/resources/scenes/caustics.json" -o "$work/caustics-ref.exr" \
    --backend bdpt --width 160 --height 120 --time 1200 --seed 999
run() { echo "== $1 $3"; "$build/bench/bench_error_estimate" "$@"; }
run "$here/../shared/scenes/cornell-box.json" "$here/../shared/scenes/cornell-box.ref.exr" path 3 64
for b in path bdpt ir cmlt; do
    run "$here/resources/scenes/door.json" "$here/resources/scenes/door.ref.exr" $b 2 64
done
run "$work/scenes/office-135.json" "$work/office-ref.exr" path 3 128 160 120
run "$here/resources/scenes/caustics.json" "$work/caustics-ref.exr" path 3 128 160 120
run "$here/resources/scenes/caustics.json" "$work/caustics-ref.exr" bdpt 2 64 160 120
