#include "ui/commands/light_commands.h"

#include "core/photometry/light_output.h"
#include "core/scene/scene_geometry.h"

namespace lucerna {

QString lightTypeName(LightType type) {
    switch (type) {
    case LightType::Point: return QObject::tr("Point light");
    case LightType::Spot: return QObject::tr("Spot light");
    case LightType::Directional: return QObject::tr("Directional light");
    case LightType::Luminaire: return QObject::tr("Luminaire");
    case LightType::Sun: return QObject::tr("Sun");
    }
    return {};
}

Light defaultLight(const Scene& scene, LightType type, const std::string& name) {
    const SceneBounds b = sceneBounds(scene);
    Light l;
    l.name = name;
    l.type = type;
    // Above the middle of the scene, a fifth of its size below the top.
    l.position = V3d(b.center.x, b.hi.y - 0.2 * (b.hi.y - b.lo.y), b.center.z);
    l.direction = V3d(0, -1, 0);
    // A plausible lamp: 1000 lm at 3000 K (a spot's flux spread over its cone), given in those
    // keys so that the file says so.
    PhotometricSpec lamp;
    lamp.quantity = PhotometricSpec::Quantity::Lumens;
    lamp.value = 1000;
    lamp.temperatureK = 3000;
    switch (type) {
    case LightType::Point: l = withPhotometric(l, lamp); break;
    case LightType::Spot:
        l.coneAngleDeg = 30;
        l.falloffStartDeg = 25;
        l = withPhotometric(l, lamp);
        break;
    case LightType::Directional:
        l.direction = V3d(-0.3, -1, 0.2);
        l.irradiance = Rgbd(2, 2, 2);
        break;
    case LightType::Luminaire:  // needs a file: not made from the Edit menu
    case LightType::Sun: break;   // made by the daylight panel (daylight_commands.h)
    }
    return l;
}

}  // namespace lucerna
