#include "render/photometry/task_area_figures.h"

#include "core/number_format.h"
#include "core/scene/plan_polygon.h"
#include "core/scene/scene_geometry.h"
#include "render/photometry/grid_text.h"

#include <algorithm>
#include <limits>

namespace lucerna {

namespace {

V3d areaCentre(const TaskArea& area) { return area.grid.corner + (area.grid.edgeU + area.grid.edgeV) * 0.5; }

// The bounds of a marked room's surfaces; nothing when none is resolved.
std::optional<std::pair<V3d, V3d>> surfaceBounds(const Scene& scene, const std::string& room) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    V3d lo(inf, inf, inf), hi(-inf, -inf, -inf);
    bool any = false;
    for (const Object& o : scene.objects) {
        if (o.room != room || !o.worldMesh) continue;
        for (const V3d& v : o.worldMesh->vertices) {
            lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
            hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
            any = true;
        }
    }
    if (!any) return std::nullopt;
    return std::pair(lo, hi);
}

}  // namespace

TaskAreaRoom taskAreaRoom(const Scene& scene, const TaskArea& area) {
    const V3d c = areaCentre(area);
    for (const Room& room : scene.rooms) {
        if (room.parametric()) {
            if (c.y < room.floorLevel || c.y > room.floorLevel + room.height || !containsPoint(room.outline, V2d(c.x, c.z)))
                continue;
            TaskAreaRoom r;
            r.lo = V3d(room.outline[0].x, room.floorLevel, room.outline[0].y);
            r.hi = V3d(room.outline[0].x, room.floorLevel + room.height, room.outline[0].y);
            for (const V2d& p : room.outline) {
                r.lo = V3d(std::min(r.lo.x, p.x), r.lo.y, std::min(r.lo.z, p.y));
                r.hi = V3d(std::max(r.hi.x, p.x), r.hi.y, std::max(r.hi.z, p.y));
            }
            r.floorLevel = room.floorLevel;
            r.description = "room '" + room.name + "'";
            return r;
        }
        const auto bounds = surfaceBounds(scene, room.name);
        if (!bounds) continue;
        const auto& [lo, hi] = *bounds;
        if (c.x < lo.x || c.x > hi.x || c.y < lo.y || c.y > hi.y || c.z < lo.z || c.z > hi.z) continue;
        return TaskAreaRoom{lo, hi, lo.y, "room '" + room.name + "'"};
    }
    const SceneBounds b = sceneBounds(scene);
    return TaskAreaRoom{b.lo, b.hi, b.lo.y, "the scene's bounds"};
}

CalculationGrid cylindricalGrid(const TaskArea& area, const TaskAreaRoom& room, double metersPerUnit) {
    CalculationGrid grid = area.grid;
    const double heightM = area.standing ? kStandingCylindricalHeightM : kSeatedCylindricalHeightM;
    grid.name = area.grid.name + " (Ez)";
    grid.corner.y = room.floorLevel + heightM / metersPerUnit;
    // Its normal is the cylinder's axis: up, whichever way the area's edges turn.
    if (grid.normal().y < 0) std::swap(grid.edgeU, grid.edgeV);
    return grid;
}

TaskAreaExtrasRequest extrasFor(const ActivityRequirement* requirement) {
    if (!requirement) return {false, false};
    return {requirement->cylindricalLux > 0 || requirement->cylindricalUniformity > 0,
            requirement->wallLux > 0 || requirement->ceilingLux > 0 || requirement->wallUniformity > 0 ||
                requirement->ceilingUniformity > 0};
}

SurfaceIlluminance surfaceIlluminance(const SurfaceFigures& f) {
    SurfaceIlluminance s{f.stats, std::nullopt};
    if (f.errorKnown) s.errors = f.errors;
    return s;
}

TaskAreaExtras computeTaskAreaExtras(const SceneSnapshot& scene, const TaskArea& area, const GridSettings& settings,
                                     const TaskAreaExtrasRequest& request, TaskContext& ctx) {
    TaskAreaExtras out;
    out.room = taskAreaRoom(*scene, area);
    const double cylindricalShare = request.cylindrical ? (request.roomSurfaces ? 1.0 / 3.0 : 1.0) : 0.0;
    if (request.cylindrical && !ctx.isCancelled()) {
        CylindricalFigures c;
        c.grid = cylindricalGrid(area, out.room, scene->metersPerUnit);
        c.layout = layoutGrid(c.grid, scene->metersPerUnit);
        c.heightAboveFloorM = area.standing ? kStandingCylindricalHeightM : kSeatedCylindricalHeightM;
        GridSettings cylindrical = settings;
        cylindrical.quantity = GridQuantity::Cylindrical;
        TaskContext part(ctx.token());
        c.result = computeSceneGrid(scene, c.layout.points, c.grid.normal(), cylindrical, part,
                                    [&](const GridResult&) { ctx.setProgress(cylindricalShare * part.progress()); });
        SurfaceFigures f;
        f.errorKnown = !c.result.errorBarUnknown;
        f.stats = gridStatistics(c.result.lux, c.result.insideGeometry);
        f.errors = gridErrorBars(f.stats, c.result.lux, c.result.errorLux, c.result.insideGeometry);
        c.figures = surfaceIlluminance(f);
        if (!c.result.lux.empty()) out.cylindrical = std::move(c);
    }
    if (request.roomSurfaces && !ctx.isCancelled()) {
        RoomSurfaceResult surfaces =
            computeRoomSurfaces(scene, out.room.lo, out.room.hi, settings, ctx, cylindricalShare, 1 - cylindricalShare);
        if (!surfaces.results.empty()) out.roomSurfaces = std::move(surfaces);
    }
    out.complete = !ctx.isCancelled() && (!request.cylindrical || out.cylindrical) &&
                   (!request.roomSurfaces || (out.roomSurfaces && out.roomSurfaces->complete));
    return out;
}

void addExtras(TaskAreaFigures& figures, const TaskAreaExtras& extras) {
    if (extras.cylindrical) figures.cylindrical = extras.cylindrical->figures;
    if (extras.roomSurfaces) {
        figures.walls = surfaceIlluminance(extras.roomSurfaces->walls);
        if (std::any_of(extras.roomSurfaces->grids.begin(), extras.roomSurfaces->grids.end(),
                        [](const RoomSurfaceGrid& g) { return g.ceiling; }) &&
            extras.roomSurfaces->results.size() == extras.roomSurfaces->grids.size())
            figures.ceiling = surfaceIlluminance(extras.roomSurfaces->ceiling);
    }
}

namespace {

std::string figuresLine(const std::string& what, const SurfaceIlluminance& s, int points) {
    if (s.grid.counted == 0) return what + ": none (every point is inside geometry or glass)";
    std::string line = what + ": Eavg " + fixedNumber(s.grid.average, 1) + " lx";
    if (s.errors) line += " +- " + fixedNumber(s.errors->average, 1) + " lx";
    line += ", Emin " + fixedNumber(s.grid.minimum, 1) + " lx, U0 " + fixedNumber(s.grid.uniformity, 2);
    if (s.errors) line += " +- " + fixedNumber(s.errors->uniformity, 2);
    if (!s.errors) line += " (error bar unknown)";
    return line + " (" + std::to_string(points) + " points)";
}

}  // namespace

std::vector<std::string> describeExtras(const TaskAreaExtras& extras, const std::optional<GridStatistics>& horizontal) {
    std::vector<std::string> lines;
    if (extras.cylindrical) {
        const CylindricalFigures& c = *extras.cylindrical;
        lines.push_back(figuresLine("Ez at " + fixedNumber(c.heightAboveFloorM, 2) + " m above the floor (" +
                                        (c.heightAboveFloorM == kStandingCylindricalHeightM ? "standing" : "seated") +
                                        ", floor of " + extras.room.description + ")",
                                    c.figures, c.figures.grid.counted));
        if (horizontal && horizontal->average > 0 && c.figures.grid.counted > 0)
            lines.push_back(describeModelling(c.figures.grid.average / horizontal->average));
    }
    if (extras.roomSurfaces) {
        const RoomSurfaceResult& r = *extras.roomSurfaces;
        lines.push_back(figuresLine("walls of " + extras.room.description, surfaceIlluminance(r.walls), r.walls.points));
        if (r.results.size() == r.grids.size())
            lines.push_back(figuresLine("ceiling of " + extras.room.description, surfaceIlluminance(r.ceiling),
                                        r.ceiling.points));
        if (!r.complete) lines.push_back("room surfaces: cancelled before every grid was computed");
    }
    return lines;
}

}  // namespace lucerna
