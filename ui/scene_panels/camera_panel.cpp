#include "ui/scene_panels/camera_panel.h"

#include "ui/disconnect_children.h"
#include "core/scene/scene_geometry.h"
#include "ui/viewport/camera_navigation.h"
#include "ui/commands/scene_commands.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace lucerna {

CameraPanel::~CameraPanel() { disconnectChildren(this); }

CameraPanel::CameraPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc), home_(doc->scene().camera) {
    auto* rows = new QVBoxLayout(this);
    const auto triple = [this](std::array<QDoubleSpinBox*, 3>& spins, const char* name) {
        for (int i = 0; i < 3; ++i) {
            QDoubleSpinBox* s = makePropertySpin(this, -1e9, 1e9, 3);
            s->setObjectName(QStringLiteral("%1%2").arg(name).arg(i));
            connect(s, &QDoubleSpinBox::valueChanged, this, [this, s] { apply(s); });
            connect(s, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
            spins[size_t(i)] = s;
        }
    };
    triple(position_, "cameraPosition");
    triple(target_, "cameraTarget");
    fov_ = makePropertySpin(this, 1, 170, 2);
    fov_->setObjectName("cameraFov");
    fov_->setSuffix(QStringLiteral(" °"));
    connect(fov_, &QDoubleSpinBox::valueChanged, this, [this] { apply(fov_); });
    connect(fov_, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
    addPropertyRow(rows, tr("Position"), {position_[0], position_[1], position_[2]});
    addPropertyRow(rows, tr("Target"), {target_[0], target_[1], target_[2]});
    addPropertyRow(rows, tr("Field of view (vertical)"), {fov_});
    auto* buttons = new QHBoxLayout;
    auto* all = new QPushButton(tr("View All"), this);
    all->setObjectName("cameraViewAll");
    auto* reset = new QPushButton(tr("Reset Camera"), this);
    reset->setObjectName("cameraReset");
    buttons->addWidget(all);
    buttons->addWidget(reset);
    rows->addLayout(buttons);
    error_ = makeWrappingLabel(this, "cameraError");
    rows->addWidget(error_);
    rows->addStretch(1);
    connect(all, &QPushButton::clicked, this, &CameraPanel::viewAll);
    connect(reset, &QPushButton::clicked, this, &CameraPanel::resetCamera);

    connect(doc_, &Document::cameraChanged, this, &CameraPanel::refresh);
    connect(doc_, &Document::replaced, this, [this] {
        merge_.finish();
        home_ = doc_->scene().camera;
    });
    // Saved (or undone back to the saved state): that camera is the one to return to.
    connect(doc_->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean) home_ = doc_->scene().camera;
    });
    refresh();
}

void CameraPanel::refresh() {
    const Camera& c = doc_->scene().camera;
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker a(position_[size_t(i)]), b(target_[size_t(i)]);
        position_[size_t(i)]->setValue(c.position[i]);
        target_[size_t(i)]->setValue(c.target[i]);
    }
    const QSignalBlocker f(fov_);
    fov_->setValue(c.fovYDeg);
}

void CameraPanel::apply(const void* field) {
    Camera c = doc_->scene().camera;
    for (int i = 0; i < 3; ++i) {
        c.position[i] = position_[size_t(i)]->value();
        c.target[i] = target_[size_t(i)]->value();
    }
    c.fovYDeg = fov_->value();
    const V3d view = c.target - c.position;
    QString why;
    if (view.length() <= 1e-9 * std::max(1.0, c.position.length())) why = tr("The target must differ from the position.");
    else if (view.normalized().cross(c.up.normalized()).length() < 1e-6)
        why = tr("The camera cannot look straight along its up direction.");
    if (!why.isEmpty()) {
        error_->setText(why);
        emit message(why);
        refresh();  // the fields show the camera as it still is
        return;
    }
    error_->clear();
    if (c == doc_->scene().camera) return;
    doc_->undoStack()->push(new EditCameraCommand(doc_, c, merge_.keyFor(field), tr("Edit camera")));
}

void CameraPanel::viewAll() {
    merge_.finish();
    error_->clear();
    const SceneBounds b = sceneBounds(doc_->scene());
    const Camera c = framedCamera(doc_->scene().camera, b.lo, b.hi);
    if (c != doc_->scene().camera) doc_->undoStack()->push(new EditCameraCommand(doc_, c, 0, tr("View all")));
}

void CameraPanel::resetCamera() {
    merge_.finish();
    error_->clear();
    if (home_ != doc_->scene().camera) doc_->undoStack()->push(new EditCameraCommand(doc_, home_, 0, tr("Reset camera")));
}

}  // namespace lucerna
