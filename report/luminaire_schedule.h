#pragma once
// The luminaire schedule of a report (README, "Reports"): the electric lights switched on,
// alike ones counted together, with their flux as installed, the power their files state, and
// the connected load per square metre of the floor; the daylight in words.

#include "report/report_data.h"

namespace lucerna {

// `scene` as loaded (its luminaires' files read). The flux is the new installation's (no
// maintenance factor); the floor area is the geometry's extent in plan (x by z, y up).
Schedule luminaireSchedule(const Scene& scene);

// What the report's figures are, as `lucerna grid` and the grid dock say it (core/scene/scene.h,
// describeMaintenance): "maintained values (maintenance factor 0.80)", "values of the new
// installation (no maintenance factor)" or "daylight only (no electric light to maintain)".
std::string maintenanceStatement(const Scene& scene);

}  // namespace lucerna
