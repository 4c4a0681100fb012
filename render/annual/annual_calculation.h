#pragma once
// A year of illuminance on a grid's points from a weather file (SPEC.md section 6), by daylight
// coefficients (daylight_coefficients.h): the paths are traced once, then every hour's Perez sky
// is averaged over the patches and dotted with each point's sky coefficients, the sun's indirect
// light is interpolated between the sun-path nodes, and the sun straight onto the point is traced
// at the hour's own position through its disc (exact: ASE and sunlit areas depend on it).
//
// Every value comes with its stated 95% error: the batch means' spread (Student's t) and the
// discretisation, measured in the same run on a sample of points and hours by summing the
// recorded paths direction by direction against the scene's own Perez sky (256-ring integral)
// and tracing the sun at its own position, compared with the binned and interpolated values.

#include "core/daylight/annual_metrics.h"
#include "core/daylight/epw_file.h"
#include "core/process_group.h"
#include "core/scene/scene.h"
#include "core/task_system.h"
#include "render/annual/daylight_coefficients.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct AnnualSettings {
    DaylightCoefficientSettings coefficients;
    double sunDeclinationStepDeg = 2.35;   // SunPathGrid
    double sunHourAngleStepDeg = 3.75;
    int sunDiscSamples = 16;              // rays through the disc per point and hour
    std::optional<double> dewPointC;      // replaces the file's (--dew-point)
    int checkPoints = 16, checkHours = 48;  // the discretisation's sample
    // Where the traced points are kept as they go (annual_checkpoint.h), in a file named by the
    // year's key; empty: nowhere. With `resume`, the points of an earlier run of the same key
    // are read instead of traced again.
    std::string checkpointDirectory;
    bool resume = false;
    // A year shared among processes (`mpirun -n N lucerna annual`, core/process_group.h): the
    // points are dealt out (the discretisation's to rank 0), their coefficients gathered on rank
    // 0, which alone evaluates the hours; each point's paths are drawn as one process draws them,
    // so the values are those of one process. Every process calls computeAnnual; nullptr: alone.
    ProcessGroup* processes = nullptr;
};

struct AnnualResult {
    std::vector<AnnualHour> hours;   // per row, with Evd
    size_t points = 0;
    std::vector<float> lux;          // hours x points (row-major by hour)
    std::vector<float> directSunLux; // the sun's disc straight through glazing alone (ASE)
    std::vector<float> errorLux;     // the stated 95% error of each value
    std::vector<uint8_t> insideGeometry;  // per point (grid_diagnosis.h): 0 lx, left out of the figures
    int daylightHours = 0;           // rows with Ib > 0 or Ed > 0
    // The discretisation's 95% relative error (of a point's total) as measured on the sample,
    // and the median over daylit values of the statistical 95% relative error.
    double discretisationRelative = 0, statisticalRelative = 0;
    // The discretisation's parts: the straight view of sky and ground (cells against cells twice
    // as fine per side, luminance by patch against the sky's own), the reflected sky (patch
    // against direction) and the sun's reflections (nodes against its own position).
    double discretisationParts[3] = {0, 0, 0};
    double tracingSeconds = 0, hoursSeconds = 0;
    bool cancelled = false;
    size_t resumedPoints = 0;        // read from the checkpoint, not traced
    bool onRoot = true;              // false on the other ranks of a shared year: nothing but this
    std::string checkpointPath;      // the checkpoint's file (left there when cancelled)
};

// The year at `points` (scene units) facing `normal`, on `scene` with its electric light off and
// its own sun and sky replaced by each hour's; the site's latitude and time zone come from the
// weather file (the scene's north stays). Progress: the tracing, then the hours.
AnnualResult computeAnnual(const Scene& scene, const std::vector<V3d>& points, const V3d& normal,
                           const WeatherFile& weather, const AnnualSettings& settings, TaskContext& ctx);

// The daylight of one row of the weather file: the weather file's site with the scene's north,
// a sun named "sun" placed by the row's instant (hour - 0.5, local standard time) with the scene's
// sun's disc, no illuminance of its own, and the row's perez sky (the scene's ground reflectance;
// dewPointC replaces the row's when given).
struct HourDaylight {
    Site site;
    Light sun;
    Sky sky;
};
HourDaylight daylightOfHour(const Scene& scene, const WeatherFile& weather, size_t row, std::optional<double> dewPointC = {});

// The row of the weather file for month/day and the hour ending `hour` (1..24); nothing if none.
std::optional<size_t> weatherRow(const WeatherFile& weather, int month, int day, int hour);

// The scene of one row of the weather file (SPEC.md section 6's --export-hour): the perez sky of
// that hour and the sun placed by the row's instant (hour - 0.5, local standard time), the
// weather file's site with the scene's north, the electric light switched off. dewPointC
// replaces the row's when given.
Scene sceneOfHour(const Scene& scene, const WeatherFile& weather, size_t row, std::optional<double> dewPointC = {});

}  // namespace lucerna
