#include "report/report_builder.h"

#include "render/annual/annual_calculation.h"

#include "core/daylight/daylight.h"
#include "core/photometry/glare.h"
#include "core/scene/scene_geometry.h"
#include "render/backend/pass_loop.h"
#include "render/display/false_colour.h"
#include "render/engine/backend_table.h"
#include "render/trace/surface_layers.h"
#include "report/area_extras.h"
#include "report/luminaire_data_sheet.h"
#include "report/luminaire_schedule.h"
#include "report/room_summary.h"

#include <QDate>
#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace lucerna {

namespace {

constexpr double kWorkPlaneM = 0.8, kBorderM = 0.5;  // EN 12464-1's usual work plane

// A stage of the report as a share of its progress: a context of its own (the parent's token,
// so that a cancel reaches it) whose progress is copied into [base, base + share] of the
// parent's while the stage runs, by a thread that looks every 50 ms (the grid, the pass loop and
// the lux view each set their own context's progress, and not all of them call back).
class Stage {
public:
    Stage(TaskContext& parent, double base, double share)
        : parent_(parent), own_(parent.token()), base_(base), share_(share), watcher_([this] { watch(); }) {}
    ~Stage() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
        }
        wake_.notify_all();
        watcher_.join();
        parent_.setProgress(base_ + share_);
    }
    TaskContext& context() { return own_; }

private:
    void watch() {
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return done_; }))
            parent_.setProgress(base_ + share_ * std::clamp(own_.progress(), 0.0, 1.0));
    }

    TaskContext& parent_;
    TaskContext own_;
    double base_, share_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread watcher_;
};

void computeGlare(const Scene& scene, const TaskArea& area, const ReportSettings& settings, AreaReport& out,
                  TaskContext& ctx) {
    std::vector<GlareObserver> observers = area.observers;
    const bool defaults = observers.empty();
    if (defaults)
        observers = defaultObservers(area, sceneBounds(scene).lo.y, scene.metersPerUnit, settings.eyeHeightM);
    GlareSettings glare;
    glare.backgroundMethod = settings.grid.autoMethod ? GridMethod::Path : settings.grid.method;
    glare.targetRelativeError = std::max(settings.grid.targetRelativeError, GlareSettings().targetRelativeError);
    glare.timeLimitSeconds = settings.grid.timeLimitSeconds;
    glare.seed = settings.grid.seed;
    glare.samplesPerPass = settings.grid.samplesPerPass;
    for (size_t i = 0; i < observers.size() && !ctx.isCancelled(); ++i) {
        ObserverGlare o{observers[i], defaults, evaluateGlare(scene, observers[i], glare, ctx)};
        ctx.setProgress(double(i + 1) / double(observers.size()));
        if (o.result.ugr && (!out.worstUgr || *o.result.ugr > *out.worstUgr)) {
            out.worstUgr = *o.result.ugr;
            out.worstUgrError = o.result.ugrErrorBar;
        }
        out.glare.push_back(std::move(o));
    }
    // The worst UGR only when every observer has one: a missing one might be the worst.
    for (const ObserverGlare& o : out.glare)
        if (!o.result.ugr) out.worstUgr.reset();
}

// The daylight factor on an area: its grid in the daylight-factor scene, by the same settings.
DaylightFactorReport computeDaylightFactor(const Scene& scene, const AreaReport& area, const ReportSettings& settings,
                                           TaskContext& ctx) {
    DaylightFactorReport df;
    DaylightFactorScene dfScene = daylightFactorScene(scene);
    df.skyHorizontalIlluminance = dfScene.skyHorizontalIlluminance;
    if (scene.site && scene.site->medianDiffuseIlluminance)
        df.medianDiffuseIlluminance = *scene.site->medianDiffuseIlluminance, df.medianGiven = true;
    const SceneSnapshot snapshot = std::make_shared<const Scene>(std::move(dfScene.scene));
    df.result = computeSceneGrid(snapshot, area.layout.points, area.grid.normal(), settings.grid, ctx);
    if (ctx.isCancelled() || !(df.skyHorizontalIlluminance > 0)) return df;
    df.percent.resize(df.result.lux.size());
    for (size_t i = 0; i < df.percent.size(); ++i) df.percent[i] = df.result.lux[i] * 100.0 / df.skyHorizontalIlluminance;
    df.statistics = gridStatistics(df.percent, df.result.insideGeometry);
    if (df.statistics.counted > 0)
        df.provision = checkDaylightProvision(df.percent, df.result.insideGeometry, df.medianDiffuseIlluminance);
    return df;
}

// The exposure (stops) that takes the image's log-average luminance to mid grey (0.18), as a
// photographer's meter would, within +-6 stops: an office at 500 lx and a sunlit room both read.
float meteredExposure(const Image& image) {
    double sum = 0;
    size_t n = 0;
    for (const Rgb& p : image.pixels) {
        const double y = luminance(p);
        if (std::isfinite(y) && y > 0) sum += std::log(y), ++n;
    }
    if (n == 0) return 0;
    return float(std::clamp(std::log2(0.18 / std::exp(sum / double(n))), -6.0, 6.0));
}

// The converged render of the camera by auto (a measured combination of the backends), of the
// scene as rendered.
ReportRenders renderCamera(const SceneSnapshot& scene, const ReportSettings& settings, TaskContext& ctx) {
    ReportRenders r;
    const BackendInfo* info = findBackend("auto");
    r.backend = "auto";
    RenderSettings rs;
    rs.spp = settings.renderSpp;
    rs.seed = settings.grid.seed;
    const std::unique_ptr<Backend> backend = info->make(sceneAsRendered(scene), rs);
    backend->prepare(ctx);
    if (ctx.isCancelled()) return r;
    // Stop at the error target. The estimate (a 5 x 5 neighbourhood per pixel, on one thread)
    // costs a fraction of a pass, so it is read every 8 passes (an even count: both halves of the
    // film alike), from 16 on, where it has settled.
    PassLoopOptions options;
    bool reached = false;
    if (settings.renderRelmse > 0) {
        options.afterPass = [&](int passes) {
            if (passes >= 16 && passes % 8 == 0) reached = backend->estimatedRelmse() <= settings.renderRelmse;
        };
        options.finishEarly = [&] { return reached; };
    }
    RenderFrame frame = runPasses(*backend, r.backend, rs, ctx, nullptr, options);
    // What auto measured and decided (render/engine/measured_auto/), for the method page.
    if (const auto it = frame.image.attributes.find("lucerna:auto"); it != frame.image.attributes.end()) r.autoReason = it->second;
    r.passes = frame.passes;
    r.samplesPerPixel = frame.samplesPerPixel;
    r.seconds = frame.seconds;
    r.estimatedRelmse = frame.estimatedRelmse;
    r.converged = std::move(frame.image);
    r.exposureStops = meteredExposure(r.converged);
    return r;
}

// Its lux view: E = pi L / albedo at the first surface each pixel sees, from the converged
// render's radiance and the albedo layer (render/display/display.h, pixelIlluminance), as the
// window's lux view reads a render: as smooth as the render itself (a per-pixel illuminance
// estimate at a sixteenth of the render's work is grainy), exact on matte surfaces under white
// light, approximate under coloured light on coloured surfaces; and the false-colour range.
void addLuxView(const SceneSnapshot& scene, ReportRenders& r) {
    addSurfaceLayers(r.converged, sceneAsRendered(scene), kAlbedoLayer);
    if (const auto range = illuminanceRange(r.converged)) r.luxLo = range->lo, r.luxHi = range->hi;
}

}  // namespace

std::vector<ReportArea> reportAreas(const Scene& scene) {
    std::vector<ReportArea> areas;
    for (const TaskArea& a : scene.taskAreas) areas.push_back({a, false});
    if (!areas.empty()) return areas;
    const SceneBounds b = sceneBounds(scene);
    ReportArea plane;
    try {
        plane.area.grid = workPlaneGrid(b.lo, b.hi, scene.metersPerUnit, kWorkPlaneM, kBorderM);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("the scene names no task areas, and its work plane (0.8 m up, less a "
                                                "0.5 m border) is empty: ") + e.what());
    }
    plane.area.grid.name = "Work plane";
    plane.defaultWorkPlane = true;
    areas.push_back(plane);
    return areas;
}

void checkReportInput(const Scene& scene, const ReportSettings& settings) {
    std::vector<RoomSurfacesReport> rooms;
    for (const ReportArea& a : reportAreas(scene)) {
        layoutGrid(a.area.grid, scene.metersPerUnit);
        if (!a.area.activity.empty() && !findActivity(a.area.activity, lightingStandardOf(scene)))
            throw std::invalid_argument("task area '" + a.area.grid.name + "': unknown activity " + a.area.activity);
        AreaReport r;
        r.name = a.area.grid.name;
        if (!a.area.activity.empty()) r.requirement = findActivity(a.area.activity, lightingStandardOf(scene));
        planAreaExtras(scene, a.area, settings, r, rooms);
    }
}

namespace {

// SPEC.md section 6 on the area's own points, as `lucerna annual --task-area` computes them.
AnnualReport computeAnnualReport(const Scene& scene, const AreaReport& r, const ReportSettings& settings, TaskContext& ctx) {
    const AnnualResult year = computeAnnual(scene, r.layout.points, r.grid.normal(), *settings.weather, AnnualSettings(), ctx);
    AnnualReport a;
    if (year.cancelled) return a;
    std::vector<uint8_t> counted(year.points);
    for (size_t p = 0; p < counted.size(); ++p) counted[p] = !year.insideGeometry[p];
    a.metrics = computeAnnualMetrics(year.hours, year.points, year.lux, year.directSunLux, settings.occupancy, counted);
    a.daylightHours = year.daylightHours;
    a.statisticalRelative = year.statisticalRelative;
    a.discretisationRelative = year.discretisationRelative;
    a.seconds = year.tracingSeconds + year.hoursSeconds;
    for (const PointAnnualMetrics& p : a.metrics.points) a.da300Percent.push_back(100 * p.da300);
    a.insideGeometry = year.insideGeometry;
    return a;
}

}  // namespace

ReportData buildReport(const SceneSnapshot& scene, const std::string& scenePath, const ReportSettings& settings,
                       TaskContext& ctx) {
    const auto start = std::chrono::steady_clock::now();
    ReportData data;
    data.scene = scene;
    data.settings = settings;
    data.sceneFile = scenePath.empty() ? "untitled scene" : QFileInfo(QString::fromStdString(scenePath)).fileName().toStdString();
    if (scene->project) {
        data.projectName = scene->project->name;
        data.client = scene->project->client;
        data.designer = scene->project->designer;
        data.notes = scene->project->notes;
    }
    if (data.projectName.empty()) data.projectName = QFileInfo(QString::fromStdString(scenePath)).completeBaseName().toStdString();
    if (data.projectName.empty()) data.projectName = "Untitled";
    data.date = QDate::currentDate().toString(Qt::ISODate).toStdString();
    data.software = "Lucerna " LUCERNA_VERSION;
    data.maintenance = maintenanceStatement(*scene);
    data.schedule = luminaireSchedule(*scene);
    data.dataSheets = luminaireDataSheets(*scene, data.schedule);
    // A scene with rooms (README, "Rooms") is summarised room by room there, not as one extent.
    if (scene->rooms.empty()) data.room = roomSummary(*scene, data.schedule);
    else data.rooms = roomsSummary(*scene);
    data.energy = sceneEnergy(*scene);

    // Everything that can fail on bad input, before any work.
    checkReportInput(*scene, settings);
    const std::vector<ReportArea> areas = reportAreas(*scene);
    const bool maintainedValues = valuesAreMaintained(maintenanceRange(*scene));
    for (const ReportArea& a : areas) {
        AreaReport r;
        r.name = a.area.grid.name;
        r.defaultWorkPlane = a.defaultWorkPlane;
        r.grid = a.area.grid;
        r.layout = layoutGrid(a.area.grid, scene->metersPerUnit);
        if (!a.area.activity.empty()) r.requirement = findActivity(a.area.activity, lightingStandardOf(*scene));
        r.colourRendering = statedColourRendering(*scene);
        planAreaExtras(*scene, a.area, settings, r, data.roomSurfaces);
        data.areas.push_back(std::move(r));
    }

    // Shares of the progress: a grid 1, an area's glare 0.5, its daylight factor 1, its Ez 1 and
    // its zones 0.5, a room's walls and ceiling 1 (five small grids, once per room box), the
    // render 2.
    const bool daylightFactor = settings.daylightFactor && analyseFeatures(*scene).hasDaylight();
    const double glareShare = settings.glare ? 0.5 : 0.0, dfShare = daylightFactor ? 1.0 : 0.0;
    const double renderShare = settings.renders ? 2.0 : 0.0, zoneShare = 0.5, annualShare = settings.weather ? 1.0 : 0.0;
    double total = double(areas.size()) * (1 + glareShare + dfShare + annualShare) + renderShare + double(data.roomSurfaces.size());
    for (const AreaReport& r : data.areas) total += (wantsCylindrical(r) ? 1.0 : 0.0) + (r.zones.empty() ? 0.0 : zoneShare);
    double done = 0;
    const auto stage = [&](double share) {
        const double base = done / total;
        done += share;
        return std::make_unique<Stage>(ctx, base, share / total);
    };
    std::vector<bool> roomDone(data.roomSurfaces.size(), false);
    for (size_t i = 0; i < areas.size(); ++i) {
        AreaReport& r = data.areas[i];
        {
            auto s = stage(1.0);
            r.result = computeSceneGrid(scene, r.layout.points, r.grid.normal(), settings.grid, s->context());
        }
        if (ctx.isCancelled()) return data;
        r.statistics = gridStatistics(r.result.lux, r.result.insideGeometry);
        if (settings.glare && data.schedule.luminaires > 0) {  // UGR rates electric lighting
            auto s = stage(glareShare);
            computeGlare(*scene, areas[i].area, settings, r, s->context());
            if (ctx.isCancelled()) return data;
        }
        if (wantsCylindrical(r)) {
            {
                auto s = stage(1.0);
                computeCylindrical(scene, areas[i].area, settings, r, s->context());
            }
            if (ctx.isCancelled()) return data;
        }
        if (r.roomSurfaces && !roomDone[*r.roomSurfaces]) {
            {
                auto s = stage(1.0);
                computeWallsAndCeiling(scene, areas[i].area, data.roomSurfaces[*r.roomSurfaces], s->context());
            }
            if (ctx.isCancelled()) return data;
            roomDone[*r.roomSurfaces] = true;
        }
        if (!r.zones.empty()) {
            {
                auto s = stage(zoneShare);
                computeZones(scene, settings, maintainedValues, r, s->context());
            }
            if (ctx.isCancelled()) return data;
        }
        checkArea(r, data.roomSurfaces, maintainedValues);
        if (daylightFactor) {
            DaylightFactorReport df;
            {
                auto s = stage(dfShare);
                df = computeDaylightFactor(*scene, r, settings, s->context());
            }
            if (ctx.isCancelled()) return data;
            r.daylightFactor = std::move(df);
        }
        if (settings.weather) {
            auto s = stage(annualShare);
            r.annual = computeAnnualReport(*scene, r, settings, s->context());
            if (ctx.isCancelled()) return data;
        }
    }
    if (data.rooms) addRoomIlluminance(*data.rooms, data.roomSurfaces);
    if (settings.renders) {
        ReportRenders renders;
        {
            auto s = stage(renderShare);
            renders = renderCamera(scene, settings, s->context());
        }
        if (ctx.isCancelled()) return data;
        addLuxView(scene, renders);
        data.renders = std::move(renders);
    }
    data.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ctx.setProgress(1);
    return data;
}

}  // namespace lucerna
