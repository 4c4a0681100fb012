#pragma once
// What a lighting design report states (README, "Reports"), as plain values: computed from a
// scene by report_builder.h, laid out on pages by report_writer.h. Every figure here is the one
// printed, so that a test can read the PDF back against it.

#include "core/photometry/calculation_grid.h"
#include "core/daylight/annual_metrics.h"
#include "core/daylight/daylight_provision.h"
#include "core/daylight/epw_file.h"
#include "core/photometry/glare.h"
#include "core/image/image.h"
#include "core/photometry/lighting_standards.h"
#include "core/photometry/surrounding_zones.h"
#include "core/scene/scene.h"
#include "core/scene/scene_energy.h"
#include "render/photometry/glare_evaluation.h"
#include "render/photometry/grid_calculation.h"
#include "render/photometry/task_area_figures.h"
#include "report/luminaire_data_sheet.h"
#include "report/room_summary.h"
#include "report/rooms_summary.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

// How the report computes its figures. The grids take `lucerna grid`'s settings (method, error
// target, seed, samples per pass, time limit), so that the same settings give the same numbers.
struct ReportSettings {
    GridSettings grid;            // every task area's grid
    // The converged render: passes of the auto backend, at most renderSpp, until its estimated
    // relMSE (the film's half-buffers, checked every 8 passes from 16 on) is at most renderRelmse
    // (0: all renderSpp passes). 64 passes leave a sunlit room grainy (relMSE 0.14); 0.002 reads
    // as a picture to hand in (the office floor after about 120 passes).
    int renderSpp = 256;
    double renderRelmse = 0.002;
    bool renders = true;          // leave the renders page out (false)
    bool glare = true;            // compute UGR for the task areas' observers
    bool daylightFactor = true;   // of a scene with daylight: each area's daylight factor too
    double eyeHeightM = 1.2;      // the default observers' eyes above the floor (seated)
    // EN 12464-1:2021's figures beside each area's grid, Ez over the area and its room's walls and
    // ceiling: each point's error target is the grid's times these (0: the grid's own), 5% and
    // 10% for the grid's 2%. Their requirements (an office: Ez, walls 150 lx, ceiling 100 lx, U0
    // 0.10) lie far from what a lit room achieves, and at the grid's 2% they took longer than the
    // rest of the office floor's report together; at these the office floor's figures carry error
    // bars of about 3% (Ez) and 5% (walls, ceiling). README, "Reports".
    double cylindricalErrorFactor = 2.5;
    double roomSurfaceErrorFactor = 5;
    // SPEC.md section 6: with a weather file, each area's year of daylight and its metrics
    // (render/annual/annual_calculation.h), occupied from 8:00 to 18:00 unless given.
    std::optional<WeatherFile> weather;
    std::string weatherPath;      // as given, for the report's words
    Occupancy occupancy;
};

// An area's year of daylight (ReportSettings::weather).
struct AnnualReport {
    AnnualMetrics metrics;
    int daylightHours = 0;
    double statisticalRelative = 0, discretisationRelative = 0;  // the stated 95% errors
    double seconds = 0;
    std::vector<double> da300Percent;     // per point, for the plan
    std::vector<uint8_t> insideGeometry;  // per point
};

// One line of the luminaire schedule: the lights of one kind that are alike (same file, same
// flux as installed, same stated watts).
struct ScheduleEntry {
    std::string kind;            // "Luminaire", "Spot light", "Point light", "Emitter"
    std::string file;            // the photometric file as the scene names it; empty for others
    std::string product;         // the luminaire's name as its file gives it
    std::vector<std::string> names;  // the lights' names in the scene
    int count = 0;
    double lumensEach = 0;       // luminous flux as installed (new, no maintenance factor), lm
    std::optional<double> wattsEach;           // the circuit power (circuit_watts, else the file's input watts)
    std::optional<double> colourRenderingIndex;// the file's Ra
    std::optional<double> temperatureK;        // the scene's colour temperature, when given
    double maintenanceFactor = 1;
};

struct Schedule {
    std::vector<ScheduleEntry> entries;
    int luminaires = 0;              // lights counted (point, spot, luminaire)
    int switchedOff = 0;             // lights switched off, not counted
    int withoutWatts = 0;            // lights whose power no file states
    double totalLumens = 0;
    std::optional<double> totalWatts;  // of the lights that state it; absent when none does
    double floorAreaM2 = 0;          // the geometry's extent in plan
    std::optional<double> wattsPerM2;  // only when every light states its power
    std::vector<std::string> daylight;  // one line per daylight source (sun, sky), in words
};

// One glare observer of a task area and what it sees.
struct ObserverGlare {
    GlareObserver observer;       // scene units
    bool defaultObserver = false; // one of the four placed at the area's edges (core/photometry/glare.h)
    GlareResult result;
};

// The daylight factor on a task area, as `lucerna grid --daylight-factor` computes it (SPEC.md
// section 5: the CIE overcast sky alone), with EN 17037's daylight provision.
struct DaylightFactorReport {
    GridResult result;                // illuminance under that sky, lx
    std::vector<double> percent;      // DF per point, %
    GridStatistics statistics;        // of the DF
    DaylightProvision provision;
    double skyHorizontalIlluminance = 0;  // Eh,sky, lx
    double medianDiffuseIlluminance = kDefaultMedianDiffuseIlluminance;
    bool medianGiven = false;         // by the site (else EN 17037's usual value)
};

// EN 12464-1's zones around a task area (core/photometry/surrounding_zones.h), computed as one grid
// of their points in the task area's plane.
struct ZoneReport {
    std::string name;           // "surrounding zone", "background area"
    double widthMeters = 0;
    ZoneGrid grid;              // clipped to the area's room box
    GridResult result;          // over grid.points
    GridStatistics statistics;
    std::optional<ZoneRequirement> requirement;  // absent: the area names no activity
    std::vector<RequirementCheck> checks;
};

// The walls and ceiling of one room box (EN 12464-1:2021), computed once for every task area in it.
struct RoomSurfacesReport {
    TaskAreaRoom room;
    RoomSurfaceResult result;
    GridSettings settings;           // as computed (the error target relaxed by roomSurfaceErrorFactor)
    std::vector<std::string> areas;  // the task areas whose requirements asked for them
};

struct AreaReport {
    std::string name;
    bool defaultWorkPlane = false;  // the scene has no task areas: the work plane at 0.8 m
    CalculationGrid grid;
    GridLayout layout;
    GridResult result;
    GridStatistics statistics;
    const ActivityRequirement* requirement = nullptr;  // the activity (null: none given)
    std::optional<double> worstUgr;
    double worstUgrError = 0;               // its 95% error bar
    std::optional<double> colourRendering;  // the lowest Ra of the luminaires (absent: not stated)
    std::vector<RequirementCheck> checks;   // with an activity
    std::vector<ObserverGlare> glare;
    std::optional<DaylightFactorReport> daylightFactor;  // scenes with daylight
    std::optional<AnnualReport> annual;                  // with a weather file
    // EN 12464-1:2021 (task_area_figures.h), as the requirement asks: the room box the area lies
    // in, Ez over the area, and its room's walls and ceiling (an index into
    // ReportData::roomSurfaces); the figures the checks were made on; the modelling ratio
    // Ez / Eavg (guidance, not checked); the zones around it (its surrounding_m, background_m).
    TaskAreaRoom room;
    std::optional<CylindricalFigures> cylindrical;
    std::optional<size_t> roomSurfaces;
    TaskAreaFigures figures;
    std::optional<double> modellingRatio;
    std::vector<ZoneReport> zones;
};

// The renders page: the camera's view, converged, and its lux view (false colour).
struct ReportRenders {
    Image converged;             // linear radiance, with the albedo layer for the lux view
    std::string backend;         // the backend that rendered it (auto)
    std::string autoReason;      // what auto measured and decided
    int passes = 0;              // the render's passes (auto's: each a pass of one method's replica)
    double samplesPerPixel = 0, seconds = 0, estimatedRelmse = 0;
    float exposureStops = 0;     // the picture's exposure: the log-average luminance to mid grey
    double luxLo = 0, luxHi = 0;  // the lux view's false-colour range (log scale)
};

struct ReportData {
    // The cover (Scene::project; the name falls back to the scene file's name).
    std::string projectName, client, designer, notes;
    std::string sceneFile;       // its file name
    std::string date;            // the day the report was made, YYYY-MM-DD
    std::string software;        // "Lucerna 0.1.0"
    std::string maintenance;     // "maintained values, MF 0.80", or the new installation
    SceneSnapshot scene;         // as loaded, for the plans
    Schedule schedule;
    std::vector<LuminaireDataSheet> dataSheets;  // one per luminaire type of the schedule
    std::optional<RoomSummary> room;             // absent for a scene with rooms (the `rooms` key)
    std::optional<RoomsSummary> rooms;           // a scene with rooms: room by room
    std::vector<RoomSurfacesReport> roomSurfaces;  // each room box once
    SceneEnergy energy;          // EN 15193-1's LENI (README, "Energy (LENI)")
    std::vector<AreaReport> areas;
    std::optional<ReportRenders> renders;
    ReportSettings settings;
    double seconds = 0;          // the whole calculation
};

}  // namespace lucerna
