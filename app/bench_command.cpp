#include "app/bench_command.h"
#include "app/cli_support.h"

#include "app/bench_plot.h"
#include "core/atomic_file.h"
#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/number_format.h"
#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/backend/pass_loop.h"
#include "render/engine/backend_table.h"

#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>

namespace lucerna::cli {

namespace {

struct BenchRun {
    std::string label;  // as given in --backends: the curve's name in the CSV and the plot
    std::string backend;
    std::map<std::string, std::string> options;  // this entry's own, over --option
};

struct BenchArgs {
    std::string scene, reference, outDir = ".";
    std::vector<BenchRun> runs;
    RenderSettings settings;  // seconds, seed, size and the shared options
    int threads = 0;
    int perDecade = 12;
    double start = 0.1;
};

std::vector<BenchRun> parseBackends(const std::string& list) {
    std::vector<BenchRun> runs;
    size_t begin = 0;
    while (begin <= list.size()) {
        const size_t end = std::min(list.find(',', begin), list.size());
        const std::string entry = list.substr(begin, end - begin);
        if (entry.empty()) throw UsageError("--backends: empty entry in '" + list + "'");
        BenchRun run{entry, {}, {}};
        size_t colon = entry.find(':');
        run.backend = entry.substr(0, colon);
        while (colon != std::string::npos) {
            const size_t next = entry.find(':', colon + 1);
            addBackendOption(entry.substr(colon + 1, next == std::string::npos ? next : next - colon - 1), run.options,
                             "--backends entry '" + entry + "'");
            colon = next;
        }
        if (run.backend != "auto-rule" && !findBackend(run.backend)) {
            std::string names = "auto, auto-rule";
            for (const BackendInfo& b : backendTable()) names += ", " + std::string(b.name);
            throw UsageError("unknown backend '" + run.backend + "' (available: " + names + ")");
        }
        runs.push_back(std::move(run));
        begin = end + 1;
    }
    return runs;
}

BenchArgs parseBenchArgs(const std::vector<std::string>& args) {
    BenchArgs b;
    std::string backends;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "--reference") b.reference = value();
        else if (a == "--backends") backends = value();
        else if (a == "--time") b.settings.seconds = parseNumber<double>(a, value(), 1e-3, 1e7);
        else if (a == "--out") b.outDir = value();
        else if (a == "--seed") b.settings.seed = parseNumber<uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--threads") b.threads = parseNumber<int>(a, value(), 1, 4096);
        else if (a == "--width") b.settings.width = parseNumber<int>(a, value(), 1, 16384);
        else if (a == "--height") b.settings.height = parseNumber<int>(a, value(), 1, 16384);
        else if (a == "--per-decade") b.perDecade = parseNumber<int>(a, value(), 1, 1000);
        else if (a == "--start") b.start = parseNumber<double>(a, value(), 1e-4, 1e6);
        else if (a == "--option") addBackendOption(value(), b.settings.options);
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (b.scene.empty()) b.scene = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (b.scene.empty()) throw UsageError("bench: no scene file given");
    if (b.reference.empty()) throw UsageError("bench: no reference image given (--reference REF.exr)");
    if (backends.empty()) throw UsageError("bench: no backends given (--backends path,bdpt,...)");
    if (!(b.settings.seconds > 0)) throw UsageError("bench: no time budget given (--time SECONDS)");
    if ((b.settings.width > 0) != (b.settings.height > 0)) throw UsageError("bench: --width and --height go together");
    b.runs = parseBackends(backends);
    // Before any backend runs: an entry's own options are its backend's, --option's any entry's;
    // auto and auto-rule (the backend the rule auto was before it measured picks, resolved once the
    // scene is read) take any backend's.
    std::vector<const BackendInfo*> every, all;
    for (const BackendInfo& info : backendTable()) every.push_back(&info);
    for (const BenchRun& run : b.runs)
        if (run.backend != "auto" && run.backend != "auto-rule") all.push_back(findBackend(run.backend));
    try {
        requireKnownOptions(b.settings.options, all.size() < b.runs.size() ? every : all);
        for (const BenchRun& run : b.runs) {
            const BackendInfo* info = run.backend == "auto" ? nullptr : findBackend(run.backend);
            requireKnownOptions(run.options, info ? std::span(&info, 1) : std::span<const BackendInfo* const>(every));
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("bench: ") + e.what());
    }
    return b;
}

std::string formatValue(double v) {
    return std::isfinite(v) ? formatNumber(v, 6) : "nan";
}

// One backend for the budget. The driver publishes a frame after a pass when a third of the gap
// between log-spaced samples has passed since the last (a frame's cost is render time, and a
// frame of auto's combination costs more than a film's copy); this thread wakes every few
// milliseconds and measures
// the newest frame once it has passed the next log-spaced time. Each sample carries the frame's
// own time, so a slow pass shows as a sparser curve, never as a wrong time.
// One backend's curve, and what it says of itself at the end (auto: what it measured and decided).
struct BenchCurve {
    std::vector<BenchSample> samples;
    std::string decision;
};

BenchCurve runOne(const BenchArgs& b, const BenchRun& run, const SceneSnapshot& scene, const Image& reference,
                  TaskSystem& tasks) {
    RenderSettings settings = b.settings;
    for (const auto& [k, v] : run.options) settings.options[k] = v;
    // Arena slots run from 0 to the arena's concurrency (one more for a master thread).
    RayRecorder rays(std::max(tasks.threadCount(), int(std::thread::hardware_concurrency())) + 1, /*countOnly=*/true);
    settings.rayRecorder = &rays;
    std::unique_ptr<Backend> backend;
    try {
        backend = findBackend(run.backend)->make(scene, settings);
    } catch (const std::invalid_argument& e) {
        throw UsageError(run.label + ": " + e.what());
    }
    Latest<RenderFrame> latest;
    auto job = tasks.submit([&](TaskContext& ctx) {
        backend->prepare(ctx);
        if (ctx.isCancelled()) return;
        rays.resetCounts();  // the passes' rays only, as the time is the passes' only
        PassLoopOptions everyPass;
        everyPass.publishSeconds = 0;
        everyPass.publishShare = (std::pow(10.0, 1.0 / b.perDecade) - 1) / 3;
        runPasses(*backend, run.backend, settings, ctx, &latest, everyPass);
    });

    std::vector<BenchSample> samples;
    int k = 0;  // index of the next log-spaced time: start * 10^(k / perDecade)
    const auto nextTime = [&] { return b.start * std::pow(10.0, double(k) / b.perDecade); };
    uint64_t seen = 0;
    const auto measure = [&](const RenderFrame& f) {
        const ImageMetrics m = compareImages(f.image, reference);
        samples.push_back({run.label, f.seconds, f.samplesPerPixel, m.rmse, m.relmse, f.estimatedRelmse, m.meanTest,
                           m.meanRef, double(rays.total())});
        while (nextTime() <= f.seconds) ++k;
    };
    const auto poll = [&](bool last) {
        if (latest.version() == seen) return;
        seen = latest.version();
        const auto frame = latest.get();
        if (frame && frame->passes > 0 && (last || frame->seconds >= nextTime())) measure(*frame);
    };
    while (!job->isFinished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(3));
        if (interrupted()) job->cancel();
        poll(false);
    }
    job->wait();
    job->rethrowIfFailed();
    if (interrupted()) return {samples, ""};
    // The final frame (published at the end) closes every curve at the budget.
    const auto final = latest.get();
    if (final && final->passes > 0 && (samples.empty() || samples.back().seconds < final->seconds)) measure(*final);
    std::string decision;
    if (final) {
        const auto it = final->image.attributes.find("lucerna:auto");
        if (it != final->image.attributes.end()) decision = it->second;
    }
    return {samples, decision};
}

void writeText(const std::string& path, const std::string& text) {
    try {
        writeTextAtomically(path, text);
    } catch (const std::runtime_error& e) {
        throw UsageError(e.what());
    }
}

int benchImpl(const std::vector<std::string>& args) {
    BenchArgs b = parseBenchArgs(args);
    Image reference;
    try {
        reference = readExr(b.reference);
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    if (b.settings.width == 0) b.settings.width = reference.width, b.settings.height = reference.height;
    if (b.settings.width != reference.width || b.settings.height != reference.height)
        throw UsageError("bench: --width/--height " + std::to_string(b.settings.width) + "x" +
                         std::to_string(b.settings.height) + " differ from the reference's " +
                         std::to_string(reference.width) + "x" + std::to_string(reference.height));
    LoadReport report;
    SceneSnapshot scene;
    try {
        scene = std::make_shared<const Scene>(loadScene(b.scene, &report));
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
    for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
    for (BenchRun& run : b.runs)
        if (run.backend == "auto-rule") {  // its curve keeps the label "auto-rule"
            const AutoChoice choice = chooseAutoBackend(*scene);
            run.backend = choice.backend;
            std::printf("%s: %s\n", run.label.c_str(), choice.reason.c_str());
        }
    std::error_code ec;
    std::filesystem::create_directories(b.outDir, ec);
    if (!std::filesystem::is_directory(b.outDir)) throw UsageError("--out: cannot create folder " + b.outDir);

    catchInterrupts();
    TaskSystem tasks(b.threads);
    std::vector<BenchSample> all;
    std::printf("%-24s %10s %10s %14s %14s %14s %12s %9s\n", "backend", "seconds", "spp", "rmse", "relmse",
                "est. relmse", "mean/ref", "Mrays/s");
    for (const BenchRun& run : b.runs) {
        const auto [samples, decision] = runOne(b, run, scene, reference, tasks);
        if (interrupted()) {
            std::cerr << "bench interrupted; no file written\n";
            return 130;
        }
        all.insert(all.end(), samples.begin(), samples.end());
        if (samples.empty()) continue;
        // The final figures, and the mean against the reference's (the bias a converged run keeps).
        const BenchSample& s = samples.back();
        std::printf("%-24s %10.3f %10.6g %14.6g %14.6g %14s %12.6f %9.3f\n", run.label.c_str(), s.seconds, s.spp,
                    s.rmse, s.relmse, formatValue(s.estimatedRelmse).c_str(),
                    s.meanRef > 0 ? s.meanTest / s.meanRef : NAN, s.seconds > 0 ? s.rays / s.seconds * 1e-6 : 0.0);
        if (!decision.empty()) std::printf("  %s: %s\n", run.label.c_str(), decision.c_str());
        std::fflush(stdout);
    }

    std::string csv = "backend,seconds,spp,rmse,relmse,estimated_relmse,rays\n";
    for (const BenchSample& s : all)
        csv += s.backend + "," + formatValue(s.seconds) + "," + formatValue(s.spp) + "," + formatValue(s.rmse) + "," +
               formatValue(s.relmse) + "," + formatValue(s.estimatedRelmse) + "," + formatValue(s.rays) + "\n";
    const std::filesystem::path out(b.outDir);
    writeText((out / "bench.csv").string(), csv);
    const std::string title = std::filesystem::path(b.scene).filename().string() + ", " +
                              std::to_string(reference.width) + "x" + std::to_string(reference.height) + ", " +
                              formatValue(b.settings.seconds) + " s per backend";
    writeText((out / "bench.svg").string(), errorPlotSvg(all, title));
    std::fprintf(stderr, "wrote %s and %s\n", (out / "bench.csv").c_str(), (out / "bench.svg").c_str());
    return 0;
}

}  // namespace

int bench(const std::vector<std::string>& args) { return runCommand(benchImpl, args); }

}  // namespace lucerna::cli
