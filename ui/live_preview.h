#pragma once
// The viewport's live image: one long-lived background job that draws a frame of the newest
// scene snapshot it was given, dropping the snapshots it had no time for. It draws with the
// OpenGL VPL preview (render/preview, through EGL, offscreen into an image) when a context can
// be made, and otherwise with a few passes of the path tracer at reduced resolution, so the
// viewport works on any machine. While it draws it holds the yield gate: the converging render
// waits, the preview comes first on the cores.

#include "core/image.h"
#include "core/scene.h"
#include "core/task_system.h"
#include "ui/yield_gate.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace lucerna {

struct LiveFrame {
    Image image;          // linear radiance at the preview's resolution
    SceneSnapshot scene;  // the snapshot it shows
    double milliseconds = 0;
};

class LivePreview : public QObject {
    Q_OBJECT
public:
    enum class Engine { Auto, Path };  // Auto: OpenGL when available, else the path tracer
    // longSide: the preview resolution's longer side in pixels (the camera's aspect is kept).
    // The preview has a task system of its own: its job lives as long as the viewport and mostly
    // waits for the next snapshot, and in the converging render's arena it would sit on a slot
    // that the render's parallel loops need.
    explicit LivePreview(const YieldGate& gate, Engine engine = Engine::Auto, int longSide = 400,
                         QObject* parent = nullptr);
    ~LivePreview() override;

    // Asks for a frame of this snapshot (the newest request wins).
    void setScene(SceneSnapshot scene);
    std::shared_ptr<const LiveFrame> frame() const { return frame_; }
    // What draws the frames, in words ("OpenGL VPL preview (llvmpipe ...)", or the path tracer
    // and why the OpenGL one is not used). Known after the first frame.
    QString engineDescription() const;
    // Frames with the albedo layer (the lux view needs it; it costs read-back time); redraws.
    void setAlbedoLayer(bool on);
    // Frames drawn so far.
    int frameCount() const { return frames_; }

signals:
    void frameReady();

private:
    void poll();

    struct Shared;
    std::shared_ptr<Shared> shared_;
    TaskSystem tasks_;  // before job_: the job is joined before its arena goes
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<const LiveFrame> frame_;
    uint64_t shownVersion_ = 0;
    int frames_ = 0;
    QTimer poll_;
};

}  // namespace lucerna
