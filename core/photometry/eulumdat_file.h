#pragma once
// EULUMDAT (.ldt) photometric files: the fixed line layout of the format (company, type and
// symmetry indicators, C-plane and gamma counts and spacings, names, dimensions, light output
// ratio, conversion factor, lamp sets, direct ratios, the C and gamma angles, then intensities in
// cd/klm), the symmetry indicator Isym 0 to 4 expanded to the full circle.
//
// Intensities are made absolute as cd/klm x (the sum of the lamp sets' "total luminous flux of
// lamps") / 1000 x the conversion factor; the stated flux is that lamp flux times the light
// output ratio, which is what the intensities integrate to. The measurement tilt is ignored.

#include "core/photometry/goniometric_distribution.h"

namespace lucerna {

// Parses the text of an EULUMDAT file; `label` (the file name) starts every error message:
// "label: line N: problem". Throws LuminaireFileError.
GoniometricDistribution parseEulumdat(const std::string& text, const std::string& label);

}  // namespace lucerna
