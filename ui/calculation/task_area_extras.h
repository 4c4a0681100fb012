#pragma once
// The figures EN 12464-1:2021 adds to a task area (render/photometry/task_area_figures.h: Ez over
// the area at the posture's height, the average illuminance of the room's walls and ceiling) as
// the Calculation grid dock computes them: after the area's Em grid has finished, as a job of
// their own on the dock's task system, over the Em grid's scene with its settings, so that they
// agree with `lucerna grid --task-area` and the report; then their lines, and their figures for
// the requirement's checks. Only a task area has them (the posture and the room come with it).

#include "core/photometry/lighting_standards.h"
#include "core/task_system.h"
#include "render/photometry/task_area_figures.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

class TaskAreaExtrasFigures {
public:
    enum class State { NotAsked, Waiting, Computing, Done, Cancelled, Failed };

    TaskAreaExtrasFigures() = default;
    // What `request` asks for `area` of `scene`, waiting for the Em grid (nothing asked: NotAsked).
    // Throws std::invalid_argument (one line) where the Ez grid cannot be laid out.
    TaskAreaExtrasFigures(const TaskArea& area, const Scene& scene, const TaskAreaExtrasRequest& request);

    State state() const { return state_; }
    // Starts the computation on `tasks` over `scene` with `settings` (the Em grid's), holding the
    // yield gate's `gate` counter while it runs. Only while Waiting.
    std::shared_ptr<TaskHandle> start(TaskSystem& tasks, const SceneSnapshot& scene, const GridSettings& settings,
                                      std::shared_ptr<std::atomic<int>> gate);
    // The started job has finished: its figures are taken (its error kept, when it failed).
    void finish(TaskHandle& job);
    // Cancelled while computing, or never started (the Em grid cancelled or failed): no figures,
    // not even a cancelled job's partial ones, and the lines say so.
    void cancel();

    // "Ez (6 x 6 points at 1.20 m) and the walls and ceiling": what is being computed.
    std::string computingText() const;
    // "Ez, walls and ceiling in 3.2 s" once done; empty otherwise.
    std::string doneText() const;
    // describeExtras' lines once done (the modelling ratio with the Em grid's `horizontal`
    // figures); before, one line saying what is to come, or that it was cancelled or failed.
    std::vector<std::string> lines(const std::optional<GridStatistics>& horizontal) const;
    // Fills the figures' cylindrical, walls and ceiling once done (addExtras); else nothing, and
    // the checks say "not computed".
    void addTo(TaskAreaFigures& figures) const;

private:
    std::string asked() const;  // "Ez", "walls and ceiling", "Ez, walls and ceiling"

    TaskArea area_;
    TaskAreaExtrasRequest request_{false, false};
    State state_ = State::NotAsked;
    int cylindricalPoints_ = 0;
    double heightAboveFloorM_ = 0;
    std::shared_ptr<std::optional<TaskAreaExtras>> computed_;  // the job's
    std::optional<TaskAreaExtras> extras_;                     // Done: what it computed
    std::string error_;
    std::chrono::steady_clock::time_point started_;
    double seconds_ = 0;
};

}  // namespace lucerna
