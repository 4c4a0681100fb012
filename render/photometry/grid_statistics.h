#pragma once
// The statistics the grid calculations share (grid_calculation.h): per-point means of
// independent estimates, their 95% error bars, and the bookkeeping after each round.

#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"

#include <chrono>
#include <cmath>
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

// Cylindrical illuminance (GridQuantity::Cylindrical) about `axis`: four vertical sensors per
// point, point-major (sensor 4 i + k faces azimuth offsetRadians + k pi / 2 about the axis), and
// the delta lights' exact part per point in lux (through glass panes with throughPanes). The mean
// of the four sensors' irradiance is an unbiased estimate of Ez when the offset is uniform in
// [0, pi / 2): the grid methods draw it afresh per pass or replica.
std::vector<IrradianceSensor> cylinderSensorsAt(const std::vector<V3d>& points, const V3d& axis, float offsetRadians);
std::vector<double> cylindricalDeltaLux(const RenderScene& scene, const std::vector<V3d>& points, const V3d& axis,
                                        bool throughPanes);
// The horizontal unit direction at `azimuth` (radians) about frame.n.
inline V3f azimuthDirection(const Frame& frame, float azimuth) {
    return frame.s * std::cos(azimuth) + frame.t * std::sin(azimuth);
}

// The largest error bar relative to its point's value, or to a thousandth of the grid's average
// for a point darker than that, over the points not inside geometry (GridResult's
// maxRelativeError).
double gridMaxRelativeError(const GridResult& r);

// Copies the means and error bars into `result` (its passes, samplesPerPoint and seconds set by
// the caller), decides convergence (only once `trusted`: every point's error bar within the
// target of its value, or of a thousandth of the grid's average for a point darker than that),
// reports progress and calls onPass.
// True when the calculation should stop (converged or out of time).
bool finishRound(const std::vector<BatchMeans>& points, bool trusted, const GridSettings& settings, TaskContext& ctx,
                 GridResult& result, const std::function<void(const GridResult&)>& onPass);

// How a method's values come out of its rounds of passes (runRounds).
enum class RoundValues {
    // One independent estimate a point each pass (path, ir, preview), taken pass by pass: alone,
    // a round is one pass; rounds of several matter only where processes exchange their values.
    EachPass,
    // The estimates so far, read once a round (bdpt, mir, mlt, cmlt: the replicas'): reading them
    // costs, so rounds grow alone too.
    EachRound,
};

// The rounds of passes of a grid calculation, until `take` says stop or the calculation is
// cancelled. `round(first, passes)` computes passes first to first + passes - 1 (fewer once
// cancelled) and returns this process's values of them, 0 for another process's. Shared among
// processes (GridSettings::processes), a round's values are summed over the processes (each
// value from its owner alone, so exactly that), and every process goes round until all agree to
// stop, a cancelled one too. A round that any process left unfinished ends the calculation
// untaken: a partial pass would bias the points it missed. `take(values, first, passes,
// seconds)` gets the round's values and the longest time any process has taken since `start`,
// and returns true to stop. A round is one pass at first; where rounds grow (RoundValues), it
// doubles, to 256 passes at most, while it takes under a tenth of the time so far: the target is
// checked often enough that the time to reach it is known within about 10%, and rarely enough
// that the checks and the exchanges cost nothing.
void runRounds(const GridSettings& settings, TaskContext& ctx, std::chrono::steady_clock::time_point start,
               RoundValues kind, const std::function<std::vector<double>(int first, int passes)>& round,
               const std::function<bool(const std::vector<double>& values, int first, int passes, double seconds)>& take);

// The passes of a method that adds one independent estimate a point each pass (path, ir,
// preview), until finishRound says stop or the calculation is cancelled: runRounds taking each
// pass. `pass(p, values)` writes pass p's estimates of this process's points into `values` (one
// a point, 0 for the others'). Shared among processes, the values and the pass the calculation
// stops at are those of one process (the last round may compute passes past it, a tenth of the
// time at most).
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
