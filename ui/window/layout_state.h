#pragma once
// The window's dock layout across runs: saved at a clean close, restored at the next start unless
// it would leave the viewport less than half the window's width (dock sizes that drifted, or a
// saved layout from a smaller screen), in which case the default layout comes back, as it does
// with View > Reset Layout.

#include <QByteArray>
#include <QObject>

#include <functional>

class QMainWindow;
class QWidget;

namespace lucerna {

class LayoutState : public QObject {
    Q_OBJECT
public:
    // Call once the docks exist: their arrangement then is the default one. defaultSizes gives the
    // docks their default sizes (it runs once the window has its size).
    LayoutState(QMainWindow* window, QWidget* viewport, std::function<void()> defaultSizes);

    // Geometry and dock layout from QSettings; the check on the viewport's width runs once the
    // window is shown.
    void restore();
    void save() const;
    // The docks as at the first start (all shown, docked where they were made, default sizes).
    void reset();
    // The viewport's least share of the window's width.
    static constexpr double kMinViewportShare = 0.5;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void checkViewportRoom();

    QMainWindow* window_;
    QWidget* viewport_;
    std::function<void()> defaultSizes_;
    QByteArray defaultState_;
    bool checkPending_ = false;
};

}  // namespace lucerna
