#include "render/vpl/vpl_contribution.h"

namespace lucerna {

float geometricClampBound(const RenderScene& scene, float fractionOfRadius) {
    if (!(fractionOfRadius > 0.0f)) return kNoClamp;
    const float d = fractionOfRadius * scene.boundsRadius();
    const float bound = 1.0f / (d * d);
    return std::isfinite(bound) && bound > 0.0f ? bound : kNoClamp;
}

Rgb vplContributionUnshadowed(const RenderScene& scene, const Vpl& vpl, const VplReceiver& r, float maxG) {
    const V3f d = vpl.position - r.x.p;
    const float dist2 = d.length2();
    if (!(dist2 > 0.0f) || !std::isfinite(dist2)) return Rgb(0, 0, 0);
    const V3f dir = d / std::sqrt(dist2);  // from x toward the VPL

    // At x: two-sided frame turned toward wo (x is never glass: gathering happens at non-delta points).
    const V3f nx = r.x.ng.dot(r.wo) < 0.0f ? -r.x.ng : r.x.ng;
    const Frame fx(nx);
    const Rgb fX = bsdfEval(*r.material, fx.toLocal(r.wo), fx.toLocal(dir));
    if (isBlack(fX)) return Rgb(0, 0, 0);
    // At the VPL: its frame already faces the side the light arrived on.
    const Frame fv(vpl.normal);
    const Rgb fV = bsdfEval(scene.material(vpl.material), fv.toLocal(vpl.incident), fv.toLocal(-dir));
    if (isBlack(fV)) return Rgb(0, 0, 0);

    const float cosX = std::abs(nx.dot(dir)), cosV = std::abs(vpl.normal.dot(dir));
    const float g = std::min(cosX * cosV / dist2, maxG);
    const Rgb value = fX * vpl.power * fV * g;
    return isFinite(value) ? value : Rgb(0, 0, 0);
}

Rgb vplTransmittance(const RenderScene& scene, const Vpl& vpl, const SurfacePoint& x) {
    SurfacePoint v;
    v.p = vpl.position;
    v.pError = vpl.pError;
    v.ng = vpl.normal;
    v.triangle = vpl.triangle;
    v.material = vpl.material;
    return scene.transmittanceBetween(x, v);
}

Rgb vplContribution(const RenderScene& scene, const Vpl& vpl, const VplReceiver& r, float maxG) {
    const Rgb c = vplContributionUnshadowed(scene, vpl, r, maxG);
    if (isBlack(c)) return c;
    return c * vplTransmittance(scene, vpl, r.x);
}

Rgb gatherVpls(const RenderScene& scene, std::span<const Vpl> vpls, std::span<const float> scale,
               const VplReceiver& r, float maxG, std::span<double> perVpl) {
    Rgb sum(0, 0, 0);
    for (size_t i = 0; i < vpls.size(); ++i) {
        const float s = scale.empty() ? 1.0f : scale[i];
        if (!(s > 0.0f)) continue;
        const Rgb c = vplContribution(scene, vpls[i], r, maxG);
        if (isBlack(c)) continue;
        sum += c * s;
        if (!perVpl.empty()) perVpl[i] += luminance(c);
    }
    return sum;
}

}  // namespace lucerna
