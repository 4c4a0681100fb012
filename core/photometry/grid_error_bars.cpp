#include "core/photometry/grid_error_bars.h"

namespace lucerna {

GridErrorBars gridErrorBars(const GridStatistics& s, const std::vector<double>& lux,
                            const std::vector<double>& errorLux, const std::vector<uint8_t>& excluded,
                            const std::vector<double>& weights) {
    GridErrorBars e;
    if (s.counted == 0 || errorLux.size() != lux.size()) return e;
    double sum = 0, weightSum = 0;
    bool minimumSeen = false;
    for (size_t i = 0; i < lux.size(); ++i) {
        if (i < excluded.size() && excluded[i]) continue;
        const double w = i < weights.size() ? weights[i] : 1.0;
        sum += w * errorLux[i];
        weightSum += w;
        if (!minimumSeen && lux[i] == s.minimum) {
            e.minimum = errorLux[i];
            minimumSeen = true;
        }
    }
    e.average = weightSum > 0 ? sum / weightSum : 0.0;
    if (s.average > 0 && s.minimum > 0) e.uniformity = s.uniformity * (e.minimum / s.minimum + e.average / s.average);
    return e;
}

}  // namespace lucerna
