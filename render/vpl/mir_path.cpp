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
}  // namespace

MirPathLayout mirPathLayout(const GatherSettings& gather, const VplOptions& vpl) {
    MirPathLayout l;
    l.cameraDimensions = 2 + 3 * (gather.maxSpecularDepth + 1);  // traceCameraVertex: 3 per iteration
    // traceLightPath: 5, then 4 per bounce; bounces past kStoredLightBounces read padding.
    l.lightDimensions = 5 + 4 * std::min(vpl.maxBounces, kStoredLightBounces);
    return l;
}

double evaluateMirPath(const RenderScene& scene, const LightSampler& lights, const Sensor& camera,
                       const GatherSettings& gather, const VplOptions& vpl, float maxG, const MirPathLayout& layout,
                       const std::vector<float>& u, MirPath& path) {
    path.vpls.clear();
    path.contribution.clear();
    const float* cam = u.data();
    const float* light = cam + layout.cameraDimensions;
    PrimarySampleStream cameraStream(cam, light);
    PrimarySampleStream lightStream(light, light + layout.lightDimensions);

    const V2f raster = cameraStream.next2D();
    const Ray ray = camera.ray(raster.x * float(camera.width()), raster.y * float(camera.height()));
    const CameraVertex cv = traceCameraVertex(scene, ray, cameraStream, gather.maxSpecularDepth);
    if (!cv.found) return 0.0;

    traceLightPath(scene, lights, lightStream, 1.0f, vpl, [&](const Vpl& v) { path.vpls.push_back(v); });
    double sum = 0;
    for (const Vpl& v : path.vpls) {
        const Rgb contribution = cv.throughput * vplContribution(scene, v, cv.receiver, maxG);
        const double ck = std::max(0.0, double(luminance(contribution)));
        path.contribution.push_back(std::isfinite(ck) ? ck : 0.0);
        sum += path.contribution.back();
    }
    return sum;
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
                            const VplOptions& vpl, float maxG, double floor, const MirPathLayout& layout,
                            const std::vector<float>& u, MirPath& path) {
    path.vpls.clear();
    path.contribution.clear();
    PrimarySampleStream lightStream(u.data(), u.data() + layout.lightDimensions);
    traceLightPath(scene, lights, lightStream, 1.0f, vpl, [&](const Vpl& v) { path.vpls.push_back(v); });
    const double perPoint = points.empty() ? 0.0 : 1.0 / double(points.size());
    double sum = 0;
    for (const Vpl& v : path.vpls) {
        double c = 0;
        for (const CameraVertex& cv : points)
            c += double(luminance(cv.throughput * vplContribution(scene, v, cv.receiver, maxG)));
        c = std::isfinite(c) ? std::max(0.0, c) * perPoint : 0.0;
        path.contribution.push_back(c + floor);
        sum += c + floor;
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
