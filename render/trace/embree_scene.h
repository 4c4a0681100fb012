#pragma once
// The one wrapper around Embree 3 (as Mitsuba 3 confines it): nothing else includes rtcore.h.
// One triangle geometry holds the whole scene; primitive ids index the caller's triangle arrays.

#include "core/math.h"

#include <cstdint>
#include <limits>
#include <atomic>
#include <memory>
#include <vector>

namespace lucerna {

struct Ray {
    V3f origin;
    V3f direction;  // need not be unit; t is measured in multiples of it
    float tNear = 0.0f;
    float tFar = std::numeric_limits<float>::infinity();
};

struct RayHit {
    float t = std::numeric_limits<float>::infinity();
    uint32_t triangle = kNone;
    float b1 = 0, b2 = 0;  // barycentrics of vertices 1 and 2
    static constexpr uint32_t kNone = 0xffffffffu;
    bool found() const { return triangle != kNone; }
};

// Every ray a tracer sends, for benchmarks: counted, and unless countOnly also recorded (to be
// replayed through bare Embree calls). One slot per arena thread, so that neither needs a lock.
struct RayRecorder {
    struct Entry {
        Ray ray;
        bool shadow;
    };
    struct alignas(64) Count {
        std::atomic<uint64_t> rays{0};  // relaxed: read only as a running total
    };
    explicit RayRecorder(int threads, bool countOnly = false)
        : perThread(countOnly ? 0 : size_t(threads)), counts(size_t(threads)), countOnly(countOnly) {}
    // Rays counted so far over all threads (closest-hit, shadow and packet rays alike).
    uint64_t total() const {
        uint64_t n = 0;
        for (const Count& c : counts) n += c.rays.load(std::memory_order_relaxed);
        return n;
    }
    void resetCounts() {
        for (Count& c : counts) c.rays.store(0, std::memory_order_relaxed);
    }

    std::vector<std::vector<Entry>> perThread;
    std::vector<Count> counts;
    bool countOnly;
};

// Glazing (SPEC.md section 5): triangles that rays cross instead of hitting, each crossing
// scaling what the ray carries by its pane's transmittance. A pane is one surface: a ray that
// crosses it where two of its triangles meet is scaled once.
struct PaneTable {
    std::vector<int32_t> paneOfTriangle;  // by triangle; -1: opaque
    std::vector<Rgb> transmittance;       // by pane
    bool empty() const { return transmittance.empty(); }
};

class EmbreeScene {
public:
    // Builds a BVH over the triangles (robust, high-quality build). Throws std::runtime_error if
    // Embree cannot be initialised.
    EmbreeScene(const std::vector<V3f>& positions, const std::vector<V3i>& triangles, PaneTable panes = {});
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Closest opaque hit in (tNear, tFar); incoherent single rays. Panes are crossed: with
    // `transmittance`, the product of the transmittances of the panes before the hit (or along
    // the whole ray when nothing is hit).
    RayHit intersect(const Ray& ray, Rgb* transmittance = nullptr) const;
    // True when any surface lies in (tNear, tFar), panes included (transmittance() crosses them).
    bool occluded(const Ray& ray) const;
    // What reaches the end of the segment (tNear, tFar) per unit sent: 0 when an opaque surface
    // is in the way, else the product of the transmittances of the panes it crosses.
    Rgb transmittance(const Ray& ray) const;
    bool hasPanes() const { return !panes_.empty(); }

    // Closest hits for many rays at once, traced as 8-wide packets with Embree's coherent flag
    // (a lone ray as a single ray): for camera rays and other bundles whose rays share an origin
    // region and direction.
    void intersectCoherent(const Ray* rays, RayHit* hits, size_t count) const;

    // Benchmarks only: while set, intersect() and occluded() append their rays to it.
    void setRecorder(RayRecorder* recorder) { recorder_ = recorder; }
    // Traces recorded rays with bare rtcIntersect1 / rtcOccluded1 calls, in parallel over the
    // calling task arena. Returns the number of hits (so that the work cannot be optimised away).
    size_t replay(const std::vector<RayRecorder::Entry>& rays) const;

private:
    void record(const Ray& ray, bool shadow) const;
    RayHit intersectUnrecorded(const Ray& ray, Rgb* transmittance = nullptr) const;

    RayRecorder* recorder_ = nullptr;
    PaneTable panes_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lucerna
