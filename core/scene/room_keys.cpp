// Rooms in a scene file (README, "Rooms"; an addition): a parametric room's outline, levels,
// materials and openings, or a room marked on its objects, checked as room_geometry.h's
// roomProblem checks what the window builds.

#include "core/scene/scene_parser.h"

#include "core/number_format.h"
#include "core/scene/room_geometry.h"
#include "core/scene/scene_resolve.h"

#include <algorithm>

namespace lucerna {

Room SceneParser::parseRoom(const Value& v, const std::string& place, const Scene& scene) const {
    checkKeys(v, place, {"name", "outline", "floor_level", "height", "materials", "openings"});
    Room room;
    const std::string namePlace = member(place, "name");
    room.name = text(required(v, place, "name"), namePlace);
    for (const Room& r : scene.rooms)
        if (r.name == room.name) fail(namePlace, "another room is already named " + quote(room.name));
    const Value* outline = v.find("outline");
    if (!outline) {
        // Marked on its objects: nothing to build it from.
        for (const char* key : {"floor_level", "height", "materials", "openings"})
            if (v.find(key))
                fail(member(place, key), "only a room with an outline takes this key (a room without one is marked on its objects)");
    } else {
        const std::string here = member(place, "outline");
        expectType(*outline, Type::Array, here);
        for (size_t i = 0; i < outline->array.size(); ++i) {
            const Value& corner = array(outline->array[i], item(here, i), 2, "numbers (x, z)");
            room.outline.emplace_back(number(corner.array[0], item(item(here, i), 0)), number(corner.array[1], item(item(here, i), 1)));
        }
        room.floorLevel = number(required(v, place, "floor_level"), member(place, "floor_level"));
        room.height = number(required(v, place, "height"), member(place, "height"));
        const std::string mPlace = member(place, "materials");
        const Value& materials = required(v, place, "materials");
        checkKeys(materials, mPlace, {"floor", "walls", "ceiling"});
        room.floorMaterial = text(required(materials, mPlace, "floor"), member(mPlace, "floor"));
        room.wallMaterial = text(required(materials, mPlace, "walls"), member(mPlace, "walls"));
        room.ceilingMaterial = text(required(materials, mPlace, "ceiling"), member(mPlace, "ceiling"));
        if (const Value* openings = v.find("openings")) {
            const std::string oPlace = member(place, "openings");
            expectType(*openings, Type::Array, oPlace);
            for (size_t i = 0; i < openings->array.size(); ++i) {
                const Value& o = openings->array[i];
                const std::string at = item(oPlace, i);
                expectType(o, Type::Object, at);
                RoomOpening opening;
                const std::string type = text(required(o, at, "type"), member(at, "type"));
                if (type == "window") opening.type = OpeningType::Window;
                else if (type == "door") opening.type = OpeningType::Door;
                else if (type == "opening") opening.type = OpeningType::Opening;
                else fail(member(at, "type"), "unknown opening type " + quote(type) + " (expected window, door or opening)");
                if (opening.type == OpeningType::Window)
                    checkKeys(o, at, {"type", "wall", "offset", "sill", "width", "height", "glazing"}, "a window");
                else if (opening.type == OpeningType::Door)
                    checkKeys(o, at, {"type", "wall", "offset", "width", "height"}, "a door");
                else
                    checkKeys(o, at, {"type", "wall", "offset", "sill", "width", "height"}, "an opening");
                const auto length = [&](const char* key) { return number(required(o, at, key), member(at, key)); };
                const double wall = integer(required(o, at, "wall"), member(at, "wall"));
                if (wall < 1 || wall > double(room.outline.size()))
                    fail(member(at, "wall"), "the room has walls 1 to " + std::to_string(room.outline.size()) + ", got " +
                                                 shortestNumber(wall));
                opening.wall = int(wall);
                opening.offset = length("offset");
                if (opening.type != OpeningType::Door) opening.sill = length("sill");
                opening.width = length("width");
                opening.height = length("height");
                if (opening.type == OpeningType::Window) opening.glazing = text(required(o, at, "glazing"), member(at, "glazing"));
                room.openings.push_back(opening);
            }
        }
    }
    if (const auto problem = roomProblem(room, scene.materials)) fail(place + "." + problem->key, problem->problem);
    return room;
}

void SceneParser::checkRooms(const Scene& scene) const {
    for (size_t i = 0; i < scene.rooms.size(); ++i) {
        const Room& r = scene.rooms[i];
        if (r.parametric()) continue;
        if (std::none_of(scene.objects.begin(), scene.objects.end(), [&](const Object& o) { return o.room == r.name; }))
            fail(item("rooms", i), "room " + quote(r.name) + " has no outline and no object is marked as its (\"room\": " +
                                       quote(r.name) + ")");
    }
}

}  // namespace lucerna
