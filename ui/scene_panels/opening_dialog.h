#pragma once
// The opening dialog (README, "Rooms"): a window, door or plain opening in one of a room's walls,
// given by the wall, its offset along the wall from the wall's first corner, its sill above the
// floor (a door's is 0), its width and height in metres, and a window's glazing transmittance.
// Edit > Add Opening opens it on a window in the middle of the room's longest wall; Edit > Edit
// Opening on the selected one. OK is refused, with the reason under the fields, while the opening
// does not fit (past the wall's end, above the ceiling, over another opening).

#include "core/scene/room_geometry.h"

#include <QDialog>

#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace lucerna {

class OpeningDialog : public QDialog {
    Q_OBJECT
public:
    // Opens on `opening` (scene units) in `room`, a window's pane of `transmittance` (0 to 1).
    OpeningDialog(const Room& room, const RoomOpening& opening, double transmittance, double metersPerUnit,
                  const QString& title, QWidget* parent = nullptr);

    // The opening as typed, scene units (values not retyped keep their exact value); a window's
    // glazing is left to the caller (glazingMaterial of the transmittance).
    RoomOpening opening() const;
    double transmittance() const;
    // Asked on OK: the reason to refuse the opening (shown in the dialog), or empty to accept.
    void setCheck(std::function<QString(const RoomOpening&, double)> check) { check_ = std::move(check); }

    void accept() override;

private:
    void typeChanged();

    Room room_;
    RoomOpening original_;
    double metersPerUnit_;
    QComboBox *type_, *wall_;
    QDoubleSpinBox *offset_, *sill_, *width_, *height_, *transmittance_;
    QLabel* problem_;
    std::function<QString(const RoomOpening&, double)> check_;
};

// A new opening of `type` in the middle of the room's longest wall (scene units): a window 1.2 m
// wide and 1.2 m high on a 0.9 m sill, a door 0.9 by 2.1 m, a plain opening 1 by 2.1 m, each
// kept within the wall and under the ceiling.
RoomOpening newOpening(const Room& room, OpeningType type, double metersPerUnit);

}  // namespace lucerna
