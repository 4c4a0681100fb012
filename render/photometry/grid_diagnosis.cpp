#include "render/photometry/grid_diagnosis.h"

#include "render/photometry/grid_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <tbb/parallel_for.h>
#include <numbers>

namespace lucerna {

namespace {
// A fixed cosine-weighted spiral over the hemisphere of +z (Fibonacci in the disc, lifted): the
// same probes for every point, so that the answer does not depend on a seed.
std::vector<V3f> hemisphereProbes(int count) {
    std::vector<V3f> dirs;
    dirs.reserve(size_t(count));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < count; ++k) {
        const double r = std::sqrt((k + 0.5) / count);
        const double phi = golden * k;
        dirs.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(std::max(0.0, 1 - r * r))));
    }
    return dirs;
}

constexpr int kMaxCrossings = 256;  // along one probe; a ray through more surfaces is cut short

// Which object each triangle of the render scene belongs to (in the order RenderScene lays them
// out: the objects with a world mesh, each one's triangles in turn).
class TriangleObjects {
public:
    explicit TriangleObjects(const Scene& scene) {
        uint32_t first = 0;
        for (size_t o = 0; o < scene.objects.size(); ++o) {
            if (!scene.objects[o].worldMesh) continue;
            firstTriangle_.push_back(first);
            object_.push_back(uint32_t(o));
            first += uint32_t(scene.objects[o].worldMesh->triangles.size());
        }
    }
    uint32_t of(uint32_t triangle) const {
        const auto it = std::upper_bound(firstTriangle_.begin(), firstTriangle_.end(), triangle);
        return object_[size_t(it - firstTriangle_.begin()) - 1];
    }

private:
    std::vector<uint32_t> firstTriangle_, object_;
};

using Tally = std::vector<std::pair<uint32_t, int>>;  // per object, a count (few objects per ray)
void addOne(Tally& tally, uint32_t object) {
    auto it = std::find_if(tally.begin(), tally.end(), [&](const auto& c) { return c.first == object; });
    if (it == tally.end()) tally.emplace_back(object, 1);
    else ++it->second;
}

// The objects whose surface a ray from `origin` along `d` crosses an odd number of times, and
// the distance to its first hit (infinity when it meets nothing).
struct Crossings {
    std::vector<uint32_t> oddObjects;
    float firstHit = std::numeric_limits<float>::infinity();
};
Crossings crossings(const RenderScene& scene, const TriangleObjects& objects, V3f origin, const V3f& d) {
    Crossings out;
    Tally counts;
    for (int k = 0; k < kMaxCrossings; ++k) {
        float t = 0;
        const std::optional<SurfacePoint> hit = scene.intersect(Ray{origin, d}, &t);
        if (!hit) break;
        if (k == 0) out.firstHit = t;
        addOne(counts, objects.of(hit->triangle));
        origin = hit->spawnOrigin(d);
    }
    for (const auto& [o, n] : counts)
        if (n % 2 == 1) out.oddObjects.push_back(o);
    return out;
}

// The objects that enclose `origin`: crossed an odd number of times by more than three quarters
// of the probes (a few slipping out through a seam do not change the answer). With the first
// hits' distances, for the on-a-surface test.
std::vector<uint32_t> enclosingObjects(const RenderScene& scene, const TriangleObjects& objects, const V3f& origin,
                                       const std::vector<V3f>& directions, std::vector<float>* firstHits = nullptr) {
    Tally votes;
    for (const V3f& d : directions) {
        const Crossings c = crossings(scene, objects, origin, d);
        if (firstHits) firstHits->push_back(c.firstHit);
        for (uint32_t o : c.oddObjects) addOne(votes, o);
    }
    std::vector<uint32_t> out;
    for (const auto& [o, n] : votes)
        if (4 * n > 3 * int(directions.size())) out.push_back(o);
    return out;
}

// Where the designer's light and eye are: what a room encloses and a solid does not.
std::vector<V3f> occupiedPositions(const Scene& scene) {
    std::vector<V3f> out{toFloat(scene.camera.position)};
    for (const Light& l : scene.lights)
        if (l.type == LightType::Point || l.type == LightType::Spot || l.type == LightType::Luminaire)
            out.push_back(toFloat(l.position));
    return out;
}
}  // namespace

std::vector<uint8_t> pointsInsideGeometry(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal) {
    const IrradianceEstimator estimator(scene);
    const TriangleObjects objects(scene.scene());
    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    const Frame frame(toFloat(normal).normalized());
    std::vector<V3f> probes = hemisphereProbes(kInsideProbeRays);
    for (V3f& d : probes) d = frame.toWorld(d);
    // A point closer than this to a surface its hemisphere faces lies on it (1 mm in a 10 m scene).
    const float onSurface = 1e-4f * scene.boundsRadius();

    std::vector<uint8_t> inside(points.size(), 0);
    std::vector<std::vector<uint32_t>> enclosing(points.size());
    tbb::parallel_for(size_t(0), sensors.size(), [&](size_t i) {
        // From the lifted sensor: a grid lying on the floor must not see the floor it lies on.
        const V3f p = estimator.lifted(sensors[i]).position;
        std::vector<float> firstHits;
        enclosing[i] = enclosingObjects(scene, objects, p, probes, &firstHits);
        const auto near = std::count_if(firstHits.begin(), firstHits.end(), [&](float t) { return t < onSurface; });
        if (8 * near > int(probes.size())) inside[i] = 1;  // on a surface: its estimate would be half in the solid
    });
    std::map<uint32_t, size_t> pointsPerObject;
    for (const std::vector<uint32_t>& e : enclosing)
        for (uint32_t o : e) ++pointsPerObject[o];
    if (pointsPerObject.empty()) return inside;

    // An enclosing object is a solid (a cabinet, a partition, a slab above) unless it encloses a
    // light or the camera the same way (a ceiling over the room, a room modelled as a closed box,
    // its faces pointing either way), or most of a work plane of several points (a daylit room
    // seen from outside).
    const std::vector<V3f> occupied = occupiedPositions(scene.scene());
    std::vector<std::vector<uint32_t>> around(occupied.size());
    tbb::parallel_for(size_t(0), occupied.size(), [&](size_t k) { around[k] = enclosingObjects(scene, objects, occupied[k], probes); });
    std::set<uint32_t> rooms;
    for (const std::vector<uint32_t>& a : around) rooms.insert(a.begin(), a.end());
    for (const auto& [o, count] : pointsPerObject)
        if (points.size() >= 4 && 2 * count > points.size()) rooms.insert(o);
    for (size_t i = 0; i < points.size(); ++i)
        for (uint32_t o : enclosing[i])
            if (!rooms.count(o)) inside[i] = 1;
    return inside;
}

std::vector<uint8_t> pointsLitThroughGlass(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal) {
    std::vector<uint8_t> lit(points.size(), 0);
    const LightSampler& lights = scene.lights();
    if (lights.deltaLights().empty() || !scene.features().hasDielectric) return lit;
    const IrradianceEstimator estimator(scene);
    const V3f n = toFloat(normal).normalized();
    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    for (size_t i = 0; i < sensors.size(); ++i) {
        SurfacePoint x;
        x.p = estimator.lifted(sensors[i]).position;
        x.pError = V3f(0, 0, 0);
        x.ng = n;
        x.triangle = 0xffffffffu;
        for (size_t l = 0; l < lights.deltaLights().size() && !lit[i]; ++l) {
            LightSample ls;
            if (!lights.sampleDeltaLight(l, x, ls) || ls.wi.dot(n) <= 0 || isBlack(ls.value)) continue;
            if (scene.occluded(ls.shadowRay) && thinPaneTransmittance(scene, ls.shadowRay) > 0) lit[i] = 1;
        }
    }
    return lit;
}

bool carriesLightThroughGlass(GridMethod method) {
    switch (method) {
    case GridMethod::Bdpt:
    case GridMethod::Mir:
    case GridMethod::Mlt:
    case GridMethod::Cmlt: return true;
    case GridMethod::Path:
    case GridMethod::Vpl:
    case GridMethod::Preview: return false;
    }
    return false;
}

}  // namespace lucerna
