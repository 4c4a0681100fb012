#pragma once
// Discomfort glare: the unified glare rating of CIE 117-1995 (README, "Glare (UGR)"),
//
//     UGR = 8 log10( 0.25 / Lb  *  sum over sources of  L^2 omega / p^2 )
//
// with Lb the background luminance (cd/m^2: the indirect illuminance at the eye over pi), and for
// each luminaire seen: L its luminance toward the eye (its intensity toward the eye over the
// projected area of its luminous parts, cd/m^2), omega the solid angle of those parts (projected
// area over the squared distance, sr) and p Guth's position index. Pure geometry and photometry:
// the background comes from elsewhere (render/photometry/glare_evaluation.h, core/photometry/ugr_table.h).
//
// The observer's frame: the line of sight is horizontal (y is up); for a source, R is its
// distance along the line of sight, H its height above the eye's horizontal plane and T its
// distance sideways (metres). CIE 117's angles (its annex): tau, from the vertical plane through
// the line of sight to the plane through the line of sight and the source, tan tau = |T| / H;
// sigma, between the line of sight and the direction of the source, tan sigma = sqrt(H^2+T^2) / R.
//
// The field of view. CIE 117 (4.5) asks to ignore luminaires with T/R outside its position-index
// table (0 to 3); the table stops at H/R = 1.9 (higher positions are hidden by brows and
// forehead). A source counts when R > 0 (in front of the eye), H > 0 (above the eye's horizontal
// plane), H/R <= 1.9 and |T|/R <= 3: about 62 degrees up and 72 degrees to either side, the
// table's own domain, so the formula is never used beyond the data it was fitted to.

#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene.h"

#include <optional>
#include <vector>

namespace lucerna {

inline constexpr double kGlareMaxHOverR = 1.9;
inline constexpr double kGlareMaxTOverR = 3.0;

// Where a source lies as the eye sees it (metres): along the line of sight, above the eye's
// horizontal plane, and sideways (the sign of T does not matter to p).
struct GlarePlacement {
    double alongM = 0, aboveM = 0, asideM = 0;  // R, H, T
    double distanceM() const;
    // Inside the field of view described above.
    bool inField() const;
};

// The placement of a point seen from an eye looking along `lineOfSight` (only its horizontal part
// counts; check it has one with horizontalLineOfSight, a vertical one is taken as -z), both
// points in scene units scaled by metersPerUnit.
GlarePlacement placeInView(const V3d& eye, const V3d& lineOfSight, const V3d& point, double metersPerUnit);
// The unit horizontal line of sight of a view direction (y up); nothing when it has no horizontal
// part (looking straight up or down, or zero).
std::optional<V3d> horizontalLineOfSight(const V3d& view);

// CIE 117's tau and sigma (degrees) of a source at H/R and T/R (R > 0).
double guthTauDeg(double hOverR, double tOverR);
double guthSigmaDeg(double hOverR, double tOverR);
// Guth's position index by CIE 117's formula (tau = a, sigma = b, degrees):
//   ln p = (35.2 - 0.31889 a - 1.22 e^(-2a/9)) 1e-3 b + (21 + 0.26667 a - 0.002963 a^2) 1e-5 b^2.
double guthPositionIndex(double hOverR, double tOverR);

// A luminaire's luminous parts in its own frame (core/photometry/goniometric_distribution.h): a flat
// rectangle or ellipse facing the nadir, lengthM along C0-C180 and widthM along C90-C270, and
// vertical sides of heightsM facing C0, C90, C180 and C270 (for an ellipse, the mean height
// around a vertical elliptic cylinder).
struct LuminousArea {
    double lengthM = 0, widthM = 0;
    bool elliptical = false;
    double heightsM[4] = {0, 0, 0, 0};
    bool empty() const { return !(lengthM > 0 && widthM > 0); }
    double flatAreaM2() const;
};
LuminousArea luminousAreaOf(const GoniometricDistribution::LuminousOpening& opening);
// The light's luminous area: its "luminous_area" key (flat, no sides) or else its file's opening;
// empty when neither states one (a point source to UGR) or the light is no loaded luminaire.
LuminousArea luminousAreaOf(const Light& light);

// The projected area (m^2) of the luminous parts seen from unit direction w, given in the
// luminaire's frame as (w.c0, w.c90, w.nadir) with w pointing from the luminaire to the eye.
double projectedLuminousArea(const LuminousArea& area, const V3d& wLocal);

// What the eye receives from one source.
struct GlareTerm {
    double luminanceCdM2 = 0;  // L
    double solidAngleSr = 0;   // omega
    double positionIndex = 1;  // p
    double value() const { return luminanceCdM2 * luminanceCdM2 * solidAngleSr / (positionIndex * positionIndex); }
};
// The term of a source of intensity I (cd) toward the eye whose luminous parts project to
// areaM2 toward it, at `placement` (in the field). L = I / A, omega = A / r^2.
GlareTerm glareTerm(double intensityCd, double projectedAreaM2, const GlarePlacement& placement);

// A luminaire seen from an eye (positions in metres, the line of sight unit and horizontal): its
// placement, its intensity toward the eye (the distribution's candela times candelaScale) and the
// projected area of its luminous parts toward the eye.
struct LuminaireSight {
    GlarePlacement placement;
    double intensityCd = 0;
    double projectedAreaM2 = 0;
};
LuminaireSight seeLuminaire(const GoniometricDistribution& distribution, double candelaScale, const LuminaireFrame& frame,
                            const LuminousArea& area, const V3d& luminaireM, const V3d& eyeM, const V3d& lineOfSight);
// The factor from a light's file candela to its candela in the scene (lumens, tilt; colour
// normalised to luminance 1): luminance(luminaireRadiantScale) x 683.
double luminaireCandelaScale(const Light& light);

// UGR from the background luminance and the sum of the sources' L^2 omega / p^2; nothing when
// either is not positive (no source in the field, or no background to rate against).
std::optional<double> unifiedGlareRating(double backgroundLuminanceCdM2, double sum);

// A task area's observers where it lists none (README, "Task areas"): four, at the midpoints of
// its sides, eyeHeightM above the floor (floorY, scene units), looking horizontally toward the
// area's centre.
std::vector<GlareObserver> defaultObservers(const TaskArea& area, double floorY, double metersPerUnit,
                                            double eyeHeightM = 1.2);

}  // namespace lucerna
