#include "ui/calculation/report_export.h"

#include "report/report_builder.h"
#include "report/report_writer.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QWidget>

#include <algorithm>
#include <stdexcept>

namespace lucerna {

ReportExport::ReportExport(TaskSystem& tasks, const YieldGate& gate, QWidget* window)
    : tasks_(tasks), gate_(gate), parent_(window) {
    poll_.setInterval(100);
    connect(&poll_, &QTimer::timeout, this, &ReportExport::poll);
}

ReportExport::~ReportExport() {
    if (job_) job_->cancel();
    job_.reset();  // waits for it
}

bool ReportExport::start(SceneSnapshot scene, const QString& scenePath, const QString& path) {
    if (job_) return false;
    // Bad input (no work plane, an area that cannot be laid out, a folder that is not there) is
    // said before any work.
    const QFileInfo target(path);
    if (!target.absoluteDir().exists()) {
        finish(false, tr("%1: no such folder").arg(target.absolutePath()), true);
        return true;
    }
    try {
        checkReportInput(*scene, settings_);
    } catch (const std::invalid_argument& e) {
        finish(false, QString::fromStdString(e.what()), true);
        return true;
    }
    path_ = path;
    auto result = std::make_shared<ReportData>();
    result_ = result;
    job_ = tasks_.submit([scene, scenePath = scenePath.toStdString(), settings = settings_, result,
                          gate = gate_.counter()](TaskContext& ctx) {
        const YieldGate::Scope hold(gate);
        ReportData data = buildReport(scene, scenePath, settings, ctx);
        if (!ctx.isCancelled()) *result = std::move(data);
    });
    if (!progress_) {
        progress_ = new QProgressDialog(parent_);
        progress_->setObjectName("reportProgress");
        progress_->setWindowTitle(tr("Export Report"));
        progress_->setRange(0, 1000);
        progress_->setMinimumDuration(0);
        progress_->setAutoClose(false);
        progress_->setAutoReset(false);
        connect(progress_, &QProgressDialog::canceled, this, &ReportExport::cancel);
    }
    progress_->setLabelText(tr("Computing the report of %1: grids, glare, renders...")
                                .arg(scenePath.isEmpty() ? tr("the untitled scene") : QFileInfo(scenePath).fileName()));
    progress_->setValue(0);
    progress_->show();
    poll_.start();
    return true;
}

void ReportExport::cancel() {
    if (!job_) return;
    job_->cancel();
    job_->wait();
    finish(false, tr("Report cancelled: no file written"));
}

void ReportExport::poll() {
    if (!job_) return;
    if (!job_->isFinished()) {
        progress_->setValue(int(1000 * job_->progress()));
        return;
    }
    const bool cancelled = job_->isCancelled();
    QString error;
    try {
        job_->rethrowIfFailed();
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
    }
    if (cancelled) return finish(false, tr("Report cancelled: no file written"));
    if (!error.isEmpty()) return finish(false, error, true);
    progress_->setLabelText(tr("Writing %1...").arg(QFileInfo(path_).fileName()));
    try {
        const int pages = writeReportPdf(*result_, path_.toStdString());
        finish(true, tr("Wrote %1 (%2 pages)").arg(QFileInfo(path_).fileName()).arg(pages));
    } catch (const std::exception& e) {
        finish(false, QString::fromStdString(e.what()), true);
    }
}

void ReportExport::finish(bool written, const QString& message, bool failed) {
    poll_.stop();
    job_.reset();
    result_.reset();
    if (progress_) progress_->hide();
    if (failed) {
        // Window-modal, not blocking: the document and the window stay as they were.
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Export Report"), message, QMessageBox::Ok, parent_);
        box->setObjectName("reportError");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
    emit finished(written, message);
}

}  // namespace lucerna
