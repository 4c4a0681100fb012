#include "ui/scene_panels/room_dialog.h"

#include "ui/properties/number_fields.h"
#include "core/scene/scene_geometry.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>

#include <algorithm>
#include <set>

namespace lucerna {

namespace {

constexpr int kDecimals = 3;  // millimetres

std::string freeRoomName(const Scene& scene) {
    std::set<std::string> names;
    for (const Room& r : scene.rooms) names.insert(r.name);
    std::string name = "room";
    for (int i = 2; names.count(name); ++i) name = "room " + std::to_string(i);
    return name;
}

}  // namespace

RoomDialog::RoomDialog(const Room& room, const std::array<std::optional<double>, 3>& reflectances, double metersPerUnit,
                       const QString& title, QWidget* parent)
    : QDialog(parent), metersPerUnit_(metersPerUnit), original_(room), openings_(room.openings),
      originalReflectances_(reflectances) {
    setObjectName("roomDialog");
    setWindowTitle(title);
    name_ = new QLineEdit(QString::fromStdString(room.name), this);
    name_->setObjectName("roomName");
    corners_ = new QTableWidget(0, 2, this);
    corners_->setObjectName("roomCorners");
    corners_->setHorizontalHeaderLabels({tr("x (m)"), tr("z (m)")});
    corners_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    corners_->setSelectionBehavior(QAbstractItemView::SelectRows);
    corners_->setSelectionMode(QAbstractItemView::SingleSelection);
    corners_->setMinimumHeight(170);
    // The fields in it take the focus; the table itself would choose its first row on the way.
    corners_->setFocusPolicy(Qt::NoFocus);
    for (const V2d& c : room.outline) {
        addCornerRow(corners_->rowCount(), c * metersPerUnit);
        originalCorners_.push_back(c);
    }
    addCorner_ = new QPushButton(tr("Add Corner"), this);
    addCorner_->setObjectName("roomAddCorner");
    addCorner_->setToolTip(tr("A corner in the middle of the wall after the selected corner"));
    removeCorner_ = new QPushButton(tr("Remove Corner"), this);
    removeCorner_->setObjectName("roomRemoveCorner");
    connect(addCorner_, &QPushButton::clicked, this, &RoomDialog::insertCorner);
    connect(removeCorner_, &QPushButton::clicked, this, &RoomDialog::removeCorner);

    floorLevel_ = makeNumberField(this, "roomFloorLevel", room.floorLevel * metersPerUnit, -1e5, 1e5, tr(" m"), kDecimals);
    height_ = makeNumberField(this, "roomHeight", room.height * metersPerUnit, 0.1, 1e3, tr(" m"), kDecimals);
    const char* names[] = {"roomFloorReflectance", "roomWallReflectance", "roomCeilingReflectance"};
    for (size_t k = 0; k < 3; ++k) {
        reflectance_[k] = makeNumberField(this, names[k], 100 * reflectances[k].value_or(0), 0, 100, tr(" %"), 0);
        if (!reflectances[k]) {
            reflectance_[k]->setEnabled(false);
            reflectance_[k]->setToolTip(tr("The material is not diffuse or glossy: edit it in the material panel"));
        }
    }
    connect(floorLevel_, &QDoubleSpinBox::valueChanged, this, &RoomDialog::updateSummary);
    connect(height_, &QDoubleSpinBox::valueChanged, this, &RoomDialog::updateSummary);
    summary_ = new QLabel(this);
    summary_->setObjectName("roomSummary");
    summary_->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Corners in plan"), corners_);
    auto* cornerButtons = new QHBoxLayout;
    cornerButtons->addWidget(addCorner_);
    cornerButtons->addWidget(removeCorner_);
    cornerButtons->addStretch(1);
    form->addRow(QString(), cornerButtons);
    form->addRow(tr("Floor level (y)"), floorLevel_);
    form->addRow(tr("Height"), height_);
    form->addRow(tr("Floor reflectance"), reflectance_[0]);
    form->addRow(tr("Wall reflectance"), reflectance_[1]);
    form->addRow(tr("Ceiling reflectance"), reflectance_[2]);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(summary_);
    layout->addWidget(buttons);
    updateSummary();
}

void RoomDialog::addCornerRow(int row, const V2d& metres) {
    corners_->insertRow(row);
    for (int column = 0; column < 2; ++column) {
        QDoubleSpinBox* box = makeNumberField(corners_, QString(), column == 0 ? metres.x : metres.y, -1e5, 1e5, QString(), kDecimals);
        box->setFrame(false);
        connect(box, &QDoubleSpinBox::valueChanged, this, &RoomDialog::updateSummary);
        // Typing into a corner chooses its row for Add and Remove Corner: its own cell becomes the
        // current one (the view then keeps the focus in it, and Tab goes on from it). On
        // editingFinished only while it has the focus (Return): on the way out the view has made
        // the field the focus went to current, and taking the old row back sent the focus back,
        // without end under a window system.
        const auto choose = [this, box, column] {
            for (int r = 0; r < corners_->rowCount(); ++r)
                if (corners_->cellWidget(r, column) == box)
                    corners_->setCurrentCell(r, column, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        };
        connect(box, &QDoubleSpinBox::valueChanged, this, choose);
        connect(box, &QDoubleSpinBox::editingFinished, this, [box, choose] {
            if (box->hasFocus()) choose();
        });
        corners_->setCellWidget(row, column, box);
    }
    nameCornerRows();
}

void RoomDialog::nameCornerRows() {
    // By row, cornerX1, cornerZ1, ..., again after every insertion or removal.
    for (int r = 0; r < corners_->rowCount(); ++r)
        for (int column = 0; column < 2; ++column)
            if (QWidget* w = corners_->cellWidget(r, column)) w->setObjectName(QString(column == 0 ? "cornerX%1" : "cornerZ%1").arg(r + 1));
}

QDoubleSpinBox* RoomDialog::cornerField(int row, int column) const {
    return qobject_cast<QDoubleSpinBox*>(corners_->cellWidget(row, column));
}

int RoomDialog::chosenCorner() const {
    const QModelIndexList rows = corners_->selectionModel()->selectedRows();
    return rows.isEmpty() ? corners_->rowCount() - 1 : rows.front().row();
}

void RoomDialog::insertCorner() {
    const int n = corners_->rowCount();
    const int r = chosenCorner();
    const V2d a(cornerField(r, 0)->value(), cornerField(r, 1)->value());
    const V2d b(cornerField((r + 1) % n, 0)->value(), cornerField((r + 1) % n, 1)->value());
    addCornerRow(r + 1, (a + b) * 0.5);
    originalCorners_.insert(originalCorners_.begin() + r + 1, std::nullopt);
    // Wall r + 1 (1-based) is split; its openings stay on its first part, later walls move on.
    for (RoomOpening& o : openings_)
        if (o.wall > r + 1) ++o.wall;
    corners_->selectRow(r + 1);
    updateSummary();
}

void RoomDialog::removeCorner() {
    const int n = corners_->rowCount();
    const int r = chosenCorner();
    if (n <= 3) {
        summary_->setText(tr("A room needs at least 3 corners."));
        return;
    }
    // The corner's two walls become one: openings in them would lose their place.
    const int before = r == 0 ? n : r, after = r + 1;
    for (const RoomOpening& o : openings_)
        if (o.wall == before || o.wall == after) {
            summary_->setText(tr("Corner %1 has openings in its walls (%2 and %3): remove them first.").arg(r + 1).arg(before).arg(after));
            return;
        }
    corners_->removeRow(r);
    originalCorners_.erase(originalCorners_.begin() + r);
    for (RoomOpening& o : openings_)
        if (o.wall > after) --o.wall;
    nameCornerRows();
    updateSummary();
}

Room RoomDialog::room() const {
    Room r = original_;
    r.name = name_->text().trimmed().toStdString();
    r.outline.clear();
    for (int row = 0; row < corners_->rowCount(); ++row) {
        const std::optional<V2d>& was = originalCorners_[size_t(row)];
        r.outline.emplace_back(sceneValue(cornerField(row, 0), was ? std::optional(was->x) : std::nullopt, metersPerUnit_),
                               sceneValue(cornerField(row, 1), was ? std::optional(was->y) : std::nullopt, metersPerUnit_));
    }
    r.floorLevel = sceneValue(floorLevel_, original_.floorLevel, metersPerUnit_);
    r.height = sceneValue(height_, original_.height, metersPerUnit_);
    r.openings = openings_;
    return r;
}

RoomReflectances RoomDialog::reflectances() const {
    double v[3];
    for (size_t k = 0; k < 3; ++k)
        v[k] = reflectance_[k]->isEnabled() ? sceneValue(reflectance_[k], originalReflectances_[k], 100)
                                            : originalReflectances_[k].value_or(0);
    return {v[0], v[1], v[2]};
}

void RoomDialog::updateSummary() {
    const Room r = room();
    summary_->setStyleSheet(QString());
    if (auto problem = outlineProblem(r.outline)) {
        summary_->setStyleSheet("color: #b00020");
        summary_->setText(tr("The outline cannot be a room: %1.").arg(QString::fromStdString(*problem)));
        return;
    }
    const RoomAreas areas = roomAreas(r);
    const double m2 = metersPerUnit_ * metersPerUnit_;
    QString text = tr("%1 corners: floor %2 m², walls %3 m²")
                       .arg(r.outline.size())
                       .arg(areas.floor * m2, 0, 'f', 2)
                       .arg(areas.walls * m2, 0, 'f', 2);
    if (!r.openings.empty()) text += tr(" (%1 openings, %2 m²)").arg(r.openings.size()).arg(areas.openings * m2, 0, 'f', 2);
    summary_->setText(text);
}

void RoomDialog::accept() {
    const Room r = room();
    QString problem;
    if (r.name.empty()) problem = tr("A room needs a name.");
    else if (auto p = outlineProblem(r.outline)) problem = tr("The outline cannot be a room: %1.").arg(QString::fromStdString(*p));
    else if (check_) problem = check_(r, reflectances());
    if (!problem.isEmpty()) {
        summary_->setStyleSheet("color: #b00020");
        summary_->setText(problem);
        adjustSize();  // room for the reason's lines
        return;
    }
    QDialog::accept();
}

Room roomAroundScene(const Scene& scene) {
    // The camera inside too (half a metre from the walls), so that the view is of the room.
    const SceneBounds b = sceneBounds(scene);
    const double metre = 1.0 / scene.metersPerUnit;
    const V3d eye = scene.camera.position;
    double x0 = std::min(b.lo.x, eye.x - 0.5 * metre), x1 = std::max(b.hi.x, eye.x + 0.5 * metre);
    double z0 = std::min(b.lo.z, eye.z - 0.5 * metre), z1 = std::max(b.hi.z, eye.z + 0.5 * metre);
    x1 = std::max(x1, x0 + 2 * metre);
    z1 = std::max(z1, z0 + 2 * metre);
    Room r = roomOnOutline(scene, {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}});
    r.height = std::max(3.0 * metre, eye.y - b.lo.y + 0.5 * metre);
    return r;
}

Room roomOnOutline(const Scene& scene, const PlanPolygon& outline) {
    Room r;
    r.name = freeRoomName(scene);
    r.outline = outline;
    r.floorLevel = scene.objects.empty() ? 0.0 : sceneBounds(scene).lo.y;
    r.height = 3.0 / scene.metersPerUnit;
    return r;
}

}  // namespace lucerna
