#include "app/report_command.h"
#include "app/cli_support.h"

#include "core/daylight/epw_file.h"
#include "core/number_format.h"
#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/photometry/grid_text.h"
#include "report/report_builder.h"
#include "report/report_writer.h"

#include <QGuiApplication>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

namespace lucerna::cli {

namespace {

struct ReportArgs {
    std::string scene, output;
    ReportSettings settings;
    int threads = 0;
};

bool endsWithPdf(const std::string& s) {
    if (s.size() < 4) return false;
    std::string tail = s.substr(s.size() - 4);
    for (char& c : tail) c = char(std::tolower((unsigned char)c));
    return tail == ".pdf";
}

ReportArgs parseReportArgs(const std::vector<std::string>& args) {
    ReportArgs r;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        GridSettings& g = r.settings.grid;
        if (a == "-o" || a == "--output") r.output = value();
        else if (a == "--method") {
            const auto method = parseGridMethod(value(), true);
            g.autoMethod = !method;
            if (method) g.method = *method;
        } else if (a == "--error") g.targetRelativeError = parseNumber<double>(a, value(), 1e-6, 1.0);
        else if (a == "--time") g.timeLimitSeconds = parseNumber<double>(a, value(), 1e-3, 1e7);
        else if (a == "--seed") g.seed = parseNumber<uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--samples") g.samplesPerPass = parseNumber<int>(a, value(), 1, 1 << 20);
        else if (a == "--spp") r.settings.renderSpp = parseNumber<int>(a, value(), 1, 1 << 24);
        else if (a == "--render-error") r.settings.renderRelmse = parseNumber<double>(a, value(), 0.0, 1.0);
        else if (a == "--threads") r.threads = parseNumber<int>(a, value(), 1, 4096);
        else if (a == "--weather") r.settings.weatherPath = value();
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (r.scene.empty()) r.scene = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (r.scene.empty()) throw UsageError("report: no scene file given");
    if (r.output.empty()) throw UsageError("report: no output file given (-o OUT.pdf)");
    if (!endsWithPdf(r.output)) throw UsageError(r.output + ": a report is a PDF (-o NAME.pdf)");
    return r;
}

int reportImpl(const std::vector<std::string>& args, int& argc, char** argv) {
    // Ctrl-C while the scene loads: nothing is written yet (catchInterrupts() takes over below).
    exitOnInterrupt("report interrupted; no file written\n");
    const ReportArgs r = parseReportArgs(args);
    checkOutputPath(r.output);
    LoadReport loadReport;
    SceneSnapshot scene;
    try {
        scene = std::make_shared<const Scene>(loadScene(r.scene, &loadReport));
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
    for (const std::string& w : loadReport.warnings) std::cerr << "warning: " << w << "\n";
    ReportSettings settings = r.settings;
    if (!settings.weatherPath.empty()) {
        try {
            settings.weather = readWeatherFile(settings.weatherPath);
        } catch (const WeatherFileError& e) {
            throw UsageError(e.what());
        }
    }
    try {
        checkReportInput(*scene, settings);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }

    catchInterrupts();
    TaskSystem tasks(r.threads);
    std::optional<ReportData> data;
    auto job = tasks.submit([&](TaskContext& ctx) {
        ReportData d = buildReport(scene, r.scene, settings, ctx);
        if (!ctx.isCancelled()) data = std::move(d);
    });
    waitShowingProgress(*job, "report");
    if (interrupted() || !data) {
        std::cerr << "report interrupted; no file written\n";
        return 130;
    }
    // A report shows no window: no display needed.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    const QGuiApplication app(argc, argv);
    int pages = 0;
    try {
        pages = writeReportPdf(*data, r.output);
    } catch (const std::runtime_error& e) {
        throw UsageError(e.what());  // the output path was checked, but the disk may be full
    }
    // Each area's figures as `lucerna grid` prints them.
    for (const AreaReport& a : data->areas) {
        std::printf("area '%s': %d x %d points, method %s\n", a.name.c_str(), a.layout.nu, a.layout.nv,
                    gridMethodName(a.result.method));
        std::printf("%s\n", gridFiguresLine(a.statistics).c_str());
        if (a.worstUgr) std::printf("UGR %.1f (worst of %zu observers)\n", *a.worstUgr, a.glare.size());
        for (const RequirementCheck& c : a.checks) std::printf("%s\n", c.describe().c_str());
        if (a.modellingRatio) std::printf("%s\n", describeModelling(*a.modellingRatio).c_str());
        for (const ZoneReport& z : a.zones)
            for (const RequirementCheck& c : z.checks) std::printf("%s: %s\n", z.name.c_str(), c.describe().c_str());
    }
    std::fprintf(stderr, "wrote %s: %d pages, %zu task area%s, %s\n", r.output.c_str(), pages, data->areas.size(),
                 data->areas.size() == 1 ? "" : "s", formatDuration(data->seconds).c_str());
    return 0;
}

}  // namespace

int report(const std::vector<std::string>& args, int& argc, char** argv) {
    return runCommand([&] { return reportImpl(args, argc, argv); });
}

}  // namespace lucerna::cli
