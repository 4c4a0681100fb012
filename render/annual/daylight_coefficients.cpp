#include "render/annual/daylight_coefficients.h"

#include "render/trace/rng.h"
#include "render/trace/warp.h"

#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr float kPiF = std::numbers::pi_v<float>;

}  // namespace

DaylightCoefficientTracer::DaylightCoefficientTracer(const RenderScene& scene, const SkyPatches& patches,
                                                     const SkyPatches& coarse, const SunPathGrid& sun,
                                                     const DaylightCoefficientSettings& settings)
    : scene_(scene), patches_(patches), coarse_(coarse), sun_(sun), settings_(settings) {
    for (int i = 0; i < sun_.nodeCount(); ++i)
        if (sun_.nodeDirection(i).y > 0) upperNodes_.push_back(i);
}

float DaylightCoefficientTracer::sunResponse(const PathRecords::SunVertex& v, const V3f& towardSun) const {
    const ShadingMaterial& mat = scene_.material(v.material);
    const V3f wiLocal = v.frame.toLocal(towardSun);
    if (!(wiLocal.z > 0)) return 0;
    const Rgb f = bsdfEval(mat, v.woLocal, wiLocal);
    if (isBlack(f)) return 0;
    const Rgb through = scene_.transmittance(Ray{v.point.spawnOrigin(towardSun), towardSun});
    return luminance(v.throughput * f * through) * wiLocal.z;
}

float DaylightCoefficientTracer::sunIndirectAt(const PathRecords& records, const V3f& towardSun) const {
    if (!(towardSun.y > 0)) return 0;
    float sum = 0;
    for (const PathRecords::SunVertex& v : records.sunVertices) sum += sunResponse(v, towardSun);
    return sum;
}

template <class OnEscape, class OnVertex>
void DaylightCoefficientTracer::tracePath(Ray ray, Rng& rng, const OnEscape& onEscape, const OnVertex& onVertex) const {
    Rgb throughput(1, 1, 1);
    for (int depth = 0;; ++depth) {
        Rgb through;
        const auto hit = scene_.intersect(ray, nullptr, &through);
        throughput *= through;  // panes crossed on the way
        if (!hit) {
            onEscape(ray.direction.normalized(), luminance(throughput), depth);
            return;
        }
        const ShadingMaterial& mat = scene_.material(hit->material);
        if (mat.isEmitter() || depth >= 64) return;  // electric light is off
        const V3f wo = -ray.direction.normalized();
        const Frame frame(shadingNormal(mat, hit->ng, wo));
        const V3f woLocal = frame.toLocal(wo);
        if (!mat.isDelta()) onVertex(PathRecords::SunVertex{*hit, hit->material, frame, woLocal, throughput});
        BsdfSample bs;
        const V2f u = rng.next2D();
        const float uLobe = rng.next1D();
        if (!bsdfSample(mat, woLocal, u, uLobe, bs)) return;
        throughput *= bs.weight;
        if (isBlack(throughput)) return;
        if (depth + 1 >= 3) {  // Russian roulette, as the path tracer plays it
            const float survive = std::min(0.95f, maxComponent(throughput));
            if (rng.next1D() >= survive) return;
            throughput /= survive;
        }
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
    }
}

template <class OnCell>
void DaylightCoefficientTracer::directView(const V3f& position, const V3f& normal, int side, const OnCell& onCell) const {
    const int ground = patches_.count();
    for (int patch = 0; patch < ground; ++patch) {
        const std::vector<V3d> cells = patches_.cells(patch, side);
        const double cellAngle = patches_.solidAngle(patch) / double(cells.size());
        for (const V3d& sky : cells)
            for (const V3d& w : {sky, V3d(sky.x, -sky.y, sky.z)}) {  // the ground: the cells mirrored
                const V3f wf(w);
                const float cosine = wf.dot(normal);
                if (!(cosine > 0)) continue;
                Rgb through;
                if (scene_.intersect(Ray{position, wf}, nullptr, &through)) continue;
                onCell(w.y > 0 ? patch : ground, wf, float(cellAngle) * cosine * luminance(through));
            }
    }
}

PointCoefficients DaylightCoefficientTracer::trace(const V3f& position, const V3f& normal, uint64_t pointIndex,
                                                   PathRecords* records) const {
    const int batches = settings_.batches, ground = patches_.count(), coarseGround = coarse_.count();
    const int coarseBins = coarseGround + 1, nodes = sun_.nodeCount();
    PointCoefficients c;
    c.sky.assign(size_t(ground) + 1, 0.0f);
    c.coarseSky.assign(size_t(batches) * coarseBins, 0.0f);
    c.sunIndirect.assign(size_t(nodes), 0.0f);
    c.sunIndirectBatches.assign(size_t(batches) * nodes, 0.0f);
    const Frame sensorFrame(normal);
    Rng rng(hashSeed(settings_.seed, pointIndex, 0x616e6e75616cULL));

    // E = pi x the mean of L over cosine-weighted directions: each of N paths carries pi / N, and
    // each batch is the mean of its N / batches. The first direction is stratified within each
    // batch (a jittered grid over the square): the sky seen straight through a window is most of
    // a point's light and its visibility is piecewise smooth, so stratifying it beats independent
    // samples by far, and the batches stay independent of each other.
    const auto firstRay = [&](int s, int count) {
        const int side = std::max(1, int(std::sqrt(double(count / batches))));
        const int i = s / batches;
        V2f u = rng.next2D();
        if (i < side * side) u = V2f((float(i % side) + u.x) / float(side), (float(i / side) + u.y) / float(side));
        return Ray{position, sensorFrame.toWorld(squareToCosineHemisphere(u))};
    };

    // The sky and the ground seen straight: the quadrature, on cells twice as fine per side as
    // the patches' luminance cells (the window's edges cut through cells: the visibility is what
    // needs them small); for the discretisation's points, also one twice as fine again.
    const int side = 2 * int(std::lround(std::sqrt(double(patches_.samples(0).size()))));
    directView(position, normal, side, [&](int bin, const V3f&, float weight) { c.sky[size_t(bin)] += weight; });
    if (records) {
        records->direct = c.sky;
        directView(position, normal, 2 * side, [&](int, const V3f& w, float weight) { records->directCells.push_back({w, weight}); });
    }

    // The sky and the ground after reflections, binned by the direction each path leaves the
    // scene in; a path that leaves at once is the quadrature's.
    const float perPath = kPiF / float(settings_.paths);
    for (int s = 0; s < settings_.paths; ++s) {
        const int batch = s % batches;
        const auto escape = [&](const V3f& w, float y, int depth) {
            if (depth == 0) return;
            const V3d wd(w);
            const int bin = wd.y > 0 ? patches_.patchOf(wd) : ground;
            const int coarseBin = wd.y > 0 ? coarse_.patchOf(wd) : coarseGround;
            c.sky[size_t(bin)] += y * perPath;
            c.coarseSky[size_t(batch) * coarseBins + coarseBin] += y * perPath * float(batches);
            if (records) records->escapes.push_back({w, y * perPath});
        };
        tracePath(firstRay(s, settings_.paths), rng, escape, [](const PathRecords::SunVertex&) {});
    }

    // The sun after reflections: next-event estimation toward every node at every vertex of
    // paths of their own (fewer: each vertex costs a shadow ray per node).
    const float perSunPath = kPiF / float(settings_.sunPaths);
    for (int s = 0; s < settings_.sunPaths; ++s) {
        const int batch = s % batches;
        const auto vertex = [&](PathRecords::SunVertex v) {
            v.throughput *= perSunPath;
            for (int node : upperNodes_) {
                const float r = sunResponse(v, V3f(sun_.nodeDirection(node)));
                if (!(r > 0)) continue;
                c.sunIndirect[size_t(node)] += r;
                c.sunIndirectBatches[size_t(batch) * nodes + node] += r * float(batches);
            }
            if (records) records->sunVertices.push_back(v);
        };
        tracePath(firstRay(s, settings_.sunPaths), rng, [](const V3f&, float, int) {}, vertex);
    }
    return c;
}

}  // namespace lucerna
