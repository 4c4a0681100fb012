#include "ui/scene_panels/outliner.h"

#include "ui/commands/light_commands.h"
#include "ui/commands/light_group_commands.h"
#include "ui/commands/material_commands.h"

#include <QHeaderView>

#include <algorithm>
#include <unordered_map>

namespace lucerna {

namespace {
constexpr int kKindRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1, kGroupRole = Qt::UserRole + 2;
constexpr int kRoomRole = Qt::UserRole + 3;  // an opening's room

Outliner::Kind kindOf(const QTreeWidgetItem* item) {
    const QVariant v = item->data(0, kKindRole);
    return v.isValid() ? Outliner::Kind(v.toInt()) : Outliner::Kind::None;
}

Qt::CheckState checkOf(bool on) { return on ? Qt::Checked : Qt::Unchecked; }

// Sets a check box only when it differs: a QTreeWidget item announces every setData.
void setCheck(QTreeWidgetItem* item, Qt::CheckState state) {
    if (item->checkState(0) != state) item->setCheckState(0, state);
}
}  // namespace

Outliner::Outliner(Document* doc, QWidget* parent) : QTreeWidget(parent), doc_(doc) {
    setColumnCount(2);
    setHeaderLabels({tr("Name"), tr("Type")});
    header()->setSectionResizeMode(0, QHeaderView::Stretch);
    header()->setStretchLastSection(false);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    // One row height for all: a group of 10,000 lights lays out without measuring each row.
    setUniformRowHeights(true);
    connect(doc_, &Document::structureChanged, this, &Outliner::rebuild);
    connect(doc_, &Document::changed, this, &Outliner::refreshChecks);
    connect(this, &QTreeWidget::itemSelectionChanged, this, &Outliner::announce);
    connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (!updating_ && column == 0) checkToggled(item);
    });
    connect(this, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        if (kindOf(item) == Kind::Group) expandedGroups_.insert(item->data(0, kGroupRole).toString().toStdString());
    });
    connect(this, &QTreeWidget::itemCollapsed, this, [this](QTreeWidgetItem* item) {
        if (kindOf(item) == Kind::Group) expandedGroups_.erase(item->data(0, kGroupRole).toString().toStdString());
    });
    rebuild();
}

QTreeWidgetItem* Outliner::heading(Kind kind) const {
    switch (kind) {
    case Kind::Object: return objects_;
    case Kind::Light: return lights_;
    case Kind::Material: return materials_;
    case Kind::TaskArea: return taskAreas_;
    case Kind::Room: return rooms_;
    default: break;
    }
    return nullptr;
}

QTreeWidgetItem* Outliner::groupItem(const std::string& group) const {
    for (const auto& [name, item] : groupItems_)
        if (name == group) return item;
    return nullptr;
}

QTreeWidgetItem* Outliner::roomItem(int room) const {
    return room >= 0 && size_t(room) < roomItems_.size() ? roomItems_[size_t(room)] : nullptr;
}

QTreeWidgetItem* Outliner::newItem(Kind kind, int index, const std::string& name, const QString& type, int room) {
    auto* item = new QTreeWidgetItem(QStringList{QString::fromStdString(name), type});
    item->setData(0, kKindRole, int(kind));
    item->setData(0, kIndexRole, index);
    if (room >= 0) item->setData(0, kRoomRole, room);
    return item;
}

QTreeWidgetItem* Outliner::lightItem(int index) const {
    return index >= 0 && size_t(index) < lightItems_.size() ? lightItems_[size_t(index)] : nullptr;
}

Outliner::Selection Outliner::selection() const {
    const auto items = selectedItems();
    if (items.isEmpty()) return {};
    const Scene& scene = doc_->scene();
    if (items.size() == 1) {
        QTreeWidgetItem* item = items.front();
        const Kind kind = kindOf(item);
        if (kind == Kind::None) return {};
        if (kind == Kind::Group) {
            const std::string name = item->data(0, kGroupRole).toString().toStdString();
            return {Kind::Group, -1, groupMembers(scene, name), name};
        }
        const int index = item->data(0, kIndexRole).toInt();
        Selection s{kind, index, kind == Kind::Light ? std::vector<int>{index} : std::vector<int>{}, {}};
        if (kind == Kind::Object) s.objects = {index};
        if (kind == Kind::Opening) s.room = item->data(0, kRoomRole).toInt();
        return s;
    }
    // Several items: the lights among them, a group standing for all its lights.
    std::vector<int> lights;
    std::vector<std::string> groups;
    for (QTreeWidgetItem* item : items) {
        if (kindOf(item) == Kind::Light) lights.push_back(item->data(0, kIndexRole).toInt());
        else if (kindOf(item) == Kind::Group) groups.push_back(item->data(0, kGroupRole).toString().toStdString());
    }
    if (!groups.empty())
        for (size_t i = 0; i < scene.lights.size(); ++i)
            if (std::find(groups.begin(), groups.end(), scene.lights[i].group) != groups.end()) lights.push_back(int(i));
    std::sort(lights.begin(), lights.end());
    lights.erase(std::unique(lights.begin(), lights.end()), lights.end());
    if (lights.empty()) {
        // Objects or materials only: the first one (their panels edit one at a time); every
        // object selected for Mark as Room.
        std::vector<int> objects;
        for (QTreeWidgetItem* item : items)
            if (kindOf(item) == Kind::Object) objects.push_back(item->data(0, kIndexRole).toInt());
        std::sort(objects.begin(), objects.end());
        for (QTreeWidgetItem* item : items)
            if (kindOf(item) != Kind::None) {
                Selection s{kindOf(item), item->data(0, kIndexRole).toInt(), {}, {}};
                if (s.kind == Kind::Object) s.objects = objects;
                if (s.kind == Kind::Opening) s.room = item->data(0, kRoomRole).toInt();
                return s;
            }
        return {};
    }
    if (lights.size() == 1 && groups.empty()) return {Kind::Light, lights.front(), lights, {}};
    if (groups.size() == 1 && lights == groupMembers(scene, groups.front())) return {Kind::Group, -1, lights, groups.front()};
    return {Kind::Lights, -1, lights, {}};
}

void Outliner::select(Kind kind, int index) {
    QTreeWidgetItem* item = nullptr;
    if (kind == Kind::Light) {
        item = lightItem(index);
    } else if (kind == Kind::Object) {
        item = index >= 0 && size_t(index) < objectItems_.size() ? objectItems_[size_t(index)] : nullptr;
    } else if (QTreeWidgetItem* parent = heading(kind); parent && index >= 0 && index < parent->childCount()) {
        item = parent->child(index);
    }
    if (!item) {
        clearSelection();
        return;
    }
    // A light inside a group: its group opens so that the selection shows.
    if (QTreeWidgetItem* parent = item->parent(); parent && kindOf(parent) == Kind::Group) parent->setExpanded(true);
    // A room's surface likewise.
    if (QTreeWidgetItem* parent = item->parent(); parent && kindOf(parent) == Kind::Room) parent->setExpanded(true);
    setCurrentItem(item);
    scrollToItem(item);
}

void Outliner::selectOpening(int room, int opening) {
    QTreeWidgetItem* node = roomItem(room);
    for (int i = 0; node && i < node->childCount(); ++i) {
        QTreeWidgetItem* item = node->child(i);
        if (kindOf(item) == Kind::Opening && item->data(0, kIndexRole).toInt() == opening) {
            node->setExpanded(true);
            setCurrentItem(item);
            scrollToItem(item);
            return;
        }
    }
    clearSelection();
}

void Outliner::selectGroup(const std::string& group) {
    if (QTreeWidgetItem* item = groupItem(group)) {
        setCurrentItem(item);
        scrollToItem(item);
    } else {
        clearSelection();
    }
}

void Outliner::selectLights(const std::vector<int>& lights) {
    {
        const QSignalBlocker block(this);
        clearSelection();
        for (int i : lights)
            if (QTreeWidgetItem* item = lightItem(i)) item->setSelected(true);
    }
    announce();
}

void Outliner::announce() {
    announced_ = selection();
    emit selectionChangedTo(announced_);
}

void Outliner::restore(const Selection& keep) {
    switch (keep.kind) {
    case Kind::None: break;
    case Kind::Group:
        if (QTreeWidgetItem* item = groupItem(keep.group)) {
            setCurrentItem(item);
        } else if (!keep.lights.empty() && keep.lights.back() < int(lightItems_.size())) {
            // Renamed: the group its lights are in now, if they are all of one; else the lights.
            const std::string now = doc_->scene().lights[size_t(keep.lights.front())].group;
            if (!now.empty() && groupMembers(doc_->scene(), now) == keep.lights) setCurrentItem(groupItem(now));
            else for (int i : keep.lights) lightItems_[size_t(i)]->setSelected(true);
        }
        break;
    case Kind::Lights:
        for (int i : keep.lights)
            if (QTreeWidgetItem* item = lightItem(i)) item->setSelected(true);
        break;
    case Kind::Opening: selectOpening(keep.room, keep.index); break;
    default: select(keep.kind, keep.index); break;
    }
}

void Outliner::rebuild() {
    // What was selected as it was announced: the items' own view of it may already read the new
    // scene (a group renamed has no lights under its old name).
    const Selection keep = announced_;
    {
        // Clearing would announce an empty selection in passing; the caller hears the final one.
        const QSignalBlocker block(this);
        updating_ = true;
        clear();
        lightItems_.clear();
        groupItems_.clear();
        const Scene& scene = doc_->scene();
        const auto addHeading = [this](const QString& title) {
            auto* item = new QTreeWidgetItem(this, {title});
            item->setFlags(Qt::ItemIsEnabled);
            QFont f = item->font(0);
            f.setBold(true);
            item->setFont(0, f);
            return item;
        };
        const auto makeItem = [](Kind kind, int index, const std::string& name, const QString& type) {
            auto* item = new QTreeWidgetItem(QStringList{QString::fromStdString(name), type});
            item->setData(0, kKindRole, int(kind));
            item->setData(0, kIndexRole, index);
            return item;
        };
        // Rooms first, their surfaces under them; the other objects under Objects.
        objectItems_.assign(scene.objects.size(), nullptr);
        addRooms(scene);
        objects_ = addHeading(tr("Objects"));
        QList<QTreeWidgetItem*> children;
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (!objectItems_[i])
                children.append(objectItems_[i] = makeItem(Kind::Object, int(i), scene.objects[i].name,
                                                            QString::fromStdString(scene.objects[i].material)));
        objects_->addChildren(children);

        // Lights: a group's node stands where its first light comes; its lights go under it, added
        // in one call each (a QTreeWidget takes a list of children far faster than one by one).
        lights_ = addHeading(tr("Lights"));
        children.clear();
        std::unordered_map<std::string, QList<QTreeWidgetItem*>> members;
        std::unordered_map<std::string, std::pair<int, int>> onCount;  // group -> (on, all)
        lightItems_.resize(scene.lights.size(), nullptr);
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            QTreeWidgetItem* item = makeItem(Kind::Light, int(i), l.name, lightTypeName(l.type));
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(0, checkOf(l.on));
            lightItems_[i] = item;
            if (l.group.empty()) {
                children.append(item);
                continue;
            }
            auto [it, fresh] = members.try_emplace(l.group);
            if (fresh) {
                QTreeWidgetItem* node = makeItem(Kind::Group, -1, l.group, {});
                node->setData(0, kGroupRole, QString::fromStdString(l.group));
                node->setFlags(node->flags() | Qt::ItemIsUserCheckable);
                QFont f = node->font(0);
                f.setItalic(true);
                node->setFont(0, f);
                groupItems_.emplace_back(l.group, node);
                children.append(node);
            }
            it->second.append(item);
            auto& count = onCount[l.group];
            count.first += l.on ? 1 : 0;
            ++count.second;
        }
        lights_->addChildren(children);
        for (auto& [name, node] : groupItems_) {
            const auto [on, all] = onCount[name];
            node->setText(1, all == 1 ? tr("Group, 1 light") : tr("Group, %1 lights").arg(all));
            node->setCheckState(0, on == all ? Qt::Checked : on == 0 ? Qt::Unchecked : Qt::PartiallyChecked);
            node->addChildren(members[name]);
            node->setExpanded(expandedGroups_.count(name) > 0);
        }

        materials_ = addHeading(tr("Materials"));
        children.clear();
        for (size_t i = 0; i < scene.materials.size(); ++i)
            children.append(makeItem(Kind::Material, int(i), scene.materials[i].name, materialTypeName(scene.materials[i].type)));
        materials_->addChildren(children);
        taskAreas_ = addHeading(tr("Task areas"));
        children.clear();
        for (size_t i = 0; i < scene.taskAreas.size(); ++i) {
            const TaskArea& t = scene.taskAreas[i];
            children.append(makeItem(Kind::TaskArea, int(i), t.grid.name,
                                     t.activity.empty() ? tr("Task area") : tr("Task area, %1").arg(QString::fromStdString(t.activity))));
        }
        taskAreas_->addChildren(children);
        for (auto* h : {objects_, lights_, materials_, taskAreas_}) h->setExpanded(true);
        updating_ = false;
        restore(keep);
    }
    announce();
}

void Outliner::refreshChecks() {
    const Scene& scene = doc_->scene();
    if (lightItems_.size() != scene.lights.size()) return;  // a rebuild follows
    updating_ = true;
    std::unordered_map<std::string, std::pair<int, int>> onCount;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        setCheck(lightItems_[i], checkOf(l.on));
        if (!l.group.empty()) {
            auto& count = onCount[l.group];
            count.first += l.on ? 1 : 0;
            ++count.second;
        }
    }
    for (auto& [name, node] : groupItems_) {
        const auto [on, all] = onCount[name];
        setCheck(node, on == all ? Qt::Checked : on == 0 ? Qt::Unchecked : Qt::PartiallyChecked);
    }
    updating_ = false;
}

void Outliner::checkToggled(QTreeWidgetItem* item) {
    const Kind kind = kindOf(item);
    if (kind != Kind::Light && kind != Kind::Group) return;
    const Scene& scene = doc_->scene();
    const bool on = item->checkState(0) != Qt::Unchecked;
    const std::vector<int> targets =
        kind == Kind::Light ? std::vector<int>{item->data(0, kIndexRole).toInt()}
                            : groupMembers(scene, item->data(0, kGroupRole).toString().toStdString());
    std::vector<int> indices;
    std::vector<Light> after;
    for (int i : targets) {
        if (i < 0 || size_t(i) >= scene.lights.size() || scene.lights[size_t(i)].on == on) continue;
        indices.push_back(i);
        after.push_back(scene.lights[size_t(i)]);
        after.back().on = on;
    }
    if (indices.empty()) {
        refreshChecks();
        return;
    }
    const QString what = kind == Kind::Group ? tr("group %1").arg(item->text(0)) : item->text(0);
    doc_->undoStack()->push(new EditLightsCommand(doc_, std::move(indices), std::move(after), 0,
                                                  on ? tr("Switch on %1").arg(what) : tr("Switch off %1").arg(what)));
}

}  // namespace lucerna
