#include "render/trace/lights/delta_light.h"

#include "core/photometry/luminaire.h"
#include "render/trace/warp.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

DeltaLight compileDeltaLight(const Light& l, GoniometricSamplers* samplers) {
    DeltaLight d;
    if (l.type == LightType::Sun) {  // daylight, placed by the site: RenderScene adds it (black here)
        d.type = LightType::Directional;
        d.intensity = Rgb(0, 0, 0);
        return d;
    }
    d.type = l.type;
    d.position = toFloat(l.position);
    d.direction = toFloat(l.direction.normalized());
    d.intensity = toFloat(l.type == LightType::Directional ? l.irradiance : l.intensity);
    if (l.type == LightType::Spot) {
        d.cosCone = float(std::cos(radians(l.coneAngleDeg)));
        d.cosFalloffStart = float(std::cos(radians(l.falloffStartDeg.value_or(l.coneAngleDeg))));
    }
    if (l.type == LightType::Luminaire) {
        d.intensity = toFloat(luminaireRadiantScale(l));  // black until the file is loaded
        const LuminaireFrame f = luminaireFrame(l.direction, l.luminaire ? l.luminaire->rotationDeg.value_or(0.0) : 0.0);
        d.direction = toFloat(f.nadir);
        d.c0 = toFloat(f.c0);
        d.c90 = toFloat(f.c90);
        if (l.luminaire && l.luminaire->distribution) {
            const auto& distribution = l.luminaire->distribution;
            if (!samplers) d.goniometric = std::make_shared<const GoniometricSampler>(distribution);
            else {
                auto& shared = (*samplers)[distribution.get()];
                if (!shared) shared = std::make_shared<const GoniometricSampler>(distribution);
                d.goniometric = shared;
            }
        } else
            d.intensity = Rgb(0, 0, 0);
    }
    return d;
}

float DeltaLight::factor(const V3f& w) const {
    switch (type) {
    case LightType::Spot: return spotFactor(w.dot(direction));
    case LightType::Luminaire: return goniometric ? goniometric->intensity(toLuminaire(w)) : 0.0f;
    default: return 1.0f;
    }
}

float DeltaLight::pdfDirection(const V3f& w) const {
    switch (type) {
    case LightType::Point: return uniformSpherePdf();
    case LightType::Spot: return w.dot(direction) < cosCone ? 0.0f : uniformConePdf(cosCone);
    case LightType::Luminaire: return goniometric ? goniometric->pdf(toLuminaire(w)) : 0.0f;
    case LightType::Directional:
    case LightType::Sun: return 0.0f;
    }
    return 0.0f;
}

float DeltaLight::spotFactor(float cosTheta) const {
    if (cosFalloffStart <= cosCone)  // equal angles: a hard edge
        return cosTheta >= cosCone ? 1.0f : 0.0f;
    const float t = std::clamp((cosTheta - cosCone) / (cosFalloffStart - cosCone), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace lucerna
