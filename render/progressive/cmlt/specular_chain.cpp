#include "render/progressive/cmlt/specular_chain.h"

namespace lucerna {

bool refractedAt(const std::vector<PathVertex>& path, int j) {
    const PathVertex& v = path[size_t(j)];
    const float a = v.sp.ng.dot(path[size_t(j - 1)].p() - v.p()), b = v.sp.ng.dot(path[size_t(j + 1)].p() - v.p());
    return a * b < 0.0f;
}

bool followSpecular(const RenderScene& scene, const SurfacePoint& hit, bool refracted, Ray& ray, Rgb& throughput) {
    const ShadingMaterial& mat = scene.material(hit.material);
    if (!mat.isDelta()) return false;
    const V3f wo = -ray.direction.normalized();
    const Frame frame(shadingNormal(mat, hit.ng, wo));
    const V3f woLocal = frame.toLocal(wo);
    BsdfSample bs;
    // The branch forced: uLobe 0 reflects whenever glass can, 1 refracts whenever it can. The
    // sampled weight is 1 for glass (the branch chosen by Fresnel); in path space the factor is
    // Fresnel's.
    if (!bsdfSample(mat, woLocal, V2f(0, 0), refracted ? 1.0f : 0.0f, bs) || bs.refracted != refracted) return false;
    if (mat.type == MaterialType::Mirror) {
        throughput *= mat.reflectance;
    } else {
        const float fr = fresnelDielectric(std::abs(woLocal.z), woLocal.z >= 0.0f ? mat.ior : 1.0f / mat.ior);
        throughput *= refracted ? 1.0f - fr : fr;
    }
    const V3f wi = frame.toWorld(bs.wi);
    ray = Ray{hit.spawnOrigin(wi), wi};
    return true;
}

}  // namespace lucerna
