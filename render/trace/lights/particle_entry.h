#pragma once
// How many daylight particles enter a room: sky and sun particles drawn as the particle backends
// draw them (LightSampler::sampleEmission, the one call light tracing, bdpt, ir, mir and cmlt
// start a particle with), each traced to its first hit, counted when that hit lies inside the
// room. With daylight particles through the windows (daylight_portals.h) most should; from the
// disc around the scene, few. Measured by bench/bench_particle_entry.

#include "core/scene/scene.h"
#include "render/trace/render_scene.h"

#include <cstdint>
#include <optional>

namespace lucerna {

// An axis-aligned box, scene units.
struct RoomBox {
    V3f lo{0, 0, 0}, hi{0, 0, 0};
    bool contains(const V3f& p) const {
        return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
    }
};

// The box around the scene's drawn rooms (their outlines from floor to ceiling), all of them
// together; nothing when the scene has no drawn room.
std::optional<RoomBox> drawnRoomsBox(const Scene& scene);

struct ParticleEntry {
    int64_t draws = 0;      // particles drawn from every light (daylight's share chosen by power)
    int64_t particles = 0;  // of them, the daylight's (the sky's and the sun's)
    int64_t inside = 0;     // daylight particles whose first hit is inside the room
    // Sky and sun particles whose direction some portal of the sampler faces (its outside toward
    // the sky they come from; none without portals): only these can be sent through a portal,
    // the others all leave from the disc (daylight_portals.h).
    int64_t facing = 0;
    // Sums of the daylight particles' luminance(power) (what each carries as it leaves), all and
    // those inside; power / draws estimates the daylight's emitted power in the sampler's units
    // (W per square metre times square scene units), powerSquared its error.
    double power = 0, powerInside = 0, powerSquared = 0;
};

// Draws particles from scene.lights() with PCG streams (seed, 0), (seed, 1), ... (the numbers in
// the order the backends take them) until `daylightParticles` have come from the daylight (or
// 100 times as many draws have been made), and traces each daylight particle's first ray through
// the scene (panes crossed, never hit). A first hit is inside `room` when it lies in the box and
// the point a centimetre before it along the ray does too, so that a particle striking a wall,
// roof or floor from outside never counts, even where the box's faces are those surfaces (walls
// of zero thickness). Particles that leave without hitting anything, or that emission refuses,
// count as not entering.
ParticleEntry countParticleEntry(const RenderScene& scene, const RoomBox& room, int64_t daylightParticles,
                                 uint64_t seed);

}  // namespace lucerna
