#pragma once
// A scene's lighting energy by EN 15193-1 (README, "Energy (LENI; an addition)";
// core/photometry/lighting_energy.h): the electric lights switched on (point, spot, luminaire),
// each at its circuit power, the scene's "energy" settings and its floor area. The window's
// Energy page, the report and `lucerna info` all state what this computes.

#include "core/photometry/lighting_energy.h"
#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

// The circuit power of `light`, W: its circuit_watts, else (a luminaire) the input power its file
// states. Absent for a light that states none, and for daylight (sun, directional).
std::optional<double> circuitWatts(const Light& light);

// Lights alike for the energy (same kind, file and circuit power), one line of the report.
struct EnergyLightType {
    std::string kind;      // "Luminaire", "Spot light", "Point light"
    std::string product;   // the luminaire file's name for it; empty for others
    std::string file;      // the photometric file as the scene names it; empty for others
    std::vector<std::string> names;  // the lights' names
    double wattsEach = 0;  // Pn, W
    bool fromFile = false; // the file's stated power (else the light's circuit_watts)
};

struct SceneEnergy {
    std::optional<LightingEnergy> energy;  // when it can be computed
    std::string notComputed;               // else why not, one line ("3 lights state no power (give circuit_watts)")
    std::vector<EnergyLightType> types;    // the lights counted whose power is known
    int lights = 0;                        // electric lights switched on (point, spot, luminaire)
    std::vector<std::string> withoutPower; // the names of those that state no power
    int emitterObjects = 0;                // emitting objects: no power to count, left out
    double planAreaM2 = 0;                 // the geometry's extent in plan (planAreaM2)
};

SceneEnergy sceneEnergy(const Scene& scene);

// "LENI 19.50 kWh/(m²·a) (W_L 810.0 kWh/a, W_P 360.0 kWh/a, A 60.0 m²)" or "LENI not computed:
// ..." (`unicode` false: m2 and a full stop in place of ² and ·, for a terminal).
std::string describeLeni(const SceneEnergy& e, bool unicode = true);

}  // namespace lucerna
