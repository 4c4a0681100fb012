#include "render/vpl/mir_path.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

namespace lucerna {

namespace {
// Reads a range of u in order. Past its end, numbers come from PCG32 seeded by a hash of the
// whole range ("padding", as pbrt's primary sample space sampler extends its vector lazily), so
// that paths are never cut short: a chain that mutates the stored numbers re-draws the padded
// ones, and a path remains a deterministic function of u.
class PrimarySampleStream final : public SampleGenerator {
public:
    PrimarySampleStream(const float* begin, const float* end) : begin_(begin), next_(begin), end_(end) {}
    float next1D() override {
        if (next_ < end_) return *next_++;
        if (!padding_) padding_.emplace(hashRange(), 0);
        return padding_->next1D();
    }
    V2f next2D() override {
        const float a = next1D();
        return V2f(a, next1D());
    }

private:
    uint64_t hashRange() const {
        uint64_t h = 0x6d69722d706164ULL;
        for (const float* p = begin_; p < end_; ++p) h = hashSeed(h, std::bit_cast<uint32_t>(*p));
        return h;
    }

    const float* begin_;
    const float* next_;
    const float* end_;
    std::optional<Rng> padding_;
};

// The throughput under which a sample of Pc plays Russian roulette (estimateMirImportance). One
// sample's relative variance times its rays, against the chain's own roulette (mir's balance
// after 4 s, seed 1): closed sphere of albedo 0.9 0.64, closed room 0.9 0.65, closed room 0.5
// 0.90, sphere 0.6 0.77, door 0.65, Cornell box 1.03, office floor 0.78; with 0.25 the closed
// rooms a little less, the Cornell box 1.19.
constexpr double kPcRouletteWindow = 0.5;

// The luminance VPL v sends to the camera through importance point x_s (clamped G, visibility).
double importanceAt(const RenderScene& scene, const Vpl& v, const CameraVertex& point, float maxG) {
    return double(luminance(point.throughput * vplContribution(scene, v, point.receiver, maxG)));
}

}  // namespace

int mirPathDimension(const VplOptions& vpl) {
    // traceLightPath: 5, then 4 per bounce; bounces past kStoredLightBounces read padding.
    return 5 + 4 * std::min(vpl.maxBounces, kStoredLightBounces);
}

std::vector<CameraVertex> traceImportancePoints(const RenderScene& scene, const Sensor& camera, int maxSpecularDepth,
                                                int count, uint64_t seed) {
    const int w = camera.width(), h = camera.height();
    const int sx = std::max(1, int(std::lround(std::sqrt(double(count) * w / h)))), sy = std::max(1, count / sx);
    std::vector<CameraVertex> points;
    Rng rng(seed, 0x696d70);
    for (int j = 0; j < sy; ++j)
        for (int i = 0; i < sx; ++i) {
            const V2f r = rng.next2D();
            const Ray ray = camera.ray((float(i) + r.x) * float(w) / float(sx), (float(j) + r.y) * float(h) / float(sy));
            const CameraVertex cv = traceCameraVertex(scene, ray, rng, maxSpecularDepth);
            if (cv.found) points.push_back(cv);
        }
    return points;
}

double evaluateMirLightPath(const RenderScene& scene, const LightSampler& lights, std::span<const CameraVertex> points,
                            const VplOptions& vpl, float maxG, double floor, const std::vector<float>& u,
                            MirPath& path) {
    path.vpls.clear();
    path.contribution.clear();
    PrimarySampleStream lightStream(u.data(), u.data() + u.size());
    traceLightPath(scene, lights, lightStream, 1.0f, vpl, [&](const Vpl& v) { path.vpls.push_back(v); });
    const double perPoint = points.empty() ? 0.0 : 1.0 / double(points.size());
    double sum = 0;
    for (const Vpl& v : path.vpls) {
        double c = 0;
        for (const CameraVertex& point : points) c += importanceAt(scene, v, point, maxG);
        c = std::isfinite(c) ? std::max(0.0, c) * perPoint : 0.0;
        path.contribution.push_back(c + floor);
        sum += c + floor;
    }
    return sum;
}

double estimateMirImportance(const RenderScene& scene, const LightSampler& lights, std::span<const CameraVertex> points,
                             const VplOptions& vpl, float maxG, double floor, int perVertex, Rng& rng,
                             int* vertexCount) {
    // The chain's roulette, near the albedo at every bounce, makes a path's vertex count
    // geometric: in a closed room of albedo 0.9 that alone is a sample's relative variance (0.9),
    // and Pc's error was most of the image's. A sample plays a weight window instead: no roulette
    // while its throughput is above kPcRouletteWindow, then survival in proportion to it. The
    // importance is linear in the vertex's power, which the compensation keeps unbiased; the
    // floor is not, so each vertex's floor counts by the chain's probability of reaching it over
    // this path's.
    struct Reach {
        double chain = 1, sampled = 1;
    } reach;
    const RouletteRule roulette = [&](const Rgb& beta, int bounce) {
        // beta is compensated for this rule's survivals, the chain's for its own.
        const Rgb uncompensated = beta * float(reach.sampled);
        reach.chain *= particleSurvival(uncompensated / float(reach.chain), bounce, vpl);
        const double survive = std::min(1.0, double(maxComponent(beta)) / kPcRouletteWindow);
        reach.sampled *= survive;
        return survive;
    };
    std::vector<Vpl> vertices;
    std::vector<double> reachRatio;
    traceLightPath(
        scene, lights, rng, 1.0f, vpl,
        [&](const Vpl& v) {
            vertices.push_back(v);
            reachRatio.push_back(reach.chain / reach.sampled);
        },
        roulette);
    if (vertexCount) *vertexCount = int(vertices.size());
    double sum = 0;
    for (size_t k = 0; k < vertices.size(); ++k) {
        double c = 0;
        for (int j = 0; j < perVertex && !points.empty(); ++j) {
            const size_t s = std::min(points.size() - 1, size_t(rng.next1D() * float(points.size())));
            c += importanceAt(scene, vertices[k], points[s], maxG);
        }
        sum += floor * reachRatio[k] + (std::isfinite(c) ? std::max(0.0, c) / double(perVertex) : 0.0);
    }
    return sum;
}

int choosePathVertex(const MirPath& path, double u) {
    double sum = 0;
    for (double c : path.contribution) sum += c;
    if (!(sum > 0)) return -1;
    double t = u * sum;
    for (size_t k = 0; k < path.contribution.size(); ++k) {
        if (t < path.contribution[k]) return int(k);
        t -= path.contribution[k];
    }
    for (size_t k = path.contribution.size(); k-- > 0;)  // rounding at the end of the sum
        if (path.contribution[k] > 0) return int(k);
    return -1;
}

}  // namespace lucerna
