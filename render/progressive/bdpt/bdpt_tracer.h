#pragma once
// The per-thread part of the bdpt backend: bidirectional path tracing (Veach & Guibas 1994;
// Veach 1997, chapter 10; modelled on pbrt-v3 chapter 16). A camera subpath and a light subpath
// are traced, then every prefix pair (s light vertices, t camera vertices) is connected:
//   s = 0   the camera subpath itself hits the front of an emitter;
//   s = 1   next-event estimation: a fresh point on a light, joined to camera vertex t-1, the
//           light chosen as `light_sampler` says (the tree: by its importance at that vertex);
//   t = 1   light tracing: light vertex s-1 joined to the pinhole and splatted onto the film;
//   else    light vertex s-1 joined to camera vertex t-1 by a shadow ray;
// and at an irradiance sensor's point, next-event estimation for the paths of one edge
// (sensor_direct.h).
// Each contribution is weighted by the power heuristic over all strategies that could have made
// the same path (eq. 10.9 with beta = 2), computed from the per-vertex densities pdfFwd/pdfRev
// so that nothing is counted twice. Light subpaths start by power, so the s = 1 strategy's
// density carries the tree's probability at x1 over power's (nextEventRatio) in every weight.
// Delta lights (no s = 0), delta BSDFs (mirror, glass: never a connection vertex) and
// one-sided emitters are handled as the path backend handles them.

#include "render/backend/film.h"
#include "render/progressive/bdpt/bdpt_settings.h"
#include "render/progressive/bdpt/bdpt_vertex.h"
#include "render/trace/sample_generator.h"

#include <array>
#include <optional>
#include <vector>

namespace lucerna {

// The paths behind one sample, for kernels that perturb a single path of it (cmlt's path-space
// lens sub-chain): the two subpaths and, for every strategy that contributed, its (s, t), its
// MIS-weighted contribution, where it lands and the vertex it sampled afresh (s = 1: the light
// point; t = 1: the sensor point), so that each path can be rebuilt vertex by vertex.
struct StrategyRecord {
    int s = 0, t = 0;
    Rgb weighted{0, 0, 0};   // finite, not black
    float misWeight = 1;     // weighted = misWeight times the unweighted contribution
    float rasterX = 0, rasterY = 0;
    PathVertex sampled;      // s = 1 or t = 1 only; s = 1: its pdfFwd the density it was drawn with
    // Next-event estimation at an irradiance sensor's point (s = t = 1, at the camera sample's
    // raster point): light straight from an emitter whose path is kept nowhere, so no
    // perturbation can rebuild it.
    bool sensorNextEvent = false;
};
struct SampledPaths {
    std::vector<PathVertex> camera, light;
    std::vector<StrategyRecord> strategies;

    // Path x_0 (the sensor) ... x_k (the light) of strategy i, appended to `out` (cleared); not
    // for a sensorNextEvent record, which keeps no path.
    void path(const StrategyRecord& r, std::vector<PathVertex>& out) const;
};

class BdptTracer {
public:
    BdptTracer(const RenderScene& scene, const BdptSettings& settings);

    // One bidirectional sample: a camera subpath through raster point (x, y) and one light
    // subpath. Returns the radiance estimate for the camera sample's own pixel (strategies with
    // t >= 2) and appends the light-tracing contributions (t = 1) to `splats`, already divided
    // by nothing: a pass that traces one light subpath per pixel normalises them like its
    // camera samples (see cameraImportance). Non-finite contributions are dropped.
    Rgb sample(float x, float y, SampleGenerator& rng, std::vector<FilmSplat>& splats);
    // The same, with the camera ray's closest hit already traced (as part of a packet of
    // coherent camera rays); `primaryHit` must be what RenderScene::intersect gives for the
    // camera ray through (x, y). With reuseLightSubpath, the light subpath of the previous call
    // is used again instead of being traced from rng's light stream, and so are its
    // light-tracing (t = 1) contributions, which do not depend on the camera subpath: for a
    // caller whose generator would give the same light and connection numbers (a Metropolis
    // kernel that moves only the camera side).
    Rgb sample(float x, float y, const std::optional<SurfacePoint>& primaryHit, bool reuseLightSubpath,
               SampleGenerator& rng, std::vector<FilmSplat>& splats);
    // For a kernel that moves only the light side: traceCameraSubpathOnly traces the camera subpath
    // through (x, y) from rng's camera stream alone, and sampleWithCameraSubpath then completes a
    // sample as sample() would, with that camera subpath and a light subpath traced from rng's
    // light stream (rng giving the same camera numbers).
    void traceCameraSubpathOnly(float x, float y, SampleGenerator& rng);
    Rgb sampleWithCameraSubpath(float x, float y, SampleGenerator& rng, std::vector<FilmSplat>& splats);

    // While set, every sample also writes its paths there (nullptr: not recorded).
    void recordPaths(SampledPaths* sink) { record_ = sink; }

private:
    enum class Reuse { Nothing, LightSubpath, CameraSubpath };
    Rgb sampleTraced(float x, float y, const std::optional<SurfacePoint>* primaryHit, Reuse reuse,
                     SampleGenerator& rng, std::vector<FilmSplat>& splats);
    void traceCameraSubpath(float x, float y, const std::optional<SurfacePoint>* primaryHit, SampleGenerator& rng);
    void traceLightSubpath(SampleGenerator& rng);
    // Extends `path` from its last vertex along `ray`, adding at most maxAdded vertices; pdfDir
    // is the solid-angle density of the ray's direction at the last vertex (pbrt's RandomWalk).
    // firstHit, when given, is the closest hit of `ray`, already traced.
    void randomWalk(Ray ray, Rgb beta, float pdfDir, int maxAdded, bool cameraSide, SampleGenerator& rng,
                    std::vector<PathVertex>& path, const std::optional<SurfacePoint>* firstHit = nullptr) const;
    // Unweighted contribution of strategy (s, t), times its MIS weight when `weighted`. For
    // t = 1 it writes the raster point it lands on.
    // `record`, when given, receives the MIS weight and the vertex sampled afresh (s = 1, t = 1).
    Rgb connect(int s, int t, bool weighted, SampleGenerator& rng, float& rasterX, float& rasterY,
                StrategyRecord* record = nullptr) const;
    // Power-heuristic weight of strategy (s, t); `sampled` is the fresh light vertex (s = 1) or
    // the pinhole (t = 1) that replaces the subpath's own.
    float misWeight(int s, int t, const PathVertex* sampled) const;
    bool connectible(const PathVertex& v) const;
    // Next-event estimation's `receiving` normal at surface vertex x1 of a path whose next
    // vertex toward the camera is x2: the side of x1 facing x2 (as the path backend's).
    V3f receivingNormal(const PathVertex& x1, const PathVertex& x2) const;
    // tau: how much likelier next-event estimation at x1 (toward x2) chooses the light of x0
    // than a light subpath starts from it by power (LightSampler::selectionRatio; 1 under power
    // selection, and where x1 is the camera, which never estimates next events).
    float nextEventRatio(const PathVertex& x0, const PathVertex& x1, const PathVertex& x2) const;
    PathVertex cameraVertex(int point) const;
    // sensorRayWeight of a path of one edge, from the sensor vertex to the emitter (or the
    // environment) it found.
    float sensorDirectWeight(const PathVertex& sensor, const PathVertex& light) const;
    // The vertex of a camera subpath that left the scene along `ray` (the environment's), with
    // the walk's throughput and the solid-angle density of its direction.
    PathVertex escapedVertex(const Ray& ray, const Rgb& beta, float pdfDir) const;

    const RenderScene& scene_;
    BdptSettings settings_;
    VertexDensities densities_;
    std::vector<PathVertex> camera_, light_;  // reused from sample to sample
    // The t = 1 contributions of light_ and how many numbers they read (kept for Reuse::LightSubpath).
    std::vector<StrategyRecord> lightTracingSplats_;
    int lightTracingNumbers_ = 0;
    SampledPaths* record_ = nullptr;
    // nextEventRatio's last answers (per tracer, so per thread).
    struct TauEntry {
        uint32_t light = 0xffffffffu;  // an emitter's triangle, or a light's number
        bool onSurface = false;
        V3f p{0, 0, 0}, receiving{0, 0, 0};
        float tau = 1;
    };
    mutable std::array<TauEntry, 8> tauCache_{};
    mutable size_t tauNext_ = 0;
};

}  // namespace lucerna
