#pragma once
// The viewport's live image: one long-lived background job that draws a frame of the newest
// scene snapshot it was given, dropping the snapshots it had no time for. It draws with the
// OpenGL VPL preview (render/preview, through EGL, offscreen into an image) when a context can
// be made, and otherwise with a few passes of the path tracer at reduced resolution, so the
// viewport works on any machine. While it draws the frame that answers an edit it holds the
// yield gate: the converging render waits, the preview comes first on the cores; a preview
// whose last answer took over a second does not (it would stall the converging render).
//
// Idle, the OpenGL preview converges: with nothing new to draw it keeps drawing frames with
// fresh VPLs and the pixel sample jittered, and shows their running mean, so the interleaving's
// blotches fade; any new snapshot starts again from a single frame. See live_preview.cpp for
// why these frames leave the gate alone and stop at kMaxFrames.

#include "core/image/image.h"
#include "core/scene/scene.h"
#include "core/task_system.h"
#include "ui/rendering/yield_gate.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <string>

namespace lucerna {

struct LiveFrame {
    Image image;          // linear radiance at the preview's resolution: the mean of `frames`
    SceneSnapshot scene;  // the snapshot it shows
    int frames = 1;       // frames averaged: 1 for the answer to an edit, more while idle
    double milliseconds = 0;       // the newest frame's drawing time
    double totalMilliseconds = 0;  // all `frames` frames together
    // What the preview gave up to stay within the GPU's limits (Preview::degradation()); empty
    // when nothing, and always for the path tracer.
    std::string degradation;
    // A quick first answer to a new scene (fewer VPLs, smaller shadow maps, lower resolution),
    // shown while the frame at the preview's own settings draws.
    bool coarse = false;
};

// "Preview: ENGINE, N frames, M ms" (and "; DEGRADATION" when the preview gave something up),
// for the status bar.
QString previewStatusText(const QString& engine, const LiveFrame& frame);

class LivePreview : public QObject {
    Q_OBJECT
public:
    // Auto: OpenGL when available, else the path tracer. OpenGL: no fallback, a failure to start
    // is the preview's error (to see why it would fall back). Path: the path tracer.
    enum class Engine { Auto, OpenGL, Path };
    // Frames averaged at most while idle (live_preview.cpp says why 64).
    static constexpr int kMaxFrames = 64;

    // longSide: the preview resolution's longer side in pixels (the camera's aspect is kept).
    // The preview has a task system of its own: its job lives as long as the viewport and mostly
    // waits for the next snapshot, and in the converging render's arena it would sit on a slot
    // that the render's parallel loops need.
    explicit LivePreview(const YieldGate& gate, Engine engine = Engine::Auto, int longSide = 400,
                         QObject* parent = nullptr);
    ~LivePreview() override;

    // $LUCERNA_PREVIEW: "opengl" or "path" choose that engine; anything else, or unset, Auto.
    static Engine engineFromEnvironment();

    // Asks for a frame of this snapshot (the newest request wins).
    void setScene(SceneSnapshot scene);
    // The scene is being replaced by another (a file opened): the frame goes at once (frameReady
    // with no frame), and frames still under way for the old scene are never shown.
    void dropFrame();
    // The newest frame; null before the first one, after dropFrame() and after a failure.
    std::shared_ptr<const LiveFrame> frame() const { return frame_; }
    // Why the newest frame failed, in one line; empty while frames succeed.
    QString error() const { return error_; }
    // What draws the frames, in words ("OpenGL VPL preview (llvmpipe ...)", or the path tracer
    // and why the OpenGL one is not used). Known after the first frame.
    QString engineDescription() const;
    // Frames with the albedo layer (the lux view needs it; it costs read-back time); redraws.
    void setAlbedoLayer(bool on);
    // Frames shown so far, each accumulation step counted.
    int frameCount() const { return frames_; }

signals:
    // The frame changed: a new one, none (dropped), or a failure (error()).
    void frameReady();

private:
    void poll();

    struct Shared;
    class Job;
    std::shared_ptr<Shared> shared_;
    TaskSystem tasks_;  // before job_: the job is joined before its arena goes
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<const LiveFrame> frame_;
    QString error_;
    uint64_t shownSequence_ = 0;
    uint64_t firstShownRequest_ = 0;  // outcomes of earlier requests are of a dropped scene
    // The window's first picture comes before the converging render takes the cores: the gate
    // is held from the first scene until the job's first answer (a coarse frame: issue 40).
    std::shared_ptr<std::atomic<int>> gate_;
    std::unique_ptr<YieldGate::Scope> firstHold_;
    bool answered_ = false;
    int frames_ = 0;
    QTimer poll_;
};

}  // namespace lucerna
