// The daylight dock's Perez sky (weather_hour.h): a weather file's hour as the scene's daylight,
// and leaving it for another model, each one undo step.

#include "ui/scene_panels/daylight_panel.h"

#include "core/daylight/epw_file.h"
#include "ui/commands/daylight_commands.h"
#include "ui/commands/light_commands.h"

#include <QComboBox>
#include <QLabel>
#include <QUndoStack>

namespace lucerna {

QString DaylightPanel::useWeatherFile(const QString& path) {
    try {
        weather_ = readWeatherFile(path.toStdString());
    } catch (const WeatherFileError& e) {
        return QString::fromStdString(e.what());
    }
    weatherPath_ = path;
    weatherLabel_->setText(tr("Weather: %1").arg(QString::fromStdString(weather_->describe())));
    return {};
}

void DaylightPanel::applyDaylight(const DaylightEdit& e, const QString& text) {
    const Scene& scene = doc_->scene();
    QUndoStack* undo = doc_->undoStack();
    undo->beginMacro(text);
    if (!scene.site || e.site != *scene.site) undo->push(new EditSiteCommand(doc_, e.site, 0, text));
    if (e.sunIndex >= 0) undo->push(new EditLightCommand(doc_, e.sunIndex, e.sun, 0, text));
    else if (e.sun.type == LightType::Sun) undo->push(new AddLightCommand(doc_, int(scene.lights.size()), e.sun, text));
    undo->push(new EditSkyCommand(doc_, e.sky, 0, text));
    undo->endMacro();
}

void DaylightPanel::choosePerez() {
    if (!weather_) {
        const QString path = askWeather_ ? askWeather_() : QString();
        if (path.isEmpty()) {
            refresh();
            return refuse(tr("A Perez sky is a weather file's hour: choose a weather file (.epw)."));
        }
        if (const QString error = useWeatherFile(path); !error.isEmpty()) {
            refresh();
            return refuse(error);
        }
    }
    const auto e = weatherHourDaylight(doc_->scene(), *weather_, localTime(), doc_->uniqueName("sun"));
    if (!e) {
        refresh();
        return refuse(tr("The weather file has no row for %1.").arg(QString::fromStdString(localTime()).replace('T', ' ')));
    }
    applyDaylight(*e, tr("Sky: the weather file's hour"));
}

void DaylightPanel::leavePerezFor(int item) {
    const Scene& scene = doc_->scene();
    DaylightEdit e = leavePerez(scene, item == kUniform ? SkyModelType::Uniform : item == kCieOvercast ? SkyModelType::CieOvercast
                                                                                                      : SkyModelType::CieGeneral);
    QUndoStack* undo = doc_->undoStack();
    const QString text = tr("Sky: %1").arg(skyModel_->itemText(item));
    undo->beginMacro(text);
    if (e.sunIndex >= 0) undo->push(new EditLightCommand(doc_, e.sunIndex, e.sun, 0, text));
    undo->push(new EditSkyCommand(doc_, item == kNoSky ? std::optional<Sky>() : std::optional<Sky>(e.sky), 0, text));
    undo->endMacro();
}

}  // namespace lucerna
