#pragma once
// Computes what a report states (report_data.h) from a scene: the schedule, each task area's grid
// (by `lucerna grid`'s path, computeSceneGrid, so that the same settings give the same figures),
// its checks against EN 12464-1 and its observers' UGR, the 2021 edition's Ez, walls, ceiling and
// zones as its requirement and keys ask (area_extras.h), and the renders. Runs as a background
// job: progress and cancellation through the TaskContext.

#include "core/task_system.h"
#include "report/report_data.h"

#include <string>
#include <vector>

namespace lucerna {

// The areas a report covers: the scene's task areas, or, when it has none, the work plane at
// 0.8 m above the lowest geometry less a 0.5 m border (EN 12464-1), named "Work plane": what
// `lucerna grid --work-plane 0.8` computes. Throws std::invalid_argument (one line) when the
// scene leaves no work plane.
struct ReportArea {
    TaskArea area;
    bool defaultWorkPlane = false;
};
std::vector<ReportArea> reportAreas(const Scene& scene);

// Throws std::invalid_argument (one line) for what cannot be computed: no work plane, a task
// area whose grid cannot be laid out or whose activity the table lacks.
void checkReportInput(const Scene& scene, const ReportSettings& settings);

// Throws as checkReportInput does, before any work. `scenePath` names the scene on the cover.
// When ctx is cancelled it returns early with what is done (discard it).
ReportData buildReport(const SceneSnapshot& scene, const std::string& scenePath, const ReportSettings& settings,
                       TaskContext& ctx);

}  // namespace lucerna
