#include "core/photometry/eulumdat_file.h"

#include "core/number_format.h"
#include "core/photometry/luminaire_file_fields.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>

namespace lucerna {

GoniometricDistribution parseEulumdat(const std::string& text, const std::string& label) {
    // EULUMDAT is one field per line.
    LuminaireFileFields in = LuminaireFileFields::lines(text, label);
    in.text("the company identification");
    in.integer("the type indicator", 0, 3);
    const int isym = in.integer("the symmetry indicator", 0, 4);
    const size_t mcLine = in.line();
    const int mc = in.integer("the number of C planes", 1, 100000);
    in.number("the distance between C planes");
    const int ng = in.integer("the number of intensities per C plane", 2, 100000);
    in.number("the distance between intensities");
    in.text("the measurement report number");
    const std::string name = in.text("the luminaire name");
    in.text("the luminaire number");
    in.text("the file name");
    in.text("the date and user");
    for (const char* what : {"the luminaire length", "the luminaire width", "the luminaire height"}) in.number(what);
    // The luminous area (mm): length or diameter along C0-C180, width along C90-C270 (0: round),
    // and the heights of its sides facing C0, C90, C180, C270.
    GoniometricDistribution::LuminousOpening opening;
    const double areaLengthMm = in.number("the luminous area length");
    const double areaWidthMm = in.number("the luminous area width");
    opening.lengthM = std::max(0.0, areaLengthMm) / 1000;
    opening.elliptical = areaWidthMm == 0;
    opening.widthM = opening.elliptical ? opening.lengthM : std::max(0.0, areaWidthMm) / 1000;
    for (int side = 0; side < 4; ++side)
        opening.heightsM[side] = std::max(0.0, in.number("the luminous area height C" + std::to_string(90 * side))) / 1000;
    in.number("the downward flux fraction");
    size_t here = in.line();
    const double lor = in.number("the light output ratio");
    if (!(lor > 0 && lor <= 100)) in.fail(here, "the light output ratio must be in (0, 100] percent, got " + shortestNumber(lor));
    here = in.line();
    const double cfli = in.number("the conversion factor for luminous intensities");
    if (!(cfli > 0)) in.fail(here, "the conversion factor must be positive, got " + shortestNumber(cfli));
    const size_t cfliLine = here;
    in.number("the measurement tilt");
    const int sets = in.integer("the number of standard sets of lamps", 1, 20);
    for (int i = 0; i < sets; ++i) in.number("the number of lamps");
    for (int i = 0; i < sets; ++i) in.text("the type of lamps");
    double lampFlux = 0;
    for (int i = 0; i < sets; ++i) {
        here = in.line();
        const double f = in.number("the total luminous flux of lamps");
        if (!(f > 0)) in.fail(here, "the total luminous flux of lamps must be positive, got " + shortestNumber(f));
        lampFlux += f;
        if (!(lampFlux <= FLT_MAX)) in.fail(here, "the lamps' total flux lies beyond single-precision range");
    }
    // The CCT when every set states the same number of kelvin ("4000", "4000K", "4000 K"); a
    // colour code ("840") or words ("warm white") state none.
    std::optional<double> cct;
    bool cctAgrees = true;
    for (int i = 0; i < sets; ++i) {
        std::string field = trimmed(in.text("the colour temperature"));
        if (!field.empty() && (field.back() == 'K' || field.back() == 'k')) field = trimmed(field.substr(0, field.size() - 1));
        const std::optional<double> k = fieldNumber(decimalPoints(field));
        const bool plausible = k && *k >= 1000 && *k <= 20000;
        if (!plausible || (cct && *cct != *k)) cctAgrees = false;
        else cct = k;
    }
    if (!cctAgrees) cct.reset();
    // Ra when the field is a number (some files give a group such as "1B": no Ra then).
    std::optional<double> ra;
    for (int i = 0; i < sets; ++i) {
        const std::optional<double> x = fieldNumber(decimalPoints(in.text("the colour rendering index")));
        if (x && *x > 0 && *x <= 100) ra = std::min(ra.value_or(*x), *x);
    }
    double watts = 0;
    for (int i = 0; i < sets; ++i) watts += std::max(0.0, in.number("the wattage"));
    for (int i = 0; i < 10; ++i) in.number("the direct ratios");

    here = in.line();
    const std::vector<double> cAngles = in.numbers(size_t(mc), "C angles");
    for (size_t i = 0; i < cAngles.size(); ++i) {
        if (!(cAngles[i] >= 0 && cAngles[i] < 360))
            in.fail(here + i, "C angles must be in [0, 360), got " + shortestNumber(cAngles[i]));
        if (i > 0 && !(cAngles[i] > cAngles[i - 1]))
            in.fail(here + i, "C angles must increase, but " + shortestNumber(cAngles[i]) + " follows " +
                                  shortestNumber(cAngles[i - 1]));
    }
    here = in.line();
    std::vector<double> gamma = in.numbers(size_t(ng), "gamma angles");
    for (size_t i = 0; i < gamma.size(); ++i) {
        if (!(gamma[i] >= 0 && gamma[i] <= 180))
            in.fail(here + i, "gamma angles must be in [0, 180], got " + shortestNumber(gamma[i]));
        if (i > 0 && !(gamma[i] > gamma[i - 1]))
            in.fail(here + i, "gamma angles must increase, but " + shortestNumber(gamma[i]) + " follows " +
                                  shortestNumber(gamma[i - 1]));
    }

    // Which measured planes the file holds (indices into cAngles), by symmetry indicator.
    size_t first = 0, count = size_t(mc);
    switch (isym) {
    case 0: break;
    case 1: count = 1; break;
    case 2: count = size_t(mc) / 2 + 1; break;
    case 3: first = size_t(mc) / 4; count = size_t(mc) / 2 + 1; break;
    case 4: count = size_t(mc) / 4 + 1; break;
    }
    if (first + count > size_t(mc) || (isym >= 2 && mc % (isym == 4 ? 4 : 2) != 0))
        in.fail(mcLine, std::to_string(mc) + " C planes do not fit symmetry indicator " + std::to_string(isym));

    here = in.line();
    const std::vector<double> values = in.numbers(count * size_t(ng), "intensities (cd/klm)");
    for (size_t i = 0; i < values.size(); ++i)
        if (values[i] < 0) in.fail(here + i, "intensities must be at least 0, got " + shortestNumber(values[i]));
    if (in.remaining() > 0)
        in.fail(in.line(), "expected " + std::to_string(values.size()) + " intensities (cd/klm), found " +
                               std::to_string(values.size() + in.remaining()));

    const double scale = lampFlux / 1000.0 * cfli;
    // The renderer works in single precision: a product beyond it (1e308 overflows to inf) would
    // give infinite flux and a black image.
    std::vector<std::vector<double>> columns(count);
    for (size_t c = 0; c < count; ++c)
        for (size_t g = 0; g < size_t(ng); ++g) {
            const double value = values[c * size_t(ng) + g];
            if (!(value * scale <= FLT_MAX))
                in.fail(cfliLine, "intensity " + shortestNumber(value) + " cd/klm times the lamps' " +
                                      shortestNumber(lampFlux) + " lm and the conversion factor " + shortestNumber(cfli) +
                                      " (this line) lies beyond single-precision range");
            columns[c].push_back(value * scale);
        }

    std::vector<CPlane> planes;
    for (size_t c = 0; c < count; ++c) {
        const double a = isym == 1 ? 0.0 : cAngles[first + c];
        planes.push_back({a, c});
        switch (isym) {
        case 1: planes.push_back({360.0, c}); break;
        case 2: planes.push_back({360.0 - a, c}); break;  // mirror about C0-C180
        case 3: planes.push_back({std::fmod(540.0 - a, 360.0), c}); break;  // about C90-C270
        case 4:
            planes.push_back({180.0 - a, c});
            planes.push_back({180.0 + a, c});
            planes.push_back({360.0 - a, c});
            break;
        default: break;
        }
    }
    GoniometricDistribution d = assembleDistribution(std::move(planes), std::move(gamma), columns, label);
    d.name = name;
    d.statedFluxLm = lampFlux * lor / 100.0;
    d.luminous = opening;
    if (watts > 0 && watts <= FLT_MAX) d.inputWatts = watts;
    d.colourRenderingIndex = ra;
    d.colourTemperatureK = cct;
    if (!(d.integratedFlux() <= FLT_MAX))
        in.fail(cfliLine, "the intensities times the conversion factor " + shortestNumber(cfli) +
                              " (this line) integrate to a flux beyond single-precision range");
    return d;
}

}  // namespace lucerna
