#include "report/luminaire_schedule.h"

#include "core/daylight/daylight.h"
#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/light_output.h"
#include "core/photometry/luminaire.h"
#include "core/number_format.h"
#include "core/photometry/photometric_units.h"
#include "core/scene/scene_energy.h"
#include "core/scene/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

ScheduleEntry entryOf(const Scene& scene, const Light& l) {
    ScheduleEntry e;
    e.count = 1;
    e.maintenanceFactor = maintenanceFactor(scene, l);
    if (l.type == LightType::Luminaire && l.luminaire) {
        e.kind = "Luminaire";
        e.file = l.luminaire->file;
        e.lumensEach = luminaireFlux(l);
        e.temperatureK = l.luminaire->temperatureK;
        if (const auto& d = l.luminaire->distribution) {
            e.product = d->name;
            e.colourRenderingIndex = d->colourRenderingIndex;
        }
    } else {
        e.kind = l.type == LightType::Spot ? "Spot light" : "Point light";
        e.lumensEach = luminousFluxLm(l);
        if (l.photometric) e.temperatureK = l.photometric->temperatureK;
    }
    e.wattsEach = circuitWatts(l);  // the scene's circuit_watts over the file's (README, "Energy")
    return e;
}

// Alike: the same kind, file, stated figures and (to a tenth of a lumen) flux.
bool alike(const ScheduleEntry& a, const ScheduleEntry& b) {
    return a.kind == b.kind && a.file == b.file && a.product == b.product && a.wattsEach == b.wattsEach &&
           a.colourRenderingIndex == b.colourRenderingIndex && a.temperatureK == b.temperatureK &&
           a.maintenanceFactor == b.maintenanceFactor && std::abs(a.lumensEach - b.lumensEach) < 0.05;
}

double triangleArea(const TriangleMesh& m, const V3i& t) {
    const V3d& a = m.vertices[size_t(t.x)];
    return 0.5 * (m.vertices[size_t(t.y)] - a).cross(m.vertices[size_t(t.z)] - a).length();
}

std::string sunLine(const Scene& scene, const Light& l) {
    const SunSpec s = l.sun.value_or(SunSpec());
    const V3d toward = sunDirection(scene, l);
    const double elevation = std::asin(std::clamp(toward.y, -1.0, 1.0)) * 180 / std::numbers::pi;
    const Daylight d = resolveDaylight(scene);  // a perez sky gives the illuminance
    std::string line = "Sun: " + formatNumber(d.sun ? d.sun->illuminanceLux : s.illuminanceLux, 6) + " lx direct normal, elevation " +
                       fixedNumber(elevation, 1) + " deg";
    if (s.time) line += ", " + *s.time + " local time";
    if (scene.site)
        line += " at " + fixedNumber(scene.site->latitudeDeg, 3) + " N, " + fixedNumber(scene.site->longitudeDeg, 3) + " E";
    if (toward.y <= 0) line += " (below the horizon: no light)";
    return line;
}

std::string skyLine(const Scene& scene) {
    const Daylight d = resolveDaylight(scene);
    const Sky& sky = *scene.sky;
    std::string line = sky.model == SkyModelType::Uniform       ? "Sky: uniform"
                       : sky.model == SkyModelType::CieOvercast ? "Sky: CIE overcast"
                       : sky.model == SkyModelType::CieGeneral  ? "Sky: CIE general sky type " + std::to_string(sky.cieType)
                                                                : "Sky: Perez all-weather, Ib " + formatNumber(sky.directNormalIrradiance, 4) +
                                                                      " W/m\u00b2, Ed " + formatNumber(sky.diffuseHorizontalIrradiance, 4) + " W/m\u00b2";
    if (d.sky) {
        const double eh = d.sky->horizontalIlluminance;
        line += ", horizontal illuminance " + formatNumber(eh, 6) + " lx, zenith luminance " +
                formatNumber(d.sky->zenithLuminance, 6) + " cd/m\u00b2";
    }
    return line + ", ground reflectance " + formatNumber(sky.groundReflectance, 3);
}

}  // namespace

Schedule luminaireSchedule(const Scene& scene) {
    Schedule s;
    double watts = 0;
    int withWatts = 0;
    for (const Light& l : scene.lights) {
        if (!l.on) {
            ++s.switchedOff;
            continue;
        }
        if (l.type == LightType::Sun) {
            s.daylight.push_back(sunLine(scene, l));
            continue;
        }
        if (l.type == LightType::Directional) {
            s.daylight.push_back("Directional light '" + l.name + "': " + formatNumber(illuminanceLx(l), 6) +
                                 " lx on a surface facing it");
            continue;
        }
        const ScheduleEntry e = entryOf(scene, l);
        ++s.luminaires;
        s.totalLumens += e.lumensEach;
        if (e.wattsEach) watts += *e.wattsEach, ++withWatts;
        else ++s.withoutWatts;
        const auto same = std::find_if(s.entries.begin(), s.entries.end(), [&](const ScheduleEntry& x) { return alike(x, e); });
        if (same != s.entries.end()) ++same->count, same->names.push_back(l.name);
        else s.entries.push_back(e), s.entries.back().names.push_back(l.name);
    }
    // Emitting objects, one line per material: pi A L, one-sided Lambertian (A in m^2).
    const double m2 = scene.metersPerUnit * scene.metersPerUnit;
    for (const Object& o : scene.objects) {
        const Material* m = scene.findMaterial(o.material);
        if (!m || m->type != MaterialType::Emitter || !o.worldMesh) continue;
        double area = 0;
        for (const V3i& t : o.worldMesh->triangles) area += triangleArea(*o.worldMesh, t);
        ScheduleEntry e;
        e.kind = "Emitter";
        e.product = "material '" + m->name + "'";
        e.names.push_back(o.name);
        e.count = 1;
        e.lumensEach = std::numbers::pi * area * m2 * luminance(m->radiance) * kLumensPerWatt;
        e.maintenanceFactor = scene.maintenance ? scene.maintenance->factor() : 1.0;
        ++s.luminaires;
        ++s.withoutWatts;
        s.totalLumens += e.lumensEach;
        s.entries.push_back(e);
    }
    if (scene.sky) s.daylight.push_back(skyLine(scene));
    if (withWatts > 0) s.totalWatts = watts;
    s.floorAreaM2 = planAreaM2(scene);
    if (s.totalWatts && s.withoutWatts == 0 && s.floorAreaM2 > 0) s.wattsPerM2 = *s.totalWatts / s.floorAreaM2;
    return s;
}

std::string maintenanceStatement(const Scene& scene) { return describeMaintenance(maintenanceRange(scene)); }

}  // namespace lucerna
