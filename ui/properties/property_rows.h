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
