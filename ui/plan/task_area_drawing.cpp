#include "ui/plan/task_area_drawing.h"

#include "ui/document/document.h"
#include "ui/plan/plan_view.h"
#include "ui/plan/task_area_outlines.h"
#include "ui/viewport/light_pick.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolButton>

#include <cmath>

namespace lucerna {

TaskAreaDrawing::TaskAreaDrawing(PlanView* view, Document* doc) : QObject(view), view_(view), doc_(doc) {
    button_ = new QToolButton(view);
    button_->setObjectName("planDrawTaskArea");
    button_->setText(PlanView::tr("Draw Task Area"));
    button_->setCheckable(true);
    button_->setToolTip(PlanView::tr("Click two opposite corners of a task area in the plan (or drag between them)"));
    QObject::connect(button_, &QToolButton::toggled, this, [this](bool on) {
        state_ = on ? State::Armed : State::Off;
        // Without a button held, the second corner follows the mouse only with tracking on.
        view_->setMouseTracking(on);
        if (on) emit view_->message(PlanView::tr("Click two opposite corners of the task area (Esc cancels)"));
        view_->update();
    });
    view->installEventFilter(this);
}

void TaskAreaDrawing::projectionChanged() {
    const bool plan = view_->projection() == PlanView::Projection::Top;
    if (!plan) button_->setChecked(false);
    button_->setEnabled(plan);
}

std::optional<QRectF> TaskAreaDrawing::rectangleBeingDrawn() const {
    if (state_ != State::Dragging && state_ != State::SecondCorner) return std::nullopt;
    return QRectF(first_, second_).normalized();
}

QPointF TaskAreaDrawing::snapped(const QPointF& widget) const {
    QPointF p = view_->planOfWidget(widget);
    const double step = view_->snapMeters() / doc_->scene().metersPerUnit;
    if (step > 0) p = QPointF(std::round(p.x() / step) * step, std::round(p.y() / step) * step);
    return p;
}

bool TaskAreaDrawing::eventFilter(QObject* watched, QEvent* event) {
    if (watched != view_) return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: return press(static_cast<const QMouseEvent&>(*event));
    case QEvent::MouseMove: return move(static_cast<const QMouseEvent&>(*event));
    case QEvent::MouseButtonRelease: return release(static_cast<const QMouseEvent&>(*event));
    case QEvent::KeyPress:
        if (static_cast<const QKeyEvent*>(event)->key() == Qt::Key_Escape && state_ != State::Off) {
            cancel();
            return true;
        }
        return false;
    default: return false;
    }
}

bool TaskAreaDrawing::press(const QMouseEvent& event) {
    if (event.button() != Qt::LeftButton) return state_ != State::Off;  // no pan while drawing
    pressed_ = true;
    pressedAt_ = event.position();
    switch (state_) {
    case State::Off: return false;  // the plan's own press (a light, a pan); a click may select on release
    case State::Armed:
        first_ = second_ = snapped(pressedAt_);
        state_ = State::Dragging;
        view_->update();
        return true;
    case State::SecondCorner:
        second_ = snapped(pressedAt_);
        view_->update();
        return true;
    case State::Dragging: return true;
    }
    return false;
}

bool TaskAreaDrawing::move(const QMouseEvent& event) {
    if (state_ == State::Off) return false;
    if (state_ == State::Dragging || state_ == State::SecondCorner) {
        second_ = snapped(event.position());
        view_->update();
    }
    return true;
}

bool TaskAreaDrawing::release(const QMouseEvent& event) {
    const bool click = pressed_ && QLineF(event.position(), pressedAt_).length() < kClickSlop;
    if (event.button() == Qt::LeftButton) pressed_ = false;
    if (event.button() != Qt::LeftButton) return state_ != State::Off;
    switch (state_) {
    case State::Off: {
        // A click on a task area (not on a light's symbol) selects it; the plan's own release goes on.
        if (!click || view_->projection() != PlanView::Projection::Top) return false;
        const QPointF pos = event.position();
        const int light = lightNear(int(doc_->scene().lights.size()), [this](int i) { return view_->lightSymbol(i); }, pos,
                                    PlanView::kSymbolRadius + 4);
        if (light >= 0) return false;
        const int area = TaskAreaOutlines::taskAreaAt(doc_->scene(), view_->planOfWidget(pos));
        if (area >= 0) emit view_->taskAreaClicked(area);
        return false;
    }
    case State::Dragging:
        if (click) {
            state_ = State::SecondCorner;  // a click: the second corner is the next click
            emit view_->message(PlanView::tr("Click the opposite corner (Esc cancels)"));
        } else {
            second_ = snapped(event.position());
            finish();
        }
        return true;
    case State::SecondCorner:
        second_ = snapped(event.position());
        finish();
        return true;
    case State::Armed: return true;
    }
    return false;
}

void TaskAreaDrawing::finish() {
    const QRectF r = QRectF(first_, second_).normalized();
    state_ = State::Off;
    button_->setChecked(false);
    view_->update();
    if (r.width() > 0 && r.height() > 0)
        emit view_->taskAreaDrawn(r.left(), r.top(), r.right(), r.bottom());
    else
        emit view_->message(PlanView::tr("The task area has no area: click two opposite corners"));
}

void TaskAreaDrawing::cancel() {
    state_ = State::Off;
    button_->setChecked(false);
    view_->update();
}

void TaskAreaDrawing::paint(QPainter& painter) const {
    const std::optional<QRectF> r = rectangleBeingDrawn();
    if (!r) return;
    const QRectF at(view_->widgetOfPlanPoint(r->topLeft()), view_->widgetOfPlanPoint(r->bottomRight()));
    const QColor c = TaskAreaOutlines::colour();
    painter.setPen(QPen(c, 1.5, Qt::DashLine));
    painter.setBrush(QColor(c.red(), c.green(), c.blue(), 40));
    painter.drawRect(at);
    const double mpu = doc_->scene().metersPerUnit;
    painter.setPen(Qt::black);
    painter.drawText(at.bottomRight() + QPointF(6, 14),
                     PlanView::tr("%1 x %2 m").arg(r->width() * mpu, 0, 'g', 4).arg(r->height() * mpu, 0, 'g', 4));
}

}  // namespace lucerna
