#include "ui/plan/room_drawing.h"

#include "core/scene/room_geometry.h"
#include "ui/document/document.h"
#include "ui/plan/plan_view.h"
#include "ui/viewport/light_pick.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolButton>

#include <cmath>

namespace lucerna {

namespace {

constexpr double kCloseReach = 8;  // widget pixels from the first corner that close the outline
const QColor kRoomColour(150, 90, 30);

// The area centroid of a simple polygon (its mean corner where it has no area).
QPointF centroid(const PlanPolygon& p) {
    double a = 0, x = 0, z = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const V2d &u = p[i], &v = p[(i + 1) % p.size()];
        const double c = u.x * v.y - v.x * u.y;
        a += c, x += (u.x + v.x) * c, z += (u.y + v.y) * c;
    }
    if (std::abs(a) < 1e-300) {
        V2d m(0, 0);
        for (const V2d& u : p) m += u;
        return p.empty() ? QPointF() : QPointF(m.x / double(p.size()), m.y / double(p.size()));
    }
    return QPointF(x / (3 * a), z / (3 * a));
}

}  // namespace

RoomDrawing::RoomDrawing(PlanView* view, Document* doc) : QObject(view), view_(view), doc_(doc) {
    button_ = new QToolButton(view);
    button_->setObjectName("planDrawRoom");
    button_->setText(PlanView::tr("Draw Room"));
    button_->setCheckable(true);
    button_->setToolTip(PlanView::tr("Drag a rectangular room, or click its corners one by one (the first again, a double "
                                     "click or Enter closes it)"));
    connect(button_, &QToolButton::toggled, this, [this](bool on) {
        state_ = on ? State::Armed : State::Off;
        corners_.clear();
        // The wall to the mouse follows it without a button held only with tracking on.
        view_->setMouseTracking(on);
        if (on)
            emit view_->message(PlanView::tr("Drag a rectangle, or click the room's corners (Enter or a double click closes, "
                                             "Backspace takes a corner back, Esc cancels)"));
        view_->update();
    });
    view->installEventFilter(this);
}

void RoomDrawing::projectionChanged() {
    const bool plan = view_->projection() == PlanView::Projection::Top;
    if (!plan) button_->setChecked(false);
    button_->setEnabled(plan);
}

std::vector<QPointF> RoomDrawing::cornersBeingDrawn() const {
    if (state_ == State::Dragging)
        return {first_, QPointF(mouse_.x(), first_.y()), mouse_, QPointF(first_.x(), mouse_.y())};
    return state_ == State::Polygon ? corners_ : std::vector<QPointF>{};
}

QPointF RoomDrawing::snapped(const QPointF& widget) const {
    QPointF p = view_->planOfWidget(widget);
    const double step = view_->snapMeters() / doc_->scene().metersPerUnit;
    if (step > 0) p = QPointF(std::round(p.x() / step) * step, std::round(p.y() / step) * step);
    return p;
}

bool RoomDrawing::eventFilter(QObject* watched, QEvent* event) {
    if (watched != view_ || state_ == State::Off) return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress: return press(static_cast<const QMouseEvent&>(*event), false);
    case QEvent::MouseButtonDblClick: return press(static_cast<const QMouseEvent&>(*event), true);
    case QEvent::MouseMove: return move(static_cast<const QMouseEvent&>(*event));
    case QEvent::MouseButtonRelease: return release(static_cast<const QMouseEvent&>(*event));
    case QEvent::KeyPress: return key(static_cast<const QKeyEvent&>(*event));
    default: return false;
    }
}

bool RoomDrawing::press(const QMouseEvent& event, bool doubleClick) {
    if (event.button() != Qt::LeftButton) return false;  // right or middle: the plan pans meanwhile
    const QPointF pos = event.position();
    pressedAt_ = pos;
    switch (state_) {
    case State::Armed:
        first_ = mouse_ = snapped(pos);
        state_ = State::Dragging;
        break;
    case State::Polygon: {
        // A double click's first click placed its corner: the second closes the outline.
        if (doubleClick) {
            finish(corners_);
            break;
        }
        if (corners_.size() >= 3 && QLineF(pos, view_->widgetOfPlanPoint(corners_.front())).length() <= kCloseReach) {
            finish(corners_);
            break;
        }
        const QPointF p = mouse_ = snapped(pos);
        if (p != corners_.back()) corners_.push_back(p);
        break;
    }
    case State::Dragging:
    case State::Off: break;
    }
    view_->update();
    return true;
}

bool RoomDrawing::move(const QMouseEvent& event) {
    mouse_ = snapped(event.position());
    view_->update();
    // A pan with the right or middle button goes on in the plan.
    return !(event.buttons() & (Qt::RightButton | Qt::MiddleButton));
}

bool RoomDrawing::release(const QMouseEvent& event) {
    if (event.button() != Qt::LeftButton) return false;
    if (state_ != State::Dragging) return true;
    if (QLineF(event.position(), pressedAt_).length() >= kClickSlop) {
        const QPointF a = first_, b = snapped(event.position());
        finish({a, QPointF(b.x(), a.y()), b, QPointF(a.x(), b.y())});
    } else {
        // A click: the first corner of a polygon.
        state_ = State::Polygon;
        corners_ = {first_};
        emit view_->message(PlanView::tr("Click the next corner; the first corner again, a double click or Enter closes the room"));
    }
    view_->update();
    return true;
}

bool RoomDrawing::key(const QKeyEvent& event) {
    switch (event.key()) {
    case Qt::Key_Escape: cancel(); return true;
    case Qt::Key_Backspace:
        if (state_ == State::Polygon) {
            corners_.pop_back();
            if (corners_.empty()) state_ = State::Armed;
            view_->update();
        }
        return true;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        if (state_ == State::Polygon) finish(corners_);
        return true;
    default: return false;
    }
}

void RoomDrawing::finish(const std::vector<QPointF>& corners) {
    PlanPolygon outline;
    for (const QPointF& c : corners)
        if (outline.empty() || outline.back() != V2d(c.x(), c.y())) outline.emplace_back(c.x(), c.y());
    if (outline.size() > 1 && outline.back() == outline.front()) outline.pop_back();
    state_ = State::Off;
    corners_.clear();
    button_->setChecked(false);
    view_->update();
    if (const auto problem = outlineProblem(outline)) {
        emit view_->message(PlanView::tr("No room drawn: %1").arg(QString::fromStdString(*problem)));
        return;
    }
    emit outlineDrawn(outline);
}

void RoomDrawing::cancel() {
    button_->setChecked(false);  // the toggle clears the corners
    emit view_->message(PlanView::tr("Room drawing cancelled"));
}

void RoomDrawing::paintOpenings(QPainter& painter, const Room& room) const {
    // As plans draw them: a gap in the wall; a window's glazing as two thin lines across it, a
    // door's leaf and swing into the room, a plain opening dashed.
    const std::vector<RoomWall> walls = roomWalls(room);
    const QColor background(246, 246, 242);  // the plan's
    for (const RoomOpening& o : room.openings) {
        if (o.wall < 1 || size_t(o.wall) > walls.size()) continue;
        const RoomWall& w = walls[size_t(o.wall - 1)];
        const V2d along = (w.to - w.from) / w.length;
        const V2d p0 = w.from + along * o.offset, p1 = w.from + along * (o.offset + o.width);
        const QPointF a = view_->widgetOfPlanPoint(QPointF(p0.x, p0.y)), b = view_->widgetOfPlanPoint(QPointF(p1.x, p1.y));
        const QPointF n(w.inward.x, w.inward.y);  // the plan's axes are the widget's, scaled
        const double r = QLineF(a, b).length();
        painter.setPen(QPen(background, 5, Qt::SolidLine, Qt::FlatCap));
        painter.drawLine(a, b);
        switch (o.type) {
        case OpeningType::Window:
            painter.setPen(QPen(openingColour(), 1.2));
            painter.drawLine(a + n * 2.0, b + n * 2.0);
            painter.drawLine(a - n * 2.0, b - n * 2.0);
            break;
        case OpeningType::Door: {
            painter.setPen(QPen(kRoomColour.darker(120), 1.2));
            const QPointF u = (b - a) / std::max(r, 1e-9);
            painter.drawLine(a, a + n * r);
            QPolygonF swing;
            for (int k = 0; k <= 16; ++k) {
                const double t = M_PI / 2 * k / 16;
                swing << a + (u * std::cos(t) + n * std::sin(t)) * r;
            }
            painter.setPen(QPen(kRoomColour.darker(120), 0.8, Qt::DashLine));
            painter.drawPolyline(swing);
            break;
        }
        case OpeningType::Opening:
            painter.setPen(QPen(kRoomColour.darker(120), 1, Qt::DashLine));
            painter.drawLine(a, b);
            break;
        }
    }
}

QColor RoomDrawing::openingColour() { return QColor(40, 120, 210); }

void RoomDrawing::paintRooms(QPainter& painter) const {
    if (view_->projection() != PlanView::Projection::Top) return;
    const Scene& scene = doc_->scene();
    const double m2 = scene.metersPerUnit * scene.metersPerUnit;
    for (const Room& room : scene.rooms) {
        if (!room.parametric()) continue;  // a marked room's walls are the model's, drawn as they are
        QPolygonF outline;
        for (const V2d& c : room.outline) outline << view_->widgetOfPlanPoint(QPointF(c.x, c.y));
        painter.setPen(QPen(kRoomColour, 1, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawPolygon(outline);
        paintOpenings(painter, room);
        const QPointF at = view_->widgetOfPlanPoint(centroid(room.outline));
        const QString text = PlanView::tr("%1\n%2 m²").arg(QString::fromStdString(room.name)).arg(roomAreas(room).floor * m2, 0, 'f', 1);
        const QRectF box = painter.fontMetrics().boundingRect(QRect(0, 0, 400, 100), Qt::AlignCenter, text).adjusted(-3, -1, 3, 1);
        const QRectF label(at - QPointF(box.width() / 2, box.height() / 2), box.size());
        painter.fillRect(label, QColor(255, 255, 255, 200));
        painter.setPen(kRoomColour.darker(140));
        painter.drawText(label, Qt::AlignCenter, text);
    }
}

void RoomDrawing::paint(QPainter& painter) const {
    if (view_->projection() != PlanView::Projection::Top) return;
    std::vector<QPointF> corners = cornersBeingDrawn();
    if (corners.empty()) return;
    QPolygonF line;
    for (const QPointF& c : corners) line << view_->widgetOfPlanPoint(c);
    QColor fill = kRoomColour;
    fill.setAlpha(40);
    painter.setPen(QPen(kRoomColour, 2));
    if (state_ == State::Dragging) {
        painter.setBrush(fill);
        painter.drawPolygon(line);
    } else {
        line << view_->widgetOfPlanPoint(mouse_);  // the next wall, to the mouse
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(line);
        painter.setPen(QPen(kRoomColour, 1, Qt::DotLine));
        painter.drawLine(line.back(), line.front());  // and back to the first corner
    }
    painter.setPen(QPen(kRoomColour.darker(130), 1.5));
    painter.setBrush(Qt::white);
    for (const QPointF& c : corners) painter.drawEllipse(view_->widgetOfPlanPoint(c), 3.5, 3.5);
    // The wall being drawn, in metres.
    const QPointF from = state_ == State::Dragging ? corners.front() : corners.back();
    const QPointF d = mouse_ - from;
    const double metres = std::hypot(d.x(), d.y()) * doc_->scene().metersPerUnit;
    painter.setPen(Qt::black);
    painter.drawText(view_->widgetOfPlanPoint(mouse_) + QPointF(8, -8),
                     state_ == State::Dragging ? PlanView::tr("%1 x %2 m")
                                                     .arg(std::abs(d.x()) * doc_->scene().metersPerUnit, 0, 'g', 4)
                                                     .arg(std::abs(d.y()) * doc_->scene().metersPerUnit, 0, 'g', 4)
                                               : PlanView::tr("%1 m").arg(metres, 0, 'g', 4));
}

}  // namespace lucerna
