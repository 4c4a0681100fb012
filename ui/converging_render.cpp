#include "ui/converging_render.h"

#include "render/progressive/backend.h"
#include "render/progressive/light_layers/layered_backend.h"
#include "render/trace/surface_layers.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <thread>

namespace lucerna {

namespace {
using Clock = std::chrono::steady_clock;

// Passes until cancelled, holding between passes while paused or while the gate is held. Render
// time excludes the held time, so the error plot is against time actually spent rendering.
// Frames carry the albedo under each pixel from the fifth pass on (traced once, after the first
// pictures are out), so that the lux view can divide by it (display.h, pixelIlluminance).
void runUntilCancelled(ProgressiveBackend& backend, const SceneSnapshot& scene, const std::string& name,
                       const RenderSettings& settings, TaskContext& ctx, Latest<RenderFrame>& latest,
                       const std::atomic<bool>& paused, const std::atomic<int>& gate) {
    double rendered = 0, lastPublish = -1;
    int passes = 0;
    std::optional<SurfaceLayers> surfaces;
    const auto publish = [&] {
        RenderFrame frame = makeRenderFrame(backend, name, settings, rendered, passes);
        if (passes >= 4 && !surfaces)
            surfaces = traceSurfaceLayers(RenderScene(scene, backend.film().width(), backend.film().height()));
        if (surfaces) addSurfaceLayers(frame.image, *surfaces, kAlbedoLayer);
        latest.publish(std::make_shared<const RenderFrame>(std::move(frame)));
        lastPublish = rendered;
    };
    while (!ctx.isCancelled()) {
        if (paused.load() || gate.load() > 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            continue;
        }
        const auto t0 = Clock::now();
        backend.renderPass(ctx, passes);
        if (ctx.isCancelled()) break;
        ++passes;
        rendered += std::chrono::duration<double>(Clock::now() - t0).count();
        // Frequent frames at first (the picture changes most), then every half second.
        if (passes <= 4 || rendered - lastPublish >= 0.5) publish();
    }
}
}  // namespace

ConvergingRender::ConvergingRender(TaskSystem& tasks, const YieldGate& gate, QObject* parent)
    : QObject(parent), tasks_(tasks), gate_(gate) {
    connect(&poll_, &QTimer::timeout, this, &ConvergingRender::poll);
    poll_.start(100);
}

ConvergingRender::~ConvergingRender() { stop(); }

void ConvergingRender::setScene(SceneSnapshot scene) {
    // With per-light layers, an edit of the lights' emission only is a new mix of the layers.
    if (lightLayers_ && isRunning() && rendered_ && scene) {
        if (auto weights = layerWeights(*rendered_, *scene)) {
            scene_ = std::move(scene);
            weights_ = std::move(*weights);
            if (frame_) {
                frame_ = mixed(*frame_);
                emit frameReady();
            }
            return;
        }
    }
    scene_ = std::move(scene);
    if (!isRunning()) return;
    // From now on frame() is only ever of the new scene: forget the old run's frames at once,
    // though its job ends a moment later (the panel keeps its last picture until a new one).
    frame_.reset();
    history_.clear();
    latest_ = std::make_shared<Latest<RenderFrame>>();
    shownVersion_ = 0;
    if (restartPending_) return;
    restartPending_ = true;
    QTimer::singleShot(0, this, [this] {
        restartPending_ = false;
        if (isRunning()) relaunch();
    });
}

void ConvergingRender::setBackend(const std::string& name) {
    if (name == choice_) return;
    choice_ = name;
    if (isRunning()) relaunch();
    emit stateChanged();
}

void ConvergingRender::setLightLayers(bool on) {
    if (on == lightLayers_) return;
    lightLayers_ = on;
    if (isRunning()) relaunch();
    emit stateChanged();
}

std::shared_ptr<const RenderFrame> ConvergingRender::mixed(const RenderFrame& frame) const {
    auto copy = std::make_shared<RenderFrame>(frame);
    mixLightLayers(copy->image, groups_, weights_);
    return copy;
}

void ConvergingRender::start() {
    if (isRunning()) {
        setPaused(false);
        return;
    }
    restart();
}

void ConvergingRender::setPaused(bool paused) {
    paused_->store(paused);
    emit stateChanged();
}

void ConvergingRender::stop() {
    if (job_) job_->cancel();
    job_.reset();  // the handle waits for the job: no frame of the old run arrives afterwards
    emit stateChanged();
}

void ConvergingRender::restart() {
    paused_->store(false);
    relaunch();
}

void ConvergingRender::relaunch() {
    if (job_) job_->cancel();
    job_.reset();
    frame_.reset();
    history_.clear();
    error_.clear();
    shownVersion_ = 0;
    if (!scene_) {
        emit stateChanged();
        return;
    }
    reason_.clear();
    inUse_ = choice_;
    if (choice_ == "auto") {
        const AutoChoice c = chooseAutoBackend(*scene_);
        inUse_ = c.backend;
        reason_ = c.reason;
    }
    const BackendInfo* info = findBackend(inUse_);
    if (!info) {
        error_ = tr("no backend named %1").arg(QString::fromStdString(inUse_));
        emit stateChanged();
        return;
    }
    latest_ = std::make_shared<Latest<RenderFrame>>();
    rendered_ = scene_;
    groups_ = lightGroups(*scene_);
    weights_.assign(groups_.size(), Rgb(1, 1, 1));
    RenderSettings settings;
    settings.seed = 1;
    job_ = tasks_.submit([scene = scene_, settings, name = inUse_, make = info->make, layered = lightLayers_,
                          latest = latest_, paused = paused_, gate = gate_.counter()](TaskContext& ctx) {
        auto backend = layered ? makeLayeredBackend(make, scene, settings) : make(scene, settings);
        backend->prepare(ctx);
        runUntilCancelled(*backend, scene, name, settings, ctx, *latest, *paused, *gate);
    });
    emit stateChanged();
}

void ConvergingRender::poll() {
    if (!job_ || !latest_) return;
    if (job_->isFinished()) {
        try {
            job_->rethrowIfFailed();
        } catch (const std::exception& e) {
            error_ = QString::fromStdString(e.what());
            job_.reset();
            emit stateChanged();
            return;
        }
    }
    if (latest_->version() == shownVersion_) return;
    shownVersion_ = latest_->version();
    frame_ = latest_->get();
    if (!frame_) return;
    if (lightLayers_ && std::any_of(weights_.begin(), weights_.end(), [](const Rgb& w) { return w != Rgb(1, 1, 1); }))
        frame_ = mixed(*frame_);
    if (std::isfinite(frame_->estimatedRelmse) && frame_->estimatedRelmse > 0)
        history_.emplace_back(frame_->seconds, frame_->estimatedRelmse);
    emit frameReady();
}

}  // namespace lucerna
