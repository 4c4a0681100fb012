#!/bin/bash
# A grid's `--method auto` against each method alone (issue 38): wall time (scene load, pilots and
# the run) to a 3% error bar on every point, capped at 30 s, one seed.
#   [METHODS="path ir auto"] [SCENE_DIR=DIR GRIDS="a.json 0.8,b.json 0.01"] bench/grid_auto.sh BUILD_DIR [SEED]
# Prints one line per scene and method: seconds, and "not reached" where the cap stopped it; for
# auto, the method that ran and its pilots' line. Entries: scene, work plane height (m), border
# (m); by default the seven bundled grids auto was tuned on, else GRIDS' entries in SCENE_DIR.
build=$1 seed=${2:-1}
root=$(dirname "$0")/..
dir=${SCENE_DIR:-$root/resources/scenes}
IFS=, read -r -a entries <<< "${GRIDS:-interior.json 0.8,office_floor.json 0.75,daylit_office.json 0.8,cornell-box.json 0.25 0.05,door.json 0.8,caustics.json 0.01,luminaire.json 0.8}"
for entry in "${entries[@]}"; do
    set -- $entry
    for m in ${METHODS:-path ir bdpt mir mlt cmlt auto}; do
        start=$(date +%s.%N)
        out=$("$build/app/lucerna" grid "$dir/$1" --work-plane "$2" ${3:+--border "$3"} --method $m --error 0.03 \
              --time 30 --seed "$seed" 2>&1)
        end=$(date +%s.%N)
        reached=$(echo "$out" | grep -q "target not reached" && echo " not reached" || echo "")
        chose=$(echo "$out" | grep -E "^auto: " || true)
        printf "%-20s %-5s %7.2f s%s %s\n" "$1" "$m" "$(echo "$end - $start" | bc)" "$reached" "$chose"
    done
done
