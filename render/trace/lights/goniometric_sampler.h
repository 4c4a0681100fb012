#pragma once
// Evaluating and importance-sampling a luminaire's goniometric distribution in its local frame:
// x = the C0 direction, y = C90, z = the nadir (gamma = 0). Directions are drawn cell by cell of
// the (C, gamma) table, a cell chosen in proportion to its exact flux and a direction in it
// uniformly in C and cos(gamma) (uniform in solid angle), so the density is piecewise constant:
// P(cell) / (solid angle of the cell).

#include "core/photometry/goniometric_distribution.h"
#include "core/math.h"
#include "render/trace/discrete_distribution.h"

#include <memory>

namespace lucerna {

class GoniometricSampler {
public:
    explicit GoniometricSampler(std::shared_ptr<const GoniometricDistribution> distribution);

    // Intensity (cd) toward the unit local direction w.
    float intensity(const V3f& w) const;
    // A unit local direction and its solid-angle density; false when the distribution is dark.
    bool sample(const V2f& u, V3f& w, float& pdf) const;
    // The solid-angle density with which sample() yields unit local direction w.
    float pdf(const V3f& w) const;
    // Total flux of the table (cd sr = lm).
    double flux() const { return cells_.total(); }
    const GoniometricDistribution& distribution() const { return *d_; }
    // Upper bounds for light trees: no direction's intensity exceeds peakIntensity() (cd), and
    // every direction farther than emissionConeRad() from the nadir has none.
    // (Bilinear interpolation never exceeds the table's entries.)
    float peakIntensity() const { return float(d_->maxIntensity()); }
    float emissionConeRad() const { return coneRad_; }

private:
    // The (C, gamma) cell of a direction and its index; false outside the tabulated gamma range.
    bool cellOf(const V3f& w, size_t& index) const;
    double cellSolidAngle(size_t c, size_t g) const;

    std::shared_ptr<const GoniometricDistribution> d_;
    DiscreteDistribution cells_;  // over c * (gammas - 1) + g
    size_t gammaCells_ = 0;
    float coneRad_ = 0;
};

// Local (C0, C90, nadir) coordinates of a luminaire's direction in degrees.
void goniometricAngles(const V3f& w, double& cDeg, double& gammaDeg);

}  // namespace lucerna
