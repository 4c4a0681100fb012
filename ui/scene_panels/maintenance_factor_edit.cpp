#include "ui/scene_panels/maintenance_factor_edit.h"

#include "ui/properties/property_rows.h"
#include "ui/scene_panels/maintenance_assistant_dialog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace lucerna {

namespace {

constexpr std::array<const char*, 4> kFactorNames{"LLMF", "LSF", "LMF", "RSMF"};
constexpr std::array<std::optional<double> MaintenanceFactor::*, 4> kFactorMembers{
    &MaintenanceFactor::lampLumenMaintenance, &MaintenanceFactor::lampSurvival, &MaintenanceFactor::luminaireMaintenance,
    &MaintenanceFactor::roomSurfaceMaintenance};

QString number(double v) { return QString::number(v, 'f', 3); }

// "0.95 x 1 x 0.9 x 0.94 = 0.804": a factor left out counts 1.
QString product(const MaintenanceFactor& mf) {
    QStringList parts;
    for (auto member : kFactorMembers) parts << QString::number((mf.*member).value_or(1), 'g', 4);
    return parts.join(QStringLiteral(" x ")) + QStringLiteral(" = ") + number(mf.factor());
}

}  // namespace

MaintenanceFactorEdit::MaintenanceFactorEdit(Absent absent, QWidget* parent) : QWidget(parent), absent_(absent) {
    mode_ = new QComboBox(this);
    mode_->setObjectName("maintenanceMode");
    mode_->addItem(absent == Absent::None ? tr("None") : tr("The scene's"));
    mode_->addItem(tr("One number"));
    mode_->addItem(tr("CIE 97's four factors"));
    mode_->setToolTip(tr("MF = LLMF x LSF x LMF x RSMF (CIE 97:2005)"));
    // Narrower than its longest entry when the panel is (a dock at its default width).
    mode_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    mode_->setMinimumContentsLength(10);

    stack_ = new QStackedWidget(this);
    stack_->addWidget(new QWidget(stack_));
    auto* numberPage = new QWidget(stack_);
    auto* numberRow = new QHBoxLayout(numberPage);
    numberRow->setContentsMargins(0, 0, 0, 0);
    number_ = makePropertySpin(numberPage, 0.001, 1, 3);
    number_->setObjectName("maintenanceNumber");
    number_->setSingleStep(0.01);
    numberRow->addWidget(new QLabel(tr("MF"), numberPage));
    numberRow->addWidget(number_, 1);
    stack_->addWidget(numberPage);
    auto* factorsPage = new QWidget(stack_);
    auto* grid = new QGridLayout(factorsPage);
    grid->setContentsMargins(0, 0, 0, 0);
    for (size_t i = 0; i < 4; ++i) {
        factors_[i] = makePropertySpin(factorsPage, 0.001, 1, 3);
        factors_[i]->setObjectName(QStringLiteral("maintenance%1").arg(QString::fromLatin1(kFactorNames[i])));
        factors_[i]->setSingleStep(0.01);
        grid->addWidget(new QLabel(QString::fromLatin1(kFactorNames[i]), factorsPage), int(i / 2), int(i % 2) * 2);
        grid->addWidget(factors_[i], int(i / 2), int(i % 2) * 2 + 1);
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(3, 1);
    stack_->addWidget(factorsPage);

    assistant_ = new QPushButton(tr("Assistant..."), this);
    assistant_->setObjectName("maintenanceAssistantButton");
    assistant_->setToolTip(tr("The four factors from the lamp, the luminaire and the room (CIE 97:2005)"));
    summary_ = makeWrappingLabel(this, "maintenanceSummary");

    auto* top = new QHBoxLayout;
    top->addWidget(mode_, 1);
    top->addWidget(assistant_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(stack_);
    layout->addWidget(summary_);
    layout->addStretch(1);

    connect(mode_, &QComboBox::activated, this, [this](int mode) {
        chooseMode(mode);
        emit edited(mode_);
        emit editingFinished();
    });
    connect(number_, &QDoubleSpinBox::valueChanged, this, [this] {
        value_ = MaintenanceFactor{.value = number_->value()};
        lastNumber_ = number_->value();
        found_.clear();
        showValue(false);
        emit edited(number_);
    });
    connect(number_, &QDoubleSpinBox::editingFinished, this, &MaintenanceFactorEdit::editingFinished);
    for (size_t i = 0; i < 4; ++i) {
        connect(factors_[i], &QDoubleSpinBox::valueChanged, this, [this, i] { typed(int(i)); });
        connect(factors_[i], &QDoubleSpinBox::editingFinished, this, &MaintenanceFactorEdit::editingFinished);
    }
    connect(assistant_, &QPushButton::clicked, this, [this] {
        MaintenanceAssistantDialog dialog(choices_, this);
        if (dialog.exec() != QDialog::Accepted || !dialog.assessment()) return;
        choices_ = dialog.choices();
        applyAssessment(*dialog.assessment());
    });
    showValue(false);
}

void MaintenanceFactorEdit::setValue(const std::optional<MaintenanceFactor>& factor) {
    // The document echoing this edit's own value keeps the assistant's lines.
    if (factor == value_) {
        showValue(true);
        return;
    }
    value_ = factor;
    if (value_ && value_->value) lastNumber_ = *value_->value;
    if (value_ && !value_->value) lastFactors_ = value_;
    found_.clear();
    showValue(false);
}

void MaintenanceFactorEdit::setSceneFactor(std::optional<double> factor) {
    sceneFactor_ = factor;
    if (absent_ == Absent::SceneFactor)
        mode_->setItemText(kAbsent, factor ? tr("The scene's (%1)").arg(factor.value(), 0, 'f', 2) : tr("The scene's (none)"));
    showValue(true);
}

MaintenanceFactor MaintenanceFactorEdit::currentFactors() const {
    if (value_ && !value_->value) return *value_;
    if (lastFactors_) return *lastFactors_;
    // Four factors of 1 to type over (or for the assistant to fill).
    return MaintenanceFactor{.lampLumenMaintenance = 1.0, .lampSurvival = 1.0, .luminaireMaintenance = 1.0,
                             .roomSurfaceMaintenance = 1.0};
}

void MaintenanceFactorEdit::chooseMode(int mode) {
    if (mode == kAbsent) value_.reset();
    if (mode == kNumber) value_ = MaintenanceFactor{.value = lastNumber_};
    if (mode == kFactors) value_ = currentFactors();
    if (value_ && !value_->value) lastFactors_ = value_;
    found_.clear();
    showValue(false);
}

void MaintenanceFactorEdit::typed(int factor) {
    MaintenanceFactor mf = currentFactors();
    mf.*kFactorMembers[size_t(factor)] = factors_[size_t(factor)]->value();
    value_ = lastFactors_ = mf;
    found_.clear();
    showValue(false);
    emit edited(factors_[size_t(factor)]);
}

void MaintenanceFactorEdit::applyAssessment(const MaintenanceAssessment& a) {
    MaintenanceFactor mf = currentFactors();
    QStringList lines;
    const std::array<const FoundFactor*, 4> found{&a.llmf, &a.lsf, &a.lmf, &a.rsmf};
    for (size_t i = 0; i < 4; ++i) {
        QString line = QString::fromStdString(found[i]->explanation);
        if (found[i]->value) mf.*kFactorMembers[i] = *found[i]->value;
        else line += tr(" (kept: %1)").arg((mf.*kFactorMembers[i]).value_or(1), 0, 'g', 4);
        lines << line;
    }
    value_ = lastFactors_ = mf;
    found_ = lines.join('\n');
    showValue(true);
    emit edited(assistant_);
    emit editingFinished();
}

void MaintenanceFactorEdit::showValue(bool keepFound) {
    const int mode = !value_ ? kAbsent : value_->value ? kNumber : kFactors;
    {
        const QSignalBlocker quiet(mode_);
        mode_->setCurrentIndex(mode);
    }
    stack_->setCurrentIndex(mode);
    stack_->setVisible(mode != kAbsent);
    // The stack as tall as its page shown, not as its tallest.
    for (int i = 0; i < stack_->count(); ++i)
        stack_->widget(i)->setSizePolicy(QSizePolicy::Preferred, i == mode ? QSizePolicy::Preferred : QSizePolicy::Ignored);
    stack_->updateGeometry();
    if (mode == kNumber) {
        const QSignalBlocker quiet(number_);
        number_->setValue(*value_->value);
    }
    if (mode == kFactors)
        for (size_t i = 0; i < 4; ++i) {
            const QSignalBlocker quiet(factors_[i]);
            factors_[i]->setValue((value_.value().*kFactorMembers[i]).value_or(1));
        }
    QString text;
    if (mode == kAbsent && absent_ == Absent::None)
        text = tr("No maintenance factor: the figures are the new installation's, and EN 12464-1's maintained "
                  "illuminance Em is not checked.");
    else if (mode == kAbsent)
        text = sceneFactor_ ? tr("The scene's maintenance factor, %1.").arg(number(*sceneFactor_))
                            : tr("The scene has none: this light's values are the new installation's.");
    else if (mode == kFactors)
        text = tr("MF = %1").arg(product(*value_));
    if (mode != kAbsent && value_->factor() == 1) {
        const QString note = tr("MF 1: the new installation's values; Em is not checked");
        text = text.isEmpty() ? note : text + " (" + note + ")";
    }
    if (keepFound && !found_.isEmpty()) text += (text.isEmpty() ? "" : "\n") + found_;
    summary_->setText(text);
    summary_->setVisible(!text.isEmpty());
}

}  // namespace lucerna
