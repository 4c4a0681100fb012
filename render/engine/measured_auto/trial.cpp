#include "render/engine/measured_auto/trial.h"

#include <algorithm>

namespace lucerna {

// Measured on the Cornell box with a glass block: path's relmse x seconds fell from 0.044 at
// 0.3 s to 0.028 at 4 s, mlt's rose from 0.025 to 0.056 by 30 s; on the two-mirror caustic scene
// a trial took bdpt to 26% of the time and it ended at 0.65 of cmlt's efficiency.
// mir: on the daylit office (30 s) ir carried seeds 5, 6 and 8 after mir's short run, whose
// efficiency ended at 0.74 to 1 of ir's; with trials mir carried seeds 5 and 8 (relmse 0.70 and
// 0.66 of ir carrying) and a third of seed 6 (0.98), and measured ahead of ir on all three at the
// end (ir 0.62 to 0.84 of mir's efficiency); over 8 seeds 0.92 (BENCHMARKS.md, R97).
// path with caustics: on the caustic glass cube its trials took 4 to 24% of the time for at most
// 0.02 of the image (R101); on the small-light caustic (seed 10) 29% of the time and 0.35 of the
// image, which came out 7 times cmlt's error alone (R105).
bool shortRunIsFair(std::string_view method, bool caustics) {
    return (method == "path" && !caustics) || method == "mir";
}

// Path's pilot understates it where its Sobol sequence gains: on the office floor its relmse x
// seconds fell from 0.031 at 2 passes to 0.016 at 100 while cmlt's stayed at 0.025, so its pilot
// showed 0.83 to 1 of cmlt's efficiency, cmlt kept the time, and auto ended 1.65 times path's
// relmse alone. Where the leader's error grows with its length, a later measure puts path first,
// and a trial brings it back (mlt, when it was a candidate, on the Cornell box with a glass
// block; there, with glass, path now takes none, and carried 3 of 4 seeds by the measures alone,
// 1.05 of path's error alone, R105).
bool takesTrial(const TrialQuestion& q) {
    if (!shortRunIsFair(q.method, q.caustics) || q.cost >= std::max(q.inImageCost, q.leadingCost)) return false;
    const double margin = q.closeTrials == 0 ? kFirstTrialMargin : kTrialMargin;
    const bool close = q.gain > (1 / margin) * q.leadingGain;
    if (!(q.closeTrials >= kCloseTrials ? leadsByMargin(q.gain, q.leadingGain) : close)) return false;
    return q.cost + q.costLeft >= q.inImageCost;
}

}  // namespace lucerna
