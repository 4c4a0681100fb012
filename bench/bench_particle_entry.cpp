// How many daylight particles enter the room, with daylight particles through the windows
// (option daylight_portals=on) and without: the scene built as the tracing backends build it,
// sky and sun particles drawn by the call they start a particle with, each traced to its first
// hit (render/trace/lights/particle_entry.h says what counts as inside).
//
// usage: bench_particle_entry SCENE.json [--particles N] [--seed S]
//                                        [--inside xmin ymin zmin xmax ymax zmax]
//   --particles: daylight particles per setting (200000); --seed: the PCG seed (1);
//   --inside: the room's box in scene units (default: the box of the scene's drawn rooms).

#include "core/daylight/daylight.h"
#include "core/scene/scene_io.h"
#include "render/trace/lights/particle_entry.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

using namespace lucerna;

namespace {

double number(const char* text, const char* key) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(v))
        throw std::invalid_argument(std::string(key) + ": not a number: '" + text + "'");
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: bench_particle_entry SCENE.json [--particles N] [--seed S] [--inside xmin ymin zmin xmax ymax zmax]";
    if (argc < 2) {
        std::fprintf(stderr, "%s\n", usage);
        return 2;
    }
    try {
        int64_t particles = 200000;
        uint64_t seed = 1;
        std::optional<RoomBox> inside;
        for (int i = 2; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "--particles" && i + 1 < argc) {
                particles = int64_t(number(argv[++i], "--particles"));
                if (particles <= 0) throw std::invalid_argument("--particles must be positive");
            } else if (a == "--seed" && i + 1 < argc) {
                seed = uint64_t(number(argv[++i], "--seed"));
            } else if (a == "--inside" && i + 6 < argc) {
                float v[6];
                for (float& x : v) x = float(number(argv[++i], "--inside"));
                inside = RoomBox{V3f(v[0], v[1], v[2]), V3f(v[3], v[4], v[5])};
                if (!(inside->lo.x < inside->hi.x && inside->lo.y < inside->hi.y && inside->lo.z < inside->hi.z))
                    throw std::invalid_argument("--inside: each min must be below its max");
            } else {
                throw std::invalid_argument("unknown or incomplete argument '" + a + "'\n" + usage);
            }
        }
        const SceneSnapshot snapshot = sceneAsRendered(std::make_shared<const Scene>(loadScene(argv[1])));
        if (!inside) inside = drawnRoomsBox(*snapshot);
        if (!inside)
            throw std::invalid_argument(std::string(argv[1]) +
                                        ": no drawn room to count particles into: give the room's box with --inside");
        std::printf("%s: room box (%g %g %g) to (%g %g %g), seed %llu\n", argv[1], inside->lo.x, inside->lo.y,
                    inside->lo.z, inside->hi.x, inside->hi.y, inside->hi.z, (unsigned long long)seed);

        double totals[2] = {0, 0}, errors[2] = {0, 0};
        for (const bool portals : {false, true}) {
            const RenderScene scene(snapshot, 0, 0, nullptr, kDefaultLightSelection, portals);
            if (!scene.lights().environment() && !resolveDaylight(scene.scene()).sun)
                throw std::invalid_argument(std::string(argv[1]) + ": the scene has no daylight (sky or sun)");
            const auto t0 = std::chrono::steady_clock::now();
            const ParticleEntry e = countParticleEntry(scene, *inside, particles, seed);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (e.particles == 0) throw std::runtime_error("no daylight particle in " + std::to_string(e.draws) + " draws");
            // Emitted power per draw, in lumens (the sampler's unit is W/m^2 x scene units^2).
            const double toLumens = kLumensPerWatt * scene.metersPerUnit() * scene.metersPerUnit();
            const double mean = e.power / double(e.draws);
            const double variance = std::max(e.powerSquared / double(e.draws) - mean * mean, 0.0);
            totals[portals] = mean * toLumens;
            errors[portals] = std::sqrt(variance / double(e.draws)) * toLumens;
            std::printf("portals %-3s: %.3g%% of particles, %.3g%% of power enter (%lld particles, %.2f s)\n",
                        portals ? "on" : "off", 100.0 * double(e.inside) / double(e.particles),
                        e.power > 0 ? 100.0 * e.powerInside / e.power : 0.0, (long long)e.particles, seconds);
            if (portals) {
                std::printf("  portals: %s\n", scene.lights().particlePortals().describe(scene.metersPerUnit()).c_str());
                // 1 - kDiscShare of the particles are drawn through a portal that faces them; those
                // that enter beyond that came from the disc.
                const double facing = double(e.facing) / double(e.particles);
                std::printf("  a portal faces the direction of %.3g%% of particles (%.3g%% are drawn through one)\n",
                            100.0 * facing, 100.0 * (1 - kDiscShare));
            }
            if (e.draws != e.particles)
                std::printf("  (%lld draws in all: the other lights' particles are not counted)\n", (long long)e.draws);
        }
        const double ratio = totals[1] / totals[0];
        const double spread = ratio * std::hypot(errors[0] / totals[0], errors[1] / totals[1]);
        std::printf("daylight power emitted: %.4g lm (portals off), %.4g lm (on), on/off %.3f +- %.3f (1 sigma)\n",
                    totals[0], totals[1], ratio, spread);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_particle_entry: %s\n", e.what());
        return 1;
    }
}
