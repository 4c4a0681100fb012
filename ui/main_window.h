#pragma once
// The application window. For now: the scene's converging physically based render, with its
// progress in the status bar.

#include "core/task_system.h"
#include "render/progressive/progressive_render.h"

#include <QLabel>
#include <QMainWindow>
#include <QTimer>

#include <memory>
#include <string>

namespace lucerna {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(const std::string& scenePath, QWidget* parent = nullptr);
    ~MainWindow() override;

    // The newest frame shown so far (null before the first).
    std::shared_ptr<const RenderFrame> shownFrame() const { return shown_; }

private:
    void openScene(const std::string& path);
    void showNewestFrame();

    QLabel* view_ = nullptr;
    QTimer refresh_;
    TaskSystem tasks_;
    Latest<RenderFrame> frames_;
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<const RenderFrame> shown_;
    uint64_t shownVersion_ = 0;
};

}  // namespace lucerna
