#pragma once
// The Energy page (README, "Energy (LENI; an addition)"): the building type and each factor of
// EN 15193-1's lighting energy, a field left empty taking its default (shown in the field, grey),
// and W_L, W_P and LENI as they follow from the scene's lights, updated with every edit. Every
// change (a building type chosen, a factor typed and the field left or Enter pressed, a field
// cleared) is one EditEnergyCommand; a value out of its range, or hours that together pass the
// 8760 of a year, is refused with a line saying why and changes nothing. A widget of its own,
// shown in a dialog of Edit > Energy... until it joins the project's settings.

#include "ui/document/document.h"

#include <QWidget>

#include <array>

class QComboBox;
class QLabel;
class QLineEdit;

namespace lucerna {

class EnergyPanel : public QWidget {
    Q_OBJECT
public:
    // The factors of EnergySettings the page edits, in its order.
    enum class Factor {
        DaytimeHours, NightHours, ConstantIlluminance, Occupancy, Daylight, ControlParasitic, EmergencyCharging,
        EmergencyHours, Area
    };
    static constexpr int kFactors = 9;

    explicit EnergyPanel(Document* doc, QWidget* parent = nullptr);
    ~EnergyPanel() override;  // disconnects its children first (ui/disconnect_children.h)

    // The fields, for tests and for focus. The building type's first entry is "Not set" (no
    // energy settings: LENI is not computed and the factors wait).
    QComboBox* buildingTypeField() const { return type_; }
    QLineEdit* field(Factor f) const { return fields_[size_t(f)]; }
    // "W_L ...", "W_P ...", "LENI ..." or why it is not computed, and the last refusal.
    QLabel* lightingEnergyLabel() const { return lighting_; }
    QLabel* parasiticEnergyLabel() const { return parasitic_; }
    QLabel* leniLabel() const { return leni_; }
    QLabel* messageLabel() const { return message_; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    // Shows the scene's settings and result; a field being typed into keeps its text unless
    // `overwriteTyped`.
    void refresh(bool overwriteTyped = false);
    void chooseBuildingType(int index);
    void applyFactor(Factor f);
    // Pushes the settings as one undo step, or says why not (and shows the scene's again).
    void change(std::optional<EnergySettings> after, const QString& what);
    void refuse(const QString& why);

    Document* doc_;
    QComboBox* type_;
    std::array<QLineEdit*, kFactors> fields_{};
    QLabel *installed_, *lighting_, *parasitic_, *leni_, *message_;
};

}  // namespace lucerna
