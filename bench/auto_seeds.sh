#!/bin/bash
# Render auto against the best single method of R62 (seed 3) at equal time, over seeds (issue 38):
# one `lucerna bench` of auto and that method per scene and seed, at the reference's size.
#   bench/auto_seeds.sh BUILD_DIR FAM DAYLIT E_REF OUT [TIME] [SEEDS...]
# FAM: bench_make_scenes' folder (the closed spheres and their references); DAYLIT:
# make_daylit_family.py's folder; E_REF: room (e)'s reference (R58). Then:
#   python3 bench/auto_seeds_table.py OUT
# With SINGLES=EARLIER_OUT in the environment it runs auto only and takes the single methods' rows
# from an earlier run of the same TIME and seeds (to measure a change to auto against them).
build=$1 fam=$2 daylit=$3 eref=$4 out=$5 time=${6:-30}
shift $(($# < 6 ? $# : 6))
seeds=${*:-1 2 3 4}
root=$(cd "$(dirname "$0")/.." && pwd)
R=$root/resources/scenes
C=$root/../shared/scenes
scenes="cornell:$C/cornell-box.json:$C/cornell-box.ref.exr:::path
door:$R/door.json:$R/door.ref.exr:::cmlt
daylit_office:$R/daylit_office.json:$R/daylit_office.ref.exr:240:160:mir,path
office_floor:$R/office_floor.json:$R/office_floor.ref.exr:240:144:path
sphere-0.6:$fam/closed-sphere-0.6-32k.json:$fam/closed-sphere-0.6-32k.ref.exr:::mir
sphere-0.9:$fam/closed-sphere-0.9-32k.json:$fam/closed-sphere-0.9-32k.ref.exr:::mir
e_deep_plan:$daylit/e_deep_plan.json:$eref:160:120:path"
for seed in $seeds; do
    for line in $scenes; do
        IFS=: read name scene ref w h best <<<"$line"
        size=""; [ -n "$w" ] && size="--width $w --height $h"
        dir=$out/$name-s$seed; mkdir -p "$dir"
        backends="auto,$best"; [ -n "$SINGLES" ] && backends=auto
        "$build/app/lucerna" bench "$scene" --reference "$ref" --time "$time" --seed "$seed" $size \
            --backends "$backends" --out "$dir" > "$dir/bench.log" 2>&1
        if [ -n "$SINGLES" ]; then
            earlier=$SINGLES/$name-s$seed/bench.csv
            { head -1 "$earlier"; grep -v '^auto,' "$earlier" | tail -n +2; tail -n +2 "$dir/bench.csv"; } > "$dir/merged.csv"
            mv "$dir/merged.csv" "$dir/bench.csv"
        fi
        echo "$name seed $seed: $(grep -E '^(auto|path|bdpt|ir|mir|mlt|cmlt) ' "$dir/bench.log" | awk '{print $1, $5}' | tr '\n' ' ')"
    done
done
