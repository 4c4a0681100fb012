#include "render/vpl/mir_path.h"

#include <bit>
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
