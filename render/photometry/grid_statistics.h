#pragma once
// The statistics the grid calculations share (grid_calculation.h): per-point means of
// independent estimates, their 95% error bars, and the bookkeeping after each round.

#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"

#include <span>
#include <vector>

namespace lucerna {

// The 0.975 quantile of Student's t with `dof` degrees of freedom (1.96 in the limit): the
// half-width of a 95% interval from the spread of a few independent estimates.
double studentT975(int dof);

// Running sums of a point's independent estimates (pass means or replica means).
struct BatchMeans {
    double sum = 0, sumSquares = 0;
    int count = 0;

    void add(double x) {
        sum += x;
        sumSquares += x * x;
        ++count;
    }
    double mean() const { return count > 0 ? sum / count : 0.0; }
    // Half-width of the 95% interval of the mean; infinite below two estimates.
    double halfWidth95() const;
};

// A result for `points` points before any estimate: zero lux, infinite error bars, the points
// inside geometry marked (left out of finishRound's test).
GridResult emptyGridResult(size_t points, const std::vector<uint8_t>& insideGeometry = {});

// A sensor at each point (scene units, as float), all facing `normal` (normalised here).
std::vector<IrradianceSensor> sensorsAt(const std::vector<V3d>& points, const V3d& normal);

// Copies the means and error bars into `result` (its passes, samplesPerPoint and seconds set by
// the caller), decides convergence (only once `trusted`: every point's error bar within the
// target of its value, or of a thousandth of the grid's average for a point darker than that),
// reports progress and calls onPass.
// True when the calculation should stop (converged or out of time).
bool finishRound(const std::vector<BatchMeans>& points, bool trusted, const GridSettings& settings, TaskContext& ctx,
                 GridResult& result, const std::function<void(const GridResult&)>& onPass);

// The end of a round of a grid shared among processes (GridSettings::processes): each process
// gives the values of what it owns (0 elsewhere) in `sums` and its own figures in `maxima` (times
// so far, 1 when cancelled); every process gets back the sums over the processes (each value
// from its owner alone, so exactly that) and the maxima, so that all decide alike. Nothing
// changes when `processes` is nullptr.
void shareRound(ProcessGroup* processes, std::vector<double>& sums, std::vector<double>& maxima);

// The passes of a method that adds one independent estimate a point each pass (path, ir,
// preview), until finishRound says stop or the calculation is cancelled. `pass(p, values)`
// writes pass p's estimates of this process's points into `values` (one a point, 0 for the
// others'). Alone, a round is one pass. Shared among processes, rounds of passes, doubled while
// a round takes under a tenth of the time so far, are exchanged at once and then taken pass by
// pass as one process takes them, so that the values and the pass the calculation stops at are
// one process's (the last round may compute passes past it, a tenth of the time at most).
void runPointPasses(size_t points, int samplesPerPass, const GridSettings& settings, TaskContext& ctx,
                    const std::function<void(int pass, std::span<double> values)>& pass,
                    const std::function<void(const GridResult&)>& onPass, GridResult& result);

// Whether block `block` of the points, or replica `block`, is this process's.
inline bool ownsBlock(const ProcessGroup* processes, int block) { return block % sizeOf(processes) == rankOf(processes); }

// The bdpt, mir, mlt and cmlt methods (grid_calculation.h); `before` is the result before any
// estimate (emptyGridResult, with the checks of the points).
GridResult computeGridByBackend(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before);

// The preview method (grid_calculation.h).
GridResult computeGridByPreview(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before);

}  // namespace lucerna
