#include "ui/scene_panels/task_area_dialog.h"

#include "core/scene/scene_geometry.h"
#include "ui/properties/property_rows.h"
#include "ui/properties/task_area_fields.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace lucerna {

TaskAreaDialog::TaskAreaDialog(const TaskArea& initial, const Scene& scene, QWidget* parent)
    : QDialog(parent), fields_(new TaskAreaFields(this)) {
    for (const TaskArea& t : scene.taskAreas) taken_.push_back(t.grid.name);
    setObjectName("taskAreaDialog");
    setWindowTitle(tr("Add task area"));
    fields_->setArea(initial, scene);
    problem_ = makeWrappingLabel(this, "taskAreaProblem");
    problem_->setStyleSheet("color: #a00000");
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(fields_, &TaskAreaFields::edited, this, &TaskAreaDialog::check);
    connect(fields_->nameField(), &QLineEdit::textEdited, this, &TaskAreaDialog::check);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(fields_);
    layout->addWidget(problem_);
    layout->addWidget(buttons_);
    check();
}

void TaskAreaDialog::check() {
    std::optional<QString> problem = fields_->problem();
    const std::string name = fields_->nameField()->text().trimmed().toStdString();
    if (!problem && std::find(taken_.begin(), taken_.end(), name) != taken_.end())
        problem = tr("Another task area is named %1").arg(QString::fromStdString(name));
    problem_->setText(problem.value_or(QString()));
    problem_->setVisible(problem.has_value());
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(!problem);
}

TaskArea TaskAreaDialog::area() const { return fields_->area(); }

TaskArea newTaskArea(const Scene& scene, const std::optional<PlanRectangle>& drawn) {
    TaskArea a;
    const auto taken = [&](const std::string& name) {
        return std::any_of(scene.taskAreas.begin(), scene.taskAreas.end(), [&](const TaskArea& t) { return t.grid.name == name; });
    };
    for (int n = int(scene.taskAreas.size()) + 1;; ++n)
        if (!taken(a.grid.name = "task area " + std::to_string(n))) break;
    const double metre = 1.0 / scene.metersPerUnit;
    const double floorY = taskAreaFloor(scene);
    PlanRectangle r;
    if (drawn) {
        r = *drawn;
    } else {
        const SceneBounds b = sceneBounds(scene);
        const double border = 0.5 * metre;
        if (b.hi.x - b.lo.x > 2 * border + metre && b.hi.z - b.lo.z > 2 * border + metre)
            r = {b.lo.x + border, b.lo.z + border, b.hi.x - b.lo.x - 2 * border, b.hi.z - b.lo.z - 2 * border, 0};
        else
            r = {b.center.x - 0.5 * metre, b.center.z - 0.5 * metre, metre, metre, 0};
    }
    r.y = floorY + 0.8 * metre;
    a.grid = gridOfPlanRectangle(r, a.grid);
    return a;
}

}  // namespace lucerna
