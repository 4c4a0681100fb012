#pragma once
// Edit > Add Room: the room's name, the floor's corner, its width, depth and height and the
// reflectances of floor, walls and ceiling (core/scene/room_geometry.h).

#include "core/scene/room_geometry.h"

#include <QDialog>

class QDoubleSpinBox;
class QLineEdit;

namespace lucerna {

class RoomDialog : public QDialog {
    Q_OBJECT
public:
    // Opens on `initial` (lengths in metres, the corner in scene units, reflectances 0 to 1).
    RoomDialog(const RoomSpec& initial, QWidget* parent = nullptr);
    RoomSpec spec() const;

private:
    QLineEdit* name_;
    QDoubleSpinBox *x_, *y_, *z_, *width_, *depth_, *height_, *floor_, *walls_, *ceiling_;
};

// A room around the scene's geometry and its camera: the plan's bounds (the camera half a metre
// inside; at least 2 m each way), 3 m high from the lowest point (higher when the eye is), named
// after the rooms already there.
RoomSpec roomAroundScene(const Scene& scene);

}  // namespace lucerna
