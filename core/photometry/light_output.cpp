#include "core/photometry/light_output.h"

#include <algorithm>

namespace lucerna {

double lightSolidAngle(const Light& light) {
    return light.type == LightType::Spot ? spotSolidAngle(light.coneAngleDeg, light.falloffStartDeg) : pointSolidAngle();
}

double luminousIntensityCd(const Light& light) { return kLumensPerWatt * luminance(light.intensity); }

double luminousFluxLm(const Light& light) { return luminousIntensityCd(light) * lightSolidAngle(light); }

Rgbd chromaticity(const Rgbd& colour) {
    const double peak = std::max({colour.x, colour.y, colour.z});
    return peak > 0 ? colour / peak : Rgbd(0, 0, 0);
}

PhotometricSpec photometricOf(const Light& light) {
    if (light.photometric) return *light.photometric;
    PhotometricSpec spec;
    spec.quantity = PhotometricSpec::Quantity::Lumens;
    spec.value = luminousFluxLm(light);
    const Rgbd& i = light.intensity;
    // Grey is the default white: no colour key for it.
    if (luminance(i) > 0 && !(i.x == i.y && i.y == i.z)) spec.colour = chromaticity(i);
    return spec;
}

Light withPhotometric(Light light, const PhotometricSpec& spec) {
    light.photometric = spec;
    light.intensity = photometricIntensity(spec, lightSolidAngle(light));
    return light;
}

Light withSpotAngles(Light light, double coneAngleDeg, std::optional<double> falloffStartDeg) {
    light.coneAngleDeg = coneAngleDeg;
    light.falloffStartDeg = falloffStartDeg;
    if (light.photometric) light.intensity = photometricIntensity(*light.photometric, lightSolidAngle(light));
    return light;
}

Light withRadiantIntensity(Light light, const Rgbd& intensity) {
    light.intensity = intensity;
    if (!light.photometric) return light;
    if (!(luminance(intensity) > 0)) {
        light.photometric.reset();  // no colour to keep: the file says "intensity"
        return light;
    }
    // The same quantity, read off the typed intensity: a colour now, no temperature.
    const PhotometricSpec::Quantity quantity = light.photometric->quantity;
    light.photometric.reset();
    PhotometricSpec spec = photometricOf(light);
    spec.quantity = quantity;
    if (quantity == PhotometricSpec::Quantity::Candela) spec.value = luminousIntensityCd(light);
    light.photometric = spec;
    return light;
}

double illuminanceLx(const Light& light) { return kLumensPerWatt * luminance(light.irradiance); }

Light withIlluminance(Light light, double lux) {
    const double y = luminance(light.irradiance);
    const Rgbd colour = y > 0 ? light.irradiance / y : Rgbd(1, 1, 1);
    light.irradiance = colour * (lux / kLumensPerWatt);
    return light;
}

Light withIrradianceColour(Light light, const Rgbd& colour) {
    const double y = luminance(colour);
    if (y <= 0) return light;  // a black colour would lose the illuminance
    light.irradiance = colour * (illuminanceLx(light) / kLumensPerWatt / y);
    return light;
}

}  // namespace lucerna
