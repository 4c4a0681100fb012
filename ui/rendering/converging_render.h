#pragma once
// The converging physically based render behind the render panel: one background job per scene
// snapshot and backend, which runs passes of a progressive backend, publishes frames and keeps
// the history of the estimated error against time. A new snapshot restarts it at once; a pause
// (the user's, or the yield gate while the preview has the cores) holds it between passes
// without losing what it has, and paused time does not count as render time.

#include "core/scene/scene.h"
#include "core/task_system.h"
#include "render/backend/light_layers/light_groups.h"
#include "render/backend/pass_loop.h"
#include "ui/rendering/yield_gate.h"

#include <QObject>
#include <QPointF>
#include <QTimer>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace lucerna {

class ConvergingRender : public QObject {
    Q_OBJECT
public:
    ConvergingRender(TaskSystem& tasks, const YieldGate& gate, QObject* parent = nullptr);
    ~ConvergingRender() override;

    // Takes the scene to render; restarts the render when it is running (once per turn of the
    // event loop, so a burst of edits costs one restart), keeping a user's pause.
    void setScene(SceneSnapshot scene);
    // "auto" or a name from backendTable(); restarts when running.
    void setBackend(const std::string& name);
    const std::string& backendChoice() const { return choice_; }
    // The backend in use and, for auto, what it is measuring (empty otherwise; once frames come,
    // their lucerna:auto_* attributes say which methods carry the image).
    const std::string& backendInUse() const { return inUse_; }
    const std::string& autoReason() const { return reason_; }

    // Per-light layers (render/backend/light_layers): the backend renders one layer per
    // light, and an edit that changes only the lights' emission (dimming, switching off,
    // recolouring) re-mixes the layers at once instead of restarting. Restarts when running.
    void setLightLayers(bool on);
    bool lightLayers() const { return lightLayers_; }

    void start();    // starts (or resumes when paused)
    void setPaused(bool paused);
    void restart();  // discards the film and starts over, unpaused
    void stop();
    bool isRunning() const { return job_ != nullptr; }
    bool isPaused() const { return paused_->load(); }

    // The newest frame shown (null before the first of this run).
    std::shared_ptr<const RenderFrame> frame() const { return frame_; }
    // (seconds, estimated relmse) of every frame of this run.
    const std::vector<QPointF>& history() const { return history_; }
    // The scene of the current run (with per-light layers, the newest emission mixed into it).
    SceneSnapshot scene() const { return scene_; }
    QString error() const { return error_; }

signals:
    void frameReady();
    void stateChanged();

private:
    void poll();
    void relaunch();  // a new job for the current scene and backend; the pause state stays
    std::shared_ptr<const RenderFrame> mixed(const RenderFrame& frame) const;  // layers weighted

    bool restartPending_ = false;
    TaskSystem& tasks_;
    YieldGate gate_;
    SceneSnapshot scene_;
    bool lightLayers_ = false;
    SceneSnapshot rendered_;           // the scene the job renders (scene_ may differ in emission)
    std::vector<LightGroup> groups_;   // its light groups, and each one's weight in the mix
    std::vector<Rgb> weights_;
    std::string choice_ = "auto", inUse_, reason_;
    std::shared_ptr<std::atomic<bool>> paused_ = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<Latest<RenderFrame>> latest_;
    std::shared_ptr<TaskHandle> job_;
    uint64_t shownVersion_ = 0;
    std::shared_ptr<const RenderFrame> frame_;
    std::vector<QPointF> history_;
    QString error_;
    QTimer poll_;
};

}  // namespace lucerna
