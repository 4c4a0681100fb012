#pragma once
// The middle of the window: the perspective viewport (the live preview) or the plan view (from
// above, or an elevation), one at a time, chosen by View > Perspective (Ctrl+1), Plan (Ctrl+2),
// Front Elevation (Ctrl+3) and Side Elevation (Ctrl+4).

#include <QStackedWidget>

class QAction;

namespace lucerna {

class PlanView;
class Viewport;

class ViewArea : public QStackedWidget {
    Q_OBJECT
public:
    enum class Mode { Perspective, Plan, Front, Side };

    ViewArea(Viewport* viewport, PlanView* plan, QWidget* parent = nullptr);

    Mode mode() const { return mode_; }
    void setMode(Mode mode);
    // The checkable actions that choose the mode (for the View menu).
    QList<QAction*> modeActions() const { return actions_; }

signals:
    void modeChanged(lucerna::ViewArea::Mode mode);

private:
    Viewport* viewport_;
    PlanView* plan_;
    Mode mode_ = Mode::Perspective;
    QList<QAction*> actions_;
};

}  // namespace lucerna
