#include "ui/commands/task_area_commands.h"

#include <QObject>

namespace lucerna {

TaskAreaListCommand::TaskAreaListCommand(Document* doc, int index, TaskArea area, bool adds, const QString& text)
    : QUndoCommand(text), doc_(doc), index_(index), area_(std::move(area)), adds_(adds) {}

TaskAreaListCommand* TaskAreaListCommand::add(Document* doc, int index, TaskArea area) {
    const QString text = QObject::tr("Add task area %1").arg(QString::fromStdString(area.grid.name));
    return new TaskAreaListCommand(doc, index, std::move(area), true, text);
}

TaskAreaListCommand* TaskAreaListCommand::remove(Document* doc, int index) {
    const TaskArea& area = doc->taskArea(index);
    return new TaskAreaListCommand(doc, index, area, false,
                                   QObject::tr("Delete task area %1").arg(QString::fromStdString(area.grid.name)));
}

void TaskAreaListCommand::redo() {
    if (adds_) doc_->insertTaskArea(index_, area_);
    else doc_->removeTaskArea(index_);
}

void TaskAreaListCommand::undo() {
    if (adds_) doc_->removeTaskArea(index_);
    else doc_->insertTaskArea(index_, area_);
}

}  // namespace lucerna
