#include "ui/window/view_area.h"

#include "ui/plan/plan_view.h"
#include "ui/viewport/viewport.h"

#include <QAction>
#include <QActionGroup>

namespace lucerna {

ViewArea::ViewArea(Viewport* viewport, PlanView* plan, QWidget* parent)
    : QStackedWidget(parent), viewport_(viewport), plan_(plan) {
    addWidget(viewport_);
    addWidget(plan_);
    auto* group = new QActionGroup(this);
    const struct {
        Mode mode;
        QString text;
        const char* name;
        const char* key;
    } modes[] = {{Mode::Perspective, tr("&Perspective"), "actionViewPerspective", "Ctrl+1"},
                 {Mode::Plan, tr("P&lan"), "actionViewPlan", "Ctrl+2"},
                 {Mode::Front, tr("&Front Elevation"), "actionViewFront", "Ctrl+3"},
                 {Mode::Side, tr("&Side Elevation"), "actionViewSide", "Ctrl+4"}};
    for (const auto& m : modes) {
        auto* a = new QAction(m.text, this);
        a->setObjectName(m.name);
        a->setShortcut(QKeySequence(tr(m.key)));
        a->setShortcutContext(Qt::WindowShortcut);
        a->setCheckable(true);
        a->setChecked(m.mode == Mode::Perspective);
        group->addAction(a);
        const Mode mode = m.mode;
        connect(a, &QAction::triggered, this, [this, mode] { setMode(mode); });
        actions_ << a;
    }
}

void ViewArea::setMode(Mode mode) {
    mode_ = mode;
    actions_[int(mode)]->setChecked(true);
    if (mode == Mode::Perspective) {
        setCurrentWidget(viewport_);
    } else {
        plan_->setProjection(mode == Mode::Plan    ? PlanView::Projection::Top
                             : mode == Mode::Front ? PlanView::Projection::Front
                                                   : PlanView::Projection::Side);
        setCurrentWidget(plan_);
    }
    emit modeChanged(mode);
}

}  // namespace lucerna
