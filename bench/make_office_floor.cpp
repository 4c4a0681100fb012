// Writes the bundled office floor scenes and everything they read:
//   bench_make_office_floor SCENES_DIR        (SCENES_DIR: resources/scenes)
// - luminaires/office_panel.ies: a recessed 600 x 600 LED panel, rotationally symmetric, a mild
//   batwing (peak near 30 degrees) cut off toward the horizontal for glare, no uplight;
// - luminaires/office_linear.ldt: a suspended linear direct/indirect luminaire (EULUMDAT,
//   symmetry 4), a batwing across its length (C0-C180), a cosine along it, 20% uplight;
// - meshes/office/*.obj: one file per material (floor, ceiling, walls, columns, desks,
//   partitions, meeting tables, cabinets), shared by both scenes;
// - office_floor.json: 84 panels over the open-plan desks and 24 linear pendants over the meeting
//   zone (108 luminaires, 4000 K), the project and two task areas for its report;
// - office_floor_points.json: the same geometry with an isotropic point light of the same flux and
//   colour in place of each luminaire, given as `intensity` only (what ../shared/tools/cycles_ref.sh
//   converts), hung 0.4 m below the ceiling so that their upward half washes the ceiling instead
//   of burning a spot into it.
// The files are written deterministically: running this again reproduces them byte for byte.

#include "core/photometry/eulumdat_file.h"
#include "core/photometry/ies_file.h"
#include "core/photometry/photometric_units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

// The floor plan (metres, y up): the open office lies in z < 13, the meeting zone beyond it.
constexpr double kRoomW = 36.0, kRoomD = 21.6, kRoomH = 3.0;
constexpr int kLuminairesX = 12, kLuminairesZ = 9;   // 3.0 m x 2.4 m spacing
constexpr int kPanelRows = 7;                        // rows of panels; the last two rows are pendants
constexpr double kPanelLumens = 3600, kLinearLumens = 4000, kTemperatureK = 4000;
constexpr double kPanelHeight = 2.99, kPendantHeight = 2.6, kPointHeight = 2.6;

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "bench_make_office_floor: %s\n", what.c_str());
    std::exit(1);
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) fail("cannot write " + path.string());
    std::printf("%s (%zu bytes)\n", path.string().c_str(), text.size());
}

// Shortest fixed form with up to `decimals` digits: "1.2", "0", "-0.815".
std::string num(double x, int decimals = 3) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

// (Streams, not operator+: GCC 12 warns falsely about chains of string additions.)
std::string triple(double x, double y, double z, int decimals) {
    std::ostringstream s;
    s << "[" << num(x, decimals) << ", " << num(y, decimals) << ", " << num(z, decimals) << "]";
    return s.str();
}
std::string vec(double x, double y, double z) { return triple(x, y, z, 3); }
std::string rgb(const Rgbd& c, int decimals) { return triple(c.x, c.y, c.z, decimals); }

// --- photometry -------------------------------------------------------------------------------

double smoothstep(double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}
double rad(double deg) { return deg * std::numbers::pi / 180; }

// Relative intensity of the panel at gamma (degrees from the nadir).
double panelShape(double gammaDeg) {
    const double g = rad(gammaDeg), s = std::sin(g);
    if (gammaDeg >= 90) return 0;
    return std::cos(g) * (1 + 0.8 * s * s) * (1 - smoothstep(50, 85, gammaDeg));
}

// Relative intensity of the linear luminaire at C (degrees; 0 across its length) and gamma.
double linearShape(double cDeg, double gammaDeg, double uplightWeight) {
    const double g = rad(gammaDeg), s = std::sin(g), c = std::cos(rad(cDeg));
    if (gammaDeg < 90) return std::cos(g) * (1 + 0.9 * s * s * c * c) * (1 - smoothstep(55, 80, gammaDeg));
    const double fromZenith = rad(180 - gammaDeg);
    return uplightWeight * std::pow(std::cos(fromZenith), 1.5) * (1 + 0.3 * c * c);
}

std::string iesText(double scale) {
    std::ostringstream s;
    s << "IESNA:LM-63-2002\n"
         "[TEST] none: a made-up distribution\n"
         "[_LUCERNA] written by bench/make_office_floor.cpp for office_floor.json; not a measured product\n"
         "[MANUFAC] Lucerna example\n"
         "[LUMINAIRE] recessed LED panel 600 x 600, mild batwing, glare cut-off\n"
         "[LAMP] LED module, "
      << num(kPanelLumens, 0)
      << " lm\n"
         "TILT=NONE\n"
         "1 "
      << num(kPanelLumens, 0) << " 1 19 1 1 2 0.6 0.6 0\n1.0 1.0 30\n";
    for (int g = 0; g <= 90; g += 5) s << g << (g == 90 ? "\n" : " ");
    s << "0\n";
    for (int g = 0; g <= 90; g += 5) s << num(scale * panelShape(g), 2) << (g == 90 ? "\n" : " ");
    return s.str();
}

// EULUMDAT with symmetry 4: the planes C0 to C90 of 24 (15 degrees apart), gamma 0 to 180 by 5.
std::string ldtText(double scale, double uplightWeight) {
    std::ostringstream s;
    s << "Lucerna example (written by bench/make_office_floor.cpp; not a measured product)\n"
         "1\n4\n24\n15\n37\n5\nnone\n"
         "linear pendant, direct/indirect\nLP-1\noffice_linear.ldt\n2026-12-03 Lucerna\n"
         "1500\n120\n50\n1450\n100\n0\n0\n0\n0\n";
    s << "80\n100\n1\n0\n1\n1\nLED\n" << num(kLinearLumens, 0) << "\n4000\n80\n32\n";
    for (int i = 0; i < 10; ++i) s << "0.5\n";
    for (int c = 0; c < 360; c += 15) s << c << "\n";
    for (int g = 0; g <= 180; g += 5) s << g << "\n";
    // cd/klm of the lamps' flux.
    for (int c = 0; c <= 90; c += 15)
        for (int g = 0; g <= 180; g += 5) s << num(scale * linearShape(c, g, uplightWeight), 2) << "\n";
    return s.str();
}

// Writes the two files with their tables scaled so that each integrates to the flux it states
// (IES: the lamp lumens; EULUMDAT: lamp flux x 100% light output ratio), so that `lucerna info`
// finds them consistent.
void writeLuminaires(const std::filesystem::path& dir) {
    const double panelFlux = parseIes(iesText(1.0), "panel").integratedFlux();
    writeFile(dir / "office_panel.ies", iesText(kPanelLumens / panelFlux));

    // Uplight weight for a 20% upward share: the share is linear in the weight's odds.
    const auto share = [](double w) { return 1 - parseEulumdat(ldtText(1.0, w), "linear").downwardFraction(); };
    const double s1 = share(1.0);
    const double w = (0.2 / 0.8) / (s1 / (1 - s1));
    const double linearFlux = parseEulumdat(ldtText(1.0, w), "linear").integratedFlux();
    // The table is cd per 1000 lm of the lamps; it integrates to 1000 lm for a 100% output ratio,
    // and the parsed table (times the lamps' flux / 1000) to the lamps' flux.
    const std::string ldt = ldtText(kLinearLumens / linearFlux, w);
    writeFile(dir / "office_linear.ldt", ldt);
    const GoniometricDistribution check = parseEulumdat(ldt, "linear");
    std::printf("office_linear.ldt: %.1f lm, %.1f%% up\n", check.integratedFlux(), 100 * (1 - check.downwardFraction()));
}

// --- geometry -----------------------------------------------------------------------------------

// An OBJ file of quads (every face planar), vertices in metres.
class ObjFile {
public:
    explicit ObjFile(std::string comment) : comment_(std::move(comment)) {}

    // Counter-clockwise seen from the side the face looks at.
    void quad(const V3d& a, const V3d& b, const V3d& c, const V3d& d) {
        const int base = int(vertices_.size()) + 1;
        for (const V3d& v : {a, b, c, d}) vertices_.push_back(v);
        faces_.push_back({base, base + 1, base + 2, base + 3});
    }

    // A closed box, faces looking out.
    void box(double x0, double y0, double z0, double x1, double y1, double z1) {
        const int base = int(vertices_.size()) + 1;
        for (int i = 0; i < 8; ++i) vertices_.push_back(V3d(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0));
        const std::array<std::array<int, 4>, 6> faces{{{0, 4, 6, 2}, {1, 3, 7, 5},    // -x, +x
                                                       {0, 1, 5, 4}, {2, 6, 7, 3},    // -y, +y
                                                       {0, 2, 3, 1}, {4, 5, 7, 6}}};  // -z, +z
        for (const auto& f : faces) faces_.push_back({base + f[0], base + f[1], base + f[2], base + f[3]});
    }

    size_t triangles() const { return faces_.size() * 2; }

    std::string text() const {
        std::ostringstream s;
        s << "# " << comment_ << " (bench/make_office_floor.cpp; metres, y up)\n";
        for (const V3d& v : vertices_) s << "v " << num(v.x) << " " << num(v.y) << " " << num(v.z) << "\n";
        for (const auto& f : faces_) s << "f " << f[0] << " " << f[1] << " " << f[2] << " " << f[3] << "\n";
        return s.str();
    }

private:
    std::string comment_;
    std::vector<V3d> vertices_;
    std::vector<std::array<int, 4>> faces_;
};

struct Part {
    std::string name, material, file;
    ObjFile obj;
};

std::vector<Part> buildGeometry() {
    std::vector<Part> parts;
    const auto part = [&](const std::string& name, const std::string& material, const std::string& comment) -> ObjFile& {
        parts.push_back({name, material, "meshes/office/" + name + ".obj", ObjFile(comment)});
        return parts.back().obj;
    };
    const double W = kRoomW, D = kRoomD, H = kRoomH;
    // The shell's faces look into the room.
    part("floor", "floor", "office floor: the floor").quad({0, 0, 0}, {0, 0, D}, {W, 0, D}, {W, 0, 0});
    part("ceiling", "ceiling", "office floor: the ceiling").quad({0, H, 0}, {W, H, 0}, {W, H, D}, {0, H, D});
    ObjFile& walls = part("walls", "wall", "office floor: the four walls");
    walls.quad({0, 0, 0}, {W, 0, 0}, {W, H, 0}, {0, H, 0});  // south, z = 0
    walls.quad({W, 0, D}, {0, 0, D}, {0, H, D}, {W, H, D});  // north
    walls.quad({0, 0, D}, {0, 0, 0}, {0, H, 0}, {0, H, D});  // west, x = 0
    walls.quad({W, 0, 0}, {W, 0, D}, {W, H, D}, {W, H, 0});  // east

    ObjFile& columns = part("columns", "column", "office floor: structural columns on a 7.2 m grid");
    for (double x : {7.2, 14.4, 21.6, 28.8})
        for (double z : {7.2, 14.4}) columns.box(x - 0.25, 0, z - 0.25, x + 0.25, H, z + 0.25);

    // Clusters of four desks (two side by side, two facing them) with a screen between the
    // facing pairs, one cluster in each structural bay, four rows.
    ObjFile& desks = part("desks", "desk", "office floor: 80 desks, 1.6 x 0.8 m, top at 0.745 m, panel ends");
    ObjFile& screens = part("partitions", "partition", "office floor: 1.2 m desk screens");
    for (double zc : {2.5, 5.7, 8.9, 12.1})
        for (double x0 : {2.0, 9.2, 16.4, 23.6, 30.8}) {
            for (int side = 0; side < 2; ++side)
                for (int k = 0; k < 2; ++k) {
                    const double xa = x0 + 1.6 * k, xb = xa + 1.6;
                    const double za = side ? zc + 0.015 : zc - 0.815, zb = za + 0.8;
                    desks.box(xa, 0.72, za, xb, 0.745, zb);                   // top
                    desks.box(xa, 0, za + 0.05, xa + 0.03, 0.72, zb - 0.05);  // end panels
                    desks.box(xb - 0.03, 0, za + 0.05, xb, 0.72, zb - 0.05);
                }
            screens.box(x0, 0, zc - 0.015, x0 + 3.2, 1.2, zc + 0.015);
        }

    ObjFile& tables = part("meeting_tables", "table", "office floor: three meeting tables, 3.6 x 1.2 m");
    for (double x0 : {3.0, 10.2, 17.4}) {
        tables.box(x0, 0.72, 17.4, x0 + 3.6, 0.75, 18.6);
        tables.box(x0 + 0.3, 0, 17.6, x0 + 0.35, 0.72, 18.4);
        tables.box(x0 + 3.25, 0, 17.6, x0 + 3.3, 0.72, 18.4);
    }
    ObjFile& cabinets = part("cabinets", "cabinet", "office floor: storage cabinets along the north wall, 1.2 m high");
    for (int i = 0; i < 10; ++i) cabinets.box(22.4 + 1.2 * i, 0, D - 0.45, 22.4 + 1.2 * i + 1.19, 1.2, D - 0.01);
    return parts;
}

// --- scenes -------------------------------------------------------------------------------------

std::string sceneHead(const std::vector<Part>& parts) {
    std::ostringstream s;
    s << "{\n  \"lucerna\": 1,\n  \"meters_per_unit\": 1,\n"
         "  \"camera\": {\"position\": [0.6, 2.2, 0.6], \"target\": [18.0, -2.4, 12.5], \"up\": [0, 1, 0],\n"
         "             \"fov_y\": 52, \"resolution\": [480, 288]},\n"
         "  \"materials\": {\n"
         "    \"floor\": {\"type\": \"diffuse\", \"albedo\": [0.21, 0.2, 0.18]},\n"
         "    \"ceiling\": {\"type\": \"diffuse\", \"albedo\": [0.8, 0.8, 0.8]},\n"
         "    \"wall\": {\"type\": \"diffuse\", \"albedo\": [0.62, 0.6, 0.55]},\n"
         "    \"column\": {\"type\": \"diffuse\", \"albedo\": [0.55, 0.55, 0.55]},\n"
         "    \"desk\": {\"type\": \"diffuse\", \"albedo\": [0.6, 0.52, 0.4]},\n"
         "    \"partition\": {\"type\": \"diffuse\", \"albedo\": [0.25, 0.33, 0.45]},\n"
         "    \"table\": {\"type\": \"diffuse\", \"albedo\": [0.3, 0.2, 0.13]},\n"
         "    \"cabinet\": {\"type\": \"diffuse\", \"albedo\": [0.7, 0.7, 0.68]}\n"
         "  },\n  \"objects\": [\n";
    for (size_t i = 0; i < parts.size(); ++i)
        s << "    {\"name\": \"" << parts[i].name << "\", \"material\": \"" << parts[i].material
          << "\", \"mesh\": {\"file\": \"" << parts[i].file << "\"}}" << (i + 1 < parts.size() ? ",\n" : "\n");
    s << "  ],\n  \"lights\": [\n";
    return s.str();
}

struct Mount {
    std::string name;
    double x, z;
    bool panel;
};

std::vector<Mount> mounts() {
    std::vector<Mount> m;
    for (int j = 0; j < kLuminairesZ; ++j)
        for (int i = 0; i < kLuminairesX; ++i) {
            const bool panel = j < kPanelRows;
            char name[32];
            std::snprintf(name, sizeof name, "%s_%d_%d", panel ? "panel" : "pendant", j + 1, i + 1);
            m.push_back({name, kRoomW * (i + 0.5) / kLuminairesX, kRoomD * (j + 0.5) / kLuminairesZ, panel});
        }
    return m;
}

// The report's cover and task areas (README, "Reports"): the desks' zone and the meeting zone at
// the desks' height, each with its EN 12464-1 activity; u along z and v along x, so that the
// grids face up.
std::string reportKeys() {
    return "  \"project\": {\"name\": \"Open-plan office floor (bundled example)\",\n"
           "              \"notes\": \"36.0 x 21.6 m, ceiling 3.0 m; reflectances ceiling 0.8, walls 0.6, floor 0.2. "
           "84 recessed panels over the desks, 24 direct/indirect pendants over the meeting zone, 4000 K. "
           "The photometric files are written by bench/make_office_floor.cpp: they are not measured products.\"},\n"
           "  \"task_areas\": [\n"
           "    {\"name\": \"Open-plan desks\", \"corner\": [1.5, 0.75, 1.2], \"u\": [0, 0, 12.2], \"v\": [33, 0, 0],\n"
           "     \"spacing\": 1, \"activity\": \"5.26.2\"},\n"
           "    {\"name\": \"Meeting zone\", \"corner\": [2.5, 0.75, 16.9], \"u\": [0, 0, 2.2], \"v\": [19, 0, 0],\n"
           "     \"spacing\": 0.5, \"activity\": \"5.26.5\"}\n"
           "  ]\n";
}

std::string luminaireScene(const std::vector<Part>& parts) {
    std::ostringstream s;
    s << sceneHead(parts);
    const std::vector<Mount> ms = mounts();
    for (size_t i = 0; i < ms.size(); ++i) {
        const Mount& m = ms[i];
        s << "    {\"name\": \"" << m.name << "\", \"type\": \"luminaire\", \"file\": \"luminaires/"
          << (m.panel ? "office_panel.ies" : "office_linear.ldt") << "\", \"position\": "
          << vec(m.x, m.panel ? kPanelHeight : kPendantHeight, m.z) << ", \"direction\": [0, -1, 0]"
          << (m.panel ? "" : ", \"rotation\": 90") << ", \"lumens\": " << num(m.panel ? kPanelLumens : kLinearLumens, 0)
          << ", \"temperature\": " << num(kTemperatureK, 0) << "}" << (i + 1 < ms.size() ? ",\n" : "\n");
    }
    s << "  ],\n" << reportKeys() << "}\n";
    return s.str();
}

std::string pointScene(const std::vector<Part>& parts) {
    std::ostringstream s;
    s << sceneHead(parts);
    const std::vector<Mount> ms = mounts();
    const Rgbd colour = blackbodyColour(kTemperatureK);
    for (size_t i = 0; i < ms.size(); ++i) {
        const Mount& m = ms[i];
        const double lumens = m.panel ? kPanelLumens : kLinearLumens;
        const Rgbd intensity = colour * (lumens / (683.0 * pointSolidAngle()));  // W/sr
        s << "    {\"name\": \"" << m.name << "\", \"type\": \"point\", \"position\": " << vec(m.x, kPointHeight, m.z)
          << ", \"intensity\": " << rgb(intensity, 6) << "}" << (i + 1 < ms.size() ? ",\n" : "\n");
    }
    s << "  ]\n}\n";
    return s.str();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bench_make_office_floor SCENES_DIR   (resources/scenes)\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    writeLuminaires(dir / "luminaires");
    const std::vector<Part> parts = buildGeometry();
    size_t triangles = 0;
    for (const Part& p : parts) {
        writeFile(dir / p.file, p.obj.text());
        triangles += p.obj.triangles();
    }
    writeFile(dir / "office_floor.json", luminaireScene(parts));
    writeFile(dir / "office_floor_points.json", pointScene(parts));
    std::printf("%zu triangles, %zu lights\n", triangles, mounts().size());
    return 0;
}
