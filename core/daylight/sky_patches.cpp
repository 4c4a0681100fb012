#include "core/daylight/sky_patches.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lucerna {

namespace {
constexpr double kPiD = std::numbers::pi;
constexpr int kTregenzaRow[7] = {30, 30, 24, 24, 18, 12, 6};

V3d direction(double altitude, double phi) {
    const double c = std::cos(altitude);
    return V3d(c * std::cos(phi), std::sin(altitude), c * std::sin(phi));
}
}  // namespace

SkyPatches::SkyPatches(int subdivision) : m_(subdivision) {
    if (m_ < 1 || m_ > 16) throw std::invalid_argument("sky subdivision must be from 1 to 16");
    rowWidth_ = (kPiD / 2) / (7 * m_ + 0.5);
    for (int r = 0; r < 7 * m_; ++r) rows_.push_back({r * rowWidth_, (r + 1) * rowWidth_, kTregenzaRow[r / m_] * m_});
    rows_.push_back({7 * m_ * rowWidth_, kPiD / 2, 1});
    // Cells per side: about 3 degrees or finer, at least 2.
    const int side = std::max(2, 8 / m_);
    perPatch_ = size_t(side * side);
    int start = 0;
    for (const Row& row : rows_) {
        rowStart_.push_back(start);
        const double s0 = std::sin(row.altLo), s1 = std::sin(row.altHi);
        const double dphi = 2 * kPiD / row.patches;
        for (int k = 0; k < row.patches; ++k) {
            const int patch = int(solidAngle_.size());
            solidAngle_.push_back((s1 - s0) * dphi);
            bounds_.push_back({s0, s1, k * dphi, dphi});
            centre_.push_back(row.patches == 1 ? V3d(0, 1, 0) : direction(std::asin(0.5 * (s0 + s1)), (k + 0.5) * dphi));
            const std::vector<V3d> c = cells(patch, side);
            double cosine = 0;
            for (const V3d& w : c) cosine += w.y;
            projected_.push_back(solidAngle_.back() * cosine / double(c.size()));
            samples_.insert(samples_.end(), c.begin(), c.end());
        }
        start += row.patches;
    }
}

std::vector<V3d> SkyPatches::cells(int patch, int side) const {
    // Equal solid angle: uniform in sin(altitude) and in azimuth.
    const Bounds& b = bounds_[size_t(patch)];
    std::vector<V3d> out;
    out.reserve(size_t(side * side));
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j)
            out.push_back(direction(std::asin(b.sinLo + (i + 0.5) / side * (b.sinHi - b.sinLo)), b.phiLo + (j + 0.5) / side * b.phiWidth));
    return out;
}

int SkyPatches::patchOf(const V3d& w) const {
    const double altitude = std::asin(std::clamp(w.y, 0.0, 1.0));
    const int r = std::min(int(altitude / rowWidth_), int(rows_.size()) - 1);
    const Row& row = rows_[size_t(r)];
    double phi = std::atan2(w.z, w.x);
    if (phi < 0) phi += 2 * kPiD;
    const int k = std::min(int(phi / (2 * kPiD) * row.patches), row.patches - 1);
    return rowStart_[size_t(r)] + k;
}

}  // namespace lucerna
