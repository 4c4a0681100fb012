#include "ui/commands/daylight_commands.h"

#include "core/daylight/daylight.h"

#include <cmath>
#include <numbers>

namespace lucerna {

int sunIndex(const Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].type == LightType::Sun) return int(i);
    return -1;
}

Light newSun(const Scene& scene, const std::string& name, const std::string& time) {
    Light l;
    l.name = name;
    l.type = LightType::Sun;
    l.sun = SunSpec();
    l.sun->illuminanceLux = 75000;
    if (scene.site) return sunAtTime(l, time);
    // Toward the sun: up and to the south, the default north being -z.
    l.direction = V3d(0, -1, -1);
    return l;
}

Light sunAtTime(const Light& sun, const std::string& time) {
    Light l = sun;
    if (!l.sun) l.sun = SunSpec();
    l.sun->time = time;
    // What the reader gives a sun placed by time, so that a saved scene reads back equal.
    l.direction = Light().direction;
    return l;
}

Light sunByDirection(const Scene& scene, const Light& sun) {
    Light l = sun;
    l.direction = -sunDirection(scene, sun);
    if (l.sun) l.sun->time.reset();
    return l;
}

double northAngleDeg(const V3d& north) {
    const double a = std::atan2(north.x, -north.z) * 180.0 / std::numbers::pi;
    return a < 0 ? a + 360.0 : a;
}

V3d northFromAngle(double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const auto clean = [](double x) { return std::abs(x) < 1e-12 ? 0.0 : x; };
    return V3d(clean(std::sin(a)), 0, clean(-std::cos(a)));
}

}  // namespace lucerna
