#pragma once
// File > Export Report (README, "Reports"): the PDF report of the document's scene, built in the
// background (report/report_builder.h) while a progress dialog shows how far it is and offers
// Cancel, then written whole or not at all (report/report_writer.h). The job holds the yield
// gate, so the converging render waits until the report is done. Nothing of the document changes.

// oneTBB before any Qt header: Qt's `emit` macro breaks TBB's headers.
#include "core/task_system.h"
#include "report/report_data.h"
#include "ui/rendering/yield_gate.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

class QProgressDialog;
class QWidget;

namespace lucerna {

class ReportExport : public QObject {
    Q_OBJECT
public:
    // `window`: the progress dialog's and message box's parent. Jobs run in `tasks`, which must
    // outlive this object (its destructor cancels and waits for the job).
    ReportExport(TaskSystem& tasks, const YieldGate& gate, QWidget* window);
    ~ReportExport() override;

    // The settings of the next report (the command line's defaults unless set; tests use small ones).
    void setSettings(const ReportSettings& settings) { settings_ = settings; }
    const ReportSettings& settings() const { return settings_; }

    // Starts the report of `scene` (its file `scenePath`, "" when untitled) to `path`; false when
    // one is running already.
    bool start(SceneSnapshot scene, const QString& scenePath, const QString& path);
    bool isRunning() const { return job_ != nullptr; }
    void cancel();
    QProgressDialog* progressDialog() const { return progress_; }

signals:
    // Once per start: written (message: "Wrote NAME (N pages)") or not (the one-line error, also
    // shown in a message box, or "Report cancelled: no file written").
    void finished(bool written, const QString& message);

private:
    void poll();
    void finish(bool written, const QString& message, bool failed = false);

    TaskSystem& tasks_;
    YieldGate gate_;
    QWidget* parent_;
    ReportSettings settings_;
    QProgressDialog* progress_ = nullptr;
    QTimer poll_;
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<ReportData> result_;  // written by the job, read once it has finished
    QString path_;
};

}  // namespace lucerna
