#include "render/trace/embree_scene.h"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include <stdexcept>
#include <string>

namespace lucerna {

namespace {
struct DeviceDeleter { void operator()(RTCDevice d) const { rtcReleaseDevice(d); } };
struct SceneDeleter { void operator()(RTCScene s) const { rtcReleaseScene(s); } };
using DeviceHandle = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using SceneHandle = std::unique_ptr<RTCSceneTy, SceneDeleter>;

void fillRay(RTCRay& r, const Ray& ray) {
    r.org_x = ray.origin.x; r.org_y = ray.origin.y; r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x; r.dir_y = ray.direction.y; r.dir_z = ray.direction.z;
    r.tnear = ray.tNear;
    r.tfar = ray.tFar;
    r.time = 0.0f;
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
}

// The panes a ray crosses, collected by a context filter: Embree calls it for every candidate
// hit, in no particular order and possibly twice for one triangle (spatial splits), so the
// crossings are kept and sorted out after the traversal. Plain contexts have no filter.
constexpr int kMaxCrossings = 64;  // past that (never in a building) further panes count as clear
struct PaneContext {
    RTCIntersectContext base;  // first: Embree hands the filter &base
    const PaneTable* panes = nullptr;
    int count = 0;
    struct Crossing {
        float t;
        int32_t pane;
    } crossings[kMaxCrossings];
};

void crossPanes(const RTCFilterFunctionNArguments* args) {
    auto* context = reinterpret_cast<PaneContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
        const int32_t pane = context->panes->paneOfTriangle[triangle];
        if (pane < 0) continue;  // opaque: the hit stands
        if (context->count < kMaxCrossings) context->crossings[context->count++] = {RTCRayN_tfar(args->ray, args->N, i), pane};
        args->valid[i] = 0;  // crossed, not hit
    }
}

void initPaneContext(PaneContext& c, const PaneTable& panes) {
    rtcInitIntersectContext(&c.base);
    c.base.filter = crossPanes;
    c.panes = &panes;
}

// The product over the crossings before tEnd, each pane once per place it is crossed: two
// crossings of one pane within a relative 1e-5 of t are its triangles meeting at an edge, or one
// triangle reported twice.
Rgb crossedTransmittance(const PaneContext& c, const PaneTable& panes, float tEnd) {
    Rgb product(1, 1, 1);
    for (int i = 0; i < c.count; ++i) {
        const auto& a = c.crossings[i];
        if (!(a.t < tEnd)) continue;
        bool counted = false;
        for (int j = 0; j < i && !counted; ++j) {
            const auto& b = c.crossings[j];
            counted = b.pane == a.pane && b.t < tEnd && std::abs(b.t - a.t) <= 1e-5f * std::max(a.t, b.t);
        }
        if (!counted) product *= panes.transmittance[size_t(a.pane)];
    }
    return product;
}
}  // namespace

struct EmbreeScene::Impl {
    DeviceHandle device;
    SceneHandle scene;
};

EmbreeScene::EmbreeScene(const std::vector<V3f>& positions, const std::vector<V3i>& triangles, PaneTable panes)
    : impl_(std::make_unique<Impl>()) {
    if (!panes.empty() && panes.paneOfTriangle.size() == triangles.size()) panes_ = std::move(panes);
    impl_->device.reset(rtcNewDevice(nullptr));
    if (!impl_->device)
        throw std::runtime_error("Embree: cannot create a device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    impl_->scene.reset(rtcNewScene(impl_->device.get()));
    rtcSetSceneFlags(impl_->scene.get(), hasPanes() ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION
                                                    : RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->scene.get(), RTC_BUILD_QUALITY_HIGH);
    if (!triangles.empty()) {
        RTCGeometry geom = rtcNewGeometry(impl_->device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree may read 16 bytes from the last vertex: pad the buffer by one float.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), positions.size() + 1));
        for (size_t i = 0; i < positions.size(); ++i) {
            v[3 * i] = positions[i].x; v[3 * i + 1] = positions[i].y; v[3 * i + 2] = positions[i].z;
        }
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), triangles.size()));
        for (size_t i = 0; i < triangles.size(); ++i) {
            idx[3 * i] = unsigned(triangles[i].x); idx[3 * i + 1] = unsigned(triangles[i].y);
            idx[3 * i + 2] = unsigned(triangles[i].z);
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(impl_->scene.get(), geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(impl_->scene.get());
    if (const RTCError err = rtcGetDeviceError(impl_->device.get()); err != RTC_ERROR_NONE)
        throw std::runtime_error("Embree: scene build failed (error " + std::to_string(int(err)) + ")");
}

EmbreeScene::~EmbreeScene() = default;

void EmbreeScene::record(const Ray& ray, bool shadow) const {
    const int slot = tbb::this_task_arena::current_thread_index();
    if (slot < 0 || size_t(slot) >= recorder_->counts.size()) return;
    recorder_->counts[size_t(slot)].rays.fetch_add(1, std::memory_order_relaxed);
    if (!recorder_->countOnly) recorder_->perThread[size_t(slot)].push_back({ray, shadow});
}

size_t EmbreeScene::replay(const std::vector<RayRecorder::Entry>& rays) const {
    std::atomic<size_t> hits{0};
    RTCScene scene = impl_->scene.get();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        size_t local = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            if (rays[i].shadow) {
                RTCRay ray;
                fillRay(ray, rays[i].ray);
                rtcOccluded1(scene, &context, &ray);
                local += ray.tfar < 0.0f;
            } else {
                RTCRayHit rh;
                fillRay(rh.ray, rays[i].ray);
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene, &context, &rh);
                local += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        }
        hits += local;
    });
    return hits;
}

RayHit EmbreeScene::intersect(const Ray& ray, Rgb* transmittance) const {
    if (recorder_) [[unlikely]] record(ray, false);
    return intersectUnrecorded(ray, transmittance);
}

RayHit EmbreeScene::intersectUnrecorded(const Ray& ray, Rgb* transmittance) const {
    PaneContext context;
    if (hasPanes()) initPaneContext(context, panes_);
    else rtcInitIntersectContext(&context.base);
    RTCRayHit rh;
    fillRay(rh.ray, ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene.get(), &context.base, &rh);
    RayHit hit;
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        hit.t = rh.ray.tfar;
        hit.triangle = rh.hit.primID;
        hit.b1 = rh.hit.u;
        hit.b2 = rh.hit.v;
    }
    if (transmittance) *transmittance = context.count > 0 ? crossedTransmittance(context, panes_, hit.t) : Rgb(1, 1, 1);
    return hit;
}

Rgb EmbreeScene::transmittance(const Ray& ray) const {
    if (!hasPanes()) return occluded(ray) ? Rgb(0, 0, 0) : Rgb(1, 1, 1);
    if (recorder_) [[unlikely]] record(ray, true);
    PaneContext context;
    initPaneContext(context, panes_);
    RTCRay r;
    fillRay(r, ray);
    rtcOccluded1(impl_->scene.get(), &context.base, &r);
    if (r.tfar < 0.0f) return Rgb(0, 0, 0);
    return crossedTransmittance(context, panes_, std::numeric_limits<float>::infinity());
}

bool EmbreeScene::occluded(const Ray& ray) const {
    if (recorder_) [[unlikely]] record(ray, true);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    fillRay(r, ray);
    rtcOccluded1(impl_->scene.get(), &context, &r);
    return r.tfar < 0.0f;  // Embree marks a hit by setting tfar to -inf
}

void EmbreeScene::intersectCoherent(const Ray* rays, RayHit* hits, size_t count) const {
    if (hasPanes()) {  // the pane filter keeps one ray's crossings: no packets
        for (size_t i = 0; i < count; ++i) hits[i] = intersect(rays[i]);
        return;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    if (recorder_) [[unlikely]]
        for (size_t i = 0; i < count; ++i) record(rays[i], false);
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[8];
    for (size_t base = 0; base < count; base += 8) {
        const size_t n = std::min<size_t>(8, count - base);
        if (n == 1) {  // a packet of one ray would only run the wide traversal on one lane
            hits[base] = intersectUnrecorded(rays[base]);
            continue;
        }
        for (size_t i = 0; i < 8; ++i) {
            valid[i] = i < n ? -1 : 0;
            const Ray& ray = rays[base + (i < n ? i : 0)];
            packet.ray.org_x[i] = ray.origin.x; packet.ray.org_y[i] = ray.origin.y; packet.ray.org_z[i] = ray.origin.z;
            packet.ray.dir_x[i] = ray.direction.x; packet.ray.dir_y[i] = ray.direction.y;
            packet.ray.dir_z[i] = ray.direction.z;
            packet.ray.tnear[i] = ray.tNear;
            packet.ray.tfar[i] = ray.tFar;
            packet.ray.time[i] = 0.0f;
            packet.ray.mask[i] = 0xffffffffu;
            packet.ray.id[i] = unsigned(i);
            packet.ray.flags[i] = 0;
            packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid, impl_->scene.get(), &context, &packet);
        for (size_t i = 0; i < n; ++i) {
            RayHit& hit = hits[base + i];
            hit = RayHit();
            if (packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID) {
                hit.t = packet.ray.tfar[i];
                hit.triangle = packet.hit.primID[i];
                hit.b1 = packet.hit.u[i];
                hit.b2 = packet.hit.v[i];
            }
        }
    }
}

}  // namespace lucerna
