#include "render/trace/lights/goniometric_sampler.h"

#include <algorithm>

namespace lucerna {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

size_t cellIndex(const std::vector<double>& v, double x) {
    const auto it = std::upper_bound(v.begin(), v.end(), x);
    const size_t i = size_t(std::max<std::ptrdiff_t>(it - v.begin(), 1)) - 1;
    return std::min(i, v.size() - 2);
}
}  // namespace

void goniometricAngles(const V3f& w, double& cDeg, double& gammaDeg) {
    gammaDeg = std::acos(std::clamp(double(w.z), -1.0, 1.0)) / kDeg;
    cDeg = std::atan2(double(w.y), double(w.x)) / kDeg;
    if (cDeg < 0) cDeg += 360.0;
}

GoniometricSampler::GoniometricSampler(std::shared_ptr<const GoniometricDistribution> distribution)
    : d_(std::move(distribution)) {
    const size_t nC = d_->cAngles.size(), nG = d_->gammaAngles.size();
    if (nC < 2 || nG < 2) return;
    gammaCells_ = nG - 1;
    std::vector<double> weights;
    weights.reserve((nC - 1) * gammaCells_);
    for (size_t c = 0; c + 1 < nC; ++c)
        for (size_t g = 0; g < gammaCells_; ++g) weights.push_back(std::max(0.0, d_->cellFlux(c, g)));
    cells_ = DiscreteDistribution(weights);

    // Bilinear interpolation is nonzero up to the gamma node after the last nonzero entry of
    // any C plane (zero beyond the tabulated range).
    size_t lastLit = 0;
    bool lit = false;
    for (size_t c = 0; c < nC; ++c)
        for (size_t g = 0; g < nG; ++g)
            if (d_->at(c, g) > 0) {
                lastLit = std::max(lastLit, g);
                lit = true;
            }
    if (lit) coneRad_ = float(d_->gammaAngles[std::min(lastLit + 1, nG - 1)] * kDeg);
}

float GoniometricSampler::intensity(const V3f& w) const {
    double c = 0, g = 0;
    goniometricAngles(w, c, g);
    return float(d_->intensity(c, g));
}

double GoniometricSampler::cellSolidAngle(size_t c, size_t g) const {
    const double dC = (d_->cAngles[c + 1] - d_->cAngles[c]) * kDeg;
    return dC * (std::cos(d_->gammaAngles[g] * kDeg) - std::cos(d_->gammaAngles[g + 1] * kDeg));
}

bool GoniometricSampler::cellOf(const V3f& w, size_t& index) const {
    if (gammaCells_ == 0) return false;
    double c = 0, g = 0;
    goniometricAngles(w, c, g);
    const auto& gammas = d_->gammaAngles;
    if (g < gammas.front() || g > gammas.back()) return false;
    index = cellIndex(d_->cAngles, c) * gammaCells_ + cellIndex(gammas, g);
    return true;
}

bool GoniometricSampler::sample(const V2f& u, V3f& w, float& pdf) const {
    if (cells_.empty()) return false;
    float uC = 0;
    const size_t k = cells_.sample(u.x, &uC);
    const size_t c = k / gammaCells_, g = k % gammaCells_;
    const double c0 = d_->cAngles[c], c1 = d_->cAngles[c + 1];
    const double cosG0 = std::cos(d_->gammaAngles[g] * kDeg), cosG1 = std::cos(d_->gammaAngles[g + 1] * kDeg);
    const double phi = (c0 + double(uC) * (c1 - c0)) * kDeg;
    const double cosG = std::clamp(cosG0 + double(u.y) * (cosG1 - cosG0), -1.0, 1.0);
    const double sinG = std::sqrt(std::max(0.0, 1.0 - cosG * cosG));
    w = V3f(float(sinG * std::cos(phi)), float(sinG * std::sin(phi)), float(cosG));
    pdf = float(cells_.pdf(k) / cellSolidAngle(c, g));
    return pdf > 0.0f && std::isfinite(pdf);
}

float GoniometricSampler::pdf(const V3f& w) const {
    size_t k = 0;
    if (cells_.empty() || !cellOf(w, k)) return 0.0f;
    const double omega = cellSolidAngle(k / gammaCells_, k % gammaCells_);
    return omega > 0 ? float(cells_.pdf(k) / omega) : 0.0f;
}

}  // namespace lucerna
