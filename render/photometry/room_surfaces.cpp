#include "render/photometry/room_surfaces.h"

#include "render/photometry/grid_statistics.h"

#include <algorithm>
#include <chrono>

namespace lucerna {

namespace {

// The box's faces as grids (facingInto turns them into the room).
std::vector<std::pair<std::string, CalculationGrid>> boxFaces(const V3d& lo, const V3d& hi) {
    const V3d size = hi - lo;
    auto face = [](const V3d& corner, const V3d& u, const V3d& v) {
        CalculationGrid g;
        g.corner = corner;
        g.edgeU = u;
        g.edgeV = v;
        return g;
    };
    const V3d x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
    return {
        {"wall 1", face(lo, z, y)},                      // x = lo
        {"wall 2", face(V3d(hi.x, lo.y, lo.z), z, y)},  // x = hi
        {"wall 3", face(lo, x, y)},                      // z = lo
        {"wall 4", face(V3d(lo.x, lo.y, hi.z), x, y)},  // z = hi
        {"ceiling", face(V3d(lo.x, hi.y, lo.z), x, z)}, // y = hi
    };
}

// The grid facing into the box: its normal turned toward the box's centre if it points out.
CalculationGrid facingInto(CalculationGrid g, const V3d& centre) {
    const V3d middle = g.corner + 0.5 * (g.edgeU + g.edgeV);
    if (g.normal().dot(centre - middle) < 0) std::swap(g.edgeU, g.edgeV);
    return g;
}

}  // namespace

std::vector<RoomSurfaceGrid> roomSurfaceGrids(const RenderScene& scene, const V3d& lo, const V3d& hi,
                                              double metersPerUnit) {
    const V3d centre = 0.5 * (lo + hi);
    const double depth = kSurfaceDepthMeters / metersPerUnit;
    const double standOff = std::max(0.01 / metersPerUnit, 3e-4 * double(scene.boundsRadius()));
    std::vector<RoomSurfaceGrid> grids;
    for (auto& [name, face] : boxFaces(lo, hi)) {
        RoomSurfaceGrid s;
        s.name = name;
        s.ceiling = name == "ceiling";
        s.grid = facingInto(face, centre);
        s.grid.name = name;
        s.layout = layoutGrid(s.grid, metersPerUnit);
        s.cellAreaM2 = s.layout.spacingUMeters * s.layout.spacingVMeters;
        const V3d n = s.grid.normal();
        // From inside the room toward the face: a ray from depth in front of each point.
        const double inward = std::min(depth, 0.5 * std::abs((hi - lo).dot(n)));
        for (const V3d& p : s.layout.points) {
            const V3d origin = p + n * inward;
            float t = 0;
            Rgb panes(1, 1, 1);
            const Ray ray{toFloat(origin), toFloat(-n), 0.0f, float(inward + standOff)};
            const std::optional<SurfacePoint> hit = scene.intersect(ray, &t, &panes);
            const bool glass = hit && scene.material(hit->material).type == MaterialType::Dielectric;
            // A pane crossed before the surface is a window (a pane that lets everything through
            // cannot be told from air); nothing within reach is an opening or no wall at all.
            const bool throughPane = std::max({panes.x, panes.y, panes.z}) < 1.0f;
            const V3d surface = hit ? origin - n * double(t) : p;
            s.points.push_back(surface + n * standOff);
            s.opening.push_back(glass || throughPane || !hit ? 1 : 0);
        }
        grids.push_back(std::move(s));
    }
    return grids;
}

SurfaceFigures combinedSurfaceFigures(const std::vector<const RoomSurfaceGrid*>& grids,
                                      const std::vector<const GridResult*>& results) {
    std::vector<double> lux, errors, weights;
    std::vector<uint8_t> excluded;
    SurfaceFigures f;
    for (size_t g = 0; g < grids.size() && g < results.size(); ++g) {
        const RoomSurfaceGrid& grid = *grids[g];
        const GridResult& r = *results[g];
        f.errorKnown = f.errorKnown && !r.errorBarUnknown;
        for (size_t i = 0; i < grid.points.size() && i < r.lux.size(); ++i) {
            lux.push_back(r.lux[i]);
            errors.push_back(r.errorLux[i]);
            weights.push_back(grid.cellAreaM2);
            excluded.push_back((i < r.insideGeometry.size() && r.insideGeometry[i]) || grid.opening[i] ? 1 : 0);
        }
    }
    f.stats = gridStatistics(lux, excluded, weights);
    f.errors = gridErrorBars(f.stats, lux, errors, excluded, weights);
    f.points = f.stats.counted;
    f.leftOut = f.stats.excluded;
    return f;
}

RoomSurfaceResult computeRoomSurfaces(const SceneSnapshot& scene, const V3d& lo, const V3d& hi,
                                      const GridSettings& requested, TaskContext& ctx, double progressBase,
                                      double progressShare) {
    const auto start = std::chrono::steady_clock::now();
    GridSettings settings = requested;
    settings.quantity = GridQuantity::Planar;
    const RenderScene renderScene(sceneAsRendered(scene), 16, 16, nullptr, settings.lightSelection);
    RoomSurfaceResult out;
    out.grids = roomSurfaceGrids(renderScene, lo, hi, scene->metersPerUnit);
    const double count = double(out.grids.size());
    for (size_t g = 0; g < out.grids.size() && !ctx.isCancelled(); ++g) {
        TaskContext part(ctx.token());
        out.results.push_back(computeGridIlluminance(renderScene, out.grids[g].points, out.grids[g].grid.normal(),
                                                     settings, part, [&](const GridResult&) {
                                                         ctx.setProgress(progressBase + progressShare * (double(g) + part.progress()) / count);
                                                     }));
    }
    out.complete = out.results.size() == out.grids.size() && !ctx.isCancelled();
    std::vector<const RoomSurfaceGrid*> walls;
    std::vector<const GridResult*> wallResults;
    for (size_t g = 0; g < out.results.size(); ++g) {
        if (out.grids[g].ceiling) {
            out.ceiling = combinedSurfaceFigures({&out.grids[g]}, {&out.results[g]});
        } else {
            walls.push_back(&out.grids[g]);
            wallResults.push_back(&out.results[g]);
        }
    }
    out.walls = combinedSurfaceFigures(walls, wallResults);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace lucerna
