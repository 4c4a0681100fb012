#include "ui/live_preview.h"

#include "core/resources.h"
#include "render/engine/backend_table.h"
#include "render/preview/preview.h"

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace lucerna {

struct LivePreview::Shared {
    std::mutex mutex;
    std::condition_variable wake;
    SceneSnapshot requested;
    uint64_t requestedSerial = 0;
    bool albedoLayer = false;
    std::string engine;  // set by the job
    Latest<LiveFrame> out;
};

namespace {
using Clock = std::chrono::steady_clock;

void previewSize(const Camera& c, int longSide, int& w, int& h) {
    const double s = std::min(1.0, double(longSide) / std::max(c.width, c.height));
    w = std::max(1, int(std::lround(c.width * s)));
    h = std::max(1, int(std::lround(c.height * s)));
}

// The fallback: a few passes of the path tracer at the preview's resolution.
Image pathFrame(const SceneSnapshot& scene, int w, int h, TaskContext& ctx) {
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.seed = 7;
    auto backend = findBackend("path")->make(scene, settings);
    backend->prepare(ctx);
    for (int pass = 0; pass < 2 && !ctx.isCancelled(); ++pass) backend->renderPass(ctx, pass);
    return backend->film().image();
}
}  // namespace

LivePreview::LivePreview(const YieldGate& gate, Engine engine, int longSide, QObject* parent)
    : QObject(parent), shared_(std::make_shared<Shared>()) {
    job_ = tasks_.submit([shared = shared_, gateCounter = gate.counter(), engine, longSide](TaskContext& ctx) {
        std::unique_ptr<Preview> gl;
        bool glFailed = engine == Engine::Path;
        std::string engineName = glFailed ? "path tracer (chosen)" : "";
        bool rebuild = true;  // the first scene, or after a failed frame: everything anew
        uint64_t done = 0;
        while (!ctx.isCancelled()) {
            SceneSnapshot scene;
            bool albedoLayer = false;
            {
                std::unique_lock lock(shared->mutex);
                shared->wake.wait_for(lock, std::chrono::milliseconds(50),
                                      [&] { return shared->requestedSerial != done; });
                if (shared->requestedSerial == done) continue;
                done = shared->requestedSerial;
                scene = shared->requested;
                albedoLayer = shared->albedoLayer;
            }
            if (!scene) continue;
            YieldGate::Scope hold(gateCounter);
            const auto t0 = Clock::now();
            int w = 0, h = 0;
            previewSize(scene->camera, longSide, w, h);
            if (!gl && !glFailed) {
                try {
                    gl = std::make_unique<Preview>(resourceDirectory() + "/shaders/preview");
                    engineName = "OpenGL VPL preview (" + gl->context().renderer() + ")";
                } catch (const std::exception& e) {
                    glFailed = true;
                    engineName = std::string("path tracer (no OpenGL preview: ") + e.what() + ")";
                }
            }
            auto frame = std::make_shared<LiveFrame>();
            frame->scene = scene;
            try {
                if (gl) {
                    if (rebuild) gl->setScene(scene, w, h);
                    else gl->update(scene, w, h);  // the preview redraws what changed
                    rebuild = false;
                    gl->setAlbedoLayer(albedoLayer);
                    frame->image = gl->render();
                } else {
                    frame->image = pathFrame(scene, w, h, ctx);
                }
            } catch (const std::exception& e) {
                // A frame that fails (a driver error) leaves the old one up; the next edit retries.
                rebuild = true;
                std::lock_guard lock(shared->mutex);
                shared->engine = engineName + "; last frame failed: " + e.what();
                continue;
            }
            frame->milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            {
                std::lock_guard lock(shared->mutex);
                shared->engine = engineName;
            }
            if (!ctx.isCancelled()) shared->out.publish(std::move(frame));
        }
    });
    connect(&poll_, &QTimer::timeout, this, &LivePreview::poll);
    poll_.start(15);
}

LivePreview::~LivePreview() {
    job_->cancel();
    shared_->wake.notify_all();
    job_.reset();
}

void LivePreview::setScene(SceneSnapshot scene) {
    {
        std::lock_guard lock(shared_->mutex);
        shared_->requested = std::move(scene);
        ++shared_->requestedSerial;
    }
    shared_->wake.notify_all();
}

void LivePreview::setAlbedoLayer(bool on) {
    {
        std::lock_guard lock(shared_->mutex);
        if (shared_->albedoLayer == on) return;
        shared_->albedoLayer = on;
        ++shared_->requestedSerial;  // the same scene again, with or without the layer
    }
    shared_->wake.notify_all();
}

QString LivePreview::engineDescription() const {
    std::lock_guard lock(shared_->mutex);
    return QString::fromStdString(shared_->engine);
}

void LivePreview::poll() {
    if (shared_->out.version() == shownVersion_) return;
    shownVersion_ = shared_->out.version();
    frame_ = shared_->out.get();
    ++frames_;
    emit frameReady();
}

}  // namespace lucerna
