// What the light tree costs and what it buys (BENCHMARKS.md, "Many lights (issue 19)"):
//
//   bench_light_tree build                 ms to build the tree (and the whole RenderScene) for
//                                          100 to 100,000 lights
//   bench_light_tree scaling SECONDS [SEEDS]
//                                          relmse at equal time, power against tree, for 10 to
//                                          10,000 point lights over a plane, the field growing
//                                          with the count (the lamps 1 m apart, the camera's view
//                                          the same), against the closed form (sum of I cos / r^2;
//                                          tests/support/closed_form_scenes.h), mean over SEEDS seeds;
//                                          also rays per second of each
//
// Run from a Release build, on an otherwise idle machine for the times.

#include "closed_form_scenes.h"
#include "render_helpers.h"

#include "core/image/image_metrics.h"
#include "render/trace/lights/light_tree.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace lucerna;
using namespace lucerna::test;

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A field of columns x rows lamps (ManyPointLightsOverPlane) with about `count` lamps.
ManyPointLightsOverPlane field(int count) {
    ManyPointLightsOverPlane s;
    s.columns = std::max(1, int(std::lround(std::sqrt(count * 1.6))));
    s.rows = std::max(1, int(std::lround(double(count) / s.columns)));
    s.resolution = 48;
    return s;
}

Image expectedImage(const ManyPointLightsOverPlane& s) {
    const std::vector<double> e = s.expected();
    Image img(s.resolution, s.resolution);
    for (size_t i = 0; i < e.size(); ++i) img.pixels[i] = V3f(float(e[i]));
    return img;
}

int build() {
    std::printf("lights,tree_ms,render_scene_power_ms,render_scene_tree_ms\n");
    for (int count : {100, 1000, 10000, 100000}) {
        Rng rng(7);
        std::vector<LightBounds> bounds;
        for (int i = 0; i < count; ++i) {
            const V3f p(100 * rng.next1D(), 3, 100 * rng.next1D());
            bounds.push_back(i % 2 ? LightBounds::point(p, 1 + rng.next1D())
                                   : LightBounds::spot(p, V3f(0, -1, 0), radians(60.0f), 1 + rng.next1D()));
        }
        auto start = Clock::now();
        const LightTree tree(bounds);
        const double treeMs = millisecondsSince(start);
        const SceneSnapshot scene = sceneFromJson(field(count).json());
        double sceneMs[2];
        for (LightSelection selection : {LightSelection::Power, LightSelection::Tree}) {
            start = Clock::now();
            const RenderScene rs(scene, 16, 16, nullptr, selection);
            sceneMs[int(selection)] = millisecondsSince(start);
        }
        std::printf("%d,%.2f,%.2f,%.2f\n", count, treeMs, sceneMs[0], sceneMs[1]);
    }
    return 0;
}

int scaling(double seconds, int seeds) {
    std::printf("lights,sampler,seconds,relmse_mean_over_seeds,spp_mean,mrays_per_s\n");
    for (int count : {10, 100, 1000, 10000}) {
        const ManyPointLightsOverPlane s = field(count);
        const SceneSnapshot scene = sceneFromJson(s.json());
        const Image reference = expectedImage(s);
        for (const char* sampler : {"power", "tree"}) {
            double relmse = 0, spp = 0, raysPerSecond = 0;
            for (int seed = 1; seed <= seeds; ++seed) {
                RayRecorder recorder(64, /*countOnly=*/true);
                RenderSettings settings;
                settings.seconds = seconds;
                settings.seed = uint64_t(seed);
                settings.options["light_sampler"] = sampler;
                settings.rayRecorder = &recorder;
                const RenderFrame frame = renderFrame("path", scene, settings);
                relmse += compareImages(frame.image, reference).relmse / seeds;
                spp += frame.samplesPerPixel / seeds;
                raysPerSecond += double(recorder.total()) / frame.seconds / seeds;
            }
            std::printf("%d,%s,%.1f,%.4g,%.0f,%.2f\n", s.columns * s.rows, sampler, seconds, relmse, spp,
                        raysPerSecond / 1e6);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "build" && argc == 2) return build();
    if (mode == "scaling" && (argc == 3 || argc == 4))
        return scaling(std::atof(argv[2]), argc == 4 ? std::atoi(argv[3]) : 4);
    std::fprintf(stderr, "usage: bench_light_tree build | scaling SECONDS [SEEDS]\n");
    return 2;
}
