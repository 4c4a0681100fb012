// Model import in a process of its own (model_import.h). The request and the result travel as
// files in a temporary folder: the request as JSON (the model, the units, the names already
// taken), the result as a SPEC.md scene with inline meshes (saveSceneToString round-trips
// exactly) and the report as JSON. A crash of the importer costs its process, not the caller's.

#include "core/mesh/model_import.h"

#include "core/atomic_file.h"
#include "core/read_crash_hook.h"
#include "core/scene/json_reader.h"
#include "core/scene/json_string.h"
#include "core/scene/scene_io.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace lucerna {

namespace {

constexpr char kRequestFile[] = "request.json";
constexpr char kSceneFile[] = "model.json";
constexpr char kReportFile[] = "report.json";

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string jsonArray(const std::vector<std::string>& items) {
    std::string out = "[";
    for (const std::string& s : items) out += (out.size() > 1 ? "," : "") + jsonQuoted(s, JsonEscapes::Short);
    return out + "]";
}

std::vector<std::string> strings(const json::Value* array) {
    std::vector<std::string> out;
    if (array)
        for (const json::Value& v : array->array) out.push_back(v.string);
    return out;
}

double number(const json::Value& root, const char* key, double fallback) {
    const json::Value* v = root.find(key);
    return v && v->type == json::Type::Number ? v->number : fallback;
}

// The request: the model, its units and the names the import must not take.
std::string requestText(const std::string& path, const ImportOptions& options) {
    std::vector<std::string> things, materials;
    if (options.into) {
        for (const Object& o : options.into->objects) things.push_back(o.name);
        for (const Light& l : options.into->lights) things.push_back(l.name);
        for (const Material& m : options.into->materials) materials.push_back(m.name);
    }
    char units[128];
    std::snprintf(units, sizeof units, "\"scene_meters_per_unit\": %.17g", options.sceneMetersPerUnit);
    std::string text = "{\"model\": " + jsonQuoted(path, JsonEscapes::Short) + ", " + units;
    if (options.fileMetersPerUnit) {
        std::snprintf(units, sizeof units, ", \"file_meters_per_unit\": %.17g", *options.fileMetersPerUnit);
        text += units;
    }
    return text + ", \"things\": " + jsonArray(things) + ", \"materials\": " + jsonArray(materials) + "}\n";
}

// Beside the running executable when installed or built there, else where the build put it.
QString importerProgram() {
    if (QCoreApplication::instance()) {
        const QString beside = QDir(QCoreApplication::applicationDirPath()).filePath("lucerna-model-import");
        if (QFileInfo(beside).isExecutable()) return beside;
    }
    return QStringLiteral(LUCERNA_MODEL_IMPORTER);
}

std::string signalName(int signal) {
    const char* name = sigabbrev_np(signal);
    return name ? std::string("SIG") + name : "signal " + std::to_string(signal);
}

// The last non-empty line the importer wrote on stderr: its one-line error.
std::string lastLine(const QByteArray& err) {
    const QList<QByteArray> lines = err.trimmed().split('\n');
    return lines.isEmpty() ? std::string() : lines.back().trimmed().toStdString();
}

}  // namespace

ModelImport importModel(const std::string& path, const ImportOptions& options) {
    QTemporaryDir folder;
    if (!folder.isValid()) throw std::runtime_error(path + ": no temporary folder for the model importer");
    const std::string request = QDir(folder.path()).filePath(kRequestFile).toStdString();
    writeTextAtomically(request, requestText(path, options));

    QProcess importer;
    importer.setProcessChannelMode(QProcess::SeparateChannels);
    importer.setStandardOutputFile(QProcess::nullDevice());
    importer.start(importerProgram(), {QString::fromStdString(request), folder.path()});
    if (!importer.waitForStarted(-1))
        throw std::runtime_error(path + ": cannot start the model importer " + importerProgram().toStdString() + ": " +
                                 importer.errorString().toStdString());
    importer.waitForFinished(-1);
    if (importer.exitStatus() == QProcess::CrashExit)  // Qt gives the signal as the exit code
        throw std::runtime_error(path + ": the model importer (Assimp) crashed on this file (" +
                                 signalName(importer.exitCode()) + "); nothing was imported");
    if (importer.exitCode() != 0) {
        const std::string why = lastLine(importer.readAllStandardError());
        throw std::runtime_error(why.empty() ? path + ": the model importer failed (exit code " +
                                                   std::to_string(importer.exitCode()) + ")"
                                             : why);
    }

    const std::string sceneFile = QDir(folder.path()).filePath(kSceneFile).toStdString();
    Scene scene;
    try {
        scene = parseScene(readText(sceneFile), sceneFile);
    } catch (const SceneError& e) {
        throw std::runtime_error(path + ": the scene the importer made would not load: " + e.what());
    }
    const json::Value report = json::parse(readText(QDir(folder.path()).filePath(kReportFile).toStdString()));
    ModelImport out;
    out.objects = std::move(scene.objects);
    for (Object& o : out.objects) o.worldMesh.reset();  // the caller resolves them in its scene
    out.materials = std::move(scene.materials);
    out.lights = std::move(scene.lights);
    out.triangles = size_t(number(report, "triangles", 0));
    out.report = strings(report.find("report"));
    return out;
}

int runModelImportProcess(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: lucerna-model-import REQUEST.json FOLDER (run by lucerna, not by hand)\n");
        return 2;
    }
    try {
        crashHereWhenTesting("model-importer");
        const json::Value request = json::parse(readText(argv[1]));
        const json::Value* model = request.find("model");
        if (!model || model->type != json::Type::String) throw std::runtime_error(std::string(argv[1]) + ": no model");
        // Only the names matter to the import: it makes its own unique against them.
        Scene taken;
        for (const std::string& name : strings(request.find("things"))) taken.objects.emplace_back().name = name;
        for (const std::string& name : strings(request.find("materials"))) taken.materials.emplace_back().name = name;
        ImportOptions options;
        options.sceneMetersPerUnit = number(request, "scene_meters_per_unit", 1.0);
        if (request.find("file_meters_per_unit")) options.fileMetersPerUnit = number(request, "file_meters_per_unit", 1.0);
        options.into = &taken;
        ModelImport imported = importModelInProcess(model->string, options);

        Scene scene;
        scene.objects = std::move(imported.objects);
        scene.materials = std::move(imported.materials);
        scene.lights = std::move(imported.lights);
        const std::string folder = argv[2];
        writeTextAtomically(folder + "/" + kSceneFile, saveSceneToString(scene));
        writeTextAtomically(folder + "/" + kReportFile, "{\"triangles\": " + std::to_string(imported.triangles) +
                                                            ", \"report\": " + jsonArray(imported.report) + "}\n");
        return 0;
    } catch (const std::exception& e) {
        std::string why = e.what();
        std::replace(why.begin(), why.end(), '\n', ' ');  // the caller reads the last line
        std::fprintf(stderr, "%s\n", why.c_str());
        return 2;
    }
}

}  // namespace lucerna
