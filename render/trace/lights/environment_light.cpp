#include "render/trace/lights/environment_light.h"

#include <cmath>

namespace lucerna {

namespace {
constexpr double kCellSolidAngle(int rows, int columns) { return 4.0 * 3.14159265358979323846 / (double(rows) * columns); }

V3d cellDirection(double y, double phi) {
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    return V3d(r * std::cos(phi), y, r * std::sin(phi));
}
}  // namespace

std::optional<EnvironmentLight> EnvironmentLight::fromDaylight(const Daylight& daylight) {
    EnvironmentLight env;
    if (daylight.sun && daylight.sun->halfAngleRad > 0 && daylight.sun->aboveHorizon) {
        const ResolvedSun& sun = *daylight.sun;
        const double h = sun.halfAngleRad, s = std::sin(h), sHalf = std::sin(0.5 * h);
        env.towardSun_ = toFloat(sun.towardSun.normalized());
        env.sunOneMinusCos_ = float(2.0 * sHalf * sHalf);
        env.sunSin2_ = float(s * s);
        env.sunRadiance_ = toFloat(sun.radiance());
        env.sunIntegral_ = luminance(sun.radiance()) * 4.0 * std::numbers::pi * sHalf * sHalf;
    }
    if (daylight.sky) {
        env.sky_ = daylight.sky;
        env.skyRelative_.emplace(daylight.sky->distribution());
        // Each cell's weight is its mean luminance over 4 x 4 points: positive wherever the sky
        // or the ground is, so that every direction that carries light can be sampled.
        constexpr int kSub = 4;
        std::vector<double> rowWeights(kRows);
        env.columns_.reserve(kRows);
        for (int r = 0; r < kRows; ++r) {
            std::vector<double> weights(kColumns);
            for (int c = 0; c < kColumns; ++c) {
                double sum = 0;
                for (int i = 0; i < kSub; ++i)
                    for (int j = 0; j < kSub; ++j) {
                        const double y = 1.0 - 2.0 * (r + (i + 0.5) / kSub) / kRows;
                        const double phi = 2.0 * std::numbers::pi * (c + (j + 0.5) / kSub) / kColumns;
                        sum += daylight.sky->luminance(cellDirection(y, phi), *env.skyRelative_);
                    }
                weights[size_t(c)] = sum / (kSub * kSub);
                rowWeights[size_t(r)] += weights[size_t(c)];
            }
            env.columns_.emplace_back(weights);
        }
        env.rows_ = DiscreteDistribution(rowWeights);
        env.skyIntegral_ = env.rows_.total() * kCellSolidAngle(kRows, kColumns) / kLumensPerWatt;
    }
    if (!(env.integratedLuminance() > 0)) return std::nullopt;
    env.sunProbability_ = float(env.sunIntegral_ / env.integratedLuminance());
    return env;
}

EnvironmentLight EnvironmentLight::reweighted(const std::function<double(const V3d&)>& factor) const {
    EnvironmentLight out = *this;
    if (!rows_.empty()) {
        std::vector<double> rowWeights(kRows, 0.0);
        for (int r = 0; r < kRows; ++r) {
            const DiscreteDistribution& row = columns_[size_t(r)];
            std::vector<double> weights(kColumns, 0.0);
            if (!row.empty())
                for (int c = 0; c < kColumns; ++c) {
                    const double y = 1.0 - 2.0 * (r + 0.5) / kRows, phi = 2.0 * std::numbers::pi * (c + 0.5) / kColumns;
                    weights[size_t(c)] = row.pdf(size_t(c)) * row.total() * std::max(0.0, factor(cellDirection(y, phi)));
                    rowWeights[size_t(r)] += weights[size_t(c)];
                }
            out.columns_[size_t(r)] = DiscreteDistribution(weights);
        }
        out.rows_ = DiscreteDistribution(rowWeights);
        out.skyIntegral_ = out.rows_.total() * kCellSolidAngle(kRows, kColumns) / kLumensPerWatt;
    }
    out.sunIntegral_ = sunSin2_ > 0 ? sunIntegral_ * std::max(0.0, factor(V3d(towardSun_))) : 0.0;
    const double total = out.integratedLuminance();
    out.sunProbability_ = total > 0 ? float(out.sunIntegral_ / total) : 0.0f;
    return out;
}

bool EnvironmentLight::insideSun(const V3f& w) const {
    // By the sine of the angle to the centre: its square keeps its precision for tiny discs. The
    // 1e-4 of slack keeps every direction sample() draws in the disc despite w's rounding: one
    // that fell out would carry the sun's radiance at the sky's density, a firefly of 1e5.
    return sunSin2_ > 0 && w.dot(towardSun_) > 0 && w.cross(towardSun_).length2() <= sunSin2_ * 1.0001f;
}

Rgb EnvironmentLight::radiance(const V3f& w) const {
    Rgb L(0, 0, 0);
    if (sky_) L += Rgb(float(sky_->luminance(V3d(w), *skyRelative_) / kLumensPerWatt));
    if (insideSun(w)) L += sunRadiance_;
    return L;
}

float EnvironmentLight::skyPdf(const V3f& w) const {
    if (rows_.empty()) return 0.0f;
    const int r = std::clamp(int((1.0f - w.y) * 0.5f * kRows), 0, kRows - 1);
    float phi = std::atan2(w.z, w.x);
    if (phi < 0) phi += 2.0f * kPi;
    const int c = std::clamp(int(phi / (2.0f * kPi) * kColumns), 0, kColumns - 1);
    const DiscreteDistribution& row = columns_[size_t(r)];
    if (row.empty()) return 0.0f;
    return float(rows_.pdf(size_t(r)) * row.pdf(size_t(c)) / kCellSolidAngle(kRows, kColumns));
}

float EnvironmentLight::pdf(const V3f& w) const {
    float p = (1.0f - sunProbability_) * skyPdf(w);
    if (insideSun(w)) p += sunProbability_ / (2.0f * kPi * sunOneMinusCos_);
    return p;
}

bool EnvironmentLight::sample(const V2f& u, V3f& w, float& pdfOut, Rgb& value) const {
    V2f v = u;
    if (v.x < sunProbability_) {
        // Uniform in the sun's cone, by 1 - cos theta (squareToUniformCone's form, with the
        // cone's 1 - cos given exactly).
        v.x = std::min(v.x / sunProbability_, 0x1.fffffep-1f);
        const float oneMinusCos = v.x * sunOneMinusCos_;
        const float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (2.0f - oneMinusCos)));
        const float phi = 2.0f * kPi * v.y;
        w = Frame(towardSun_).toWorld(V3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0f - oneMinusCos));
        // Value and density by the same test as radiance() and pdf(), which MIS and the
        // portals' mixture evaluate.
        value = radiance(w);
        pdfOut = pdf(w);
        return pdfOut > 0 && !isBlack(value);
    }
    if (rows_.empty()) return false;
    v.x = std::min((v.x - sunProbability_) / (1.0f - sunProbability_), 0x1.fffffep-1f);
    float ur = 0, uc = 0;
    const size_t r = rows_.sample(v.x, &ur);
    const size_t c = columns_[r].sample(v.y, &uc);
    const double y = 1.0 - 2.0 * (double(r) + ur) / kRows;
    const double phi = 2.0 * std::numbers::pi * (double(c) + uc) / kColumns;
    w = toFloat(cellDirection(y, phi));
    value = radiance(w);
    pdfOut = pdf(w);
    return pdfOut > 0 && !isBlack(value);
}

}  // namespace lucerna
