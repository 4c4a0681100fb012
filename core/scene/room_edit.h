#pragma once
// Edits of a scene's rooms as the window makes them, each one undo step (README, "Rooms"): a room
// added or changed (its surfaces generated again in place of the old ones), objects marked as a
// room, a room removed. Each edit is computed once against the scene as it is and kept as what
// it takes out and puts in, so that it applies and reverts exactly however often it is redone.

#include "core/scene/room_geometry.h"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace lucerna {

// What a lighting calculation asks of a room's surfaces, 0 to 1 (EN 12464-1's usual ranges as
// defaults).
struct RoomReflectances {
    double floor = 0.2, walls = 0.5, ceiling = 0.7;
};

// One edit of the rooms: the lists of rooms and materials before and after, and the objects
// taken out (at their indices before the edit, ascending) and put in (at their indices after it,
// ascending).
struct RoomEdit {
    std::vector<Room> roomsBefore, roomsAfter;
    std::vector<Material> materialsBefore, materialsAfter;
    std::vector<std::pair<size_t, Object>> removed, inserted;
    // The new scene's floor went with it (placeRoom's placeholderFloor).
    bool removedPlaceholderFloor = false;
};

// The scene after the edit; revertRoomEdit takes it back to what it was. The scene must be the
// one the edit was computed against (or, for revert, the one applying it gave).
void applyRoomEdit(Scene& scene, const RoomEdit& edit);
void revertRoomEdit(Scene& scene, const RoomEdit& edit);

// Adds `room` (index -1) or puts it in place of the room at `index`, its surfaces generated
// (roomSurfaces) in place of those tagged with the room before: where the first of them stood in
// the list of objects, a new room's after the others. `materials` is the list of materials as it
// becomes, the room's (and its windows' glazing) among them. When `placeholderFloor` gives an
// object whose mesh lies at the room's floor level and overlaps its outline in plan (the new
// scene's floor, under the room's own), it goes too, and its material when nothing else uses it.
// Throws std::invalid_argument with a one-line reason when the room cannot be built
// ("outline: the outline crosses itself: walls 1 and 3 meet") or another room has its name.
RoomEdit placeRoom(const Scene& scene, int index, const Room& room, std::vector<Material> materials,
                   std::optional<size_t> placeholderFloor = std::nullopt);

// Sets the room's three surfaces to diffuse greys of `r` in `materials`: a room that names no
// materials yet (a new one) gets three new ones, "ROOM floor", "ROOM walls", "ROOM ceiling" (made
// free among the materials); otherwise the albedo of each named diffuse or glossy material is
// set (another type is left as it is: a reflectance says nothing of a mirror).
void setRoomReflectances(Room& room, std::vector<Material>& materials, const RoomReflectances& r);
// The floor's, walls' and ceiling's reflectance as their materials give them (the albedo's
// luminance of a diffuse or glossy material; nothing for other types or a material not found).
std::array<std::optional<double>, 3> roomReflectances(const Room& room, const std::vector<Material>& materials);
// The name of a grey glazing material of `transmittance` (0 to 1): one of `materials` that is
// exactly that, else a new one "ROOM glazing" (made free) appended to them.
std::string glazingMaterial(std::vector<Material>& materials, const std::string& roomName, double transmittance);

// Marks objects (indices into the scene's) as the surfaces of a new room named `name`: no
// outline, never generated again; the objects are tagged and stay where they are. Throws
// std::invalid_argument when none are given, one is a room's already, another room has the name,
// or together they do not form a closed shell ("... 12 edges belong to one face only").
RoomEdit markRoom(const Scene& scene, const std::string& name, const std::vector<int>& objects);

// Removes the room at `index`: a parametric room with its surfaces, and the materials only they
// used; a marked room's objects stay, no longer tagged.
RoomEdit removeRoom(const Scene& scene, int index);

// The indices of the objects tagged with the room named `name`, ascending.
std::vector<size_t> roomObjects(const Scene& scene, const std::string& name);

}  // namespace lucerna
