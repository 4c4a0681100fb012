#pragma once
// The plan's Draw Task Area tool (README, "Task areas"): with its button on, two corners clicked
// in the plan (or one drag from corner to corner), snapped like a moved light, give a task area's
// rectangle; the plan view then announces it (PlanView::taskAreaDrawn) and the window opens the
// task area dialog on it at the work plane's height. Escape, or the button again, cancels. With
// the tool off, a click (no drag) on a task area that no light symbol covers selects it
// (PlanView::taskAreaClicked). An event filter on the view installed after the plan's own
// (ui/plan/plan_interaction.h), so it sees the mouse first and takes only what is its own.

#include <QObject>
#include <QPointF>
#include <QRectF>

#include <optional>

class QEvent;
class QMouseEvent;
class QPainter;
class QToolButton;

namespace lucerna {

class Document;
class PlanView;

class TaskAreaDrawing : public QObject {
public:
    // Filters `view`'s events from now on; a child of it. Its button is a child of the view.
    TaskAreaDrawing(PlanView* view, Document* doc);

    QToolButton* button() const { return button_; }
    // The tool works in the plan only: off and disabled in the elevations.
    void projectionChanged();
    // The rectangle being drawn, plan coordinates (x, z); nothing while none is.
    std::optional<QRectF> rectangleBeingDrawn() const;
    // Draws the rectangle being drawn with its size in metres.
    void paint(QPainter& painter) const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class State { Off, Armed, Dragging, SecondCorner };

    bool press(const QMouseEvent& event);
    bool move(const QMouseEvent& event);
    bool release(const QMouseEvent& event);
    void finish();
    void cancel();
    // The plan point under a widget point, on the snap grid when the plan snaps.
    QPointF snapped(const QPointF& widget) const;

    PlanView* view_;
    Document* doc_;
    QToolButton* button_;
    State state_ = State::Off;
    QPointF first_, second_;   // plan coordinates of the corners
    QPointF pressedAt_;        // widget position of the last left press
    bool pressed_ = false;     // a left press not yet released (any state)
};

}  // namespace lucerna
