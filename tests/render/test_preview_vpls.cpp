// The preview's VPL shading pass against the CPU sum over the same VPLs
// (render/vpl/vpl_contribution.h), headless on llvmpipe through EGL:
// - with a 1 x 1 pattern, no blur and no direct light, the preview (its VPL loop and its unrolled
//   body alike) equals the CPU sum at every pixel;
// - a VPL's light that crosses a pane is times the pane's transmittance;
// - a wall millimetres from a VPL stays in its shadow cube and casts its shadow.

#include "render_helpers.h"

#include "render/preview/preview.h"
#include "render/trace/render_scene.h"
#include "render/vpl/vpl_contribution.h"

#include <QtTest>

#include <functional>
#include <optional>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A glossy floor seen from above, nothing else: what a hand-made VPL set lights is exactly what
// the CPU sum gives.
const char* kGlossyFloor = R"({"lucerna": 1, "camera": {"position": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1],
  "fov_y": 70, "resolution": [40, 30]},
  "materials": {"floor": {"type": "glossy", "albedo": [0.3, 0.4, 0.5], "specular": [0.5, 0.4, 0.3], "roughness": 0.3},
                "wall": {"type": "diffuse", "albedo": [0.8, 0.6, 0.4]}},
  "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-20,0,-20],[-20,0,20],[20,0,20],[20,0,-20]]}}]})";

// The VPLs' light alone, as the CPU sum sees it: one sub-buffer, no blur, no direct light, the
// pixel's centre.
Image vplFrame(const SceneSnapshot& scene, const VplSet& vpls, PreviewSettings s) {
    s.patternX = s.patternY = 1;
    s.blur = false;
    s.direct = false;
    Preview preview;
    preview.setSettings(s);
    preview.setScene(scene);
    preview.setVpls(vpls);
    return preview.render(0.5f, 0.5f);
}

struct CpuComparison {
    double worst = 0;  // the largest relative difference of a channel
    int compared = 0;  // pixels compared
};

// The frame against the unshadowed CPU sum of the VPLs' light at the surface each pixel's centre
// ray hits, times filter(hit point): the pixels where filter gives nothing are left out.
CpuComparison compareWithCpuSum(const Image& img, const RenderScene& rs, const VplSet& vpls, float maxG,
                                const std::function<std::optional<Rgb>(const V3f&)>& filter) {
    CpuComparison out;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            float t = 0;
            const Ray ray = rs.camera().ray(float(x) + 0.5f, float(y) + 0.5f);
            const auto hit = rs.intersect(ray, &t);
            if (!hit) continue;
            const std::optional<Rgb> factor = filter(hit->p);
            if (!factor) continue;
            VplReceiver r;
            r.x = *hit;
            r.material = &rs.material(hit->material);
            r.wo = -ray.direction;
            Rgb cpu(0, 0, 0);
            for (const Vpl& v : vpls) cpu += vplContributionUnshadowed(rs, v, r, maxG) * *factor;
            for (int c = 0; c < 3; ++c)
                out.worst = std::max(out.worst, std::abs(img.at(x, y)[c] - cpu[c]) / std::max(1e-6, double(cpu[c])));
            ++out.compared;
        }
    return out;
}

}  // namespace

class TestPreviewVpls : public QObject {
    Q_OBJECT
private slots:
    void oneByOneEqualsCpuSum();
    void vplLightThroughPanes();
    void wallNextToVplCastsItsShadow();
};

void TestPreviewVpls::oneByOneEqualsCpuSum() {
    const SceneSnapshot scene = sceneFromJson(kGlossyFloor);
    const RenderScene rs(scene);
    // VPLs above the floor, facing down, glossy and diffuse, some near enough to be clamped.
    VplSet vpls;
    for (int i = 0; i < 24; ++i) {
        Vpl v;
        const float a = 0.7f * float(i);
        v.position = V3f(0.6f * std::cos(a), 0.05f + 0.04f * float(i % 7), 0.45f * std::sin(a));
        v.normal = V3f(0, -1, 0);
        v.incident = V3f(0.3f * std::sin(a), -1.0f, 0.2f).normalized();
        v.power = Rgb(0.02f + 0.001f * float(i), 0.03f, 0.025f);
        v.material = uint32_t(i % 2);  // floor (glossy), wall (diffuse)
        vpls.push_back(v);
    }
    // Both ways of the VPL shading pass (shade_vpl.frag): the loop over a storage buffer and the
    // unrolled body over a uniform block.
    for (const int unroll : {0, 64}) {
        PreviewSettings s;
        s.maxUnrolledVpls = unroll;
        s.clampDistance = 0.02f;
        s.visibility = false;  // the CPU sum is unshadowed
        const Image img = vplFrame(scene, vpls, s);
        QCOMPARE(img.width, 40);
        QCOMPARE(img.height, 30);
        const CpuComparison c = compareWithCpuSum(img, rs, vpls, geometricClampBound(rs, s.clampDistance),
                                                  [](const V3f&) { return Rgb(1, 1, 1); });
        qInfo("largest relative difference, GPU (%s) against CPU: %.3g over %d pixels", unroll ? "unrolled" : "loop",
              c.worst, c.compared);
        QCOMPARE(c.compared, 40 * 30);
        // float on both sides, positions rasterised vs. ray cast: agreement to 0.5%.
        QVERIFY2(c.worst < 5e-3, qPrintable(QString::number(c.worst)));
    }
}

// A VPL's light that crosses a pane on its way to a pixel is times the pane's transmittance: a
// low glass wall standing on the floor between VPLs just above the floor on one side and the
// floor on both (the camera high above sees the floor past the pane, not through it), against
// the CPU sum with the pane's transmittance on the segments that cross it.
void TestPreviewVpls::vplLightThroughPanes() {
    const SceneSnapshot scene = sceneFromJson(R"({"lucerna": 1, "camera": {"position": [0, 1.2, 0], "target": [0, 0, 0],
  "up": [0, 0, 1], "fov_y": 70, "resolution": [40, 30]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
                "glass": {"type": "glazing", "transmittance": [0.5, 0.6, 0.7]}},
  "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-20,0,-20],[-20,0,20],[20,0,20],[20,0,-20]]}},
              {"name": "pane", "material": "glass", "mesh": {"quad": [[0.1,0,-20],[0.1,0,20],[0.1,0.06,20],[0.1,0.06,-20]]}}]})");
    const RenderScene rs(scene);
    VplSet vpls;
    for (int i = 0; i < 12; ++i) {
        Vpl v;
        v.position = V3f(-0.1f - 0.05f * float(i % 4), 0.02f + 0.01f * float(i % 3), 0.3f * std::sin(0.9f * float(i)));
        v.normal = V3f(0, -1, 0);
        v.incident = V3f(0, -1, 0);
        v.power = Rgb(0.02f, 0.03f, 0.025f);
        v.material = 0;
        vpls.push_back(v);
    }
    PreviewSettings s;
    s.clampDistance = 0.02f;
    s.visibility = false;  // the CPU sum is unshadowed; the pane casts no shadow, it filters
    const Image img = vplFrame(scene, vpls, s);
    const Rgb transmittance(0.5f, 0.6f, 0.7f);
    int behind = 0;
    // Every VPL is at x < 0.1: the points past the pane (x > 0.1) see them through it.
    const CpuComparison c =
        compareWithCpuSum(img, rs, vpls, geometricClampBound(rs, s.clampDistance), [&](const V3f& p) -> std::optional<Rgb> {
            if (std::abs(p.x - 0.1f) < 0.02f) return std::nullopt;  // the pane's own line
            behind += p.x > 0.1f;
            return p.x > 0.1f ? transmittance : Rgb(1, 1, 1);
        });
    qInfo("largest relative difference against the CPU sum with the pane: %.3g (%d pixels behind the pane)", c.worst,
          behind);
    QVERIFY(behind > 100);
    QVERIFY2(c.worst < 5e-3, qPrintable(QString::number(c.worst)));
}

// A VPL 5 mm behind a wall (as on the ground against a building's facade) lights nothing past
// it: its shadow cube keeps the wall. With the cubes' near plane at 1/1000 of the scene's radius
// (3 cm here, beyond the cube's centre lifted 3 mm off the VPL's surface) the wall was clipped
// away and the light leaked through (a closed room with a sunlit ground outside read 13% of its
// unshadowed light, 5% now: the rest is the 32-texel faces).
void TestPreviewVpls::wallNextToVplCastsItsShadow() {
    const SceneSnapshot scene = sceneFromJson(R"({"lucerna": 1, "camera": {"position": [1, 1.5, 0], "target": [1, 0, 0],
  "up": [0, 0, 1], "fov_y": 60, "resolution": [40, 30]},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "objects": [{"name": "floor", "material": "grey", "mesh": {"quad": [[-20,0,-20],[-20,0,20],[20,0,20],[20,0,-20]]}},
              {"name": "wall", "material": "grey", "mesh": {"quad": [[0,0,-20],[0,0,20],[0,1,20],[0,1,-20]]}}]})");
    VplSet vpls(1);
    vpls[0].position = V3f(-0.005f, 0.3f, 0);
    vpls[0].normal = V3f(1, 0, 0);  // toward the wall
    vpls[0].incident = V3f(1, 0, 0);
    vpls[0].power = Rgb(1, 1, 1);
    vpls[0].material = 0;
    const auto frameMean = [&](bool visibility) {
        PreviewSettings s;
        s.visibility = visibility;
        return vplFrame(scene, vpls, s).mean();
    };
    const double unshadowed = frameMean(false), shadowed = frameMean(true);
    qInfo("floor past the wall: %.3g with the VPL's shadow cube, %.3g without", shadowed, unshadowed);
    QVERIFY(unshadowed > 0);
    QVERIFY2(shadowed < 0.01 * unshadowed, qPrintable(QString("%1 of %2").arg(shadowed).arg(unshadowed)));
}

QTEST_GUILESS_MAIN(TestPreviewVpls)
#include "test_preview_vpls.moc"
