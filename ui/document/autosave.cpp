#include "ui/document/autosave.h"

#include "core/scene/scene_io.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUuid>

namespace lucerna {

namespace {
// Two files: the scene as SPEC.md JSON (mesh paths as the document has them, relative to its
// folder), and the path it is parsed against (the document's file, or a name in its folder for
// an untitled scene) with the document's own path on the second line.
QString sceneFile(const QString& dir) { return QDir(dir).filePath("autosave.json"); }
QString originFile(const QString& dir) { return QDir(dir).filePath("autosave.origin"); }
// The run marker: the id of the newest run that has not closed cleanly (or is still running).
QString runFile(const QString& dir) { return QDir(dir).filePath("run.marker"); }

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAtomically(const QString& path, const QByteArray& bytes) {
    QSaveFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size() && f.commit();
}
}  // namespace

Autosave::Autosave(Document& document, QString directory, int intervalMs, QObject* parent)
    : QObject(parent), document_(document), directory_(std::move(directory)),
      runId_(QUuid::createUuid().toByteArray(QUuid::WithoutBraces)) {
    // Without a marker, a crash of this run would never be offered back: worth a try now and at
    // each autosave.
    if (QDir().mkpath(directory_)) writeAtomically(runFile(directory_), runId_);
    connect(&timer_, &QTimer::timeout, this, [this] { writeNow(); });
    connect(document_.undoStack(), &QUndoStack::indexChanged, this, [this] { letGo_ = false; });
    timer_.start(intervalMs);
}

bool Autosave::writeNow() {
    if (letGo_ || !document_.isModified()) return false;
    const Scene& scene = document_.scene();
    const std::string parseAs =
        document_.path().empty() ? QDir(QString::fromStdString(scene.baseDir)).filePath("untitled.json").toStdString()
                                 : document_.path();
    if (!QDir().mkpath(directory_)) return false;
    if (readAll(runFile(directory_)) != runId_ && !writeAtomically(runFile(directory_), runId_)) return false;
    // The origin first: a scene file without its origin is never read back.
    return writeAtomically(originFile(directory_),
                           QByteArray::fromStdString(parseAs + "\n" + document_.path() + "\n") + runId_ + "\n") &&
           writeAtomically(sceneFile(directory_), QByteArray::fromStdString(saveSceneToString(scene)));
}

void Autosave::discard() { discard(directory_); }

void Autosave::letGo() {
    discard();
    letGo_ = true;
}

void Autosave::closedCleanly() {
    timer_.stop();
    discard();
    // Another run may have started since and written its own marker: that one stays.
    if (readAll(runFile(directory_)) == runId_) QFile::remove(runFile(directory_));
}

void Autosave::discard(const QString& directory) {
    QFile::remove(sceneFile(directory));
    QFile::remove(originFile(directory));
}

std::optional<Autosave::Recovery> Autosave::pending(const QString& directory, QString* error) {
    QFile scene(sceneFile(directory)), origin(originFile(directory));
    if (!scene.exists() || !origin.exists() || !scene.open(QIODevice::ReadOnly) || !origin.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QStringList lines = QString::fromUtf8(origin.readAll()).split('\n');
    // Left by a run that closed cleanly (a clean switch to another scene, a second window's
    // leftovers), or older than the scene's file: stale, not offered.
    const QString runner = lines.value(2);
    const QString documentPath = lines.value(1);
    const bool unclean = !runner.isEmpty() && QString::fromUtf8(readAll(runFile(directory))) == runner;
    const bool newer = documentPath.isEmpty() || !QFileInfo::exists(documentPath) ||
                       QFileInfo(scene).lastModified() >= QFileInfo(documentPath).lastModified();  // equal: coarse clocks
    if (!unclean || !newer) {
        scene.close();
        origin.close();
        discard(directory);
        return std::nullopt;
    }
    try {
        Recovery r;
        r.scene = parseScene(scene.readAll().toStdString(), lines.value(0).toStdString());
        r.documentPath = lines.value(1).toStdString();
        return r;
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        discard(directory);
        return std::nullopt;
    }
}

QString Autosave::defaultDirectory() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath("recovery");
}

}  // namespace lucerna
