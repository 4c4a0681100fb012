#pragma once
// The building blocks the property panels share: a labelled row of fields (a widget of its own,
// so that hiding a row leaves no gap, which a QFormLayout would) and a numeric field that counts
// a typed value when Enter is pressed or the field is left, not at every keystroke.

#include <QString>

#include <initializer_list>

class QDoubleSpinBox;
class QLabel;
class QVBoxLayout;
class QWidget;

namespace lucerna {

// Adds a row `label: fields...` to `rows` (whose widget is the rows' parent); the label is the
// row's first QLabel child.
QWidget* addPropertyRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields);
QLabel* rowLabel(QWidget* row);
// A row for a field too wide to stand beside its label in a narrow dock (a colour's mode and
// value, a maintenance factor's mode and assistant): `label` on a line of its own, the fields
// under it at the row's full width. rowLabel() finds `label`.
QWidget* addStackedPropertyRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields);
// A row of three fields that fits a narrow dock: `label` on a line of its own, under it the
// fields side by side, each after its short name (x, y, z). rowLabel() finds `label`.
QWidget* addTripleRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields,
                      std::initializer_list<QString> names = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")});

// A label whose text wraps to the panel's width, named `name` (tests find it by it).
QLabel* makeWrappingLabel(QWidget* parent, const QString& name, const QString& text = {});

// A spin box for a property: no keyboard tracking, accelerated arrows, and a width the layout
// shares (three in a row must not widen the dock past the viewport).
QDoubleSpinBox* makePropertySpin(QWidget* parent, double lo, double hi, int decimals);

// Undo merging for a panel: edits from the same field fold into one command until the field's
// editing finishes (Enter, focus out, slider release); then the next edit is a new step.
class MergeTracker {
public:
    // The merge key for an edit from `field`.
    int keyFor(const void* field);
    void finish() { last_ = nullptr; }

private:
    const void* last_ = nullptr;
    int key_ = 0;
};

}  // namespace lucerna
