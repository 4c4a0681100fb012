#pragma once
// A maintenance factor as a designer sets it (README, "Maintained values"): none (for a light:
// the scene's), one number, or CIE 97's four factors LLMF x LSF x LMF x RSMF, each editable, with
// an Assistant... that fills the four from the lamp, the luminaire and the room
// (MaintenanceAssistantDialog) and shows how each was found. The scene's and a light's editor
// alike; the owner turns edited() into its undo step.
//
// A field's value counts only for the factor typed into it: the others keep their exact values
// (a factor shows three decimals, and a file's 0.8765 stays 0.8765 until typed over).

#include "core/photometry/maintenance_assistant.h"

#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace lucerna {

class MaintenanceFactorEdit : public QWidget {
    Q_OBJECT
public:
    // What no factor means where the edit stands: the scene has none (Em is not checked), or the
    // light takes the scene's.
    enum class Absent { None, SceneFactor };
    // The modes of modeField(), in its order.
    enum Mode { kAbsent = 0, kNumber = 1, kFactors = 2 };

    MaintenanceFactorEdit(Absent absent, QWidget* parent = nullptr);

    // Shows `factor` (from the document: not an edit). The value it has already keeps the
    // assistant's lines under it.
    void setValue(const std::optional<MaintenanceFactor>& factor);
    const std::optional<MaintenanceFactor>& value() const { return value_; }
    // For Absent::SceneFactor: the scene's factor, which the first choice names ("scene's (0.80)").
    void setSceneFactor(std::optional<double> factor);
    // What the assistant opens on (by default MaintenanceChoices's; the scene's room is better).
    void setAssistantChoices(const MaintenanceChoices& choices) { choices_ = choices; }

    // The fields, for tests: the mode, the one number, LLMF, LSF, LMF, RSMF, the assistant's
    // button and the line under them (the product, or how the assistant found each factor).
    QComboBox* modeField() const { return mode_; }
    QDoubleSpinBox* numberField() const { return number_; }
    const std::array<QDoubleSpinBox*, 4>& factorFields() const { return factors_; }
    QPushButton* assistantButton() const { return assistant_; }
    QLabel* summary() const { return summary_; }

    // Fills the four factors from an assessment (what the assistant's OK does): those found
    // replace the fields', the others keep theirs. One edit.
    void applyAssessment(const MaintenanceAssessment& assessment);

signals:
    // The user changed the value (value() has it); `source` is the field, for undo merging.
    void edited(const void* source);
    // A field's editing finished (Enter, focus out): the next edit is a new undo step.
    void editingFinished();

private:
    void chooseMode(int mode);
    void typed(int factor);
    // The fields and the line under them as value_ is; keepFound: with the assistant's lines.
    void showValue(bool keepFound);
    MaintenanceFactor currentFactors() const;

    Absent absent_;
    std::optional<MaintenanceFactor> value_;
    // What the other modes had, restored when the user switches back to them.
    double lastNumber_ = 0.8;
    std::optional<MaintenanceFactor> lastFactors_;
    std::optional<double> sceneFactor_;
    MaintenanceChoices choices_;
    QString found_;  // the assistant's lines, until the value changes otherwise
    QComboBox* mode_;
    QStackedWidget* stack_;
    QDoubleSpinBox* number_;
    std::array<QDoubleSpinBox*, 4> factors_{};
    QPushButton* assistant_;
    QLabel* summary_;
};

}  // namespace lucerna
