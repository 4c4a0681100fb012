#include "app/annual_command.h"

#include "app/cli_support.h"
#include "app/grid_placement.h"
#include "core/atomic_file.h"
#include "core/process_group.h"
#include "core/resources.h"
#include "core/daylight/annual_metrics.h"
#include "core/daylight/epw_file.h"
#include "core/scene/scene_io.h"
#include "render/annual/annual_calculation.h"
#include "render/annual/annual_text.h"

#include <cstdio>
#include <iostream>
#include <optional>

namespace lucerna::cli {

namespace {

struct AnnualArgs {
    std::string scene, weather, csv, hourly, hourlyError, hourlyDirect, gridName = "annual";
    std::optional<double> workPlaneM, spacingM, dewPointC;
    double borderM = 0.5;
    std::string taskArea;
    Occupancy occupancy;
    std::optional<std::array<int, 3>> exportHour;  // month, day, hour
    std::string exportPath;
    AnnualSettings settings;
    int threads = 0;
};

Occupancy parseOccupancy(const std::string& text) {
    const size_t dash = text.find('-');
    if (dash == std::string::npos) throw UsageError("--occupancy: expected FROM-TO in hours, got '" + text + "'");
    Occupancy o;
    o.fromHour = parseNumber<double>("--occupancy", text.substr(0, dash), 0.0, 24.0);
    o.toHour = parseNumber<double>("--occupancy", text.substr(dash + 1), 0.0, 24.0);
    if (!(o.fromHour < o.toHour)) throw UsageError("--occupancy: FROM must be before TO, got '" + text + "'");
    return o;
}

std::array<int, 3> parseHourOfYear(const std::string& text) {
    int month = 0, day = 0, hour = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%d-%d-%d%c", &month, &day, &hour, &tail) != 3 || month < 1 || month > 12 || day < 1 ||
        day > 31 || hour < 1 || hour > 24)
        throw UsageError("--export-hour: expected MM-DD-HH (hour 1 to 24, the hour ending then), got '" + text + "'");
    return {month, day, hour};
}

AnnualArgs parseAnnualArgs(const std::vector<std::string>& args) {
    AnnualArgs a;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& o = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(o + " needs a value");
            return args[++i];
        };
        if (o == "--weather") a.weather = value();
        else if (o == "--work-plane") a.workPlaneM = parseNumber<double>(o, value(), -1e6, 1e6);
        else if (o == "--border") a.borderM = parseNumber<double>(o, value(), 0.0, 1e6);
        else if (o == "--task-area") a.taskArea = value();
        else if (o == "--spacing") a.spacingM = parseNumber<double>(o, value(), 1e-6, 1e6);
        else if (o == "--occupancy") a.occupancy = parseOccupancy(value());
        else if (o == "--dew-point") a.settings.dewPointC = parseNumber<double>(o, value(), -90.0, 60.0);
        else if (o == "--csv") a.csv = value();
        else if (o == "--hourly") a.hourly = value();
        else if (o == "--hourly-error") a.hourlyError = value();
        else if (o == "--hourly-direct") a.hourlyDirect = value();
        else if (o == "--export-hour") {
            a.exportHour = parseHourOfYear(value());
            a.exportPath = value();
        } else if (o == "--seed") a.settings.coefficients.seed = parseNumber<uint64_t>(o, value(), 0, UINT64_MAX);
        else if (o == "--threads") a.threads = parseNumber<int>(o, value(), 1, 4096);
        else if (o == "--sky-subdivision") a.settings.coefficients.skySubdivision = parseNumber<int>(o, value(), 1, 16);
        else if (o == "--paths") a.settings.coefficients.paths = parseNumber<int>(o, value(), 16, 1 << 24);
        else if (o == "--sun-paths") a.settings.coefficients.sunPaths = parseNumber<int>(o, value(), 8, 1 << 20);
        else if (o == "--resume") a.settings.resume = true;
        else if (!o.empty() && o[0] == '-') throw UsageError("unknown option " + o);
        else if (a.scene.empty()) a.scene = o;
        else throw UsageError("unexpected argument '" + o + "'");
    }
    if (a.scene.empty()) throw UsageError("annual: no scene file given");
    if (a.weather.empty()) throw UsageError("annual: no weather file given (--weather FILE.epw)");
    if (!a.exportHour && (a.workPlaneM.has_value() == !a.taskArea.empty()))
        throw UsageError("annual: give one of --work-plane HEIGHT or --task-area NAME");
    return a;
}

std::string pointsCsv(const std::vector<V3d>& points, const AnnualMetrics& m) {
    std::string out = "x,y,z,da300,udi_fell_short,udi_useful,udi_exceeded,ase_hours,mean_lux\n";
    char line[256];
    for (size_t p = 0; p < points.size(); ++p) {
        const PointAnnualMetrics& q = m.points[p];
        std::snprintf(line, sizeof line, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g\n", points[p].x, points[p].y,
                      points[p].z, q.da300, q.udiFellShort, q.udiUseful, q.udiExceeded, q.aseHours, q.meanLux);
        out += line;
    }
    return out;
}

std::string hourlyCsv(const AnnualResult& r, const std::vector<float>& values) {
    std::string out = "month,day,hour";
    for (size_t p = 0; p < r.points; ++p) out += ",p" + std::to_string(p + 1);
    out += '\n';
    char number[32];
    for (size_t row = 0; row < r.hours.size(); ++row) {
        const AnnualHour& h = r.hours[row];
        out += std::to_string(h.month) + ',' + std::to_string(h.day) + ',' + std::to_string(h.hour);
        for (size_t p = 0; p < r.points; ++p) {
            std::snprintf(number, sizeof number, ",%.6g", double(values[row * r.points + p]));
            out += number;
        }
        out += '\n';
    }
    return out;
}

int exportHour(const AnnualArgs& a, const Scene& scene, const WeatherFile& weather) {
    const auto& [month, day, hour] = *a.exportHour;
    if (const auto row = weatherRow(weather, month, day, hour)) {
        const WeatherHour& h = weather.hours[*row];
        saveScene(sceneOfHour(scene, weather, *row, a.settings.dewPointC), a.exportPath);
        std::fprintf(stderr, "wrote %s: row %zu of %s (Ib %g W/m2, Ed %g W/m2)\n", a.exportPath.c_str(), *row + 1,
                     a.weather.c_str(), h.directNormalIrradiance, h.diffuseHorizontalIrradiance);
        return 0;
    }
    throw UsageError("--export-hour: the weather file has no row " + std::to_string(month) + "-" + std::to_string(day) +
                     "-" + std::to_string(hour));
}

// What a year needs once its arguments, scene and weather file are read.
struct AnnualSetup {
    AnnualArgs a;
    Scene scene;
    WeatherFile weather;
};

// Everything that can fail on bad input before any work; of a shared year every rank does it,
// and rank 0 alone checks the output paths (it alone writes).
AnnualSetup setUpAnnual(const std::vector<std::string>& args, const ProcessGroup* processes) {
    AnnualSetup s;
    s.a = parseAnnualArgs(args);
    if (rankOf(processes) == 0)
        for (const std::string* path : {&s.a.csv, &s.a.hourly, &s.a.hourlyError, &s.a.hourlyDirect, &s.a.exportPath})
            if (!path->empty()) checkOutputPath(*path);
    try {
        s.scene = loadScene(s.a.scene);
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
    try {
        s.weather = readWeatherFile(s.a.weather);
    } catch (const WeatherFileError& e) {
        throw UsageError(e.what());
    }
    return s;
}

int annualImpl(const std::vector<std::string>& args, ProcessGroup* processes) {
    exitOnInterrupt("annual interrupted; no file written\n");
    std::optional<AnnualSetup> setup = setUpTogether(processes, [&] { return setUpAnnual(args, processes); });
    AnnualArgs& a = setup->a;
    const Scene& scene = setup->scene;
    const WeatherFile& weather = setup->weather;
    const bool speaks = rankOf(processes) == 0;  // of a shared year, rank 0 prints and writes
    if (a.exportHour) return speaks ? exportHour(a, scene, weather) : 0;

    CalculationGrid grid;
    if (a.workPlaneM) grid = workPlaneGridOf(scene, *a.workPlaneM, a.borderM, a.spacingM, a.gridName);
    else {
        grid = taskAreaOf(scene, a.taskArea).grid;
        if (a.spacingM) grid.spacingMeters = a.spacingM;
    }
    GridLayout layout;
    try {
        layout = layoutGrid(grid, scene.metersPerUnit);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }

    // The traced points are kept as they go, so that an interrupted year can go on (--resume).
    a.settings.checkpointDirectory = cacheDirectory("annual");
    a.settings.processes = processes;
    catchInterrupts();
    TaskSystem tasks(a.threads);
    std::optional<AnnualResult> result;
    auto job = tasks.submit([&](TaskContext& ctx) {
        result = computeAnnual(scene, layout.points, grid.normal(), weather, a.settings, ctx);
    });
    std::exception_ptr failure;
    try {
        waitShowingProgress(*job, "annual", 1,
                            !processes ? ProgressLines::TerminalOnly : speaks ? ProgressLines::Also : ProgressLines::Never);
    } catch (...) {
        failure = std::current_exception();
    }
    agreeOnOutcome(processes, failure);
    if (!result || result->cancelled || (!processes && interrupted())) {
        if (!speaks) return 130;
        std::cerr << "annual interrupted; no file written"
                  << (result && !result->checkpointPath.empty() ? "; the same command with --resume goes on from the points traced"
                                                                : "")
                  << "\n";
        return 130;
    }
    if (!result->onRoot) return 0;
    if (result->resumedPoints > 0)
        std::fprintf(stderr, "resumed: %zu points read from %s\n", result->resumedPoints, result->checkpointPath.c_str());
    const AnnualResult& r = *result;
    std::vector<uint8_t> counted(r.points);
    for (size_t p = 0; p < r.points; ++p) counted[p] = !r.insideGeometry[p];
    const AnnualMetrics m = computeAnnualMetrics(r.hours, r.points, r.lux, r.directSunLux, a.occupancy, counted);

    const SkyPatches patches(a.settings.coefficients.skySubdivision);
    std::printf("annual grid '%s': %d x %d points, spacing %.3g x %.3g m; daylight coefficients: Reinhart MF:%d sky "
                "(%d patches and the ground), %d paths per point, the sun's reflections by %d more at the nodes of "
                "its path, its direct light traced each hour through its disc\n",
                grid.name.c_str(), layout.nu, layout.nv, layout.spacingUMeters, layout.spacingVMeters,
                a.settings.coefficients.skySubdivision, patches.count(), a.settings.coefficients.paths,
                a.settings.coefficients.sunPaths);
    for (const std::string& line : annualFigureLines(weather, r, m, a.occupancy)) std::printf("%s\n", line.c_str());
    std::printf("%s; time: tracing %.1f s, hours %.1f s\n", annualErrorLine(r).c_str(), r.tracingSeconds, r.hoursSeconds);
    const auto write = [](const std::string& path, const std::string& text) {
        if (path.empty()) return;
        writeTextAtomically(path, text);
        std::fprintf(stderr, "wrote %s\n", path.c_str());
    };
    write(a.csv, pointsCsv(layout.points, m));
    write(a.hourly, hourlyCsv(r, r.lux));
    write(a.hourlyError, hourlyCsv(r, r.errorLux));
    write(a.hourlyDirect, hourlyCsv(r, r.directSunLux));
    return 0;
}

}  // namespace

int annual(const std::vector<std::string>& args, ProcessGroup* processes) {
    return runCommand([&] { return annualImpl(args, processes); });
}

}  // namespace lucerna::cli
