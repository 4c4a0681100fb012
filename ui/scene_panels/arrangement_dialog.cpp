#include "ui/scene_panels/arrangement_dialog.h"

#include "core/scene/scene_geometry.h"
#include "ui/commands/light_commands.h"
#include "ui/document/document.h"
#include "ui/io/luminaire_import.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>
#include <stdexcept>

namespace lucerna {

namespace {
enum Source { kSelected, kPoint, kFile };  // the luminaire list's data

QDoubleSpinBox* lengthSpin(QWidget* parent, const QString& suffix, double lo, double hi) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setRange(lo, hi);
    spin->setDecimals(3);
    spin->setSingleStep(0.1);
    spin->setSuffix(suffix);
    spin->setKeyboardTracking(false);
    return spin;
}
}  // namespace

ArrangementDialog::ArrangementDialog(const Document& doc, int selectedLight, QWidget* parent)
    : QDialog(parent), doc_(doc), selectedLight_(selectedLight) {
    setWindowTitle(tr("Arrange Lights"));
    setObjectName("arrangementDialog");
    const Scene& scene = doc.scene();
    const QString unit = QStringLiteral(" ") + lengthUnit(scene);
    auto* form = new QFormLayout;

    source_ = new QComboBox(this);
    source_->setObjectName("arrangeSource");
    const bool selectable = selectedLight >= 0 && size_t(selectedLight) < scene.lights.size() &&
                            scene.lights[size_t(selectedLight)].type != LightType::Directional;
    if (selectable)
        source_->addItem(tr("The selected light, %1").arg(QString::fromStdString(scene.lights[size_t(selectedLight)].name)), kSelected);
    source_->addItem(tr("Point light, 1000 lm at 3000 K"), kPoint);
    source_->addItem(tr("Luminaire file (IES, EULUMDAT)"), kFile);
    form->addRow(tr("Luminaire"), source_);
    file_ = new QLineEdit(this);
    file_->setObjectName("arrangeFile");
    browse_ = new QPushButton(tr("Browse..."), this);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(file_, 1);
    fileRow->addWidget(browse_);
    form->addRow(tr("File"), fileRow);

    const char* names[4] = {"arrangeX0", "arrangeZ0", "arrangeX1", "arrangeZ1"};
    for (size_t k = 0; k < 4; ++k) {
        rect_[k] = lengthSpin(this, unit, -1e7, 1e7);
        rect_[k]->setObjectName(names[k]);
    }
    auto* from = new QHBoxLayout, *to = new QHBoxLayout;
    from->addWidget(new QLabel(tr("x"), this));
    from->addWidget(rect_[0], 1);
    from->addWidget(new QLabel(tr("z"), this));
    from->addWidget(rect_[1], 1);
    to->addWidget(new QLabel(tr("x"), this));
    to->addWidget(rect_[2], 1);
    to->addWidget(new QLabel(tr("z"), this));
    to->addWidget(rect_[3], 1);
    form->addRow(tr("Rectangle from"), from);
    form->addRow(tr("to"), to);

    byCount_ = new QRadioButton(tr("By count"), this);
    byCount_->setObjectName("arrangeByCount");
    bySpacing_ = new QRadioButton(tr("By spacing"), this);
    bySpacing_->setObjectName("arrangeBySpacing");
    byCount_->setChecked(true);
    columns_ = new QSpinBox(this);
    columns_->setObjectName("arrangeColumns");
    rows_ = new QSpinBox(this);
    rows_->setObjectName("arrangeRows");
    for (QSpinBox* s : {columns_, rows_}) {
        s->setRange(1, kMaxFieldLights);
        s->setKeyboardTracking(false);
    }
    auto* count = new QHBoxLayout;
    count->addWidget(byCount_);
    count->addWidget(columns_, 1);
    count->addWidget(new QLabel(tr("along x by"), this));
    count->addWidget(rows_, 1);
    count->addWidget(new QLabel(tr("along z"), this));
    form->addRow(tr("Field"), count);
    spacingX_ = lengthSpin(this, tr(" m"), 0.001, 1e6);
    spacingX_->setObjectName("arrangeSpacingX");
    spacingZ_ = lengthSpin(this, tr(" m"), 0.001, 1e6);
    spacingZ_->setObjectName("arrangeSpacingZ");
    auto* spacing = new QHBoxLayout;
    spacing->addWidget(bySpacing_);
    spacing->addWidget(spacingX_, 1);
    spacing->addWidget(new QLabel(tr("along x by"), this));
    spacing->addWidget(spacingZ_, 1);
    spacing->addWidget(new QLabel(tr("along z"), this));
    form->addRow(QString(), spacing);

    ceiling_ = lengthSpin(this, unit, -1e7, 1e7);
    ceiling_->setObjectName("arrangeCeiling");
    ceiling_->setToolTip(tr("The height (y) of the ceiling the field hangs from"));
    form->addRow(tr("Ceiling at y"), ceiling_);
    suspension_ = lengthSpin(this, tr(" m"), 0, 1e4);
    suspension_->setObjectName("arrangeSuspension");
    suspension_->setToolTip(tr("How far below the ceiling the lights hang: their centres are at y = ceiling - suspension"));
    form->addRow(tr("Suspension below it"), suspension_);
    group_ = new QLineEdit(QString::fromStdString(unusedGroupName(scene, "field")), this);
    group_->setObjectName("arrangeGroup");
    form->addRow(tr("Group"), group_);

    summary_ = new QLabel(this);
    summary_->setObjectName("arrangeSummary");
    error_ = new QLabel(this);
    error_->setObjectName("arrangeError");
    error_->setStyleSheet("color: #b00000");
    error_->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(summary_);
    layout->addWidget(error_);
    layout->addWidget(buttons);

    // Defaults: the scene's plan, one light every 1.5 m or so, 0.1 m under the ceiling.
    const SceneBounds b = sceneBounds(scene);
    const double mpu = scene.metersPerUnit;
    spacingX_->setValue(1.5);
    spacingZ_->setValue(1.5);
    suspension_->setValue(0.1);
    columns_->setValue(std::max(1, int(std::lround((b.hi.x - b.lo.x) * mpu / 1.5))));
    rows_->setValue(std::max(1, int(std::lround((b.hi.z - b.lo.z) * mpu / 1.5))));
    setRectangle(b.lo.x, b.lo.z, b.hi.x, b.hi.z);

    const auto changed = [this] { updateSummary(); };
    for (QDoubleSpinBox* s : {rect_[0], rect_[1], rect_[2], rect_[3], spacingX_, spacingZ_, ceiling_, suspension_})
        connect(s, &QDoubleSpinBox::valueChanged, this, changed);
    for (QSpinBox* s : {columns_, rows_}) connect(s, &QSpinBox::valueChanged, this, changed);
    connect(byCount_, &QRadioButton::toggled, this, changed);
    connect(group_, &QLineEdit::textChanged, this, changed);
    connect(file_, &QLineEdit::textChanged, this, changed);
    connect(source_, &QComboBox::currentIndexChanged, this, changed);
    connect(browse_, &QPushButton::clicked, this, [this] {
        const QString path = askFile_ ? askFile_() : QString();
        if (!path.isEmpty()) setLuminaireFile(path);
    });
    updateSummary();
}

void ArrangementDialog::setRectangle(double x0, double z0, double x1, double z1) {
    const double v[4] = {x0, z0, x1, z1};
    for (size_t k = 0; k < 4; ++k) rect_[k]->setValue(v[k]);
    ceiling_->setValue(ceilingAbove(doc_.scene(), (x0 + x1) / 2, (z0 + z1) / 2));
}

void ArrangementDialog::setArrangement(const FieldArrangement& f) {
    const double v[4] = {f.x0, f.z0, f.x1, f.z1};
    for (size_t k = 0; k < 4; ++k) rect_[k]->setValue(v[k]);
    (f.bySpacing ? bySpacing_ : byCount_)->setChecked(true);
    columns_->setValue(f.columns);
    rows_->setValue(f.rows);
    spacingX_->setValue(f.spacingXm);
    spacingZ_->setValue(f.spacingZm);
    ceiling_->setValue(f.ceilingY);
    suspension_->setValue(f.suspensionM);
}

FieldArrangement ArrangementDialog::arrangement() const {
    FieldArrangement f;
    f.x0 = rect_[0]->value();
    f.z0 = rect_[1]->value();
    f.x1 = rect_[2]->value();
    f.z1 = rect_[3]->value();
    f.bySpacing = bySpacing_->isChecked();
    f.columns = columns_->value();
    f.rows = rows_->value();
    f.spacingXm = spacingX_->value();
    f.spacingZm = spacingZ_->value();
    f.ceilingY = ceiling_->value();
    f.suspensionM = suspension_->value();
    return f;
}

std::string ArrangementDialog::group() const { return group_->text().trimmed().toStdString(); }

void ArrangementDialog::setLuminaireFile(const QString& path) {
    source_->setCurrentIndex(source_->findData(kFile));
    file_->setText(path);
}

Light ArrangementDialog::prototype() const {
    const Scene& scene = doc_.scene();
    switch (source_->currentData().toInt()) {
    case kSelected: return scene.lights.at(size_t(selectedLight_));
    case kFile: {
        if (file_->text().trimmed().isEmpty()) throw std::runtime_error("choose a luminaire file (IES or EULUMDAT)");
        try {
            Light l = luminaireFromFile(doc_, file_->text().trimmed());
            l.photometric.reset();
            return l;
        } catch (const std::exception& e) {
            throw std::runtime_error("cannot read " + file_->text().trimmed().toStdString() + ": " + e.what());
        }
    }
    default: {
        Light l = defaultLight(scene, LightType::Point, "light");
        l.direction = V3d(0, -1, 0);
        return l;
    }
    }
}

QString ArrangementDialog::problem() const {
    try {
        layoutField(arrangement(), doc_.scene().metersPerUnit);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    if (group().empty()) return tr("the field's group needs a name");
    if (source_->currentData().toInt() == kFile && file_->text().trimmed().isEmpty())
        return tr("choose a luminaire file (IES or EULUMDAT)");
    return {};
}

void ArrangementDialog::updateSummary() {
    const bool file = source_->currentData().toInt() == kFile;
    file_->setEnabled(file);
    browse_->setEnabled(file);
    columns_->setEnabled(byCount_->isChecked());
    rows_->setEnabled(byCount_->isChecked());
    spacingX_->setEnabled(bySpacing_->isChecked());
    spacingZ_->setEnabled(bySpacing_->isChecked());
    const Scene& scene = doc_.scene();
    try {
        const FieldArrangement f = arrangement();
        const FieldLayout layout = layoutField(f, scene.metersPerUnit);
        const double mpu = scene.metersPerUnit;
        const double dx = layout.columns > 1 ? (layout.positions[1].x - layout.positions[0].x) * mpu
                                             : std::abs(f.x1 - f.x0) * mpu;
        const double dz = layout.rows > 1 ? (layout.positions[size_t(layout.columns)].z - layout.positions[0].z) * mpu
                                          : std::abs(f.z1 - f.z0) * mpu;
        summary_->setText(tr("%1 x %2 = %3 lights, %4 m apart along x and %5 m along z, at y = %6")
                              .arg(layout.columns)
                              .arg(layout.rows)
                              .arg(layout.positions.size())
                              .arg(dx, 0, 'g', 4)
                              .arg(dz, 0, 'g', 4)
                              .arg(layout.positions.front().y, 0, 'g', 6));
    } catch (const std::exception&) {
        summary_->setText(QString());
    }
    error_->setText(problem());
}

void ArrangementDialog::accept() {
    QString reason = problem();
    if (reason.isEmpty()) {
        try {
            prototype();
        } catch (const std::exception& e) {
            reason = QString::fromStdString(e.what());
        }
    }
    if (!reason.isEmpty()) {
        error_->setText(reason);
        return;
    }
    QDialog::accept();
}

}  // namespace lucerna
