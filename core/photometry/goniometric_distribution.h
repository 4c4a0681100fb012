#pragma once
// A luminaire's goniometric (luminous intensity) distribution in IES type C photometry: intensity
// in candela tabulated over C planes (azimuth about the luminaire's nadir axis) and gamma angles
// (from the nadir, 0 = straight down the axis, 180 = straight up). Read from IES LM-63 and
// EULUMDAT files (core/photometry/ies_file.h, core/photometry/eulumdat_file.h); used by every backend through the
// scene's "luminaire" lights (README).

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucerna {

// A luminaire file that cannot be read: what() is one line "file: line N: problem".
class LuminaireFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct GoniometricDistribution {
    std::string name;                 // the luminaire's name or catalogue number, if the file gives one
    std::vector<double> cAngles;      // degrees, strictly ascending, 0 first and 360 last (the circle closed)
    std::vector<double> gammaAngles;  // degrees, strictly ascending, within [0, 180]; at least two
    std::vector<double> candela;      // cd, candela[c * gammaAngles.size() + g]
    // The flux the file states for what it describes, in lm: for IES the lamps' flux (lamps x
    // lumens per lamp x ballast factor), for EULUMDAT the luminaire's (lamp flux x light output
    // ratio); 0 when the file states none (IES absolute photometry, lumens per lamp -1).
    double statedFluxLm = 0;
    // IES TILT=INCLUDE: multipliers against the lamp's tilt angle (degrees); empty = no tilt table.
    std::vector<double> tiltAngles, tiltMultipliers;

    // The luminous opening the file states (IES: width, length, height; EULUMDAT: the luminous
    // area's length or diameter, width and heights), what UGR's luminance is read against:
    //   - lengthM along the C0-C180 axis, widthM along C90-C270, metres; both 0: none stated
    //     (a point source, for which UGR needs the scene's `luminous_area`);
    //   - elliptical: a disc (or an ellipse) of those diameters, else a rectangle;
    //   - heightsM: the luminous sides facing C0, C90, C180 and C270 (metres, 0: a flat opening).
    struct LuminousOpening {
        double lengthM = 0, widthM = 0;
        bool elliptical = false;
        double heightsM[4] = {0, 0, 0, 0};
        bool stated() const { return lengthM > 0 && widthM > 0; }
    } luminous;
    // The luminaire's electrical input the file states, W (IES input watts; EULUMDAT the lamp
    // sets' wattage including ballast, summed); absent when the file gives 0 or less.
    std::optional<double> inputWatts;
    // The colour rendering index Ra the file states (EULUMDAT's lamp set field, when it is a
    // number; the lowest of several sets); IES files state none.
    std::optional<double> colourRenderingIndex;
    // The correlated colour temperature the file states, K (EULUMDAT's lamp set field when it is
    // a number of kelvin, "4000" or "4000 K", the same for every set); IES files state none.
    std::optional<double> colourTemperatureK;

    double at(size_t c, size_t g) const { return candela[c * gammaAngles.size() + g]; }

    // Intensity (cd) at C (degrees, any value: periodic) and gamma (degrees, [0, 180]),
    // bilinear in the two angles; 0 outside the tabulated gamma range.
    double intensity(double cDeg, double gammaDeg) const;

    // Luminous flux (lm = cd sr) of the cell between C planes c, c+1 and gamma angles g, g+1:
    // the exact integral of the bilinear intensity against sin(gamma) dgamma dC.
    double cellFlux(size_t c, size_t g) const;
    // The distribution's total flux, the sum of cellFlux (exact for the bilinear interpolant).
    double integratedFlux() const;
    // The share of integratedFlux() in the cells below the horizontal (gamma <= 90 degrees): the
    // downward part of a luminaire's light (1 for a recessed panel, 0.8 for a 20% uplight).
    double downwardFraction() const;
    double maxIntensity() const;

    // The TILT=INCLUDE multiplier at a tilt angle (degrees), linear between the table's angles
    // and clamped at its ends; 1 without a table.
    double tiltMultiplier(double angleDeg) const;
};

// One measured C plane: its angle and which of the file's columns it holds (a mirror image of a
// measured plane names that plane's column).
struct CPlane {
    double angleDeg = 0;
    size_t column = 0;
};

// Assembles the full 0..360 table from C planes (measured ones and the mirror images a symmetry
// implies; duplicates of an angle keep the first) and the file's columns of gamma values. A plane
// at 360 is added from the one at 0 when missing. Throws LuminaireFileError(label: problem) when
// no plane lies at 0 or an angle is outside [0, 360].
GoniometricDistribution assembleDistribution(std::vector<CPlane> planes, std::vector<double> gammaAngles,
                                             const std::vector<std::vector<double>>& columns,
                                             const std::string& label);

}  // namespace lucerna
