#!/bin/sh
# Issue 21's scene families (bench/make_families.py, bench_make_scenes): references, and benches
# of every backend in turns over several seeds.
#   bench/families.sh BUILD_DIR DIR refs [SECONDS]      references: bdpt for SECONDS (default 240)
#                                                        on every door and caustic scene, seed 1000
#   bench/families.sh BUILD_DIR DIR bench SCENE BACKENDS SECONDS SEEDS...
#                                                        one lucerna bench per seed into DIR/b-SCENE-SEED,
#                                                        then time_to_error.py on the first two backends
# DIR holds the scenes (make_families.py DIR; bench_make_scenes DIR for the closed spheres).
set -e
build=$1 dir=$2 mode=$3
shift 3
case $mode in
refs)
    t=${1:-240}
    for s in "$dir"/door-*.json "$dir"/caustic-*.json; do
        n=$(basename "$s" .json)
        "$build/app/lucerna" render "$s" -o "$dir/$n.ref.exr" --backend bdpt --time "$t" --seed 1000
    done ;;
bench)
    scene=$1 backends=$2 t=$3
    shift 3
    csvs=""
    for seed in "$@"; do
        "$build/app/lucerna" bench "$dir/$scene.json" --reference "$dir/$scene.ref.exr" --time "$t" --seed "$seed" \
            --backends "$backends" --out "$dir/b-$scene-$seed" > /dev/null
        csvs="$csvs $dir/b-$scene-$seed/bench.csv"
    done
    a=$(echo "$backends" | cut -d, -f1) b=$(echo "$backends" | cut -d, -f2)
    python3 "$(dirname "$0")/time_to_error.py" $csvs "$a" "$b" ;;
*) echo "usage: see the head of $0" >&2; exit 2 ;;
esac
