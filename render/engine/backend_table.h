#pragma once
// The explicit table that names the backends (Tungsten-style), the refusal of unknown options,
// and `--backend auto`'s choice. Above the backends' own folders (render/progressive/,
// render/preview/), which it lists; nothing below includes it.

#include "render/backend/backend.h"

#include <span>
#include <string>
#include <string_view>

namespace lucerna {

// How a render under mpirun shares a backend's work among the processes
// (render/backend/pooled_films.h): disjoint passes of the one estimate (same seed, pass indices
// dealt out), or each process its own chains (own seed, own normalisation), pooled by work.
enum class ProcessShare { DisjointPasses, OwnChains };

struct BackendInfo {
    std::string_view name;
    std::string_view summary;
    BackendFactory make;
    std::span<const std::string_view> options;  // every option key its settings read
    ProcessShare share = ProcessShare::DisjointPasses;
};

// Every backend that exists, in the order the UI lists them.
std::span<const BackendInfo> backendTable();
// nullptr when no backend has that name. "auto" is found too (measured_auto_backend.h), though
// the table does not list it: it combines the backends the table names.
const BackendInfo* findBackend(std::string_view name);
// Throws std::invalid_argument, one line naming the key and the options there are, when
// `options` holds a key that none of `backends` reads (a mistyped option would otherwise be
// ignored and the render made with the default).
void requireKnownOptions(const std::map<std::string, std::string>& options, std::span<const BackendInfo* const> backends);

// What the rule that auto was before it measured picks for a scene, and why, in one line: a
// probe of what the camera sees. Still the choice of the per-pixel illuminance layer's method,
// and `lucerna bench`'s entry auto-rule, so that the measured auto is compared with it.
struct AutoChoice {
    std::string backend;
    std::string reason;
};
AutoChoice chooseAutoBackend(const Scene& scene);

}  // namespace lucerna
