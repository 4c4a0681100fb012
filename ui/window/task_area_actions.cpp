#include "ui/window/task_area_actions.h"

#include "ui/commands/task_area_commands.h"
#include "ui/document/document.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/task_area_dialog.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <QMainWindow>
#include <QMenu>

#include <algorithm>
#include <cmath>

namespace lucerna {

TaskAreaActions::TaskAreaActions(Document& doc, Outliner& outliner, WindowMessages& messages)
    : doc_(doc), outliner_(outliner), messages_(messages) {}

void TaskAreaActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("Add &Task Area..."), "actionAddTaskArea", QKeySequence(tr("Ctrl+Alt+T")), this,
                 [this] { addTaskArea(); });
}

void TaskAreaActions::addTaskArea(const std::optional<PlanRectangle>& drawn) {
    TaskAreaDialog dialog(newTaskArea(doc_.scene(), drawn), doc_.scene(), messages_.window());
    if (dialog.exec() == QDialog::Accepted) messages_.warnUnless(add(dialog.area()), tr("Add task area"));
}

void TaskAreaActions::addDrawnTaskArea(double x0, double z0, double x1, double z1) {
    PlanRectangle r;
    r.x0 = std::min(x0, x1);
    r.z0 = std::min(z0, z1);
    r.width = std::abs(x1 - x0);
    r.depth = std::abs(z1 - z0);
    addTaskArea(r);
}

bool TaskAreaActions::add(const TaskArea& area) {
    if (area.grid.name.empty()) return messages_.fail(tr("A task area needs a name"));
    if (doc_.taskAreaNameInUse(area.grid.name))
        return messages_.fail(tr("Another task area is named %1").arg(QString::fromStdString(area.grid.name)));
    const int index = int(doc_.scene().taskAreas.size());
    doc_.undoStack()->push(TaskAreaListCommand::add(&doc_, index, area));
    outliner_.select(Outliner::Kind::TaskArea, index);
    messages_.show(tr("Added task area %1").arg(QString::fromStdString(area.grid.name)), 5000);
    return true;
}

}  // namespace lucerna
