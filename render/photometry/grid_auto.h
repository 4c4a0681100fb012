#pragma once
// A grid's `--method auto` as a measurement: short pilots of every method that can carry the
// scene's light to the points (path, vpl, bdpt, mir, mlt, cmlt; bdpt, mlt and cmlt where a lamp
// reaches a point only through glass), each one's error per unit of time from its own error bars,
// in rounds of doubling length with the methods far behind left out (successive halving); the
// grid then runs with the method that measured best. The pilots' work is not reused: a grid's
// methods keep their samples in different forms (points, replicas), so their results are not
// combined; the pilots cost their time, which the rounds keep to a share of the budget.

#include "render/photometry/grid_calculation.h"

#include <optional>
#include <string>

namespace lucerna {

struct GridAutoChoice {
    GridMethod method = GridMethod::Path;
    // A pilot that reached the grid's error target: the grid's result (a grid that one method
    // finishes within a pilot costs no more than that pilot).
    std::optional<GridResult> finished;
    // "pilots: path 1, bdpt 0.31, ... (efficiency, best 1), 1.2 s": what was measured.
    std::string measured;
    double seconds = 0;  // the pilots' time
};

// Runs the pilots on `points` (computeGridIlluminance with each method). `litThroughGlass`: a
// lamp reaches some point only through glass. The pilots' first round is a fiftieth of the time
// limit (0.2 s where there is none, at least 0.1 s), each next round twice the last; a method
// stays while its efficiency is at least a quarter of the best's, and the survivors run best
// first; at most four rounds. A pilot runs to the grid's own error target, and the first that
// reaches it ends the choice with its result. Cancelled: path.
GridAutoChoice chooseGridMethod(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, bool litThroughGlass, TaskContext& ctx);

}  // namespace lucerna
