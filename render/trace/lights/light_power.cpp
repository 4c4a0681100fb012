#include "render/trace/lights/light_power.h"

#include "render/trace/lights/delta_light.h"
#include "render/trace/lights/emitter_triangle.h"
#include "render/trace/lights/environment_light.h"

#include <algorithm>

namespace lucerna {

namespace {

double emitterPower(const EmitterTriangle& e) { return kPi * double(e.area) * luminance(e.radiance); }

double deltaPower(const DeltaLight& l, float metersPerUnit, float sceneRadius) {
    const double y = luminance(l.intensity);
    const double toScene = 1.0 / (double(metersPerUnit) * metersPerUnit);  // E = I / (d mpu)^2
    switch (l.type) {
    case LightType::Point: return 4.0 * kPi * y * toScene;
    case LightType::Spot: {
        // Solid angle of the cone, with the smooth edge counted at half weight.
        const double c = 0.5 * (double(l.cosCone) + double(std::max(l.cosCone, l.cosFalloffStart)));
        return 2.0 * kPi * (1.0 - c) * y * toScene;
    }
    case LightType::Luminaire: return l.goniometric ? l.goniometric->flux() * y * toScene : 0.0;
    case LightType::Directional: return kPi * double(sceneRadius) * sceneRadius * y;
    case LightType::Sun: return 0.0;  // never a delta light of its own (compileDeltaLight)
    }
    return 0.0;
}

}  // namespace

PowerSelection::PowerSelection(const std::vector<EmitterTriangle>& emitters, const std::vector<DeltaLight>& deltas,
                               const EnvironmentLight* environment, float metersPerUnit, float sceneRadius,
                               size_t triangleCount) {
    std::vector<double> weights;
    weights.reserve(emitters.size() + deltas.size() + 1);
    for (const auto& e : emitters) weights.push_back(emitterPower(e));
    for (const auto& l : deltas) weights.push_back(deltaPower(l, metersPerUnit, sceneRadius));
    // The power of the particles the environment sends: pi R^2 times its integrated radiance.
    if (environment) weights.push_back(kPi * double(sceneRadius) * sceneRadius * environment->integratedLuminance());
    select_ = DiscreteDistribution(weights);
    areaPdf_.assign(emitters.empty() ? 0 : triangleCount, 0.0f);
    if (!select_.empty())
        for (size_t i = 0; i < emitters.size(); ++i)
            areaPdf_[emitters[i].triangle] = float(select_.pdf(i) / double(emitters[i].area));
}

}  // namespace lucerna
