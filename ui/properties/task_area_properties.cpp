#include "ui/properties/task_area_properties.h"

#include "ui/commands/task_area_commands.h"
#include "ui/disconnect_children.h"
#include "ui/properties/task_area_fields.h"

#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace lucerna {

TaskAreaProperties::TaskAreaProperties(Document* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), fields_(new TaskAreaFields(this)) {
    problem_ = makeWrappingLabel(this, "taskAreaPropertiesProblem");
    problem_->setStyleSheet("color: #a00000");
    problem_->hide();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(fields_);
    layout->addWidget(problem_);
    layout->addStretch(1);
    connect(fields_, &TaskAreaFields::edited, this, &TaskAreaProperties::apply);
    connect(fields_, &TaskAreaFields::finished, this, [this] { merge_.finish(); });
    connect(doc_, &Document::changed, this, &TaskAreaProperties::refresh);
    refresh();
}

TaskAreaProperties::~TaskAreaProperties() { disconnectChildren(this); }

QString TaskAreaProperties::problem() const { return problem_->text(); }

void TaskAreaProperties::setTaskArea(int index) {
    if (index != index_) {
        merge_.finish();
        problem_->clear();
        problem_->hide();
    }
    index_ = index;
    refresh();
}

void TaskAreaProperties::refresh() {
    const Scene& scene = doc_->scene();
    const bool valid = index_ >= 0 && size_t(index_) < scene.taskAreas.size();
    fields_->setVisible(valid);
    if (!valid) return;
    const TaskArea& area = scene.taskAreas[size_t(index_)];
    // Only when it differs from what the fields give (an undo, another view's edit), the floor
    // moved or the edition changed: a refresh while the user types would take the field from
    // under the keys.
    if (!(fields_->area() == area) || fields_->floorY() != taskAreaFloor(scene) ||
        fields_->metersPerUnit() != scene.metersPerUnit || fields_->edition() != lightingStandardOf(scene))
        fields_->setArea(area, scene);
}

void TaskAreaProperties::apply(const QObject* field) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || size_t(index_) >= scene.taskAreas.size()) return;
    const TaskArea& now = scene.taskAreas[size_t(index_)];
    std::optional<QString> problem = fields_->problem();
    const TaskArea after = fields_->area();
    if (!problem && doc_->taskAreaNameInUse(after.grid.name, index_))
        problem = tr("Another task area is named %1").arg(QString::fromStdString(after.grid.name));
    if (problem) {
        problem_->setText(*problem);
        problem_->show();
        fields_->setArea(now, scene);  // back to the area as it is
        return;
    }
    problem_->clear();
    problem_->hide();
    if (after == now) return;
    const QString text = after.grid.name != now.grid.name
                             ? tr("Rename task area %1 to %2").arg(QString::fromStdString(now.grid.name),
                                                                   QString::fromStdString(after.grid.name))
                             : tr("Edit task area %1").arg(QString::fromStdString(now.grid.name));
    doc_->undoStack()->push(new EditTaskAreaCommand(doc_, index_, after, merge_.keyFor(field), text));
}

}  // namespace lucerna
