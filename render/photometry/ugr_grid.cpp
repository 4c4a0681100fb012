#include "render/photometry/ugr_grid.h"

#include "core/number_format.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace lucerna {

V3d gridViewDirection(const CalculationGrid& grid, GridViewDirection direction) {
    switch (direction) {
    case GridViewDirection::PlusU: return grid.edgeU;
    case GridViewDirection::MinusU: return -grid.edgeU;
    case GridViewDirection::PlusV: return grid.edgeV;
    case GridViewDirection::MinusV: return -grid.edgeV;
    }
    return grid.edgeU;
}

std::string describeGridView(const CalculationGrid& grid, GridViewDirection direction) {
    const char* along = direction == GridViewDirection::PlusU    ? "+u"
                        : direction == GridViewDirection::MinusU ? "-u"
                        : direction == GridViewDirection::PlusV  ? "+v"
                                                                 : "-v";
    const V3d toward = gridViewDirection(grid, direction).normalized();
    char text[96];
    std::snprintf(text, sizeof text, "along %s, toward (%.3g, %.3g, %.3g)", along, toward.x, toward.y, toward.z);
    return text;
}

std::vector<V3d> observerPositions(const GridLayout& layout, double floorY, double metersPerUnit, double eyeHeightM) {
    std::vector<V3d> eyes;
    eyes.reserve(layout.points.size());
    for (const V3d& p : layout.points) eyes.emplace_back(p.x, floorY + eyeHeightM / metersPerUnit, p.z);
    return eyes;
}

std::vector<std::string> ugrGridFigures(const GlareGridResult& result, const GridLayout& layout, double eyeHeightM,
                                        const std::string& view) {
    double hi = -1e300, lo = 1e300, lbLo = 1e300, lbHi = 0, bar = 0;
    size_t hiAt = 0, loAt = 0;
    int rated = 0;
    for (size_t k = 0; k < result.observers.size(); ++k) {
        const GlareResult& r = result.observers[k];
        if (!r.ugr) continue;
        ++rated;
        if (*r.ugr > hi) hi = *r.ugr, hiAt = k;
        if (*r.ugr < lo) lo = *r.ugr, loAt = k;
        lbLo = std::min(lbLo, r.backgroundLuminanceCdM2);
        lbHi = std::max(lbHi, r.backgroundLuminanceCdM2);
        bar = std::max(bar, r.ugrErrorBar);
    }
    char line[256];
    std::vector<std::string> lines;
    std::snprintf(line, sizeof line, "UGR of %zu observers (the new installation), eyes %.1f m above the floor, looking %s",
                  result.observers.size(), eyeHeightM, view.c_str());
    lines.emplace_back(line);
    if (rated == 0) {
        lines.emplace_back("No luminaire in the field of view of any observer");
        return lines;
    }
    // As the table numbers them: rows from the far side down.
    const auto column = [&](size_t k) { return int(k) % layout.nu + 1; };
    const auto row = [&](size_t k) { return layout.nv - int(k) / layout.nu; };
    std::snprintf(line, sizeof line, "UGR max %.1f (column %d, row %d), min %.1f (column %d, row %d)", hi, column(hiAt),
                  row(hiAt), lo, column(loAt), row(loAt));
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "Lb %.1f to %.1f cd/m^2; UGR error bar at most %.2f (95%%), %s", lbLo, lbHi, bar,
                  gridMethodName(result.method));
    lines.emplace_back(line);
    if (rated < int(result.observers.size()))
        lines.emplace_back(std::to_string(int(result.observers.size()) - rated) + " observers see no luminaire (shown -)");
    return lines;
}

std::string ugrCsv(const GridLayout& layout, const std::vector<V3d>& eyes, const GlareGridResult& result) {
    std::ostringstream s;
    s << "i,j,x,y,z,ugr,error,background_cd_m2\n";
    for (size_t k = 0; k < result.observers.size() && k < eyes.size(); ++k) {
        const GlareResult& r = result.observers[k];
        s << k % size_t(layout.nu) << "," << k / size_t(layout.nu) << "," << shortestNumber(eyes[k].x) << ","
          << shortestNumber(eyes[k].y) << "," << shortestNumber(eyes[k].z) << ",";
        if (r.ugr)
            s << shortestNumber(*r.ugr) << "," << shortestNumber(r.ugrErrorBar) << ","
              << shortestNumber(r.backgroundLuminanceCdM2);
        else s << ",,";
        s << "\n";
    }
    return s.str();
}

}  // namespace lucerna
