#pragma once
// Illuminance on the points of a calculation grid (core/calculation_grid.h), progressively: each
// pass adds independent estimates at every point, and the error bar of a point comes from the
// spread of its per-pass means (batch means: within a pass the VPL method shares one VPL set
// between points and samples, across passes everything is independent).
//
// The error bar is the 95% half-width, 1.96 standard errors of the mean. The calculation ends
// when every point's error bar is within the target fraction of its value (after a few passes,
// so that the spread itself is estimated), at the time limit, or when cancelled.

#include "core/task_system.h"
#include "render/photometry/irradiance_estimator.h"

#include <functional>
#include <string>
#include <vector>

namespace lucerna {

enum class GridMethod { Path, Vpl };

// "path" or "ir" (the backends whose estimators these are); nothing for another name.
std::optional<GridMethod> gridMethodFromName(const std::string& name);
const char* gridMethodName(GridMethod method);

struct GridSettings {
    GridMethod method = GridMethod::Path;
    // Estimates per point per pass; 0: the method's default, 16 for path and 1 for ir, whose
    // variance comes mostly from the VPL set, fresh each pass (measured on the interior scene:
    // 1 estimate on 16 light paths per pass reached 2% four times sooner than 4 on 64).
    int samplesPerPass = 0;
    int vplPathsPerPass = 16;      // Vpl: light paths of each pass's VPL set
    double targetRelativeError = 0.02;
    int minPasses = 8;             // before the spread of the pass means is trusted
    double timeLimitSeconds = 0;   // 0: no limit
    uint64_t seed = 1;
};

struct GridResult {
    std::vector<double> lux;         // mean illuminance per point
    std::vector<double> errorLux;    // 95% half-width per point (infinite before two passes)
    int passes = 0;
    long long samplesPerPoint = 0;
    double seconds = 0;
    double maxRelativeError = 0;     // max over points of errorLux / lux (0 / 0 counts as 0)
    bool converged = false;          // every point within the target
};

// Computes the illuminance (lux, 683 Y(E)) on `points` (scene units), measured on the side the
// unit `normal` faces. Progress in ctx is the fraction of the error target reached (or of the time
// limit); `onPass`, if given, sees the result after each pass (on the calling thread).
GridResult computeGridIlluminance(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                  const GridSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GridResult&)>& onPass = {});

}  // namespace lucerna
