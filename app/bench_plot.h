#pragma once
// The plot of `lucerna bench`: error against time, log-log, one curve per backend, as SVG text
// (simple enough to write by hand, and readable in any browser and in the repository viewer).

#include <string>
#include <vector>

namespace lucerna::cli {

struct BenchSample {
    std::string backend;  // the label of the run ("mir", "mir:tries=1")
    double seconds = 0;
    double spp = 0;
    double rmse = 0;
    double relmse = 0;
    double estimatedRelmse = 0;  // NaN before the film has two halves
    double meanTest = 0, meanRef = 0;  // SPEC.md's means: what bias a converged run keeps
    double rays = 0;  // rays traced since the passes began, read as the frame was measured
};

// Two panels side by side, relmse and rmse against seconds, with decade grid lines, axis labels
// and a legend; `title` goes on top. Samples with a non-positive or non-finite value are left out
// of their panel. Curves keep the order in which backends first appear in `samples`.
std::string errorPlotSvg(const std::vector<BenchSample>& samples, const std::string& title);

}  // namespace lucerna::cli
