#pragma once
// The tabular method of CIE 117-1995 as CIE 190:2010 lays out a luminaire's UGR table (README,
// "Glare (UGR)"): UGR for a regular array of one luminaire in standard rooms, seen by an observer
// seated at the middle of one wall, at eye level, looking horizontally along the room.
//
// Geometry (all in units of H, the height of the luminaire plane above the eye; UGR does not
// depend on H itself, which is taken as 2 m): the room spans X across the line of sight and Y
// along it; the luminaires hang at the ceiling plane H above the eye in the centres of an array of
// square cells of side S (spacing-to-height S/H: 1 or 0.25), the first row S/2 from the
// observer's wall; the eye at the middle of that wall. The rows: X = 2H by Y = 2, 3, 4, 6, 8, 12H;
// X = 4H by Y = 2 to 12H; X = 8H by Y = 4 to 12H; X = 12H by Y = 4, 6, 8H. Columns: the five
// reflectance sets of ceiling, walls and floor cavity, viewed crosswise and endwise.
//
// Crosswise and endwise. Crosswise: the line of sight runs along the luminaires' C0-C180 plane,
// the observer looking toward C0 (so the luminaires ahead are seen from their C180 side, and a
// linear luminaire whose lamps run along C90-C270, as EULUMDAT files usually describe one, is
// seen across its length). Endwise: the line of sight runs along C90-C270, looking toward C90.
//
// The sources: every luminaire in the field of view of core/photometry/glare.h (H/R <= 1.9, |T|/R <= 3),
// with its luminance from the file's candela toward the eye and the projected area of its
// luminous opening (core/photometry/glare.h); their flux is the luminaire's as given.
//
// The background, Lb = E_ind / pi, E_ind the indirect illuminance at the eye (vertical, facing
// the line of sight), by a three-surface radiosity of the room: the floor cavity (a plane at eye
// level, the set's floor reflectance), the walls between it and the ceiling plane, and the
// ceiling; each uniform in exitance, with the exact view factors of the box (parallel opposed
// rectangles; the rest by reciprocity and closure) and the direct flux of the array on each
// surface: the floor cavity's exact for the table (each luminaire's flux landing inside the
// rectangle, from a cumulative table of where its downward directions land, tabulated on a
// quarter-degree grid), the ceiling the whole upward flux (the luminaires are at the ceiling
// plane), the walls the rest. The eye sees the floor cavity over half of its hemisphere (it
// lies in that plane), the ceiling by the exact view factor of a vertical element to the
// rectangle, and the walls over the rest.
//
// How this differs from CIE 190's own formulae: CIE 190 takes Lb from the walls' average
// indirect illuminance, found with the transfer factors of CIE 52 for the room index, rather
// than the illuminance at the eye itself; here the eye sees the three surfaces by its own view
// factors, which is what a calculation at an observer in the scene
// (render/photometry/glare_evaluation.h) estimates. Both assume uniform exitance per surface.
// Values may therefore differ from a manufacturer's published table by a few tenths of a unit.
// Tables normalised to another flux F0 differ by 8 log10(flux / F0).

#include "core/photometry/glare.h"
#include "core/photometry/goniometric_distribution.h"

#include <array>
#include <vector>

namespace lucerna {

struct UgrReflectances {
    double ceiling, walls, floor;
};
inline constexpr std::array<UgrReflectances, 5> kUgrReflectanceSets{
    {{0.7, 0.5, 0.2}, {0.7, 0.3, 0.2}, {0.5, 0.5, 0.2}, {0.5, 0.3, 0.2}, {0.3, 0.3, 0.2}}};

struct UgrRoom {
    double x, y;  // across and along the line of sight, in units of H
};
inline constexpr std::array<UgrRoom, 19> kUgrRooms{{{2, 2},  {2, 3},  {2, 4},  {2, 6},  {2, 8},  {2, 12}, {4, 2},
                                                    {4, 3},  {4, 4},  {4, 6},  {4, 8},  {4, 12}, {8, 4},  {8, 6},
                                                    {8, 8},  {8, 12}, {12, 4}, {12, 6}, {12, 8}}};

enum class UgrViewing { Crosswise, Endwise };

// The table for one spacing-to-height ratio: values[room][viewing][set], in kUgrRooms' and
// kUgrReflectanceSets' order (viewing 0 crosswise, 1 endwise). NaN where no luminaire is in the
// field of view.
struct UgrTable {
    double spacingToHeight = 1;
    double fluxLm = 0;
    std::vector<std::array<std::array<double, 5>, 2>> values;
};

// The luminaire of a table: its distribution (candela as in the file), its flux (the
// distribution is scaled to it) and its luminous area.
struct UgrLuminaire {
    const GoniometricDistribution* distribution = nullptr;
    double fluxLm = 0;     // 0: the distribution's own integrated flux
    LuminousArea area;     // empty: the file's opening
};

// One value of the table: UGR of the array at spacing S/H in room `room` viewed `viewing` under
// `set`. Nothing when no luminaire is in the field of view. Throws std::invalid_argument (one
// line) when the luminaire has no luminous area or no flux.
std::optional<double> tabularUgr(const UgrLuminaire& luminaire, double spacingToHeight, const UgrRoom& room,
                                 UgrViewing viewing, const UgrReflectances& set);

// The whole table at one spacing. Throws as tabularUgr.
UgrTable ugrTable(const UgrLuminaire& luminaire, double spacingToHeight);

// The indirect illuminance at the eye (lx) of the three-surface model above, for direct fluxes
// (lm) on the floor cavity, walls and ceiling of a room X x Y x H (metres): exposed for tests.
double roomIndirectIlluminanceAtEye(double xM, double yM, double hM, const UgrReflectances& set, double floorFluxLm,
                                    double wallFluxLm, double ceilingFluxLm);
// The view factor between two directly opposed parallel rectangles a x b at distance c.
double opposedRectanglesViewFactor(double a, double b, double c);
// The view factor from a differential element at p (unit normal n) to a planar polygon wholly on
// its front side or on its plane (Lambert's contour formula).
double pointToPolygonViewFactor(const V3d& p, const V3d& n, const std::vector<V3d>& polygon);

}  // namespace lucerna
