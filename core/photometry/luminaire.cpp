#include "core/photometry/luminaire.h"

#include "core/photometry/eulumdat_file.h"
#include "core/photometry/ies_file.h"
#include "core/regular_file.h"

#include <fstream>
#include <sstream>

namespace lucerna {

GoniometricDistribution loadLuminaireFile(const std::string& path) {
    std::string ext;
    const size_t dot = path.rfind('.');
    if (dot != std::string::npos && path.find('/', dot) == std::string::npos)
        for (char c : path.substr(dot + 1)) ext += char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != "ies" && ext != "ldt")
        throw LuminaireFileError(path + ": not a luminaire file (expected the extension .ies or .ldt)");
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        throw LuminaireFileError(path + ": not a regular file (" + kind + ")");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LuminaireFileError(path + ": cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw LuminaireFileError(path + ": cannot read the file");
    return ext == "ies" ? parseIes(text.str(), path) : parseEulumdat(text.str(), path);
}

LuminaireFrame luminaireFrame(const V3d& direction, double rotationDeg) {
    LuminaireFrame f;
    f.nadir = direction.normalized();
    const V3d x(1, 0, 0);
    const V3d ref = std::abs(f.nadir.dot(x)) > 1.0 - 1e-9 ? V3d(0, 0, 1) : x;
    const V3d c0 = (ref - f.nadir * ref.dot(f.nadir)).normalized();
    const V3d c90 = c0.cross(f.nadir);
    const double r = radians(rotationDeg);
    f.c0 = c0 * std::cos(r) + c90 * std::sin(r);
    f.c90 = f.c0.cross(f.nadir);
    return f;
}

double luminaireTiltDeg(const V3d& direction) {
    const double c = std::clamp(direction.normalized().dot(V3d(0, -1, 0)), -1.0, 1.0);
    return std::acos(c) * 180.0 / std::numbers::pi;
}

Rgbd luminaireRadiantScale(const Light& l) {
    if (!l.luminaire || !l.luminaire->distribution) return Rgbd(0, 0, 0);
    const LuminaireSpec& s = *l.luminaire;
    const GoniometricDistribution& d = *s.distribution;
    const Rgbd white(1, 1, 1);
    const Rgbd colour = s.temperatureK ? blackbodyColour(*s.temperatureK)
                                       : s.colour.value_or(white) / luminance(s.colour.value_or(white));
    double scale = 1.0;
    if (s.lumens) {
        const double flux = d.integratedFlux();
        scale = flux > 0 ? *s.lumens / flux : 0.0;
    }
    scale *= d.tiltMultiplier(luminaireTiltDeg(l.direction));
    return colour * (scale / kLumensPerWatt);
}

double luminaireFlux(const Light& l) {
    if (!l.luminaire || !l.luminaire->distribution) return 0.0;
    return l.luminaire->distribution->integratedFlux() * luminance(luminaireRadiantScale(l)) * kLumensPerWatt;
}

}  // namespace lucerna
