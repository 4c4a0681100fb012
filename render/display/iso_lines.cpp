#include "render/display/iso_lines.h"

#include <cmath>

namespace lucerna {

std::vector<double> isoLevels(double lo, double hi, int wanted) {
    std::vector<double> out;
    if (!(hi > lo) || wanted < 1 || !std::isfinite(lo) || !std::isfinite(hi)) return out;
    const double raw = (hi - lo) / (wanted + 1);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    double step = decade;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= raw) {
            step = m * decade;
            break;
        }
    for (double level = std::floor(lo / step + 1) * step; level < hi; level += step)
        if (level > lo) out.push_back(level);
    return out;
}

std::vector<IsoSegment> isoSegments(const std::vector<double>& values, int nu, int nv, const std::vector<double>& levels) {
    std::vector<IsoSegment> out;
    if (nu < 2 || nv < 2 || values.size() < size_t(nu) * size_t(nv)) return out;
    const auto at = [&](int i, int j) { return values[size_t(j) * size_t(nu) + size_t(i)]; };
    for (double level : levels)
        for (int j = 0; j + 1 < nv; ++j)
            for (int i = 0; i + 1 < nu; ++i) {
                // Corners counter-clockwise from (i, j): 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1).
                const double v[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                const double ci[4] = {double(i), double(i + 1), double(i + 1), double(i)};
                const double cj[4] = {double(j), double(j), double(j + 1), double(j + 1)};
                int mask = 0;
                for (int k = 0; k < 4; ++k)
                    if (v[k] >= level) mask |= 1 << k;
                if (mask == 0 || mask == 15) continue;
                // The crossing on edge k (from corner k to corner k+1).
                const auto cross = [&](int k, double& x, double& y) {
                    const int a = k, b = (k + 1) % 4;
                    const double t = (level - v[a]) / (v[b] - v[a]);
                    x = ci[a] + t * (ci[b] - ci[a]);
                    y = cj[a] + t * (cj[b] - cj[a]);
                };
                std::vector<int> edges;
                for (int k = 0; k < 4; ++k)
                    if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) edges.push_back(k);
                const auto add = [&](int e0, int e1) {
                    IsoSegment s{0, 0, 0, 0, level};
                    cross(e0, s.i0, s.j0);
                    cross(e1, s.i1, s.j1);
                    out.push_back(s);
                };
                if (edges.size() == 2) {
                    add(edges[0], edges[1]);
                } else if (edges.size() == 4) {
                    // Saddle: corners 0 and 2 on one side, 1 and 3 on the other. When the centre
                    // is on corner 0's side, the lines cut off corners 1 and 3.
                    const bool centreAbove = (v[0] + v[1] + v[2] + v[3]) / 4 >= level;
                    const bool zeroAbove = (mask & 1) != 0;
                    if (centreAbove == zeroAbove) {
                        add(0, 1);  // around corner 1
                        add(2, 3);  // around corner 3
                    } else {
                        add(3, 0);  // around corner 0
                        add(1, 2);  // around corner 2
                    }
                }
            }
    return out;
}

}  // namespace lucerna
