#include "app/cli.h"
#include "app/cli_support.h"

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/number_format.h"
#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/backend/film.h"
#include "render/backend/light_layers/layered_backend.h"
#include "render/backend/pass_loop.h"
#include "render/backend/pooled_films.h"
#include "render/display/display.h"
#include "render/display/white_balance.h"
#include "render/engine/backend_table.h"
#include "render/engine/measured_auto/measured_auto_settings.h"
#include "render/photometry/illuminance_layer.h"
#include "render/trace/surface_layers.h"

#include <QSaveFile>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <csignal>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <new>
#include <numbers>
#include <optional>
#include <unistd.h>

namespace lucerna::cli {

namespace {

struct RenderArgs {
    std::string scene, output, backend = "auto";
    RenderSettings settings;
    int threads = 0;
    unsigned layers = 0;  // --layers: extra EXR layers (README), none by default
    int illuminanceSpp = 16;  // estimates per pixel of the illuminance layer
    bool png = false;             // -o NAME.png: a tone-mapped picture instead of the EXR
    bool saveOnInterrupt = false; // Ctrl-C ends at a pass boundary and writes the passes done
    std::optional<WhiteBalance> white;  // --white-balance: the PNG's white (D65 without)
};

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.begin(), suffix.end(), s.end() - std::ptrdiff_t(suffix.size()),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

// The sRGB picture of an image (render/display/display.h's tone curve), written whole or not at
// all, as `convert` writes it.
void writePngPicture(const Image& image, const std::string& path, const DisplaySettings& display) {
    const QImage png = toDisplayImage(image, display);
    QSaveFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::WriteOnly) || !png.save(&file, "PNG") || !file.commit())
        throw UsageError(path + ": cannot write");
}

// --white-balance: "D65", "lights" (the scene's lights' colour) or a colour temperature in kelvin.
WhiteBalance parseWhiteBalance(const std::string& option, const std::string& text) {
    WhiteBalance w;
    if (text == "D65" || text == "d65") return w;
    if (text == "lights") {
        w.reference = WhiteReference::DominantLights;
        return w;
    }
    w.reference = WhiteReference::Temperature;
    try {
        w.kelvin = parseNumber<double>(option, text, 1000.0, 40000.0);
    } catch (const UsageError&) {
        throw UsageError(option + " takes D65, lights or a colour temperature from 1000 to 40000 (kelvin), not '" +
                         text + "'");
    }
    return w;
}

RenderArgs parseRenderArgs(const std::vector<std::string>& args) {
    RenderArgs r;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "-o" || a == "--output") r.output = value();
        else if (a == "--backend") r.backend = value();
        else if (a == "--spp") r.settings.spp = parseNumber<int>(a, value(), 1, 1 << 24);
        else if (a == "--time") r.settings.seconds = parseNumber<double>(a, value(), 1e-3, 1e7);
        else if (a == "--seed") r.settings.seed = parseNumber<uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--threads") r.threads = parseNumber<int>(a, value(), 1, 4096);
        else if (a == "--width") r.settings.width = parseNumber<int>(a, value(), 1, 16384);
        else if (a == "--height") r.settings.height = parseNumber<int>(a, value(), 1, 16384);
        else if (a == "--illuminance-spp") r.illuminanceSpp = parseNumber<int>(a, value(), 1, 1 << 20);
        else if (a == "--layers") {
            std::string error;
            const auto bits = parseLayerList(value(), &error);
            if (!bits) throw UsageError("--layers: " + error);
            r.layers = *bits;
        } else if (a == "--option") addBackendOption(value(), r.settings.options);
        else if (a == "--save-on-interrupt") r.saveOnInterrupt = true;
        else if (a == "--white-balance") r.white = parseWhiteBalance(a, value());
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (r.scene.empty()) r.scene = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (r.scene.empty()) throw UsageError("render: no scene file given");
    if (r.output.empty()) throw UsageError("render: no output file given (-o OUT.exr)");
    // The name says the format: never an EXR under another image type's name.
    r.png = endsWithNoCase(r.output, ".png");
    if (!r.png && !endsWithNoCase(r.output, ".exr"))
        throw UsageError(r.output + ": unknown image type (-o NAME.exr for radiance, NAME.png for a tone-mapped picture)");
    if (r.png && r.layers) throw UsageError("--layers needs an EXR output (-o NAME.exr), not " + r.output);
    if (!r.png && r.white)
        throw UsageError("--white-balance needs a PNG output (-o NAME.png): an EXR keeps the rendered values");
    return r;
}

Scene loadOrThrow(const std::string& path, LoadReport* report) {
    try {
        return loadScene(path, report);
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
}

// A render its film cannot hold (two half-images of three doubles per pixel: 16384 x 16384 needs
// 12.9 GB) is bad input, not an internal error. Beyond the machine's memory it is refused
// before any work; within it, an allocation can still fail (a ulimit, other programs), and
// that std::bad_alloc becomes this same line.
std::string tooLargeForMemory(int width, int height) {
    const double gb = Film::bytes(width, height) / 1e9;
    char buf[160];
    std::snprintf(buf, sizeof buf, "a %d x %d render needs more memory than is available (its film alone holds %.3g GB)",
                  width, height, gb);
    return buf;
}

// What a render needs once its arguments, scene and backend are known.
struct RenderSetup {
    RenderArgs r;
    SceneSnapshot scene;
    std::string backendName;
    const BackendInfo* info = nullptr;
    std::unique_ptr<Backend> backend;
    int width = 0, height = 0;
    std::optional<GridMethod> illuminanceMethod;
};

// Everything that can fail on bad input before any work. Of a distributed render, every rank
// does this (each loads the scene and makes its backend); rank 0 alone prints what a single
// process prints and checks the output path (it alone writes).
RenderSetup setUpRender(const std::vector<std::string>& args, const ProcessGroup* processes) {
    const int rank = rankOf(processes);
    RenderSetup s;
    s.r = parseRenderArgs(args);
    RenderArgs& r = s.r;
    if (rank == 0) checkOutputPath(r.output);
    LoadReport report;
    s.scene = std::make_shared<const Scene>(loadOrThrow(r.scene, &report));
    if (rank == 0)
        for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";

    s.backendName = r.backend;
    // Per-light layers render a backend once per light group: auto's pilots of every method for
    // every layer would cost more than they find, so there the rule auto was picks.
    std::string ruleReason;
    if (s.backendName == "auto" && (r.layers & kLightLayers)) {
        const AutoChoice rule = chooseAutoBackend(*s.scene);
        s.backendName = rule.backend;
        ruleReason = rule.reason;
    }
    s.info = findBackend(s.backendName);
    if (!s.info) {
        std::string names = "auto";
        for (const BackendInfo& b : backendTable()) names += ", " + std::string(b.name);
        throw UsageError("unknown backend '" + r.backend + "' (available: " + names + ")");
    }
    try {
        // auto passes the options to whichever backend it picks: any backend's are fine.
        std::vector<const BackendInfo*> readers{s.info};
        if (r.backend == "auto")
            for (const BackendInfo& b : backendTable()) readers.push_back(&b);
        requireKnownOptions(r.settings.options, readers);
        // Of a distributed render, the Metropolis backends run chains of their own on each rank.
        RenderSettings settings = r.settings;
        if (s.info->share == ProcessShare::OwnChains) settings.seed = processSeed(r.settings.seed, rank);
        s.backend = (r.layers & kLightLayers) ? makeLayeredBackend(s.info->make, s.scene, settings)
                                              : s.info->make(s.scene, settings);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    s.width = r.settings.width ? r.settings.width : s.scene->camera.width;
    s.height = r.settings.height ? r.settings.height : s.scene->camera.height;
    const double pages = double(::sysconf(_SC_PHYS_PAGES)), pageSize = double(::sysconf(_SC_PAGESIZE));
    if (pages > 0 && pageSize > 0 && Film::bytes(s.width, s.height) > pages * pageSize)
        throw UsageError(tooLargeForMemory(s.width, s.height));
    if (!ruleReason.empty() && rank == 0) std::cerr << "auto (per-light layers: its rule): " << ruleReason << "\n";
    if (s.backendName == "auto" && rank == 0) {
        std::cerr << "auto: measures";
        for (const std::string& name : autoCandidates(*s.scene)) std::cerr << " " << name;
        std::cerr << " in short pilots, then gives each pass to the method that takes the most off the error and "
                     "combines their films\n";
    }
    // auto's illuminance layer: the method of the rule it was before it measured.
    s.illuminanceMethod = gridMethodFromName(s.backendName == "auto" ? chooseAutoBackend(*s.scene).backend : s.backendName);
    if ((r.layers & kIlluminanceLayer) && !s.illuminanceMethod)
        throw UsageError("--layers illuminance: backend " + s.backendName + " has no illuminance estimator");
    return s;
}

// A test's fault (tests/app/test_mpi.cpp): with LUCERNA_TEST_ABORT_RANK=N in the environment, rank N
// of a distributed render aborts after its first pass, as a node that dies would.
std::function<void(int)> testFault(const ProcessGroup* processes) {
    const char* rank = std::getenv("LUCERNA_TEST_ABORT_RANK");
    if (!processes || !rank || std::to_string(processes->rank()) != rank) return {};
    return [](int) {
        std::fprintf(stderr, "lucerna: LUCERNA_TEST_ABORT_RANK: rank %s aborts\n", std::getenv("LUCERNA_TEST_ABORT_RANK"));
        std::abort();
    };
}

// After every rank's passes: their films pooled on rank 0 (render/backend/pooled_films.h), and
// rank 0's frame remade from them with the figures of the whole run. Collective.
void poolDistributedRender(RenderSetup& s, ProcessGroup& processes, RenderFrame& frame, std::vector<float>& illuminance) {
    // Every rank's render time and passes, so that the header tells the whole run.
    const double mine[2] = {frame.seconds, double(frame.passes)};
    const std::vector<double> all = processes.allGather(mine);
    double seconds = 0, passes = 0;
    std::string rankPasses;  // "4 4 4": how the passes were shared
    for (int r = 0; r < processes.size(); ++r) {
        seconds = std::max(seconds, all[size_t(2 * r)]);
        passes += all[size_t(2 * r + 1)];
        rankPasses += (r ? " " : "") + std::to_string(int(all[size_t(2 * r + 1)]));
    }
    const auto start = std::chrono::steady_clock::now();
    poolFilms(*s.backend, processes);
    if (s.r.layers & kIlluminanceLayer) {
        std::vector<double> lux(illuminance.begin(), illuminance.end());  // each rank's rows, 0 elsewhere
        processes.sumToRoot(lux);
        std::copy(lux.begin(), lux.end(), illuminance.begin());
    }
    const double reduction = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (processes.rank() != 0) return;
    frame = makeRenderFrame(*s.backend, s.backendName, s.r.settings, seconds, int(passes));
    frame.image.attributes["lucerna:ranks"] = std::to_string(processes.size());
    frame.image.attributes["lucerna:rank_passes"] = rankPasses;
    frame.image.attributes["lucerna:reduction_seconds"] = formatNumber(reduction, 4);
}

int renderImpl(const std::vector<std::string>& args, ProcessGroup* processes) {
    // Ctrl-C while the scene loads: nothing is written yet (catchInterrupts() takes over below).
    exitOnInterrupt("render interrupted; no file written\n");
    const int rank = rankOf(processes);
    std::optional<RenderSetup> setup = setUpTogether(processes, [&] { return setUpRender(args, processes); });
    RenderSetup& s = *setup;
    const RenderArgs& r = s.r;
    const std::string& backendName = s.backendName;

    catchInterrupts();
    TaskSystem tasks(r.threads);
    std::optional<RenderFrame> result;
    std::vector<float> illuminance;
    // Whether the pass loop ended on a Ctrl-C (a later one, during the layers or the write,
    // leaves a complete render).
    bool stoppedEarly = false;
    PassLoopOptions loop;
    if (r.saveOnInterrupt) loop.finishEarly = [&stoppedEarly] { return stoppedEarly = interrupted(); };
    loop.shareIndex = rank;
    loop.shareCount = sizeOf(processes);
    loop.globalPassIndices = s.info->share == ProcessShare::DisjointPasses;
    loop.afterPass = testFault(processes);
    auto job = tasks.submit([&](TaskContext& ctx) {
        s.backend->prepare(ctx);
        if (ctx.isCancelled()) return;
        RenderFrame frame = runPasses(*s.backend, backendName, r.settings, ctx, nullptr, loop);
        if (ctx.isCancelled() || (frame.passes == 0 && interrupted() && !processes)) return;  // nothing converged to save
        if (r.layers & kIlluminanceLayer) {
            ctx.setProgress(0);
            // By the render's own backend's machinery (illuminance_layer.h); rows dealt to ranks.
            const RenderScene compiled(sceneAsRendered(s.scene), frame.image.width, frame.image.height);
            illuminance = traceIlluminanceLayer(compiled, *s.illuminanceMethod, r.illuminanceSpp, r.settings.seed, ctx,
                                                r.settings.options, RowShare{rank, sizeOf(processes)});
            if (ctx.isCancelled()) return;
        }
        result = std::move(frame);
    });
    std::exception_ptr failure;
    try {
        // With --save-on-interrupt the first Ctrl-C is the pass loop's (it finishes), a second
        // one cancels.
        waitShowingProgress(*job, backendName, r.saveOnInterrupt ? 2 : 1,
                            !processes ? ProgressLines::TerminalOnly : rank == 0 ? ProgressLines::Also : ProgressLines::Never);
    } catch (const std::bad_alloc&) {
        failure = std::make_exception_ptr(UsageError(tooLargeForMemory(s.width, s.height)));
    } catch (...) {
        failure = std::current_exception();
    }
    agreeOnOutcome(processes, failure);
    // Interrupted (mpirun passes a Ctrl-C on to every rank): no rank writes unless all saved.
    bool stopped = (interrupted() && !r.saveOnInterrupt) || !result;
    if (processes && processes->size() > 1) {
        const double mine = stopped ? 1.0 : 0.0;
        for (double theirs : processes->allGather(std::span(&mine, 1))) stopped = stopped || theirs > 0;
    }
    if (stopped) {
        if (rank == 0) std::cerr << "render interrupted; no file written\n";
        return 130;
    }
    if (processes) {  // one rank too, so that its header says so
        try {
            poolDistributedRender(s, *processes, *result, illuminance);
        } catch (const std::bad_alloc&) {
            throw UsageError(tooLargeForMemory(s.width, s.height));
        }
        if (rank != 0) return stoppedEarly ? 130 : 0;  // rank 0 writes
    }
    const bool savedEarly = stoppedEarly;
    if (savedEarly)
        std::fprintf(stderr, "render interrupted after %d passes; saving what converged so far\n", result->passes);
    // From here on the image is complete: a Ctrl-C during the write is ignored (README).
    try {
        if (r.layers & kAllLayers) addSurfaceLayers(result->image, s.scene, r.layers);
        if (r.layers & kIlluminanceLayer) result->image.channels["illuminance.Y"] = std::move(illuminance);
        if (r.png) {
            DisplaySettings display;
            display.white = r.white.value_or(WhiteBalance{});
            display.lights = lightsWhite(*s.scene);
            writePngPicture(result->image, r.output, display);
        }
        else writeExr(r.output, result->image);
    } catch (const std::bad_alloc&) {
        throw UsageError(tooLargeForMemory(s.width, s.height));
    } catch (const ImageError& e) {
        throw UsageError(e.what());  // the output path was checked, but the disk may be full
    }
    std::fprintf(stderr, "wrote %s: %s, %.0f spp in %s, estimated relmse %.3g", r.output.c_str(),
                 backendName.c_str(), result->samplesPerPixel, formatDuration(result->seconds).c_str(),
                 result->estimatedRelmse);
    if (processes) std::fprintf(stderr, ", %d ranks", processes->size());
    std::fprintf(stderr, "\n");
    if (const auto it = result->image.attributes.find("lucerna:auto"); it != result->image.attributes.end())
        std::fprintf(stderr, "auto: %s\n", it->second.c_str());
    // What a backend gave up to fit the machine (the preview's shadow maps), one line each.
    const std::string prefix = "lucerna:", suffix = ":degradation";  // lucerna:BACKEND:degradation
    for (const auto& [key, value] : result->image.attributes)
        if (key.starts_with(prefix) && key.ends_with(suffix) && !value.empty())
            std::fprintf(stderr, "note: %s: %s\n", key.substr(prefix.size(), key.size() - prefix.size() - suffix.size()).c_str(),
                         value.c_str());
    // Saved, but not the render asked for: a script can tell (README, "Interrupting").
    return savedEarly ? 130 : 0;
}

int compareImpl(const std::vector<std::string>& args) {
    if (args.size() != 2) throw UsageError("usage: lucerna compare TEST.exr REFERENCE.exr");
    Image test, ref;
    try {
        test = readExr(args[0]);
        ref = readExr(args[1]);
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    if (test.width != ref.width || test.height != ref.height)
        throw UsageError("image sizes differ: " + args[0] + " is " + std::to_string(test.width) + "x" +
                         std::to_string(test.height) + ", " + args[1] + " is " + std::to_string(ref.width) + "x" +
                         std::to_string(ref.height));
    std::cout << formatMetrics(compareImages(test, ref));
    return 0;
}

int convertImpl(const std::vector<std::string>& args) {
    if (args.size() != 2 && !(args.size() == 4 && args[2] == "--exposure"))
        throw UsageError("usage: lucerna convert IN.exr OUT.png [--exposure STOPS]");
    const float exposure = args.size() == 4 ? parseNumber<float>("--exposure", args[3], -64.0f, 64.0f) : 0.0f;
    checkOutputPath(args[1]);
    Image image;
    try {
        image = readExr(args[0]);
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    DisplaySettings display;
    display.exposureStops = exposure;
    writePngPicture(image, args[1], display);
    return 0;
}

}  // namespace

int render(const std::vector<std::string>& args, ProcessGroup* processes) {
    return runCommand([&] { return renderImpl(args, processes); });
}
int compare(const std::vector<std::string>& args) { return runCommand(compareImpl, args); }
int convert(const std::vector<std::string>& args) { return runCommand(convertImpl, args); }

void printUsage() {
    std::cout << "usage:\n"
                 "  lucerna [SCENE.json]                      open the application\n"
                 "  lucerna render SCENE.json -o OUT.exr|OUT.png [--backend NAME] [--spp N | --time SECONDS]\n"
                 "                 [--seed N] [--threads N] [--width W --height H] [--option NAME=VALUE]\n"
                 "                 [--save-on-interrupt]   Ctrl-C writes the passes done so far\n"
                 "                 [--layers albedo,normal,depth,illuminance,lights] [--illuminance-spp N]\n"
                 "                 extra EXR layers: the first visible surface, its illuminance in lux,\n"
                 "                 one layer per light\n"
                 "                 [--white-balance D65|lights|KELVIN]   the PNG's white (D65 by default)\n"
                 "  lucerna compare TEST.exr REFERENCE.exr    error metrics (SPEC.md section 4)\n"
                 "  lucerna info SCENE.json                   validate and print statistics\n"
                 "  lucerna convert IN.exr OUT.png [--exposure STOPS]   sRGB picture of an EXR\n"
                 "  lucerna bench SCENE.json --reference REF.exr --backends NAME[:k=v],... --time SECONDS\n"
                 "                [--out DIR] [--seed N] [--threads N] [--width W --height H] [--option NAME=VALUE]\n"
                 "                error against time per backend: DIR/bench.csv and DIR/bench.svg\n"
                 "  lucerna grid SCENE.json (--work-plane HEIGHT_M [--border M] | --corner X,Y,Z --u X,Y,Z --v X,Y,Z)\n"
                 "               [--spacing M] [--method path|ir|bdpt|mir|mlt|cmlt|preview] [--error F]\n"
                 "               [--time SECONDS] [--option NAME=VALUE] [--csv OUT.csv]\n"
                 "               illuminance on a calculation grid: Eavg, Emin, Emax, U0 (EN 12464-1)\n"
                 "               [--daylight-factor [--median-diffuse-illuminance LX]]   the daylight factor under\n"
                 "               the CIE overcast sky instead, with EN 17037's daylight provision\n"
                 "               [--task-area NAME]   the scene's task area, checked against its EN 12464-1 activity\n"
                 "               with its zones and the 2021 figures it asks: Ez at 1.2/1.6 m, walls, ceiling\n"
                 "               [--cylindrical] [--room-surfaces] (each whatever it asks) | [--horizontal-only]\n"
                 "               [--cylindrical] without --task-area: the points measure Ez about the grid's normal\n"
                 "  lucerna annual SCENE.json --weather FILE.epw (--work-plane HEIGHT_M | --task-area NAME) [--spacing M]\n"
                 "                 [--occupancy FROM-TO] [--dew-point C] [--csv OUT.csv] [--hourly OUT.csv]\n"
                 "                 [--hourly-error OUT.csv] [--seed N] [--threads N] [--sky-subdivision M] [--paths N] [--resume]\n"
                 "                 a year of daylight from the weather file: sDA, ASE, UDI, EN 17037's illuminance method\n"
                 "  lucerna annual SCENE.json --weather FILE.epw --export-hour MM-DD-HH OUT.json   one hour as a scene\n"
                 "  lucerna standards [--edition 2011|2021]   the bundled EN 12464-1 activities (default 2021)\n"
                 "  lucerna glare SCENE.json --observer X,Y,Z --view X,Y,Z [--method M] [--error F] [--time SECONDS]\n"
                 "                [--seed N] [--threads N]   discomfort glare (UGR, CIE 117) at an eye, per luminaire\n"
                 "  lucerna glare --table FILE.ies|FILE.ldt [--lumens LM] [--luminous-area W,L]\n"
                 "                the luminaire's UGR table by the tabular method (CIE 190's layout)\n"
                 "  lucerna report SCENE.json -o OUT.pdf [--method M] [--error F] [--seed N] [--samples N]\n"
                 "                 [--time SECONDS] [--spp N] [--render-error F] [--threads N] [--weather FILE.epw]\n"
                 "                 the lighting design report: room, schedule, luminaire data sheets, task areas\n"
                 "                 (plan, figures, checks, UGR), renders and method; the grids as `grid` computes them\n"
                 "  lucerna import MODEL -o SCENE.json [--meters-per-unit M] [--model-unit M] [--inline-meshes]\n"
                 "                 OBJ+MTL, glTF, FBX, COLLADA, ... as a scene; prints what was approximated\n"
                 "backends: auto";
    for (const BackendInfo& b : backendTable()) std::cout << ", " << b.name;
    std::cout << "\n";
}

}  // namespace lucerna::cli
