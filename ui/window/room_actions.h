#pragma once
// Rooms in the window (README, "Rooms"): Edit > Add Room... (a rectangle around the scene, or the
// outline drawn in the plan with Draw Room), Edit Room... (its corners, levels and reflectances),
// Add Opening... and Edit Opening... (a window, door or plain opening in a wall), Mark as Room
// (objects that close a shell), and Delete on a room or an opening. Each is one undo step
// (ui/commands/room_commands.h); the room's surfaces are generated again from its parameters
// (core/scene/room_edit.h). A room whose floor lies on the new scene's floor (File > New) takes
// that floor away in the same step, and says so.

#include "core/scene/room_edit.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QMenu;

namespace lucerna {

class Document;
class Outliner;
class WindowMessages;

class RoomActions : public QObject {
    Q_OBJECT
public:
    RoomActions(Document& doc, Outliner& outliner, WindowMessages& messages);

    // Adds Add Room... (Ctrl+Alt+R), Edit Room..., Add Opening..., Edit Opening... and Mark as
    // Room... to `menu`.
    void addTo(QMenu* menu);

    // The room dialog on a new room: around the scene, or on `outline` (scene units) drawn in the
    // plan; OK adds it.
    void addRoomInteractively(const std::optional<PlanPolygon>& outline = std::nullopt);
    // The dialog on the selected room (or the room of the selected surface or opening).
    void editRoomInteractively();
    // The opening dialog on a new window in the selected room's longest wall.
    void addOpeningInteractively();
    // The opening dialog on the selected opening.
    void editOpeningInteractively();
    // Asks a name, then marks the selected objects as a room.
    void markAsRoomInteractively();

    // The operations behind them, without dialogs; each is one undo step and selects what it
    // made, or returns false with a one-line reason (WindowMessages::lastError) and changes
    // nothing. `room` names no materials yet: they are made from the reflectances.
    bool addRoom(Room room, const RoomReflectances& reflectances);
    bool editRoom(int index, const Room& room, const RoomReflectances& reflectances);
    // A window's pane takes a glazing material of `transmittance` (found or made).
    bool addOpening(int room, RoomOpening opening, double transmittance);
    bool editOpening(int room, int index, RoomOpening opening, double transmittance);
    bool removeOpening(int room, int index);
    bool markAsRoom(const std::vector<int>& objects, const std::string& name);
    bool removeRoom(int index);
    // Delete on a room or an opening selected: removes it and returns true; false for anything
    // else (EditActions deletes that).
    bool deleteSelection();

    // The selected room: a room's node, an opening's room, a surface's room; -1 for none.
    int selectedRoom() const;

private:
    // The reason the edit cannot be made, or empty; `edit` gets it.
    QString attemptEdit(const std::function<RoomEdit()>& make, RoomEdit& edit) const;
    // The room's opening with a window's glazing set, the materials as they become.
    void withGlazing(const Room& room, RoomOpening& opening, double transmittance, std::vector<Material>& materials) const;
    bool push(RoomEdit edit, const QString& text);

    Document& doc_;
    Outliner& outliner_;
    WindowMessages& messages_;
};

}  // namespace lucerna
