// The daylight dock's levels: how bright the sun and the sky are, as fixed numbers or following
// the sun's altitude (the IES model of core/daylight/daylight_availability.h, which
// resolveDaylight applies), the sky's quantity (Eh or Lz), and the line that says where the sun
// stands and what sun and sky give an open plane.

#include "ui/scene_panels/daylight_panel.h"

#include "core/daylight/daylight.h"
#include "core/daylight/sky_model.h"
#include "ui/commands/daylight_commands.h"
#include "ui/commands/light_commands.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

// Toward the sun of the scene's sun (switched on or not: a CIE general sky keeps its place), or
// the zenith when there is none or its time cannot be placed.
V3d towardSun(const Scene& scene) {
    const int i = sunIndex(scene);
    if (i < 0) return V3d(0, 1, 0);
    try {
        return sunDirection(scene, scene.lights[size_t(i)]);
    } catch (const std::exception&) {
        return V3d(0, 1, 0);
    }
}

// The sky's horizontal illuminance on an open plane, lx (the sky alone). A coarse integral for
// a CIE general sky: the panel shows it on every step of a slider drag.
double skyHorizontalIlluminance(const Sky& sky, const V3d& sun) {
    if (sky.horizontalIlluminance) return *sky.horizontalIlluminance;
    return sky.zenithLuminance.value_or(0.0) * relativeHorizontalIlluminance(sky, sun, 64);
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

QString lux(double value) { return QStringLiteral("%L1 lx").arg(value, 0, 'f', 0); }

// What the levels give now: the sun's direct normal illuminance (as if it were switched on) and
// the sky's horizontal illuminance, lx.
struct Levels {
    double sunLux = 0, skyLux = 0;
};
Levels levelsNow(const Scene& scene) {
    Scene on = scene;
    const int i = sunIndex(on);
    if (i >= 0) on.lights[size_t(i)].on = true;
    Levels out;
    try {
        const Daylight d = resolveDaylight(on);
        if (d.sun) out.sunLux = d.sun->illuminanceLux;
        if (d.sky) out.skyLux = d.sky->horizontalIlluminance;
    } catch (const std::exception&) {
    }
    return out;
}

bool follows(const std::optional<Sky>& sky) { return sky && sky->levels == DaylightLevels::FollowAltitude; }

}  // namespace

void DaylightPanel::chooseLevels(int item) {
    const Scene& scene = beginChoice();
    if (!scene.sky || scene.sky->model == SkyModelType::Perez) return refresh();
    const bool follow = item == kFollowAltitude;
    if (follow == follows(scene.sky)) return;
    if (follow && sunIndex(scene) < 0)
        return refuse(tr("Levels that follow the sun's altitude need the sun: add it first."));
    Sky sky = *scene.sky;
    sky.zenithLuminance.reset();
    sky.horizontalIlluminance.reset();
    sky.levels = follow ? DaylightLevels::FollowAltitude : DaylightLevels::Fixed;
    // Fixed at what the sky gives now: the light does not jump.
    if (!follow) sky.horizontalIlluminance = levelsNow(scene).skyLux;
    setSkyAndSun(sky, follow ? tr("Daylight levels: follow the sun's altitude") : tr("Daylight levels: fixed"));
}

void DaylightPanel::setSkyAndSun(const std::optional<Sky>& sky, const QString& text) {
    const Scene& scene = doc_->scene();
    const int i = sunIndex(scene);
    std::optional<Light> sun;
    if (i >= 0 && scene.lights[size_t(i)].sun) {
        Light l = scene.lights[size_t(i)];
        const bool perez = sky && sky->model == SkyModelType::Perez;
        if (follows(sky) && l.sun->illuminanceGiven) {
            l.sun->illuminanceGiven = false;
            l.sun->illuminanceLux = 0;  // what the reader gives a sun without the key
        } else if (!follows(sky) && !perez && !l.sun->illuminanceGiven) {
            l.sun->illuminanceLux = levelsNow(scene).sunLux;
            l.sun->illuminanceGiven = true;
        }
        if (l != scene.lights[size_t(i)]) sun = l;
    }
    QUndoStack* undo = doc_->undoStack();
    undo->beginMacro(text);
    if (sun) undo->push(new EditLightCommand(doc_, i, *sun, 0, text));
    undo->push(new EditSkyCommand(doc_, sky, 0, text));
    undo->endMacro();
}

void DaylightPanel::refreshLevels() {
    const Scene& scene = doc_->scene();
    const bool perez = scene.sky && scene.sky->model == SkyModelType::Perez;
    const bool follow = follows(scene.sky);
    levels_->setEnabled(scene.sky && !perez);
    levels_->setCurrentIndex(follow ? kFollowAltitude : kFixedLevels);
    // Following, the fields show what the model gives and take no edits.
    sunIlluminance_->setReadOnly(follow);
    skyValue_->setReadOnly(follow);
    if (!follow) return;
    const Levels now = levelsNow(scene);
    sunIlluminance_->setValue(now.sunLux);
    skyQuantity_->setEnabled(false);
    skyQuantity_->setCurrentIndex(kHorizontalIlluminance);
    skyValue_->setSuffix(QStringLiteral(" lx"));
    skyValue_->setValue(now.skyLux);
}

void DaylightPanel::showSunPosition() {
    const Scene& scene = doc_->scene();
    const int i = sunIndex(scene);
    double sunEh = 0;
    if (i < 0) {
        sunPosition_->setText(tr("No sun."));
    } else {
        const Light& sun = scene.lights[size_t(i)];
        try {
            const V3d toward = sunDirection(scene, sun);
            const V3d north = scene.site ? scene.site->north.normalized() : Site().north;
            const V3d east = north.cross(V3d(0, 1, 0));
            const double elevation = degrees(std::asin(std::clamp(toward.y, -1.0, 1.0)));
            double azimuth = degrees(std::atan2(toward.dot(east), toward.dot(north)));
            if (azimuth < 0) azimuth += 360;
            QString where = tr("Elevation %1°, azimuth %2° (from north, eastward)")
                                .arg(elevation, 0, 'f', 1)
                                .arg(azimuth, 0, 'f', 1);
            if (elevation <= 0) where += tr("; below the horizon: no sunlight");
            if (!(sun.sun && sun.sun->time))
                where += scene.site ? tr(". Placed by direction: a date or time places it by the site's clock.")
                                    : tr(". Placed by direction: choose a site to place it by date and time.");
            if (!sun.on) where += tr(" The sun is switched off.");
            sunPosition_->setText(where);
            if (sun.on && sun.sun && toward.y > 0) sunEh = sun.sun->illuminanceLux * toward.y;
        } catch (const std::exception& e) {
            sunPosition_->setText(QString::fromStdString(e.what()));
        }
    }
    if (!scene.sky) {
        horizontalIlluminance_->setText(i < 0 ? QString() : tr("Eh %1 from the sun (no sky)").arg(lux(sunEh)));
        return;
    }
    double skyEh = 0;
    // The hour's model, or the IES model for levels that follow the sun, gives both.
    if (scene.sky->model == SkyModelType::Perez || scene.sky->levels == DaylightLevels::FollowAltitude) {
        const Daylight d = resolveDaylight(scene);
        skyEh = d.sky->horizontalIlluminance;
        sunEh = d.sun && d.sun->aboveHorizon ? d.sun->illuminanceLux * d.sun->towardSun.y : 0;
    } else {
        skyEh = skyHorizontalIlluminance(*scene.sky, towardSun(scene));
    }
    horizontalIlluminance_->setText(
        tr("Eh %1: sun %2, sky %3").arg(lux(sunEh + skyEh), lux(sunEh), lux(skyEh)));
}

void DaylightPanel::chooseSkyQuantity(int item) {
    const Scene& scene = beginChoice();
    if (!scene.sky) return;
    if (scene.sky->levels == DaylightLevels::FollowAltitude) return refresh();  // the model gives Eh
    const bool zenith = item == kZenithLuminance;
    if (zenith == scene.sky->zenithLuminance.has_value()) return;
    // The same sky, given by the other quantity.
    Sky sky = *scene.sky;
    const V3d sun = towardSun(scene);
    const double lz = zenithLuminance(sky, sun);
    if (zenith) {
        sky.zenithLuminance = lz;
        sky.horizontalIlluminance.reset();
    } else {
        sky.horizontalIlluminance = lz * relativeHorizontalIlluminance(sky, sun);
        sky.zenithLuminance.reset();
    }
    doc_->undoStack()->push(new EditSkyCommand(doc_, sky, 0,
                                               zenith ? tr("Give the sky by its zenith luminance")
                                                      : tr("Give the sky by its horizontal illuminance")));
}

}  // namespace lucerna
