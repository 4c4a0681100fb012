// The interactive preview's benchmarks (issue 5): milliseconds per frame and per pass for
// 640x480 and 1024x768, 256 and 1024 VPLs, no interleaving, 2x2, 4x4 and 8x6; the G-buffer split
// in one pass against two; and the accuracy against the Cornell box reference (relmse with VPL
// visibility off and on, the energy the clamp loses).
//
// A "frame" here is what a camera move costs: G-buffer, split, shading, gather, blur, direct and
// the read-back. Shadow maps are redrawn only when a light or the VPLs change; they are reported
// beside the frame. With interleaving, the area lights' samples are shaded in the VPL shading
// pass (one sample per pixel at 16 samples and 4x4); without, in the direct pass.
//
// usage: bench_preview [SCENE.json] [--quick] [--accuracy-only] [--target] [--frames N]
//        bench_preview --scenes SCENE.json... [--frames N] [--shaded-lights N] [--proxy N] [--size W H]
//                      [--sky-samples N] [--sky-size TEXELS]
//        bench_preview --back-wall
// --scenes: issue 20's table (realSceneRow), one row a scene; --back-wall: backWallBlotches.
// --target: only the llvmpipe budget, the defaults at 640x480 (256 VPLs, 4x4), per pass,
//           with each split mode (fused, one pass, two passes) in turns.

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/scene/scene_io.h"
#include "render/preview/preview.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

struct Row {
    PreviewTimings best;  // per pass, the least over the frames
    double shadows = 0;   // the first frame's shadow maps (lights and VPLs changed)
};

// Per pass, the least time over the frames: the machine is shared (other builds run beside the
// benchmark), and the minimum is the figure that load spikes disturb least.
void keepLeast(PreviewTimings& best, const PreviewTimings& t, bool first) {
    double* b[] = {&best.gbuffer, &best.lightBlocks, &best.split, &best.shading, &best.gather, &best.direct, &best.readback, &best.total};
    const double v[] = {t.gbuffer, t.lightBlocks, t.split, t.shading, t.gather, t.direct, t.readback, t.total};
    for (size_t i = 0; i < std::size(b); ++i) *b[i] = first ? v[i] : std::min(*b[i], v[i]);
}

Row measure(Preview& preview, int frames) {
    Row row;
    preview.render();  // first frame: shadow maps, buffers, shader warm-up
    row.shadows = preview.timings().shadows;
    for (int f = 0; f < frames; ++f) {
        preview.render();
        keepLeast(row.best, preview.timings(), f == 0);
    }
    return row;
}

// The configurations of one table block measured in turns (frame f of every configuration, then
// frame f + 1 ...), each in its own Preview, so that a change of load hits all of them alike and
// their ratios stay honest.
std::vector<Row> measureInTurns(std::vector<std::unique_ptr<Preview>>& previews, int frames) {
    std::vector<Row> rows(previews.size());
    for (size_t i = 0; i < previews.size(); ++i) {
        previews[i]->render();
        rows[i].shadows = previews[i]->timings().shadows;
    }
    for (int f = 0; f < frames; ++f)
        for (size_t i = 0; i < previews.size(); ++i) {
            previews[i]->render();
            keepLeast(rows[i].best, previews[i]->timings(), f == 0);
        }
    return rows;
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

// Issue 20's table for one scene at 640x480: the least of `frames` camera-move frames (the camera
// nudged, nothing regenerated) and of `frames` idle accumulation frames (fresh VPLs, area samples
// and light deal, a jittered pixel position, as the application's idle refinement draws them),
// per pass; then, when SCENE.ref.exr exists beside it, a single frame's and 16 frames' relmse and
// mean against it at its resolution.
void realSceneRow(const std::string& path, const PreviewSettings& settings, int frames, int width, int height) {
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(path));
    Preview preview;
    preview.setSettings(settings);
    const auto t0 = std::chrono::steady_clock::now();
    preview.setScene(scene, width, height);
    preview.render();
    const double firstMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // The least time of `frames` calls of step(f), in ms.
    const auto leastMs = [&](const auto& step) {
        double least = 1e30;
        for (int f = 0; f < frames; ++f) {
            const auto start = std::chrono::steady_clock::now();
            step(f);
            least = std::min(least, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        return least;
    };
    const auto jitter = [](int f) { return std::pair((f % 4 + 0.5f) / 4.0f, ((f / 4) % 4 + 0.5f) / 4.0f); };
    Row move;
    Camera camera = scene->camera;
    leastMs([&](int f) {
        camera.position = camera.position + V3d(0.001, 0, 0) * ((f % 2) ? -1.0 : 1.0);
        preview.setCamera(camera);
        preview.render();
        keepLeast(move.best, preview.timings(), f == 0);
    });
    double idleShadows = 1e30;
    // Fresh VPLs (traced on the CPU) and the frame.
    const double idleMs = leastMs([&](int f) {
        preview.regenerate(uint64_t(500 + f));
        const auto [jx, jy] = jitter(f);
        preview.render(jx, jy);
        idleShadows = std::min(idleShadows, preview.timings().shadows);
    });
    // The same VPLs dealt anew (Preview::redeal), as most idle frames are on big scenes.
    const double dealMs = leastMs([&](int f) {
        preview.redeal(uint64_t(700 + f));
        const auto [jx, jy] = jitter(f);
        preview.render(jx, jy);
    });
    const auto name = path.substr(path.find_last_of('/') + 1);
    const PreviewTimings& m = move.best;
    std::printf("| %s | %.0f | %.1f (G %.1f, light blocks %.1f, shading %.1f, gather %.1f, direct %.1f, read %.1f) | %.1f "
                "(shadows %.1f) | %.1f |",
                name.c_str(), firstMs, m.total, m.gbuffer, m.lightBlocks, m.shading, m.gather, m.direct, m.readback, idleMs,
                idleShadows, dealMs);
    const std::string refPath = path.substr(0, path.size() - 5) + ".ref.exr";
    Image ref;
    try {
        ref = readExr(refPath);
    } catch (const std::exception&) {
        std::printf(" | | | |\n");  // no reference
        return;
    }
    preview.setScene(scene, ref.width, ref.height);
    const Image one = preview.render();
    const Image sixteen = average(preview, 16);
    std::printf(" %.4f | %.4f | %+.2f%% / %+.2f%% |", compareImages(one, ref).relmse, compareImages(sixteen, ref).relmse,
                100.0 * (meanOf(one) / meanOf(ref) - 1.0), 100.0 * (meanOf(sixteen) / meanOf(ref) - 1.0));
    std::printf(" %s |\n", preview.degradation().empty() ? "" : preview.degradation().c_str());
    std::fflush(stdout);
}

// The interleaving pattern on a flat wall (issue 20): on the Cornell box's back wall (the part
// right of the tall block, above the short one), the relmse of single frames against the mean of
// 64 frames, interleaved 4 x 4 (with the blur) and not interleaved (1 x 1, every VPL at every
// pixel), each the mean over 8 seeds; 640 x 640.
void backWallBlotches() {
    const SceneSnapshot scene =
        std::make_shared<const Scene>(loadScene(std::string(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json"));
    const auto wallRelmse = [](const Image& t, const Image& r) {
        double sum = 0;
        long n = 0;
        for (int y = int(0.24 * t.height); y < int(0.60 * t.height); ++y)
            for (int x = int(0.54 * t.width); x < int(0.76 * t.width); ++x)
                for (int c = 0; c < 3; ++c) {
                    const double d = t.at(x, y)[c] - r.at(x, y)[c], v = r.at(x, y)[c];
                    sum += d * d / (v * v + 0.01);
                    ++n;
                }
        return sum / double(n);
    };
    std::printf("| pattern | single frame relmse on the back wall (mean of 8) | ms a frame |\n|---|---|---|\n");
    for (int n : {4, 1}) {
        Preview preview;
        PreviewSettings s;
        s.patternX = s.patternY = n;
        preview.setSettings(s);
        preview.setScene(scene, 640, 640);
        const Image converged = average(preview, 64);
        double sum = 0, ms = 1e30;
        for (int seed = 0; seed < 8; ++seed) {
            preview.regenerate(uint64_t(9000 + seed));
            sum += wallRelmse(preview.render(), converged);
            ms = std::min(ms, preview.timings().total - preview.timings().shadows);
        }
        std::printf("| %dx%d | %.5f | %.1f |\n", n, n, sum / 8, ms);
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string scenePath = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json";
    bool quick = false, accuracyOnly = false, targetOnly = false;
    int frames = 5;
    std::vector<std::string> realScenes;
    PreviewSettings realSettings;
    int realWidth = 640, realHeight = 480;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--scenes")) {
            while (i + 1 < argc && argv[i + 1][0] != '-') realScenes.push_back(argv[++i]);
        } else if (!std::strcmp(argv[i], "--shaded-lights") && i + 1 < argc) realSettings.lightsShadedInFull = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--proxy") && i + 1 < argc) realSettings.shadowProxyTriangles = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--sky-samples") && i + 1 < argc) realSettings.skySamples = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--sky-size") && i + 1 < argc) realSettings.skyShadowSize = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--size") && i + 2 < argc) {
            realWidth = std::atoi(argv[++i]);
            realHeight = std::atoi(argv[++i]);
        }
        else if (!std::strcmp(argv[i], "--back-wall")) {
            backWallBlotches();
            return 0;
        } else if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--accuracy-only")) accuracyOnly = true;
        else if (!std::strcmp(argv[i], "--target")) targetOnly = true;
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
        else scenePath = argv[i];
    }
    if (!realScenes.empty()) {
        std::printf("## %dx%d, defaults (least of %d frames; ms)\n\n", realWidth, realHeight, frames);
        std::printf("| scene | first frame (setup) | camera-move frame | idle frame, fresh VPLs | idle frame, new deal | "
                    "relmse 1 frame | relmse 16 frames | mean error 1 / 16 | degradation |\n"
                    "|---|---|---|---|---|---|---|---|---|\n");
        for (const std::string& path : realScenes) realSceneRow(path, realSettings, frames, realWidth, realHeight);
        return 0;
    }
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(scenePath));
    Preview preview;
    std::printf("renderer: %s (EGL %s)\nscene: %s\n\n", preview.context().renderer().c_str(),
                preview.context().platform().c_str(), scenePath.c_str());

    if (targetOnly) {
        // The defaults, and the split modes against each other in turns.
        std::vector<std::unique_ptr<Preview>> previews;
        const SplitMode modes[] = {SplitMode::Fused, SplitMode::OnePass, SplitMode::TwoPass};
        const char* names[] = {"fused split (default)", "one-pass split", "two-pass split"};
        for (SplitMode mode : modes) {
            PreviewSettings s;
            s.split = mode;
            previews.push_back(std::make_unique<Preview>());
            previews.back()->setSettings(s);
            previews.back()->setScene(scene, 640, 480);
        }
        const std::vector<Row> rows = measureInTurns(previews, frames);
        std::printf("defaults at 640x480, 256 VPLs, 4x4 (least of %d frames, the modes in turns)\n", frames);
        for (size_t i = 0; i < rows.size(); ++i) {
            const PreviewTimings& t = rows[i].best;
            std::printf("%s: G-buffer %.2f, split %.2f, shading %.2f, gather + blur x %.2f, blur y + direct %.2f, "
                        "read-back %.2f: frame %.2f ms\n",
                        names[i], t.gbuffer, t.split, t.shading, t.gather, t.direct, t.readback, t.total);
        }
        return 0;
    }
    if (!accuracyOnly) {
        std::printf("## ms per frame and per pass (least of %d frames after one warm-up; patterns measured in turns)\n\n", frames);
        std::printf("| resolution | VPLs | pattern | G-buffer | split | shading | gather + blur x | blur y + direct | read-back | frame "
                    "| fps | shading speedup | frame speedup | shadow maps (on change) |\n");
        std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        const int sizes[2][2] = {{640, 480}, {1024, 768}};
        const int patterns[4][2] = {{1, 1}, {2, 2}, {4, 4}, {8, 6}};
        for (const auto& size : sizes) {
            if (quick && size[0] != 640) continue;
            for (int vpls : {256, 1024}) {
                if (quick && vpls != 256) continue;
                std::vector<std::unique_ptr<Preview>> previews;
                for (const auto& pattern : patterns) {
                    PreviewSettings s;
                    s.vplCount = vpls;
                    s.patternX = pattern[0];
                    s.patternY = pattern[1];
                    previews.push_back(std::make_unique<Preview>());
                    previews.back()->setSettings(s);
                    previews.back()->setScene(scene, size[0], size[1]);
                }
                const std::vector<Row> rows = measureInTurns(previews, frames);
                const double baseShading = rows[0].best.shading, baseFrame = rows[0].best.total;
                for (size_t k = 0; k < rows.size(); ++k) {
                    const PreviewTimings& t = rows[k].best;
                    std::printf("| %dx%d | %d | %dx%d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | %.1fx | "
                                "%.1fx | %.1f |\n",
                                size[0], size[1], vpls, patterns[k][0], patterns[k][1], t.gbuffer, t.split, t.shading,
                                t.gather, t.direct, t.readback, t.total, 1000.0 / t.total, baseShading / t.shading,
                                baseFrame / t.total, rows[k].shadows);
                }
                std::fflush(stdout);
            }
        }

        // The unrolled VPL loop applies only to small sub-buffers (maxUnrolledVpls), so the 1x1 rows
        // above always loop: interleaving's own speedup is the loop's against the loop. Here both,
        // the unrolled one allowed up to 64 VPLs a sub-buffer.
        std::printf("\n## VPL shading pass at 640x480: a loop over the VPLs against the unrolled body, ms\n\n");
        std::printf("| VPLs | pattern | 1x1 (loop) | loop | unrolled | speedup over 1x1, loop | speedup, unrolled |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        for (int vpls : {256, 1024}) {
            if (quick && vpls != 256) continue;
            std::vector<std::unique_ptr<Preview>> previews;
            const int configs[5][3] = {{1, 1, 0}, {4, 4, 0}, {4, 4, 64}, {8, 6, 0}, {8, 6, 64}};  // n, m, unroll limit
            for (const auto& c : configs) {
                PreviewSettings s;
                s.vplCount = vpls;
                s.patternX = c[0];
                s.patternY = c[1];
                s.maxUnrolledVpls = c[2];
                previews.push_back(std::make_unique<Preview>());
                previews.back()->setSettings(s);
                previews.back()->setScene(scene, 640, 480);
            }
            const std::vector<Row> rows = measureInTurns(previews, frames);
            const double base = rows[0].best.shading;
            for (int k : {1, 3}) {
                const double loop = rows[size_t(k)].best.shading, unrolled = rows[size_t(k) + 1].best.shading;
                std::printf("| %d | %dx%d | %.2f | %.2f | %.2f | %.1fx | %.1fx |\n", vpls, configs[k][0], configs[k][1], base,
                            loop, unrolled, base / loop, base / unrolled);
            }
            std::fflush(stdout);
        }

        std::printf("\n## G-buffer split (RGBA32F + RGBA32UI attachments): one pass against two\n\n");
        std::printf("| resolution | pattern | one pass ms | two passes ms |\n|---|---|---|---|\n");
        for (const auto& size : {std::pair{640, 480}, std::pair{1024, 768}, std::pair{1024, 1024}}) {
            for (const auto& pattern : {std::pair{4, 4}, std::pair{8, 6}}) {
                std::vector<std::unique_ptr<Preview>> previews;
                for (int two = 0; two < 2; ++two) {
                    PreviewSettings s;
                    s.patternX = pattern.first;
                    s.patternY = pattern.second;
                    s.split = two == 1 ? SplitMode::TwoPass : SplitMode::OnePass;
                    previews.push_back(std::make_unique<Preview>());
                    previews.back()->setSettings(s);
                    previews.back()->setScene(scene, size.first, size.second);
                }
                const std::vector<Row> rows = measureInTurns(previews, frames);
                const double ms[2] = {rows[0].best.split, rows[1].best.split};
                std::printf("| %dx%d | %dx%d | %.2f | %.2f |\n", size.first, size.second, pattern.first, pattern.second,
                            ms[0], ms[1]);
                std::fflush(stdout);
            }
        }
    }

    if (!accuracyOnly) {
        std::printf("\n## VPL visibility (cube shadow maps, %d^2 texels a face): frame and shadow-map time\n\n",
                    PreviewSettings().vplShadowSize);
        std::printf("| resolution | VPLs | pattern | visibility | shading ms | frame ms | VPL + light shadow maps ms (on change) |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        for (int vpls : {256, 1024})
            for (bool visibility : {false, true}) {
                if (quick && vpls != 256) continue;
                PreviewSettings s;
                s.vplCount = vpls;
                s.visibility = visibility;
                preview.setSettings(s);
                preview.setScene(scene, 640, 480);
                const Row r = measure(preview, frames);
                std::printf("| 640x480 | %d | 4x4 | %s | %.2f | %.2f | %.1f |\n", vpls, visibility ? "on" : "off",
                            r.best.shading, r.best.total, r.shadows);
                std::fflush(stdout);
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
