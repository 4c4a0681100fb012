#pragma once
// The Energy tab of File > Project Settings (ui/scene_panels/project_dialog.h; README, "Energy
// (LENI; an addition)"): the building type and each factor of EN 15193-1's lighting energy, a
// field left empty taking its default (shown in the field, grey), and W_L, W_P and LENI as they
// follow from the scene's lights and what the tab shows, updated when a field is left or the
// building type chosen. Nothing is applied before the dialog's OK, which sets the scene's
// `energy` key with the other tabs' settings in one undo step.
//
// A value out of its range, a word, or hours that together pass the 8760 of a year gets a line
// saying why as soon as the field is left; the field keeps what was typed, so that it can be
// corrected, and OK stays on this tab until it is (check()).

#include "ui/scene_panels/project_dialog.h"

#include <array>

class QComboBox;
class QLabel;
class QLineEdit;

namespace lucerna {

class EnergySettingsPage : public ProjectSettingsPage {
    Q_OBJECT
public:
    // The factors of EnergySettings the tab edits, in its order.
    enum class Factor {
        DaytimeHours, NightHours, ConstantIlluminance, Occupancy, Daylight, ControlParasitic, EmergencyCharging,
        EmergencyHours, Area
    };
    static constexpr int kFactors = 9;

    // `scene`: the scene whose lights and plan the results are worked from (its own energy
    // settings are replaced by the tab's).
    explicit EnergySettingsPage(SceneSnapshot scene, QWidget* parent = nullptr);
    ~EnergySettingsPage() override;  // disconnects its children first (ui/disconnect_children.h)

    void load(const ProjectSettings& settings) override;
    // The building type "Not set": no `energy` key. A field as loaded keeps the loaded value
    // exactly; while the tab has a problem (check()), the energy settings are left as they are.
    void store(ProjectSettings& settings) const override;
    // Empty, or the first problem of what the tab shows (the line it shows), its field focused.
    QString check() override;

    // The fields, for tests and for focus. The building type's first entry is "Not set" (no
    // energy settings: LENI is not computed and the factors wait).
    QComboBox* buildingTypeField() const { return type_; }
    QLineEdit* field(Factor f) const { return fields_[size_t(f)]; }
    // "W_L ...", "W_P ...", "LENI ..." or why it is not computed, and the problem, if any.
    QLabel* lightingEnergyLabel() const { return lighting_; }
    QLabel* parasiticEnergyLabel() const { return parasitic_; }
    QLabel* leniLabel() const { return leni_; }
    QLabel* messageLabel() const { return message_; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    // What the tab shows as settings, and the first problem with it (then `badField`, the field
    // at fault, or -1 for the settings as a whole).
    struct Shown {
        std::optional<EnergySettings> settings;
        QString problem;
        int badField = -1;
    };
    Shown shown() const;
    // After an edit: the problem line, and while the tab is shown the defaults in the empty
    // fields and the results.
    void refresh();

    SceneSnapshot scene_;
    std::optional<EnergySettings> loaded_;
    std::array<QString, kFactors> loadedText_;  // each field's text as loaded
    QComboBox* type_;
    std::array<QLineEdit*, kFactors> fields_{};
    QLabel *installed_, *lighting_, *parasitic_, *leni_, *message_;
};

}  // namespace lucerna
