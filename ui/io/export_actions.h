#pragma once
// File > Export: the converging render's newest frame or the live preview's as SPEC.md section 3
// EXR images (ui/io/image_export.h), the converged image as the display shows it as a PNG, and
// the lighting design report as a PDF (ui/calculation/report_export.h).

#include <QObject>
#include <QString>

#include <functional>

class QMenu;

namespace lucerna {

class CompareView;
class ConvergingRender;
class Document;
class FileDialogs;
class LivePreview;
class ReportExport;
class WindowMessages;

class ExportActions : public QObject {
    Q_OBJECT
public:
    // `compare` holds the display settings the PNG is drawn with.
    ExportActions(const Document& doc, const ConvergingRender& render, const LivePreview& preview, ReportExport& report,
                  const CompareView& compare, FileDialogs& dialogs, WindowMessages& messages);

    // Adds Export EXR, Export Preview EXR, Export Both EXR, Export PNG and Export Report to `menu`.
    void addTo(QMenu* menu);

    // The operations behind the menu, without dialogs. Each returns false and says why
    // (WindowMessages::fail) when it fails, e.g. when there is no frame yet.
    bool exportExr(const QString& path);  // the converging render's newest frame
    // The live preview's newest frame; both: PATH-preview.exr and PATH-converged.exr. Every EXR
    // export carries albedo, normal and depth layers (README).
    bool exportPreviewExr(const QString& path);
    bool exportBothExr(const QString& path);
    // The converging render's newest frame at full resolution, as the display settings show it
    // (exposure, tone curve or false colour).
    bool exportPng(const QString& path);

private:
    // Runs `write`; a failure it throws is said, a success is `done` in the status bar.
    bool written(const std::function<void()>& write, const QString& done);
    // The file name the save dialogs offer: the scene's name with `extension`, else `fallback`'s.
    QString suggested(const QString& extension, const QString& fallback) const;

    const Document& doc_;
    const ConvergingRender& render_;
    const LivePreview& preview_;
    ReportExport& report_;
    const CompareView& compare_;
    FileDialogs& dialogs_;
    WindowMessages& messages_;
};

}  // namespace lucerna
