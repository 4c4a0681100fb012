#pragma once
// Sampling an index in proportion to non-negative weights (a tabulated CDF, binary search).

#include <algorithm>
#include <vector>

namespace lucerna {

class DiscreteDistribution {
public:
    DiscreteDistribution() = default;
    explicit DiscreteDistribution(const std::vector<double>& weights) {
        cdf_.resize(weights.size() + 1, 0.0);
        for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
        total_ = cdf_.back();
    }

    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    double total() const { return total_; }
    bool empty() const { return total_ <= 0.0; }

    double pdf(size_t i) const { return (cdf_[i + 1] - cdf_[i]) / total_; }

    // Index for u in [0, 1); never one of zero weight. `uRemapped` receives u rescaled to [0, 1)
    // within the chosen cell, so that one random number can serve twice.
    size_t sample(float u, float* uRemapped = nullptr) const {
        const double target = double(u) * total_;
        size_t i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin());
        i = std::clamp<size_t>(i, 1, size()) - 1;
        while (cdf_[i + 1] - cdf_[i] <= 0.0 && i + 1 < size()) ++i;  // skip empty cells at the end of a run
        if (uRemapped) {
            const double w = cdf_[i + 1] - cdf_[i];
            *uRemapped = float(std::clamp((target - cdf_[i]) / w, 0.0, 0x1.fffffep-1));
        }
        return i;
    }

private:
    std::vector<double> cdf_;
    double total_ = 0.0;
};

}  // namespace lucerna
