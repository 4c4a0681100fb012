#!/bin/sh
# The light tree against power selection on the bundled scenes, each with the backend `auto`
# picks for it, over 4 seeds: the expected time to the same error (bench/time_to_error.py).
# The default light_sampler is the tree where it is not worse (issue 19: within 5%).
#   bench/light_sampler_default.sh BUILD_DIR REF_DIR OUT_DIR [SECONDS]
# REF_DIR holds SCENE-ref.exr at 160 x 120 for interior, luminaire and caustics (long renders:
# `lucerna render resources/scenes/S.json -o REF_DIR/S-ref.exr --width 160 --height 120
# --backend path --time 420`, bdpt for caustics); the Cornell box's is ../shared's, the door's
# resources/scenes/door.ref.exr.
set -e
build=$1 refs=$2 out=$3 t=${4:-10}
mkdir -p "$out"
run() {  # scene reference backend width height
    for seed in 1 2 3 4; do
        "$build/app/lucerna" bench "$1" --reference "$2" --time "$t" --seed $seed --width $4 --height $5 \
            --backends "$3:light_sampler=power,$3:light_sampler=tree" --out "$out/$(basename "$1" .json)-$seed" > /dev/null
    done
    echo "== $(basename "$1" .json) ($3)"
    python3 "$(dirname "$0")/time_to_error.py" "$out/$(basename "$1" .json)"-[1-4]/bench.csv \
        "$3:light_sampler=power" "$3:light_sampler=tree"
}
here=$(dirname "$0")/..
run "$here/../shared/scenes/cornell-box.json" "$here/../shared/scenes/cornell-box.ref.exr" path 256 256
run "$here/resources/scenes/door.json" "$here/resources/scenes/door.ref.exr" cmlt 256 192
run "$here/resources/scenes/caustics.json" "$refs/caustics-ref.exr" bdpt 160 120
run "$here/resources/scenes/interior.json" "$refs/interior-ref.exr" path 160 120
run "$here/resources/scenes/luminaire.json" "$refs/luminaire-ref.exr" path 160 120
