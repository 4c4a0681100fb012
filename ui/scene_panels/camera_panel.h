#pragma once
// The camera dock: the scene camera's position, target and vertical field of view as numbers in
// the scene's unit and degrees, each typed value one undo step (a field's arrow steps merge), and
// View All (the whole scene in view, looking the same way) and Reset Camera (back to the camera
// the scene was opened or saved with, or an import placed). A value that would break the camera
// (the target on the position, a view along the up vector) is refused with a line saying why.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"

#include <QWidget>

#include <array>

class QDoubleSpinBox;
class QLabel;

namespace lucerna {

class CameraPanel : public QWidget {
    Q_OBJECT
public:
    explicit CameraPanel(Document* doc, QWidget* parent = nullptr);
    ~CameraPanel() override;  // disconnects its children first (ui/disconnect_children.h)

    void viewAll();
    void resetCamera();
    // The camera Reset Camera goes back to.
    void setHomeCamera(const Camera& camera) { home_ = camera; }

signals:
    void message(const QString& text);

private:
    void refresh();
    void apply(const void* field);

    Document* doc_;
    std::array<QDoubleSpinBox*, 3> position_{}, target_{};
    QDoubleSpinBox* fov_;
    QLabel* error_;
    MergeTracker merge_;
    Camera home_;
};

}  // namespace lucerna
