#include "app/glare_command.h"
#include "app/cli_support.h"

#include "core/photometry/glare.h"
#include "core/photometry/luminaire.h"
#include "core/number_format.h"
#include "core/scene/scene_io.h"
#include "core/photometry/ugr_table.h"
#include "render/photometry/glare_evaluation.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <optional>

namespace lucerna::cli {

namespace {

struct GlareArgs {
    std::string scene, table;
    std::optional<V3d> observer, view;
    std::optional<double> lumens;
    std::optional<V2d> luminousArea;
    GlareSettings settings;
    int threads = 0;
};

GlareArgs parseGlareArgs(const std::vector<std::string>& args) {
    GlareArgs g;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "--observer") g.observer = parseVector(a, value());
        else if (a == "--view") g.view = parseVector(a, value());
        else if (a == "--table") g.table = value();
        else if (a == "--lumens") g.lumens = parseNumber<double>(a, value(), 1e-6, 1e12);
        else if (a == "--luminous-area") {
            const std::string& text = value();
            const size_t comma = text.find(',');
            if (comma == std::string::npos) throw UsageError(a + ": expected W,L in metres, got '" + text + "'");
            g.luminousArea = V2d(parseNumber<double>(a, text.substr(0, comma), 1e-6, 1e3),
                                 parseNumber<double>(a, text.substr(comma + 1), 1e-6, 1e3));
        } else if (a == "--method") {
            g.settings.backgroundMethod = *parseGridMethod(value(), false);
        } else if (a == "--error") g.settings.targetRelativeError = parseNumber<double>(a, value(), 1e-6, 1.0);
        else if (a == "--time") g.settings.timeLimitSeconds = parseNumber<double>(a, value(), 1e-3, 1e7);
        else if (a == "--seed") g.settings.seed = parseNumber<uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--samples") g.settings.samplesPerPass = parseNumber<int>(a, value(), 1, 1 << 20);
        else if (a == "--threads") g.threads = parseNumber<int>(a, value(), 1, 4096);
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (g.scene.empty()) g.scene = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (!g.table.empty()) {
        if (!g.scene.empty() || g.observer || g.view)
            throw UsageError("glare: --table FILE takes no scene, --observer or --view");
        return g;
    }
    if (g.lumens || g.luminousArea) throw UsageError("glare: --lumens and --luminous-area go with --table FILE");
    if (g.scene.empty()) throw UsageError("glare: no scene file given (or --table FILE.ies|FILE.ldt)");
    if (!g.observer || !g.view) throw UsageError("glare: give the eye with --observer X,Y,Z and --view X,Y,Z");
    if (!horizontalLineOfSight(*g.view))
        throw UsageError("--view: the direction has no horizontal part (UGR assumes a horizontal line of sight)");
    return g;
}

std::string fixed(double x, int decimals) {
    if (!std::isfinite(x)) return "inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return buf;
}

int printTable(const GlareArgs& g) {
    GoniometricDistribution d;
    try {
        d = loadLuminaireFile(g.table);
    } catch (const LuminaireFileError& e) {
        throw UsageError(e.what());
    }
    UgrLuminaire luminaire;
    luminaire.distribution = &d;
    luminaire.fluxLm = g.lumens.value_or(0.0);
    if (g.luminousArea) luminaire.area.widthM = g.luminousArea->x, luminaire.area.lengthM = g.luminousArea->y;
    std::vector<UgrTable> tables;
    try {
        for (double spacing : {1.0, 0.25}) tables.push_back(ugrTable(luminaire, spacing));
    } catch (const std::invalid_argument& e) {
        throw UsageError(g.table + ": " + e.what() + (g.luminousArea ? "" : "; give --luminous-area W,L"));
    }
    const LuminousArea area = luminaire.area.empty() ? luminousAreaOf(d.luminous) : luminaire.area;
    std::printf("UGR table of %s (CIE 117 tabular method, CIE 190 layout): %.0f lm, luminous area %s x %s m%s\n",
                g.table.c_str(), tables[0].fluxLm, fixed(area.widthM, 3).c_str(), fixed(area.lengthM, 3).c_str(),
                area.elliptical ? " (elliptical)" : "");
    std::printf("observer at the middle of a wall at eye level, luminaires H above the eye; room X across and Y along "
                "the line of sight\n");
    std::printf("crosswise: line of sight along C0-C180, toward C0; endwise: along C90-C270, toward C90\n");
    for (const UgrTable& t : tables) {
        std::printf("\nspacing-to-height %.2f\n", t.spacingToHeight);
        const char* names[3] = {"ceiling", "walls", "floor"};
        for (int r = 0; r < 3; ++r) {
            std::printf("%-12s", names[r]);
            for (int v = 0; v < 2; ++v) {
                for (const UgrReflectances& s : kUgrReflectanceSets)
                    std::printf("%6.2f", r == 0 ? s.ceiling : r == 1 ? s.walls : s.floor);
                std::printf(v == 0 ? "   " : "\n");
            }
        }
        std::printf("%-12s%-33s%s\n", "room X x Y", "  viewed crosswise", "  viewed endwise");
        for (size_t k = 0; k < kUgrRooms.size(); ++k) {
            std::printf("%3gH x %2gH  ", kUgrRooms[k].x, kUgrRooms[k].y);
            for (int v = 0; v < 2; ++v) {
                for (double u : t.values[k][size_t(v)])
                    std::isfinite(u) ? std::printf("%6.1f", u) : std::printf("%6s", "-");
                std::printf(v == 0 ? "   " : "\n");
            }
        }
    }
    return 0;
}

int glareImpl(const std::vector<std::string>& args) {
    exitOnInterrupt("glare interrupted\n");
    const GlareArgs g = parseGlareArgs(args);
    if (!g.table.empty()) return printTable(g);
    Scene scene;
    try {
        scene = loadScene(g.scene);
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }

    catchInterrupts();
    TaskSystem tasks(g.threads);
    std::optional<GlareGridResult> result;
    auto job = tasks.submit([&](TaskContext& ctx) {
        GlareGridResult r = evaluateGlareGrid(scene, {*g.observer}, *g.view, g.settings, ctx);
        if (!ctx.isCancelled()) result = std::move(r);
    });
    waitShowingProgress(*job, std::string("glare ") + gridMethodName(g.settings.backgroundMethod));
    if (interrupted() || !result) {
        std::cerr << "glare interrupted\n";
        return 130;
    }
    const GlareGridResult& grid = *result;
    const GlareResult& r = grid.observers.front();
    const V3d& o = *g.observer;
    const V3d view = *horizontalLineOfSight(*g.view);
    std::printf("glare at (%g, %g, %g) looking (%.3g, 0, %.3g), background by %s\n", o.x, o.y, o.z, view.x, view.z,
                gridMethodName(grid.method));
    if (!r.ugr) {
        std::printf("UGR: none (%s)\n", r.sources.empty() ? "no luminaire in the field of view"
                                                         : "no indirect light reaches the eye");
    } else {
        std::printf("UGR %s +- %s (95%%)\n", fixed(*r.ugr, 1).c_str(), fixed(r.ugrErrorBar, 1).c_str());
        std::printf("background luminance Lb %s cd/m^2 (indirect illuminance at the eye %s lx) after %d passes, %s%s\n",
                    fixed(r.backgroundLuminanceCdM2, 2).c_str(), fixed(r.backgroundLuminanceCdM2 * std::numbers::pi, 1).c_str(),
                    grid.passes, formatDuration(grid.seconds).c_str(), grid.converged ? "" : " (target not reached)");
    }
    if (!r.sources.empty()) {
        std::printf("%-24s %12s %12s %7s %7s\n", "light", "L (cd/m^2)", "omega (sr)", "p", "share");
        constexpr size_t kListed = 20;  // the rest together in one line
        double rest = 0;
        for (size_t i = 0; i < r.sources.size(); ++i) {
            const LuminaireGlare& s = r.sources[i];
            if (i >= kListed) {
                rest += s.share;
                continue;
            }
            std::printf("%-24s %12.4g %12.4g %7.2f %6.1f%%\n", s.light.c_str(), s.luminanceCdM2, s.solidAngleSr,
                        s.positionIndex, 100 * s.share);
        }
        if (r.sources.size() > kListed)
            std::printf("%zu more luminaires in the field of view, %.1f%% together\n", r.sources.size() - kListed, 100 * rest);
    }
    for (const std::string& note : r.notes) std::printf("note: %s\n", note.c_str());
    return 0;
}

}  // namespace

int glare(const std::vector<std::string>& args) { return runCommand(glareImpl, args); }

}  // namespace lucerna::cli
