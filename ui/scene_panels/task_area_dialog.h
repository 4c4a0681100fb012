#pragma once
// Edit > Add Task Area, and the plan's Draw Task Area once its two corners are clicked: a task
// area's fields (ui/properties/task_area_fields.h) with OK and Cancel. OK is refused, with the
// reason under the fields, while they give no valid area or its name is taken.

#include "core/photometry/plan_rectangle.h"
#include "core/scene/scene.h"

#include <QDialog>

#include <optional>
#include <string>
#include <vector>

class QDialogButtonBox;
class QLabel;

namespace lucerna {

class TaskAreaFields;

class TaskAreaDialog : public QDialog {
    Q_OBJECT
public:
    // Opens on `initial`, placed in `scene` (whose task areas' names are taken).
    TaskAreaDialog(const TaskArea& initial, const Scene& scene, QWidget* parent = nullptr);

    TaskArea area() const;
    TaskAreaFields* fields() const { return fields_; }

private:
    void check();

    std::vector<std::string> taken_;  // the scene's task areas' names
    TaskAreaFields* fields_;
    QLabel* problem_;
    QDialogButtonBox* buttons_;
};

// A new task area for `scene`: named "task area N" (free among its task areas), on the rectangle
// given (a drawn one, scene units) or the room's work plane less a 0.5 m border (its middle metre
// where the room is smaller), 0.8 m above the floor, no activity, EN 12464-1's spacing.
TaskArea newTaskArea(const Scene& scene, const std::optional<PlanRectangle>& drawn = std::nullopt);

}  // namespace lucerna
