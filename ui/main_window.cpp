#include "ui/main_window.h"

#include "core/scene_io.h"
#include "render/progressive/backend.h"
#include "ui/display.h"

#include <QFileInfo>
#include <QStatusBar>

namespace lucerna {

MainWindow::MainWindow(const std::string& scenePath, QWidget* parent) : QMainWindow(parent) {
    view_ = new QLabel(this);
    view_->setAlignment(Qt::AlignCenter);
    view_->setMinimumSize(256, 256);
    setCentralWidget(view_);
    resize(900, 700);
    connect(&refresh_, &QTimer::timeout, this, &MainWindow::showNewestFrame);
    refresh_.start(200);
    openScene(scenePath);
}

MainWindow::~MainWindow() {
    if (job_) job_->cancel();
}

void MainWindow::openScene(const std::string& path) {
    if (job_) job_->cancel();
    job_.reset();
    setWindowTitle(QStringLiteral("%1 - Lucerna").arg(QFileInfo(QString::fromStdString(path)).fileName()));
    SceneSnapshot scene;
    try {
        scene = std::make_shared<const Scene>(loadScene(path));
    } catch (const std::exception& e) {
        statusBar()->showMessage(QString::fromStdString(e.what()));
        return;
    }
    const AutoChoice choice = chooseAutoBackend(*scene);
    RenderSettings settings;
    settings.seconds = 1e9;  // converge until the scene changes or the window closes
    statusBar()->showMessage(QString::fromStdString("auto: " + choice.reason));
    job_ = tasks_.submit([this, scene, settings, name = choice.backend](TaskContext& ctx) {
        auto backend = findBackend(name)->make(scene, settings);
        backend->prepare(ctx);
        runProgressive(*backend, name, settings, ctx, &frames_, 0.25);
    });
}

void MainWindow::showNewestFrame() {
    if (frames_.version() == shownVersion_) return;
    shownVersion_ = frames_.version();
    shown_ = frames_.get();
    if (!shown_) return;
    // Fit the view, keeping the aspect ratio; upscaling stays sharp so that pixels can be read.
    const QImage picture = toDisplayImage(shown_->image);
    const QSize fitted = picture.size().scaled(view_->size(), Qt::KeepAspectRatio);
    view_->setPixmap(QPixmap::fromImage(picture.scaled(fitted, Qt::IgnoreAspectRatio, Qt::FastTransformation)));
    statusBar()->showMessage(QStringLiteral("%1 spp, %2 s, estimated relmse %3")
                                 .arg(shown_->samplesPerPixel)
                                 .arg(shown_->seconds, 0, 'f', 1)
                                 .arg(shown_->estimatedRelmse, 0, 'g', 3));
}

}  // namespace lucerna
