#pragma once
// The preview's luminaire distributions: each luminaire's candela table resampled onto one common
// (C, gamma) grid, a layer of an R32F 2D texture array with linear filtering. direct.frag reads
// it at u = C / 360, v = gamma / 180 (texel centres on the grid's angles).

#include "render/preview/gl_objects.h"
#include "render/trace/lights/goniometric_sampler.h"

#include <vector>

namespace lucerna::preview_detail {

// 1 degree in C (0..360), 0.5 degree in gamma (0..180): finer than the usual files' steps, so
// linear filtering of the resampled table stays close to the files' own bilinear interpolation.
inline constexpr int kLuminaireTableC = 361, kLuminaireTableGamma = 361;

// The texture array with one layer per distribution (one black layer when there are none, so
// that the sampler is always bound to something complete).
gl::Texture makeLuminaireTables(const std::vector<const GoniometricDistribution*>& distributions);

}  // namespace lucerna::preview_detail
