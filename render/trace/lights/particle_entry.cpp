#include "render/trace/lights/particle_entry.h"

#include "render/trace/rng.h"

#include <algorithm>

namespace lucerna {

std::optional<RoomBox> drawnRoomsBox(const Scene& scene) {
    std::optional<RoomBox> box;
    for (const Room& room : scene.rooms) {
        if (!room.parametric()) continue;
        for (const V2d& c : room.outline) {
            const V3f lo(float(c.x), float(room.floorLevel), float(c.y));
            const V3f hi(float(c.x), float(room.floorLevel + room.height), float(c.y));
            if (!box) box = RoomBox{lo, hi};
            box->lo = V3f(std::min(box->lo.x, lo.x), std::min(box->lo.y, lo.y), std::min(box->lo.z, lo.z));
            box->hi = V3f(std::max(box->hi.x, hi.x), std::max(box->hi.y, hi.y), std::max(box->hi.z, hi.z));
        }
    }
    return box;
}

ParticleEntry countParticleEntry(const RenderScene& scene, const RoomBox& room, int64_t daylightParticles,
                                 uint64_t seed) {
    const LightSampler& lights = scene.lights();
    const std::optional<uint32_t> sun = scene.directionalSun();
    const float centimetre = 0.01f / scene.metersPerUnit();
    const RoomBox grown{room.lo - V3f(centimetre), room.hi + V3f(centimetre)};

    ParticleEntry count;
    const int64_t maxDraws = 100 * daylightParticles;
    while (count.particles < daylightParticles && count.draws < maxDraws) {
        Rng rng(seed, uint64_t(count.draws++));
        // As instant radiosity and bdpt take them: position, direction, then the light's choice.
        const V2f uPosition = rng.next2D(), uDirection = rng.next2D();
        const float uSelect = rng.next1D();
        EmissionSample es;
        const bool emitted = lights.sampleEmission(uPosition, uDirection, uSelect, es);
        // sampleEmission numbers the chosen light before it emits, so a refused particle is
        // still known to be the daylight's.
        const bool daylight = lights.isEnvironment(es.light) || es.light == sun;
        if (!daylight) continue;
        ++count.particles;
        if (!emitted || !isFinite(es.power)) continue;
        if (lights.particlePortals().letsIn(-es.direction)) ++count.facing;
        const double power = luminance(es.power);
        count.power += power;
        count.powerSquared += power * power;
        // The first ray as the backends start it (a daylight particle has no surface to leave).
        const Ray ray{es.position, es.direction};
        float t = 0;
        const std::optional<SurfacePoint> hit = scene.intersect(ray, &t);
        if (!hit) continue;
        const float length = es.direction.length();
        const V3f before = hit->p - es.direction * (std::min(centimetre, 0.5f * t * length) / length);
        if (grown.contains(hit->p) && room.contains(before)) {
            ++count.inside;
            count.powerInside += power;
        }
    }
    return count;
}

}  // namespace lucerna
