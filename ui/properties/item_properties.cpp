#include "ui/properties/item_properties.h"

#include "ui/disconnect_children.h"
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lucerna {

ItemProperties::~ItemProperties() { disconnectChildren(this); }

ItemProperties::ItemProperties(Document* doc, const QString& none, QWidget* parent) : QWidget(parent), doc_(doc) {
    if (!none.isEmpty()) empty_ = makeWrappingLabel(this, {}, none);
    fields_ = new QWidget(this);
    rows_ = new QVBoxLayout(fields_);
    rows_->setContentsMargins(0, 0, 0, 0);
    fields_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
}

void ItemProperties::select(int index) {
    if (index != index_) merge_.finish();
    index_ = index;
    refresh();
}

bool ItemProperties::showsItem(size_t count) {
    const bool valid = index_ >= 0 && size_t(index_) < count;
    if (empty_) {
        empty_->setVisible(!valid);
        fields_->setVisible(valid);
    } else {
        setVisible(valid);
    }
    return valid;
}

QDoubleSpinBox* ItemProperties::makeSpin(double lo, double hi, int decimals,
                                         std::function<void(QDoubleSpinBox*)> edited) {
    QDoubleSpinBox* spin = makePropertySpin(fields_, lo, hi, decimals);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [spin, edited = std::move(edited)] { edited(spin); });
    connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
    return spin;
}

std::vector<std::unique_ptr<QSignalBlocker>> ItemProperties::quietFields() const {
    std::vector<std::unique_ptr<QSignalBlocker>> blocks;
    for (QWidget* w : fields_->findChildren<QWidget*>()) blocks.push_back(std::make_unique<QSignalBlocker>(w));
    return blocks;
}

std::optional<std::string> ItemProperties::newName(QLineEdit* field, const std::string& current) const {
    const std::string name = field->text().trimmed().toStdString();
    if (name == current || name.empty() || doc_->nameInUse(name)) {
        field->setText(QString::fromStdString(current));
        return std::nullopt;
    }
    return name;
}

QString ItemProperties::renameText(const std::string& from, const std::string& to) const {
    return tr("Rename %1 to %2").arg(QString::fromStdString(from), QString::fromStdString(to));
}

}  // namespace lucerna
