#include "app/grid_command.h"

#include "app/grid_placement.h"
#include "app/cli_support.h"
#include "app/grid_task_area.h"

#include "core/atomic_file.h"
#include "core/photometry/calculation_grid.h"
#include "core/daylight/daylight.h"
#include "core/daylight/daylight_provision.h"
#include "core/photometry/lighting_standards.h"
#include "core/process_group.h"
#include "core/scene/scene_geometry.h"
#include "core/scene/scene_io.h"
#include "render/backend/backend_options.h"
#include "render/engine/backend_table.h"
#include "render/photometry/grid_calculation.h"
#include "render/photometry/grid_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <span>

namespace lucerna::cli {

namespace {

struct GridArgs {
    std::string scene, csv;
    CalculationGrid grid;
    std::optional<double> workPlaneM;  // height above the lowest geometry, metres
    double borderM = 0.5;              // EN 12464-1: the band along the walls left out
    bool corner = false, u = false, v = false;
    GridSettings settings;
    int threads = 0;
    bool daylightFactor = false;                    // SPEC.md section 5's DF instead of lux
    std::optional<double> medianDiffuseIlluminance; // lx, EN 17037's site value
    std::string taskArea;                           // the scene's task area (README, "Task areas")
    // --cylindrical: with a task area, Ez over it whatever its activity asks; else the grid's
    // points measure Ez. --room-surfaces: the walls and ceiling whatever it asks.
    // --horizontal-only: neither, whatever it asks.
    bool cylindrical = false, roomSurfaces = false, horizontalOnly = false;
};

GridArgs parseGridArgs(const std::vector<std::string>& args) {
    GridArgs g;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "--work-plane") g.workPlaneM = parseNumber<double>(a, value(), -1e6, 1e6);
        else if (a == "--border") g.borderM = parseNumber<double>(a, value(), 0.0, 1e6);
        else if (a == "--corner") g.grid.corner = parseVector(a, value()), g.corner = true;
        else if (a == "--u") g.grid.edgeU = parseVector(a, value()), g.u = true;
        else if (a == "--v") g.grid.edgeV = parseVector(a, value()), g.v = true;
        else if (a == "--spacing") g.grid.spacingMeters = parseNumber<double>(a, value(), 1e-6, 1e6);
        else if (a == "--name") g.grid.name = value();
        else if (a == "--method") {
            const auto method = parseGridMethod(value(), true);
            g.settings.autoMethod = !method;
            if (method) g.settings.method = *method;
        } else if (a == "--error") g.settings.targetRelativeError = parseNumber<double>(a, value(), 1e-6, 1.0);
        else if (a == "--time") g.settings.timeLimitSeconds = parseNumber<double>(a, value(), 1e-3, 1e7);
        else if (a == "--seed") g.settings.seed = parseNumber<uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--samples") g.settings.samplesPerPass = parseNumber<int>(a, value(), 1, 1 << 20);
        else if (a == "--option") addBackendOption(value(), g.settings.backendOptions);
        else if (a == "--replicas") g.settings.replicas = parseNumber<int>(a, value(), 2, 1024);
        else if (a == "--vpl-paths") g.settings.vplPathsPerPass = parseNumber<int>(a, value(), 1, 1 << 24);
        else if (a == "--threads") g.threads = parseNumber<int>(a, value(), 1, 4096);
        else if (a == "--csv") g.csv = value();
        else if (a == "--daylight-factor") g.daylightFactor = true;
        else if (a == "--cylindrical") g.cylindrical = true;
        else if (a == "--room-surfaces") g.roomSurfaces = true;
        else if (a == "--horizontal-only") g.horizontalOnly = true;
        else if (a == "--task-area") {
            g.taskArea = value();
            if (g.taskArea.empty()) throw UsageError("--task-area: the name is empty");
        }
        else if (a == "--median-diffuse-illuminance")
            g.medianDiffuseIlluminance = parseNumber<double>(a, value(), 1.0, 200000.0);
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (g.scene.empty()) g.scene = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (g.scene.empty()) throw UsageError("grid: no scene file given");
    const bool rectangle = g.corner || g.u || g.v;
    if (int(rectangle) + int(g.workPlaneM.has_value()) + int(!g.taskArea.empty()) != 1)
        throw UsageError("grid: give one of --work-plane HEIGHT, --corner, --u and --v, or --task-area NAME");
    if (!g.taskArea.empty() && g.daylightFactor)
        throw UsageError("--task-area: not with --daylight-factor (a task area is checked in lux; give its rectangle)");
    if (rectangle && !(g.corner && g.u && g.v)) throw UsageError("grid: --corner, --u and --v go together");
    if (g.taskArea.empty() && (g.roomSurfaces || g.horizontalOnly))
        throw UsageError(std::string(g.roomSurfaces ? "--room-surfaces" : "--horizontal-only") +
                         ": only with --task-area NAME (the room is the task area's)");
    if (g.horizontalOnly && (g.cylindrical || g.roomSurfaces))
        throw UsageError("--horizontal-only: not with --cylindrical or --room-surfaces");
    if (g.cylindrical && g.daylightFactor)
        throw UsageError("--cylindrical: not with --daylight-factor (the daylight factor is on a plane)");
    if (g.cylindrical && g.taskArea.empty()) g.settings.quantity = GridQuantity::Cylindrical;
    if (g.medianDiffuseIlluminance && !g.daylightFactor)
        throw UsageError("--median-diffuse-illuminance: only with --daylight-factor");
    return g;
}

// Lines of render/photometry/grid_text.h, each on its own.
void printLines(const std::vector<std::string>& lines) {
    for (const std::string& line : lines) std::printf("%s\n", line.c_str());
}

// What a grid needs once its arguments and scene are known.
struct GridSetup {
    GridArgs g;
    SceneSnapshot scene;             // with --daylight-factor, the daylight-factor scene
    GridLayout layout;
    double skyHorizontalIlluminance = 0;  // --daylight-factor: Eh,sky, lx
    double medianDiffuseIlluminance = kDefaultMedianDiffuseIlluminance;
    bool medianGiven = false;        // by the option or the site (else EN 17037's usual value)
    const ActivityRequirement* requirement = nullptr;  // --task-area with an activity
    std::optional<TaskArea> area;    // --task-area: the area, with --spacing's spacing when given
    ZoneGrids zones;                 // its zones, whose points go after the grid's
};

// Everything that can fail on bad input before any work; of a distributed grid, every rank does
// it, and rank 0 alone checks the CSV's path (it alone writes).
GridSetup setUpGrid(const std::vector<std::string>& args, const ProcessGroup* processes) {
    GridArgs g = parseGridArgs(args);
    if (!g.csv.empty() && rankOf(processes) == 0) checkOutputPath(g.csv);
    Scene loaded;
    try {
        loaded = loadScene(g.scene);
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
    double skyEh = 0, median = kDefaultMedianDiffuseIlluminance;
    bool medianGiven = false;
    if (g.daylightFactor) {
        // SPEC.md section 5: the CIE overcast sky alone, everything electric off.
        if (g.medianDiffuseIlluminance) median = *g.medianDiffuseIlluminance, medianGiven = true;
        else if (loaded.site && loaded.site->medianDiffuseIlluminance)
            median = *loaded.site->medianDiffuseIlluminance, medianGiven = true;
        DaylightFactorScene df = daylightFactorScene(loaded);
        if (!(df.skyHorizontalIlluminance > 0))
            throw UsageError("grid: --daylight-factor: the sky gives no light (its quantity is 0)");
        skyEh = df.skyHorizontalIlluminance;
        loaded = std::move(df.scene);
    }
    const SceneSnapshot scene = std::make_shared<const Scene>(std::move(loaded));
    const ActivityRequirement* requirement = nullptr;
    std::optional<TaskArea> taskArea;
    if (!g.taskArea.empty()) {
        const TaskArea* area = &taskAreaOf(*scene, g.taskArea);
        const auto spacing = g.grid.spacingMeters;
        g.grid = area->grid;
        if (spacing) g.grid.spacingMeters = spacing;
        if (!area->activity.empty()) requirement = findActivity(area->activity, lightingStandardOf(*scene));
        taskArea = *area;
        taskArea->grid.spacingMeters = g.grid.spacingMeters;
    }
    if (g.workPlaneM) g.grid = workPlaneGridOf(*scene, *g.workPlaneM, g.borderM, g.grid.spacingMeters, g.grid.name);
    GridLayout layout;
    try {
        layout = layoutGrid(g.grid, scene->metersPerUnit);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    ZoneGrids zones;
    if (taskArea) {
        try {
            const TaskAreaRoom room = taskAreaRoom(*scene, *taskArea);
            zones = ZoneGrids(*taskArea, requirement, scene->metersPerUnit, room.lo, room.hi, layout.points.size());
        } catch (const std::invalid_argument& e) {
            throw UsageError("--task-area: " + std::string(e.what()));
        }
    }

    // light_sampler is every tracing method's, the estimators of path and ir included.
    try {
        RenderSettings check;
        check.options = g.settings.backendOptions;
        g.settings.lightSelection = lightSelectionOption(check);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const bool onlyLightSampler =
        g.settings.backendOptions.empty() ||
        (g.settings.backendOptions.size() == 1 && g.settings.backendOptions.contains("light_sampler"));
    if (g.settings.autoMethod) {
        if (!onlyLightSampler)
            throw UsageError("--option: method auto takes no backend options but light_sampler (it chooses path or bdpt)");
    } else if (g.settings.method != GridMethod::Path && g.settings.method != GridMethod::Vpl) {
        RenderSettings check;  // the backend's own parser judges the options before any work
        check.options = g.settings.backendOptions;
        try {
            const BackendInfo* method = findBackend(gridMethodName(g.settings.method));
            requireKnownOptions(check.options, std::span(&method, 1));
            method->make(scene, check);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    } else if (!onlyLightSampler) {
        throw UsageError("--option: method " + std::string(gridMethodName(g.settings.method)) +
                         " takes no backend options but light_sampler (path and ir are set with --samples and --vpl-paths)");
    }
    return {std::move(g), scene, std::move(layout), skyEh, median, medianGiven, requirement, std::move(taskArea),
            std::move(zones)};
}

// --daylight-factor: DF = 100 E / Eh,sky per point (SPEC.md section 5), its average, minimum and
// uniformity, and EN 17037's daylight provision on the plane.
int reportDaylightFactor(const GridSetup& setup, const GridResult& r) {
    const GridArgs& g = setup.g;
    const GridLayout& layout = setup.layout;
    const double perLux = 100.0 / setup.skyHorizontalIlluminance;
    std::vector<double> df(r.lux.size());
    for (size_t i = 0; i < df.size(); ++i) df[i] = r.lux[i] * perLux;
    const GridStatistics s = gridStatistics(df, r.insideGeometry);
    std::printf("daylight factor on grid '%s': %d x %d points, spacing %.3g x %.3g m, method %s%s\n", g.grid.name.c_str(),
                layout.nu, layout.nv, layout.spacingUMeters, layout.spacingVMeters, gridMethodName(r.method),
                g.settings.autoMethod ? " (auto)" : "");
    if (!r.autoMeasured.empty()) std::printf("auto: %s\n", r.autoMeasured.c_str());
    std::printf("CIE overcast sky alone, Eh,sky %.1f lx on an open horizontal plane; sun and electric lights off\n",
                setup.skyHorizontalIlluminance);
    if (s.excluded > 0) std::printf("%s\n", excludedPointsLine(s, layout.points.size(), true).c_str());
    std::printf("%s\n", daylightFactorFiguresLine(s).c_str());
    if (s.counted > 0) {
        printLines(gridErrorLines(r, s.counted));
        const DaylightProvision p = checkDaylightProvision(df, r.insideGeometry, setup.medianDiffuseIlluminance);
        std::printf("median external diffuse illuminance %.0f lx%s; EN 17037 asks for its reference plane 0.85 m above "
                    "the floor (this grid's plane is the one given)\n",
                    setup.medianDiffuseIlluminance, setup.medianGiven ? "" : " (not given: EN 17037's usual value)");
        std::printf("%s", describeProvision(p).c_str());
    }
    std::printf("%s", gridTableText(layout, r, perLux, 2).c_str());
    if (!g.csv.empty()) {
        writeTextAtomically(g.csv, gridCsv(layout, r.lux, r.errorLux, r.insideGeometry, r.errorBarUnknown, perLux));
        std::fprintf(stderr, "wrote %s\n", g.csv.c_str());
    }
    return 0;
}

// Runs `work` (true when it finished) as a job, showing its progress; whether it stopped short
// (Ctrl-C), every process of a distributed grid agreeing.
bool runStoppable(TaskSystem& tasks, const std::string& label, ProcessGroup* processes,
                  const std::function<bool(TaskContext&)>& work) {
    bool finished = false;
    auto job = tasks.submit([&](TaskContext& ctx) { finished = work(ctx) && !ctx.isCancelled(); });
    std::exception_ptr failure;
    try {
        const bool speaks = rankOf(processes) == 0;
        waitShowingProgress(*job, label, 1,
                            !processes ? ProgressLines::TerminalOnly : speaks ? ProgressLines::Also : ProgressLines::Never);
    } catch (...) {
        failure = std::current_exception();
    }
    agreeOnOutcome(processes, failure);
    bool stopped = interrupted() || !finished;
    if (sizeOf(processes) > 1) {  // every rank stopped with the others (runRounds), but say so together
        const double mine = stopped ? 1.0 : 0.0;
        for (double theirs : processes->allGather(std::span(&mine, 1))) stopped = stopped || theirs > 0;
    }
    return stopped;
}

// The task area's part of the output after its figures: the 2021 figures computed, the
// requirement and every check in one list, then the zones.
void reportTaskArea(const GridSetup& setup, const GridResult& all, const GridStatistics& s, const GridResult& r,
                    const std::optional<TaskAreaExtras>& extras, const MaintenanceRange& maintenance) {
    const Scene& scene = *setup.scene;
    if (extras) printLines(extrasLines(*extras, s));
    if (setup.requirement && s.counted > 0) {
        std::printf("%s\n", describeRequirement(*setup.requirement, lightingStandardOf(scene)).c_str());
        TaskAreaFigures figures;
        figures.grid = s;
        if (!r.errorBarUnknown) figures.gridErrors = gridErrorBars(s, r.lux, r.errorLux, r.insideGeometry);
        figures.colourRendering = statedColourRendering(scene);
        figures.maintainedValues = valuesAreMaintained(maintenance);
        if (extras) addExtras(figures, *extras);
        for (const RequirementCheck& c : checkRequirements(*setup.requirement, figures))
            std::printf("  %s\n", c.describe().c_str());
    } else if (!setup.requirement) {
        std::printf("task area '%s' names no activity: nothing to check\n", setup.g.taskArea.c_str());
    }
    printLines(setup.zones.lines(all, valuesAreMaintained(maintenance)));
}

int gridImpl(const std::vector<std::string>& args, ProcessGroup* processes) {
    // Ctrl-C while the scene loads: nothing is written yet (catchInterrupts() takes over below).
    exitOnInterrupt("grid interrupted; no file written\n");
    std::optional<GridSetup> setup = setUpTogether(processes, [&] { return setUpGrid(args, processes); });
    GridArgs& g = setup->g;
    const SceneSnapshot& scene = setup->scene;
    const GridLayout& layout = setup->layout;
    g.settings.processes = processes;
    const bool speaks = rankOf(processes) == 0;  // of a distributed grid, rank 0 prints and writes
    const std::string method = g.settings.autoMethod ? "auto" : gridMethodName(g.settings.method);

    catchInterrupts();
    TaskSystem tasks(g.threads);
    // The zones' points after the grid's own, in the same calculation (as the dock computes them).
    std::vector<V3d> points = layout.points;
    points.insert(points.end(), setup->zones.points().begin(), setup->zones.points().end());
    std::optional<GridResult> all;
    bool stopped = runStoppable(tasks, "grid " + method, processes, [&](TaskContext& ctx) {
        // The report's path too (report/report_builder.cpp), so that their figures agree.
        all = computeSceneGrid(scene, points, g.grid.normal(), g.settings, ctx);
        return true;
    });
    // Then the 2021 figures the area's activity asks for, with the same method and settings.
    std::optional<TaskAreaExtras> extras;
    const TaskAreaExtrasRequest request =
        setup->area ? requestedExtras(setup->requirement, g.cylindrical, g.roomSurfaces, g.horizontalOnly)
                    : TaskAreaExtrasRequest{false, false};
    if (!stopped && (request.cylindrical || request.roomSurfaces)) {
        const std::string what = request.cylindrical && request.roomSurfaces ? "Ez and room surfaces"
                                 : request.cylindrical                        ? "Ez"
                                                                              : "room surfaces";
        stopped = runStoppable(tasks, what + " " + method, processes, [&](TaskContext& ctx) {
            extras = computeTaskAreaExtras(scene, *setup->area, g.settings, request, ctx);
            return extras->complete;
        });
    }
    if (stopped) {
        if (speaks) std::cerr << "grid interrupted; no file written\n";
        return 130;
    }
    if (!speaks) return 0;

    if (g.daylightFactor) return reportDaylightFactor(*setup, *all);
    const GridResult r = setup->zones.taskPart(*all);
    const GridStatistics s = gridStatistics(r.lux, r.insideGeometry);
    const bool cylindrical = g.settings.quantity == GridQuantity::Cylindrical;
    std::printf("grid '%s': %d x %d points, spacing %.3g x %.3g m, method %s%s%s\n", g.grid.name.c_str(), layout.nu,
                layout.nv, layout.spacingUMeters, layout.spacingVMeters, gridMethodName(r.method),
                g.settings.autoMethod ? " (auto)" : "",
                cylindrical ? "; cylindrical illuminance Ez about the grid's normal" : "");
    if (!all->autoMeasured.empty()) std::printf("auto: %s\n", all->autoMeasured.c_str());
    const MaintenanceRange maintenance = maintenanceRange(*scene);
    std::printf("%s\n", describeMaintenance(maintenance).c_str());
    if (s.excluded > 0) std::printf("%s\n", excludedPointsLine(s, layout.points.size()).c_str());
    std::printf("%s%s\n", cylindrical ? "Ez: " : "", gridFiguresLine(s).c_str());
    printLines(gridErrorLines(r, s.counted));
    if (setup->area) reportTaskArea(*setup, *all, s, r, extras, maintenance);
    std::printf("%s", gridTableText(layout, r).c_str());
    if (!g.csv.empty()) {
        writeTextAtomically(g.csv, gridCsv(layout, r.lux, r.errorLux, r.insideGeometry, r.errorBarUnknown));
        std::fprintf(stderr, "wrote %s\n", g.csv.c_str());
    }
    return 0;
}
}  // namespace

int grid(const std::vector<std::string>& args, ProcessGroup* processes) {
    return runCommand([&] { return gridImpl(args, processes); });
}

}  // namespace lucerna::cli
