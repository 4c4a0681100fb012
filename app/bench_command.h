#pragma once
// `lucerna bench`: speed against error (DESIGN.md, "Speed against error"). Runs each backend in
// turn for a wall-clock budget, measures rmse and relmse against a reference at log-spaced times,
// and writes bench.csv and bench.svg (error against time, log-log, one curve per backend).

#include <string>
#include <vector>

namespace lucerna::cli {

// bench SCENE.json --reference REF.exr --backends LIST --time SECONDS [--out DIR]
//       [--width W --height H] [--seed N] [--threads N] [--option NAME=VALUE] [--per-decade N]
//       [--start SECONDS]
// LIST is comma-separated; an entry may carry options of its own after colons
// ("mir:tries=1:large_step=0.5"), which override --option for that entry. Returns the exit status
// of SPEC.md section 2 (2 with one line for bad usage or input).
int bench(const std::vector<std::string>& args);

}  // namespace lucerna::cli
