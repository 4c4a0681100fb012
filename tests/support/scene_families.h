#pragma once
// Families of the scenes designers bring, made to size: an open-plan office with a grid of
// ceiling lights, a closed room lit by a tessellated ceiling panel, many emitter triangles. Used
// by the preview's tests (small members) and by bench_preview (the sizes the issue names), so
// that what is tuned on one member is confirmed on another.

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace lucerna::test {

namespace family_detail {

inline std::string vec(double x, double y, double z) {
    std::ostringstream s;
    s.precision(9);
    s << "[" << x << "," << y << "," << z << "]";
    return s.str();
}

// An axis-aligned box [lo, hi] as 6 quads (diffuse is two-sided, so winding does not matter).
inline std::string box(const std::string& name, const std::string& material, double x0, double y0, double z0,
                       double x1, double y1, double z1) {
    const auto q = [&](const std::string& n, std::string a, std::string b, std::string c, std::string d) {
        return R"({"name": ")" + name + "_" + n + R"(", "material": ")" + material + R"(", "mesh": {"quad": [)" + a +
               "," + b + "," + c + "," + d + "]}}";
    };
    return q("bottom", vec(x0, y0, z0), vec(x0, y0, z1), vec(x1, y0, z1), vec(x1, y0, z0)) + "," +
           q("top", vec(x0, y1, z0), vec(x1, y1, z0), vec(x1, y1, z1), vec(x0, y1, z1)) + "," +
           q("left", vec(x0, y0, z0), vec(x0, y1, z0), vec(x0, y1, z1), vec(x0, y0, z1)) + "," +
           q("right", vec(x1, y0, z0), vec(x1, y0, z1), vec(x1, y1, z1), vec(x1, y1, z0)) + "," +
           q("back", vec(x0, y0, z1), vec(x0, y1, z1), vec(x1, y1, z1), vec(x1, y0, z1)) + "," +
           q("front", vec(x0, y0, z0), vec(x1, y0, z0), vec(x1, y1, z0), vec(x0, y1, z0));
}

// A panel in the plane y = height facing down (-y), split into cells x cells quads, each two
// triangles wound so that the emitting front face looks down.
inline std::string downwardPanel(const std::string& name, const std::string& material, double x0, double z0,
                                 double x1, double z1, double height, int cells) {
    std::ostringstream verts, tris;
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j)
            verts << (i + j ? "," : "") << vec(x0 + (x1 - x0) * i / cells, height, z0 + (z1 - z0) * j / cells);
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const int a = i * (cells + 1) + j, b = a + 1, c = a + cells + 1, d = c + 1;
            // (d - a) x (b - a) points down (-y): a, d, b runs counter-clockwise seen from below.
            tris << (i + j ? "," : "") << "[" << a << "," << d << "," << b << "],[" << a << "," << c << "," << d << "]";
        }
    return R"({"name": ")" + name + R"(", "material": ")" + material + R"(", "mesh": {"vertices": [)" + verts.str() +
           R"(], "triangles": [)" + tris.str() + "]}}";
}

}  // namespace family_detail

// An open-plan office, width x depth x 3 m (metres, y up), lit by a lightsX x lightsZ grid of
// ceiling point lights (every third one a downward spot), with rows of desks, low partitions and
// columns; the camera stands in a corner at eye height looking across. Each light gives
// `intensity` W/sr.
inline std::string officeJson(int lightsX, int lightsZ, int width, int height, double intensity = 40.0,
                              double roomW = 30.0, double roomD = 18.0) {
    using namespace family_detail;
    const double roomH = 3.0;
    std::ostringstream s;
    s << R"({"lucerna": 1, "meters_per_unit": 1, "camera": {"position": )" << vec(1.0, 1.6, 1.0)
      << R"(, "target": )" << vec(roomW * 0.6, 0.9, roomD * 0.7) << R"(, "up": [0, 1, 0], "fov_y": 60, "resolution": [)"
      << width << "," << height << R"(]},
  "materials": {"wall": {"type": "diffuse", "albedo": [0.7, 0.7, 0.68]},
                "floor": {"type": "diffuse", "albedo": [0.3, 0.28, 0.25]},
                "ceiling": {"type": "diffuse", "albedo": [0.85, 0.85, 0.85]},
                "desk": {"type": "glossy", "albedo": [0.55, 0.45, 0.35], "specular": [0.04, 0.04, 0.04], "roughness": 0.3},
                "partition": {"type": "diffuse", "albedo": [0.3, 0.4, 0.55]},
                "column": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]}},
  "objects": [)";
    s << R"({"name": "floor", "material": "floor", "mesh": {"quad": [)" << vec(0, 0, 0) << "," << vec(0, 0, roomD)
      << "," << vec(roomW, 0, roomD) << "," << vec(roomW, 0, 0) << "]}},";
    s << R"({"name": "ceiling", "material": "ceiling", "mesh": {"quad": [)" << vec(0, roomH, 0) << ","
      << vec(roomW, roomH, 0) << "," << vec(roomW, roomH, roomD) << "," << vec(0, roomH, roomD) << "]}},";
    s << R"({"name": "wall_w", "material": "wall", "mesh": {"quad": [)" << vec(0, 0, 0) << "," << vec(0, roomH, 0)
      << "," << vec(0, roomH, roomD) << "," << vec(0, 0, roomD) << "]}},";
    s << R"({"name": "wall_e", "material": "wall", "mesh": {"quad": [)" << vec(roomW, 0, 0) << ","
      << vec(roomW, 0, roomD) << "," << vec(roomW, roomH, roomD) << "," << vec(roomW, roomH, 0) << "]}},";
    s << R"({"name": "wall_n", "material": "wall", "mesh": {"quad": [)" << vec(0, 0, roomD) << ","
      << vec(0, roomH, roomD) << "," << vec(roomW, roomH, roomD) << "," << vec(roomW, 0, roomD) << "]}},";
    s << R"({"name": "wall_s", "material": "wall", "mesh": {"quad": [)" << vec(0, 0, 0) << "," << vec(roomW, 0, 0)
      << "," << vec(roomW, roomH, 0) << "," << vec(0, roomH, 0) << "]}}";
    // Desks in rows of pairs with a partition between each pair, aisles between the rows.
    int n = 0;
    for (double z = 2.5; z + 1.6 < roomD - 1.5; z += 3.6)
        for (double x = 3.0; x + 1.6 < roomW - 2.0; x += 2.4) {
            s << "," << box("desk" + std::to_string(n), "desk", x, 0.72, z, x + 1.6, 0.75, z + 0.8);
            s << "," << box("desk" + std::to_string(n) + "b", "desk", x, 0.72, z + 0.85, x + 1.6, 0.75, z + 1.65);
            s << "," << box("partition" + std::to_string(n), "partition", x, 0.0, z + 0.8, x + 1.6, 1.25, z + 0.85);
            ++n;
        }
    for (double x = roomW / 4; x < roomW - 1; x += roomW / 4)
        for (double z = roomD / 3; z < roomD - 1; z += roomD / 3)
            s << "," << box("column" + std::to_string(n++), "column", x - 0.2, 0, z - 0.2, x + 0.2, roomH, z + 0.2);
    s << R"(], "lights": [)";
    for (int i = 0; i < lightsX; ++i)
        for (int j = 0; j < lightsZ; ++j) {
            const double x = roomW * (i + 0.5) / lightsX, z = roomD * (j + 0.5) / lightsZ;
            const int k = i * lightsZ + j;
            s << (k ? "," : "") << R"({"name": "L)" << k << R"(", "position": )" << vec(x, roomH - 0.1, z);
            if (k % 3 == 2)
                s << R"(, "type": "spot", "direction": [0, -1, 0], "cone_angle": 60, "falloff_start": 45, "intensity": )"
                  << vec(intensity * 1.5, intensity * 1.5, intensity * 1.5) << "}";
            else
                s << R"(, "type": "point", "intensity": )" << vec(intensity, intensity * 0.95, intensity * 0.85) << "}";
        }
    s << "]}";
    return s.str();
}

// A closed room 6 x 3 x 5 m of one diffuse albedo, lit by a ceiling panel of cells x cells quads
// (2 cells^2 emitter triangles) of radiance `radiance`, seen from inside (the panel out of view:
// its edges, many times brighter than the walls, would weigh on the mean by their antialiasing).
inline std::string closedRoomJson(double albedo, int cells, int width, int height, double radiance = 10.0) {
    using namespace family_detail;
    std::ostringstream s;
    s.precision(9);
    s << R"({"lucerna": 1, "camera": {"position": [0.6, 1.5, 0.6], "target": [4.5, 0.3, 4.0], "up": [0, 1, 0],
  "fov_y": 70, "resolution": [)"
      << width << "," << height << R"(]},
  "materials": {"wall": {"type": "diffuse", "albedo": )"
      << vec(albedo, albedo, albedo) << R"(}, "panel": {"type": "emitter", "radiance": )"
      << vec(radiance, radiance, radiance) << R"(}},
  "objects": [)"
      << box("room", "wall", 0, 0, 0, 6, 3, 5) << "," << box("cabinet", "wall", 4.4, 0, 0.2, 5.8, 1.8, 0.8) << ","
      << downwardPanel("panel", "panel", 2.0, 1.5, 4.0, 3.5, 2.99, cells) << "]}";
    return s.str();
}

}  // namespace lucerna::test
