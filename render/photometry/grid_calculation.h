#pragma once
// Illuminance on the points of a calculation grid (core/photometry/calculation_grid.h), progressively, by
// one of three kinds of method:
//   - path, ir: the irradiance estimators of those backends (irradiance_estimator.h). Each pass
//     adds independent estimates at every point, and the error bar of a point comes from the
//     spread of its per-pass means (batch means: within a pass the VPL method shares one VPL set
//     between points and samples, across passes everything is independent).
//   - bdpt, mir, mlt, cmlt: the backend itself renders the grid's points as irradiance sensors
//     (sensor.h), in independent replicas (own seeds, own chains, own normalisations); the error
//     bar comes from the spread of the replicas' estimates (Student's t), since the passes of a
//     Markov chain are not independent. Delta lights, which no ray can hit, are summed exactly
//     and added, as the path and ir estimators do.
//   - preview: a hemicube of preview frames at each point (hemicube_irradiance.h), fresh VPLs and
//     area-light samples each pass, error bars from the pass means as for path and ir. It
//     converges to the preview's own answer (clamped VPLs, shadow maps), not to the exact one.
//
// The error bar is the 95% half-width, Student's t times the standard error of the mean. The calculation ends
// when every point's error bar is within the target fraction of its value (after a few passes,
// so that the spread itself is estimated), at the time limit, or when cancelled.

#include "core/process_group.h"
#include "core/task_system.h"
#include "render/photometry/irradiance_estimator.h"

#include <functional>
#include <map>
#include <cstdint>
#include <string>
#include <vector>

namespace lucerna {

enum class GridMethod { Path, Vpl, Bdpt, Mir, Mlt, Cmlt, Preview };
inline constexpr GridMethod kGridMethods[] = {GridMethod::Path, GridMethod::Vpl, GridMethod::Bdpt, GridMethod::Mir,
                                              GridMethod::Mlt,  GridMethod::Cmlt, GridMethod::Preview};

// The name of the backend whose machinery a method uses ("path", "ir", "bdpt", "mir", "mlt",
// "cmlt", "preview"); nothing for another name.
std::optional<GridMethod> gridMethodFromName(const std::string& name);
const char* gridMethodName(GridMethod method);

// What a grid's points measure: the illuminance on the side the normal faces, or the
// cylindrical illuminance about it (EN 12464-1:2021's Ez, the normal then the cylinder's axis,
// up: the mean over azimuths of the illuminance on a vertical plane; estimated by planes at
// random azimuths, the delta lights' part exactly; irradiance_estimator.h).
enum class GridQuantity { Planar, Cylindrical };

struct GridSettings {
    GridMethod method = GridMethod::Path;
    GridQuantity quantity = GridQuantity::Planar;
    // Auto: the cheapest method to start, replaced by one that short pilots between its passes
    // measure to be clearly faster on the points (grid_auto.h), among those that carry light
    // through glass where a lamp reaches some point only through it (grid_diagnosis.h); in a
    // distributed grid, where the processes must agree without
    // measuring alike, bdpt when a lamp reaches a point only through glass, else path. The time
    // limit covers the pilots. `method` is then ignored.
    bool autoMethod = false;
    // Estimates per point per pass; 0: the method's default, 16 for path and 1 for ir, whose
    // variance comes mostly from the VPL set, fresh each pass (measured on the interior scene:
    // 1 estimate on 16 light paths per pass reached 2% four times sooner than 4 on 64).
    int samplesPerPass = 0;
    int vplPathsPerPass = 16;      // Vpl: light paths of each pass's VPL set
    double targetRelativeError = 0.02;
    int minPasses = 8;             // path, ir: before the spread of the pass means is trusted
    int replicas = 8;              // bdpt, mir, mlt, cmlt: independent renders of the sensors
    int sensorPixelsPerSide = 2;   // bdpt, mir, mlt, cmlt: each point's block of pixels (sensor.h)
    std::map<std::string, std::string> backendOptions;  // all but path, ir: as render's --option
    // How next-event estimation chooses lights, for path and ir (the other methods' backends
    // read light_sampler from backendOptions); build the RenderScene with it.
    LightSelection lightSelection = kDefaultLightSelection;
    double timeLimitSeconds = 0;   // 0: no limit
    uint64_t seed = 1;
    // A grid shared among processes (`mpirun -n N lucerna grid`, core/process_group.h): path, ir
    // and preview deal out blocks of points, bdpt, mir, mlt and cmlt their replicas; after each
    // round the processes exchange their values, so that every one holds the whole result and
    // all stop together. Each point's or replica's samples are drawn as one process draws them,
    // so the values are those of one process. Every process calls computeGridIlluminance;
    // nullptr: this process alone.
    ProcessGroup* processes = nullptr;
};

struct GridResult {
    std::vector<double> lux;         // mean illuminance per point
    std::vector<double> errorLux;    // 95% half-width per point (infinite before two passes)
    int passes = 0;                  // path, ir: passes; the others: passes of each replica
    long long samplesPerPoint = 0;   // estimates (camera samples) per point, all replicas together
    double seconds = 0;
    double prepareSeconds = 0;       // of seconds, before the first pass (bdpt, mir, mlt, cmlt: preparing the replicas)
    double maxRelativeError = 0;     // max over points of errorLux / max(lux, Eavg / 1000) (0 / 0: 0), points inside geometry left out
    bool converged = false;          // every point within the target
    GridMethod method = GridMethod::Path;  // the method used (auto's choice)
    // auto: what its pilots measured and which method ran (grid_auto.h), one line; empty otherwise.
    std::string autoMeasured;
    // Per point, 1 when inside closed geometry (grid_diagnosis.h): left out of the figures and of
    // the convergence test. Empty when nothing was checked.
    std::vector<uint8_t> insideGeometry;
    // Points a delta light reaches only through glass; when the method cannot carry that light
    // (path, ir, preview), their values miss it and no error bar is backed: errorBarUnknown.
    int litThroughGlass = 0;
    bool errorBarUnknown = false;
};

// Computes the illuminance (lux, 683 Y(E)) on `points` (scene units), measured on the side the
// unit `normal` faces, after checking the points (grid_diagnosis.h): those inside geometry are
// marked, and light through glass that the method cannot carry is flagged. Progress in ctx is the fraction of the error target reached (or of the time
// limit); `onPass`, if given, sees the result after each pass (on the calling thread).
GridResult computeGridIlluminance(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                  const GridSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GridResult&)>& onPass = {});

// The grid of a scene as `lucerna grid` and the report compute it, so that their numbers agree
// for the same settings: the scene as rendered (core/scene/scene.h, sceneAsRendered: the lights
// switched off left out, maintenance factors applied), compiled with settings.lightSelection,
// then computeGridIlluminance. Cancelled before the calculation starts (and not distributed, where
// every process goes on to the exchanges): an empty result.
GridResult computeSceneGrid(const SceneSnapshot& scene, const std::vector<V3d>& points, const V3d& normal,
                            const GridSettings& settings, TaskContext& ctx,
                            const std::function<void(const GridResult&)>& onPass = {});

}  // namespace lucerna
