#pragma once
// The maintenance factor's assistant (core/photometry/maintenance_assistant.h): the lamp and its
// operating hours, the luminaire's type, environment and cleaning interval, and the room's size,
// distribution, environment and cleaning interval; it shows each of CIE 97's four factors as it
// is found, with the line saying where it came from, and what is not found and why.

#include "core/photometry/maintenance_assistant.h"

#include <QDialog>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;

namespace lucerna {

class MaintenanceAssistantDialog : public QDialog {
    Q_OBJECT
public:
    explicit MaintenanceAssistantDialog(const MaintenanceChoices& initial, QWidget* parent = nullptr,
                                        const Cie97Tables& tables = bundledCie97Tables());

    MaintenanceChoices choices() const;
    // What the choices give; nullopt while they are refused (the dialog says why, OK is disabled).
    const std::optional<MaintenanceAssessment>& assessment() const { return assessment_; }

private:
    void update();

    const Cie97Tables& tables_;
    std::optional<MaintenanceAssessment> assessment_;
    QComboBox *lamp_, *luminaire_, *luminaireEnvironment_, *distribution_, *roomEnvironment_;
    QDoubleSpinBox *ledRating_, *ledLife_, *hours_, *luminaireCleaning_;
    QDoubleSpinBox *length_, *width_, *height_, *roomCleaning_;
    QCheckBox* spotReplacement_;
    QWidget *ledRow_, *ledLifeRow_;
    QLabel *roomIndex_, *result_;
    QPushButton* ok_;
};

// Choices for a scene: its extent in plan as the room (in metres) and its highest light's height
// above a work plane 0.8 m over the lowest geometry as the mounting height; the rest as
// MaintenanceChoices has it.
MaintenanceChoices choicesForScene(const Scene& scene);

}  // namespace lucerna
