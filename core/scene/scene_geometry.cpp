#include "core/scene/scene_geometry.h"

#include "core/scene/scene_io.h"

#include <QString>

#include <limits>

namespace lucerna {

SceneBounds sceneBounds(const Scene& scene) {
    V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    bool any = false;
    const auto add = [&](const V3d& v) {
        lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
        hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
        any = true;
    };
    for (const Object& o : scene.objects)
        if (o.worldMesh)
            for (const V3d& v : o.worldMesh->vertices) add(v);
    for (const Light& l : scene.lights)
        if (l.type != LightType::Directional && l.type != LightType::Sun) add(l.position);  // at infinity
    SceneBounds b;
    if (!any) return b;
    b.lo = lo;
    b.hi = hi;
    b.center = (lo + hi) * 0.5;
    b.radius = std::max(0.5 * (hi - lo).length(), 1e-9);
    return b;
}

double planAreaM2(const Scene& scene) {
    const SceneBounds b = sceneBounds(scene);
    return (b.hi.x - b.lo.x) * (b.hi.z - b.lo.z) * scene.metersPerUnit * scene.metersPerUnit;
}

Object resolvedObject(const Scene& scene, Object object) {
    // resolveMeshes works on whole scenes; a scene of this one object reads only its mesh.
    Scene single;
    single.baseDir = scene.baseDir;
    single.materials = scene.materials;  // the loader checks the object's material
    object.worldMesh.reset();
    single.objects.push_back(std::move(object));
    resolveMeshes(single);
    return std::move(single.objects.front());
}

QString lengthUnit(const Scene& scene) {
    const double m = scene.metersPerUnit;
    const auto near = [m](double v) { return std::abs(m / v - 1.0) < 1e-9; };
    if (near(1.0)) return QStringLiteral("m");
    if (near(0.001)) return QStringLiteral("mm");
    if (near(0.01)) return QStringLiteral("cm");
    if (near(0.0254)) return QStringLiteral("in");
    if (near(0.3048)) return QStringLiteral("ft");
    if (near(1000.0)) return QStringLiteral("km");
    return QStringLiteral("u");
}

}  // namespace lucerna
