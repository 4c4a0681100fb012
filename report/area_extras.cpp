#include "report/area_extras.h"

#include "core/photometry/grid_error_bars.h"

#include <stdexcept>

namespace lucerna {

namespace {

bool sameBox(const TaskAreaRoom& a, const TaskAreaRoom& b) { return a.lo == b.lo && a.hi == b.hi; }

// Elements [begin, end) of a per-point vector (empty stays empty).
template <class T> std::vector<T> slice(const std::vector<T>& v, size_t begin, size_t end) {
    if (v.size() < end) return {};
    return std::vector<T>(v.begin() + std::ptrdiff_t(begin), v.begin() + std::ptrdiff_t(end));
}

}  // namespace

void planAreaExtras(const Scene& scene, const TaskArea& area, const ReportSettings& settings, AreaReport& report,
                    std::vector<RoomSurfacesReport>& rooms) {
    report.room = taskAreaRoom(scene, area);
    if (extrasFor(report.requirement).roomSurfaces) {
        size_t k = 0;
        while (k < rooms.size() && !sameBox(rooms[k].room, report.room)) ++k;
        if (k == rooms.size()) {
            RoomSurfacesReport r;
            r.room = report.room;
            r.settings = settings.grid;
            if (settings.roomSurfaceErrorFactor > 0) r.settings.targetRelativeError *= settings.roomSurfaceErrorFactor;
            rooms.push_back(std::move(r));
        }
        rooms[k].areas.push_back(report.name);
        report.roomSurfaces = k;
    }
    TaskAreaZones zones;
    try {
        zones = taskAreaZones(area, scene.metersPerUnit, report.room.lo, report.room.hi);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("task area '" + area.grid.name + "': " + e.what());
    }
    std::optional<ZoneRequirement> surrounding;
    if (report.requirement) surrounding = surroundingZoneRequirement(report.requirement->maintainedLux);
    if (zones.surrounding)
        report.zones.push_back({"surrounding zone", *area.surroundingMeters, std::move(*zones.surrounding), {}, {},
                                surrounding, {}});
    if (zones.background)
        report.zones.push_back({"background area", *area.backgroundMeters, std::move(*zones.background), {}, {},
                                surrounding ? std::optional(backgroundAreaRequirement(surrounding->maintainedLux))
                                            : std::nullopt,
                                {}});
}

bool wantsCylindrical(const AreaReport& report) { return extrasFor(report.requirement).cylindrical; }

void computeCylindrical(const SceneSnapshot& scene, const TaskArea& area, const ReportSettings& settings,
                        AreaReport& report, TaskContext& ctx) {
    GridSettings grid = settings.grid;
    if (settings.cylindricalErrorFactor > 0) grid.targetRelativeError *= settings.cylindricalErrorFactor;
    TaskAreaExtras extras = computeTaskAreaExtras(scene, area, grid, {true, false}, ctx);
    if (!ctx.isCancelled()) report.cylindrical = std::move(extras.cylindrical);
}

void computeWallsAndCeiling(const SceneSnapshot& scene, const TaskArea& area, RoomSurfacesReport& room,
                            TaskContext& ctx) {
    TaskAreaExtras extras = computeTaskAreaExtras(scene, area, room.settings, {false, true}, ctx);
    if (extras.roomSurfaces) room.result = std::move(*extras.roomSurfaces);
}

void computeZones(const SceneSnapshot& scene, const ReportSettings& settings, bool maintainedValues,
                  AreaReport& report, TaskContext& ctx) {
    std::vector<V3d> points;
    std::vector<size_t> begin;
    for (const ZoneReport& z : report.zones) {
        begin.push_back(points.size());
        points.insert(points.end(), z.grid.points.begin(), z.grid.points.end());
    }
    if (points.empty()) return;
    const GridResult all = computeSceneGrid(scene, points, report.grid.normal(), settings.grid, ctx);
    if (ctx.isCancelled()) return;
    for (size_t k = 0; k < report.zones.size(); ++k) {
        ZoneReport& z = report.zones[k];
        const size_t b = begin[k], e = b + z.grid.points.size();
        z.result = all;
        z.result.lux = slice(all.lux, b, e);
        z.result.errorLux = slice(all.errorLux, b, e);
        z.result.insideGeometry = slice(all.insideGeometry, b, e);
        z.statistics = gridStatistics(z.result.lux, z.result.insideGeometry);
        if (!z.requirement || z.statistics.counted == 0) continue;
        TaskAreaFigures f;
        f.grid = z.statistics;
        if (!z.result.errorBarUnknown)
            f.gridErrors = gridErrorBars(z.statistics, z.result.lux, z.result.errorLux, z.result.insideGeometry);
        f.maintainedValues = maintainedValues;
        z.checks = checkZone(*z.requirement, f);
    }
}

void checkArea(AreaReport& r, const std::vector<RoomSurfacesReport>& rooms, bool maintainedValues) {
    TaskAreaFigures& f = r.figures;
    f.grid = r.statistics;
    if (!r.result.errorBarUnknown) f.gridErrors = gridErrorBars(r.statistics, r.result.lux, r.result.errorLux, r.result.insideGeometry);
    f.worstUgr = r.worstUgr;
    f.worstUgrError = r.worstUgrError;
    f.colourRendering = r.colourRendering;
    f.maintainedValues = maintainedValues;
    if (r.cylindrical) f.cylindrical = r.cylindrical->figures;
    if (r.roomSurfaces && *r.roomSurfaces < rooms.size()) {
        const RoomSurfaceResult& s = rooms[*r.roomSurfaces].result;
        if (!s.results.empty()) f.walls = surfaceIlluminance(s.walls);
        if (s.complete) f.ceiling = surfaceIlluminance(s.ceiling);
    }
    r.modellingRatio = modellingRatio(f);
    if (r.requirement) r.checks = checkRequirements(*r.requirement, f);
}

void addRoomIlluminance(RoomsSummary& summary, const std::vector<RoomSurfacesReport>& rooms) {
    for (RoomEntry& e : summary.rooms)
        for (const RoomSurfacesReport& r : rooms) {
            if (r.room.description != "room '" + e.name + "'" || r.result.results.empty()) continue;
            e.walls = surfaceIlluminance(r.result.walls);
            if (r.result.complete) e.ceiling = surfaceIlluminance(r.result.ceiling);
        }
}

}  // namespace lucerna
