#include "core/photometry/glare.h"

#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
constexpr double kDegrees = 180.0 / std::numbers::pi;
const V3d kUp(0, 1, 0);
}  // namespace

double GlarePlacement::distanceM() const { return std::sqrt(alongM * alongM + aboveM * aboveM + asideM * asideM); }

bool GlarePlacement::inField() const {
    return alongM > 0 && aboveM > 0 && aboveM <= kGlareMaxHOverR * alongM && std::abs(asideM) <= kGlareMaxTOverR * alongM;
}

std::optional<V3d> horizontalLineOfSight(const V3d& view) {
    V3d h(view.x, 0, view.z);
    const double length = h.length();
    // A view within about 0.06 degrees of the vertical has no line of sight worth the name.
    if (!(length > 1e-3 * view.length()) || !std::isfinite(length)) return std::nullopt;
    return h / length;
}

GlarePlacement placeInView(const V3d& eye, const V3d& lineOfSight, const V3d& point, double metersPerUnit) {
    const V3d forward = horizontalLineOfSight(lineOfSight).value_or(V3d(0, 0, -1));
    const V3d right = forward.cross(kUp);
    const V3d d = (point - eye) * metersPerUnit;
    return {d.dot(forward), d.dot(kUp), d.dot(right)};
}

double guthTauDeg(double hOverR, double tOverR) { return std::atan2(std::abs(tOverR), hOverR) * kDegrees; }

double guthSigmaDeg(double hOverR, double tOverR) {
    return std::atan(std::sqrt(hOverR * hOverR + tOverR * tOverR)) * kDegrees;
}

double guthPositionIndex(double hOverR, double tOverR) {
    const double a = guthTauDeg(hOverR, tOverR), b = guthSigmaDeg(hOverR, tOverR);
    const double lnP = (35.2 - 0.31889 * a - 1.22 * std::exp(-2.0 * a / 9.0)) * 1e-3 * b +
                       (21.0 + 0.26667 * a - 0.002963 * a * a) * 1e-5 * b * b;
    return std::exp(lnP);
}

double LuminousArea::flatAreaM2() const {
    if (empty()) return 0;
    return elliptical ? std::numbers::pi / 4 * lengthM * widthM : lengthM * widthM;
}

LuminousArea luminousAreaOf(const GoniometricDistribution::LuminousOpening& opening) {
    LuminousArea a;
    if (!opening.stated()) return a;
    a.lengthM = opening.lengthM;
    a.widthM = opening.widthM;
    a.elliptical = opening.elliptical;
    for (int i = 0; i < 4; ++i) a.heightsM[i] = std::max(0.0, opening.heightsM[i]);
    return a;
}

LuminousArea luminousAreaOf(const Light& light) {
    if (light.type != LightType::Luminaire || !light.luminaire) return {};
    const LuminaireSpec& s = *light.luminaire;
    if (s.luminousAreaM) {
        LuminousArea a;
        a.widthM = s.luminousAreaM->x;
        a.lengthM = s.luminousAreaM->y;
        return a;
    }
    if (!s.distribution) return {};
    return luminousAreaOf(s.distribution->luminous);
}

double projectedLuminousArea(const LuminousArea& area, const V3d& w) {
    if (area.empty()) return 0;
    double projected = area.flatAreaM2() * std::max(0.0, w.z);
    const double* h = area.heightsM;
    if (area.elliptical) {
        // A vertical elliptic cylinder of semi-axes a (C0) and b (C90): its silhouette is as wide
        // as the ellipse across the horizontal part of w, 2 sqrt(a^2 wy^2 + b^2 wx^2).
        const double height = (h[0] + h[1] + h[2] + h[3]) / 4;
        const double a = area.lengthM / 2, b = area.widthM / 2;
        projected += 2 * height * std::sqrt(a * a * w.y * w.y + b * b * w.x * w.x);
    } else {
        // The sides facing C0 and C180 are as wide as the opening (along C90), those facing C90
        // and C270 as long (along C0).
        projected += h[0] * area.widthM * std::max(0.0, w.x) + h[2] * area.widthM * std::max(0.0, -w.x) +
                     h[1] * area.lengthM * std::max(0.0, w.y) + h[3] * area.lengthM * std::max(0.0, -w.y);
    }
    return projected;
}

GlareTerm glareTerm(double intensityCd, double projectedAreaM2, const GlarePlacement& placement) {
    GlareTerm t;
    if (!(projectedAreaM2 > 0)) return t;
    const double r = placement.distanceM();
    t.luminanceCdM2 = intensityCd / projectedAreaM2;
    t.solidAngleSr = projectedAreaM2 / (r * r);
    t.positionIndex = guthPositionIndex(placement.aboveM / placement.alongM, placement.asideM / placement.alongM);
    return t;
}

LuminaireSight seeLuminaire(const GoniometricDistribution& d, double candelaScale, const LuminaireFrame& frame,
                            const LuminousArea& area, const V3d& luminaireM, const V3d& eyeM, const V3d& lineOfSight) {
    LuminaireSight s;
    s.placement = placeInView(eyeM, lineOfSight, luminaireM, 1.0);
    const V3d toEye = eyeM - luminaireM;
    const double r = toEye.length();
    if (!(r > 0)) return s;
    const V3d w = toEye / r;
    const V3d local(w.dot(frame.c0), w.dot(frame.c90), w.dot(frame.nadir));
    const double gamma = std::acos(std::clamp(local.z, -1.0, 1.0)) * kDegrees;
    double c = std::atan2(local.y, local.x) * kDegrees;
    if (c < 0) c += 360;
    s.intensityCd = d.intensity(c, gamma) * candelaScale;
    s.projectedAreaM2 = projectedLuminousArea(area, local);
    return s;
}

double luminaireCandelaScale(const Light& light) { return luminance(luminaireRadiantScale(light)) * kLumensPerWatt; }

std::optional<double> unifiedGlareRating(double backgroundLuminanceCdM2, double sum) {
    if (!(backgroundLuminanceCdM2 > 0) || !(sum > 0)) return std::nullopt;
    return 8.0 * std::log10(0.25 / backgroundLuminanceCdM2 * sum);
}

std::vector<GlareObserver> defaultObservers(const TaskArea& area, double floorY, double metersPerUnit,
                                            double eyeHeightM) {
    const CalculationGrid& g = area.grid;
    const V3d centre = g.corner + g.edgeU * 0.5 + g.edgeV * 0.5;
    const double eyeY = floorY + eyeHeightM / metersPerUnit;
    std::vector<GlareObserver> observers;
    for (const V3d& midpoint : {g.corner + g.edgeU * 0.5, g.corner + g.edgeU + g.edgeV * 0.5,
                                g.corner + g.edgeV + g.edgeU * 0.5, g.corner + g.edgeV * 0.5}) {
        GlareObserver o;
        o.position = V3d(midpoint.x, eyeY, midpoint.z);
        const V3d toCentre(centre.x - midpoint.x, 0, centre.z - midpoint.z);
        o.view = toCentre.length() > 0 ? toCentre.normalized() : V3d(0, 0, -1);
        observers.push_back(o);
    }
    return observers;
}

}  // namespace lucerna
