#pragma once
// Scenes that break careless light transport code: singular geometric terms, grazing angles,
// extreme dynamic range, coincident surfaces, light that cannot get out. Every backend must
// render them without a single NaN or infinite pixel (issue 3, "Tests"). Small on purpose
// (a few hundred triangles at most, 32x32 pixels), so that each backend can afford them all.

#include <string>
#include <vector>

namespace lucerna::test {

struct HardCase {
    std::string name;
    std::string json;
};

namespace hard_case_detail {

// A closed box [0,s]^3 of diffuse walls, wound so that every wall's front faces inward.
inline std::string boxWalls(const std::string& material, double s) {
    const std::string S = std::to_string(s);
    const auto quad = [&](const std::string& name, const std::string& a, const std::string& b, const std::string& c,
                          const std::string& d) {
        return R"({"name": ")" + name + R"(", "material": ")" + material + R"(", "mesh": {"quad": [)" + a + "," + b +
               "," + c + "," + d + "]}}";
    };
    const std::string o = "[0,0,0]", x = "[" + S + ",0,0]", y = "[0," + S + ",0]", z = "[0,0," + S + "]";
    const std::string xy = "[" + S + "," + S + ",0]", xz = "[" + S + ",0," + S + "]", yz = "[0," + S + "," + S + "]";
    const std::string xyz = "[" + S + "," + S + "," + S + "]";
    return quad(material + "_floor", o, z, xz, x) + "," + quad(material + "_ceiling", y, xy, xyz, yz) + "," +
           quad(material + "_left", o, y, yz, z) + "," + quad(material + "_right", x, xz, xyz, xy) + "," +
           quad(material + "_back", z, yz, xyz, xz) + "," + quad(material + "_front", o, x, xy, y);
}

}  // namespace hard_case_detail

inline std::vector<HardCase> hardCaseScenes() {
    using hard_case_detail::boxWalls;
    std::vector<HardCase> cases;
    const std::string camera32 = R"("resolution": [32, 32])";

    // A light right in a sharp concave corner: light (and VPLs) land a hair away from the
    // surfaces they then illuminate, so 1/d^2 is as singular as it gets.
    cases.push_back({"vpl corners", R"({"lucerna": 1, "camera": {"position": [0.5, 0.5, 0.5], "target": [0, 0, 0],
        "fov_y": 60, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.9, 0.9, 0.9]},
                    "lamp": {"type": "emitter", "radiance": [50, 50, 50]}},
      "objects": [
        {"name": "floor", "material": "white", "mesh": {"quad": [[0,0,0],[0,0,1],[1,0,1],[1,0,0]]}},
        {"name": "wall_x", "material": "white", "mesh": {"quad": [[0,0,0],[0,1,0],[0,1,1],[0,0,1]]}},
        {"name": "wall_z", "material": "white", "mesh": {"quad": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}},
        {"name": "wedge", "material": "white", "mesh": {"vertices": [[0.2,0,0.2],[0.8,0,0.2],[0.8,0.001,0.8]],
                                                        "triangles": [[0,2,1]]}},
        {"name": "lamp", "material": "lamp", "mesh": {"quad": [[1e-4,1e-4,0.02],[1e-4,0.02,0.02],[1e-4,0.02,1e-4],[1e-4,1e-4,1e-4]]}}],
      "lights": [{"name": "corner bulb", "type": "point", "position": [1e-5, 1e-5, 1e-5], "intensity": [1, 1, 1]}]})"});

    // Light arriving almost parallel to the surfaces: an emitter 1e-4 above the floor facing
    // along it, a spot skimming the floor and a sun 0.01 degrees above the horizon.
    cases.push_back({"grazing light", R"({"lucerna": 1, "camera": {"position": [0, 2, -3], "target": [0, 0, 0],
        "fov_y": 50, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]},
                    "shiny": {"type": "glossy", "albedo": [0.2, 0.2, 0.2], "specular": [0.8, 0.8, 0.8], "roughness": 0.05},
                    "lamp": {"type": "emitter", "radiance": [10, 10, 10]}},
      "objects": [
        {"name": "floor", "material": "white", "mesh": {"quad": [[-5,0,-5],[-5,0,5],[5,0,5],[5,0,-5]]}},
        {"name": "plate", "material": "shiny", "mesh": {"quad": [[-1,0.001,-1],[-1,0.001,1],[1,0.001,1],[1,0.001,-1]]}},
        {"name": "lamp", "material": "lamp", "mesh": {"quad": [[-2,1e-4,2],[2,1e-4,2],[2,0.5,2.0001],[-2,0.5,2.0001]]}}],
      "lights": [
        {"name": "skimming spot", "type": "spot", "position": [-3, 0.01, 0], "direction": [1, -0.0001, 0],
         "intensity": [20, 20, 20], "cone_angle": 5},
        {"name": "low sun", "type": "directional", "direction": [0.3, -0.0001745, 1], "irradiance": [2, 2, 2]}]})"});

    // A 1e-3 x 1e-3 emitter of radiance 1e9 next to an ordinary one: 12 orders of magnitude
    // between what different paths carry.
    cases.push_back({"tiny bright emitter", R"({"lucerna": 1, "camera": {"position": [0, 1, -2], "target": [0, 0.3, 0],
        "fov_y": 60, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]},
                    "mirror": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]},
                    "glass": {"type": "dielectric", "ior": 1.5},
                    "sun": {"type": "emitter", "radiance": [1e9, 1e9, 1e9]},
                    "dim": {"type": "emitter", "radiance": [0.1, 0.1, 0.1]}},
      "objects": [
        {"name": "floor", "material": "white", "mesh": {"quad": [[-3,0,-3],[-3,0,3],[3,0,3],[3,0,-3]]}},
        {"name": "mirror", "material": "mirror", "mesh": {"quad": [[1,0,-1],[1,0,1],[1,1,1],[1,1,-1]]}},
        {"name": "glass", "material": "glass", "mesh": {"vertices": [[-0.3,0,0],[0.3,0,0],[0,0,0.5],[0,0.6,0.2]],
                                                        "triangles": [[0,2,1],[0,1,3],[1,2,3],[2,0,3]]}},
        {"name": "speck", "material": "sun", "mesh": {"quad": [[0,1.5,0],[0.001,1.5,0],[0.001,1.5,0.001],[0,1.5,0.001]]}},
        {"name": "dim", "material": "dim", "mesh": {"quad": [[-3,3,-3],[3,3,-3],[3,3,3],[-3,3,3]]}}]})"});

    // Two different surfaces in exactly the same plane (z-fighting), and a mirror coincident
    // with a diffuse wall.
    cases.push_back({"coincident surfaces", R"({"lucerna": 1, "camera": {"position": [0, 1, -2.5], "target": [0, 0.4, 0],
        "fov_y": 55, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]},
                    "red": {"type": "diffuse", "albedo": [0.8, 0.1, 0.1]},
                    "mirror": {"type": "mirror", "reflectance": [1, 1, 1]},
                    "lamp": {"type": "emitter", "radiance": [5, 5, 5]}},
      "objects": [
        {"name": "floor", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,0,2],[2,0,2],[2,0,-2]]}},
        {"name": "floor again", "material": "red", "mesh": {"quad": [[-1,0,-1],[-1,0,1],[1,0,1],[1,0,-1]]}},
        {"name": "wall", "material": "white", "mesh": {"quad": [[-2,0,1],[-2,2,1],[2,2,1],[2,0,1]]}},
        {"name": "wall mirror", "material": "mirror", "mesh": {"quad": [[-1,0,1],[-1,2,1],[1,2,1],[1,0,1]]}},
        {"name": "lamp", "material": "lamp", "mesh": {"quad": [[-0.5,1.5,-0.5],[0.5,1.5,-0.5],[0.5,1.5,0.5],[-0.5,1.5,0.5]]}}],
      "lights": [{"name": "bulb", "type": "point", "position": [0, 0.5, 0], "intensity": [1, 1, 1]}]})"});

    // Lights shut in a closed box seen from outside (the image must be black, and nothing may
    // escape through the seams), next to a second box with the camera inside it.
    cases.push_back({"light inside closed box", R"({"lucerna": 1, "camera": {"position": [3, 1, -3], "target": [0.5, 0.5, 0.5],
        "fov_y": 40, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.95, 0.95, 0.95]},
                    "lamp": {"type": "emitter", "radiance": [100, 100, 100]}},
      "objects": [)" + boxWalls("white", 1.0) + R"(,
        {"name": "lamp", "material": "lamp", "mesh": {"quad": [[0.4,0.5,0.4],[0.6,0.5,0.4],[0.6,0.5,0.6],[0.4,0.5,0.6]]}}],
      "lights": [{"name": "bulb", "type": "point", "position": [0.5, 0.2, 0.5], "intensity": [10, 10, 10]},
                 {"name": "spot", "type": "spot", "position": [0.5, 0.9, 0.5], "direction": [0, -1, 0],
                  "intensity": [10, 10, 10], "cone_angle": 60, "falloff_start": 30}]})"});
    cases.push_back({"camera inside closed box", R"({"lucerna": 1, "camera": {"position": [0.5, 0.5, 0.05], "target": [0.5, 0.4, 1],
        "fov_y": 90, )" + camera32 + R"(},
      "materials": {"white": {"type": "diffuse", "albedo": [0.95, 0.95, 0.95]},
                    "lamp": {"type": "emitter", "radiance": [100, 100, 100]}},
      "objects": [)" + boxWalls("white", 1.0) + R"(,
        {"name": "lamp", "material": "lamp", "mesh": {"quad": [[0.4,0.99,0.4],[0.4,0.99,0.6],[0.6,0.99,0.6],[0.6,0.99,0.4]]}}],
      "lights": [{"name": "bulb", "type": "point", "position": [0.5, 0.5, 0.999], "intensity": [1, 1, 1]}]})"});
    return cases;
}

}  // namespace lucerna::test
