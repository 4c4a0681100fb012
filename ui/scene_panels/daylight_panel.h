#pragma once
// The daylight dock (SPEC.md section 5): the site (a city from a short list, or latitude,
// longitude, UTC offset and north typed), the sun (present or not, its illuminance and disc,
// its date and a time-of-day slider that moves it), and the sky (model, CIE type, its quantity as
// zenith luminance or horizontal illuminance, ground reflectance). It shows where the sun stands
// (elevation and azimuth) and the horizontal illuminance Eh the sun and sky give an open plane.
// The daylight levels (sun and sky brightness) are fixed numbers or follow the sun's altitude (the
// IES model, daylight_availability.h: the fields then show what it gives and are read-only); a
// Perez sky takes them from its weather file's hour.
// Every edit is an undo step (a slider drag or a run of arrow steps is one); what would make the
// scene invalid (a CIE general sky without a sun) is refused with a line saying why.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"
#include "ui/scene_panels/weather_hour.h"

#include <QWidget>

#include <functional>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDateEdit;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace lucerna {

class TimeOfDayEdit;

class DaylightPanel : public QWidget {
    Q_OBJECT
public:
    explicit DaylightPanel(Document* doc, QWidget* parent = nullptr);
    ~DaylightPanel() override;  // disconnects its children first (ui/disconnect_children.h)

    // "YYYY-MM-DDTHH:MM" of the date field and the time slider: the sun's time, or the one a
    // sun placed from now on gets.
    std::string localTime() const;
    // Where a Perez sky's weather file comes from (a file dialog; empty: none chosen).
    void setWeatherQuestion(std::function<QString()> ask) { askWeather_ = std::move(ask); }
    // Reads the weather file a Perez sky takes its hours from; the one-line error, or empty.
    QString useWeatherFile(const QString& path);

signals:
    void message(const QString& text);

private:
    // The sky model box's items.
    static constexpr int kNoSky = 0, kUniform = 1, kCieOvercast = 2, kCieGeneral = 3, kPerez = 4;
    // The daylight levels box's items.
    static constexpr int kFollowAltitude = 0, kFixedLevels = 1;
    // The sky quantity box's items.
    static constexpr int kHorizontalIlluminance = 0, kZenithLuminance = 1;

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
    // The Perez sky (weather_hour.h): the weather file's hour at the clock, and leaving it.
    void choosePerez();
    void leavePerezFor(int item);
    // Site, sun and sky as one undo step.
    void applyDaylight(const DaylightEdit& e, const QString& text);
    // The levels (daylight_panel_levels.cpp): following the sun's altitude or fixed, one undo
    // step; the sky (or none) with the sun's keys made to match it, as one step (a sky whose
    // levels follow takes the sun's illuminance key away; one that does not gives it back, at what
    // the sun gave); the fields of the levels.
    void chooseLevels(int item);
    void setSkyAndSun(const std::optional<Sky>& sky, const QString& text);
    void refreshLevels();

    Document* doc_;
    MergeTracker merge_;
    std::optional<Sky> lastSky_;  // what choosing a model after "none" brings back

    QComboBox* city_;
    QDoubleSpinBox *latitude_, *longitude_, *utcOffset_, *north_;
    QCheckBox* sunPresent_;
    QDoubleSpinBox *sunIlluminance_, *sunDiameter_;
    QDateEdit* date_;
    QSlider* timeSlider_;
    TimeOfDayEdit* time_;
    QLabel *sunPosition_, *horizontalIlluminance_;
    QComboBox* skyModel_;
    QComboBox* levels_;
    QWidget* cieTypeRow_;
    QSpinBox* cieType_;
    QLabel* cieTypeName_;
    QComboBox* skyQuantity_;
    QDoubleSpinBox* skyValue_;
    QDoubleSpinBox* groundReflectance_;
    QLabel* error_;
    QLabel* weatherLabel_;
    std::function<QString()> askWeather_;
    std::optional<WeatherFile> weather_;
    QString weatherPath_;
};

}  // namespace lucerna
