// Resolving a parsed scene (scene_resolve.h): world-space meshes from inline, quad and file
// meshes under their transforms, degenerate triangles dropped, luminaire files read.

#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/luminaire.h"
#include "core/mesh/mesh_file.h"
#include "core/scene/scene_resolve.h"

#include <QDir>

#include <cfloat>
#include <map>

namespace lucerna {

namespace {

// Why world vertices must stay within float range: the backends trace in single precision.
bool representable(const V3d& p) {
    return std::abs(p.x) <= FLT_MAX && std::abs(p.y) <= FLT_MAX && std::abs(p.z) <= FLT_MAX;
}

V3d apply(const M44d& m, const V3d& p) {
    return V3d(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
               m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
               m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

// Zero area within rounding: the sine of the corner angle is below 1e-12 (collinear points
// computed in floating point rarely give an exact zero).
bool degenerate(const V3d& a, const V3d& b, const V3d& c) {
    const V3d e1 = b - a, e2 = c - a;
    return e1.cross(e2).length() <= 1e-12 * e1.length() * e2.length();
}

}  // namespace

void resolveScene(Scene& scene, LoadReport* report, const std::string& label) {
    const auto fail = [&](const std::string& place, const std::string& problem) {
        throw SceneError(label + ": " + place + ": " + problem);
    };
    const QDir base(QString::fromStdString(scene.baseDir));
    std::map<std::string, TriangleMesh> files;  // each file read once, however many objects use it
    std::vector<std::shared_ptr<const TriangleMesh>> world(scene.objects.size());
    std::map<std::string, std::pair<double, size_t>> emitterArea;  // material -> area, first object
    int dropped = 0;
    std::vector<std::string> warnings;

    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const std::string place = item("objects", i) + ".mesh";
        TriangleMesh local;
        const TriangleMesh* source = &o.mesh.inlineMesh;
        if (o.mesh.kind == MeshSource::Kind::Quad) {
            local.vertices.assign(o.mesh.quad.begin(), o.mesh.quad.end());
            local.triangles = {V3i(0, 1, 2), V3i(0, 2, 3)};
            source = &local;
        } else if (o.mesh.kind == MeshSource::Kind::File) {
            const std::string path = base.absoluteFilePath(QString::fromStdString(o.mesh.file)).toStdString();
            auto it = files.find(path);
            if (it == files.end()) {
                try {
                    it = files.emplace(path, readMeshFile(path)).first;
                } catch (const std::runtime_error& e) {
                    fail(place + ".file", std::string("cannot load mesh file ") + e.what());
                }
            }
            source = &it->second;
        }

        const M44d m = o.transform ? o.transform->toMatrix() : M44d();
        auto out = std::make_shared<TriangleMesh>();
        out->vertices.reserve(source->vertices.size());
        for (size_t k = 0; k < source->vertices.size(); ++k) {
            const V3d p = apply(m, source->vertices[k]);
            if (!representable(p))
                fail(place, "vertex " + std::to_string(k) + " lies beyond single-precision range after the transform");
            out->vertices.push_back(p);
        }
        const int n = int(out->vertices.size());
        int droppedHere = 0;
        double area = 0;
        for (size_t k = 0; k < source->triangles.size(); ++k) {
            const V3i& t = source->triangles[k];
            if (t.x < 0 || t.x >= n || t.y < 0 || t.y >= n || t.z < 0 || t.z >= n)
                fail(place + ".triangles[" + std::to_string(k) + "]", "index out of range (the mesh has " +
                                                                          std::to_string(n) + " vertices)");
            const V3d &a = out->vertices[size_t(t.x)], &b = out->vertices[size_t(t.y)], &c = out->vertices[size_t(t.z)];
            if (degenerate(a, b, c)) {
                ++droppedHere;
                continue;
            }
            area += 0.5 * (b - a).cross(c - a).length();
            out->triangles.push_back(t);
        }
        if (droppedHere > 0) {
            dropped += droppedHere;
            warnings.push_back(label + ": " + place + ": dropped " + std::to_string(droppedHere) + " of " +
                               std::to_string(source->triangles.size()) + " triangles as degenerate (zero area)");
        } else if (source->triangles.empty()) {
            warnings.push_back(label + ": " + place + ": the mesh has no triangles");
        }
        const Material* mat = scene.findMaterial(o.material);
        if (!mat) fail(item("objects", i) + ".material", "unknown material " + quote(o.material));
        if (mat->type == MaterialType::Emitter) emitterArea.try_emplace(o.material, 0.0, i).first->second.first += area;
        world[i] = std::move(out);
    }

    for (const auto& [name, areaAndObject] : emitterArea)
        if (!(areaAndObject.first > 0))
            fail(item("objects", areaAndObject.second) + ".mesh",
                 "the objects of emitter material " + quote(name) + " have zero total area");

    // Luminaire files, each read once however many lights use it.
    std::map<std::string, std::shared_ptr<const GoniometricDistribution>> distributionFiles;
    std::vector<std::shared_ptr<const GoniometricDistribution>> distributions(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        if (l.type != LightType::Luminaire || !l.luminaire) continue;
        const std::string path = base.absoluteFilePath(QString::fromStdString(l.luminaire->file)).toStdString();
        auto it = distributionFiles.find(path);
        if (it == distributionFiles.end()) {
            try {
                it = distributionFiles.emplace(path, std::make_shared<const GoniometricDistribution>(loadLuminaireFile(path))).first;
            } catch (const LuminaireFileError& e) {
                fail(item("lights", i) + ".file", std::string("cannot load luminaire file ") + e.what());
            }
        }
        distributions[i] = it->second;
    }

    // Only now that nothing can fail does the scene change.
    for (size_t i = 0; i < world.size(); ++i) scene.objects[i].worldMesh = std::move(world[i]);
    for (size_t i = 0; i < distributions.size(); ++i)
        if (distributions[i]) scene.lights[i].luminaire->distribution = std::move(distributions[i]);
    if (report) {
        report->degenerateTrianglesDropped += dropped;
        report->warnings.insert(report->warnings.end(), warnings.begin(), warnings.end());
    }
}

void resolveMeshes(Scene& scene, LoadReport* report) {
    resolveScene(scene, report, scene.baseDir.empty() ? std::string("scene") : scene.baseDir);
}

}  // namespace lucerna
