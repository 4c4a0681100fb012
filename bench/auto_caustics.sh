#!/bin/bash
# Render auto on the caustic family (issue 38) against bdpt, mlt and cmlt, the methods it may
# combine through glass and mirrors: one `lucerna bench` of the four in turns per scene and seed.
#   bench/auto_caustics.sh BUILD_DIR DIR OUT [TIME] [SEEDS...]
# DIR holds make_families.py's caustic-*.json; a scene without DIR/NAME.ref.exr first gets one
# (180 s of bdpt, seed 1000). Then: python3 bench/auto_seeds_table.py OUT
build=$1 dir=$2 out=$3 time=${4:-30}
shift $(($# < 4 ? $# : 4))
seeds=${*:-1 2 3 4}
for seed in $seeds; do
    for scene in "$dir"/caustic-*.json; do
        name=$(basename "$scene" .json)
        [ -f "$dir/$name.ref.exr" ] ||
            "$build/app/lucerna" render "$scene" -o "$dir/$name.ref.exr" --backend bdpt --time 180 --seed 1000 || exit 1
        run=$out/$name-s$seed
        mkdir -p "$run"
        "$build/app/lucerna" bench "$scene" --reference "$dir/$name.ref.exr" --time "$time" --seed "$seed" \
            --backends auto,bdpt,mlt,cmlt --out "$run" > "$run/bench.log" 2>&1
        echo "$name seed $seed: $(grep -E '^(auto|bdpt|mlt|cmlt) ' "$run/bench.log" | awk '{print $1, $5}' | tr '\n' ' ')"
    done
done
