#include "render/photometry/grid_text.h"

#include "core/number_format.h"

#include <cstdarg>
#include <cstdio>

namespace lucerna {

namespace {
// printf into a string; every line written here is far shorter than the buffer.
[[gnu::format(printf, 1, 2)]] std::string printed(const char* format, ...) {
    char buf[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buf, sizeof buf, format, args);
    va_end(args);
    return buf;
}
}  // namespace

std::string gridFiguresLine(const GridStatistics& s) {
    if (s.counted == 0) return "Eavg, Emin, Emax, U0: none (every point is inside geometry)";
    return printed("Eavg %.1f lx, Emin %.1f lx, Emax %.1f lx, U0 %.3f", s.average, s.minimum, s.maximum, s.uniformity);
}

std::string daylightFactorFiguresLine(const GridStatistics& s) {
    if (s.counted == 0) return "DF: none (every point is inside geometry)";
    return printed("DFavg %.2f%%, DFmin %.2f%%, DFmax %.2f%%, uniformity DFmin/DFavg %.3f", s.average, s.minimum,
                   s.maximum, s.uniformity);
}

std::string excludedPointsLine(const GridStatistics& s, size_t points, bool daylightFactor) {
    if (s.excluded == 0) return {};
    return printed("%d of %zu points inside geometry, excluded%s", s.excluded, points,
                   daylightFactor ? "" : " from Eavg, Emin, Emax and U0");
}

std::vector<std::string> gridErrorLines(const GridResult& r, int counted) {
    const std::string after = printed("after %d passes, %lld samples per point, ", r.passes, r.samplesPerPoint) +
                              formatDuration(r.seconds);
    if (r.errorBarUnknown)
        return {printed("%s cannot carry light through glass to %d of %d points: use bdpt (or method auto)",
                        gridMethodName(r.method), r.litThroughGlass, counted),
                "error bar unknown (the light through glass is missing) " + after};
    return {printed("error bar (95%%) at most %.2f%% of each point's value ", 100.0 * r.maxRelativeError) + after +
            (r.converged ? "" : " (target not reached)")};
}

std::string gridPointText(const GridResult& r, size_t k, double scale, int decimals) {
    if (k < r.insideGeometry.size() && r.insideGeometry[k]) return "inside";
    return printed("%.*f", decimals, r.lux[k] * scale);
}

std::string gridTableText(const GridLayout& layout, const GridResult& r, double scale, int decimals) {
    if (layout.nu > 16) return {};
    std::string table;
    for (int j = layout.nv - 1; j >= 0; --j) {
        for (int i = 0; i < layout.nu; ++i)
            table += printed("%9s", gridPointText(r, size_t(j) * size_t(layout.nu) + size_t(i), scale, decimals).c_str());
        table += "\n";
    }
    return table;
}

}  // namespace lucerna
