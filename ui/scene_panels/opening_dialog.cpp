#include "ui/scene_panels/opening_dialog.h"

#include "ui/properties/number_fields.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>

namespace lucerna {

OpeningDialog::OpeningDialog(const Room& room, const RoomOpening& opening, double transmittance, double metersPerUnit,
                             const QString& title, QWidget* parent)
    : QDialog(parent), room_(room), original_(opening), metersPerUnit_(metersPerUnit) {
    setObjectName("openingDialog");
    setWindowTitle(title);
    type_ = new QComboBox(this);
    type_->setObjectName("openingType");
    type_->addItem(tr("Window (glazed)"), int(OpeningType::Window));
    type_->addItem(tr("Door (to the floor)"), int(OpeningType::Door));
    type_->addItem(tr("Opening (unglazed)"), int(OpeningType::Opening));
    type_->setCurrentIndex(type_->findData(int(opening.type)));
    wall_ = new QComboBox(this);
    wall_->setObjectName("openingWall");
    const std::vector<RoomWall> walls = roomWalls(room);
    for (size_t k = 0; k < walls.size(); ++k)
        wall_->addItem(tr("Wall %1 (%2 m)").arg(k + 1).arg(walls[k].length * metersPerUnit, 0, 'f', 2), int(k + 1));
    wall_->setCurrentIndex(std::clamp(opening.wall - 1, 0, std::max(0, wall_->count() - 1)));
    const double m = metersPerUnit;
    offset_ = makeNumberField(this, "openingOffset", opening.offset * m, 0, 1e5, tr(" m"), 3);
    sill_ = makeNumberField(this, "openingSill", opening.sill * m, 0, 1e4, tr(" m"), 3);
    width_ = makeNumberField(this, "openingWidth", opening.width * m, 0.001, 1e5, tr(" m"), 3);
    height_ = makeNumberField(this, "openingHeight", opening.height * m, 0.001, 1e4, tr(" m"), 3);
    transmittance_ = makeNumberField(this, "openingTransmittance", 100 * transmittance, 0, 100, tr(" %"), 0);
    transmittance_->setToolTip(tr("The glazing's transmittance at every angle (SPEC.md's glazing material)"));
    problem_ = new QLabel(this);
    problem_->setObjectName("openingProblem");
    problem_->setWordWrap(true);
    problem_->setStyleSheet("color: #b00020");

    auto* form = new QFormLayout;
    form->addRow(tr("Type"), type_);
    form->addRow(tr("Wall"), wall_);
    form->addRow(tr("Offset along the wall"), offset_);
    form->addRow(tr("Sill above the floor"), sill_);
    form->addRow(tr("Width"), width_);
    form->addRow(tr("Height"), height_);
    form->addRow(tr("Glazing transmittance"), transmittance_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(problem_);
    layout->addWidget(buttons);
    connect(type_, &QComboBox::currentIndexChanged, this, &OpeningDialog::typeChanged);
    typeChanged();
}

void OpeningDialog::typeChanged() {
    const auto type = OpeningType(type_->currentData().toInt());
    // A door reaches the floor; only a window holds a pane.
    if (type == OpeningType::Door) sill_->setValue(0);
    sill_->setEnabled(type != OpeningType::Door);
    transmittance_->setEnabled(type == OpeningType::Window);
    problem_->clear();
}

RoomOpening OpeningDialog::opening() const {
    RoomOpening o = original_;
    o.type = OpeningType(type_->currentData().toInt());
    o.wall = wall_->currentData().toInt();
    o.offset = sceneValue(offset_, original_.offset, metersPerUnit_);
    o.sill = o.type == OpeningType::Door ? 0.0 : sceneValue(sill_, original_.sill, metersPerUnit_);
    o.width = sceneValue(width_, original_.width, metersPerUnit_);
    o.height = sceneValue(height_, original_.height, metersPerUnit_);
    if (o.type != OpeningType::Window) o.glazing.clear();
    return o;
}

double OpeningDialog::transmittance() const { return transmittance_->value() / 100; }

void OpeningDialog::accept() {
    const QString problem = check_ ? check_(opening(), transmittance()) : QString();
    if (!problem.isEmpty()) {
        problem_->setText(problem);
        adjustSize();  // room for the reason's lines
        return;
    }
    QDialog::accept();
}

RoomOpening newOpening(const Room& room, OpeningType type, double metersPerUnit) {
    const double metre = 1.0 / metersPerUnit;
    RoomOpening o;
    o.type = type;
    const std::vector<RoomWall> walls = roomWalls(room);
    size_t longest = 0;
    for (size_t k = 1; k < walls.size(); ++k)
        if (walls[k].length > walls[longest].length) longest = k;
    o.wall = int(longest) + 1;
    const double length = walls.empty() ? 0 : walls[longest].length;
    o.width = std::min(length * 0.8, (type == OpeningType::Window ? 1.2 : type == OpeningType::Door ? 0.9 : 1.0) * metre);
    o.sill = type == OpeningType::Window ? std::min(0.9 * metre, room.height * 0.3) : 0.0;
    o.height = std::min(type == OpeningType::Window ? 1.2 * metre : 2.1 * metre, room.height * 0.9 - o.sill);
    o.offset = 0.5 * (length - o.width);
    return o;
}

}  // namespace lucerna
