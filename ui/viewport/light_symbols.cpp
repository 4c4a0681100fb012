#include "ui/viewport/light_symbols.h"

#include <algorithm>

namespace lucerna {

double depthAlongView(const ViewMapping& view, const V3d& world) {
    const Camera& c = view.camera();
    return (world - c.position).dot((c.target - c.position).normalized());
}

double nearPlaneDepth(double metersPerUnit) { return kNearPlaneM / (metersPerUnit > 0 ? metersPerUnit : 1.0); }

std::optional<LightSymbol> lightSymbol(const Light& light, const ViewMapping& view, double metersPerUnit,
                                       double smallestPx, double largestPx) {
    if (light.type == LightType::Directional || light.type == LightType::Sun || !view.isValid()) return std::nullopt;
    if (depthAlongView(view, light.position) < nearPlaneDepth(metersPerUnit)) return std::nullopt;
    const auto centre = view.toWidget(light.position);
    if (!centre || !view.rect().contains(*centre)) return std::nullopt;
    const double mpu = metersPerUnit > 0 ? metersPerUnit : 1.0;
    const double radius = (kSymbolRadiusM / mpu) / view.worldPerPixel(light.position);
    return LightSymbol{*centre, std::clamp(radius, smallestPx, largestPx)};
}

std::optional<QLineF> projectedSegment(const ViewMapping& view, const V3d& a, const V3d& b, double nearDepth) {
    const double da = depthAlongView(view, a), db = depthAlongView(view, b);
    if (da < nearDepth && db < nearDepth) return std::nullopt;
    V3d p = a, q = b;
    // The part behind the near plane, from where the segment crosses it.
    if (da < nearDepth) p = a + (b - a) * ((nearDepth - da) / (db - da));
    else if (db < nearDepth) q = a + (b - a) * ((nearDepth - da) / (db - da));
    const auto wp = view.toWidget(p), wq = view.toWidget(q);
    if (!wp || !wq) return std::nullopt;
    return QLineF(*wp, *wq);
}

double aimLineLength(std::optional<double> hitDistance, double metersPerUnit) {
    const double longest = kLongestAimLineM / (metersPerUnit > 0 ? metersPerUnit : 1.0);
    return hitDistance && *hitDistance > 0 ? std::min(*hitDistance, longest) : longest;
}

}  // namespace lucerna
