#include "render/photometry/glare_evaluation.h"

#include "core/photometry/glare.h"
#include "core/photometry/luminaire.h"
#include "render/photometry/grid_diagnosis.h"
#include "render/photometry/irradiance_estimator.h"
#include "render/trace/render_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;
constexpr double kOwnSurfaceM = 0.01;  // a surface this close to a luminaire's centre does not hide it

// The scene UGR rates: new (no maintenance), lights switched off left out, no daylight.
struct GlareScene {
    SceneSnapshot scene;
    std::vector<std::string> notes;
};

GlareScene glareScene(const Scene& loaded) {
    Scene s = withoutMaintenance(loaded);
    bool daylight = s.sky.has_value();
    s.sky.reset();
    std::erase_if(s.lights, [&](const Light& l) {
        const bool day = l.type == LightType::Sun || l.type == LightType::Directional;
        daylight = daylight || (day && l.on);
        return day;
    });
    GlareScene g;
    if (daylight) g.notes.push_back("daylight (sky, sun, directional lights) left out: UGR rates the electric lighting");
    int emitters = 0;
    for (const Object& o : s.objects) {
        const Material* m = s.findMaterial(o.material);
        emitters += m && m->type == MaterialType::Emitter && luminance(m->radiance) > 0;
    }
    if (emitters > 0)
        g.notes.push_back(std::to_string(emitters) + " emitter object" + (emitters > 1 ? "s" : "") +
                          " not rated as glare sources (area lights); their light, direct included, counts in the background");
    g.scene = withoutLightsSwitchedOff(std::make_shared<const Scene>(std::move(s)));
    return g;
}

// Names gathered under one reason, for a note: "'a', 'b' and 3 more: reason".
class LeftOut {
public:
    void add(const std::string& reason, const std::string& light) { byReason_[reason].push_back(light); }
    void appendTo(std::vector<std::string>& notes) const {
        for (const auto& [reason, names] : byReason_) {
            std::string line;
            const size_t shown = std::min<size_t>(names.size(), 4);
            for (size_t i = 0; i < shown; ++i) line += (i ? ", '" : "'") + names[i] + "'";
            if (names.size() > shown) line += " and " + std::to_string(names.size() - shown) + " more";
            notes.push_back(line + ": " + reason);
        }
    }

private:
    std::map<std::string, std::vector<std::string>> byReason_;
};

struct SourceTerm {
    std::string light;
    GlareTerm term;
};

// The luminaires an eye sees, with their terms.
std::vector<SourceTerm> sourcesSeen(const RenderScene& rs, const V3d& eye, const V3d& lineOfSight, LeftOut& leftOut) {
    const Scene& scene = rs.scene();
    const double mpu = scene.metersPerUnit;
    std::vector<SourceTerm> sources;
    for (const Light& light : scene.lights) {
        if (light.type == LightType::Point || light.type == LightType::Spot) {
            leftOut.add("no luminous area (point or spot light)", light.name);
            continue;
        }
        if (light.type != LightType::Luminaire || !light.luminaire || !light.luminaire->distribution) continue;
        const LuminousArea area = luminousAreaOf(light);
        if (area.empty()) {
            leftOut.add("its file states no luminous area (give \"luminous_area\": [w, l])", light.name);
            continue;
        }
        const GlarePlacement placement = placeInView(eye, lineOfSight, light.position, mpu);
        if (!placement.inField()) continue;
        const LuminaireFrame frame = luminaireFrame(light.direction, light.luminaire->rotationDeg.value_or(0.0));
        const LuminaireSight sight = seeLuminaire(*light.luminaire->distribution, luminaireCandelaScale(light), frame,
                                                  area, light.position * mpu, eye * mpu, lineOfSight);
        if (!(sight.intensityCd > 0)) continue;  // dark toward the eye
        if (!(sight.projectedAreaM2 > 0)) {
            leftOut.add("its luminous area faces away from the eye", light.name);
            continue;
        }
        const V3d toLight = light.position - eye;
        const double lengthM = toLight.length() * mpu;
        Ray ray{toFloat(eye), toFloat(toLight), 0.0f, float(std::max(0.0, 1.0 - kOwnSurfaceM / lengthM))};
        const double through = luminance(rs.transmittance(ray));
        if (!(through > 0)) {
            leftOut.add("hidden from the eye", light.name);
            continue;
        }
        sources.push_back({light.name, glareTerm(sight.intensityCd * through, sight.projectedAreaM2, placement)});
    }
    return sources;
}

struct ObserverState {
    std::vector<SourceTerm> sources;
    double sum = 0;
    double deltaLux = 0;             // the direct light of the delta lights at the eye
    std::vector<std::string> notes;
    int firstPoint = -1;             // its first copy among the background's points; -1: none
};

GlareResult resultOf(const ObserverState& o, double indirectLux, double errorLux) {
    GlareResult r;
    r.notes = o.notes;
    if (o.sources.empty()) {
        r.notes.push_back("no luminaire in the field of view");
        return r;
    }
    for (const SourceTerm& s : o.sources)
        r.sources.push_back({s.light, s.term.luminanceCdM2, s.term.solidAngleSr, s.term.positionIndex,
                             o.sum > 0 ? s.term.value() / o.sum : 0.0});
    std::stable_sort(r.sources.begin(), r.sources.end(),
                     [](const LuminaireGlare& a, const LuminaireGlare& b) { return a.share > b.share; });
    r.backgroundLuminanceCdM2 = std::max(0.0, indirectLux) / kPiD;
    r.ugr = unifiedGlareRating(r.backgroundLuminanceCdM2, o.sum);
    if (!r.ugr) {
        r.notes.push_back("no indirect light reaches the eye: UGR is undefined");
        return r;
    }
    r.ugrErrorBar = indirectLux > errorLux ? 8.0 * std::log10(indirectLux / (indirectLux - errorLux))
                                           : std::numeric_limits<double>::infinity();
    return r;
}

}  // namespace

GlareGridResult evaluateGlareGrid(const Scene& loaded, const std::vector<V3d>& positions, const V3d& view,
                                  const GlareSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GlareGridResult&)>& onPass) {
    const std::optional<V3d> lineOfSight = horizontalLineOfSight(view);
    if (!lineOfSight) throw std::invalid_argument("the view direction has no horizontal part (UGR assumes a horizontal line of sight)");
    const GlareScene g = glareScene(loaded);
    const RenderScene rs(g.scene, 8, 8);  // the camera is unused
    const IrradianceEstimator estimator(rs);
    const bool throughPanes = carriesLightThroughGlass(settings.backgroundMethod);
    const V3f normal = toFloat(*lineOfSight);

    GlareGridResult result;
    result.method = settings.backgroundMethod;
    std::vector<ObserverState> observers(positions.size());
    std::vector<size_t> needing;  // observers with a source: they need the background
    for (size_t i = 0; i < positions.size(); ++i) {
        ObserverState& o = observers[i];
        LeftOut leftOut;
        o.sources = sourcesSeen(rs, positions[i], *lineOfSight, leftOut);
        o.notes = g.notes;
        leftOut.appendTo(o.notes);
        for (const SourceTerm& s : o.sources) o.sum += s.term.value();
        if (o.sources.empty()) continue;
        o.deltaLux = kLumensPerWatt * luminance(estimator.deltaLightsIrradiance({toFloat(positions[i]), normal}, throughPanes));
        needing.push_back(i);
    }
    const auto finish = [&](const std::vector<double>& indirect, const std::vector<double>& error) {
        result.observers.clear();
        for (size_t i = 0; i < observers.size(); ++i) result.observers.push_back(resultOf(observers[i], indirect[i], error[i]));
    };
    std::vector<double> indirect(positions.size(), 0.0), error(positions.size(), 0.0);
    if (needing.empty()) {
        finish(indirect, error);
        result.converged = true;
        if (onPass) onPass(result);
        return result;
    }

    // Copies of each eye, so that a few observers still keep every thread busy (the path and ir
    // estimators give a task 16 points); each copy draws its own samples.
    const bool pointPasses = settings.backgroundMethod == GridMethod::Path || settings.backgroundMethod == GridMethod::Vpl;
    const int threads = tbb::this_task_arena::max_concurrency();
    const int copies =
        pointPasses ? std::clamp(int((16 * threads + needing.size() - 1) / needing.size()), 1, 64) : 1;
    std::vector<V3d> points;
    for (size_t i : needing) {
        observers[i].firstPoint = int(points.size());
        for (int c = 0; c < copies; ++c) points.push_back(positions[i]);
    }

    GridSettings grid;
    grid.method = settings.backgroundMethod;
    grid.samplesPerPass = settings.samplesPerPass;
    grid.targetRelativeError = 1e-12;  // the stop is decided here, on the indirect part alone
    grid.timeLimitSeconds = settings.timeLimitSeconds;
    grid.seed = settings.seed;
    TaskContext background{CancellationToken()};
    bool glassMissing = false;
    computeGridIlluminance(rs, points, *lineOfSight, grid, background, [&](const GridResult& r) {
        bool trusted = !pointPasses || r.passes >= grid.minPasses;
        double sumIndirect = 0;
        for (size_t i : needing) {
            const ObserverState& o = observers[i];
            double lux = 0, variance = 0;
            for (int c = 0; c < copies; ++c) {
                const size_t k = size_t(o.firstPoint + c);
                lux += r.lux[k];
                variance += r.errorLux[k] * r.errorLux[k];
            }
            indirect[i] = lux / copies - o.deltaLux;
            error[i] = std::sqrt(variance) / copies;
            trusted = trusted && std::isfinite(error[i]);
            sumIndirect += std::max(0.0, indirect[i]);
        }
        // As the grids do: relative to the value, or to a thousandth of the mean for a dark eye.
        const double floor = 1e-3 * sumIndirect / double(needing.size());
        double worst = 0;
        for (size_t i : needing)
            worst = std::max(worst, error[i] == 0 ? 0.0 : error[i] / std::max({indirect[i], floor, 1e-300}));
        result.passes = r.passes;
        result.seconds = r.seconds;
        result.converged = trusted && worst <= settings.targetRelativeError;
        glassMissing = r.errorBarUnknown;
        finish(indirect, error);
        if (glassMissing)
            for (size_t i : needing)
                result.observers[i].notes.push_back(std::string(gridMethodName(r.method)) +
                                                    " cannot carry light that reaches the eye only through glass: "
                                                    "the background misses it (use bdpt)");
        double progress = trusted && worst > 0 ? std::min(1.0, std::pow(settings.targetRelativeError / worst, 2.0))
                                               : trusted ? 1.0 : 0.0;
        if (settings.timeLimitSeconds > 0) progress = std::max(progress, std::min(1.0, r.seconds / settings.timeLimitSeconds));
        ctx.setProgress(progress);
        if (onPass) onPass(result);
        if (result.converged || ctx.isCancelled()) background.token().cancel();
    });
    if (result.observers.empty()) finish(indirect, std::vector<double>(positions.size(), std::numeric_limits<double>::infinity()));
    return result;
}

GlareResult evaluateGlare(const Scene& scene, const GlareObserver& observer, const GlareSettings& settings,
                          TaskContext& ctx) {
    GlareGridResult r = evaluateGlareGrid(scene, {observer.position}, observer.view, settings, ctx);
    return std::move(r.observers.front());
}

}  // namespace lucerna
