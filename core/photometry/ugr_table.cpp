#include "core/photometry/ugr_table.h"

#include "core/photometry/luminaire.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;
constexpr double kHeightM = 2.0;  // H; UGR of the table does not depend on it

// Where a luminaire's downward light lands on a plane H below it: the flux of the directions
// landing at a < A and b < B (a along C0, b along C90, in units of H), tabulated at the corners
// of cells of H/8 out to 12.5 H each way (beyond the largest room) and bilinear in between, so
// that the flux reaching any rectangle of the plane costs four look-ups. The directions are a
// quarter-degree grid in gamma and half a degree in C, each carrying the distribution's flux in
// its cell (midpoint intensity times the cell's solid angle).
class LandingTable {
public:
    LandingTable(const GoniometricDistribution& d, double scale) {
        constexpr int kGammaSteps = 720, kCSteps = 720;  // 0.25 degrees over 180, 0.5 over 360
        std::vector<double> bins(size_t(kBins) * kBins, 0.0);
        const double dGamma = kPiD / kGammaSteps, dC = 2 * kPiD / kCSteps;
        for (int g = 0; g < kGammaSteps; ++g) {
            const double g0 = g * dGamma, g1 = g0 + dGamma, gm = g0 + dGamma / 2;
            const double solidAngle = (std::cos(g0) - std::cos(g1)) * dC;
            const double gammaDeg = gm * 180 / kPiD;
            for (int c = 0; c < kCSteps; ++c) {
                const double cm = (c + 0.5) * dC;
                const double flux = d.intensity(cm * 180 / kPiD, gammaDeg) * scale * solidAngle;
                if (!(flux > 0)) continue;
                if (g1 > kPiD / 2 + 1e-12) {
                    upward_ += flux;
                    continue;
                }
                downward_ += flux;
                const double t = std::tan(gm);
                bins[size_t(binOf(t * std::sin(cm))) * kBins + size_t(binOf(t * std::cos(cm)))] += flux;
            }
        }
        // cumulative_[j][i]: the flux of bins below edge j in b and edge i in a.
        const int n = kBins + 1;
        cumulative_.assign(size_t(n) * n, 0.0);
        for (int j = 1; j < n; ++j)
            for (int i = 1; i < n; ++i)
                cumulative_[size_t(j) * n + i] = bins[size_t(j - 1) * kBins + size_t(i - 1)] +
                                                 cumulative_[size_t(j - 1) * n + i] + cumulative_[size_t(j) * n + i - 1] -
                                                 cumulative_[size_t(j - 1) * n + i - 1];
    }

    double downward() const { return downward_; }
    double upward() const { return upward_; }
    // The flux landing in [a0, a1] x [b0, b1] (units of H).
    double inside(double a0, double a1, double b0, double b1) const {
        return below(a1, b1) - below(a0, b1) - below(a1, b0) + below(a0, b0);
    }

private:
    static constexpr double kStep = 0.125, kExtent = 12.5;
    static constexpr int kBins = 200;  // 2 x 12.5 / 0.125
    static int binOf(double x) { return std::clamp(int(std::floor((x + kExtent) / kStep)), 0, kBins - 1); }
    double below(double a, double b) const {
        const auto edge = [](double x, int& k, double& f) {
            const double u = std::clamp((x + kExtent) / kStep, 0.0, double(kBins));
            k = std::min(int(u), kBins - 1);
            f = u - k;
        };
        int i, j;
        double s, t;
        edge(a, i, s);
        edge(b, j, t);
        const int n = kBins + 1;
        const auto G = [&](int jj, int ii) { return cumulative_[size_t(jj) * n + ii]; };
        return (G(j, i) * (1 - s) + G(j, i + 1) * s) * (1 - t) + (G(j + 1, i) * (1 - s) + G(j + 1, i + 1) * s) * t;
    }

    std::vector<double> cumulative_;
    double downward_ = 0, upward_ = 0;
};

// What does not depend on the reflectances: the sources' sum and the direct flux on each surface.
struct ArrayFigures {
    double sum = 0;  // sum of L^2 omega / p^2 over the luminaires in the field
    int sources = 0;
    double floorFlux = 0, wallFlux = 0, ceilingFlux = 0;
};

struct Prepared {
    const GoniometricDistribution* d;
    double scale;  // candela of the table to candela at the luminaire's flux
    LuminousArea area;
    LandingTable landing;
};

Prepared prepare(const UgrLuminaire& l) {
    if (!l.distribution) throw std::invalid_argument("UGR table: no luminaire distribution");
    const GoniometricDistribution& d = *l.distribution;
    const double integrated = d.integratedFlux();
    if (!(integrated > 0)) throw std::invalid_argument("UGR table: the luminaire emits no light");
    const double scale = l.fluxLm > 0 ? l.fluxLm / integrated : 1.0;
    const LuminousArea area = l.area.empty() ? luminousAreaOf(d.luminous) : l.area;
    if (area.empty())
        throw std::invalid_argument("UGR table: the luminaire file states no luminous area (UGR needs its luminance)");
    return {&d, scale, area, LandingTable(d, scale)};
}

ArrayFigures arrayFigures(const Prepared& p, double spacingToHeight, const UgrRoom& room, UgrViewing viewing) {
    if (!(spacingToHeight > 0) || !(room.x > 0) || !(room.y > 0))
        throw std::invalid_argument("UGR table: the room and the spacing must be positive");
    const double H = kHeightM, X = room.x * H, Y = room.y * H;
    const int nx = std::max(1, int(std::lround(room.x / spacingToHeight)));
    const int ny = std::max(1, int(std::lround(room.y / spacingToHeight)));
    // Scene convention (y up), the line of sight along +z: crosswise puts C0 along it (rotation
    // 270 from the default C0 = +x of a luminaire hanging straight down), endwise C90 (180).
    const LuminaireFrame frame = luminaireFrame(V3d(0, -1, 0), viewing == UgrViewing::Crosswise ? 270.0 : 180.0);
    const V3d eye(X / 2, 0, 0), lineOfSight(0, 0, 1);
    ArrayFigures f;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const V3d at((i + 0.5) * X / nx, H, (j + 0.5) * Y / ny);
            const LuminaireSight s = seeLuminaire(*p.d, p.scale, frame, p.area, at, eye, lineOfSight);
            if (s.placement.inField() && s.intensityCd > 0 && s.projectedAreaM2 > 0) {
                f.sum += glareTerm(s.intensityCd, s.projectedAreaM2, s.placement).value();
                ++f.sources;
            }
            // The floor cavity in the luminaire's own axes (they are the room's, up to sign).
            double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
            for (const V3d& corner : {V3d(0, 0, 0), V3d(X, 0, 0), V3d(0, 0, Y), V3d(X, 0, Y)}) {
                const V3d d = (corner - V3d(at.x, 0, at.z)) / H;
                const double a = d.dot(frame.c0), b = d.dot(frame.c90);
                a0 = std::min(a0, a), a1 = std::max(a1, a), b0 = std::min(b0, b), b1 = std::max(b1, b);
            }
            f.floorFlux += p.landing.inside(a0, a1, b0, b1);
        }
    const double n = double(nx) * ny;
    f.ceilingFlux = n * p.landing.upward();
    f.wallFlux = std::max(0.0, n * p.landing.downward() - f.floorFlux);
    return f;
}

std::optional<double> ugrOf(const ArrayFigures& f, const UgrRoom& room, const UgrReflectances& set) {
    const double H = kHeightM;
    const double E = roomIndirectIlluminanceAtEye(room.x * H, room.y * H, H, set, f.floorFlux, f.wallFlux, f.ceilingFlux);
    return unifiedGlareRating(E / kPiD, f.sum);
}

}  // namespace

double opposedRectanglesViewFactor(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double x2 = 1 + x * x, y2 = 1 + y * y;
    const double sx = std::sqrt(x2), sy = std::sqrt(y2);
    return 2 / (kPiD * x * y) *
           (0.5 * std::log(x2 * y2 / (x2 + y2 - 1)) + x * sy * std::atan(x / sy) + y * sx * std::atan(y / sx) -
            x * std::atan(x) - y * std::atan(y));
}

double pointToPolygonViewFactor(const V3d& p, const V3d& n, const std::vector<V3d>& polygon) {
    double sum = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const V3d a = polygon[i] - p, b = polygon[(i + 1) % polygon.size()] - p;
        const V3d c = a.cross(b);
        const double length = c.length();
        if (!(length > 0)) continue;  // an edge whose line passes through p subtends nothing
        const double angle = std::atan2(length, a.dot(b));
        sum += angle * n.dot(c / length);
    }
    return std::abs(sum) / (2 * kPiD);
}

double roomIndirectIlluminanceAtEye(double X, double Y, double H, const UgrReflectances& set, double floorFlux,
                                    double wallFlux, double ceilingFlux) {
    const double aFloor = X * Y, aWalls = 2 * (X + Y) * H;
    const double fFC = opposedRectanglesViewFactor(X, Y, H);
    const double fFW = 1 - fFC;
    const double fWF = aFloor * fFW / aWalls;  // also wall to ceiling, by symmetry
    const double fWW = 1 - 2 * fWF;
    // Surfaces 0 floor cavity, 1 walls, 2 ceiling: M = rho (E + F M).
    const double F[3][3] = {{0, fFW, fFC}, {fWF, fWW, fWF}, {fFC, fFW, 0}};
    const double rho[3] = {set.floor, set.walls, set.ceiling};
    const double E[3] = {floorFlux / aFloor, wallFlux / aWalls, ceilingFlux / aFloor};
    double A[3][4];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j ? 1.0 : 0.0) - rho[i] * F[i][j];
        A[i][3] = rho[i] * E[i];
    }
    // Gaussian elimination; the matrix is diagonally dominant (reflectances below 1).
    for (int k = 0; k < 3; ++k)
        for (int i = k + 1; i < 3; ++i) {
            const double m = A[i][k] / A[k][k];
            for (int j = k; j < 4; ++j) A[i][j] -= m * A[k][j];
        }
    double M[3];
    for (int i = 2; i >= 0; --i) {
        double s = A[i][3];
        for (int j = i + 1; j < 3; ++j) s -= A[i][j] * M[j];
        M[i] = s / A[i][i];
    }
    // The eye lies in the floor cavity's plane at the middle of one wall, facing along the room:
    // the cavity fills the lower half of its view, the ceiling and the walls the upper half.
    const V3d eye(X / 2, 0, 0), facing(0, 0, 1);
    const double fCeiling = pointToPolygonViewFactor(eye, facing, {V3d(0, H, 0), V3d(X, H, 0), V3d(X, H, Y), V3d(0, H, Y)});
    return 0.5 * M[0] + (0.5 - fCeiling) * M[1] + fCeiling * M[2];
}

std::optional<double> tabularUgr(const UgrLuminaire& luminaire, double spacingToHeight, const UgrRoom& room,
                                 UgrViewing viewing, const UgrReflectances& set) {
    const Prepared p = prepare(luminaire);
    return ugrOf(arrayFigures(p, spacingToHeight, room, viewing), room, set);
}

UgrTable ugrTable(const UgrLuminaire& luminaire, double spacingToHeight) {
    const Prepared p = prepare(luminaire);
    UgrTable t;
    t.spacingToHeight = spacingToHeight;
    t.fluxLm = p.landing.downward() + p.landing.upward();
    for (const UgrRoom& room : kUgrRooms) {
        auto& row = t.values.emplace_back();
        for (int v = 0; v < 2; ++v) {
            const ArrayFigures f = arrayFigures(p, spacingToHeight, room, v == 0 ? UgrViewing::Crosswise : UgrViewing::Endwise);
            for (size_t s = 0; s < kUgrReflectanceSets.size(); ++s)
                row[size_t(v)][s] = ugrOf(f, room, kUgrReflectanceSets[s]).value_or(std::numeric_limits<double>::quiet_NaN());
        }
    }
    return t;
}

}  // namespace lucerna
