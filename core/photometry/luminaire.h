#pragma once
// Goniometric luminaires in a scene (README, "Luminaires"): reading their photometric file, the
// frame that orients the distribution, and the scale from the file's candela to the radiant
// intensity (W/sr per RGB channel) that the backends use.
//
// Conventions. gamma = 0 is the light's `direction` (its nadir). C = 0 points along world +X
// made perpendicular to the nadir (world +Z when the nadir is along X), turned about the nadir by
// `rotation` degrees toward C = 90; C90 = C0 x nadir. Seen from above a luminaire hanging
// straight down (nadir -Y), C grows counterclockwise as IES LM-63 asks: C0 = +X, C90 = -Z.

#include "core/photometry/goniometric_distribution.h"
#include "core/scene/scene.h"

namespace lucerna {

// Reads an IES (.ies) or EULUMDAT (.ldt) file, chosen by the extension (any case). Throws
// LuminaireFileError with one line "path: problem" or "path: line N: problem".
GoniometricDistribution loadLuminaireFile(const std::string& path);

struct LuminaireFrame {
    V3d nadir, c0, c90;  // orthonormal; a direction (C, gamma) is cos g nadir + sin g (cos C c0 + sin C c90)
};
LuminaireFrame luminaireFrame(const V3d& direction, double rotationDeg);

// The angle (degrees) between a nadir and world down (0, -1, 0): the tilt at which an IES
// TILT=INCLUDE table is read for a luminaire mounted in the scene.
double luminaireTiltDeg(const V3d& direction);

// Radiant intensity per candela of the file's table (W/sr/cd per channel): the colour
// (luminance 1) / 683, times lumens / integrated flux when "lumens" is given, times the tilt
// multiplier. Black while the distribution is not loaded.
Rgbd luminaireRadiantScale(const Light& light);

// The luminaire's luminous flux as the scene uses it (lm): integrated flux x the scale's luminance x 683.
double luminaireFlux(const Light& light);

}  // namespace lucerna
