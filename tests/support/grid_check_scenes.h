#pragma once
// Scenes for the checks a calculation grid makes of its points (render/photometry/grid_diagnosis.h):
// a cabinet (a closed box) standing on a floor under a lamp, and a lamp over a glass pane with the
// grid under it. Metres, y up.

#include "closed_form_scenes.h"

#include <sstream>
#include <string>

namespace lucerna::test {

// A closed box from lo to hi, faces outward (counter-clockwise seen from outside; `inward`: seen
// from inside), as JSON mesh.
inline std::string boxMesh(const V3d& lo, const V3d& hi, bool inward = false) {
    const V3d v[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                      {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    std::ostringstream s;
    s << "{\"vertices\": [";
    for (int i = 0; i < 8; ++i) s << (i ? "," : "") << jsonVec(v[i]);
    s << (inward ? "], \"triangles\": [[0,1,2],[0,2,3],[4,6,5],[4,7,6],[0,5,1],[0,4,5],[3,6,7],[3,2,6],[0,7,4],[0,3,7],"
                   "[1,6,2],[1,5,6]]}"
                 : "], \"triangles\": [[0,2,1],[0,3,2],[4,5,6],[4,6,7],[0,1,5],[0,5,4],[3,7,6],[3,6,2],[0,4,7],[0,7,3],"
                   "[1,2,6],[1,6,5]]}");
    return s.str();
}

// A 6 m floor, a 1 x 1.2 x 1 m cabinet in its middle, a point lamp (10 W/sr) 2.5 m above it. A work
// plane at 0.6 m with 0.5 m spacing over the middle 4 m has 8 x 8 points, the middle 2 x 2 inside
// the cabinet.
inline std::string cabinetSceneJson() {
    std::ostringstream s;
    s << R"({"lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0, 5, -5], "target": [0, 0, 0], "fov_y": 50, "resolution": [64, 64]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "objects": [
    {"name": "floor", "material": "white", "mesh": {"quad": [[-3,0,-3],[-3,0,3],[3,0,3],[3,0,-3]]}},
    {"name": "cabinet", "material": "white", "mesh": )"
      << boxMesh(V3d(-0.5, 0, -0.5), V3d(0.5, 1.2, 0.5)) << R"(}],
  "lights": [{"name": "lamp", "type": "point", "position": [0, 2.5, 0], "intensity": [10, 10, 10]}]})";
    return s.str();
}

// The cabinet scene in a closed 6 x 3 x 6 m room (one box, floor included) whose faces point out
// of the room (`outward`, as a box primitive makes it) or into it; the lamp and the camera in the
// room, or (`fromOutside`) both 2 m above its roof.
inline std::string boxRoomSceneJson(bool outward, bool fromOutside) {
    std::ostringstream s;
    const double y = fromOutside ? 5 : 2.5;
    s << R"({"lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0, )" << y << R"(, -2.5], "target": [0, 0, 0], "fov_y": 50, "resolution": [64, 64]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "objects": [
    {"name": "room", "material": "white", "mesh": )"
      << boxMesh(V3d(-3, 0, -3), V3d(3, 3, 3), !outward) << R"(},
    {"name": "cabinet", "material": "white", "mesh": )"
      << boxMesh(V3d(-0.5, 0, -0.5), V3d(0.5, 1.2, 0.5)) << R"(}],
  "lights": [{"name": "lamp", "type": "point", "position": [0, )" << y << R"(, 0], "intensity": [10, 10, 10]}]})";
    return s.str();
}

// A point lamp (10 W/sr) 3 m above a 2 x 2 grid at y = 0 (0.5 m spacing, facing up), with (glass)
// or without a 1 cm pane of glass (n = 1.5, 6 m square) at 1.5 m between them. Nothing else: no
// random path reaches the grid through the pane.
inline std::string lampOverPaneJson(bool glass) {
    std::ostringstream s;
    s << R"({"lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0, 1, -6], "target": [0, 1, 0], "fov_y": 50, "resolution": [64, 64]},
  "materials": {"glass": {"type": "dielectric", "ior": 1.5}},
  "objects": [)";
    if (glass) s << R"({"name": "pane", "material": "glass", "mesh": )" << boxMesh(V3d(-3, 1.5, -3), V3d(3, 1.51, 3)) << "}";
    s << R"(],
  "lights": [{"name": "lamp", "type": "point", "position": [0, 3, 0], "intensity": [10, 10, 10]}]})";
    return s.str();
}

// (1 - R)^2 with R = ((n - 1) / (n + 1))^2: the light two faces of glass let through at normal
// incidence, inter-reflections left out.
inline double paneTransmittanceAtNormalIncidence(double n) {
    const double r = (n - 1) / (n + 1);
    return (1 - r * r) * (1 - r * r);
}

}  // namespace lucerna::test
