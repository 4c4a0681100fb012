#pragma once
// Scenes whose images are known in closed form, and those closed forms. Shared by the tests of
// every backend (and the preview).

#include "core/math.h"
#include "render/trace/camera.h"

#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace lucerna::test {

// Irradiance at x (unit normal n) from a uniform Lambertian polygon of radiance 1, by Lambert's
// formula: E = 1/2 sum_i angle(R_i, R_i+1) n . normalize(R_i x R_i+1) (up to orientation).
inline double lambertPolygonIrradiance(const V3d& x, const V3d& n, const std::vector<V3d>& polygon) {
    double sum = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const V3d a = (polygon[i] - x).normalized(), b = (polygon[(i + 1) % polygon.size()] - x).normalized();
        const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
        const V3d c = a.cross(b);
        if (c.length() > 0) sum += angle * n.dot(c.normalized());
    }
    return 0.5 * std::abs(sum);
}

// Expected image of a scene whose camera sees only the plane y = 0: the radiance function of the
// floor point, averaged over k x k points in each pixel (SPEC.md's box filter).
inline std::vector<double> expectedFloorImage(const Camera& cam, const std::function<double(const V3d&)>& radiance,
                                              int k = 6) {
    const PinholeCamera camera(cam, cam.width, cam.height);
    std::vector<double> out(size_t(cam.width) * cam.height, 0.0);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            double sum = 0;
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const V3f d = camera.direction(x + (i + 0.5f) / k, y + (j + 0.5f) / k);
                    const double t = -cam.position.y / double(d.y);
                    sum += radiance(cam.position + V3d(d.x, d.y, d.z) * t);
                }
            out[size_t(y) * cam.width + x] = sum / (k * k);
        }
    return out;
}

// A camera at `position` looking straight down (-y) with a 90 degree square view.
inline Camera lookingDown(const V3d& position, int resolution) {
    Camera c;
    c.position = position;
    c.target = V3d(position.x, 0, position.z);
    c.up = V3d(0, 0, 1);
    c.fovYDeg = 90;
    c.width = c.height = resolution;
    return c;
}

inline std::string jsonVec(const V3d& v) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << v.x << "," << v.y << "," << v.z << "]";
    return s.str();
}

// A diffuse floor (albedo rho) under a square emitter of half-size a at height h, facing down;
// the camera at height h/2 looks straight down. Nothing else.
struct RectangleOverPlane {
    double rho = 0.5, a = 0.5, h = 1.0, radiance = 2.0;
    int resolution = 32;

    std::vector<V3d> emitter() const { return {{-a, h, -a}, {a, h, -a}, {a, h, a}, {-a, h, a}}; }
    Camera camera() const { return lookingDown(V3d(0, h / 2, 0), resolution); }
    std::string json() const {
        const auto e = emitter();
        std::ostringstream s;
        s << R"({"lucerna": 1, "camera": {"position": )" << jsonVec(camera().position)
          << R"(, "target": [0,0,0], "up": [0,0,1], "fov_y": 90, "resolution": [)" << resolution << "," << resolution
          << R"(]}, "materials": {"floor": {"type": "diffuse", "albedo": [)" << rho << "," << rho << "," << rho
          << R"(]}, "lamp": {"type": "emitter", "radiance": [)" << radiance << "," << radiance << "," << radiance
          << R"(]}}, "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-20,0,-20],[-20,0,20],[20,0,20],[20,0,-20]]}},)"
          << R"({"name": "lamp", "material": "lamp", "mesh": {"quad": [)" << jsonVec(e[0]) << "," << jsonVec(e[1]) << ","
          << jsonVec(e[2]) << "," << jsonVec(e[3]) << "]}}]}";
        return s.str();
    }
    std::vector<double> expected() const {
        const auto e = emitter();
        return expectedFloorImage(camera(), [&](const V3d& p) {
            return rho / std::numbers::pi * radiance * lambertPolygonIrradiance(p, V3d(0, 1, 0), e);
        });
    }
};

// A delta light over a diffuse floor, in a millimetre scene. Point: the floor's radiance is
// rho/pi * I cos / (d * 0.001)^2; spot: the same times SPEC.md's smoothstep of the cone;
// directional: rho/pi * E cos, whatever the scale.
struct DeltaLightOverPlane {
    enum class Kind { Point, Spot, Directional };
    Kind kind = Kind::Point;
    double rho = 0.5, h = 1000.0, intensity = 2.0;
    double coneDeg = 20.0, falloffStartDeg = 12.0;  // spot
    V3d sunDirection{-0.3, -1.0, 0.2};              // directional
    int resolution = 32;

    Camera camera() const { return lookingDown(V3d(0, h / 2, 0), resolution); }
    std::string json() const {
        std::ostringstream s;
        s.precision(17);
        const std::string rgb = "[" + std::to_string(intensity) + "," + std::to_string(intensity) + "," +
                                std::to_string(intensity) + "]";
        s << R"({"lucerna": 1, "meters_per_unit": 0.001, "camera": {"position": )" << jsonVec(camera().position)
          << R"(, "target": [0,0,0], "up": [0,0,1], "fov_y": 90, "resolution": [)" << resolution << "," << resolution
          << R"(]}, "materials": {"floor": {"type": "diffuse", "albedo": [)" << rho << "," << rho << "," << rho
          << R"(]}}, "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-20000,0,-20000],[-20000,0,20000],[20000,0,20000],[20000,0,-20000]]}}],)"
          << R"("lights": [)";
        switch (kind) {
        case Kind::Point:
            s << R"({"name": "bulb", "type": "point", "position": [0,)" << h << R"(,0], "intensity": )" << rgb << "}";
            break;
        case Kind::Spot:
            s << R"({"name": "spot", "type": "spot", "position": [0,)" << h << R"(,0], "direction": [0,-1,0], "intensity": )"
              << rgb << R"(, "cone_angle": )" << coneDeg << R"(, "falloff_start": )" << falloffStartDeg << "}";
            break;
        case Kind::Directional:
            s << R"({"name": "sun", "type": "directional", "direction": )" << jsonVec(sunDirection)
              << R"(, "irradiance": )" << rgb << "}";
            break;
        }
        s << "]}";
        return s.str();
    }
    std::vector<double> expected() const {
        return expectedFloorImage(camera(), [&](const V3d& p) {
            if (kind == Kind::Directional)
                return rho / std::numbers::pi * intensity * (-sunDirection.normalized().y);
            const V3d d = V3d(0, h, 0) - p;
            const double dist = d.length();
            const double cosTheta = h / dist;
            double factor = 1.0;
            if (kind == Kind::Spot) {
                const double a = std::cos(coneDeg * std::numbers::pi / 180);
                const double b = std::cos(falloffStartDeg * std::numbers::pi / 180);
                const double t = std::clamp((cosTheta - a) / (b - a), 0.0, 1.0);
                factor = t * t * (3 - 2 * t);
            }
            return rho / std::numbers::pi * intensity * factor * cosTheta / (dist * 0.001 * dist * 0.001);
        });
    }
};

// Many point lights over a diffuse floor: a field of 40 x 25 lamps, 1 m apart, at heights from
// 2 to 3 m and of intensities from 0.5 to 2 W/sr (a fixed pseudo-random pattern), over a floor
// of albedo rho; the camera at 1 m looks straight down at the middle. The floor's radiance is
// rho / pi * sum_i I_i cos_i / r_i^2 (nothing else in the scene casts a shadow).
struct ManyPointLightsOverPlane {
    double rho = 0.8;
    int columns = 40, rows = 25;
    int resolution = 32;

    struct Lamp {
        V3d position;
        double intensity;
    };
    std::vector<Lamp> lamps() const {
        std::vector<Lamp> out;
        uint32_t state = 12345;
        const auto next = [&state] {  // a small LCG: the pattern is part of the scene, not a sample
            state = state * 1664525u + 1013904223u;
            return double(state >> 8) / double(1u << 24);
        };
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                const double x = c - 0.5 * (columns - 1) + 0.3 * (next() - 0.5);
                const double z = r - 0.5 * (rows - 1) + 0.3 * (next() - 0.5);
                out.push_back({V3d(x, 2.0 + next(), z), 0.5 + 1.5 * next()});
            }
        return out;
    }
    Camera camera() const { return lookingDown(V3d(0.17, 1, 0.23), resolution); }
    std::string json() const {
        std::ostringstream s;
        s.precision(17);
        s << R"({"lucerna": 1, "camera": {"position": )" << jsonVec(camera().position) << R"(, "target": )"
          << jsonVec(camera().target) << R"(, "up": [0,0,1], "fov_y": 90, "resolution": [)" << resolution << ","
          << resolution << R"(]}, "materials": {"floor": {"type": "diffuse", "albedo": [)" << rho << "," << rho << ","
          << rho << R"(]}}, "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-200,0,-200],[-200,0,200],[200,0,200],[200,0,-200]]}}],)"
          << R"("lights": [)";
        const auto all = lamps();
        for (size_t i = 0; i < all.size(); ++i)
            s << (i ? "," : "") << R"({"name": "lamp)" << i << R"(", "type": "point", "position": )"
              << jsonVec(all[i].position) << R"(, "intensity": [)" << all[i].intensity << "," << all[i].intensity << ","
              << all[i].intensity << "]}";
        s << "]}";
        return s.str();
    }
    std::vector<double> expected() const {
        const auto all = lamps();
        return expectedFloorImage(camera(), [&](const V3d& p) {
            double e = 0;
            for (const Lamp& l : all) {
                const V3d d = l.position - p;
                const double dist2 = d.length2();
                e += l.intensity * (d.y / std::sqrt(dist2)) / dist2;
            }
            return rho / std::numbers::pi * e;
        }, 4);
    }
};

// A closed sphere whose inner cap (polar angle < capAngle around +y) emits radiance Le inward and
// whose remaining shell is diffuse with albedo rho. Inside a sphere every point sees every area
// element with form factor dA/A, so the shell's radiance is uniform:
// L = rho Le (Ae/A) / (1 - rho (A - Ae)/A), with the areas of the actual tessellation.
struct SphereWithEmittingCap {
    double rho = 0.5, radiance = 1.0, capAngleDeg = 30.0;
    int rings = 48, segments = 96;
    int resolution = 24;
    double capArea = 0, totalArea = 0;

    std::string json() {
        std::vector<V3d> v;
        const double pi = std::numbers::pi;
        for (int i = 0; i <= rings; ++i)
            for (int j = 0; j < segments; ++j) {
                const double th = pi * i / rings, ph = 2 * pi * j / segments;
                v.push_back(V3d(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)));
            }
        std::ostringstream cap, shell;
        cap.precision(17);
        shell.precision(17);
        bool firstCap = true, firstShell = true;
        capArea = totalArea = 0;
        const int capRings = int(std::lround(capAngleDeg / 180.0 * rings));
        const auto add = [&](int a, int b, int c, bool isCap) {
            // Wound so that the front face (counter-clockwise) looks into the sphere.
            const double area = 0.5 * (v[b] - v[a]).cross(v[c] - v[a]).length();
            if (area <= 0) return;
            totalArea += area;
            std::ostringstream& s = isCap ? cap : shell;
            bool& first = isCap ? firstCap : firstShell;
            if (isCap) capArea += area;
            s << (first ? "" : ",") << "[" << a << "," << b << "," << c << "]";
            first = false;
        };
        for (int i = 0; i < rings; ++i)
            for (int j = 0; j < segments; ++j) {
                const int a = i * segments + j, b = i * segments + (j + 1) % segments;
                const int c = (i + 1) * segments + j, d = (i + 1) * segments + (j + 1) % segments;
                add(a, d, b, i < capRings);
                add(a, c, d, i < capRings);
            }
        std::ostringstream verts;
        verts.precision(17);
        for (size_t i = 0; i < v.size(); ++i) verts << (i ? "," : "") << jsonVec(v[i]);
        std::ostringstream s;
        s << R"({"lucerna": 1, "camera": {"position": [0,0,0], "target": [0,-1,0], "up": [0,0,1], "fov_y": 60, "resolution": [)"
          << resolution << "," << resolution << R"(]}, "materials": {"shell": {"type": "diffuse", "albedo": [)" << rho
          << "," << rho << "," << rho << R"(]}, "cap": {"type": "emitter", "radiance": [)" << radiance << ","
          << radiance << "," << radiance << R"(]}}, "objects": [{"name": "cap", "material": "cap", "mesh": {"vertices": [)"
          << verts.str() << R"(], "triangles": [)" << cap.str()
          << R"(]}}, {"name": "shell", "material": "shell", "mesh": {"vertices": [)" << verts.str()
          << R"(], "triangles": [)" << shell.str() << "]}}]}";
        return s.str();
    }
    double expectedRadiance() const {
        const double f = capArea / totalArea;
        return rho * radiance * f / (1.0 - rho * (1.0 - f));
    }
};

}  // namespace lucerna::test
