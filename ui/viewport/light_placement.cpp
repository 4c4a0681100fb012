#include "ui/viewport/light_placement.h"

#include "ui/commands/light_commands.h"

namespace lucerna {

double placementOffset(double metersPerUnit, double geometryDiagonal) {
    const double quarterMetre = 0.25 / std::max(metersPerUnit, 1e-300);
    return geometryDiagonal > 0 ? std::min(quarterMetre, 0.1 * geometryDiagonal) : quarterMetre;
}

Light placedLight(const Scene& scene, LightType type, const std::string& name, const SurfaceHit& hit, double offset) {
    Light light = defaultLight(scene, type, name);
    light.position = hit.point + hit.normal * offset;
    // The normal faces the camera, so the spot looks away from the surface, into the room.
    if (type == LightType::Spot) light.direction = hit.normal;
    return light;
}

std::optional<Light> aimedLight(const Light& light, const SurfaceHit& hit) {
    Light aimed = light;
    switch (light.type) {
    case LightType::Point:
    case LightType::Sun: return std::nullopt;  // the sun is placed by its site and time, or its own panel
    case LightType::Spot:
    case LightType::Luminaire: {  // its direction is its nadir, aimed like a spot's axis
        const V3d d = hit.point - light.position;
        if (d.length() <= 1e-12 * std::max(1.0, light.position.length())) return std::nullopt;
        aimed.direction = d.normalized();
        return aimed;
    }
    case LightType::Directional: aimed.direction = -hit.normal; return aimed;
    }
    return std::nullopt;
}

}  // namespace lucerna
