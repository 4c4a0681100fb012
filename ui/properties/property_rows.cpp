#include "ui/properties/property_rows.h"

#include "ui/viewport/viewport.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace lucerna {

QWidget* addPropertyRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields) {
    auto* row = new QWidget(rows->parentWidget());
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    auto* l = new QLabel(label, row);
    l->setMinimumWidth(110);
    h->addWidget(l);
    for (QWidget* f : fields) {
        f->setParent(row);
        h->addWidget(f, 1);
    }
    rows->addWidget(row);
    return row;
}

QWidget* addStackedPropertyRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields) {
    auto* row = new QWidget(rows->parentWidget());
    auto* v = new QVBoxLayout(row);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(2);
    v->addWidget(new QLabel(label, row));
    auto* h = new QHBoxLayout;
    for (QWidget* f : fields) {
        f->setParent(row);
        h->addWidget(f, 1);
    }
    v->addLayout(h);
    rows->addWidget(row);
    return row;
}

QWidget* addTripleRow(QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields,
                      std::initializer_list<QString> names) {
    auto* row = new QWidget(rows->parentWidget());
    auto* grid = new QGridLayout(row);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(4);
    grid->addWidget(new QLabel(label, row), 0, 0, 1, 2 * int(fields.size()));
    int column = 0;
    auto name = names.begin();
    for (QWidget* f : fields) {
        auto* short_ = new QLabel(name != names.end() ? *name++ : QString(), row);
        short_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        f->setParent(row);
        // Narrower than a row's fields may be elsewhere: three of them and their names share
        // the dock's width.
        f->setMinimumWidth(44);
        grid->addWidget(short_, 1, column);
        grid->addWidget(f, 1, column + 1);
        grid->setColumnStretch(column + 1, 1);
        column += 2;
    }
    rows->addWidget(row);
    return row;
}

QLabel* rowLabel(QWidget* row) { return row->findChild<QLabel*>(QString(), Qt::FindDirectChildrenOnly); }

QLabel* makeWrappingLabel(QWidget* parent, const QString& name, const QString& text) {
    auto* label = new QLabel(text, parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    return label;
}

QDoubleSpinBox* makePropertySpin(QWidget* parent, double lo, double hi, int decimals) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setKeyboardTracking(false);
    spin->setRange(lo, hi);
    spin->setDecimals(decimals);
    spin->setAccelerated(true);
    spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    spin->setMinimumWidth(60);
    return spin;
}

int MergeTracker::keyFor(const void* field) {
    if (field != last_) {
        last_ = field;
        key_ = nextMergeKey();
    }
    return key_;
}

}  // namespace lucerna
