#include "ui/io/export_actions.h"

#include "core/image/exr_io.h"
#include "render/display/display.h"
#include "ui/calculation/report_export.h"
#include "ui/compare/compare_view.h"
#include "ui/document/document.h"
#include "ui/io/file_dialogs.h"
#include "ui/io/image_export.h"
#include "ui/rendering/converging_render.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <QMenu>

namespace lucerna {

ExportActions::ExportActions(const Document& doc, const ConvergingRender& render, const LivePreview& preview,
                             ReportExport& report, const CompareView& compare, FileDialogs& dialogs,
                             WindowMessages& messages)
    : doc_(doc), render_(render), preview_(preview), report_(report), compare_(compare), dialogs_(dialogs),
      messages_(messages) {
    connect(&report_, &ReportExport::finished, this,
            [this](bool, const QString& message) { messages_.show(message, 8000); });
}

void ExportActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("&Export EXR..."), "actionExportExr", QKeySequence(tr("Ctrl+E")), this, [this] {
        const QString path = dialogs_.save(tr("Export the converged image"), tr("OpenEXR (*.exr)"), suggested("exr", "render"));
        if (!path.isEmpty()) messages_.warnUnless(exportExr(path), tr("Export EXR"));
    });
    addMenuEntry(menu, tr("Export &Preview EXR..."), "actionExportPreviewExr", QKeySequence(tr("Ctrl+Alt+E")), this, [this] {
        const QString path = dialogs_.save(tr("Export the preview"), tr("OpenEXR (*.exr)"), suggested("exr", "preview"));
        if (!path.isEmpty()) messages_.warnUnless(exportPreviewExr(path), tr("Export EXR"));
    });
    addMenuEntry(menu, tr("Export &Both EXR..."), "actionExportBothExr", {}, this, [this] {
        const QString path = dialogs_.save(tr("Export preview and converged image (NAME-preview.exr, NAME-converged.exr)"),
                                           tr("OpenEXR (*.exr)"), suggested("exr", "render"));
        if (!path.isEmpty()) messages_.warnUnless(exportBothExr(path), tr("Export EXR"));
    });
    addMenuEntry(menu, tr("Export P&NG..."), "actionExportPng", QKeySequence(tr("Ctrl+Shift+E")), this, [this] {
        const QString path =
            dialogs_.save(tr("Export the converged image as a picture"), tr("PNG (*.png)"), suggested("png", "render"));
        if (!path.isEmpty()) messages_.warnUnless(exportPng(path), tr("Export PNG"));
    });
    addMenuEntry(menu, tr("Export &Report..."), "actionExportReport", QKeySequence(tr("Ctrl+Shift+R")), this, [this] {
        QString path = dialogs_.save(tr("Export the lighting design report"), tr("PDF (*.pdf)"), suggested("pdf", "report"));
        if (path.isEmpty()) return;
        if (!path.endsWith(QStringLiteral(".pdf"), Qt::CaseInsensitive)) path += QStringLiteral(".pdf");
        if (!report_.start(doc_.snapshot(), QString::fromStdString(doc_.path()), path))
            messages_.show(tr("A report is being computed already"), 5000);
    });
}

QString ExportActions::suggested(const QString& extension, const QString& fallback) const {
    return suggestedFileName(QString::fromStdString(doc_.path()), extension, fallback);
}

bool ExportActions::written(const std::function<void()>& write, const QString& done) {
    if (!messages_.attempt(write)) return false;
    messages_.show(done, 5000);
    return true;
}

bool ExportActions::exportExr(const QString& path) {
    const auto frame = render_.frame();
    if (!frame) return messages_.fail(tr("Nothing to export yet: the converging render has no frame."));
    return written([&] { writeExr(path.toStdString(), convergedExportImage(*frame, render_.scene())); },
                   tr("Exported %1 (%2 spp)").arg(path).arg(frame->samplesPerPixel));
}

bool ExportActions::exportPreviewExr(const QString& path) {
    const auto frame = preview_.frame();
    if (!frame) return messages_.fail(tr("Nothing to export yet: the preview has no frame."));
    return written([&] { writeExr(path.toStdString(), previewExportImage(*frame, preview_.engineDescription())); },
                   tr("Exported %1").arg(path));
}

bool ExportActions::exportBothExr(const QString& path) {
    // Two files: the two images differ in size (the preview draws at a reduced resolution).
    return exportPreviewExr(exportSibling(path, "-preview")) && exportExr(exportSibling(path, "-converged"));
}

bool ExportActions::exportPng(const QString& path) {
    const auto frame = render_.frame();
    if (!frame) return messages_.fail(tr("Nothing to export yet: the converging render has no frame."));
    return written([&] { writePng(toDisplayImage(frame->image, compare_.displaySettings()), path); },
                   tr("Exported %1").arg(path));
}

}  // namespace lucerna
