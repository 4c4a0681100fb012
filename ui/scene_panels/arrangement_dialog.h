#pragma once
// Edit > Arrange Lights: the numerical dialog of the arrangement tool (light_arrangement.h). It
// asks for the luminaire (the selected light, a default point light, or an IES or EULUMDAT file),
// the rectangle in plan (the scene's bounds, or the one drawn in the plan view), count or spacing,
// the ceiling's height and the suspension below it, and the group's name; it shows the field it
// would make as the values change, and refuses OK with a one-line reason while they make none.

#include "ui/scene_panels/light_arrangement.h"

#include <QDialog>

#include <array>
#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QSpinBox;

namespace lucerna {

class Document;

class ArrangementDialog : public QDialog {
    Q_OBJECT
public:
    // `selectedLight`: the light offered as the field's luminaire (-1: none).
    ArrangementDialog(const Document& doc, int selectedLight, QWidget* parent = nullptr);

    // The rectangle in plan (scene units); the ceiling follows it (ceilingAbove its centre).
    void setRectangle(double x0, double z0, double x1, double z1);
    void setArrangement(const FieldArrangement& field);
    FieldArrangement arrangement() const;
    std::string group() const;
    // The light the field copies. Throws std::runtime_error (one line) when the chosen luminaire
    // file cannot be read.
    Light prototype() const;
    // The file dialog of "Luminaire file..." (the window's; tests answer it).
    void setFileQuestion(std::function<QString()> ask) { askFile_ = std::move(ask); }
    void setLuminaireFile(const QString& path);

    // The one-line reason OK is refused, or "" (for tests).
    QString problem() const;

    void accept() override;

private:
    void updateSummary();

    const Document& doc_;
    int selectedLight_;
    QComboBox* source_;
    QLineEdit* file_;
    QPushButton* browse_;
    std::array<QDoubleSpinBox*, 4> rect_{};  // x0, z0, x1, z1
    QRadioButton *byCount_, *bySpacing_;
    QSpinBox *columns_, *rows_;
    QDoubleSpinBox *spacingX_, *spacingZ_, *ceiling_, *suspension_;
    QLineEdit* group_;
    QLabel *summary_, *error_;
    std::function<QString()> askFile_;
};

}  // namespace lucerna
