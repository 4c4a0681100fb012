#include "ui/rendering/live_preview.h"

#include "core/resources.h"
#include "render/engine/backend_table.h"
#include "render/preview/frame_accumulator.h"
#include "render/preview/preview.h"
#include "render/trace/rng.h"

#include <QByteArray>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <limits>
#include <optional>

namespace lucerna {

namespace {
using Clock = std::chrono::steady_clock;
using Milliseconds = std::chrono::milliseconds;

// What the job hands the window: a frame, or why there is none.
struct Outcome {
    std::shared_ptr<const LiveFrame> frame;  // null when the frame failed
    std::string error;
    uint64_t request = 0;   // the request it answers (dropFrame() hides earlier ones)
    uint64_t sequence = 0;  // unique per outcome, so that the window takes each once
};

// Accumulation starts only after this long without a new snapshot: key repeats and wheel steps
// come closer together than this, and an idle frame started between two of them would delay the
// second by a whole frame. (Drags hold the yield gate, which stops accumulation by itself.)
constexpr Milliseconds kSettle(100);
// How long the job sleeps waiting for a snapshot when it has nothing else to do.
constexpr Milliseconds kPoll(50);

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

QString previewStatusText(const QString& engine, const LiveFrame& frame) {
    const QString frames = frame.frames == 1 ? LivePreview::tr("1 frame") : LivePreview::tr("%1 frames").arg(frame.frames);
    QString text = LivePreview::tr("Preview: %1, %2, %3 ms").arg(engine, frames).arg(frame.milliseconds, 0, 'f', 0);
    if (frame.coarse) text += LivePreview::tr("; a coarse first frame, the full one follows");
    else if (!frame.degradation.empty()) text += "; " + QString::fromStdString(frame.degradation);
    return text;
}

struct LivePreview::Shared {
    std::mutex mutex;
    std::condition_variable wake;
    SceneSnapshot requested;
    uint64_t requestedSerial = 0;
    bool albedoLayer = false;
    std::string engine;  // set by the job
    Latest<Outcome> out;
};

// The background job: answers each new snapshot with one plain frame while holding the gate
// (when the last answer took under a second), then, idle, refines the OpenGL preview's frame with accumulated ones.
//
// Why accumulation frames leave the yield gate alone: the gate exists so that an edit is
// answered before anything else runs. Once answered, the converging render is what the user is
// waiting for, and holding the gate through 64 frames (seconds on llvmpipe) would stall it after
// every edit; so idle frames share the cores with it, and they begin only while nobody holds the
// gate (a drag in progress, a calculation grid) and stop at kMaxFrames.
//
// Why kMaxFrames = 64: measured on the Cornell box at the window's 256 x 256 on llvmpipe, the
// relmse against an independent 128-frame mean is 0.021 for one frame, 0.0032 for 4, 0.0018 for
// 16 (the blotches gone to the eye: about 1 s alone, 1.3 to 2.7 s in the window beside the
// converging render) and 0.00046 for 64; and the 64-frame mean is at 0.0009 against the
// path-traced reference (BENCHMARKS.md, "Interactive preview (issue 5)"), so about half of what
// is left there is the preview's own bias (clamped VPLs), which no number of frames removes. At
// about 60 ms a frame, 64 frames are some 4 s of the cores (5 to 10 s in the window, where they
// halve the converging render's samples per second meanwhile); more would take the cores from it
// for a change below a display step.
class LivePreview::Job {
public:
    Job(std::shared_ptr<Shared> shared, std::shared_ptr<std::atomic<int>> gate, Engine engine, int longSide)
        : shared_(std::move(shared)), gate_(std::move(gate)), engine_(engine), longSide_(longSide),
          engineName_(engine == Engine::Path ? "path tracer (chosen)" : "") {}

    void run(TaskContext& ctx) {
        while (!ctx.isCancelled()) {
            if (auto request = take(wait())) {
                answer(*request, ctx);
            } else if (idleFrameDue()) {
                accumulate(ctx);
            }
        }
    }

private:
    struct Request {
        SceneSnapshot scene;
        bool albedoLayer = false;
        uint64_t serial = 0;
    };

    static constexpr double kGateBudgetMs = 1000;
    double lastAnswerMs_ = std::numeric_limits<double>::infinity();

    bool accumulating() const { return accumulating_ && sum_.count() < kMaxFrames; }
    bool idleFrameDue() const { return accumulating() && Clock::now() >= settledAt_ && gate_->load() == 0; }

    // No wait when an idle frame is due; until the settle time when one is coming.
    Clock::duration wait() const {
        if (idleFrameDue()) return Clock::duration::zero();
        if (accumulating() && gate_->load() == 0)
            return std::clamp<Clock::duration>(settledAt_ - Clock::now(), Clock::duration::zero(), kPoll);
        return kPoll;
    }

    std::optional<Request> take(Clock::duration wait) {
        std::unique_lock lock(shared_->mutex);
        shared_->wake.wait_for(lock, wait, [&] { return shared_->requestedSerial != done_; });
        if (shared_->requestedSerial == done_) return std::nullopt;
        done_ = shared_->requestedSerial;
        return Request{shared_->requested, shared_->albedoLayer, done_};
    }

    // The plain frame that answers a request: no regeneration beyond what Preview::update
    // decides, the pixel centre; it starts the accumulation over.
    void answer(const Request& request, TaskContext& ctx) {
        accumulating_ = false;
        if (!request.scene) return;
        // The gate only for a preview that answers within a second: one that takes longer (a
        // floor of 10,000 lights on a software rasteriser: minutes) would stop the converging
        // render that long after every edit, so it shares the cores instead. Unknown before the
        // first answer, which comes at load, not after an edit.
        std::optional<YieldGate::Scope> hold;
        if (lastAnswerMs_ < kGateBudgetMs) hold.emplace(gate_);
        const auto t0 = Clock::now();
        Image image;
        try {
            image = draw(request, ctx);
        } catch (const std::exception& e) {
            return fail(e.what(), request.serial);
        }
        const double ms = millisecondsSince(t0);
        lastAnswerMs_ = ms;
        current_ = request;
        sum_.restart(image.width, image.height);
        sum_.add(image);
        totalMilliseconds_ = ms;
        // The path tracer is not accumulated: the converging render beside it is the same
        // estimator, converging already.
        accumulating_ = gl_ != nullptr;
        settledAt_ = Clock::now() + kSettle;
        publish(std::move(image), ms, ctx);
    }

    // One more idle frame, at the next point in the pixel: fresh VPLs and area-light samples, or
    // the same ones dealt anew to the sub-buffers (no shadow map drawn). A fresh set removes the
    // VPLs' own error, a new deal only the interleaving pattern: every frame is fresh while a
    // fresh set's shadow maps draw under kCheapShadowTriangles (the Cornell box: 50 thousand, a
    // 135-light office: 2.5 million, 0.3 s a frame on llvmpipe; decided from the scene, not the
    // clock, so that the result is the same on a loaded machine); past it (a hall of 7,500
    // triangles: 12 million, 1 s against 0.14 s a deal) most frames are deals, one fresh set
    // every `cost ratio` frames, at most 8.
    void accumulate(TaskContext& ctx) {
        constexpr double kCheapShadowTriangles = 3e6;
        const auto t0 = Clock::now();
        const bool fresh = gl_->freshSetShadowTriangles() < kCheapShadowTriangles ||
                           framesSinceFresh_ + 1 >= std::clamp(int(std::lround(freshMs_ / std::max(dealMs_, 1.0))), 1, 8);
        Image image;
        try {
            image = drawJitteredFrame(*gl_, hashSeed(0x11fe9ULL, ++regenerations_), sequenceJitter(sum_.count()),
                                      fresh ? FrameRenewal::FreshSet : FrameRenewal::NewDeal);
        } catch (const std::exception& e) {
            return fail(e.what(), current_.serial);
        }
        sum_.add(image);
        const double ms = millisecondsSince(t0);
        (fresh ? freshMs_ : dealMs_) = ms;
        framesSinceFresh_ = fresh ? 0 : framesSinceFresh_ + 1;
        totalMilliseconds_ += ms;
        publish(sum_.mean(), ms, ctx);
    }

    Image draw(const Request& request, TaskContext& ctx) {
        int w = 0, h = 0;
        previewSize(request.scene->camera, longSide_, w, h);
        if (!gl_ && engine_ != Engine::Path && !glFailed_) startOpenGl();
        if (!gl_) return pathFrame(request.scene, w, h, ctx);
        gl_->setAlbedoLayer(request.albedoLayer);
        if (!rebuild_) {
            gl_->update(request.scene, w, h);  // the preview redraws what changed
            return gl_->render();
        }
        rebuild_ = false;
        const PreviewSettings full = gl_->settings();
        const auto t0 = Clock::now();
        gl_->setSettings(coarseSettings(full));
        gl_->setScene(request.scene, w, h);
        publishCoarse(gl_->render(), millisecondsSince(t0), request, ctx);
        gl_->setSettings(full);  // new VPLs and shadow maps at the preview's own settings
        return gl_->render();
    }

    // A scene's first frame comes first at these settings (issue 40): the office floor's first
    // frame took 9 s in the window on llvmpipe, nearly all of it the cube shadow maps of 108
    // lights at 128 px a face and of 256 VPLs, drawn while the converging render took half the
    // cores. Its light is unbiased but blotchy (32 VPLs) and its shadows soft (32 px maps); the
    // frame at the full settings replaces it as soon as it is drawn.
    static PreviewSettings coarseSettings(PreviewSettings s) {
        s.vplCount = std::min(s.vplCount, 32);
        s.shadowSize = std::min(s.shadowSize, 32);
        s.vplShadowSize = std::min(s.vplShadowSize, 16);
        s.skySamples = std::min(s.skySamples, 16);
        s.skyShadowSize = std::min(s.skyShadowSize, 128);
        return s;
    }

    // Accumulation starts from the full frame.
    void publishCoarse(Image image, double milliseconds, const Request& request, TaskContext& ctx) {
        current_ = request;
        sum_.restart(image.width, image.height);
        sum_.add(image);
        totalMilliseconds_ = milliseconds;
        publish(std::move(image), milliseconds, ctx, true);
    }

    // Auto falls back to the path tracer for good; OpenGL alone fails every request with the
    // same reason (the machine will not grow an OpenGL 4.5 context).
    void startOpenGl() {
        if (!glStartError_.empty()) throw std::runtime_error(glStartError_);
        try {
            gl_ = std::make_unique<Preview>(resourceDirectory() + "/shaders/preview");
            engineName_ = "OpenGL VPL preview (" + gl_->context().renderer() + ")";
        } catch (const std::exception& e) {
            if (engine_ == Engine::OpenGL) {
                glStartError_ = std::string("the OpenGL preview cannot start: ") + e.what();
                engineName_ = "OpenGL VPL preview (not started)";
                throw std::runtime_error(glStartError_);
            }
            glFailed_ = true;
            engineName_ = std::string("path tracer (no OpenGL preview: ") + e.what() + ")";
        }
    }

    void publish(Image image, double milliseconds, TaskContext& ctx, bool coarse = false) {
        auto frame = std::make_shared<LiveFrame>();
        frame->coarse = coarse;
        frame->image = std::move(image);
        frame->scene = current_.scene;
        frame->frames = sum_.count();
        frame->milliseconds = milliseconds;
        frame->totalMilliseconds = totalMilliseconds_;
        if (gl_) frame->degradation = gl_->degradation();
        setEngine();
        if (!ctx.isCancelled())
            shared_->out.publish(std::make_shared<Outcome>(Outcome{std::move(frame), {}, current_.serial, ++sequence_}));
    }

    // A frame that failed leaves the OpenGL preview in a state nobody knows (a GL error still
    // pending, targets half made): the next request starts a new one, on a scene of its own.
    void fail(const std::string& what, uint64_t request) {
        accumulating_ = false;
        gl_.reset();
        rebuild_ = true;
        setEngine();
        shared_->out.publish(std::make_shared<Outcome>(Outcome{nullptr, what, request, ++sequence_}));
    }

    void setEngine() {
        std::lock_guard lock(shared_->mutex);
        shared_->engine = engineName_;
    }

    static double millisecondsSince(Clock::time_point t0) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    }

    std::shared_ptr<Shared> shared_;
    std::shared_ptr<std::atomic<int>> gate_;
    Engine engine_;
    int longSide_;
    std::unique_ptr<Preview> gl_;
    bool glFailed_ = false;     // Auto fell back to the path tracer
    std::string glStartError_;  // OpenGL alone could not start
    std::string engineName_;
    bool rebuild_ = true;       // the first scene, or after a failed frame: everything anew
    uint64_t done_ = 0;         // the newest request taken
    uint64_t sequence_ = 0;
    // Every regeneration gets a seed of its own, so that no two frames of a mean share a VPL set
    // (the plain frame after a camera move keeps the last idle frame's).
    uint64_t regenerations_ = 0;
    // The last idle frame's cost with a fresh VPL set and with a new deal (ms; 0: not yet
    // measured, so the first idle frame is fresh).
    double freshMs_ = 0, dealMs_ = 0;
    int framesSinceFresh_ = 0;

    Request current_;  // the request the frames shown are of
    bool accumulating_ = false;
    FrameAccumulator sum_;  // the frames shown, of current_'s scene
    double totalMilliseconds_ = 0;
    Clock::time_point settledAt_;
};

LivePreview::LivePreview(const YieldGate& gate, Engine engine, int longSide, QObject* parent)
    : QObject(parent), shared_(std::make_shared<Shared>()), gate_(gate.counter()) {
    // The job, and the OpenGL context in it, live and die on the job's thread.
    job_ = tasks_.submit([shared = shared_, gate = gate.counter(), engine, longSide](TaskContext& ctx) {
        Job(shared, gate, engine, longSide).run(ctx);
    });
    connect(&poll_, &QTimer::timeout, this, &LivePreview::poll);
    poll_.start(15);
}

LivePreview::~LivePreview() {
    job_->cancel();
    shared_->wake.notify_all();
    job_.reset();
}

LivePreview::Engine LivePreview::engineFromEnvironment() {
    const QByteArray choice = qgetenv("LUCERNA_PREVIEW").toLower();
    if (choice == "opengl") return Engine::OpenGL;
    if (choice == "path") return Engine::Path;
    return Engine::Auto;
}

void LivePreview::setScene(SceneSnapshot scene) {
    if (!answered_ && !firstHold_) firstHold_ = std::make_unique<YieldGate::Scope>(gate_);
    {
        std::lock_guard lock(shared_->mutex);
        shared_->requested = std::move(scene);
        ++shared_->requestedSerial;
    }
    shared_->wake.notify_all();
}

void LivePreview::dropFrame() {
    {
        std::lock_guard lock(shared_->mutex);
        firstShownRequest_ = shared_->requestedSerial + 1;
    }
    frame_.reset();
    error_.clear();
    emit frameReady();
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
    const auto outcome = shared_->out.get();
    if (!outcome || outcome->sequence == shownSequence_) return;
    shownSequence_ = outcome->sequence;
    answered_ = true;
    firstHold_.reset();
    if (outcome->request < firstShownRequest_) return;  // of a scene dropped since
    frame_ = outcome->frame;
    error_ = QString::fromStdString(outcome->error);
    if (frame_) ++frames_;
    emit frameReady();
}

}  // namespace lucerna
