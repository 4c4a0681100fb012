#include "ui/window/room_actions.h"

#include "ui/commands/room_commands.h"
#include "ui/document/document.h"
#include "ui/document/new_scene.h"
#include "ui/scene_panels/opening_dialog.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/room_dialog.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QRegularExpression>

#include <cmath>

namespace lucerna {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// A reason for the opening dialog: the opening named by the dialog itself, not by its key in the
// file ("openings[2]: the window does not fit ..." reads "the window does not fit ...").
QString withoutOpeningKey(const QString& why) {
    static const QRegularExpression key(QStringLiteral("^openings\\[\\d+\\](: |\\.)"));
    return QString(why).remove(key);
}

// The new scene's floor, where it is still there untouched.
std::optional<size_t> newScenesFloor(const Scene& scene) {
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (isNewScenesFloor(scene.objects[i])) return i;
    return std::nullopt;
}

// The edit that adds `room` with its three materials made from the reflectances.
RoomEdit addition(const Scene& scene, Room room, const RoomReflectances& r) {
    std::vector<Material> materials = scene.materials;
    setRoomReflectances(room, materials, r);
    return placeRoom(scene, -1, room, materials, newScenesFloor(scene));
}

// The edit that puts `room` in place of room `index`; a reflectance changed sets its material's
// albedo (one left as it was leaves a coloured material alone).
RoomEdit change(const Scene& scene, int index, const Room& room, const RoomReflectances& r) {
    std::vector<Material> materials = scene.materials;
    if (room.parametric()) {
        const auto now = roomReflectances(room, materials);
        const std::pair<const std::string*, double> wanted[] = {
            {&room.floorMaterial, r.floor}, {&room.wallMaterial, r.walls}, {&room.ceilingMaterial, r.ceiling}};
        for (size_t k = 0; k < 3; ++k) {
            if (!now[k] || std::abs(*now[k] - wanted[k].second) < 1e-12) continue;
            if (!(wanted[k].second >= 0 && wanted[k].second <= 1)) throw std::invalid_argument("a reflectance must lie between 0 and 1");
            for (Material& m : materials)
                if (m.name == *wanted[k].first) m.albedo = Rgbd(wanted[k].second, wanted[k].second, wanted[k].second);
        }
    }
    return placeRoom(scene, index, room, materials, newScenesFloor(scene));
}

}  // namespace

RoomActions::RoomActions(Document& doc, Outliner& outliner, WindowMessages& messages)
    : doc_(doc), outliner_(outliner), messages_(messages) {}

void RoomActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("Add &Room..."), "actionAddRoom", QKeySequence(tr("Ctrl+Alt+R")), this,
                 [this] { addRoomInteractively(); });
    addMenuEntry(menu, tr("Edit R&oom..."), "actionEditRoom", {}, this, [this] { editRoomInteractively(); });
    addMenuEntry(menu, tr("Add Ope&ning..."), "actionAddOpening", {}, this, [this] { addOpeningInteractively(); });
    addMenuEntry(menu, tr("Edit Openin&g..."), "actionEditOpening", {}, this, [this] { editOpeningInteractively(); });
    addMenuEntry(menu, tr("&Mark as Room..."), "actionMarkAsRoom", {}, this, [this] { markAsRoomInteractively(); });
    menu->addSeparator();
}

int RoomActions::selectedRoom() const {
    const Outliner::Selection s = outliner_.selection();
    const Scene& scene = doc_.scene();
    if (s.kind == Outliner::Kind::Room) return s.index;
    if (s.kind == Outliner::Kind::Opening) return s.room;
    if (s.kind == Outliner::Kind::Object && s.index >= 0 && size_t(s.index) < scene.objects.size())
        for (size_t r = 0; r < scene.rooms.size(); ++r)
            if (scene.rooms[r].name == scene.objects[size_t(s.index)].room) return int(r);
    return -1;
}

QString RoomActions::attemptEdit(const std::function<RoomEdit()>& make, RoomEdit& edit) const {
    try {
        edit = make();
    } catch (const std::exception& e) {
        return qs(e.what());
    }
    return QString();
}

bool RoomActions::push(RoomEdit edit, const QString& text) {
    const bool floorGone = edit.removedPlaceholderFloor;
    doc_.undoStack()->push(new RoomEditCommand(&doc_, std::move(edit), text));
    messages_.show(floorGone ? tr("%1; the new scene's floor under it is removed (Undo brings it back)").arg(text) : text, 8000);
    return true;
}

// ---- rooms ----

void RoomActions::addRoomInteractively(const std::optional<PlanPolygon>& outline) {
    const Scene& scene = doc_.scene();
    const Room initial = outline ? roomOnOutline(scene, *outline) : roomAroundScene(scene);
    const RoomReflectances defaults;
    RoomDialog dialog(initial, {defaults.floor, defaults.walls, defaults.ceiling}, scene.metersPerUnit, tr("Add room"),
                      messages_.window());
    dialog.setCheck([this](const Room& room, const RoomReflectances& r) {
        RoomEdit edit;
        return attemptEdit([&] { return addition(doc_.scene(), room, r); }, edit);
    });
    if (dialog.exec() == QDialog::Accepted) messages_.warnUnless(addRoom(dialog.room(), dialog.reflectances()), tr("Add room"));
}

bool RoomActions::addRoom(Room room, const RoomReflectances& reflectances) {
    RoomEdit edit;
    const QString why = attemptEdit([&] { return addition(doc_.scene(), room, reflectances); }, edit);
    if (!why.isEmpty()) return messages_.fail(tr("Could not add the room: %1").arg(why));
    const int index = int(edit.roomsAfter.size()) - 1;
    const double m2 = doc_.scene().metersPerUnit * doc_.scene().metersPerUnit;
    push(std::move(edit), tr("Add room %1 (%2 m²)").arg(qs(room.name)).arg(roomAreas(room).floor * m2, 0, 'f', 1));
    outliner_.select(Outliner::Kind::Room, index);
    return true;
}

void RoomActions::editRoomInteractively() {
    const int index = selectedRoom();
    if (index < 0) {
        messages_.warnUnless(messages_.fail(tr("Select a room (or one of its surfaces) in the outliner first")), tr("Edit room"));
        return;
    }
    const Scene& scene = doc_.scene();
    const Room& room = scene.rooms[size_t(index)];
    if (!room.parametric()) {
        messages_.warnUnless(messages_.fail(tr("Room %1 is marked on imported objects: it has no outline to edit").arg(qs(room.name))),
                             tr("Edit room"));
        return;
    }
    RoomDialog dialog(room, roomReflectances(room, scene.materials), scene.metersPerUnit, tr("Edit room %1").arg(qs(room.name)),
                      messages_.window());
    dialog.setCheck([this, index](const Room& r, const RoomReflectances& refl) {
        RoomEdit edit;
        return attemptEdit([&] { return change(doc_.scene(), index, r, refl); }, edit);
    });
    if (dialog.exec() == QDialog::Accepted)
        messages_.warnUnless(editRoom(index, dialog.room(), dialog.reflectances()), tr("Edit room"));
}

bool RoomActions::editRoom(int index, const Room& room, const RoomReflectances& reflectances) {
    if (index < 0 || size_t(index) >= doc_.scene().rooms.size()) return messages_.fail(tr("No such room"));
    RoomEdit edit;
    const QString why = attemptEdit([&] { return change(doc_.scene(), index, room, reflectances); }, edit);
    if (!why.isEmpty()) return messages_.fail(tr("Could not change room %1: %2").arg(qs(doc_.scene().rooms[size_t(index)].name), why));
    if (edit.roomsAfter == edit.roomsBefore && edit.materialsAfter == edit.materialsBefore && !edit.removedPlaceholderFloor) {
        messages_.show(tr("Room %1 is unchanged").arg(qs(room.name)), 5000);
        return true;
    }
    push(std::move(edit), tr("Edit room %1").arg(qs(room.name)));
    outliner_.select(Outliner::Kind::Room, index);
    return true;
}

bool RoomActions::removeRoom(int index) {
    RoomEdit edit;
    const QString why = attemptEdit([&] { return lucerna::removeRoom(doc_.scene(), index); }, edit);
    if (!why.isEmpty()) return messages_.fail(why);
    const QString text = tr("Delete room %1").arg(qs(edit.roomsBefore[size_t(index)].name));
    return push(std::move(edit), text);
}

// ---- openings ----

void RoomActions::withGlazing(const Room& room, RoomOpening& opening, double transmittance, std::vector<Material>& materials) const {
    if (opening.type == OpeningType::Window) opening.glazing = glazingMaterial(materials, room.name, transmittance);
    else opening.glazing.clear();
}

void RoomActions::addOpeningInteractively() {
    const int index = selectedRoom();
    const Scene& scene = doc_.scene();
    if (index < 0 || !scene.rooms[size_t(index)].parametric()) {
        messages_.warnUnless(messages_.fail(tr("Select a drawn room (or one of its surfaces) in the outliner first")), tr("Add opening"));
        return;
    }
    const Room& room = scene.rooms[size_t(index)];
    OpeningDialog dialog(room, newOpening(room, OpeningType::Window, scene.metersPerUnit), 0.7, scene.metersPerUnit,
                         tr("Add an opening to %1").arg(qs(room.name)), messages_.window());
    dialog.setCheck([this, index](const RoomOpening& o, double tau) {
        Room room = doc_.scene().rooms[size_t(index)];
        std::vector<Material> materials = doc_.scene().materials;
        RoomOpening opening = o;
        RoomEdit edit;
        return withoutOpeningKey(attemptEdit([&] {
            withGlazing(room, opening, tau, materials);
            room.openings.push_back(opening);
            return placeRoom(doc_.scene(), index, room, materials);
        }, edit));
    });
    if (dialog.exec() == QDialog::Accepted)
        messages_.warnUnless(addOpening(index, dialog.opening(), dialog.transmittance()), tr("Add opening"));
}

bool RoomActions::addOpening(int roomIndex, RoomOpening opening, double transmittance) {
    const Scene& scene = doc_.scene();
    if (roomIndex < 0 || size_t(roomIndex) >= scene.rooms.size()) return messages_.fail(tr("No such room"));
    Room room = scene.rooms[size_t(roomIndex)];
    if (!room.parametric()) return messages_.fail(tr("Room %1 is marked on imported objects: it has no walls of its own").arg(qs(room.name)));
    std::vector<Material> materials = scene.materials;
    RoomEdit edit;
    const QString why = attemptEdit([&] {
        withGlazing(room, opening, transmittance, materials);
        room.openings.push_back(opening);
        return placeRoom(scene, roomIndex, room, materials);
    }, edit);
    if (!why.isEmpty()) return messages_.fail(tr("Could not add the %1: %2").arg(openingTypeName(opening.type), why));
    push(std::move(edit), tr("Add %1 to %2").arg(openingTypeName(opening.type), qs(room.name)));
    outliner_.selectOpening(roomIndex, int(room.openings.size()) - 1);
    return true;
}

void RoomActions::editOpeningInteractively() {
    const Outliner::Selection s = outliner_.selection();
    const Scene& scene = doc_.scene();
    if (s.kind != Outliner::Kind::Opening || s.room < 0 || size_t(s.room) >= scene.rooms.size()) {
        messages_.warnUnless(messages_.fail(tr("Select an opening under its room in the outliner first")), tr("Edit opening"));
        return;
    }
    const Room& room = scene.rooms[size_t(s.room)];
    const RoomOpening& opening = room.openings.at(size_t(s.index));
    const Material* glazing = scene.findMaterial(opening.glazing);
    OpeningDialog dialog(room, opening, glazing ? luminance(glazing->transmittance) : 0.7, scene.metersPerUnit,
                         tr("Edit an opening of %1").arg(qs(room.name)), messages_.window());
    const int roomIndex = s.room, index = s.index;
    dialog.setCheck([this, roomIndex, index](const RoomOpening& o, double tau) {
        Room room = doc_.scene().rooms[size_t(roomIndex)];
        std::vector<Material> materials = doc_.scene().materials;
        RoomOpening changed = o;
        RoomEdit edit;
        return withoutOpeningKey(attemptEdit([&] {
            withGlazing(room, changed, tau, materials);
            room.openings.at(size_t(index)) = changed;
            return placeRoom(doc_.scene(), roomIndex, room, materials);
        }, edit));
    });
    if (dialog.exec() == QDialog::Accepted)
        messages_.warnUnless(editOpening(roomIndex, index, dialog.opening(), dialog.transmittance()), tr("Edit opening"));
}

bool RoomActions::editOpening(int roomIndex, int index, RoomOpening opening, double transmittance) {
    const Scene& scene = doc_.scene();
    if (roomIndex < 0 || size_t(roomIndex) >= scene.rooms.size() || index < 0 ||
        size_t(index) >= scene.rooms[size_t(roomIndex)].openings.size())
        return messages_.fail(tr("No such opening"));
    Room room = scene.rooms[size_t(roomIndex)];
    std::vector<Material> materials = scene.materials;
    RoomEdit edit;
    const QString why = attemptEdit([&] {
        withGlazing(room, opening, transmittance, materials);
        room.openings[size_t(index)] = opening;
        return placeRoom(scene, roomIndex, room, materials);
    }, edit);
    if (!why.isEmpty()) return messages_.fail(tr("Could not change the %1: %2").arg(openingTypeName(opening.type), why));
    push(std::move(edit), tr("Edit %1 of %2").arg(openingTypeName(opening.type), qs(room.name)));
    outliner_.selectOpening(roomIndex, index);
    return true;
}

bool RoomActions::removeOpening(int roomIndex, int index) {
    const Scene& scene = doc_.scene();
    if (roomIndex < 0 || size_t(roomIndex) >= scene.rooms.size() || index < 0 ||
        size_t(index) >= scene.rooms[size_t(roomIndex)].openings.size())
        return messages_.fail(tr("No such opening"));
    Room room = scene.rooms[size_t(roomIndex)];
    const OpeningType type = room.openings[size_t(index)].type;
    room.openings.erase(room.openings.begin() + index);
    RoomEdit edit;
    const QString why = attemptEdit([&] { return placeRoom(scene, roomIndex, room, scene.materials); }, edit);
    if (!why.isEmpty()) return messages_.fail(why);
    push(std::move(edit), tr("Delete %1 of %2").arg(openingTypeName(type), qs(room.name)));
    outliner_.select(Outliner::Kind::Room, roomIndex);
    return true;
}

// ---- marked rooms, deletion ----

void RoomActions::markAsRoomInteractively() {
    const Outliner::Selection s = outliner_.selection();
    if (s.kind != Outliner::Kind::Object || s.objects.empty()) {
        messages_.warnUnless(messages_.fail(tr("Select the objects that make up the room in the outliner first (Ctrl or Shift click)")),
                             tr("Mark as room"));
        return;
    }
    bool ok = false;
    const QString name = QInputDialog::getText(messages_.window(), tr("Mark as room"),
                                               tr("Name of the room made of these %1 objects:").arg(s.objects.size()),
                                               QLineEdit::Normal, qs(roomAroundScene(doc_.scene()).name), &ok);
    if (ok) messages_.warnUnless(markAsRoom(s.objects, name.trimmed().toStdString()), tr("Mark as room"));
}

bool RoomActions::markAsRoom(const std::vector<int>& objects, const std::string& name) {
    RoomEdit edit;
    const QString why = attemptEdit([&] { return markRoom(doc_.scene(), name, objects); }, edit);
    if (!why.isEmpty()) return messages_.fail(tr("Could not mark a room: %1").arg(why));
    const int index = int(edit.roomsAfter.size()) - 1;
    push(std::move(edit), tr("Mark %1 objects as room %2").arg(objects.size()).arg(qs(name)));
    outliner_.select(Outliner::Kind::Room, index);
    return true;
}

bool RoomActions::deleteSelection() {
    const Outliner::Selection s = outliner_.selection();
    if (s.kind == Outliner::Kind::Room) return removeRoom(s.index) || true;
    if (s.kind == Outliner::Kind::Opening) return removeOpening(s.room, s.index) || true;
    return false;
}

}  // namespace lucerna
