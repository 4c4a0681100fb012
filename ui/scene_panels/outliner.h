#pragma once
// The outliner: the scene's objects, lights, materials and task areas under four headings. Lights of a
// group (the lights' "group" key) sit under a node of their group, collapsed until opened, so a
// field of 10,000 luminaires is one line; every light and group has a check box that switches it
// on and off (one undo step for a whole group). Several lights and groups can be selected at once
// (Ctrl or Shift click). It rebuilds itself when the document's structure changes (add, delete,
// rename, regroup) and keeps the selection where it can.

#include "ui/document/document.h"

#include <QTreeWidget>

#include <set>
#include <string>
#include <vector>

namespace lucerna {

class Outliner : public QTreeWidget {
    Q_OBJECT
public:
    // Group: one group node; Lights: several lights and groups together.
    // TaskArea: one of the scene's task areas (README, "Task areas"), under their own heading.
    // Room: one of the scene's rooms, its surfaces (objects) and openings under it (README,
    // "Rooms"; outliner_rooms.cpp); Opening: one of a room's openings.
    enum class Kind { None, Object, Light, Material, Group, Lights, TaskArea, Room, Opening };
    struct Selection {
        Kind kind = Kind::None;
        int index = -1;           // Object, Light, Material, TaskArea
        std::vector<int> lights;  // Light, Group, Lights: the lights selected (a group's members), ascending
        std::string group;        // Group: its name
        int room = -1;            // Opening: its room (index is the opening's)
        std::vector<int> objects; // Object: every object selected, ascending
        bool operator==(const Selection&) const = default;
    };

    explicit Outliner(Document* doc, QWidget* parent = nullptr);

    Selection selection() const;
    void select(Kind kind, int index);
    void selectGroup(const std::string& group);
    void selectOpening(int room, int opening);
    // The node of a room, or null.
    QTreeWidgetItem* roomItem(int room) const;
    void selectLights(const std::vector<int>& lights);
    // The heading item of a kind (tests walk its children).
    QTreeWidgetItem* heading(Kind kind) const;
    // The node of a group, or null.
    QTreeWidgetItem* groupItem(const std::string& group) const;
    // The item of a light (under its group's node or the Lights heading), or null.
    QTreeWidgetItem* lightItem(int index) const;
    QSize sizeHint() const override { return {280, 300}; }

signals:
    void selectionChangedTo(lucerna::Outliner::Selection selection);

private:
    void rebuild();
    // The Rooms heading: each room with its surfaces and openings (outliner_rooms.cpp).
    void addRooms(const Scene& scene);
    // An item of `kind` for the item at `index` (an opening's: of room `room`).
    static QTreeWidgetItem* newItem(Kind kind, int index, const std::string& name, const QString& type, int room = -1);
    void refreshChecks();
    void checkToggled(QTreeWidgetItem* item);
    void restore(const Selection& keep);
    void announce();

    Document* doc_;
    QTreeWidgetItem *objects_ = nullptr, *lights_ = nullptr, *materials_ = nullptr, *taskAreas_ = nullptr;
    std::vector<QTreeWidgetItem*> lightItems_;           // by light index
    QTreeWidgetItem* rooms_ = nullptr;
    std::vector<QTreeWidgetItem*> objectItems_, roomItems_;  // by object and room index
    std::vector<std::pair<std::string, QTreeWidgetItem*>> groupItems_;
    std::set<std::string> expandedGroups_;               // kept open across rebuilds
    bool updating_ = false;                              // check states set by the outliner itself
    Selection announced_;                                // the selection last announced
};

}  // namespace lucerna
