#include "ui/io/image_export.h"

#include "core/number_format.h"
#include "render/trace/surface_layers.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <stdexcept>
#include <string>

namespace lucerna {

Image convergedExportImage(const RenderFrame& frame, const SceneSnapshot& scene) {
    Image image = frame.image;  // carries lucerna:backend, spp, seconds, seed
    addSurfaceLayers(image, scene);
    return image;
}

Image previewExportImage(const LiveFrame& frame, const QString& engineDescription) {
    Image image = frame.image;
    const bool gl = engineDescription.startsWith("OpenGL");
    // The fallback path tracer draws two passes with seed 7 (ui/rendering/live_preview.cpp); the OpenGL
    // preview's frame is the mean of `frames` frames, each one sample per pixel, the first with
    // its default settings (seed 1, render/preview/preview.h) and idle ones with fresh VPLs.
    image.attributes["lucerna:backend"] = gl ? "preview" : "path";
    image.attributes["lucerna:spp"] = std::to_string(gl ? frame.frames : 2);
    image.attributes["lucerna:seconds"] = formatNumber(frame.totalMilliseconds / 1000.0);
    image.attributes["lucerna:seed"] = gl ? "1" : "7";
    image.attributes["lucerna:preview_engine"] = engineDescription.toStdString();
    addSurfaceLayers(image, frame.scene);
    return image;
}

QString exportSibling(const QString& path, const QString& suffix) {
    const QFileInfo info(path);
    const QString ext = info.suffix().isEmpty() ? QStringLiteral("exr") : info.suffix();
    return info.dir().filePath(info.completeBaseName() + suffix + "." + ext);
}

void writePng(const QImage& picture, const QString& path) {
    if (picture.isNull()) throw std::runtime_error("there is no picture to export yet");
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || !picture.save(&file, "PNG") || !file.commit())
        throw std::runtime_error(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
}

}  // namespace lucerna
