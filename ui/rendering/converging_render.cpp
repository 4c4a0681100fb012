#include "ui/rendering/converging_render.h"

#include "render/backend/light_layers/layered_backend.h"
#include "render/engine/backend_table.h"
#include "render/engine/measured_auto/measured_auto_settings.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace lucerna {

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
    if (choice_ == "auto" && lightLayers_) {
        // One render per light group: auto's pilots for every layer would cost more than they
        // find, so the rule auto was picks (README, "Per-light layers").
        const AutoChoice rule = chooseAutoBackend(*scene_);
        inUse_ = rule.backend;
        reason_ = "per-light layers, by its rule: " + rule.reason;
    } else if (choice_ == "auto") {
        std::string candidates;
        for (const std::string& name : autoCandidates(*scene_)) candidates += (candidates.empty() ? "" : ", ") + name;
        reason_ = "measuring " + candidates + " in short pilots";
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
    settings.firstFrameSoon = true;
    job_ = tasks_.submit([scene = scene_, settings, name = inUse_, make = info->make, layered = lightLayers_,
                          latest = latest_, paused = paused_, gate = gate_.counter()](TaskContext& ctx) {
        PassLoopOptions loop;
        loop.openEnded = true;
        loop.eagerPasses = 4;
        loop.hold = [&paused = *paused, &gate = *gate] { return paused.load() || gate.load() > 0; };
        // The preview's answer first (the gate: a scene's first, coarse frame; an edit's frame),
        // but never more than a few seconds: preparing (auto's replicas, VPL sets, chains' seeds)
        // takes the cores as passes do.
        const auto waitUntil = std::chrono::steady_clock::now() + std::chrono::seconds(3);
        while (gate->load() > 0 && std::chrono::steady_clock::now() < waitUntil && !ctx.isCancelled())
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        auto backend = layered ? makeLayeredBackend(make, scene, settings) : make(scene, settings);
        backend->prepare(ctx);
        loop.albedoScene = scene;
        runPasses(*backend, name, settings, ctx, latest.get(), loop);
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
