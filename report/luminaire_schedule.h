#pragma once
// The luminaire schedule of a report (README, "Reports"): the electric lights switched on,
// alike ones counted together, with their flux as installed, the power their files state, and
// the connected load per square metre of the floor; the daylight in words.

#include "report/report_data.h"

namespace lucerna {

// `scene` as loaded (its luminaires' files read). The flux is the new installation's (no
// maintenance factor); the floor area is the geometry's extent in plan (x by z, y up).
Schedule luminaireSchedule(const Scene& scene);

// "maintained values, MF 0.80" (or "MF 0.72 to 0.80"), or "new installation (no maintenance
// factor)": what the report's figures are.
std::string maintenanceStatement(const Scene& scene);

}  // namespace lucerna
