#pragma once
// The sky divided into patches for daylight coefficients: Tregenza's 145 patches (Tregenza 1987)
// and Reinhart's subdivisions of them (MF:m, 144 m^2 + 1 patches; Radiance's reinhart.cal):
// 7 m rows of altitude width 90 / (7 m + 0.5) degrees holding 30, 30, 24, 24, 18, 12 and 6
// patches per Tregenza row times m each, and a polar cap of half a row.
//
// Each patch also carries a few directions in cells of equal solid angle, so that a sky's
// luminance averaged over a patch (and the sky's horizontal integral) is a midpoint rule.

#include "core/math.h"

#include <span>
#include <vector>

namespace lucerna {

class SkyPatches {
public:
    // subdivision: Reinhart's m, 1 (Tregenza) to 16.
    explicit SkyPatches(int subdivision);

    int subdivision() const { return m_; }
    int count() const { return int(solidAngle_.size()); }
    // The patch a unit direction above the horizon (w.y > 0) falls in; azimuth phi = atan2(z, x).
    int patchOf(const V3d& w) const;
    double solidAngle(int patch) const { return solidAngle_[size_t(patch)]; }
    // The integral of cos(zenith) over the patch by the midpoint rule on its cells (samples()):
    // its share of a horizontal plane's illuminance, consistently with the cells.
    double projectedSolidAngle(int patch) const { return projected_[size_t(patch)]; }
    // Directions at the centres of the patch's equal-solid-angle cells, each of solid angle
    // solidAngle(patch) / samples(patch).size().
    std::span<const V3d> samples(int patch) const {
        return std::span<const V3d>(samples_).subspan(size_t(patch) * perPatch_, perPatch_);
    }
    // The same cells, `side` x `side` of them (finer than samples() for side above its own).
    std::vector<V3d> cells(int patch, int side) const;
    // The patch's centre direction (a degenerate cell at the cap's pole aside).
    V3d centre(int patch) const { return centre_[size_t(patch)]; }

private:
    struct Row {
        double altLo, altHi;  // radians
        int patches;
    };
    int m_ = 1;
    double rowWidth_ = 0;  // radians
    std::vector<Row> rows_;           // the cap last, with one patch
    std::vector<int> rowStart_;       // first patch of each row
    std::vector<double> solidAngle_, projected_;
    struct Bounds {
        double sinLo, sinHi, phiLo, phiWidth;
    };
    std::vector<Bounds> bounds_;
    std::vector<V3d> centre_, samples_;
    size_t perPatch_ = 1;
};

}  // namespace lucerna
