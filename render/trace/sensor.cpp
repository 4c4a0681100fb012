#include "render/trace/sensor.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

Sensor::Sensor(std::vector<IrradianceSensor> points, int pixelsPerSide)
    : points_(std::move(points)), side_(std::max(1, pixelsPerSide)) {
    frames_.reserve(points_.size());
    for (IrradianceSensor& p : points_) {
        p.normal = p.normal.normalized();
        frames_.emplace_back(p.normal);
    }
}

int Sensor::pointAt(float x) const {
    if (isPinhole()) return 0;
    return std::clamp(int(x) / side_, 0, int(points_.size()) - 1);
}

Ray Sensor::ray(float x, float y) const {
    if (isPinhole()) return pinhole_.ray(x, y);
    const int i = pointAt(x);
    // The polar map: r^2 = u is uniform, so the density of directions is cos / pi.
    const float u = std::clamp((x - float(i * side_)) / float(side_), 0.0f, 1.0f);
    const float v = std::clamp(y / float(side_), 0.0f, 1.0f);
    const float r = std::sqrt(u), phi = 2.0f * kPi * v;
    const V3f local(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u)));
    return Ray{points_[size_t(i)].position, frames_[size_t(i)].toWorld(local).normalized()};
}

bool Sensor::rasterPoint(int point, const V3f& dir, float& x, float& y) const {
    if (isPinhole()) return pinhole_.rasterPoint(dir, x, y);
    const V3f local = frames_[size_t(point)].toLocal(dir);
    if (!(local.z > 0.0f)) return false;
    const float u = std::min(local.x * local.x + local.y * local.y, 1.0f);
    float v = std::atan2(local.y, local.x) / (2.0f * kPi);
    if (v < 0.0f) v += 1.0f;
    x = std::min((float(point) + u) * float(side_), float((point + 1) * side_) - 1e-3f);
    y = std::min(v * float(side_), float(side_) - 1e-3f);
    return true;
}

float Sensor::pdfDirection(int point, const V3f& dir) const {
    if (isPinhole()) {
        float x, y;
        if (!pinhole_.rasterPoint(dir, x, y)) return 0.0f;
        const float cosTheta = dir.dot(pinhole_.forward());
        return 1.0f / (pinhole_.imagePlaneArea() * cosTheta * cosTheta * cosTheta);
    }
    return std::max(0.0f, dir.dot(points_[size_t(point)].normal)) * kInvPi;
}

}  // namespace lucerna
