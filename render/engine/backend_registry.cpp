#include "render/engine/backend_table.h"

#include "render/engine/measured_auto/measured_auto_backend.h"
#include "render/preview/headless_backend.h"
#include "render/progressive/bdpt/bdpt_backend.h"
#include "render/progressive/cmlt/cmlt_backend.h"
#include "render/progressive/ir/ir_backend.h"
#include "render/progressive/mir/mir_backend.h"
#include "render/progressive/mlt/mlt_backend.h"
#include "render/progressive/path/path_backend.h"

#include <algorithm>
#include <set>
#include <vector>
#include <stdexcept>

namespace lucerna {

namespace {
// The option keys each backend's settings read (fromOptions): a test checks that every key listed
// here is read, and the command line refuses a key not listed, so a new option goes in both
// places. mlt reads bdpt's, cmlt mlt's, mir ir's gathering options;
// every tracing backend reads light_sampler and daylight_portals (TracingBackend; path sends no
// particles, so its list leaves daylight_portals out).
constexpr std::string_view kPathOptions[] = {"max_depth", "rr_depth", "light_sampler"};
constexpr std::string_view kBdptOptions[] = {"max_depth", "rr_depth", "strategies", "light_sampler", "daylight_portals"};
constexpr std::string_view kIrOptions[] = {"vpl_paths", "interleave", "max_bounces", "clamp", "compensate", "residual_vpls",
                                          "direct_samples", "light_sampler", "daylight_portals"};
constexpr std::string_view kMirOptions[] = {"vpl_paths", "tries",      "large_step", "pc_samples", "importance_points", "defensive",
                                            "max_bounces", "clamp",   "compensate", "residual_vpls", "direct_samples",
                                            "light_sampler", "daylight_portals"};
constexpr std::string_view kMltOptions[] = {"bootstrap", "bootstrap_first_per_pixel", "chains", "mutations",
                                            "large_step", "sigma", "caustic", "max_depth", "rr_depth", "strategies",
                                            "light_sampler", "daylight_portals"};
constexpr std::string_view kCmltOptions[] = {"path_lens_steps", "tries", "sigma_pixels", "caustic_sigma", "lens_steps",
                                             "caustic_steps", "bootstrap", "bootstrap_first_per_pixel", "chains",
                                             "mutations", "large_step", "sigma", "caustic", "max_depth", "rr_depth",
                                             "strategies", "light_sampler", "daylight_portals"};
constexpr std::string_view kPreviewOptions[] = {"vpls",       "clamp", "area_samples", "unroll",        "pattern",
                                                "visibility", "blur",  "split",        "vpl_source",    "shaded_lights",
                                                "proxy_triangles", "sky_samples", "sky_shadow_size"};

// The explicit factory table: one row per backend.
const BackendInfo kBackends[] = {
    {"path", "unidirectional path tracing with next-event estimation and MIS", &makePathBackend, kPathOptions},
    {"bdpt", "bidirectional path tracing: every connection strategy, light-tracing splats, power-heuristic MIS", &makeBdptBackend, kBdptOptions},
    {"ir", "instant radiosity: fresh VPLs per pass, clamped gathering with path-traced bias compensation", &makeIrBackend, kIrOptions},
    {"mir", "Metropolis instant radiosity: VPLs from a multiple-try Metropolis chain over camera-to-light paths", &makeMirBackend, kMirOptions, ProcessShare::OwnChains},
    {"mlt", "Metropolis light transport: primary-sample-space chains driving the bidirectional sampler", &makeMltBackend, kMltOptions, ProcessShare::OwnChains},
    {"cmlt", "coherent Metropolis light transport: MLT seeds, lens sub-chains of candidates traced as packets, expected-value deposits", &makeCmltBackend, kCmltOptions, ProcessShare::OwnChains},
    {"preview", "interactive VPL preview (OpenGL through EGL): deferred shading, interleaved sampling, shadow-mapped direct light", &makePreviewBackend, kPreviewOptions},
};
// Every tracing backend's option keys: auto passes its options to all its candidates.
std::span<const std::string_view> allTracingOptions() {
    static const std::vector<std::string_view> keys = [] {
        std::set<std::string_view> all;
        for (const BackendInfo& b : kBackends)
            if (b.name != "preview") all.insert(b.options.begin(), b.options.end());
        return std::vector<std::string_view>(all.begin(), all.end());
    }();
    return keys;
}
}  // namespace

std::span<const BackendInfo> backendTable() { return kBackends; }

const BackendInfo* findBackend(std::string_view name) {
    // Not in the table, which lists the methods: auto is a measured combination of them. Each
    // process of a distributed render measures and combines its own replicas, from its own seed.
    static const BackendInfo kAuto{"auto",
                                   "measures every method consistent for the scene in short pilots, gives the time "
                                   "where it buys the most error reduction, combines their films by inverse-error weights",
                                   &makeMeasuredAutoBackend, allTracingOptions(), ProcessShare::OwnChains};
    if (name == kAuto.name) return &kAuto;
    for (const BackendInfo& b : kBackends)
        if (b.name == name) return &b;
    return nullptr;
}

void requireKnownOptions(const std::map<std::string, std::string>& options, std::span<const BackendInfo* const> backends) {
    for (const auto& [key, value] : options) {
        bool known = false;
        for (const BackendInfo* b : backends) known = known || std::ranges::find(b->options, key) != b->options.end();
        if (known) continue;
        std::string names, keys;
        std::set<std::string_view> all;
        for (const BackendInfo* b : backends) {
            names += (names.empty() ? "" : ", ") + std::string(b->name);
            all.insert(b->options.begin(), b->options.end());
        }
        for (std::string_view k : all) keys += (keys.empty() ? "" : ", ") + std::string(k);
        throw std::invalid_argument("no option '" + key + "' for " + names + " (options: " + keys + ")");
    }
}

}  // namespace lucerna
