#pragma once
// Daylit scenes whose images are known in closed form (SPEC.md section 5), for every backend and
// the preview: a diffuse plane under an open overcast sky, a uniform sky seen through an opening
// (or a pane) in the roof of a black box, and a sun's disc over a plane, with the penumbra behind
// a straight edge.

#include "closed_form_scenes.h"

#include "core/daylight/daylight.h"
#include "render/trace/lights/environment_light.h"

#include <cmath>
#include <numbers>

namespace lucerna::test {

// The environment of a CIE general sky of `type` giving skyLx on the horizontal, and a sun
// travelling along sunTravel of sunLx and angular diameter sunDiameterDeg (0: a delta sun, then
// the environment is the sky alone); nullopt without one.
inline std::optional<EnvironmentLight> cieEnvironment(int type, double skyLx, const V3d& sunTravel = V3d(0, -1, 0),
                                                      double sunLx = 0, double sunDiameterDeg = 0) {
    Scene scene;
    Sky sky;
    sky.model = SkyModelType::CieGeneral;
    sky.cieType = type;
    sky.horizontalIlluminance = skyLx;
    scene.sky = sky;
    if (sunLx > 0) {
        Light sun;
        sun.name = "sun";
        sun.type = LightType::Sun;
        sun.direction = sunTravel;
        sun.sun = SunSpec{};
        sun.sun->illuminanceLux = sunLx;
        sun.sun->angularDiameterDeg = sunDiameterDeg;
        scene.lights.push_back(sun);
    }
    return EnvironmentLight::fromDaylight(resolveDaylight(scene));
}

inline std::string greyJson(double v) { return "[" + std::to_string(v) + "," + std::to_string(v) + "," + std::to_string(v) + "]"; }

inline std::string quadJson(const std::string& name, const std::string& material, const std::vector<V3d>& q) {
    return R"({"name": ")" + name + R"(", "material": ")" + material + R"(", "mesh": {"quad": [)" + jsonVec(q[0]) + "," +
           jsonVec(q[1]) + "," + jsonVec(q[2]) + "," + jsonVec(q[3]) + "]}}";
}

inline std::string cameraJson(const Camera& c) {
    return R"("camera": {"position": )" + jsonVec(c.position) + R"(, "target": )" + jsonVec(c.target) + R"(, "up": )" +
           jsonVec(c.up) + R"(, "fov_y": )" + std::to_string(c.fovYDeg) + R"(, "resolution": [)" + std::to_string(c.width) +
           "," + std::to_string(c.height) + "]}";
}

// A diffuse plane (albedo rho) under the traditional CIE overcast sky of zenith luminance Lz:
// E = 7 pi Lz / 9, so the plane's radiance is rho E / (pi 683) per channel.
struct OvercastOverPlane {
    double rho = 0.5, zenithLuminance = 683.0 * 9.0 / 7.0;  // E = pi W/m^2: radiance rho
    int resolution = 32;
    Camera camera() const { return lookingDown(V3d(0, 1, 0), resolution); }
    std::string json() const {
        return R"({"lucerna": 1, )" + cameraJson(camera()) + R"(, "materials": {"floor": {"type": "diffuse", "albedo": )" +
               greyJson(rho) + R"(}}, "objects": [)" +
               quadJson("floor", "floor", {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}}) +
               R"(], "sky": {"model": "cie_overcast", "zenith_luminance": )" + std::to_string(zenithLuminance) + "}}";
    }
    double expectedRadiance() const { return rho / std::numbers::pi * 7.0 * std::numbers::pi * zenithLuminance / 9.0 / 683.0; }
    std::vector<double> expected() const {
        return expectedFloorImage(camera(), [&](const V3d&) { return expectedRadiance(); });
    }
};

// A closed box (floor albedo rho; walls and roof black, both sides) whose roof at height h has
// a rectangular opening, under a uniform sky of luminance Lz; optionally a glazing pane of
// transmittance tau fills the opening. The floor's irradiance is Lambert's polygon formula for
// the opening at radiance Lz / 683 (times tau). The camera at h/2 looks straight down.
// Optionally, the opening is filled by a quad marked as an opening ("portal": true, README), and
// a sun of diameter 0 at the zenith, of illuminance Es, lights the floor under the opening with
// rho Es tau / (pi 683).
struct SkyThroughOpening {
    double rho = 0.5, h = 2.0, half = 1.5, zenithLuminance = 683.0;
    double x0 = -0.3, x1 = 0.5, z0 = -0.4, z1 = 0.4;  // the opening
    std::optional<double> glazing;                     // its pane's transmittance
    bool marked = false;                               // a quad marked as an opening fills it
    std::optional<double> zenithSun;                   // the sun's illuminance, lx
    int resolution = 32;

    Camera camera() const { return lookingDown(V3d(0, h / 2, 0), resolution); }
    std::vector<V3d> opening() const { return {{x0, h, z0}, {x1, h, z0}, {x1, h, z1}, {x0, h, z1}}; }
    std::string json() const {
        const double a = half;
        std::string objects = quadJson("floor", "floor", {{-a, 0, -a}, {-a, 0, a}, {a, 0, a}, {a, 0, -a}});
        // Walls, then the roof around the opening as four strips.
        objects += "," + quadJson("wall_w", "black", {{-a, 0, -a}, {-a, h, -a}, {-a, h, a}, {-a, 0, a}});
        objects += "," + quadJson("wall_e", "black", {{a, 0, -a}, {a, 0, a}, {a, h, a}, {a, h, -a}});
        objects += "," + quadJson("wall_n", "black", {{-a, 0, -a}, {a, 0, -a}, {a, h, -a}, {-a, h, -a}});
        objects += "," + quadJson("wall_s", "black", {{-a, 0, a}, {-a, h, a}, {a, h, a}, {a, 0, a}});
        objects += "," + quadJson("roof_w", "black", {{-a, h, -a}, {-a, h, a}, {x0, h, a}, {x0, h, -a}});
        objects += "," + quadJson("roof_e", "black", {{x1, h, -a}, {x1, h, a}, {a, h, a}, {a, h, -a}});
        objects += "," + quadJson("roof_n", "black", {{x0, h, -a}, {x0, h, z0}, {x1, h, z0}, {x1, h, -a}});
        objects += "," + quadJson("roof_s", "black", {{x0, h, z1}, {x0, h, a}, {x1, h, a}, {x1, h, z1}});
        std::string materials = R"("floor": {"type": "diffuse", "albedo": )" + greyJson(rho) +
                                R"(}, "black": {"type": "diffuse", "albedo": [0,0,0]})";
        if (glazing) {
            materials += R"(, "glass": {"type": "glazing", "transmittance": )" + greyJson(*glazing) + "}";
            objects += "," + quadJson("pane", "glass", opening());
        } else if (marked) {
            std::string opening = quadJson("opening", "black", this->opening());
            objects += "," + opening.insert(opening.find(R"("mesh")"), R"("portal": true, )");
        }
        const std::string sun = zenithSun ? R"(, "lights": [{"name": "sun", "type": "sun", "illuminance": )" +
                                                std::to_string(*zenithSun) +
                                                R"(, "angular_diameter": 0, "direction": [0, -1, 0]}])"
                                          : "";
        return R"({"lucerna": 1, )" + cameraJson(camera()) + R"(, "materials": {)" + materials + R"(}, "objects": [)" +
               objects + "]" + sun + R"(, "sky": {"model": "uniform", "zenith_luminance": )" +
               std::to_string(zenithLuminance) + "}}";
    }
    double floorRadiance(const V3d& p) const {
        return rho / std::numbers::pi * zenithLuminance / 683.0 * glazing.value_or(1.0) *
               lambertPolygonIrradiance(p, V3d(0, 1, 0), opening());
    }
    std::vector<double> expected() const {
        std::vector<double> image = expectedFloorImage(camera(), [&](const V3d& p) { return floorRadiance(p); });
        if (zenithSun) {  // the sunlit rectangle's edges sampled finely: they cross pixels
            const double sunlit = rho / std::numbers::pi * *zenithSun / 683.0 * glazing.value_or(1.0);
            const std::vector<double> sun = expectedFloorImage(
                camera(), [&](const V3d& p) { return p.x > x0 && p.x < x1 && p.z > z0 && p.z < z1 ? sunlit : 0.0; },
                64);
            for (size_t i = 0; i < image.size(); ++i) image[i] += sun[i];
        }
        return image;
    }
};

// A sun of angular diameter d and illuminance E over a diffuse plane, at zenith angle Z in the
// x-y plane: the plane's radiance is rho E cos Z / (pi 683). With `edge`, an opaque half-plane
// (x < 0) at height H hides part of a sun at the zenith: behind its edge the irradiance is the
// visible fraction of the disc (a circular segment) times E.
struct SunOverPlane {
    double rho = 0.5, illuminance = 683.0 * std::numbers::pi, diameterDeg = 0.53, zenithDeg = 40;
    bool edge = false;
    double H = 10.0, view = 0.08;  // edge: the blocker's height, and the half-width seen on the floor
    int resolution = 32;

    // With the edge, just above the floor, looking down at the penumbra: x from -view to +view.
    Camera camera() const { return lookingDown(V3d(0, edge ? view : 1.0, 0), resolution); }
    V3d travel() const {
        const double z = (edge ? 0.0 : zenithDeg) * std::numbers::pi / 180;
        return V3d(-std::sin(z), -std::cos(z), 0);
    }
    std::string json() const {
        std::string objects = quadJson("floor", "floor", {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}});
        if (edge) objects += "," + quadJson("blocker", "black", {{-40, H, -40}, {-40, H, 40}, {0, H, 40}, {0, H, -40}});
        return R"({"lucerna": 1, )" + cameraJson(camera()) + R"(, "materials": {"floor": {"type": "diffuse", "albedo": )" +
               greyJson(rho) + R"(}, "black": {"type": "diffuse", "albedo": [0,0,0]}}, "objects": [)" + objects +
               R"(], "lights": [{"name": "sun", "type": "sun", "illuminance": )" + std::to_string(illuminance) +
               R"(, "angular_diameter": )" + std::to_string(diameterDeg) + R"(, "direction": )" + jsonVec(travel()) + "}]}";
    }
    // The visible fraction of the disc at floor point x behind the edge (small angles: a chord
    // at distance x / H from the disc's centre, in units of its angular radius).
    double visibleFraction(double x) const {
        const double alpha = 0.5 * diameterDeg * std::numbers::pi / 180;
        const double c = std::clamp(-x / (H * alpha), -1.0, 1.0);
        return (std::acos(c) - c * std::sqrt(1 - c * c)) / std::numbers::pi;
    }
    double floorRadiance(const V3d& p) const {
        const double cosZ = -travel().y;
        const double full = rho / std::numbers::pi * illuminance / 683.0 * cosZ;
        return edge ? full * visibleFraction(p.x) : full;
    }
    std::vector<double> expected() const {
        return expectedFloorImage(camera(), [&](const V3d& p) { return floorRadiance(p); });
    }
};

}  // namespace lucerna::test
