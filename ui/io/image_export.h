#pragma once
// What File > Export writes: the converged image or the live preview as SPEC.md section 3 EXR
// images, each with the albedo, normal and depth layers of the scene it shows (at its own size)
// and the lucerna: attributes; and the picture on the screen as a PNG.

#include "core/image/image.h"
#include "render/backend/pass_loop.h"
#include "ui/rendering/live_preview.h"

#include <QImage>
#include <QString>

namespace lucerna {

// The converging render's frame of `scene` with the surface layers. Throws std::runtime_error.
Image convergedExportImage(const RenderFrame& frame, const SceneSnapshot& scene);
// The preview frame with the surface layers and attributes: lucerna:backend "preview" (or "path"
// where the preview fell back to the path tracer), lucerna:spp, lucerna:seconds (the time the
// frame took), lucerna:seed, and lucerna:preview_engine in words.
Image previewExportImage(const LiveFrame& frame, const QString& engineDescription);

// "DIR/name.exr" with a suffix before the extension: "DIR/name-preview.exr".
QString exportSibling(const QString& path, const QString& suffix);

// Writes a PNG whole or not at all. Throws std::runtime_error with a one-line reason.
void writePng(const QImage& picture, const QString& path);

}  // namespace lucerna
