#pragma once
// The integral over the upper hemisphere (up is +y) of f(w) cos(zenith), by the midpoint rule on
// `resolution` zenith rings (at least 8) and 4 x resolution azimuths: a sky's horizontal
// illuminance from its luminance. The sky models' integrands are smooth except near the sun,
// where the indicatrix has a kink of bounded slope.

#include "core/math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

template <class F>
double horizontalIntegral(const F& f, int resolution) {
    constexpr double kPi = std::numbers::pi;
    const int nz = std::max(resolution, 8), nphi = 4 * nz;
    const double dz = (kPi / 2) / nz, dphi = 2 * kPi / nphi;
    double sum = 0;
    for (int i = 0; i < nz; ++i) {
        const double z = (i + 0.5) * dz, sz = std::sin(z), cz = std::cos(z);
        double ring = 0;
        for (int j = 0; j < nphi; ++j) {
            const double phi = (j + 0.5) * dphi;
            ring += f(V3d(sz * std::cos(phi), cz, sz * std::sin(phi)));
        }
        sum += ring * cz * sz;
    }
    return sum * dz * dphi;
}

}  // namespace lucerna
