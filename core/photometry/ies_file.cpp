#include "core/photometry/ies_file.h"

#include "core/message_text.h"
#include "core/number_format.h"
#include "core/photometry/luminaire_file_fields.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace lucerna {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

void checkAscending(const LuminaireFileFields& t, size_t line, const std::vector<double>& v, const std::string& what) {
    for (size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1]))
            t.fail(line, what + " must increase, but " + shortestNumber(v[i]) + " follows " + shortestNumber(v[i - 1]));
}

}  // namespace

GoniometricDistribution parseIes(const std::string& text, const std::string& label) {
    std::vector<std::string> lines;
    {
        std::istringstream in(text);
        std::string l;
        while (std::getline(in, l)) lines.push_back(l);
    }
    // Header: an optional version line, keyword lines, then TILT=.
    std::string name, lumcat;
    size_t tiltLine = lines.size();
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string l = trimmed(lines[i]);
        if (upper(l).rfind("TILT", 0) == 0) {
            tiltLine = i;
            break;
        }
        if (l.size() > 1 && l[0] == '[') {
            const size_t close = l.find(']');
            if (close == std::string::npos) continue;
            const std::string key = upper(l.substr(1, close - 1));
            const std::string value = trimmed(l.substr(close + 1));
            if (key == "LUMINAIRE" && name.empty()) name = value;
            if (key == "LUMCAT" && lumcat.empty()) lumcat = value;
        }
    }
    if (tiltLine == lines.size())
        throw LuminaireFileError(label + ": line " + std::to_string(lines.size()) + ": no TILT= line (is this an IES file?)");
    const std::string tiltText = trimmed(lines[tiltLine]);
    const size_t eq = tiltText.find('=');
    const std::string tilt = eq == std::string::npos ? std::string() : upper(trimmed(tiltText.substr(eq + 1)));
    const int tiltLineNumber = int(tiltLine + 1);
    if (tilt != "NONE" && tilt != "INCLUDE")
        throw LuminaireFileError(label + ": line " + std::to_string(tiltLineNumber) + ": " + printableWord(tiltText, 60) +
                                 ": a separate tilt file is not supported (use TILT=INCLUDE or TILT=NONE)");

    // The numbers after the TILT line, separated by blanks or commas.
    LuminaireFileFields t = LuminaireFileFields::words(lines, tiltLine + 1, label);
    GoniometricDistribution d;
    d.name = !name.empty() ? name : lumcat;
    if (tilt == "INCLUDE") {
        t.integer("the lamp-to-luminaire geometry", 1, 3);
        const int n = t.integer("the number of tilt angles", 1, 1000);
        size_t line = t.line();
        d.tiltAngles = t.numbers(size_t(n), "tilt angles");
        checkAscending(t, line, d.tiltAngles, "tilt angles");
        line = t.line();
        d.tiltMultipliers = t.numbers(size_t(n), "tilt multipliers");
        for (double m : d.tiltMultipliers)
            if (m < 0) t.fail(line, "tilt multipliers must be at least 0, got " + shortestNumber(m));
    }
    const int lamps = t.integer("the number of lamps", 1, 1000000);
    size_t line = t.line();
    const double lumensPerLamp = t.number("lumens per lamp");
    if (!(lumensPerLamp > 0 || lumensPerLamp == -1))
        t.fail(line, "lumens per lamp must be positive, or -1 for absolute photometry, got " + shortestNumber(lumensPerLamp));
    const size_t lumensLine = line;
    line = t.line();
    const double multiplier = t.number("the candela multiplier");
    if (!(multiplier > 0)) t.fail(line, "the candela multiplier must be positive, got " + shortestNumber(multiplier));
    const size_t multiplierLine = line;
    const int nV = t.integer("the number of vertical angles", 2, 100000);
    const int nH = t.integer("the number of horizontal angles", 1, 100000);
    line = t.line();
    const int type = t.integer("the photometric type", 1, 3);
    if (type != 1)
        t.fail(line, std::string("photometric type ") + (type == 2 ? "B" : "A") + " is not supported (only type C)");
    // The luminous opening: width along C90-C270, length along C0-C180, height; in feet (units
    // type 1) or metres (2); LM-63-2002 marks round and elliptical openings by negative values.
    const int units = t.integer("the units type", 1, 2);
    const double toMetres = units == 1 ? 0.3048 : 1.0;
    const double width = t.number("the luminaire width"), length = t.number("the luminaire length");
    const double height = t.number("the luminaire height");
    line = t.line();
    const double ballast = t.number("the ballast factor");
    if (!(ballast > 0)) t.fail(line, "the ballast factor must be positive, got " + shortestNumber(ballast));
    const size_t ballastLine = line;
    t.number("the ballast-lamp factor (future use, or file generation type)");
    const double inputWatts = t.number("the input watts");

    line = t.line();
    std::vector<double> vertical = t.numbers(size_t(nV), "vertical angles");
    checkAscending(t, line, vertical, "vertical angles");
    if (!((vertical.front() == 0 || vertical.front() == 90) && (vertical.back() == 90 || vertical.back() == 180)))
        t.fail(line, "type C vertical angles must run from 0 or 90 to 90 or 180 degrees, got " +
                         shortestNumber(vertical.front()) + " to " + shortestNumber(vertical.back()));
    line = t.line();
    const std::vector<double> horizontal = t.numbers(size_t(nH), "horizontal angles");
    checkAscending(t, line, horizontal, "horizontal angles");
    const double last = horizontal.back();
    if (horizontal.front() != 0 || !(last == 0 || last == 90 || last == 180 || last == 360))
        t.fail(line, "type C horizontal angles must start at 0 and end at 0, 90, 180 or 360 degrees, got " +
                         shortestNumber(horizontal.front()) + " to " + shortestNumber(last));

    line = t.line();
    const size_t count = size_t(nV) * size_t(nH);
    const std::vector<double> values = t.numbers(count, "candela values");
    for (double v : values)
        if (v < 0) t.fail(line, "candela values must be at least 0, got " + shortestNumber(v));
    if (t.remaining() > 0)
        t.fail(t.line(), "expected " + std::to_string(count) + " candela values, found " +
                             std::to_string(count + t.remaining()));

    // The renderer works in single precision: a product beyond it (1e308 overflows to inf) would
    // give infinite flux and a black image.
    std::vector<std::vector<double>> columns(static_cast<size_t>(nH));
    for (size_t h = 0; h < size_t(nH); ++h)
        for (size_t v = 0; v < size_t(nV); ++v) {
            const double value = values[h * size_t(nV) + v];
            const double cd = value * multiplier * ballast;
            if (!(cd <= FLT_MAX))
                t.fail(multiplierLine, "candela value " + shortestNumber(value) + " times the candela multiplier " +
                                           shortestNumber(multiplier) + " (this line) and the ballast factor " +
                                           shortestNumber(ballast) + " (line " + std::to_string(ballastLine) +
                                           ") lies beyond single-precision range");
            columns[h].push_back(cd);
        }
    if (!(double(lamps) * lumensPerLamp * ballast <= FLT_MAX))
        t.fail(lumensLine, "the lamps' flux, " + std::to_string(lamps) + " x " + shortestNumber(lumensPerLamp) +
                               " lm times the ballast factor, lies beyond single-precision range");
    std::vector<CPlane> planes;
    for (size_t h = 0; h < horizontal.size(); ++h) planes.push_back({horizontal[h], h});
    if (last <= 90)  // quadrant (or rotational) symmetry: mirror about C90-C270 into 90..180
        for (size_t h = 0; h < horizontal.size(); ++h) planes.push_back({180.0 - horizontal[h], h});
    if (last <= 180) {  // mirror about C0-C180 into 180..360
        const size_t n = planes.size();
        for (size_t k = 0; k < n; ++k) planes.push_back({360.0 - planes[k].angleDeg, planes[k].column});
    }
    const std::string name2 = d.name;
    GoniometricDistribution full = assembleDistribution(std::move(planes), std::move(vertical), columns, label);
    full.name = name2;
    full.tiltAngles = std::move(d.tiltAngles);
    full.tiltMultipliers = std::move(d.tiltMultipliers);
    full.statedFluxLm = lumensPerLamp > 0 ? lamps * lumensPerLamp * ballast : 0.0;
    full.luminous.widthM = std::abs(width) * toMetres;
    full.luminous.lengthM = std::abs(length) * toMetres;
    full.luminous.elliptical = width < 0 || length < 0;
    for (double& h : full.luminous.heightsM) h = std::abs(height) * toMetres;
    if (inputWatts > 0 && inputWatts <= FLT_MAX) full.inputWatts = inputWatts;
    if (!(full.integratedFlux() <= FLT_MAX))
        t.fail(multiplierLine, "the candela values times the candela multiplier " + shortestNumber(multiplier) +
                                   " (this line) integrate to a flux beyond single-precision range");
    return full;
}

}  // namespace lucerna
