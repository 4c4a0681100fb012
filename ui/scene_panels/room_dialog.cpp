#include "ui/scene_panels/room_dialog.h"

#include "core/scene/scene_geometry.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>

#include <algorithm>

namespace lucerna {

namespace {
QDoubleSpinBox* field(QWidget* parent, const char* name, double value, double lo, double hi, const QString& suffix,
                      int decimals = 2) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}
}  // namespace

RoomDialog::RoomDialog(const RoomSpec& initial, QWidget* parent) : QDialog(parent) {
    setObjectName("roomDialog");
    setWindowTitle(tr("Add room"));
    name_ = new QLineEdit(QString::fromStdString(initial.name), this);
    name_->setObjectName("roomName");
    x_ = field(this, "roomX", initial.corner.x, -1e6, 1e6, QString());
    y_ = field(this, "roomY", initial.corner.y, -1e6, 1e6, QString());
    z_ = field(this, "roomZ", initial.corner.z, -1e6, 1e6, QString());
    width_ = field(this, "roomWidth", initial.width, 0.1, 1e4, tr(" m"));
    depth_ = field(this, "roomDepth", initial.depth, 0.1, 1e4, tr(" m"));
    height_ = field(this, "roomHeight", initial.height, 0.1, 1e3, tr(" m"));
    floor_ = field(this, "roomFloorReflectance", 100 * initial.floorReflectance, 0, 100, tr(" %"), 0);
    walls_ = field(this, "roomWallReflectance", 100 * initial.wallReflectance, 0, 100, tr(" %"), 0);
    ceiling_ = field(this, "roomCeilingReflectance", 100 * initial.ceilingReflectance, 0, 100, tr(" %"), 0);
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Floor corner x (least)"), x_);
    form->addRow(tr("Floor level y"), y_);
    form->addRow(tr("Floor corner z (least)"), z_);
    form->addRow(tr("Width (along x)"), width_);
    form->addRow(tr("Depth (along z)"), depth_);
    form->addRow(tr("Height"), height_);
    form->addRow(tr("Floor reflectance"), floor_);
    form->addRow(tr("Wall reflectance"), walls_);
    form->addRow(tr("Ceiling reflectance"), ceiling_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

RoomSpec RoomDialog::spec() const {
    RoomSpec s;
    s.name = name_->text().trimmed().toStdString();
    s.corner = V3d(x_->value(), y_->value(), z_->value());
    s.width = width_->value();
    s.depth = depth_->value();
    s.height = height_->value();
    s.floorReflectance = floor_->value() / 100;
    s.wallReflectance = walls_->value() / 100;
    s.ceilingReflectance = ceiling_->value() / 100;
    return s;
}

RoomSpec roomAroundScene(const Scene& scene) {
    RoomSpec s;
    int rooms = 1;
    for (const Object& o : scene.objects) rooms += o.name.rfind("room ", 0) == 0 && o.name.ends_with(" floor");
    s.name = rooms == 1 ? "room" : "room " + std::to_string(rooms);
    // The camera inside too (half a metre from the walls), so that the view is of the room.
    const SceneBounds b = sceneBounds(scene);
    const double metre = 1.0 / scene.metersPerUnit;
    const V3d eye = scene.camera.position;
    const double x0 = std::min(b.lo.x, eye.x - 0.5 * metre), x1 = std::max(b.hi.x, eye.x + 0.5 * metre);
    const double z0 = std::min(b.lo.z, eye.z - 0.5 * metre), z1 = std::max(b.hi.z, eye.z + 0.5 * metre);
    s.corner = V3d(x0, b.lo.y, z0);
    s.width = std::max((x1 - x0) / metre, 2.0);
    s.depth = std::max((z1 - z0) / metre, 2.0);
    s.height = std::max(3.0, (eye.y - b.lo.y) / metre + 0.5);
    return s;
}

}  // namespace lucerna
