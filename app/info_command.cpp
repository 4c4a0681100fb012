// lucerna info (SPEC.md section 2: validate a scene and print its statistics, with the additions
// the README lists: photometry, maintenance, energy, task areas, portals) and lucerna standards
// (the bundled EN 12464-1 tables).
#include "app/cli.h"
#include "app/cli_support.h"

#include "core/daylight/daylight.h"
#include "core/daylight/sky_model.h"
#include "core/number_format.h"
#include "core/photometry/lighting_standards.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_energy.h"
#include "core/scene/scene_io.h"
#include "render/engine/backend_table.h"
#include "render/engine/measured_auto/measured_auto_settings.h"
#include "render/trace/render_scene.h"

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace lucerna::cli {

namespace {

Scene loadOrThrow(const std::string& path, LoadReport* report) {
    try {
        return loadScene(path, report);
    } catch (const SceneError& e) {
        throw UsageError(e.what());
    }
}

const char* materialTypeName(MaterialType t) {
    switch (t) {
    case MaterialType::Diffuse: return "diffuse";
    case MaterialType::Glossy: return "glossy";
    case MaterialType::Mirror: return "mirror";
    case MaterialType::Dielectric: return "dielectric";
    case MaterialType::Emitter: return "emitter";
    case MaterialType::Glazing: return "glazing";
    }
    return "?";
}

std::string formatLumens(double lm) { return formatNumber(lm, 6); }

// A luminaire's file against itself: the flux it states, the flux its table integrates to (exact
// for the bilinear table), its peak; then what the scene makes of it. Files whose two fluxes
// differ by more than 2% get a warning line (for IES files the stated flux is the lamps', so a
// light output ratio under 98% shows here too).
void printLuminaire(const Light& l) {
    const LuminaireSpec& s = *l.luminaire;
    std::cout << "luminaire, " << s.file;
    if (!s.distribution) {
        std::cout << " (not loaded)\n";
        return;
    }
    const GoniometricDistribution& d = *s.distribution;
    const double integrated = d.integratedFlux();
    std::cout << ": file states ";
    if (d.statedFluxLm > 0) std::cout << formatLumens(d.statedFluxLm) << " lm";
    else std::cout << "no flux (absolute photometry)";
    std::cout << ", distribution integrates to " << formatLumens(integrated) << " lm, max "
              << formatLumens(d.maxIntensity()) << " cd; in the scene " << formatLumens(luminaireFlux(l)) << " lm\n";
    // What UGR and the report read (README, "Glare", "Reports").
    std::cout << "    luminous area ";
    if (s.luminousAreaM) std::cout << s.luminousAreaM->x << " x " << s.luminousAreaM->y << " m (luminous_area)";
    else if (d.luminous.stated())
        std::cout << d.luminous.widthM << " x " << d.luminous.lengthM << " m" << (d.luminous.elliptical ? " (round)" : "")
                  << " (file)";
    else std::cout << "not stated";
    std::cout << "; input " << (d.inputWatts ? formatNumber(*d.inputWatts, 6) + " W" : std::string("not stated"))
              << "; Ra " << (d.colourRenderingIndex ? formatNumber(*d.colourRenderingIndex, 3) : std::string("not stated"))
              << "; CCT " << (d.colourTemperatureK ? formatNumber(*d.colourTemperatureK, 6) + " K" : std::string("not stated"))
              << "\n";
    if (d.statedFluxLm > 0 && std::abs(integrated - d.statedFluxLm) > 0.02 * d.statedFluxLm) {
        char pct[32];
        std::snprintf(pct, sizeof pct, "%+.0f%%", 100.0 * (integrated - d.statedFluxLm) / d.statedFluxLm);
        std::cout << "  warning: luminaire '" << l.name << "': file states " << formatLumens(d.statedFluxLm)
                  << " lm, distribution integrates to " << formatLumens(integrated) << " lm (" << pct << ")\n";
    }
}

// Each light's luminous output (683 lm/W, Rec.709 luminance; SPEC.md): the flux of point and spot
// lights from their distribution's solid angle, of emissive objects pi A L (one-sided Lambertian,
// A in m^2), and the illuminance a directional light gives a surface facing it.
// SPEC.md section 5: where the sun stands and what it gives.
void printSun(const Scene& scene, const Light& l) {
    const SunSpec s = l.sun.value_or(SunSpec());
    const V3d toward = sunDirection(scene, l);
    const double elevation = std::asin(std::clamp(toward.y, -1.0, 1.0)) * 180 / std::numbers::pi;
    const Daylight d = resolveDaylight(scene);  // a perez sky gives the illuminance
    std::cout << "sun, " << formatLumens(d.sun ? d.sun->illuminanceLux : s.illuminanceLux) << " lx direct normal, disc " << s.angularDiameterDeg
              << " deg, elevation " << std::fixed << std::setprecision(2) << elevation << std::defaultfloat
              << std::setprecision(6) << " deg" << (s.time ? " at " + *s.time + " local time" : std::string())
              << (toward.y > 0 ? "" : " (below the horizon: no light)") << "\n";
}

void printSky(const Scene& scene) {
    if (!scene.sky) return;
    const Daylight d = resolveDaylight(scene);
    const char* model = scene.sky->model == SkyModelType::Uniform       ? "uniform"
                        : scene.sky->model == SkyModelType::CieOvercast ? "cie_overcast"
                        : scene.sky->model == SkyModelType::CieGeneral  ? "cie_general"
                                                                        : "perez";
    const double eh = d.sky->horizontalIlluminance;
    std::cout << "sky: " << model;
    if (scene.sky->model == SkyModelType::CieGeneral) std::cout << " type " << scene.sky->cieType;
    if (scene.sky->levels == DaylightLevels::FollowAltitude) std::cout << ", levels following the sun's altitude (IES)";
    if (const auto& p = d.sky->perez)
        std::cout << " (Ib " << formatLumens(scene.sky->directNormalIrradiance) << " W/m2, Ed "
                  << formatLumens(scene.sky->diffuseHorizontalIrradiance) << " W/m2: clearness " << std::setprecision(3)
                  << p->clearness() << ", brightness " << p->brightness() << std::setprecision(6) << ", category "
                  << p->category() << ")";
    std::cout << ", zenith luminance " << formatLumens(d.sky->zenithLuminance) << " cd/m2, horizontal illuminance "
              << formatLumens(eh) << " lx, ground " << formatLumens(d.sky->groundLuminance) << " cd/m2\n";
}

void printPhotometry(const Scene& scene) {
    const auto lumens = [](double watts) { return formatLumens(watts * kLumensPerWatt); };
    for (const Light& l : scene.lights) {
        std::cout << "  " << l.name << (l.on ? "" : " (switched off)") << ": ";
        switch (l.type) {
        case LightType::Point:
            std::cout << "point, " << lumens(luminance(l.intensity) * pointSolidAngle()) << " lm\n";
            break;
        case LightType::Spot:
            std::cout << "spot, " << lumens(luminance(l.intensity) * spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg))
                      << " lm (" << lumens(luminance(l.intensity)) << " cd on axis)\n";
            break;
        case LightType::Directional:
            std::cout << "directional, " << lumens(luminance(l.irradiance)) << " lx on a surface facing it\n";
            break;
        case LightType::Luminaire: printLuminaire(l); break;
        case LightType::Sun: printSun(scene, l); break;
        }
    }
    printSky(scene);
    const double m2 = scene.metersPerUnit * scene.metersPerUnit;
    for (const Object& o : scene.objects) {
        const auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                                     [&](const Material& m) { return m.name == o.material; });
        if (it == scene.materials.end() || it->type != MaterialType::Emitter || !o.worldMesh) continue;
        double area = 0;
        for (const V3i& t : o.worldMesh->triangles) {
            const V3d& a = o.worldMesh->vertices[size_t(t.x)];
            area += 0.5 * (o.worldMesh->vertices[size_t(t.y)] - a).cross(o.worldMesh->vertices[size_t(t.z)] - a).length();
        }
        std::cout << "  " << o.name << ": emitter, " << lumens(std::numbers::pi * area * m2 * luminance(it->radiance))
                  << " lm\n";
    }
}

int infoImpl(const std::vector<std::string>& args) {
    if (args.size() != 1) throw UsageError("usage: lucerna info SCENE.json");
    LoadReport report;
    const Scene scene = loadOrThrow(args[0], &report);
    for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
    const SceneFeatures f = analyseFeatures(scene);
    std::cout << "scene: " << args[0] << "\n"
              << "meters_per_unit: " << scene.metersPerUnit << "\n"
              << "camera: " << scene.camera.width << "x" << scene.camera.height << ", fov_y " << scene.camera.fovYDeg
              << " deg\n"
              << "objects: " << scene.objects.size() << "\n"
              << "triangles: " << f.triangles << "\n"
              << "degenerate triangles dropped: " << report.degenerateTrianglesDropped << "\n"
              << "materials: " << scene.materials.size() << "\n";
    for (const Material& m : scene.materials) std::cout << "  " << m.name << ": " << materialTypeName(m.type) << "\n";
    std::cout << "emitter triangles: " << f.emitterTriangles << "\n"
              << "lights: " << scene.lights.size() << " (point " << f.pointLights << ", spot " << f.spotLights
              << ", directional " << f.directionalLights << ", luminaire " << f.luminaires;
    if (f.hasSun) std::cout << ", sun 1";
    if (const auto off = std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return !l.on; }))
        std::cout << "; " << off << " switched off";
    std::cout << ")\n";
    printPhotometry(scene);
    if (maintenanceRange(scene).maintained()) std::cout << "maintenance: " << describeMaintenance(maintenanceRange(scene)) << "\n";
    // EN 15193-1 (README, "Energy"): when the scene gives its building type.
    if (scene.energy) std::cout << "energy: " << describeLeni(sceneEnergy(scene), false) << "\n";
    for (const TaskArea& a : scene.taskAreas) {
        std::cout << "task area '" << a.grid.name << "': ";
        if (const ActivityRequirement* r = findActivity(a.activity, lightingStandardOf(scene)))
            std::cout << describeRequirement(*r, lightingStandardOf(scene));
        else std::cout << "no activity";
        std::cout << "\n";
    }
    std::string needs;
    if (f.hasDiffuse) needs += " diffuse";
    if (f.hasGlossy) needs += " glossy";
    if (f.hasMirror) needs += " mirror";
    if (f.hasDielectric) needs += " dielectric";
    if (f.emitterTriangles) needs += " area-lights";
    if (f.hasDeltaLights()) needs += " delta-lights";
    if (f.hasDaylight()) needs += " daylight";
    if (f.hasGlazing) needs += " glazing";
    if (f.hasDaylight()) {  // the panes and openings daylight particles go through (which side is outside: traced)
        const RenderScene traced(std::make_shared<const Scene>(scene), 0, 0, nullptr, kDefaultLightSelection, true);
        std::cout << "portals (mir's by default, the others' with --option daylight_portals=on): "
                  << traced.lights().particlePortals().describe(float(scene.metersPerUnit));
        std::string openings;
        for (const Object& o : scene.objects)
            if (o.portal) openings += (openings.empty() ? "" : ", ") + o.name;
        if (!openings.empty()) std::cout << "; objects marked as openings: " << openings;
        std::cout << "\n";
    }
    std::cout << "needs:" << (needs.empty() ? " nothing (no light, or nothing to light)" : needs) << "\n";
    std::string candidates;
    for (const std::string& name : autoCandidates(scene)) candidates += " " + name;
    std::cout << "auto backend: measures" << candidates << " and combines their films; its former rule would pick "
              << chooseAutoBackend(scene).reason << "\n";
    return 0;
}

int standardsImpl(const std::vector<std::string>& args) {
    const char* usage = "usage: lucerna standards [--edition 2011|2021]";
    StandardEdition edition = kDefaultStandardEdition;
    if (!args.empty()) {
        if (args.size() != 2 || args[0] != "--edition") throw UsageError(usage);
        if (args[1] == "2011") edition = StandardEdition::En12464_2011;
        else if (args[1] == "2021") edition = StandardEdition::En12464_2021;
        else throw UsageError("--edition: expected 2011 or 2021, got '" + args[1] + "'");
    }
    const bool with2021 = edition == StandardEdition::En12464_2021;
    std::cout << standardEditionName(edition) << " (a selection): reference, area: activity; Em lx, UGR_L, U0, Ra";
    if (with2021)
        std::cout << "; Em,u lx; Ez, walls, ceiling lx (U0)\n"
                     "  \"2011 entry\": the bundled 2021 table lacks the activity; it is checked against its 2011 figures";
    std::cout << "\n";
    // A 2021 figure, "-" where the entry states none.
    const auto lux = [](double x, double u0) {
        if (!(x > 0)) return std::string("-");
        return fixedNumber(x, 0) + (u0 > 0 ? " (" + fixedNumber(u0, 2) + ")" : std::string());
    };
    for (const ActivityRequirement* a : activitiesOf(edition)) {
        std::cout << a->reference << "  " << a->area << ": " << a->activity << "; Em " << a->maintainedLux << ", UGR_L "
                  << a->ugrLimit << ", U0 " << fixedNumber(a->uniformity, 2) << ", Ra " << a->colourRendering;
        if (with2021 && a->edition != edition) std::cout << "; 2011 entry";
        else if (with2021)
            std::cout << "; Em,u " << lux(a->modifiedLux, 0) << "; Ez " << lux(a->cylindricalLux, a->cylindricalUniformity)
                      << ", walls " << lux(a->wallLux, a->wallUniformity) << ", ceiling "
                      << lux(a->ceilingLux, a->ceilingUniformity);
        std::cout << "\n";
    }
    return 0;
}

}  // namespace

int info(const std::vector<std::string>& args) { return runCommand(infoImpl, args); }
int standards(const std::vector<std::string>& args) { return runCommand(standardsImpl, args); }

}  // namespace lucerna::cli
