#pragma once
// The viewport: the live preview's newest frame, the lights drawn over it, and mouse navigation.
// Left drag on a light moves it in the image plane at its depth; left drag elsewhere orbits the
// camera about its target; right or middle drag pans; the wheel zooms. Each drag is one undo
// command (its steps merge), and while a button is down the converging render yields.

#include "core/document.h"
#include "ui/image_view.h"
#include "ui/yield_gate.h"

#include <memory>
#include <optional>

namespace lucerna {

// A key that no earlier interaction used, so that the steps of one drag merge with each other
// and with nothing else (undo commands' mergeKey).
int nextMergeKey();

class Viewport : public ImageView {
    Q_OBJECT
public:
    Viewport(Document* doc, const YieldGate& gate, QWidget* parent = nullptr);

    void setSelectedLight(int index);
    // Widget position of a light's marker (nothing for directional lights or off-screen ones).
    std::optional<QPointF> lightMarker(int index) const;

signals:
    void lightClicked(int index);

protected:
    void paintOverlay(QPainter& painter) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, MoveLight };
    int lightAt(const QPointF& pos) const;
    void endDrag();

    Document* doc_;
    YieldGate gate_;
    int selected_ = -1;
    Drag drag_ = Drag::None;
    int dragLight_ = -1;
    int mergeKey_ = 0;
    int wheelKey_ = nextMergeKey();  // renewed by each press, so a run of wheel steps is one command
    QPointF last_;
    std::unique_ptr<YieldGate::Scope> hold_;
};

}  // namespace lucerna
