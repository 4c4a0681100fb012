#include "core/scene/scene_energy.h"

#include "core/number_format.h"
#include "core/photometry/goniometric_distribution.h"
#include "core/scene/scene_geometry.h"

#include <algorithm>

namespace lucerna {

std::optional<double> circuitWatts(const Light& l) {
    if (l.type == LightType::Directional || l.type == LightType::Sun) return std::nullopt;
    if (l.circuitWatts) return l.circuitWatts;
    if (l.type == LightType::Luminaire && l.luminaire && l.luminaire->distribution)
        return l.luminaire->distribution->inputWatts;
    return std::nullopt;
}

SceneEnergy sceneEnergy(const Scene& scene) {
    SceneEnergy s;
    std::vector<double> watts;
    for (const Light& l : scene.lights) {
        if (!l.on || l.type == LightType::Directional || l.type == LightType::Sun) continue;
        ++s.lights;
        const std::optional<double> pn = circuitWatts(l);
        if (!pn) {
            s.withoutPower.push_back(l.name);
            continue;
        }
        watts.push_back(*pn);
        EnergyLightType t;
        t.kind = l.type == LightType::Luminaire ? "Luminaire" : l.type == LightType::Spot ? "Spot light" : "Point light";
        if (l.type == LightType::Luminaire && l.luminaire) {
            t.file = l.luminaire->file;
            if (l.luminaire->distribution) t.product = l.luminaire->distribution->name;
        }
        t.wattsEach = *pn;
        t.fromFile = !l.circuitWatts;
        const auto same = std::find_if(s.types.begin(), s.types.end(), [&](const EnergyLightType& x) {
            return x.kind == t.kind && x.file == t.file && x.product == t.product && x.wattsEach == t.wattsEach &&
                   x.fromFile == t.fromFile;
        });
        if (same != s.types.end()) same->names.push_back(l.name);
        else s.types.push_back(t), s.types.back().names.push_back(l.name);
    }
    for (const Object& o : scene.objects)
        if (const Material* m = scene.findMaterial(o.material); m && m->type == MaterialType::Emitter) ++s.emitterObjects;
    s.planAreaM2 = planAreaM2(scene);

    const double area = scene.energy && scene.energy->areaM2 ? *scene.energy->areaM2 : s.planAreaM2;
    if (!scene.energy) {
        s.notComputed = "no building type (Edit > Energy..., or the scene's \"energy\" key)";
    } else if (s.lights == 0) {
        s.notComputed = "no electric light is switched on";
    } else if (!s.withoutPower.empty()) {
        const size_t n = s.withoutPower.size();
        s.notComputed = std::to_string(n) + (n == 1 ? " light states" : " lights state") + " no power (give circuit_watts)";
    } else if (!(area > 0)) {
        s.notComputed = "the floor area is 0 m² (give area_m2)";
    } else if (const std::string problem = energySettingsProblem(*scene.energy); !problem.empty()) {
        s.notComputed = problem;
    } else {
        s.energy = computeLightingEnergy(*scene.energy, watts, area);
    }
    return s;
}

std::string describeLeni(const SceneEnergy& s, bool unicode) {
    if (!s.energy) return "LENI not computed: " + s.notComputed;
    const LightingEnergy& e = *s.energy;
    const std::string m2 = unicode ? "m\u00b2" : "m2";
    return "LENI " + fixedNumber(e.leni, 2) + " kWh/(" + m2 + (unicode ? "\u00b7" : " ") + "a) (W_L " +
           fixedNumber(e.lightingKWh, 1) + " kWh/a, W_P " + fixedNumber(e.parasiticKWh, 1) + " kWh/a, A " +
           fixedNumber(e.areaM2.value, 1) + " " + m2 + ")";
}

}  // namespace lucerna
