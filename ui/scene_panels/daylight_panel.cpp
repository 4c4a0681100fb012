#include "ui/scene_panels/daylight_panel.h"

#include "ui/disconnect_children.h"
#include "core/daylight/daylight.h"
#include "core/daylight/sky_model.h"
#include "core/daylight/solar_position.h"
#include "ui/commands/daylight_commands.h"
#include "ui/commands/light_commands.h"
#include "ui/scene_panels/site_cities.h"
#include "ui/scene_panels/time_of_day_edit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateEdit>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace lucerna {

namespace {

// The city list: "No site", the cities, then "Custom site" for any other place.
constexpr int kNoSite = 0;
constexpr int kCustomSite = int(kSiteCities.size()) + 1;

// A field's edit: `value` takes the field's value; returns the undo step's name.
template <class T, class Field> QString taken(T& value, const Field* field, const QString& step) {
    value = field->value();
    return step;
}

// The ISO 15469 / CIE S 011 descriptions of the 15 general skies.
const char* const kCieSkyNames[15] = {
    "Overcast, steep gradation, uniform in azimuth (the CIE standard overcast sky)",
    "Overcast, steep gradation, slight brightening toward the sun",
    "Overcast, moderate gradation, uniform in azimuth",
    "Overcast, moderate gradation, slight brightening toward the sun",
    "Sky of uniform luminance",
    "Partly cloudy, no gradation toward the zenith, slight brightening toward the sun",
    "Partly cloudy, no gradation toward the zenith, brighter circumsolar region",
    "Partly cloudy, no gradation toward the zenith, distinct solar corona",
    "Partly cloudy, the sun obscured",
    "Partly cloudy, brighter circumsolar region",
    "White-blue sky, distinct solar corona",
    "CIE standard clear sky, low luminance turbidity",
    "CIE standard clear sky, polluted atmosphere",
    "Cloudless turbid sky, broad solar corona",
    "White-blue turbid sky, broad solar corona",
};

// A sky for a scene that had none: beside a sun, its levels follow the sun's altitude; without
// one (nothing to follow), 10,000 lx on an open plane, a bright overcast day.
Sky defaultSky(const Scene& scene) {
    Sky s;
    s.model = SkyModelType::CieOvercast;
    if (sunIndex(scene) >= 0) s.levels = DaylightLevels::FollowAltitude;
    else s.horizontalIlluminance = 10000;
    return s;
}

}  // namespace

DaylightPanel::~DaylightPanel() { disconnectChildren(this); }

DaylightPanel::DaylightPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* layout = new QVBoxLayout(this);
    // Slim margins: the left docks are narrow, and the rows' labels take 110 px already.
    layout->setContentsMargins(4, 4, 4, 4);
    const auto group = [this, layout](const QString& title) {
        auto* box = new QGroupBox(title, this);
        auto* rows = new QVBoxLayout(box);
        rows->setContentsMargins(4, 4, 4, 4);
        layout->addWidget(box);
        return rows;
    };
    // The panel's labels are short: a narrower label column leaves the fields room in a narrow dock.
    const auto row = [](QVBoxLayout* rows, const QString& label, std::initializer_list<QWidget*> fields) {
        QWidget* r = addPropertyRow(rows, label, fields);
        rowLabel(r)->setMinimumWidth(84);
        return r;
    };
    // A numeric field whose edits are one undo step per field until editing finishes.
    const auto spin = [this](QWidget* parent, const char* name, double lo, double hi, int decimals,
                             void (DaylightPanel::*apply)(const void*)) {
        QDoubleSpinBox* s = makePropertySpin(parent, lo, hi, decimals);
        s->setMinimumWidth(50);
        s->setObjectName(name);
        connect(s, &QDoubleSpinBox::valueChanged, this, [this, s, apply] { (this->*apply)(s); });
        connect(s, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
        return s;
    };

    // Site.
    QVBoxLayout* site = group(tr("Site"));
    city_ = new QComboBox(this);
    city_->setObjectName("daylightCity");
    city_->addItem(tr("No site"));
    for (const SiteCity& c : kSiteCities) city_->addItem(QString::fromUtf8(c.name.data(), qsizetype(c.name.size())));
    city_->addItem(tr("Custom site"));
    city_->setToolTip(tr("Where the scene stands on Earth: what places the sun by date and time"));
    connect(city_, &QComboBox::activated, this, &DaylightPanel::chooseCity);
    row(site, tr("Place"), {city_});
    latitude_ = spin(this, "daylightLatitude", -90, 90, 4, &DaylightPanel::editSite);
    latitude_->setSuffix(QStringLiteral(" °N"));
    longitude_ = spin(this, "daylightLongitude", -180, 180, 4, &DaylightPanel::editSite);
    longitude_->setSuffix(QStringLiteral(" °E"));
    utcOffset_ = spin(this, "daylightUtcOffset", -14, 14, 2, &DaylightPanel::editSite);
    utcOffset_->setSingleStep(0.5);
    utcOffset_->setSuffix(QStringLiteral(" h"));
    utcOffset_->setToolTip(tr("Local time = UTC + this offset; the standard time, without daylight saving"));
    north_ = spin(this, "daylightNorth", 0, 360, 1, &DaylightPanel::editSite);
    north_->setSuffix(QStringLiteral(" °"));
    north_->setWrapping(true);
    north_->setSingleStep(5);
    north_->setToolTip(tr("The direction of geographic north, in degrees from -z toward +x (0: north is -z, east +x)"));
    row(site, tr("Latitude"), {latitude_});
    row(site, tr("Longitude"), {longitude_});
    row(site, tr("UTC offset"), {utcOffset_});
    row(site, tr("North"), {north_});

    // Sun.
    QVBoxLayout* sun = group(tr("Sun"));
    sunPresent_ = new QCheckBox(tr("present"), this);
    sunPresent_->setObjectName("daylightSunPresent");
    connect(sunPresent_, &QCheckBox::clicked, this, &DaylightPanel::setSunPresent);
    row(sun, tr("Sun"), {sunPresent_});
    sunIlluminance_ = spin(this, "daylightSunIlluminance", 0, 1e6, 0, &DaylightPanel::editSun);
    sunIlluminance_->setSingleStep(1000);
    sunIlluminance_->setSuffix(QStringLiteral(" lx"));
    sunIlluminance_->setToolTip(tr("Direct normal illuminance: on a surface facing the sun"));
    sunDiameter_ = spin(this, "daylightSunDiameter", 0, 5, 2, &DaylightPanel::editSun);
    sunDiameter_->setSingleStep(0.05);
    sunDiameter_->setSuffix(QStringLiteral(" °"));
    sunDiameter_->setToolTip(tr("The sun's disc; 0 makes it a point at infinity with hard shadows"));
    row(sun, tr("Illuminance"), {sunIlluminance_});
    row(sun, tr("Angular diameter"), {sunDiameter_});
    date_ = new QDateEdit(QDate(2025, 6, 21), this);
    date_->setObjectName("daylightDate");
    date_->setDisplayFormat(QStringLiteral("yyyy-MM-dd"));
    date_->setDateRange(QDate(1900, 1, 1), QDate(2100, 12, 31));
    date_->setCalendarPopup(true);
    date_->setKeyboardTracking(false);
    connect(date_, &QDateEdit::dateChanged, this, [this] { moveSun(date_); });
    connect(date_, &QDateEdit::editingFinished, this, [this] { merge_.finish(); });
    row(sun, tr("Date"), {date_});
    timeSlider_ = new QSlider(Qt::Horizontal, this);
    timeSlider_->setObjectName("daylightTimeSlider");
    timeSlider_->setRange(0, 24 * 60 - 1);  // minutes of the local day
    timeSlider_->setSingleStep(5);
    timeSlider_->setPageStep(60);
    timeSlider_->setValue(12 * 60);
    timeSlider_->setToolTip(tr("Local time at the site: drag to move the sun"));
    connect(timeSlider_, &QSlider::valueChanged, this, [this] {
        moveSun(timeSlider_);
        // A drag is one step; a click on the track or a key is a step of its own.
        if (!timeSlider_->isSliderDown()) merge_.finish();
    });
    connect(timeSlider_, &QSlider::sliderReleased, this, [this] { merge_.finish(); });
    time_ = new TimeOfDayEdit(QTime(12, 0), this);
    time_->setObjectName("daylightTime");
    time_->setKeyboardTracking(false);
    connect(time_, &QTimeEdit::timeChanged, this, [this] { moveSun(time_); });
    connect(time_, &QTimeEdit::editingFinished, this, [this] { merge_.finish(); });
    timeSlider_->setTickPosition(QSlider::TicksBelow);
    timeSlider_->setTickInterval(3 * 60);
    row(sun, tr("Time"), {time_});
    // The slider has the dock's whole width: a narrow one would move the sun by the hour.
    sun->addWidget(timeSlider_);
    sunPosition_ = makeWrappingLabel(this, "daylightSunPosition");
    sun->addWidget(sunPosition_);
    horizontalIlluminance_ = makeWrappingLabel(this, "daylightHorizontalIlluminance");
    horizontalIlluminance_->setToolTip(tr("The horizontal illuminance of the sun and the sky on an open plane"));
    sun->addWidget(horizontalIlluminance_);

    // Sky.
    QVBoxLayout* sky = group(tr("Sky"));
    skyModel_ = new QComboBox(this);
    skyModel_->setObjectName("daylightSkyModel");
    skyModel_->addItems({tr("None"), tr("Uniform"), tr("CIE overcast (traditional)"), tr("CIE general"),
                         tr("Perez (a weather file's hour)")});
    weatherLabel_ = new QLabel(tr("Perez: a weather file's hour (chosen with the model)"), this);
    weatherLabel_->setObjectName("daylightWeather");
    weatherLabel_->setWordWrap(true);
    connect(skyModel_, &QComboBox::activated, this, &DaylightPanel::chooseSkyModel);
    row(sky, tr("Model"), {skyModel_});
    sky->addWidget(weatherLabel_);
    levels_ = new QComboBox(this);
    levels_->setObjectName("daylightLevels");
    levels_->addItems({tr("Follow the sun's altitude (IES)"), tr("Fixed")});
    levels_->setToolTip(tr("Follow: the sun's direct normal illuminance and the sky's horizontal illuminance come "
                           "from the sun's altitude (IES daylight availability; CIE types 11-15 clear, 6-10 partly "
                           "cloudy, 1-5, CIE overcast and uniform overcast, without direct sun). Fixed: the numbers "
                           "below, at any time. A Perez sky takes them from its weather file's hour."));
    connect(levels_, &QComboBox::activated, this, &DaylightPanel::chooseLevels);
    row(sky, tr("Daylight levels"), {levels_});
    cieType_ = new QSpinBox(this);
    cieType_->setObjectName("daylightCieType");
    cieType_->setRange(1, 15);
    cieType_->setKeyboardTracking(false);
    connect(cieType_, &QSpinBox::valueChanged, this, [this] { editSky(cieType_); });
    connect(cieType_, &QSpinBox::editingFinished, this, [this] { merge_.finish(); });
    cieTypeRow_ = row(sky, tr("CIE type"), {cieType_});
    cieTypeName_ = makeWrappingLabel(this, "daylightCieTypeName");
    sky->addWidget(cieTypeName_);
    skyQuantity_ = new QComboBox(this);
    skyQuantity_->setObjectName("daylightSkyQuantity");
    skyQuantity_->addItems({tr("Eh (lx)"), tr("Lz (cd/m²)")});
    skyQuantity_->setToolTip(tr("Eh: the horizontal illuminance of the sky alone on an open plane; Lz: the sky's "
                                "luminance at the zenith. Switching keeps the sky as it is."));
    connect(skyQuantity_, &QComboBox::activated, this, &DaylightPanel::chooseSkyQuantity);
    row(sky, tr("Given as"), {skyQuantity_});
    skyValue_ = spin(this, "daylightSkyValue", 0, 1e7, 0, &DaylightPanel::editSky);
    skyValue_->setSingleStep(100);
    row(sky, tr("Value"), {skyValue_});
    groundReflectance_ = spin(this, "daylightGroundReflectance", 0, 1, 2, &DaylightPanel::editSky);
    groundReflectance_->setSingleStep(0.05);
    groundReflectance_->setToolTip(tr("The ground below the horizon reflects this share of the sun and sky's light"));
    row(sky, tr("Ground reflectance"), {groundReflectance_});

    // Lists and date fields narrow with the dock like the number fields (makePropertySpin).
    for (QWidget* w : std::initializer_list<QWidget*>{city_, date_, time_, skyModel_, levels_, cieType_, skyQuantity_}) {
        w->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        w->setMinimumWidth(50);
    }

    error_ = makeWrappingLabel(this, "daylightError");
    layout->addWidget(error_);
    layout->addStretch(1);

    connect(doc_, &Document::changed, this, &DaylightPanel::refresh);
    connect(doc_, &Document::replaced, this, [this] {
        merge_.finish();
        lastSky_.reset();
        error_->clear();
    });
    refresh();
}

std::string DaylightPanel::localTime() const {
    const QDate d = date_->date();
    const int minutes = timeSlider_->value();
    return formatLocalTime(LocalTime{d.year(), d.month(), d.day(), minutes / 60, minutes % 60, 0});
}

void DaylightPanel::refuse(const QString& why) {
    error_->setText(why);
    emit message(why);
    refresh();  // the fields show the scene as it still is
}

void DaylightPanel::refresh() {
    // Signals blocked: showing the scene is no edit of it.
    std::vector<std::unique_ptr<QSignalBlocker>> blocks;
    for (QWidget* w : findChildren<QWidget*>()) blocks.push_back(std::make_unique<QSignalBlocker>(w));
    refreshSite();
    refreshSun();
    refreshSky();
    refreshLevels();
    showSunPosition();
}

void DaylightPanel::refreshSite() {
    const std::optional<Site>& site = doc_->scene().site;
    for (QWidget* w : {static_cast<QWidget*>(latitude_), static_cast<QWidget*>(longitude_),
                       static_cast<QWidget*>(utcOffset_), static_cast<QWidget*>(north_)})
        w->setEnabled(site.has_value());
    if (!site) {
        city_->setCurrentIndex(kNoSite);
        return;
    }
    const int city = siteCityAt(site->latitudeDeg, site->longitudeDeg, site->utcOffsetHours);
    city_->setCurrentIndex(city < 0 ? kCustomSite : city + 1);
    latitude_->setValue(site->latitudeDeg);
    longitude_->setValue(site->longitudeDeg);
    utcOffset_->setValue(site->utcOffsetHours);
    north_->setValue(northAngleDeg(site->north));
}

void DaylightPanel::refreshSun() {
    const Scene& scene = doc_->scene();
    const int i = sunIndex(scene);
    const Light* sun = i < 0 ? nullptr : &scene.lights[size_t(i)];
    sunPresent_->setChecked(sun != nullptr);
    // A perez sky's model gives the sun's illuminance (SPEC.md section 6).
    const bool perez = scene.sky && scene.sky->model == SkyModelType::Perez;
    sunIlluminance_->setEnabled(sun != nullptr && !perez);
    sunDiameter_->setEnabled(sun != nullptr);
    // The clock places the sun only at a site; without a sun it is the time a new sun gets.
    for (QWidget* w : {static_cast<QWidget*>(date_), static_cast<QWidget*>(timeSlider_), static_cast<QWidget*>(time_)})
        w->setEnabled(scene.site.has_value());
    if (!sun || !sun->sun) return;
    const Daylight daylight = perez ? resolveDaylight(scene) : Daylight();
    sunIlluminance_->setValue(daylight.sun ? daylight.sun->illuminanceLux : sun->sun->illuminanceLux);
    sunDiameter_->setValue(sun->sun->angularDiameterDeg);
    if (sun->sun->time)
        if (const auto t = parseLocalTime(*sun->sun->time)) {
            date_->setDate(QDate(t->year, t->month, t->day));
            timeSlider_->setValue(t->hour * 60 + t->minute);
        }
    time_->setTime(QTime(timeSlider_->value() / 60, timeSlider_->value() % 60));
}

void DaylightPanel::refreshSky() {
    const std::optional<Sky>& sky = doc_->scene().sky;
    for (QWidget* w : {static_cast<QWidget*>(skyQuantity_), static_cast<QWidget*>(skyValue_),
                       static_cast<QWidget*>(groundReflectance_)})
        w->setEnabled(sky.has_value());
    const bool general = sky && sky->model == SkyModelType::CieGeneral;
    cieTypeRow_->setVisible(general);
    cieTypeName_->setVisible(general);
    weatherLabel_->setVisible(false);
    if (!sky) {
        skyModel_->setCurrentIndex(kNoSky);
        return;
    }
    skyModel_->setCurrentIndex(sky->model == SkyModelType::Uniform       ? kUniform
                               : sky->model == SkyModelType::CieOvercast ? kCieOvercast
                               : sky->model == SkyModelType::CieGeneral  ? kCieGeneral
                                                                         : kPerez);
    groundReflectance_->setValue(sky->groundReflectance);
    // A perez sky's quantity comes from its hour's irradiances.
    const bool perez = sky->model == SkyModelType::Perez;
    weatherLabel_->setVisible(perez);
    if (perez && !weather_) weatherLabel_->setText(tr("Perez: this hour's irradiances (choose the model again for a weather file)"));
    skyQuantity_->setEnabled(!perez);
    skyValue_->setEnabled(!perez);
    if (perez) {  // shown, not edited: the hour's Evd
        skyQuantity_->setCurrentIndex(kHorizontalIlluminance);
        skyValue_->setSuffix(QStringLiteral(" lx"));
        const Daylight d = resolveDaylight(doc_->scene());
        skyValue_->setValue(d.sky ? d.sky->horizontalIlluminance : 0.0);
        return;
    }
    if (general) {
        cieType_->setValue(sky->cieType);
        if (sky->cieType >= 1 && sky->cieType <= 15) cieTypeName_->setText(tr(kCieSkyNames[sky->cieType - 1]));
    }
    const bool zenith = sky->zenithLuminance.has_value();
    skyQuantity_->setCurrentIndex(zenith ? kZenithLuminance : kHorizontalIlluminance);
    skyValue_->setSuffix(zenith ? QStringLiteral(" cd/m²") : QStringLiteral(" lx"));
    skyValue_->setValue(zenith ? *sky->zenithLuminance : sky->horizontalIlluminance.value_or(0.0));
}

const Scene& DaylightPanel::beginChoice() {
    merge_.finish();
    error_->clear();
    return doc_->scene();
}

void DaylightPanel::chooseCity(int item) {
    const Scene& scene = beginChoice();
    if (item == kNoSite) {
        if (!scene.site) return;
        // A sun placed by time keeps where it stands, by direction: the scene stays valid.
        QUndoStack* undo = doc_->undoStack();
        undo->beginMacro(tr("Remove the site"));
        const int i = sunIndex(scene);
        if (i >= 0 && scene.lights[size_t(i)].sun && scene.lights[size_t(i)].sun->time)
            undo->push(new EditLightCommand(doc_, i, sunByDirection(scene, scene.lights[size_t(i)]), 0,
                                            tr("Place the sun by direction")));
        undo->push(new EditSiteCommand(doc_, std::nullopt, 0, tr("Remove the site")));
        undo->endMacro();
        return;
    }
    Site site = scene.site.value_or(Site());
    QString text;
    if (item == kCustomSite) {
        if (scene.site) return refresh();  // the fields edit the site; the list shows what it is
        site.latitudeDeg = latitude_->value();
        site.longitudeDeg = longitude_->value();
        site.utcOffsetHours = utcOffset_->value();
        text = tr("Add a site");
    } else {
        const SiteCity& c = kSiteCities[size_t(item - 1)];
        site.latitudeDeg = c.latitudeDeg;
        site.longitudeDeg = c.longitudeDeg;
        site.utcOffsetHours = c.utcOffsetHours;
        text = tr("Place the site in %1").arg(city_->itemText(item));
    }
    if (site == scene.site) return;
    doc_->undoStack()->push(new EditSiteCommand(doc_, site, 0, text));
}

template <class Command, class Value, class Edit>
void DaylightPanel::editValue(const void* field, const std::optional<Value>& current, Edit edit) {
    error_->clear();
    if (!current) return;
    Value value = *current;
    const QString text = edit(value);
    if (text.isEmpty() || value == *current) return;
    doc_->undoStack()->push(new Command(doc_, std::move(value), merge_.keyFor(field), text));
}

void DaylightPanel::editSite(const void* field) {
    editValue<EditSiteCommand>(field, doc_->scene().site, [&](Site& site) {
        if (field == latitude_) return taken(site.latitudeDeg, latitude_, tr("Change the latitude"));
        if (field == longitude_) return taken(site.longitudeDeg, longitude_, tr("Change the longitude"));
        if (field == utcOffset_) return taken(site.utcOffsetHours, utcOffset_, tr("Change the UTC offset"));
        // Only when the angle shown changed: the vector read from a file stays as it was.
        if (std::abs(north_->value() - northAngleDeg(site.north)) < 0.05) return QString();
        site.north = northFromAngle(north_->value());
        site.northGiven = true;
        return tr("Turn north");
    });
}

void DaylightPanel::setSunPresent(bool present) {
    const Scene& scene = beginChoice();
    const int i = sunIndex(scene);
    if (present && i < 0) {
        const Light sun = newSun(scene, doc_->uniqueName("sun"), localTime());
        doc_->undoStack()->push(new AddLightCommand(doc_, int(scene.lights.size()), sun,
                                                    tr("Add %1").arg(QString::fromStdString(sun.name))));
    } else if (!present && i >= 0) {
        if (scene.sky && scene.sky->model == SkyModelType::CieGeneral)
            return refuse(tr("A CIE general sky is shaped by the sun: choose another sky model before removing the sun."));
        if (scene.sky && scene.sky->model == SkyModelType::Perez)
            return refuse(tr("A Perez sky needs its hour's sun: choose another sky model before removing the sun."));
        if (scene.sky && scene.sky->levels == DaylightLevels::FollowAltitude) {
            // Nothing left to follow: the sky keeps, fixed, what it gives now.
            QUndoStack* undo = doc_->undoStack();
            undo->beginMacro(tr("Delete %1").arg(QString::fromStdString(scene.lights[size_t(i)].name)));
            chooseLevels(kFixedLevels);
            undo->push(new DeleteLightCommand(doc_, i));
            undo->endMacro();
            return;
        }
        doc_->undoStack()->push(new DeleteLightCommand(doc_, i));
    }
}

void DaylightPanel::editSun(const void* field) {
    error_->clear();
    const Scene& scene = doc_->scene();
    const int i = sunIndex(scene);
    if (i < 0) return;
    Light l = scene.lights[size_t(i)];
    if (!l.sun) l.sun = SunSpec();
    QString text;
    if (field == sunIlluminance_) {
        if (!l.sun->illuminanceGiven) return;  // a model gives it; the field only shows it
        l.sun->illuminanceLux = sunIlluminance_->value();
        text = tr("Change the sun's illuminance");
    } else {
        l.sun->angularDiameterDeg = sunDiameter_->value();
        l.sun->angularDiameterGiven = true;
        text = tr("Change the sun's diameter");
    }
    if (l == scene.lights[size_t(i)]) return;
    doc_->undoStack()->push(new EditLightCommand(doc_, i, l, merge_.keyFor(field), text));
}

void DaylightPanel::moveSun(const void* field) {
    error_->clear();
    // The slider and the time field show the same minute.
    if (field == time_) {
        const QSignalBlocker block(timeSlider_);
        timeSlider_->setValue(time_->time().hour() * 60 + time_->time().minute());
    } else if (field == timeSlider_) {
        const QSignalBlocker block(time_);
        time_->setTime(QTime(timeSlider_->value() / 60, timeSlider_->value() % 60));
    }
    const Scene& scene = doc_->scene();
    const int i = sunIndex(scene);
    if (i < 0 || !scene.site) return;  // the clock is kept for the sun added next
    const Light l = sunAtTime(scene.lights[size_t(i)], localTime());
    if (l == scene.lights[size_t(i)]) return;
    const QString text = tr("Move the sun to %1").arg(QString::fromStdString(localTime()).replace('T', ' '));
    doc_->undoStack()->push(new EditLightCommand(doc_, i, l, merge_.keyFor(field), text));
    // A Perez sky takes the irradiances of the hour the clock is in (a step of its own when the
    // hour changes); without its weather file it keeps the hour it has.
    const Scene& moved = doc_->scene();
    if (moved.sky && moved.sky->model == SkyModelType::Perez && weather_)
        if (const auto e = weatherHourDaylight(moved, *weather_, localTime(), "sun"); e && e->sky != *moved.sky)
            doc_->undoStack()->push(new EditSkyCommand(doc_, e->sky, 0, tr("Sky: the weather file's hour")));
}

void DaylightPanel::chooseSkyModel(int item) {
    const Scene& scene = beginChoice();
    if (item == kNoSky && scene.sky && scene.sky->model == SkyModelType::Perez) return leavePerezFor(item);
    if (item == kNoSky) {
        if (!scene.sky) return;
        lastSky_ = scene.sky;
        setSkyAndSun(std::nullopt, tr("Remove the sky"));
        return;
    }
    if (item == kCieGeneral && sunIndex(scene) < 0)
        return refuse(tr("A CIE general sky is shaped by the sun: add the sun first."));
    const bool perez = scene.sky && scene.sky->model == SkyModelType::Perez;
    if (item == kPerez && !perez) return choosePerez();
    if (item != kPerez && perez) return leavePerezFor(item);
    if (item == kPerez) return;
    Sky sky = scene.sky ? *scene.sky : lastSky_.value_or(defaultSky(scene));
    if (sky.levels == DaylightLevels::FollowAltitude && sunIndex(scene) < 0) sky = defaultSky(scene);
    const int remembered = sky.cieType;
    sky.model = item == kUniform ? SkyModelType::Uniform : item == kCieOvercast ? SkyModelType::CieOvercast
                                                                                : SkyModelType::CieGeneral;
    // The standard clear sky unless a type was chosen before; other models have no type.
    sky.cieType = item == kCieGeneral ? (remembered >= 1 && remembered <= 15 ? remembered : 12) : 0;
    if (sky == scene.sky) return;
    setSkyAndSun(sky, tr("Sky: %1").arg(skyModel_->itemText(item)));
}

void DaylightPanel::editSky(const void* field) {
    editValue<EditSkyCommand>(field, doc_->scene().sky, [&](Sky& sky) {
        if (field == cieType_) return taken(sky.cieType, cieType_, tr("Change the CIE sky type"));
        if (field == skyValue_ && sky.levels == DaylightLevels::FollowAltitude) return QString();  // shown, not edited
        if (field == skyValue_)
            return taken(sky.zenithLuminance ? sky.zenithLuminance : sky.horizontalIlluminance, skyValue_,
                         sky.zenithLuminance ? tr("Change the zenith luminance") : tr("Change the sky's illuminance"));
        sky.groundReflectance = groundReflectance_->value();
        sky.groundReflectanceGiven = true;
        return tr("Change the ground reflectance");
    });
}

}  // namespace lucerna
