#pragma once
// Independent estimates of one grid combined point by point (issue 38): grid auto's path and ir
// runs (its pilots, and the method a pilot took over from) each estimate every point pass by
// pass, unbiased, with an error bar from the spread of their pass means, so that nothing a run
// measured is lost when another method goes on.

#include "render/photometry/grid_calculation.h"

#include <span>

namespace lucerna {

// Fewer passes than this and a run's error bars are too rough to weigh it by (its variance's own
// error, sqrt(2 / passes), over a quarter): it is left out.
constexpr int kCombinedMinPasses = 32;

// The runs (results for the same points from independent passes; each one's method in its
// `method`) combined, parts[0] the reference (the running method's; its method's runs are always
// in). Per point:
// - the runs of one method are pooled by their passes (the pass means' mean and their pooled
//   spread): no weight there depends on a value;
// - the methods are weighed by the inverse of their pooled variance, which comes from hundreds of
//   pass means or more. A method that has met a rare contribution less often than its share
//   (a caustic reached by few paths) shows too low a value with too small a spread, and would
//   take the weight: a method whose value is more than 3 combined standard deviations from the
//   reference method's is left out at that point (a consistent method, 1 time in 370), and a
//   method's variance is taken as at least a quarter of its median ratio to the reference
//   method's times the reference's there (one within those 3 deviations, its spread still small);
// - the error bar is sqrt(sum(w_m^2 e_m^2)) / sum(w_m) from the methods' 95% bars e_m (Student's
//   quantile of their passes); a point a method has exact (bar 0: delta lights alone) takes it.
// Runs of under kCombinedMinPasses passes are left out. The result is parts[0] with those values,
// its maxRelativeError and convergence (against settings' target) recomputed, its passes and
// samples the sums of the runs in. Nothing in parts[0]: parts[0] as it is.
GridResult combineGridResults(std::span<const GridResult* const> parts, const GridSettings& settings);

}  // namespace lucerna
