// Rays per second of the path tracer against bare Embree on the same rays.
//
// The path tracer renders the scene (timed); the same render, being deterministic for a seed, is
// run again with every ray recorded; the recorded rays are then traced by bare rtcIntersect1 /
// rtcOccluded1 calls (timed). The ratio of the two rates is the share of the time the tracer
// spends tracing rays rather than on everything else (sampling, shading, bookkeeping).
//
// usage: bench_rays SCENE.json [--spp N] [--threads N] [--million]
//   --million adds a tessellated bumpy sphere of about a million triangles to the scene.

#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/backend/film.h"
#include "render/progressive/path/path_backend.h"
#include "render/trace/path_settings.h"
#include "render/trace/render_scene.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace lucerna;

namespace {

// A sphere of radius r at c with bumps, rings x segments quads (2 triangles each).
std::shared_ptr<TriangleMesh> bumpySphere(const V3d& c, double r, int rings, int segments) {
    auto mesh = std::make_shared<TriangleMesh>();
    const double pi = std::numbers::pi;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= segments; ++j) {
            const double th = pi * i / rings, ph = 2 * pi * j / segments;
            const double rr = r * (1.0 + 0.03 * std::sin(17 * th) * std::sin(13 * ph));
            mesh->vertices.push_back(c + V3d(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)) * rr);
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const int a = i * (segments + 1) + j, b = a + 1, d = a + segments + 1, e = d + 1;
            mesh->triangles.push_back(V3i(a, b, e));
            mesh->triangles.push_back(V3i(a, e, d));
        }
    return mesh;
}

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_rays SCENE.json [--spp N] [--threads N] [--million]\n");
        return 2;
    }
    int spp = 16, threads = 0;
    bool million = false;
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--spp") && i + 1 < argc) spp = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--million")) million = true;
    }
    Scene scene = loadScene(argv[1]);
    if (million) {
        // Centred low in the scene's bounds, a fifth of its size: it shadows and is lit.
        V3d lo(1e300), hi(-1e300);
        for (const Object& o : scene.objects)
            for (const V3d& v : o.worldMesh->vertices) {
                lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
                hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
            }
        const double r = 0.2 * std::min(hi.x - lo.x, std::min(hi.y - lo.y, hi.z - lo.z));
        Object o;
        o.name = "bumpy_sphere";
        for (const Material& m : scene.materials)
            if (m.type == MaterialType::Diffuse) o.material = m.name;
        o.mesh.kind = MeshSource::Kind::Inline;
        o.worldMesh = bumpySphere(V3d(0.5 * (lo.x + hi.x), lo.y + 1.1 * r, 0.5 * (lo.z + hi.z)), r, 500, 1000);
        scene.objects.push_back(std::move(o));
    }
    const auto snapshot = std::make_shared<const Scene>(std::move(scene));
    TaskSystem tasks(threads);
    PathSettings settings;
    size_t triangles = 0, rays = 0, hits = 0;
    double pathSeconds = 0, rawSeconds = 0;
    auto job = tasks.submit([&](TaskContext& ctx) {
        RenderScene rs(snapshot);
        triangles = rs.triangleCount();
        {
            Film film(rs.camera().width(), rs.camera().height());
            const auto t0 = std::chrono::steady_clock::now();
            for (int pass = 0; pass < spp; ++pass) renderPathPass(rs, settings, 1, pass, film, ctx);
            pathSeconds = seconds(t0);
        }
        RayRecorder recorder(tasks.threadCount());
        rs.setRayRecorder(&recorder);
        Film film(rs.camera().width(), rs.camera().height());
        for (int pass = 0; pass < spp; ++pass) renderPathPass(rs, settings, 1, pass, film, ctx);
        rs.setRayRecorder(nullptr);
        std::vector<RayRecorder::Entry> all;
        for (auto& v : recorder.perThread) all.insert(all.end(), v.begin(), v.end());
        rays = all.size();
        const auto t0 = std::chrono::steady_clock::now();
        hits = rs.accel().replay(all);
        rawSeconds = seconds(t0);
    });
    job->wait();
    job->rethrowIfFailed();
    std::printf("scene: %s%s\ntriangles: %zu\nthreads: %d\nspp: %d\nrays: %zu (hits %zu)\n", argv[1],
                million ? " + bumpy sphere" : "", triangles, tasks.threadCount(), spp, rays, hits);
    std::printf("path tracer: %.3f s, %.2f Mrays/s\nbare embree: %.3f s, %.2f Mrays/s\nratio: %.3f\n", pathSeconds,
                rays / pathSeconds * 1e-6, rawSeconds, rays / rawSeconds * 1e-6, rawSeconds / pathSeconds);
    return 0;
}
