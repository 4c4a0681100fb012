#pragma once
// Making task areas in the window (README, "Task areas"): Edit > Add Task Area... opens the task
// area dialog (ui/scene_panels/task_area_dialog.h) on a new area over the room's work plane; a
// rectangle drawn in the plan (Draw Task Area) opens it on that rectangle. OK adds the area as
// one undo step and selects it in the outliner, whose properties page then edits it.

#include "core/photometry/plan_rectangle.h"
#include "core/scene/scene.h"

#include <QObject>

#include <optional>

class QMenu;

namespace lucerna {

class Document;
class Outliner;
class WindowMessages;

class TaskAreaActions : public QObject {
    Q_OBJECT
public:
    TaskAreaActions(Document& doc, Outliner& outliner, WindowMessages& messages);

    // Adds Add Task Area... (Ctrl+Alt+T) to `menu`.
    void addTo(QMenu* menu);
    // The dialog on a new task area, over `drawn` (scene units) when given; OK adds it.
    void addTaskArea(const std::optional<PlanRectangle>& drawn = std::nullopt);
    // The plan's drawn rectangle, corners (x0, z0) and (x1, z1) in scene units: the dialog on it.
    void addDrawnTaskArea(double x0, double z0, double x1, double z1);
    // Adds `area` after the others, one undo step, and selects it; false with a one-line reason
    // (WindowMessages::lastError) when its name is empty or another task area's.
    bool add(const TaskArea& area);

private:
    Document& doc_;
    Outliner& outliner_;
    WindowMessages& messages_;
};

}  // namespace lucerna
