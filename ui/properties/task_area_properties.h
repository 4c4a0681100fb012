#pragma once
// The properties page of a task area selected in the outliner or the plan: the fields of the
// dialog (ui/properties/task_area_fields.h), each change one undo step (EditTaskAreaCommand; a
// spin box's arrow steps merge until the field is left). A change the fields cannot take (an
// empty or taken name, an observer's value that is not a number) is refused with its reason
// under the fields, which go back to the area as it is.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"

#include <QWidget>

class QLabel;

namespace lucerna {

class TaskAreaFields;

class TaskAreaProperties : public QWidget {
    Q_OBJECT
public:
    explicit TaskAreaProperties(Document* doc, QWidget* parent = nullptr);
    ~TaskAreaProperties() override;

    // -1: none (the page shows nothing).
    void setTaskArea(int index);
    int taskArea() const { return index_; }
    TaskAreaFields* fields() const { return fields_; }
    // The reason the last change was refused (empty after a change taken).
    QString problem() const;

private:
    void refresh();
    void apply(const QObject* field);

    Document* doc_;
    int index_ = -1;
    TaskAreaFields* fields_;
    QLabel* problem_;
    MergeTracker merge_;
};

}  // namespace lucerna
