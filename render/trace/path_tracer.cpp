#include "render/trace/path_tracer.h"

namespace lucerna {

Rgb PathTracer::nextEventEstimate(const SurfacePoint& hit, const ShadingMaterial& mat, const Frame& frame,
                                  const V3f& woLocal, SampleGenerator& rng) const {
    LightSample ls;
    const V2f u = rng.next2D();
    const float uSelect = rng.next1D();
    if (!scene_.lights().sample(hit, u, uSelect, ls, frame.n)) return Rgb(0, 0, 0);
    const V3f wiLocal = frame.toLocal(ls.wi);
    const Rgb f = bsdfEval(mat, woLocal, wiLocal);
    if (isBlack(f)) return Rgb(0, 0, 0);
    const Rgb through = scene_.transmittance(ls.shadowRay);
    if (isBlack(through)) return Rgb(0, 0, 0);
    const Rgb unweighted = f * ls.value * through * (std::abs(wiLocal.z) / ls.pdf);
    if (ls.isDelta) return unweighted;
    return unweighted * powerHeuristic(ls.pdf, bsdfPdf(mat, woLocal, wiLocal));
}

Rgb PathTracer::radiance(Ray ray, SampleGenerator& rng, const ScatteredFrom* from) const {
    Rgb L(0, 0, 0), throughput(1, 1, 1);
    // The camera ray counts as a specular bounce: emitters seen directly are not MIS-weighted.
    bool specularBounce = from == nullptr;
    float bsdfPdfPrev = from ? from->pdf : 0.0f;
    V3f pPrev = from ? from->origin : ray.origin;
    V3f nPrev = from ? from->receiving : V3f(0, 0, 0);

    for (int depth = 0;; ++depth) {
        Rgb through;
        const auto hit = scene_.intersect(ray, nullptr, &through);
        throughput *= through;  // panes crossed on the way (glazing)
        if (!hit) {
            // Leaving the scene: daylight, weighted against next-event estimation as emitters are.
            const Rgb Le = scene_.escapedRadiance(ray.direction);
            if (!isBlack(Le)) {
                const float weight =
                    specularBounce ? 1.0f : powerHeuristic(bsdfPdfPrev, scene_.lights().pdfEnvironment(ray.direction, pPrev));
                L += throughput * Le * weight;
            }
            break;
        }
        const ShadingMaterial& mat = scene_.material(hit->material);
        const V3f wo = -ray.direction;  // unit: camera and BSDF directions are

        if (mat.isEmitter()) {
            if (hit->ng.dot(wo) > 0.0f) {  // one-sided: only the front emits
                float weight = 1.0f;
                if (!specularBounce)
                    weight = powerHeuristic(bsdfPdfPrev, scene_.lights().pdfEmitter(hit->triangle, pPrev, hit->p, hit->ng, nPrev));
                L += throughput * mat.radiance * weight;
            }
            break;  // emitters reflect nothing
        }
        if (depth >= settings_.maxDepth) break;

        const Frame frame(shadingNormal(mat, hit->ng, wo));
        const V3f woLocal = frame.toLocal(wo);
        if (!mat.isDelta()) L += throughput * nextEventEstimate(*hit, mat, frame, woLocal, rng);

        BsdfSample bs;
        const V2f u = rng.next2D();
        const float uLobe = rng.next1D();
        if (!bsdfSample(mat, woLocal, u, uLobe, bs)) break;
        throughput *= bs.weight;
        if (isBlack(throughput)) break;
        specularBounce = bs.isDelta;
        bsdfPdfPrev = bs.pdf;
        pPrev = hit->p;
        nPrev = frame.n;

        if (depth + 1 >= settings_.rouletteStartDepth) {
            const float survive = std::min(0.95f, maxComponent(throughput));
            if (rng.next1D() >= survive) break;
            throughput /= survive;
        }
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
    }
    return L;
}

}  // namespace lucerna
