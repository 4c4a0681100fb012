#pragma once
// The preview's daylight (SPEC.md section 5) as directional lights, each drawn with an
// orthographic shadow map: the sun as one, its direction drawn within the disc for every fresh
// set (frames averaged converge to the disc's penumbra); the sky, with the ground below the
// horizon, as a set of directions drawn in proportion to their luminance, stratified, each
// carrying its share of the irradiance, so that for any receiver and any occluder the sum is an
// unbiased estimate of the sky's light (frames with fresh directions average to it).

#include "core/daylight/daylight.h"
#include "core/math.h"

#include <optional>
#include <vector>

namespace lucerna {

struct DirectionalSample {
    V3f toward;      // unit world direction toward the light (the light travels along -toward)
    Rgb irradiance;  // W/m^2 per channel on a surface facing it
};

// The sun's light for a fresh set: its direction uniform within the disc (the resolved direction
// itself for a delta sun), its normal irradiance; nothing at or below the horizon.
std::optional<DirectionalSample> sunSample(const ResolvedSun& sun, uint64_t seed);

// `count` directions over the whole sphere (sky above the horizon, ground below) with density
// p(w) proportional to a table of the luminance (kSkyTableRows equal-area rows by twice as many
// columns, with a floor of 1% of the mean where there is light), the points a randomly shifted
// Fibonacci lattice warped through the table: irradiance = L(w) / 683 / (count p(w)), white.
// Empty when the sky is black.
std::vector<DirectionalSample> skySamples(const ResolvedSky& sky, int count, uint64_t seed);
inline constexpr int kSkyTableRows = 32;

}  // namespace lucerna
