#include "ui/io/mesh_import.h"

#include "core/mesh/mesh_file.h"
#include "core/scene/scene_geometry.h"

#include <QDir>
#include <QFileInfo>

#include <limits>
#include <stdexcept>

namespace lucerna {

namespace {
struct Box {
    V3d lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    double largestSide() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}); }
};

Box boundsOf(const std::vector<V3d>& points) {
    Box b;
    for (const V3d& v : points) {
        b.lo = V3d(std::min(b.lo.x, v.x), std::min(b.lo.y, v.y), std::min(b.lo.z, v.z));
        b.hi = V3d(std::max(b.hi.x, v.x), std::max(b.hi.y, v.y), std::max(b.hi.z, v.z));
    }
    return b;
}

std::string uniqueMaterialName(const Scene& scene, const std::string& base) {
    if (scene.materialIndex(base) < 0) return base;
    for (int i = 2;; ++i)
        if (const std::string name = base + "-" + std::to_string(i); scene.materialIndex(name) < 0) return name;
}
}  // namespace

std::string scenePathOf(const Document& doc, const QString& file) {
    const QString absolute = QFileInfo(file).absoluteFilePath();
    const std::string& baseDir = doc.scene().baseDir;
    const bool saved = !doc.path().empty() && !baseDir.empty();
    return (saved ? QDir(QString::fromStdString(baseDir)).relativeFilePath(absolute) : absolute).toStdString();
}

MeshImport importMesh(const Document& doc, const QString& file) {
    const Scene& scene = doc.scene();
    const QFileInfo info(file);
    const QString absolute = info.absoluteFilePath();
    const TriangleMesh mesh = readMeshFile(absolute.toStdString());  // throws with a one-line reason
    if (mesh.triangles.empty()) throw std::runtime_error(file.toStdString() + ": the mesh has no faces");

    MeshImport out;
    const std::string base = info.completeBaseName().isEmpty() ? std::string("mesh") : info.completeBaseName().toStdString();
    out.object.name = doc.uniqueName(base);
    out.material.name = uniqueMaterialName(scene, base);
    out.material.type = MaterialType::Diffuse;
    out.material.albedo = Rgbd(0.8, 0.8, 0.8);
    out.object.material = out.material.name;
    out.object.mesh.kind = MeshSource::Kind::File;
    out.object.mesh.file = scenePathOf(doc, file);

    const Box m = boundsOf(mesh.vertices);
    const double side = m.largestSide();
    const bool hasGeometry = std::any_of(scene.objects.begin(), scene.objects.end(),
                                         [](const Object& o) { return o.worldMesh && !o.worldMesh->vertices.empty(); });
    if (hasGeometry && side > 0) {
        const SceneBounds s = sceneBounds(scene);
        const double sceneSide = std::max({s.hi.x - s.lo.x, s.hi.y - s.lo.y, s.hi.z - s.lo.z});
        if (side < 0.02 * sceneSide || side > 2.0 * sceneSide) {
            Transform t;
            const double k = sceneSide / (3.0 * side);
            t.scale = V3d(k, k, k);
            const V3d bottom((m.lo.x + m.hi.x) * 0.5, m.lo.y, (m.lo.z + m.hi.z) * 0.5);
            t.translate = V3d(s.center.x, s.lo.y, s.center.z) - bottom * k;
            out.object.transform = t;
        }
    }
    // The world mesh from the stored path, as the loader will find it, in the scene as it will
    // be (with the new material).
    Scene withMaterial = scene;
    withMaterial.materials.push_back(out.material);
    out.object = resolvedObject(withMaterial, std::move(out.object));
    return out;
}

}  // namespace lucerna
