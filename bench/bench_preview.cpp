// The interactive preview's benchmarks (issue 5): milliseconds per frame and per pass for
// 640x480 and 1024x768, 256 and 1024 VPLs, no interleaving, 2x2, 4x4 and 8x6; the G-buffer split
// in one pass against two; and the accuracy against the Cornell box reference (relmse with VPL
// visibility off and on, the energy the clamp loses).
//
// A "frame" here is what a camera move costs: G-buffer, split, shading, gather, blur, direct and
// the read-back. Shadow maps are redrawn only when a light or the VPLs change; they are reported
// beside the frame.
//
// usage: bench_preview [SCENE.json] [--quick] [--accuracy-only] [--frames N]

#include "core/exr_io.h"
#include "core/image_metrics.h"
#include "core/scene_io.h"
#include "render/preview/preview.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

struct Row {
    PreviewTimings mean;
    double shadows = 0;  // the first frame's shadow maps (lights and VPLs changed)
};

Row measure(Preview& preview, int frames) {
    Row row;
    preview.render();  // first frame: shadow maps, buffers, shader warm-up
    row.shadows = preview.timings().shadows;
    PreviewTimings& m = row.mean;
    for (int f = 0; f < frames; ++f) {
        preview.render();
        const PreviewTimings& t = preview.timings();
        m.gbuffer += t.gbuffer;
        m.split += t.split;
        m.shading += t.shading;
        m.gather += t.gather;
        m.blur += t.blur;
        m.direct += t.direct;
        m.readback += t.readback;
        m.total += t.total;
    }
    for (double* v : {&m.gbuffer, &m.split, &m.shading, &m.gather, &m.blur, &m.direct, &m.readback, &m.total})
        *v /= frames;
    return row;
}

double meanOf(const Image& img) {
    double s = 0;
    for (const Rgb& p : img.pixels) s += double(p.x) + p.y + p.z;
    return s / (3.0 * double(img.pixels.size()));
}

Image average(Preview& preview, int frames) {
    Image sum;
    for (int f = 0; f < frames; ++f) {
        preview.regenerate(uint64_t(77 + f));
        const Image img = preview.render((f % 8 + 0.5f) / 8.0f, ((f / 8) % 8 + 0.5f) / 8.0f);
        if (f == 0) sum = Image(img.width, img.height);
        for (size_t i = 0; i < img.pixels.size(); ++i) sum.pixels[i] += img.pixels[i];
    }
    for (Rgb& p : sum.pixels) p /= float(frames);
    return sum;
}

}  // namespace

int main(int argc, char** argv) {
    std::string scenePath = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json";
    bool quick = false, accuracyOnly = false;
    int frames = 5;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--accuracy-only")) accuracyOnly = true;
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
        else scenePath = argv[i];
    }
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(scenePath));
    Preview preview;
    std::printf("renderer: %s (EGL %s)\nscene: %s\n\n", preview.context().renderer().c_str(),
                preview.context().platform().c_str(), scenePath.c_str());

    if (!accuracyOnly) {
        std::printf("## ms per frame (mean of %d frames after one warm-up), per pass\n\n", frames);
        std::printf("| resolution | VPLs | pattern | G-buffer | split | shading | gather | blur | direct | read-back | frame "
                    "| fps | shading speedup | frame speedup | shadow maps (on change) |\n");
        std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        const int sizes[2][2] = {{640, 480}, {1024, 768}};
        const int patterns[4][2] = {{1, 1}, {2, 2}, {4, 4}, {8, 6}};
        for (const auto& size : sizes) {
            if (quick && size[0] != 640) continue;
            for (int vpls : {256, 1024}) {
                if (quick && vpls != 256) continue;
                double baseShading = 0, baseFrame = 0;
                for (const auto& pattern : patterns) {
                    PreviewSettings s;
                    s.vplCount = vpls;
                    s.patternX = pattern[0];
                    s.patternY = pattern[1];
                    preview.setSettings(s);
                    preview.setScene(scene, size[0], size[1]);
                    const Row r = measure(preview, frames);
                    const PreviewTimings& t = r.mean;
                    if (pattern[0] * pattern[1] == 1) baseShading = t.shading, baseFrame = t.total;
                    std::printf("| %dx%d | %d | %dx%d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | %.1fx | "
                                "%.1fx | %.1f |\n",
                                size[0], size[1], vpls, pattern[0], pattern[1], t.gbuffer, t.split, t.shading, t.gather,
                                t.blur, t.direct, t.readback, t.total, 1000.0 / t.total, baseShading / t.shading,
                                baseFrame / t.total, r.shadows);
                    std::fflush(stdout);
                }
            }
        }

        std::printf("\n## G-buffer split (4 RGBA32F attachments): one pass against two\n\n");
        std::printf("| resolution | pattern | one pass ms | two passes ms |\n|---|---|---|---|\n");
        for (const auto& size : {std::pair{640, 480}, std::pair{1024, 768}, std::pair{1024, 1024}}) {
            for (const auto& pattern : {std::pair{4, 4}, std::pair{8, 6}}) {
                double ms[2] = {0, 0};
                for (int two = 0; two < 2; ++two) {
                    PreviewSettings s;
                    s.patternX = pattern.first;
                    s.patternY = pattern.second;
                    s.twoPassSplit = two == 1;
                    preview.setSettings(s);
                    preview.setScene(scene, size.first, size.second);
                    ms[two] = measure(preview, frames).mean.split;
                }
                std::printf("| %dx%d | %dx%d | %.2f | %.2f |\n", size.first, size.second, pattern.first, pattern.second,
                            ms[0], ms[1]);
                std::fflush(stdout);
            }
        }
    }

    // Accuracy against the converged reference, at the reference's own resolution.
    const std::string refPath = std::string(LUCERNA_RESOURCE_DIR) + "/../../shared/scenes/cornell-box.ref.exr";
    Image ref;
    try {
        ref = readExr(refPath);
    } catch (const std::exception& e) {
        std::printf("\n(no reference: %s)\n", e.what());
        return 0;
    }
    std::printf("\n## Accuracy against %s (%dx%d)\n\n", refPath.c_str(), ref.width, ref.height);
    std::printf("| visibility | VPLs | pattern | clamp | frames | relmse | mean | reference mean | mean lost to the clamp |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (bool visibility : {false, true})
        for (int framesAveraged : {1, 64}) {
            PreviewSettings s;
            s.visibility = visibility;
            preview.setSettings(s);
            preview.setScene(scene, ref.width, ref.height);
            const Image clamped = average(preview, framesAveraged);
            PreviewSettings noClamp = s;
            noClamp.clampDistance = 0;
            preview.setSettings(noClamp);
            const Image unclamped = average(preview, framesAveraged);
            const ImageMetrics m = compareImages(clamped, ref);
            std::printf("| %s | %d | %dx%d | %.2f R | %d | %.5f | %.5f | %.5f | %.2f%% |\n", visibility ? "on" : "off",
                        s.vplCount, s.patternX, s.patternY, s.clampDistance, framesAveraged, m.relmse, meanOf(clamped),
                        meanOf(ref), 100.0 * (1.0 - meanOf(clamped) / meanOf(unclamped)));
            if (framesAveraged == 64)
                writeExr(std::string("preview-cornell-visibility-") + (visibility ? "on" : "off") + ".exr", clamped);
            std::fflush(stdout);
        }
    return 0;
}
