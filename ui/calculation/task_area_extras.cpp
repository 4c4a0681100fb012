#include "ui/calculation/task_area_extras.h"

#include "core/number_format.h"
#include "ui/rendering/yield_gate.h"

namespace lucerna {

TaskAreaExtrasFigures::TaskAreaExtrasFigures(const TaskArea& area, const Scene& scene, const TaskAreaExtrasRequest& request)
    : area_(area), request_(request) {
    if (!request.cylindrical && !request.roomSurfaces) return;
    if (request.cylindrical) {  // laid out now, so that a bad grid is told before any work
        const GridLayout layout = layoutGrid(cylindricalGrid(area, taskAreaRoom(scene, area), scene.metersPerUnit),
                                             scene.metersPerUnit);
        cylindricalPoints_ = int(layout.points.size());
        heightAboveFloorM_ = area.standing ? kStandingCylindricalHeightM : kSeatedCylindricalHeightM;
    }
    state_ = State::Waiting;
}

std::shared_ptr<TaskHandle> TaskAreaExtrasFigures::start(TaskSystem& tasks, const SceneSnapshot& scene,
                                                         const GridSettings& settings,
                                                         std::shared_ptr<std::atomic<int>> gate) {
    if (state_ != State::Waiting) return nullptr;
    state_ = State::Computing;
    started_ = std::chrono::steady_clock::now();
    computed_ = std::make_shared<std::optional<TaskAreaExtras>>();
    return tasks.submit([scene, area = area_, settings, request = request_, out = computed_,
                         gate = std::move(gate)](TaskContext& ctx) {
        const YieldGate::Scope hold(gate);  // a foreground request, as the Em grid
        TaskAreaExtras extras = computeTaskAreaExtras(scene, area, settings, request, ctx);
        if (extras.complete) *out = std::move(extras);  // read once the job has finished
    });
}

void TaskAreaExtrasFigures::finish(TaskHandle& job) {
    if (state_ != State::Computing) return;
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    try {
        job.rethrowIfFailed();
    } catch (const std::exception& e) {
        state_ = State::Failed;
        error_ = e.what();
        return;
    }
    if (!computed_ || !*computed_) {
        state_ = State::Cancelled;
        return;
    }
    extras_ = std::move(**computed_);
    computed_.reset();
    state_ = State::Done;
}

void TaskAreaExtrasFigures::cancel() {
    if (state_ != State::Waiting && state_ != State::Computing) return;
    state_ = State::Cancelled;
    computed_.reset();
}

std::string TaskAreaExtrasFigures::asked() const {
    if (request_.cylindrical && request_.roomSurfaces) return "Ez, walls and ceiling";
    return request_.cylindrical ? "Ez" : "walls and ceiling";
}

std::string TaskAreaExtrasFigures::computingText() const {
    std::string text;
    if (request_.cylindrical)
        text = "Ez (" + std::to_string(cylindricalPoints_) + " points at " + fixedNumber(heightAboveFloorM_, 2) +
               " m above the floor)";
    if (request_.roomSurfaces) text += (text.empty() ? "" : ", then ") + std::string("the room's walls and ceiling");
    return text;
}

std::string TaskAreaExtrasFigures::doneText() const {
    return state_ == State::Done ? asked() + " in " + formatDuration(seconds_) : std::string();
}

std::vector<std::string> TaskAreaExtrasFigures::lines(const std::optional<GridStatistics>& horizontal) const {
    switch (state_) {
    case State::NotAsked: return {};
    case State::Waiting: return {asked() + ": computed after the Em grid"};
    case State::Computing: return {asked() + ": computing..."};
    case State::Cancelled: return {asked() + ": cancelled, not computed"};
    case State::Failed: return {asked() + ": failed: " + error_};
    case State::Done: break;
    }
    return describeExtras(*extras_, horizontal);
}

void TaskAreaExtrasFigures::addTo(TaskAreaFigures& figures) const {
    if (state_ == State::Done) addExtras(figures, *extras_);
}

}  // namespace lucerna
