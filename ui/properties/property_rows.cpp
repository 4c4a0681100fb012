#include "ui/properties/property_rows.h"

#include "ui/viewport/viewport.h"

#include <QDoubleSpinBox>
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
