#include "render/engine/measured_auto/trial.h"

#include <algorithm>

namespace lucerna {

// Measured on the Cornell box with a glass block: path's relmse x seconds fell from 0.044 at
// 0.3 s to 0.028 at 4 s, mlt's rose from 0.025 to 0.056 by 30 s; on the two-mirror caustic scene
// a trial took bdpt to 26% of the time and it ended at 0.65 of cmlt's efficiency.
bool shortRunIsFair(std::string_view method) { return method == "path"; }

// Path's pilot understates it where its Sobol sequence gains: on the office floor its relmse x
// seconds fell from 0.031 at 2 passes to 0.016 at 100 while cmlt's stayed at 0.025, so its pilot
// showed 0.83 to 1 of cmlt's efficiency, cmlt kept the time, and auto ended 1.65 times path's
// relmse alone. Where the leader's error grows with its length (mlt on the Cornell box with a
// glass block), a later measure puts path first, and a trial brings it back.
bool takesTrial(const TrialQuestion& q) {
    if (!shortRunIsFair(q.method) || q.cost >= std::max(q.inImageCost, q.leadingCost)) return false;
    const bool close = q.gain > (1 / kTrialMargin) * q.leadingGain;
    if (!(q.closeTrials >= kCloseTrials ? leadsByMargin(q.gain, q.leadingGain) : close)) return false;
    return q.cost + q.costLeft >= q.inImageCost;
}

}  // namespace lucerna
