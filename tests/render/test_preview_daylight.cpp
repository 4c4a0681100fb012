// The interactive preview under daylight (SPEC.md section 5), headless on llvmpipe through EGL:
// - a uniform sky seen through a rectangular opening in the zero-thickness roof of a closed box
//   with black walls and roof: the floor's radiance is albedo E / pi with E that of a Lambertian
//   rectangle of the sky's radiance in the opening (Lambert's polygon formula), within 3% over the
//   floor and in each quarter of it; with a pane of glazing in the opening, times its
//   transmittance, channel by channel (the pane casts no shadow, its transmittance map scales);
// - looking up through the glazed opening, the sky shows at Lz / 683 times the transmittance,
//   the roof around it black;
// - pixels that see nothing show the sky's radiance toward them (a CIE general sky with its sun,
//   the ground below the horizon), as core/daylight/daylight.h computes it;
// - a sun over a plane: radiance albedo E cos Z / pi / 683 per channel, within 3%; edited to
//   below the horizon it gives nothing, and edited back at half the illuminance half the light;
// - the sky's directions (daylight_samples.h) are an unbiased estimate: their irradiance on an
//   open horizontal plane averages to the sky's horizontal illuminance.

#include "render_helpers.h"

#include "core/daylight/daylight.h"
#include "core/daylight/sky_model.h"
#include "render/preview/daylight_samples.h"
#include "render/preview/frame_accumulator.h"
#include "render/preview/preview.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <sstream>

using namespace lucerna;
using namespace lucerna::test;

namespace {

constexpr double kPiD = std::numbers::pi;

// The box: floor [0, 4] x [0, 4] at y = 0, roof at y = 2.5 with the opening [0.8, 3.2] x [1, 3].
constexpr double kW = 4, kH = 2.5, kX0 = 0.8, kX1 = 3.2, kZ0 = 1.0, kZ1 = 3.0;
constexpr double kLz = 10000;  // cd/m^2
constexpr double kAlbedo = 0.5;

std::string quad(const char* name, const char* material, V3d a, V3d b, V3d c, V3d d) {
    std::ostringstream o;
    o << R"({"name": ")" << name << R"(", "material": ")" << material << R"(", "mesh": {"quad": [)";
    for (const V3d* v : {&a, &b, &c, &d}) o << "[" << v->x << "," << v->y << "," << v->z << "]" << (v == &d ? "" : ",");
    o << "]}}";
    return o.str();
}

// The closed box under a uniform sky; `pane`: glazing of that transmittance in the opening;
// `camera`: the camera's JSON.
std::string boxScene(const std::string& camera, const char* pane = nullptr) {
    std::ostringstream o;
    o << R"({"lucerna": 1, "camera": )" << camera << R"(,
      "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
                    "black": {"type": "diffuse", "albedo": [0, 0, 0]})";
    if (pane) o << R"(, "pane": {"type": "glazing", "transmittance": )" << pane << "}";
    o << R"(},
      "sky": {"model": "uniform", "zenith_luminance": )" << kLz << R"(, "ground_reflectance": 0},
      "objects": [)";
    o << quad("floor", "floor", {0, 0, 0}, {0, 0, kW}, {kW, 0, kW}, {kW, 0, 0}) << ",\n";
    o << quad("wall-x0", "black", {0, 0, 0}, {0, kH, 0}, {0, kH, kW}, {0, 0, kW}) << ",\n";
    o << quad("wall-x1", "black", {kW, 0, 0}, {kW, 0, kW}, {kW, kH, kW}, {kW, kH, 0}) << ",\n";
    o << quad("wall-z0", "black", {0, 0, 0}, {kW, 0, 0}, {kW, kH, 0}, {0, kH, 0}) << ",\n";
    o << quad("wall-z1", "black", {0, 0, kW}, {0, kH, kW}, {kW, kH, kW}, {kW, 0, kW}) << ",\n";
    // The roof around the opening: four rectangles, zero thickness.
    o << quad("roof-a", "black", {0, kH, 0}, {kW, kH, 0}, {kW, kH, kZ0}, {0, kH, kZ0}) << ",\n";
    o << quad("roof-b", "black", {0, kH, kZ1}, {kW, kH, kZ1}, {kW, kH, kW}, {0, kH, kW}) << ",\n";
    o << quad("roof-c", "black", {0, kH, kZ0}, {kX0, kH, kZ0}, {kX0, kH, kZ1}, {0, kH, kZ1}) << ",\n";
    o << quad("roof-d", "black", {kX1, kH, kZ0}, {kW, kH, kZ0}, {kW, kH, kZ1}, {kX1, kH, kZ1});
    if (pane) o << ",\n" << quad("pane", "pane", {kX0, kH, kZ0}, {kX1, kH, kZ0}, {kX1, kH, kZ1}, {kX0, kH, kZ1});
    o << "]}";
    return o.str();
}

// Looking straight down at the floor from just under the roof.
const std::string kFloorCamera =
    R"({"position": [2, 2.4, 2], "target": [2, 0, 2], "up": [0, 0, -1], "fov_y": 60, "resolution": [48, 48]})";

// Lambert's polygon formula: the projected solid angle of a planar polygon seen from p on a
// surface of unit normal n, (1/2) sum over edges of the angle they subtend times n . (their
// plane's unit normal). The illuminance of a Lambertian polygon of luminance L is L times it.
double projectedSolidAngle(const V3d& p, const V3d& n, const std::vector<V3d>& polygon) {
    double sum = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const V3d a = (polygon[i] - p).normalized(), b = (polygon[(i + 1) % polygon.size()] - p).normalized();
        const V3d c = a.cross(b);
        const double len = c.length();
        sum += std::atan2(len, a.dot(b)) * n.dot(c) / len;
    }
    return std::abs(sum) / 2;
}

// The floor point the raster point (i + jx, j + jy) sees (SPEC.md's pinhole); the pixel's centre by
// default.
V3d floorPoint(const Camera& cam, int i, int j, double jx = 0.5, double jy = 0.5) {
    const V3d f = (cam.target - cam.position).normalized(), r = f.cross(cam.up).normalized(), u = r.cross(f);
    const double t = std::tan(cam.fovYDeg * kPiD / 360.0), aspect = double(cam.width) / cam.height;
    const V3d d = f + r * ((2.0 * (i + jx) / cam.width - 1.0) * aspect * t) + u * ((1.0 - 2.0 * (j + jy) / cam.height) * t);
    return cam.position + d * (-cam.position.y / d.y);
}

// The mean of `frames` preview frames, each with fresh VPLs, sky directions and sun sample and a
// jittered point in the pixel, as the preview backend's passes do.
// 32 frames of 64 sky directions: the directions' own noise in a quarter of the floor, measured
// over six seeds, stays under 1.7% (24 frames: 2.4%); the mean over the floor under 1.3%.
constexpr int kBoxFrames = 32;
Image averagedFrames(Preview& preview, int frames) {
    FrameAccumulator sum;
    for (int f = 0; f < frames; ++f) {
        const V2f jitter((f % 4 + 0.5f) / 4.0f, ((f / 4) % 4 + 0.5f) / 4.0f);
        sum.add(drawJitteredFrame(preview, uint64_t(2000 + f), jitter));
    }
    return sum.mean();
}

// Floor radiance of the box against albedo E / pi, E from Lambert's formula times `tau`: the
// relative error of the whole floor's mean and the worst of its four quarters' means, channel c.
struct BoxErrors {
    double whole = 0, worstQuarter = 0;
};
BoxErrors boxErrors(const Image& img, const Camera& cam, int c, double tau) {
    const std::vector<V3d> opening = {{kX0, kH, kZ0}, {kX1, kH, kZ0}, {kX1, kH, kZ1}, {kX0, kH, kZ1}};
    double sum[5] = {0, 0, 0, 0, 0}, expected[5] = {0, 0, 0, 0, 0};
    for (int j = 0; j < img.height; ++j)
        for (int i = 0; i < img.width; ++i) {
            const V3d p = floorPoint(cam, i, j);
            const double e = kLz / 683.0 * tau * projectedSolidAngle(p, V3d(0, 1, 0), opening);
            const int quarter = (i * 2 / img.width) + 2 * (j * 2 / img.height);
            for (const int k : {0, 1 + quarter}) {
                sum[k] += img.at(i, j)[c];
                expected[k] += kAlbedo * e / kPiD;
            }
        }
    BoxErrors out;
    out.whole = sum[0] / expected[0] - 1;
    for (int k = 1; k < 5; ++k) out.worstQuarter = std::max(out.worstQuarter, std::abs(sum[k] / expected[k] - 1));
    return out;
}

}  // namespace

class TestPreviewDaylight : public QObject {
    Q_OBJECT
private slots:
    void skyDirectionsAreUnbiased();
    void skyThroughRoofOpening();
    void skyThroughGlazedOpening();
    void skySeenThroughPane();
    void backgroundIsTheSky();
    void sunOverPlane();
};

void TestPreviewDaylight::skyDirectionsAreUnbiased() {
    // A CIE clear sky (type 12) with its sun 30 degrees up, and the ground below: the
    // directions' irradiance on an open horizontal plane, cos-weighted, averages to Lz times
    // relativeHorizontalIlluminance; on a plane facing down, to pi times the ground's luminance.
    ResolvedSky sky;
    sky.sky.model = SkyModelType::CieGeneral;
    sky.sky.cieType = 12;
    sky.towardSun = V3d(0, 0.5, std::sqrt(0.75));
    sky.zenithLuminance = 5000;
    sky.groundLuminance = 3000;
    const double expectedUp = sky.zenithLuminance * relativeHorizontalIlluminance(sky.sky, sky.towardSun);
    const double expectedDown = kPiD * sky.groundLuminance;
    double up = 0, down = 0;
    constexpr int kSets = 200;
    for (int s = 0; s < kSets; ++s)
        for (const DirectionalSample& d : skySamples(sky, 64, uint64_t(s))) {
            up += 683.0 * d.irradiance.x * std::max(0.0f, d.toward.y);
            down += 683.0 * d.irradiance.x * std::max(0.0f, -d.toward.y);
        }
    up /= kSets;
    down /= kSets;
    qInfo("sky directions: up %.1f lx (expected %.1f), down %.1f lx (expected %.1f)", up, expectedUp, down, expectedDown);
    QVERIFY2(std::abs(up / expectedUp - 1) < 0.01, qPrintable(QString::number(up / expectedUp)));
    QVERIFY2(std::abs(down / expectedDown - 1) < 0.01, qPrintable(QString::number(down / expectedDown)));
}

void TestPreviewDaylight::skyThroughRoofOpening() {
    const SceneSnapshot scene = sceneFromJson(boxScene(kFloorCamera));
    Preview preview;
    preview.setScene(scene);
    const Image img = averagedFrames(preview, kBoxFrames);
    const BoxErrors e = boxErrors(img, scene->camera, 1, 1.0);
    qInfo("uniform sky through the roof opening: floor mean %+.2f%%, worst quarter %.2f%%", 100 * e.whole,
          100 * e.worstQuarter);
    QVERIFY2(std::abs(e.whole) < 0.03, qPrintable(QString::number(e.whole)));
    QVERIFY2(e.worstQuarter < 0.03, qPrintable(QString::number(e.worstQuarter)));
}

void TestPreviewDaylight::skyThroughGlazedOpening() {
    const SceneSnapshot scene = sceneFromJson(boxScene(kFloorCamera, "[0.8, 0.6, 0.3]"));
    Preview preview;
    preview.setScene(scene);
    const Image img = averagedFrames(preview, kBoxFrames);
    const double tau[3] = {0.8, 0.6, 0.3};
    for (int c = 0; c < 3; ++c) {
        const BoxErrors e = boxErrors(img, scene->camera, c, tau[c]);
        qInfo("uniform sky through a pane of transmittance %.1f: floor mean %+.2f%%, worst quarter %.2f%%", tau[c],
              100 * e.whole, 100 * e.worstQuarter);
        QVERIFY2(std::abs(e.whole) < 0.03, qPrintable(QString::number(e.whole)));
        QVERIFY2(e.worstQuarter < 0.03, qPrintable(QString::number(e.worstQuarter)));
    }
}

void TestPreviewDaylight::skySeenThroughPane() {
    // From the floor's middle looking up: the opening (1.6 x 1 at 3 m) fills the middle of the
    // image; through the pane the uniform sky is Lz / 683 times the transmittance, the roof black.
    const std::string camera =
        R"({"position": [2, 0.1, 2], "target": [2, 3, 2], "up": [0, 0, -1], "fov_y": 60, "resolution": [32, 32]})";
    const SceneSnapshot scene = sceneFromJson(boxScene(camera, "[0.8, 0.6, 0.3]"));
    Preview preview;
    preview.setScene(scene);
    const Image img = preview.render();
    const double tau[3] = {0.8, 0.6, 0.3};
    for (int c = 0; c < 3; ++c) {
        const double centre = img.at(16, 16)[c], expected = kLz / 683.0 * tau[c];
        QVERIFY2(std::abs(centre / expected - 1) < 1e-3, qPrintable(QString("%1 vs %2").arg(centre).arg(expected)));
        QCOMPARE(img.at(1, 1)[c], 0.0f);  // the black roof, seen from below
    }
}

void TestPreviewDaylight::backgroundIsTheSky() {
    // A small floor far below; everything else is sky (a CIE clear sky, type 12, with its sun)
    // or ground: each pixel's radiance equals ResolvedSky::radiance toward the pixel's centre.
    const char* json = R"({"lucerna": 1, "camera": {"position": [0, 1, 0], "target": [1, 0.6, 0.3], "fov_y": 100,
      "resolution": [40, 30]},
      "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-0.1,0,-0.1],[-0.1,0,0.1],[0.1,0,0.1],[0.1,0,-0.1]]}}],
      "lights": [{"name": "sun", "type": "sun", "direction": [-0.6, -0.5, -0.4], "illuminance": 80000}],
      "sky": {"model": "cie_general", "cie_type": 12, "horizontal_illuminance": 20000, "ground_reflectance": 0.3}})";
    const SceneSnapshot scene = sceneFromJson(json);
    const Daylight daylight = resolveDaylight(*scene);
    QVERIFY(daylight.sky && daylight.sun);
    Preview preview;
    preview.setScene(scene);
    const Image img = preview.render();
    const Camera& cam = scene->camera;
    const V3d f = (cam.target - cam.position).normalized(), r = f.cross(cam.up).normalized(), u = r.cross(f);
    const double t = std::tan(cam.fovYDeg * kPiD / 360.0), aspect = double(cam.width) / cam.height;
    double worst = 0;
    int sky = 0, ground = 0;
    for (int j = 0; j < img.height; ++j)
        for (int i = 0; i < img.width; ++i) {
            const V3d d = (f + r * ((2.0 * (i + 0.5) / cam.width - 1.0) * aspect * t) +
                           u * ((1.0 - 2.0 * (j + 0.5) / cam.height) * t)).normalized();
            if (d.y < 0 && (cam.position + d * (-cam.position.y / d.y) - V3d(0, 0, 0)).length() < 0.2) continue;
            if (std::abs(d.y) < 1e-3) continue;  // the horizon's edge
            (d.y > 0 ? sky : ground) += 1;
            const double expected = daylight.sky->radiance(d);
            worst = std::max(worst, std::abs(img.at(i, j).y / expected - 1));
        }
    qInfo("background: %d sky and %d ground pixels, worst relative difference %.2g", sky, ground, worst);
    QVERIFY(sky > 100 && ground > 100);
    QVERIFY2(worst < 1e-3, qPrintable(QString::number(worst)));
}

void TestPreviewDaylight::sunOverPlane() {
    // A sun 60 degrees from the zenith over a plane of albedo 0.5: L = albedo E cos Z / pi / 683
    // per channel (white sun), whatever the disc's jitter.
    const auto scene = [](const char* direction) {
        return sceneFromJson(std::string(R"({"lucerna": 1, "camera": {"position": [0, 2, 0.01], "target": [0, 0, 0],
          "up": [0, 0, -1], "fov_y": 50, "resolution": [32, 32]},
          "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
          "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-3,0,-3],[-3,0,3],[3,0,3],[3,0,-3]]}}],
          "lights": [{"name": "sun", "type": "sun", "direction": )") + direction + R"(, "illuminance": 100000}]})");
    };
    const double cosZ = 0.5;
    Preview preview;
    preview.setScene(scene("[0.8660254037844386, -0.5, 0]"));
    const Image img = averagedFrames(preview, 4);
    const double expected = kAlbedo * 100000.0 * cosZ / kPiD / 683.0;
    double mean = 0;
    for (const Rgb& p : img.pixels) mean += (double(p.x) + p.y + p.z) / 3.0;
    mean /= double(img.pixels.size());
    qInfo("sun over a plane: %.4f W/sr/m^2, expected %.4f (%+.2f%%)", mean, expected, 100 * (mean / expected - 1));
    QVERIFY2(std::abs(mean / expected - 1) < 0.03, qPrintable(QString::number(mean / expected - 1)));
    // The sun edited to below the horizon (Preview::setLight resolves daylight again): no light.
    Light below = scene("[0.8660254037844386, 0.5, 0]")->lights[0];
    preview.setLight(0, below);
    const Image dark = preview.render();
    for (const Rgb& p : dark.pixels) QCOMPARE(p, Rgb(0, 0, 0));
    // And back, brighter: the plane follows.
    below.direction = V3d(0.8660254037844386, -0.5, 0);
    below.sun->illuminanceLux = 50000;
    preview.setLight(0, below);
    double again = 0;
    for (const Rgb& p : preview.render().pixels) again += (double(p.x) + p.y + p.z) / 3.0;
    again /= double(img.pixels.size());
    QVERIFY2(std::abs(again / (0.5 * expected) - 1) < 0.03, qPrintable(QString::number(again / (0.5 * expected) - 1)));
}

QTEST_GUILESS_MAIN(TestPreviewDaylight)
#include "test_preview_daylight.moc"
