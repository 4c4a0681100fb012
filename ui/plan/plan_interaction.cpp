#include "ui/plan/plan_interaction.h"

#include "render/display/plan_projection.h"
#include "ui/commands/light_commands.h"
#include "ui/document/document.h"
#include "ui/plan/plan_view.h"
#include "ui/viewport/light_pick.h"
#include "ui/viewport/viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QToolButton>
#include <QWheelEvent>

#include <cmath>

namespace lucerna {

PlanInteraction::PlanInteraction(PlanView* view, Document* doc, const YieldGate& gate)
    : QObject(view), view_(view), doc_(doc), gate_(gate) {
    view->installEventFilter(this);
}

PlanInteraction::~PlanInteraction() = default;

std::optional<QRectF> PlanInteraction::fieldBeingDrawn() const {
    if (drag_ != Drag::Field) return std::nullopt;
    return QRectF(fieldStart_, fieldEnd_).normalized();
}

bool PlanInteraction::eventFilter(QObject* watched, QEvent* event) {
    if (watched != view_) return false;
    switch (event->type()) {
    // (A double click is a second press, as QWidget's own handler makes it.)
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: press(static_cast<const QMouseEvent&>(*event)); return true;
    case QEvent::MouseMove: move(static_cast<const QMouseEvent&>(*event)); return true;
    case QEvent::MouseButtonRelease: release(static_cast<const QMouseEvent&>(*event)); return true;
    case QEvent::Wheel: zoom(static_cast<const QWheelEvent&>(*event)); return true;
    case QEvent::KeyPress: return cancelField(static_cast<const QKeyEvent&>(*event));
    default: return false;
    }
}

int PlanInteraction::lightAt(const QPointF& pos) const {
    return lightNear(int(doc_->scene().lights.size()), [this](int i) { return view_->lightSymbol(i); }, pos,
                     PlanView::kSymbolRadius + 4);
}

QPointF PlanInteraction::snappedPlan(const QPointF& widget) const {
    QPointF p = view_->planOfWidget(widget);
    const double step = view_->snapMeters() / doc_->scene().metersPerUnit;
    if (step > 0) p = QPointF(std::round(p.x() / step) * step, std::round(p.y() / step) * step);
    return p;
}

void PlanInteraction::press(const QMouseEvent& event) {
    if (drag_ != Drag::None) return;
    pressed_ = last_ = event.position();
    moved_ = false;
    if (event.button() == Qt::LeftButton && view_->drawFieldButton()->isChecked() &&
        view_->projection() == PlanView::Projection::Top) {
        drag_ = Drag::Field;
        fieldStart_ = fieldEnd_ = snappedPlan(pressed_);
        hold_ = std::make_unique<YieldGate::Scope>(gate_.counter());
        view_->update();
        return;
    }
    const int light = event.button() == Qt::LeftButton ? lightAt(pressed_) : -1;
    if (light >= 0) {
        drag_ = Drag::MoveLight;
        dragLight_ = light;
        dragStart_ = doc_->scene().lights[size_t(light)];
        mergeKey_ = nextMergeKey();
        emit view_->lightClicked(light);
    } else {
        drag_ = Drag::Pan;
    }
    hold_ = std::make_unique<YieldGate::Scope>(gate_.counter());
}

void PlanInteraction::moveDraggedLight(const QPointF& pos) {
    const auto& lights = doc_->scene().lights;
    if (dragLight_ < 0 || size_t(dragLight_) >= lights.size()) return;
    const V3d delta = worldDelta(view_->projection(), view_->planOfWidget(pos) - view_->planOfWidget(pressed_));
    Light light = lights[size_t(dragLight_)];
    V3d p = dragStart_.position + delta;
    const double step = view_->snapMeters() / doc_->scene().metersPerUnit;
    if (step > 0)
        for (int axis = 0; axis < 3; ++axis)
            if (delta[axis] != 0) p[axis] = std::round(p[axis] / step) * step;
    if (p == light.position) return;
    light.position = p;
    doc_->undoStack()->push(new EditLightCommand(doc_, dragLight_, light, mergeKey_,
                                                 PlanView::tr("Move %1").arg(QString::fromStdString(light.name))));
}

void PlanInteraction::move(const QMouseEvent& event) {
    const QPointF pos = event.position();
    if (drag_ == Drag::None) return;
    if (!moved_ && QLineF(pos, pressed_).length() < kClickSlop) return;
    moved_ = true;
    if (drag_ == Drag::Field) {
        fieldEnd_ = snappedPlan(pos);
        view_->update();
    } else if (drag_ == Drag::Pan) {
        view_->panBy(pos - last_);
    } else {
        moveDraggedLight(pos);
    }
    last_ = pos;
}

void PlanInteraction::release(const QMouseEvent& event) {
    if (drag_ == Drag::Field) {
        fieldEnd_ = snappedPlan(event.position());
        drag_ = Drag::None;
        hold_.reset();
        view_->drawFieldButton()->setChecked(false);
        view_->update();
        if (fieldStart_.x() != fieldEnd_.x() && fieldStart_.y() != fieldEnd_.y())
            emit view_->fieldDrawn(fieldStart_.x(), fieldStart_.y(), fieldEnd_.x(), fieldEnd_.y());
        else
            emit view_->message(PlanView::tr("The field's rectangle has no area: drag from one corner to the opposite one"));
        return;
    }
    if (drag_ == Drag::MoveLight && moved_) moveDraggedLight(event.position());
    if (drag_ == Drag::MoveLight && moved_ && size_t(dragLight_) < doc_->scene().lights.size()) {
        const V3d p = doc_->scene().lights[size_t(dragLight_)].position;
        emit view_->message(PlanView::tr("Moved %1 to (%2, %3, %4)")
                                .arg(QString::fromStdString(dragStart_.name))
                                .arg(p.x, 0, 'g', 6)
                                .arg(p.y, 0, 'g', 6)
                                .arg(p.z, 0, 'g', 6));
    }
    drag_ = Drag::None;
    dragLight_ = -1;
    hold_.reset();
}

void PlanInteraction::zoom(const QWheelEvent& event) {
    const double steps = event.angleDelta().y() / 120.0;
    if (steps != 0) view_->zoomAbout(event.position(), std::pow(1.2, steps));
}

bool PlanInteraction::cancelField(const QKeyEvent& event) {
    if (event.key() != Qt::Key_Escape || !(view_->drawFieldButton()->isChecked() || drag_ == Drag::Field)) return false;
    if (drag_ == Drag::Field) {
        drag_ = Drag::None;
        hold_.reset();
    }
    view_->drawFieldButton()->setChecked(false);
    view_->update();
    return true;
}

}  // namespace lucerna
