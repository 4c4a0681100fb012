// The outliner's Rooms heading (README, "Rooms"): each room, drawn or marked, with its surfaces
// (the objects tagged with it) and a drawn room's openings under it.

#include "ui/scene_panels/outliner.h"

#include "core/scene/room_geometry.h"

#include <unordered_map>

namespace lucerna {

namespace {
constexpr int kOpenRoomSurfaces = 24;  // a room of more (a marked building) starts collapsed
}

void Outliner::addRooms(const Scene& scene) {
    rooms_ = new QTreeWidgetItem(this, {tr("Rooms")});
    rooms_->setFlags(Qt::ItemIsEnabled);
    QFont bold = rooms_->font(0);
    bold.setBold(true);
    rooms_->setFont(0, bold);
    roomItems_.assign(scene.rooms.size(), nullptr);
    std::unordered_map<std::string, int> byName;
    std::vector<QList<QTreeWidgetItem*>> children(scene.rooms.size());
    const double m2 = scene.metersPerUnit * scene.metersPerUnit;
    for (size_t r = 0; r < scene.rooms.size(); ++r) {
        const Room& room = scene.rooms[r];
        byName.emplace(room.name, int(r));
        roomItems_[r] = newItem(Kind::Room, int(r), room.name,
                                room.parametric() ? tr("Room, %1 m²").arg(roomAreas(room).floor * m2, 0, 'f', 1) : tr("Room, marked"));
    }
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto it = byName.find(scene.objects[i].room);
        if (it == byName.end()) continue;
        objectItems_[i] = newItem(Kind::Object, int(i), scene.objects[i].name, QString::fromStdString(scene.objects[i].material));
        children[size_t(it->second)].append(objectItems_[i]);
    }
    for (size_t r = 0; r < scene.rooms.size(); ++r) {
        std::unordered_map<int, int> counts;  // by type: window 1, window 2, door 1, ...
        for (size_t k = 0; k < scene.rooms[r].openings.size(); ++k) {
            const RoomOpening& o = scene.rooms[r].openings[k];
            const QString type = openingTypeName(o.type);
            const std::string name = type.toStdString() + " " + std::to_string(++counts[int(o.type)]);
            children[r].append(newItem(Kind::Opening, int(k), name,
                                       tr("%1 in wall %2, %3 x %4 m")
                                           .arg(type.left(1).toUpper() + type.mid(1))
                                           .arg(o.wall)
                                           .arg(o.width * scene.metersPerUnit, 0, 'f', 2)
                                           .arg(o.height * scene.metersPerUnit, 0, 'f', 2),
                                       int(r)));
        }
        rooms_->addChild(roomItems_[r]);
        roomItems_[r]->addChildren(children[r]);
        roomItems_[r]->setExpanded(children[r].size() <= kOpenRoomSurfaces);
    }
    rooms_->setExpanded(true);
}

}  // namespace lucerna
