#!/usr/bin/env bash
# MPI (issue 23): scaling of a render on this machine (1 and 2 ranks of one thread each against
# one process of two threads), the cost of pooling a 4K film, and the figures the N-node model
# of BENCHMARKS.md ("MPI (issue 23)") takes. Usage: bench/mpi_scaling.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build}
out=${2:-/tmp/mpi_scaling}
lucerna="$build/app/lucerna"
scene=resources/scenes/cornell-box.json
mkdir -p "$out"
# --bind-to none: Open MPI binds each of up to 2 ranks to one core by default, which pins a
# rank's threads to that core (and, on a shared machine, to whatever else runs there).
mpirun=(mpirun --oversubscribe --allow-run-as-root --bind-to none --mca btl_vader_single_copy_mechanism none)
attr() { exrheader "$1" | sed -n "s/^lucerna:$2 (type string): \"\(.*\)\"/\1/p"; }
run() {  # label, output, command...
  local label=$1 exr=$2; shift 2
  local t0 t1
  t0=$(date +%s.%N)
  "$@" 2>/dev/null
  t1=$(date +%s.%N)
  printf '%-34s wall %6.2f s  render %6.2f s  reduction %s s  spp %s  passes %s  est. relmse %s\n' "$label" \
    "$(echo "$t1 - $t0" | bc)" "$(attr "$exr" seconds)" "$(attr "$exr" reduction_seconds)" "$(attr "$exr" spp)" \
    "$(attr "$exr" rank_passes)" "$(attr "$exr" estimated_relmse)"
}
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for backend in path mlt; do
  common=("$scene" --backend "$backend" --spp 96 --width 320 --height 240 --seed 1)
  run "$backend: 1 process, 2 threads" "$out/p2.exr" "$lucerna" render "${common[@]}" -o "$out/p2.exr" --threads 2
  run "$backend: mpirun 1 rank, 1 thread" "$out/r1.exr" "${mpirun[@]}" -n 1 "$lucerna" render "${common[@]}" -o "$out/r1.exr" --threads 1
  run "$backend: mpirun 2 ranks, 1 thread each" "$out/r2.exr" "${mpirun[@]}" -n 2 "$lucerna" render "${common[@]}" -o "$out/r2.exr" --threads 1
done
# A 4K film (3840 x 2160: 398 MB of doubles a rank) pooled from 2 ranks; rank 0's peak memory.
/usr/bin/time -f "4K, 2 ranks: max resident %M KB (the larger rank)" \
  "${mpirun[@]}" -n 2 "$lucerna" render "$scene" --backend path --spp 4 --width 3840 --height 2160 --threads 1 \
  --seed 1 -o "$out/4k.exr" 2>&1 | grep -v "^wrote" || true
run "path 4K: (above, read back)" "$out/4k.exr" true
# The pooling's copies alone (one rank: no transfer between processes) at 4K.
run "path 4K: mpirun 1 rank, 2 threads" "$out/4k_1.exr" "${mpirun[@]}" -n 1 "$lucerna" render "$scene" --backend path \
  --spp 1 --width 3840 --height 2160 --threads 2 --seed 1 -o "$out/4k_1.exr"
# The same 4K render in one process: the pooled film (two blocks of the reduce-scatter) must
# give the same pixels.
"$lucerna" render "$scene" --backend path --spp 4 --width 3840 --height 2160 --threads 2 --seed 1 -o "$out/4k_one.exr" 2>/dev/null
echo "4K, 2 ranks against 1 process: $("$lucerna" compare "$out/4k.exr" "$out/4k_one.exr" | tr '\n' ' ')"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
