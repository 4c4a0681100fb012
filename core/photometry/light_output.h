#pragma once
// A light's output as a designer reads and edits it: a point or spot light's luminous flux (lm)
// and on-axis luminous intensity (cd) with a colour or a colour temperature, a directional
// light's illuminance (lx) on a surface facing it. The scene keeps the photometric keys as they
// were typed (Light::photometric, README "Photometric lights"); `intensity` always holds the
// radiant intensity they convert to, which is what every backend reads.

#include "core/scene/scene.h"

namespace lucerna {

// The solid angle that a point or spot light's flux spreads over (photometric_units.h).
double lightSolidAngle(const Light& light);

// 683 x luminance of the radiant intensity (cd, on axis for a spot) and that times the solid angle (lm).
double luminousIntensityCd(const Light& light);
double luminousFluxLm(const Light& light);

// The light's photometric specification: the one it was given, or one read off its radiant
// intensity (lumens, and the intensity's colour; white when its channels are equal or black).
PhotometricSpec photometricOf(const Light& light);

// The light given by `spec`: the specification kept for the file, the intensity converted.
Light withPhotometric(Light light, const PhotometricSpec& spec);

// A spot's new angles: a flux given in lumens stays the flux (it spreads over the new cone), so
// the intensity is converted again; a candela value stays the on-axis intensity.
Light withSpotAngles(Light light, double coneAngleDeg, std::optional<double> falloffStartDeg);

// A radiant intensity typed as it is (the advanced view), kept exactly; photometric keys, when
// the light has them, are read off it in the same quantity (lumens or candela) with its colour,
// so that the file's keys still give this intensity (scene_writer's check).
Light withRadiantIntensity(Light light, const Rgbd& intensity);

// Directional light: illuminance (lx) on a surface facing it, and the irradiance's colour.
double illuminanceLx(const Light& light);
Light withIlluminance(Light light, double lux);
Light withIrradianceColour(Light light, const Rgbd& colour);

// A colour scaled so that its largest channel is 1 (what a colour field shows); black stays black.
Rgbd chromaticity(const Rgbd& colour);

}  // namespace lucerna
