#pragma once
// The plan view's mouse and keys (ui/plan/plan_view.h says what they do): a light moved in the
// view's plane and snapped, a field's rectangle drawn, the view panned and zoomed. An event
// filter on the view, so that the view itself only draws.

#include "core/scene/scene.h"
#include "ui/rendering/yield_gate.h"

#include <QObject>
#include <QPointF>
#include <QRectF>

#include <memory>
#include <optional>

class QKeyEvent;
class QMouseEvent;
class QWheelEvent;

namespace lucerna {

class Document;
class PlanView;

class PlanInteraction : public QObject {
public:
    // Filters `view`'s events from now on; a child of it.
    PlanInteraction(PlanView* view, Document* doc, const YieldGate& gate);
    ~PlanInteraction() override;

    // The field's rectangle being drawn, in plan coordinates (nothing while none is).
    std::optional<QRectF> fieldBeingDrawn() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class Drag { None, Pan, MoveLight, Field };

    void press(const QMouseEvent& event);
    void move(const QMouseEvent& event);
    void release(const QMouseEvent& event);
    void zoom(const QWheelEvent& event);
    // True when the key was for the field tool (Escape cancels it).
    bool cancelField(const QKeyEvent& event);
    int lightAt(const QPointF& pos) const;
    void moveDraggedLight(const QPointF& pos);
    // The plan point under a widget point, on the snap grid when it snaps.
    QPointF snappedPlan(const QPointF& widget) const;

    PlanView* view_;
    Document* doc_;
    YieldGate gate_;
    Drag drag_ = Drag::None;
    int dragLight_ = -1;
    Light dragStart_;
    QPointF pressed_, last_;
    QPointF fieldStart_, fieldEnd_;  // plan coordinates of the field being drawn
    bool moved_ = false;
    int mergeKey_ = 0;
    std::unique_ptr<YieldGate::Scope> hold_;
};

}  // namespace lucerna
