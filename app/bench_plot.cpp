#include "app/bench_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>

namespace lucerna::cli {

namespace {

// Colour-blind-safe palette (Okabe and Ito), cycled when there are more backends.
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};

std::string escapeXml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// A decade's label: plain numbers near 1, powers of ten elsewhere.
std::string decadeLabel(int e) {
    if (e >= -2 && e <= 3) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, e));
        return buf;
    }
    return "1e" + std::to_string(e);
}

struct Panel {
    double x0, y0, w, h;  // plotting area in SVG units
    std::string yLabel;
    std::function<double(const BenchSample&)> value;
};

void drawPanel(std::ostringstream& svg, const Panel& p, const std::vector<BenchSample>& samples,
               const std::vector<std::string>& backends) {
    const auto usable = [](double v) { return std::isfinite(v) && v > 0; };
    double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
    for (const BenchSample& s : samples) {
        const double v = p.value(s);
        if (!usable(s.seconds) || !usable(v)) continue;
        xMin = std::min(xMin, s.seconds), xMax = std::max(xMax, s.seconds);
        yMin = std::min(yMin, v), yMax = std::max(yMax, v);
    }
    if (!(xMin <= xMax)) xMin = 0.1, xMax = 10, yMin = 1e-3, yMax = 1;  // nothing to draw: empty axes
    // Whole decades on both axes, at least one each, so the grid lines frame the curves.
    const int ex0 = int(std::floor(std::log10(xMin))), ex1 = std::max(ex0 + 1, int(std::ceil(std::log10(xMax))));
    const int ey0 = int(std::floor(std::log10(yMin))), ey1 = std::max(ey0 + 1, int(std::ceil(std::log10(yMax))));
    const auto px = [&](double x) { return p.x0 + (std::log10(x) - ex0) / (ex1 - ex0) * p.w; };
    const auto py = [&](double y) { return p.y0 + p.h - (std::log10(y) - ey0) / (ey1 - ey0) * p.h; };

    svg << "<rect x=\"" << fmt(p.x0) << "\" y=\"" << fmt(p.y0) << "\" width=\"" << fmt(p.w) << "\" height=\""
        << fmt(p.h) << "\" fill=\"white\" stroke=\"#333\"/>\n";
    for (int e = ex0; e <= ex1; ++e) {
        const double x = p.x0 + double(e - ex0) / (ex1 - ex0) * p.w;
        svg << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(p.y0) << "\" x2=\"" << fmt(x) << "\" y2=\""
            << fmt(p.y0 + p.h) << "\" stroke=\"#ccc\"/>\n";
        svg << "<text x=\"" << fmt(x) << "\" y=\"" << fmt(p.y0 + p.h + 16) << "\" text-anchor=\"middle\">"
            << decadeLabel(e) << "</text>\n";
        for (int m = 2; m <= 9 && e < ex1; ++m) {  // minor ticks
            const double xm = px(m * std::pow(10.0, e));
            svg << "<line x1=\"" << fmt(xm) << "\" y1=\"" << fmt(p.y0 + p.h - 5) << "\" x2=\"" << fmt(xm)
                << "\" y2=\"" << fmt(p.y0 + p.h) << "\" stroke=\"#333\"/>\n";
        }
    }
    for (int e = ey0; e <= ey1; ++e) {
        const double y = p.y0 + p.h - double(e - ey0) / (ey1 - ey0) * p.h;
        svg << "<line x1=\"" << fmt(p.x0) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(p.x0 + p.w) << "\" y2=\""
            << fmt(y) << "\" stroke=\"#ccc\"/>\n";
        svg << "<text x=\"" << fmt(p.x0 - 6) << "\" y=\"" << fmt(y + 4) << "\" text-anchor=\"end\">" << decadeLabel(e)
            << "</text>\n";
    }
    svg << "<text x=\"" << fmt(p.x0 + p.w / 2) << "\" y=\"" << fmt(p.y0 + p.h + 36)
        << "\" text-anchor=\"middle\">time (s)</text>\n";
    svg << "<text transform=\"translate(" << fmt(p.x0 - 46) << "," << fmt(p.y0 + p.h / 2)
        << ") rotate(-90)\" text-anchor=\"middle\">" << escapeXml(p.yLabel) << "</text>\n";

    for (size_t b = 0; b < backends.size(); ++b) {
        std::string points;
        for (const BenchSample& s : samples) {
            const double v = p.value(s);
            if (s.backend != backends[b] || !usable(s.seconds) || !usable(v)) continue;
            points += fmt(px(s.seconds)) + "," + fmt(py(v)) + " ";
        }
        if (points.empty()) continue;
        svg << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << kColours[b % std::size(kColours)]
            << "\" points=\"" << points << "\"/>\n";
    }
}

}  // namespace

std::string errorPlotSvg(const std::vector<BenchSample>& samples, const std::string& title) {
    std::vector<std::string> backends;
    for (const BenchSample& s : samples)
        if (std::find(backends.begin(), backends.end(), s.backend) == backends.end()) backends.push_back(s.backend);

    const double panelW = 380, panelH = 300, top = 50, left = 70, gap = 90;
    const double legendH = 24.0 * double(backends.size()) + 10;
    const double width = left + 2 * panelW + gap + 30, height = top + panelH + 60 + legendH;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width) << "\" height=\"" << fmt(height)
        << "\" viewBox=\"0 0 " << fmt(width) << " " << fmt(height)
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<text x=\"" << fmt(width / 2) << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" << escapeXml(title)
        << "</text>\n";
    drawPanel(svg, {left, top, panelW, panelH, "relmse", [](const BenchSample& s) { return s.relmse; }}, samples,
              backends);
    drawPanel(svg, {left + panelW + gap, top, panelW, panelH, "rmse", [](const BenchSample& s) { return s.rmse; }},
              samples, backends);
    // Legend under the panels: one line per backend, in the curves' colours.
    const double ly = top + panelH + 56;
    for (size_t b = 0; b < backends.size(); ++b) {
        const double y = ly + 24.0 * double(b);
        svg << "<line x1=\"" << fmt(left) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(left + 30) << "\" y2=\""
            << fmt(y) << "\" stroke-width=\"3\" stroke=\"" << kColours[b % std::size(kColours)] << "\"/>\n";
        svg << "<text x=\"" << fmt(left + 38) << "\" y=\"" << fmt(y + 4) << "\">" << escapeXml(backends[b])
            << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace lucerna::cli
