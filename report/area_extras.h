#pragma once
// The report's figures of EN 12464-1:2021 beside a task area's Em, U0, UGR and Ra
// (render/photometry/task_area_figures.h, which `lucerna grid --task-area` and the dock use too):
// Ez over the area and its room's walls and ceiling, as its requirement asks, each room box's
// computed once however many areas lie in it; and the surrounding zone and background area its
// keys give (core/photometry/surrounding_zones.h). The report builder runs each part as a stage
// of its progress.

#include "core/task_system.h"
#include "report/report_data.h"

#include <vector>

namespace lucerna {

// Before any work: the area's room box (taskAreaRoom), the room box whose walls and ceiling its
// requirement asks for (an index into `rooms`, which gains the box the first time, with the
// error target `settings` give it), and its zones' grids, clipped to the room box, with their
// requirements. Throws std::invalid_argument (one line, naming the area) where a zone's grid
// cannot be laid out.
void planAreaExtras(const Scene& scene, const TaskArea& area, const ReportSettings& settings, AreaReport& report,
                    std::vector<RoomSurfacesReport>& rooms);

// Whether the area's requirement asks for Ez (its grid computed by computeCylindrical).
bool wantsCylindrical(const AreaReport& report);

// Ez over the area at the posture's height, by the report's grid settings. Cancelled: nothing.
void computeCylindrical(const SceneSnapshot& scene, const TaskArea& area, const ReportSettings& settings,
                        AreaReport& report, TaskContext& ctx);

// The walls and ceiling of `room` (planned by planAreaExtras for `area`), with room.settings.
// Cancelled: an incomplete result (discard the report).
void computeWallsAndCeiling(const SceneSnapshot& scene, const TaskArea& area, RoomSurfacesReport& room, TaskContext& ctx);

// The zones' points as one grid facing as the area does, by the report's grid settings; each
// zone's figures and checks (`maintainedValues`: as the area's). Cancelled: nothing.
void computeZones(const SceneSnapshot& scene, const ReportSettings& settings, bool maintainedValues,
                  AreaReport& report, TaskContext& ctx);

// The figures the area's requirement is checked on (the grid's, its UGR and Ra, and what was
// computed of Ez, walls and ceiling), its checks and the modelling ratio.
void checkArea(AreaReport& report, const std::vector<RoomSurfacesReport>& rooms, bool maintainedValues);

// Each room of the summary gains the walls' and ceiling's figures computed for its box (that of
// a task area lying in it: taskAreaRoom names the room).
void addRoomIlluminance(RoomsSummary& summary, const std::vector<RoomSurfacesReport>& rooms);

}  // namespace lucerna
