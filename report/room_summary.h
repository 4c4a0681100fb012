#pragma once
// The room summary of a report (README, "Reports"): the room's dimensions (the geometry's
// extent), the reflectances of its main surfaces, the maintenance factor, the luminaires and the
// connected load, as a designer states them before the results.

#include "core/scene/scene.h"

#include <array>
#include <functional>
#include <optional>
#include <string>

namespace lucerna {

struct Schedule;

// A main surface: among the faces facing one way (up: the floor; sideways: the walls; down: the
// ceiling; a face's way is that of its normal within 45 degrees of vertical, else sideways), the
// material of the largest total area. Only materials with a diffuse part (diffuse, glossy) count.
struct MainSurface {
    std::string role;         // "Floor", "Walls", "Ceiling"
    std::string material;     // empty: no face with a diffuse material faces that way
    double reflectance = 0;   // the material's diffuse albedo, luminance-weighted (Y of Rec. 709), 0..1
    double areaM2 = 0;        // of the material's faces facing that way
    double facingAreaM2 = 0;  // of every counted face facing that way
};

struct RoomSummary {
    double widthM = 0, depthM = 0, heightM = 0;  // the geometry's extent along x, z and y
    std::array<MainSurface, 3> surfaces;         // floor, walls, ceiling
    MaintenanceRange maintenance;
    std::optional<MaintenanceFactor> sceneMaintenance;  // the scene's own key, for its CIE 97 factors
    int luminaires = 0;                          // lights switched on (the schedule's count)
    std::optional<double> connectedLoadW;        // of the lights that state their power
    int withoutWatts = 0;                        // lights that state none
    double floorAreaM2 = 0;                      // the schedule's (the extent in plan)
};

// The floor, walls and ceiling by that rule, among the objects `include` accepts (all: the summary's).
std::array<MainSurface, 3> mainSurfaces(const Scene& scene, const std::function<bool(const Object&)>& include);

// The summary of `scene` (as loaded: its meshes in world space) with `schedule`'s lights.
RoomSummary roomSummary(const Scene& scene, const Schedule& schedule);

}  // namespace lucerna
