#include "render/trace/lights/environment_sampler.h"

#include "render/trace/warp.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

EnvironmentSampler::EnvironmentSampler(EnvironmentLight environment, std::vector<Portal> portals)
    : environment_(std::move(environment)) {
    if (environment_.hasSky() && !portals.empty() && portals.size() <= kMaxPortalTriangles) {
        std::vector<double> areas;
        for (const Portal& p : portals) areas.push_back(p.area), portalArea_ += p.area;
        if (portalArea_ > 0) portals_ = std::move(portals), portalSelect_ = DiscreteDistribution(areas);
    }
}

bool EnvironmentSampler::sample(const V3f& p, const V2f& u, V3f& wi, Rgb& radiance) const {
    const float q = portalShare();
    if (u.x < q) {
        // Aim at a uniform point of the panes.
        float uRest = 0.0f;
        const Portal& portal = portals_[portalSelect_.sample(std::min(u.x / q, 0x1.fffffep-1f), &uRest)];
        const V2f b = squareToUniformTriangle(V2f(uRest, u.y));
        const V3f target = portal.p0 * (1.0f - b.x - b.y) + portal.p1 * b.x + portal.p2 * b.y;
        const V3f d = target - p;
        const float length = d.length();
        if (!(length > 0.0f)) return false;
        wi = d / length;
        radiance = environment_.radiance(wi);
        return !isBlack(radiance);
    }
    float ignored = 0.0f;
    const V2f rest(std::min((u.x - q) / (1.0f - q), 0x1.fffffep-1f), u.y);
    return environment_.sample(rest, wi, ignored, radiance);
}

float EnvironmentSampler::pdf(const V3f& w, const V3f& p) const {
    const float q = portalShare();
    return (1.0f - q) * environment_.pdf(w) + (q > 0 ? q * portalPdf(w, p) : 0.0f);
}

float EnvironmentSampler::portalPdf(const V3f& w, const V3f& p) const {
    // Every pane triangle the ray from p along w crosses adds t^2 / (A |cos|): the uniform
    // density 1 / A over the panes' total area A, turned into solid angle at p.
    float pdf = 0.0f;
    for (const Portal& portal : portals_) {
        const float cosine = portal.normal.dot(w);
        if (cosine == 0.0f) continue;
        const V3f e1 = portal.p1 - portal.p0, e2 = portal.p2 - portal.p0;
        const V3f s = w.cross(e2);
        const float det = e1.dot(s);
        if (det == 0.0f) continue;
        const V3f o = p - portal.p0;
        const float b1 = o.dot(s) / det;
        const V3f q = o.cross(e1);
        const float b2 = w.dot(q) / det, t = e2.dot(q) / det;
        if (b1 < 0 || b2 < 0 || b1 + b2 > 1 || !(t > 0)) continue;
        pdf += t * t / (portalArea_ * std::abs(cosine));
    }
    return pdf;
}

}  // namespace lucerna
