#include "app/import_command.h"

#include "app/cli_support.h"
#include "core/mesh/mesh_file.h"
#include "core/mesh/model_import.h"
#include "core/scene/scene_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <set>

namespace lucerna::cli {

namespace {

// A camera from the front-right and a little above (y is up), far enough back that the bounding
// sphere of the geometry and lights fills most of a 45 degree view.
Camera cameraFor(const Scene& scene) {
    V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    const auto grow = [&](const V3d& p) {
        lo = V3d(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
        hi = V3d(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    };
    for (const Object& o : scene.objects)
        for (const V3d& v : o.mesh.inlineMesh.vertices) grow(v);
    Camera camera;
    if (lo.x > hi.x) return camera;
    const V3d centre = (lo + hi) * 0.5;
    const double radius = std::max((hi - lo).length() * 0.5, 1e-6);
    camera.fovYDeg = 45;
    camera.target = centre;
    camera.position = centre + V3d(0.45, 0.35, 1.0).normalized() * (1.1 * radius / std::sin(camera.fovYDeg * M_PI / 360.0));
    camera.up = V3d(0, 1, 0);
    camera.width = 640;
    camera.height = 480;
    return camera;
}

// What an import has written so far, taken back if it fails: no half-written import (a folder
// of meshes without its scene) is left behind.
struct Written {
    std::filesystem::path createdFolder;  // empty if it was there before
    std::vector<std::filesystem::path> files;

    void undo() const {
        std::error_code ec;
        for (const auto& f : files) std::filesystem::remove(f, ec);
        if (!createdFolder.empty()) std::filesystem::remove(createdFolder, ec);  // only if empty
    }
};

// Each object's mesh to a PLY file of its own in `folder` (beside the scene, which refers to
// it relatively): an architect's model of a million triangles reads and edits far better than
// as inline JSON. File names are the object names made safe, unique within the folder.
void moveMeshesToFiles(Scene& scene, const std::filesystem::path& sceneFile, Written& written) {
    const std::filesystem::path folderName = sceneFile.stem().string() + "-meshes";
    const std::filesystem::path folder = sceneFile.parent_path() / folderName;
    std::error_code ec;
    const bool existed = std::filesystem::exists(folder, ec);
    std::filesystem::create_directories(folder, ec);
    if (ec) throw UsageError(folder.string() + ": cannot create the folder (" + ec.message() + ")");
    if (!existed) written.createdFolder = folder;
    std::set<std::string> used;
    for (Object& o : scene.objects) {
        if (o.mesh.kind != MeshSource::Kind::Inline) continue;
        std::string base = o.name;
        for (char& c : base)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
        if (base.empty() || base[0] == '.') base = "mesh" + base;
        std::string name = base + ".ply";
        for (int i = 2; used.count(name); ++i) name = base + "-" + std::to_string(i) + ".ply";
        used.insert(name);
        try {
            writePlyFile((folder / name).string(), o.mesh.inlineMesh);
            written.files.push_back(folder / name);
        } catch (const std::runtime_error& e) {
            throw UsageError(e.what());
        }
        o.mesh.kind = MeshSource::Kind::File;
        o.mesh.file = (folderName / name).generic_string();
        o.mesh.inlineMesh = {};
    }
}

int importImpl(const std::vector<std::string>& args) {
    std::string model, output;
    ImportOptions options;
    bool inlineMeshes = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "-o") output = value();
        else if (a == "--meters-per-unit") options.sceneMetersPerUnit = parseNumber<double>(a, value(), 1e-9, 1e9);
        else if (a == "--model-unit") options.fileMetersPerUnit = parseNumber<double>(a, value(), 1e-9, 1e9);
        else if (a == "--inline-meshes") inlineMeshes = true;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (model.empty()) model = a;
        else throw UsageError("unexpected argument '" + a + "'");
    }
    if (model.empty() || output.empty())
        throw UsageError(
            "usage: lucerna import MODEL -o SCENE.json [--meters-per-unit M] [--model-unit M] [--inline-meshes]");
    checkOutputPath(output);

    ModelImport imported;
    try {
        imported = importModel(model, options);
    } catch (const std::runtime_error& e) {
        throw UsageError(e.what());
    }
    Scene scene;
    scene.metersPerUnit = options.sceneMetersPerUnit;
    scene.metersPerUnitGiven = true;
    scene.materials = std::move(imported.materials);
    scene.objects = std::move(imported.objects);
    scene.lights = std::move(imported.lights);
    scene.camera = cameraFor(scene);  // from the inline meshes, before they move to files
    // The scene's own loader judges it before anything is written: an import never leaves a
    // scene behind that `lucerna info` would refuse.
    try {
        parseScene(saveSceneToString(scene), output);
    } catch (const SceneError& e) {
        throw UsageError(model + ": the scene it makes would not load: " + e.what());
    }
    Written written;
    try {
        if (!inlineMeshes) moveMeshesToFiles(scene, std::filesystem::path(output), written);
        saveScene(scene, output);
    } catch (const std::exception& e) {
        written.undo();
        throw UsageError(e.what());
    }
    for (const std::string& line : imported.report) std::cout << line << "\n";
    const bool lit = !scene.lights.empty() || std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
                         return m.type == MaterialType::Emitter;
                     });
    if (!lit) std::cout << "note: the model brings no light; add one before rendering\n";
    std::cout << "wrote " << output << "\n";
    return 0;
}

}  // namespace

int importModelCommand(const std::vector<std::string>& args) { return runCommand(importImpl, args); }

}  // namespace lucerna::cli
