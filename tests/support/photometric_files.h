#pragma once
// Photometric files written by the tests themselves (test_luminaire, test_luminaire_scenes): IES
// LM-63 and EULUMDAT text for an intensity given as a function, and closed-form distributions
// whose flux is known (isotropic: 4 pi I0; cosine: pi I0; a 10 degree beam with a 2 degree
// linear ramp).

#include <QString>

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace lucerna::test {

inline constexpr double kPiD = std::numbers::pi;
inline constexpr double kDegD = kPiD / 180.0;
using Intensity = std::function<double(double cDeg, double gammaDeg)>;

inline std::vector<double> steps(double from, double to, double step) {
    std::vector<double> v;
    const int n = int(std::lround((to - from) / step));
    for (int i = 0; i <= n; ++i) v.push_back(from + step * i);
    return v;
}

inline std::string num(double x) {
    std::ostringstream s;
    s.precision(12);
    s << x;
    return s.str();
}

// An LM-63-2002 file of type C photometry, ten values a line.
inline std::string iesText(const std::vector<double>& vertical, const std::vector<double>& horizontal, const Intensity& I,
                    double lumensPerLamp = 1000, const std::string& tilt = "TILT=NONE", double multiplier = 1) {
    std::ostringstream s;
    s << "IESNA:LM-63-2002\n[TEST] written by test_luminaire\n[LUMINAIRE] test luminaire\n" << tilt << "\n";
    s << "1 " << num(lumensPerLamp) << " " << num(multiplier) << " " << vertical.size() << " " << horizontal.size()
      << " 1 2 0.1 0.1 0.05\n1.0 1.0 10\n";
    const auto list = [&](const std::vector<double>& v) {
        for (size_t i = 0; i < v.size(); ++i) s << num(v[i]) << ((i % 10 == 9 || i + 1 == v.size()) ? "\n" : " ");
    };
    list(vertical);
    list(horizontal);
    for (double h : horizontal) {
        std::vector<double> col;
        for (double v : vertical) col.push_back(I(h, v) / multiplier);
        list(col);
    }
    return s.str();
}

// A EULUMDAT file: mc C planes dc apart, the planes the symmetry indicator keeps, in cd/klm of
// lampFlux, light output ratio lor percent.
inline std::string ldtText(int isym, int mc, const std::vector<double>& gamma, const Intensity& I, double lampFlux, double lor) {
    const double dc = 360.0 / mc;
    std::ostringstream s;
    s << "Lucerna tests\n1\n" << isym << "\n" << mc << "\n" << num(dc) << "\n" << gamma.size() << "\n"
      << num(gamma.size() > 1 ? gamma[1] - gamma[0] : 0) << "\nreport\ntest luminaire\nT-1\ntest.ldt\n2026-11-23\n";
    for (int i = 0; i < 10; ++i) s << "100\n";  // dimensions, downward flux fraction
    s << num(lor) << "\n1.0\n0\n1\n1\nLED\n" << num(lampFlux) << "\n3000\n90\n20\n";
    for (int i = 0; i < 10; ++i) s << "0.5\n";
    for (int i = 0; i < mc; ++i) s << num(i * dc) << "\n";
    for (double g : gamma) s << num(g) << "\n";
    size_t first = 0, count = size_t(mc);
    if (isym == 1) count = 1;
    if (isym == 2) count = size_t(mc) / 2 + 1;
    if (isym == 3) first = size_t(mc) / 4, count = size_t(mc) / 2 + 1;
    if (isym == 4) count = size_t(mc) / 4 + 1;
    for (size_t c = first; c < first + count; ++c)
        for (double g : gamma) s << num(I(c * dc, g) * 1000.0 / lampFlux) << "\n";
    return s.str();
}

inline const Intensity kIsotropic = [](double, double) { return 100.0; };
inline const Intensity kCosine = [](double, double g) { return g <= 90 ? 100.0 * std::max(0.0, std::cos(g * kDegD)) : 0.0; };
// 10 degrees at I0, a linear ramp to 0 at 12 degrees.
inline const Intensity kBeam = [](double, double g) { return g <= 10 ? 5000.0 : g >= 12 ? 0.0 : 5000.0 * (12 - g) / 2; };
// Quadrant-symmetric (about both C0-C180 and C90-C270) and asymmetric in gamma.
inline const Intensity kQuadrant = [](double c, double g) {
    return 200.0 * (1.0 + 0.5 * std::cos(2 * c * kDegD)) * (1.0 + std::cos(g * kDegD)) + 10;
};
// Brighter toward C0 than C180 (symmetric only about C0-C180): shows which way the frame turns.
inline const Intensity kAsymmetric = [](double c, double g) {
    return g <= 90 ? 800.0 * (1.0 + 0.6 * std::cos(c * kDegD)) * std::cos(g * kDegD) : 0.0;
};

// The beam's flux: 2 pi (I0 (1 - cos 10) + integral over the ramp of I sin), by Simpson's rule.
inline double beamFlux() {
    double ramp = 0;
    const int n = 20000;
    const double a = 10 * kDegD, b = 12 * kDegD, h = (b - a) / n;
    for (int i = 0; i <= n; ++i) {
        const double g = a + i * h;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        ramp += w * kBeam(0, g / kDegD) * std::sin(g);
    }
    ramp *= h / 3;
    return 2 * kPiD * (5000.0 * (1 - std::cos(10 * kDegD)) + ramp);
}

inline void writeFile(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

}  // namespace lucerna::test
