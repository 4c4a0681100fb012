#pragma once
// The room dialog (README, "Rooms"): a room's name, the corners of its outline in plan (x and z in
// metres, one row each; Add Corner splits the wall after the chosen corner, Remove Corner joins
// its two walls), its floor level and height in metres, and the reflectances of floor, walls and
// ceiling. Edit > Add Room opens it on a rectangle around the scene, the plan's Draw Room on the
// outline drawn, Edit > Edit Room on a room of the scene. A line under the fields gives the
// floor's and walls' areas as they are typed; OK is refused, with the reason on that line, while
// the room cannot be built (a crossed outline, an opening that no longer fits its wall).

#include "core/scene/room_edit.h"

#include <QDialog>

#include <functional>
#include <optional>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace lucerna {

class RoomDialog : public QDialog {
    Q_OBJECT
public:
    // Opens on `room` (scene units; metersPerUnit converts to the metres shown). A reflectance
    // left out is shown disabled (its material is not diffuse or glossy).
    RoomDialog(const Room& room, const std::array<std::optional<double>, 3>& reflectances, double metersPerUnit,
               const QString& title, QWidget* parent = nullptr);

    // The room as typed, scene units: values not retyped keep their exact value; its openings
    // follow their walls when corners are added or removed.
    Room room() const;
    // The reflectances typed (0 to 1); a disabled one keeps what it was opened on.
    RoomReflectances reflectances() const;
    // Asked on OK: the reason to refuse the room (shown in the dialog), or empty to accept it.
    void setCheck(std::function<QString(const Room&, const RoomReflectances&)> check) { check_ = std::move(check); }
    // The corners' fields in row `row` (tests type into them).
    QDoubleSpinBox* cornerField(int row, int column) const;

    void accept() override;

private:
    void addCornerRow(int row, const V2d& metres);
    void nameCornerRows();
    // The selected corner's row, else the last.
    int chosenCorner() const;
    void insertCorner();
    void removeCorner();
    void updateSummary();

    double metersPerUnit_;
    Room original_;
    std::vector<RoomOpening> openings_;  // wall numbers kept up with the corners
    // Per row, the corner it was opened on (scene units), or nothing for a corner added.
    std::vector<std::optional<V2d>> originalCorners_;
    std::array<std::optional<double>, 3> originalReflectances_;
    QLineEdit* name_;
    QTableWidget* corners_;
    QPushButton *addCorner_, *removeCorner_;
    QDoubleSpinBox *floorLevel_, *height_;
    std::array<QDoubleSpinBox*, 3> reflectance_;  // floor, walls, ceiling, in percent
    QLabel* summary_;
    std::function<QString(const Room&, const RoomReflectances&)> check_;
};

// A new room around the scene's geometry and its camera: the plan's bounds (the camera half a
// metre inside; at least 2 m each way) as a rectangle, 3 m high from the lowest point (higher
// when the eye is), named after the rooms already there ("room", "room 2", ...). Names no
// materials yet (setRoomReflectances makes them).
Room roomAroundScene(const Scene& scene);
// A new room on an outline drawn in the plan (scene units): the floor at the scene's lowest
// point, 3 m high, named as above.
Room roomOnOutline(const Scene& scene, const PlanPolygon& outline);

}  // namespace lucerna
