#!/bin/bash
# The office floor scenes' references and benchmarks (bench/office_floor.md has the figures).
#   bash bench/office_floor.sh refs [SECONDS]      converged references at 240 x 144: path with the
#                                                  light tree (stored as resources/scenes/*.ref.exr)
#                                                  and bdpt (power light selection) as the cross-check,
#                                                  SECONDS each (1500 unless given)
#   bash bench/office_floor.sh cycles [SPP]        Blender Cycles on the point-light variant, converged
#                                                  (SPP, 16384 unless given; $OUT/cycles-ref.exr), compared
#                                                  with our reference and with the bdpt cross-check
#   bash bench/office_floor.sh equal_time [T ...]  Cycles at the samples it renders in T seconds of wall
#                                                  time (10 and 60 unless given) against path (tree, power)
#                                                  and bdpt at the same wall time, all against the reference
#   bash bench/office_floor.sh bench [SECONDS]     lucerna bench of path (tree, power), bdpt and cmlt on both
#                                                  scenes against their references, SECONDS each (60)
#   bash bench/office_floor.sh grid                the work-plane grid at 0.75 m of both scenes
# Run from the repository root after a build (build/app/lucerna); cycles and equal_time need
# `apt-get install blender python3-numpy` and ../shared/tools/cycles_ref.sh. Everything runs under
# `nice`; results go to $OUT (/tmp/office_floor unless set).
set -euo pipefail
lucerna=${LUCERNA:-build/app/lucerna}
scenes=resources/scenes
out=${OUT:-/tmp/office_floor}
size=(--width 240 --height 144)
cycles_ref=${CYCLES_REF:-../shared/tools/cycles_ref.sh}
mkdir -p "$out"

compare() {  # compare TEST REF: relmse and both means on one line
    "$lucerna" compare "$1" "$2" | awk -F': ' '{v[$1]=$2} END {printf "relmse %s mean_test %s mean_ref %s\n", v["relmse"], v["mean_test"], v["mean_ref"]}'
}

# Cycles' own wall time for the render itself, from cycles_render.py's log line.
cycles() {  # cycles OUT SPP
    local log
    log=$(nice bash "$cycles_ref" "$scenes/office_floor_points.json" "$1" "$2" --width 240 --height 144 --seed 1)
    echo "$log" | grep -o 'render wall time: [0-9.]* s' | awk '{print $4}'
}

case "${1:-}" in
refs)
    t=${2:-1500}
    for s in office_floor office_floor_points; do
        nice "$lucerna" render "$scenes/$s.json" -o "$out/$s.path.exr" --backend path --option light_sampler=tree \
            --time "$t" --seed 1 "${size[@]}"
        nice "$lucerna" render "$scenes/$s.json" -o "$out/$s.bdpt.exr" --backend bdpt --time "$t" --seed 2 "${size[@]}"
        echo "$s: bdpt against path: $(compare "$out/$s.bdpt.exr" "$out/$s.path.exr")"
    done
    echo "copy $out/*.path.exr to $scenes/*.ref.exr once they agree"
    ;;
cycles)
    spp=${2:-16384}
    secs=$(cycles "$out/cycles-ref.exr" "$spp")
    echo "cycles $spp spp in $secs s against our reference: $(compare "$out/cycles-ref.exr" "$scenes/office_floor_points.ref.exr")"
    [ -f "$out/office_floor_points.bdpt.exr" ] &&
        echo "our bdpt against cycles: $(compare "$out/office_floor_points.bdpt.exr" "$out/cycles-ref.exr")"
    ;;
equal_time)
    shift
    times=("$@")
    [ ${#times[@]} -gt 0 ] || times=(10 60)
    ref=$scenes/office_floor_points.ref.exr
    # Cycles' samples per second, from a short calibration render.
    cal=$(cycles "$out/cycles-cal.exr" 64)
    for t in "${times[@]}"; do
        spp=$(awk -v t="$t" -v c="$cal" 'BEGIN {n = int(64 * t / c); print (n < 1 ? 1 : n)}')
        secs=$(cycles "$out/cycles-$t.exr" "$spp")
        echo "t=$t cycles $spp spp in $secs s: $(compare "$out/cycles-$t.exr" "$ref")"
        [ -f "$out/cycles-ref.exr" ] && echo "t=$t cycles against converged cycles: $(compare "$out/cycles-$t.exr" "$out/cycles-ref.exr")"
        for b in "path:light_sampler=tree" "path:light_sampler=power" "bdpt"; do
            name=${b//[:=]/_}
            opt=()
            [[ $b == *:* ]] && opt=(--option "${b#*:}")
            nice "$lucerna" render "$scenes/office_floor_points.json" -o "$out/$name-$t.exr" --backend "${b%%:*}" \
                "${opt[@]}" --time "$secs" --seed 3 "${size[@]}" 2>&1 | tail -1
            echo "t=$t $b in $secs s: $(compare "$out/$name-$t.exr" "$ref")"
        done
    done
    ;;
bench)
    # Every backend auto might choose, and both light selections of path, against the reference.
    t=${2:-60}
    for s in office_floor office_floor_points; do
        nice "$lucerna" bench "$scenes/$s.json" --reference "$scenes/$s.ref.exr" --time "$t" --seed 1 \
            --backends path:light_sampler=tree,path:light_sampler=power,bdpt,cmlt --out "$out/bench-$s" | tail -6
    done
    ;;
grid)
    for s in office_floor office_floor_points; do
        nice "$lucerna" grid "$scenes/$s.json" --work-plane 0.75 --error 0.02 --time 1200 --seed 1 --csv "$out/$s.grid.csv" |
            head -3
    done
    ;;
*)
    sed -n '2,18p' "$0"
    exit 2
    ;;
esac
