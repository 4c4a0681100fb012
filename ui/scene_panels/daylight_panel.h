#pragma once
// The daylight dock (SPEC.md section 5): the site (a city from a short list, or latitude,
// longitude, UTC offset and north typed), the sun (present or not, its illuminance and disc,
// its date and a time-of-day slider that moves it), and the sky (model, CIE type, its quantity as
// zenith luminance or horizontal illuminance, ground reflectance). It shows where the sun stands
// (elevation and azimuth) and the horizontal illuminance Eh the sun and sky give an open plane.
// Every edit is an undo step (a slider drag or a run of arrow steps is one); what would make the
// scene invalid (a CIE general sky without a sun) is refused with a line saying why.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"

#include <QWidget>

#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDateEdit;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTimeEdit;

namespace lucerna {

class DaylightPanel : public QWidget {
    Q_OBJECT
public:
    explicit DaylightPanel(Document* doc, QWidget* parent = nullptr);
    ~DaylightPanel() override;  // disconnects its children first (ui/disconnect_children.h)

    // "YYYY-MM-DDTHH:MM" of the date field and the time slider: the sun's time, or the one a
    // sun placed from now on gets.
    std::string localTime() const;

signals:
    void message(const QString& text);

private:
    void refresh();
    void refreshSite();
    void refreshSun();
    void refreshSky();
    void showSunPosition();
    void refuse(const QString& why);

    // A choice from a list or a check box is an undo step of its own: it ends the fields' merge
    // runs and clears the error line. Returns the scene.
    const Scene& beginChoice();
    void chooseCity(int item);
    void editSite(const void* field);
    // A field's edit of the site or the sky, pushed as a `Command` that merges with the field's
    // earlier steps: `edit` changes a copy of the value and names the step ("" refuses it).
    // Nothing happens when there is no value to edit or the edit leaves it as it was.
    template <class Command, class Value, class Edit>
    void editValue(const void* field, const std::optional<Value>& current, Edit edit);
    void setSunPresent(bool present);
    void editSun(const void* field);
    void moveSun(const void* field);
    void chooseSkyModel(int item);
    void editSky(const void* field);
    void chooseSkyQuantity(int item);

    Document* doc_;
    MergeTracker merge_;
    std::optional<Sky> lastSky_;  // what choosing a model after "none" brings back

    QComboBox* city_;
    QDoubleSpinBox *latitude_, *longitude_, *utcOffset_, *north_;
    QCheckBox* sunPresent_;
    QDoubleSpinBox *sunIlluminance_, *sunDiameter_;
    QDateEdit* date_;
    QSlider* timeSlider_;
    QTimeEdit* time_;
    QLabel *sunPosition_, *horizontalIlluminance_;
    QComboBox* skyModel_;
    QWidget* cieTypeRow_;
    QSpinBox* cieType_;
    QLabel* cieTypeName_;
    QComboBox* skyQuantity_;
    QDoubleSpinBox* skyValue_;
    QDoubleSpinBox* groundReflectance_;
    QLabel* error_;
};

}  // namespace lucerna
