#include "render/vpl/instant_radiosity.h"

#include "core/photometry/luminaire.h"
#include "render/trace/rng.h"

#include <algorithm>

namespace lucerna {

namespace {

// Two-sided materials shade with the geometric normal turned toward the side the light came
// from (SPEC.md); VPLs never sit on glass, whose frame would stay fixed.
V3f facingNormal(const V3f& ng, const V3f& towardLight) { return ng.dot(towardLight) < 0.0f ? -ng : ng; }

// First triangle index of every object in the render scene (objects without a mesh own none).
std::vector<size_t> objectTriangleStarts(const Scene& scene) {
    std::vector<size_t> starts;
    size_t next = 0;
    for (const Object& o : scene.objects) {
        starts.push_back(next);
        if (o.worldMesh) next += o.worldMesh->triangles.size();
    }
    starts.push_back(next);
    return starts;
}

// As RenderScene decides which lights it keeps (compileDeltaLight's intensity; a luminaire's is
// its file's scale, black until the file is loaded), without building a luminaire's tables.
bool lightIsBlack(const Light& l) {
    if (l.type == LightType::Luminaire) return isBlack(toFloat(luminaireRadiantScale(l)));
    if (l.type == LightType::Sun) return true;  // daylight is the environment, no light of its own
    return isBlack(toFloat(l.type == LightType::Directional ? l.irradiance : l.intensity));
}

// The scene's light sampler restricted to one source (see the header).
LightSampler samplerForSource(const RenderScene& scene, const VplLightSource& source) {
    const LightSampler& all = scene.lights();
    std::vector<EmitterTriangle> emitters;
    std::vector<DeltaLight> deltas;
    if (source.isObject) {
        const auto starts = objectTriangleStarts(scene.scene());
        const size_t lo = starts[size_t(source.sceneIndex)], hi = starts[size_t(source.sceneIndex) + 1];
        for (const EmitterTriangle& e : all.emitters())
            if (e.triangle >= lo && e.triangle < hi) emitters.push_back(e);
    } else {
        // deltaLights() holds the scene's non-black lights in scene order.
        size_t k = 0;
        const auto& lights = scene.scene().lights;
        for (size_t i = 0; i < lights.size(); ++i) {
            if (lightIsBlack(lights[i])) continue;
            if (int(i) == source.sceneIndex && k < all.deltaLights().size()) deltas.push_back(all.deltaLights()[k]);
            ++k;
        }
    }
    return LightSampler(std::move(emitters), std::move(deltas), scene.metersPerUnit(), scene.boundsCenter(),
                        scene.boundsRadius(), scene.triangleCount());
}

// The first ray of a particle: off the emitter's surface, or from the delta light's position.
Ray emissionRay(const EmissionSample& e) {
    if (e.triangle != 0xffffffffu) return Ray{e.surface().spawnOrigin(e.direction), e.direction};
    return Ray{e.position, e.direction};
}

VplSet generateWith(const RenderScene& scene, const LightSampler& lights, int lightPaths, uint64_t seed,
                    const VplOptions& options) {
    VplSet vpls;
    if (lightPaths <= 0 || lights.empty()) return vpls;
    const float scale = 1.0f / float(lightPaths);
    for (int i = 0; i < lightPaths; ++i) {
        Rng rng(seed, uint64_t(i));
        traceLightPath(scene, lights, rng, scale, options, [&](const Vpl& v) { vpls.push_back(v); });
    }
    return vpls;
}

}  // namespace

std::vector<VplLightSource> vplLightSources(const RenderScene& scene) {
    std::vector<VplLightSource> sources;
    const Scene& s = scene.scene();
    const auto starts = objectTriangleStarts(s);
    const auto& emitters = scene.lights().emitters();
    for (size_t o = 0; o < s.objects.size(); ++o) {
        double power = 0;
        for (const EmitterTriangle& e : emitters)
            if (e.triangle >= starts[o] && e.triangle < starts[o + 1])
                power += kPi * double(e.area) * luminance(e.radiance);
        if (power > 0) sources.push_back({s.objects[o].name, true, int(o), power});
    }
    for (size_t i = 0; i < s.lights.size(); ++i) {
        if (lightIsBlack(s.lights[i])) continue;
        VplLightSource src{s.lights[i].name, false, int(i), 0.0};
        src.power = samplerForSource(scene, src).totalPower();
        sources.push_back(src);
    }
    return sources;
}

VplSet generateVpls(const RenderScene& scene, int lightPaths, uint64_t seed, const VplOptions& options) {
    return generateWith(scene, scene.lights(), lightPaths, seed, options);
}

VplSet generateVplsForLight(const RenderScene& scene, int sourceIndex, int lightPaths, uint64_t seed,
                            const VplOptions& options) {
    const auto sources = vplLightSources(scene);
    if (sourceIndex < 0 || size_t(sourceIndex) >= sources.size()) return {};
    return generateWith(scene, samplerForSource(scene, sources[size_t(sourceIndex)]), lightPaths, seed, options);
}

double particleSurvival(const Rgb& beta, int bounce, const VplOptions& options) {
    return bounce >= options.rouletteStartBounce ? double(std::min(0.95f, maxComponent(beta))) : 1.0;
}

int traceLightPath(const RenderScene& scene, const LightSampler& lights, SampleGenerator& u, float powerScale,
                   const VplOptions& options, const std::function<void(const Vpl&)>& deposit,
                   const RouletteRule& roulette) {
    // Always draw the same count of numbers per step, so that a primary-sample-space stream keeps
    // each dimension's meaning whatever happens along the path.
    const V2f uPos = u.next2D(), uDir = u.next2D();
    const float uSelect = u.next1D();
    EmissionSample e;
    if (!lights.sampleEmission(uPos, uDir, uSelect, e) || isBlack(e.power) || !isFinite(e.power)) return 0;

    const Rgb power = e.power * powerScale;
    Rgb beta(1, 1, 1);  // throughput relative to the emitted power, for Russian roulette
    Ray ray = emissionRay(e);
    int deposited = 0;
    for (int bounce = 1; bounce <= options.maxBounces; ++bounce) {
        Rgb through;
        const auto hit = scene.intersect(ray, nullptr, &through);
        if (!hit) break;
        beta *= through;  // glazing crossed on the way
        if (isBlack(beta)) break;
        const ShadingMaterial& mat = scene.material(hit->material);
        if (mat.isEmitter()) break;  // emitters reflect nothing
        const V3f incident = -ray.direction.normalized();
        const V3f n = mat.type == MaterialType::Dielectric ? hit->ng : facingNormal(hit->ng, incident);

        if (!mat.isDelta() && bounce >= options.minBounce) {
            Vpl v;
            v.position = hit->p;
            v.pError = hit->pError;
            v.normal = n;
            v.incident = incident;
            v.power = power * beta;
            v.material = hit->material;
            v.triangle = hit->triangle;
            v.bounce = bounce;
            if (isFinite(v.power) && !isBlack(v.power)) {
                deposit(v);
                ++deposited;
            }
        }
        if (bounce == options.maxBounces) break;

        // Continue: sample the BSDF with wo = incident. The materials are symmetric and glass is
        // not scaled by eta^2 (SPEC.md), so the adjoint weight equals the ordinary one.
        const Frame frame(n);
        BsdfSample bs;
        const V2f ud = u.next2D();
        const float uLobe = u.next1D(), uRoulette = u.next1D();
        if (!bsdfSample(mat, frame.toLocal(incident), ud, uLobe, bs)) break;
        beta *= bs.weight;
        if (isBlack(beta) || !isFinite(beta)) break;
        const double survive = roulette ? roulette(beta, bounce) : particleSurvival(beta, bounce, options);
        if (survive < 1) {
            if (double(uRoulette) >= survive) break;
            beta /= float(survive);
        }
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
    }
    return deposited;
}

}  // namespace lucerna
