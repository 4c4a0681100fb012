#pragma once
// The plan's Draw Room tool (README, "Rooms"): with its button on, a drag from corner to corner
// draws a rectangular room; clicks instead place the corners of a polygon one by one, closed by
// a click on the first corner, a double click (its corner the last), or Enter. Corners snap like
// a moved light; Backspace takes the last corner back, Escape cancels. The outline drawn is
// announced (outlineDrawn) and the window opens the room dialog on it for its height, floor level
// and reflectances. With the tool off it draws the scene's rooms in the plan: each outline
// dashed, with its name and floor area. An event filter on the view installed after the plan's
// own (ui/plan/plan_interaction.h), so it sees the mouse first and takes only what is its own.

#include "core/scene/plan_polygon.h"

#include <QObject>
#include <QPointF>

#include <optional>
#include <vector>

class QEvent;
class QKeyEvent;
class QMouseEvent;
class QPainter;
class QToolButton;
class QColor;

namespace lucerna {

class Document;
struct Room;
class PlanView;

class RoomDrawing : public QObject {
    Q_OBJECT
public:
    // Filters `view`'s events from now on; a child of it. Its button is a child of the view.
    RoomDrawing(PlanView* view, Document* doc);

    QToolButton* button() const { return button_; }
    // The tool works in the plan only: off and disabled in the elevations.
    void projectionChanged();
    // The corners placed so far, plan coordinates (x, z); the rectangle's four while dragging.
    std::vector<QPointF> cornersBeingDrawn() const;
    // The scene's drawn rooms in the plan: each outline dashed, its name and floor area.
    void paintRooms(QPainter& painter) const;
    // The outline being drawn, with the wall to the mouse.
    void paint(QPainter& painter) const;
    // The colour a window's glazing is drawn in (for tests reading pixels back).
    static QColor openingColour();

signals:
    // A closed outline (scene units, as drawn).
    void outlineDrawn(const lucerna::PlanPolygon& outline);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class State { Off, Armed, Dragging, Polygon };

    bool press(const QMouseEvent& event, bool doubleClick);
    bool move(const QMouseEvent& event);
    bool release(const QMouseEvent& event);
    bool key(const QKeyEvent& event);
    // Announces the outline (when it makes a room) and turns the tool off.
    void finish(const std::vector<QPointF>& corners);
    void cancel();
    QPointF snapped(const QPointF& widget) const;
    void paintOpenings(QPainter& painter, const Room& room) const;

    PlanView* view_;
    Document* doc_;
    QToolButton* button_;
    State state_ = State::Off;
    std::vector<QPointF> corners_;  // the polygon's, plan coordinates
    QPointF first_, mouse_;         // the drag's first corner; the mouse (snapped), plan coordinates
    QPointF pressedAt_;             // widget position of the last left press
};

}  // namespace lucerna
